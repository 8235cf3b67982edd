"""Sensitivity studies (``soilcut sensitivity``): Morris screening or Sobol
indices of a case's outputs, on threads or on any executor."""

from __future__ import annotations

import concurrent.futures
import io
import json
import os
from collections.abc import Mapping
from typing import Any, Union

from . import _soilcut
from ._case import Case, case_of, native_of
from ._run import pandas

Range = Union[str, tuple[float, float]]


class SensitivityResult:
    """A finished sensitivity study: what ``soilcut sensitivity`` writes.

    Attributes:
        indices: ``indices.csv`` as a DataFrame: per output and key, Sobol's
            ``S1``, ``S1_low``, ``S1_high``, ``ST``, ``ST_low``, ``ST_high``
            (95 % bootstrap intervals) or Morris's ``mu_star``,
            ``mu_star_low``, ``mu_star_high``, ``sigma``, ``mu`` (in the
            output's unit); no rows if a run failed.
        indices2: ``indices2.csv`` as a DataFrame (``second_order=True``
            only, else None): per output and pair of keys (``key``,
            ``key2``), ``S2``, ``S2_low``, ``S2_high``.
        samples: ``samples.csv``: every design run (``run``, ``point``,
            ``k``, the inputs, ``status``, ``error``, the outputs).
        tornado: ``tornado.csv``: the one-at-a-time runs at each key's ends.
        summary: ``summary.json`` as a dict: the study, each output's unit
            and chaos share, ``complete`` (False if a run failed) and
            ``stopped`` (which, and why).
        files: every file's text by name (``indices.csv``, ``indices2.csv``
            with second-order indices, ``samples.csv``,
            ``tornado.csv``, ``summary.json``, ``sensitivity.md``,
            ``timing.csv``), byte for byte as the command line writes them.
        pictures: the paths of ``indices.png``, ``morris.png`` and
            ``tornado.png``, if drawn (``pictures=``).
    """

    def __init__(self, d: dict[str, Any]) -> None:
        pd = pandas("soilcut.sensitivity (DataFrames)")
        self.files: dict[str, str] = d["files"]
        self.pictures: list[str] = [str(p) for p in d["pictures"]]
        self.summary: dict[str, Any] = json.loads(self.files["summary.json"])

        def frame(name: str):
            return pd.read_csv(io.StringIO(self.files[name]))

        self.indices = frame("indices.csv")
        self.indices2 = frame("indices2.csv") if "indices2.csv" in self.files else None
        self.samples = frame("samples.csv")
        self.tornado = frame("tornado.csv")

    @property
    def complete(self) -> bool:
        """Whether every run succeeded (and so the indices were computed)."""
        return bool(self.summary["complete"])

    def __repr__(self) -> str:
        s = self.summary
        return (
            f"SensitivityResult(method={s['method']!r}, runs={s['runs'] + s['tornado_runs']}, "
            f"outputs={len(s['outputs'])}, complete={s['complete']})"
        )


def _run(case: Case, run: _soilcut.SensitivityRun) -> _soilcut.SensitivityRow:
    """One run of a study (on a worker of an executor): its row."""
    return _soilcut.sensitivity_run(native_of(case), run)


def sensitivity(
    case: Case,
    vary: Mapping[str, Range],
    *,
    method: str = "sobol",
    second_order: bool = False,
    samples: int | None = None,
    levels: int = _soilcut.SENSITIVITY_LEVELS,
    members: int = _soilcut.SENSITIVITY_MEMBERS,
    dummy: bool = False,
    seed: int = 0,
    jobs: int = 0,
    executor: concurrent.futures.Executor | None = None,
    pictures: str | os.PathLike[str] | None = None,
) -> SensitivityResult:
    """Morris screening or Sobol indices of the case's outputs over ranges
    of its keys, as ``soilcut sensitivity`` computes them: the same design,
    runs, indices and files for the same case, ranges and seed, whatever
    runs the runs. Each design point, and each point of the tornado (each
    key at the ends of its range, the others at the case's values), is an
    ensemble of ``members`` perturbed runs; the indices are those of the
    ensemble mean, and each output's chaos share (``summary["outputs"]``)
    says how much of its variance the chaos carries. A run that fails
    leaves the result without indices (``complete`` False), not an
    exception. Bad arguments raise ``ValueError`` naming the argument (a
    key the case does not have: :class:`soilcut.CaseError`), before any
    run; a missing pandas an ``ImportError``.

    Args:
        vary: dotted key → its range, ``(lo, hi)`` or ``"lo:hi"``, lo < hi.
        method: ``"sobol"`` (first-order and total indices, Saltelli's
            design on a scrambled Sobol sequence) or ``"morris"``
            (elementary effects μ*, σ, μ).
        second_order: Sobol: also the second-order index S2 of every pair
            of keys (``indices2``), at N (2 keys + 2) design runs instead of
            N (keys + 2); refused with Morris.
        samples: Sobol: base points N, a power of 2 ≥ 16 (512 if None);
            Morris: trajectories r ≥ 2 (20 if None). The study makes
            N (keys + 2), N (2 keys + 2) or r (keys + 1) design runs, and the tornado's
            2 keys + 1, each times ``members``.
        levels: Morris: levels p of the grid (even).
        members: members K of each point's ensemble (1: one run a point).
        dummy: add an input ``dummy`` that no run reads: its indices show
            the estimators' noise floor.
        seed: seed of the design and the bootstrap.
        jobs: threads when no executor is given (0: one per core). The
            result does not depend on it.
        executor: any ``concurrent.futures.Executor`` to make the runs on,
            one task a run: a ``ProcessPoolExecutor``, or a cluster's, such
            as Dask's ``distributed.Client(...).get_executor()`` (a
            ``LocalCluster`` on this machine, or a scheduler of many
            machines; dask-jobqueue for Slurm or PBS). The result is the
            same as on threads, bit for bit, whatever the workers.
        pictures: a folder to draw ``indices.png``, ``morris.png`` (Morris)
            and ``tornado.png`` into, as the command line does (None: none).
    """
    pandas("soilcut.sensitivity (DataFrames)")  # before the runs, not after them
    case = case_of(case)
    study = _soilcut.SensitivityStudy(
        native_of(case),
        list(vary.items()),
        method,
        samples,
        levels,
        second_order,
        members,
        dummy,
        seed,
        jobs,
    )
    if executor is None:
        return SensitivityResult(study.run(pictures))
    futures = [executor.submit(_run, case, run) for run in study.runs()]
    rows = [f.result() for f in futures]
    return SensitivityResult(study.analyse(rows, pictures))
