"""Runs of a case: ``soilcut.run`` and its result."""

from __future__ import annotations

import os
import pathlib
from typing import Any, NamedTuple, Union

import numpy as np

from . import _soilcut
from ._case import Case, case_of, native_of
from ._errors import StepError

PathLike = Union[str, "os.PathLike[str]"]


class Frame(NamedTuple):
    """The ground surface after ``step`` increments (0: before the first), as
    ``frames.csv`` holds it: from the blade face to beyond the disturbed
    zone, thinned to at most 400 nodes. Lengths in the case's unit."""

    step: int
    u: float
    """Blade displacement (length)."""
    x: np.ndarray
    y: np.ndarray
    accumulated_shear: np.ndarray


def _frames(columns: dict[str, np.ndarray]) -> list[Frame]:
    ids = columns["frame"]
    starts = np.flatnonzero(np.r_[True, ids[1:] != ids[:-1]])
    ends = np.r_[starts[1:], len(ids)]
    return [
        Frame(
            int(columns["step"][a]),
            float(columns["u"][a]),
            columns["x"][a:b],
            columns["y"][a:b],
            columns["accumulated_shear"][a:b],
        )
        for a, b in zip(starts, ends)
    ]


def pandas(what: str):
    """pandas, or an ``ImportError`` saying that ``what`` needs it and which
    extra installs it (plain ``pip install ./python`` has no pandas)."""
    try:
        import pandas as pd
    except ImportError as e:
        raise ImportError(f"{what} needs pandas: pip install 'soilcut[pandas]' (or pandas)") from e
    return pd


def _frame_of(columns: dict[str, np.ndarray]):
    return pandas("a DataFrame").DataFrame(columns)


class RunResult:
    """A finished run: what ``soilcut run`` writes, as Python values.

    Attributes:
        case: the case that was run.
        history: one NumPy array per column of ``history.csv``, in its order
            (``step``, ``u``, ``u_over_d``, ``force``, ``force_norm``,
            ``force_h``, ``force_v``, ``beta_deg``, ``x_emergence``, ``mass``,
            ``y_emergence``, ``friction_deg``, ``slip``, ``dilation_deg``,
            ``dilation_area``, ``depth``, ``mass_spilled``, ``weight``,
            ``force_factor``, ``face_friction_deg``, ``moment``,
            ``tool_x``, ``tool_y``, ``tool_rotation``): forces and
            masses per unit width (γ·length²), ``moment`` per unit width
            (γ·length³), ``force_norm`` = P/(γ0 d²);
            with ``blade.width`` per blade (γ·length³) and ``force_norm`` =
            P/(γ0 d² w); lengths in the case's unit, angles in degrees. The
            numbers are the file's exactly.
        profile: the final ground surface, arrays ``x``, ``y`` (the
            centreline), ``accumulated_shear`` (length), ``unit_weight``
            (force/length³) and ``ridge_height`` (length: the side heaps'
            crest beside a blade of finite width, 0 in plane strain).
        summary: the content of ``summary.json`` (peaks, baselines, mass
            drift, ``wall_time_s``, ...).
        frames: the surfaces captured for the animation (:class:`Frame`),
            the deformation pattern through the run.

    A result pickles (to move it between processes or keep it on disk).
    """

    def __init__(self, case: Case, native: _soilcut.RunRecords) -> None:
        self.case = case
        self._native = native
        self.history: dict[str, np.ndarray] = native.history()
        self.history["step"] = self.history["step"].astype(np.int64)
        self.profile: dict[str, np.ndarray] = native.profile()
        self.summary: dict[str, Any] = native.summary()
        self.frames: list[Frame] = _frames(native.frames())

    def __reduce__(self):
        # The files hold every number exactly (shortest round-trip text).
        return (_restore_run, (self.case, self._native.files()))

    def history_frame(self):
        """``history`` as a pandas DataFrame (needs pandas)."""
        return _frame_of(self.history)

    def profile_frame(self):
        """``profile`` as a pandas DataFrame (needs pandas)."""
        return _frame_of(self.profile)

    def save(self, folder: PathLike, *, pictures: bool = True, force: bool = False) -> pathlib.Path:
        """Writes the folder ``soilcut run`` writes: ``history.csv``,
        ``profile.csv``, ``summary.json``, ``case.resolved.toml``,
        ``frames.csv`` and, with ``pictures``, ``plots/`` and
        ``animation.gif``, and the marker ``.soilcut``. The files appear
        together or not at all. An existing, non-empty folder is replaced
        only with ``force=True`` and only if soilcut wrote it (it holds
        ``.soilcut``); else, or if ``folder`` is a file,
        ``FileExistsError``. Returns the folder."""
        folder = pathlib.Path(folder)
        self._native.write(os.fspath(folder), force, pictures)
        return folder

    def __repr__(self) -> str:
        s = self.summary
        return (
            f"RunResult({self.case.name!r}: {s['steps']} steps, "
            f"max force_norm {s['max_force_norm']:.4f} at u/d = {s['u_over_d_at_max']:.3f})"
        )


def _restore_run(case: Case, files: list[tuple[str, str]]) -> RunResult:
    return RunResult(case, _soilcut.RunRecords.from_files(files))


class Ensemble:
    """A case run N times with imperceptible perturbations (member k:
    ``soil.d50`` × (1 + 0.001 k) in the refined model, ``blade.wall_friction``
    + 0.01° × k in the original; k = −3 … 3 for N = 7, k = 0 the case
    itself), and the spread its own chaos puts on the results: what
    ``soilcut run CASE --ensemble N`` writes.

    Attributes:
        members: each member's :class:`RunResult`, in the order of k.
        folders: the members' folder names (``k-3`` … ``k+3``).
        windows: per unit window k ≤ u/d < k + 1, NumPy arrays of
            ``ensemble.csv``'s columns: ``u_over_d_from``, ``u_over_d_to``,
            ``members``, ``mean``, ``std`` (sample standard deviation over the
            members), ``min``, ``max`` of the members' window means of
            P/(γ0 d²), then one column per member.
        summary: the content of the ensemble's ``summary.json`` (the
            perturbation, the spread of the whole-run mean, of the largest
            and the first force and of every window mean, wall times).
    """

    def __init__(self, case: Case, native: _soilcut.EnsembleRun) -> None:
        self.case = case
        self._native = native
        self.windows: dict[str, np.ndarray] = native.windows()
        self.summary: dict[str, Any] = native.summary()
        members = native.members()
        self.folders: list[str] = [name for name, _ in members]
        self.members: list[RunResult] = [
            RunResult(Case._from_native(run.case()), run) for _, run in members
        ]

    def windows_frame(self):
        """``windows`` as a pandas DataFrame (needs pandas)."""
        return _frame_of(self.windows)

    def save(self, folder: PathLike, *, pictures: bool = True, force: bool = False) -> pathlib.Path:
        """Writes the folder ``soilcut run --ensemble`` writes:
        ``ensemble.csv``, ``summary.json``, each member's run folder and,
        with ``pictures``, ``plots/envelope.{png,svg}`` and the members'
        pictures. The files appear together or not at all; an existing,
        non-empty folder is replaced only with ``force=True`` and only if
        soilcut wrote it (it holds ``.soilcut``; else ``FileExistsError``).
        Returns the folder."""
        folder = pathlib.Path(folder)
        self._native.write(os.fspath(folder), force, pictures)
        return folder

    def __repr__(self) -> str:
        m = self.summary["mean_force_norm"]
        return (
            f"Ensemble({self.case.name!r}: {len(self.members)} members, mean force_norm "
            f"{m['mean']:.4f} ± {m['std']:.4f} (sd))"
        )


def run(
    case: Case | PathLike, *, ensemble: int | None = None, jobs: int = 0
) -> RunResult | Ensemble:
    """Runs ``case`` (a :class:`Case`, or a case file's path or text) to its
    end, as ``soilcut run`` does, and returns the result. The interpreter is
    released while it runs (other threads go on).

    With ``ensemble=N``, runs the case's N perturbed members in parallel on
    ``jobs`` threads (0: one per core; the result does not depend on it) and
    returns an :class:`Ensemble`, as ``soilcut run CASE --ensemble N`` does.

    Raises :class:`soilcut.CaseError` for a case the model cannot simulate
    and :class:`soilcut.StepError` if an increment has no admissible
    mechanism (its ``result`` keeps the increments made before, marked as
    stopped, as ``soilcut run`` keeps them); warns with
    :class:`soilcut.AccuracyWarning` where the case's grid is known to cost
    accuracy, as ``soilcut run`` warns on stderr.
    """
    the_case = case_of(case)
    if ensemble is not None:
        # The count's rule (at least 2) is the library's; the type is Python's.
        if isinstance(ensemble, bool) or not isinstance(ensemble, int):
            raise ValueError(
                f"ensemble: expected an int >= 2 (members; 7 is the rule's), got {ensemble!r}"
            )
        if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 0:
            raise ValueError(f"jobs: expected an int >= 0 (0: one per core), got {jobs!r}")
        return Ensemble(the_case, _soilcut.ensemble(native_of(the_case), ensemble, jobs))
    try:
        return RunResult(the_case, _soilcut.run(native_of(the_case)))
    except StepError as stopped:
        records = getattr(stopped, "_records", None)
        if records is not None:
            stopped.result = RunResult(the_case, records)
            del stopped._records
        raise
