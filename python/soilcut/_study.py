"""Studies made of many runs: sweeps, calibration, the analytical baselines."""

from __future__ import annotations

import concurrent.futures
import os
from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple, Union

import numpy as np

from . import _soilcut
from ._case import Case, case_of, native_of
from ._run import pandas

Spec = Union[str, tuple[float, float], tuple[float, float, int], Sequence[Any]]


def _frame(tables: list[dict[str, Any]]):
    """The DataFrame of ``sweep.csv`` from its columns (the extension's
    tables: whole numbers, values, text and float64 arrays), one table per
    run or one for all."""
    pd = pandas("soilcut.sweep (a DataFrame)")

    # The tables' columns joined before the frame is made (arrays as
    # arrays), so that each column's type is inferred as for one table.
    def joined(name: str):
        parts = [t[name] for t in tables]
        if isinstance(parts[0], np.ndarray):
            return np.concatenate(parts)
        return [v for part in parts for v in part]

    return pd.DataFrame({name: joined(name) for name in tables[0]})


def _sweep_row(case: Case, keys: list[str], values: list[Any], run: int, total: int):
    """One run of a sweep (on a worker of an executor): its row of
    ``sweep.csv`` as columns of one value."""
    return _soilcut.sweep_row(native_of(case), keys, values, run, total)[0]


def sweep(
    case: Case,
    vary: Mapping[str, Spec] | None = None,
    *,
    samples: Sequence[Mapping[str, Any]] | None = None,
    sample: str = "grid",
    seed: int = 0,
    jobs: int = 0,
    executor: concurrent.futures.Executor | None = None,
):
    """Runs ``case`` for many values of its keys, as ``soilcut sweep`` does,
    and returns ``sweep.csv`` as a pandas DataFrame: ``run``, the varied keys,
    ``status`` (``ok`` or ``failed``), ``error``, then the figures of each run
    (``initial_force_norm``, ``max_force_norm``, ``u_over_d_at_max``,
    ``final_force_norm``, ``peaks``, ``mean_force_norm_last_half``,
    ``mass_drift_rel``, ``band_jumps``, ``steps``; forces as P/(γ0 d²)), the
    figures as float64 (the numbers themselves, NaN where a run failed). A
    run that fails is a row with its error, not an exception. A key that
    is not part of the case raises :class:`soilcut.CaseError` naming it and
    the nearest keys, and a missing pandas an ``ImportError``, both before
    any run.

    Args:
        vary: dotted key → values: a spec string as ``--vary`` takes it
            (``"30:45:7"`` grid, ``"30:45"`` interval, ``"0.3,0.6"`` list),
            a tuple ``(lo, hi, n)`` (grid) or ``(lo, hi)`` (interval, for
            ``sample="lhs:N"``), or a list of values.
        samples: instead of ``vary``, the runs themselves: one dict of
            dotted key → value per run (every dict with the same keys).
        sample: ``"grid"`` (every combination) or ``"lhs:N"`` (a seeded
            Latin-hypercube sample of N runs).
        seed: the seed of the Latin-hypercube sample.
        jobs: threads when no executor is given (0: one per core). The
            result does not depend on it.
        executor: any ``concurrent.futures.Executor`` to run the runs on: a
            ``ProcessPoolExecutor``, or a cluster's, such as Dask's
            ``Client.get_executor()`` (dask-jobqueue for Slurm or PBS). The
            result is the same as on one thread, row for row.
    """
    pandas("soilcut.sweep (a DataFrame)")  # before the runs, not after them
    case = case_of(case)
    native = native_of(case)
    if (vary is None) == (samples is None):
        raise ValueError("give either vary (keys and their values) or samples (one dict per run)")
    if samples is not None:
        keys = list(samples[0].keys()) if samples else []
        if not keys:
            raise ValueError("samples: give at least one run with at least one key")
        points = []
        for i, s in enumerate(samples):
            if list(s.keys()) != keys:
                raise ValueError(f"samples[{i}]: the keys differ from those of samples[0]: {keys}")
            points.append([s[k] for k in keys])
        _soilcut.sweep_check(native, keys, points[0])
    else:
        varies = list(vary.items())
        if executor is None:
            return _frame([_soilcut.sweep_run(native, varies, sample, seed, jobs)])
        keys, points = _soilcut.sweep_points(native, varies, sample, seed)
    total = len(points)
    own = executor is None
    if own:
        executor = concurrent.futures.ThreadPoolExecutor(max_workers=jobs or os.cpu_count())
    try:
        futures = [
            executor.submit(_sweep_row, case, keys, values, i + 1, total)
            for i, values in enumerate(points)
        ]
        rows = [f.result() for f in futures]
    finally:
        if own:
            executor.shutdown()
    return _frame(rows)


class FitResult:
    """A calibration (``soilcut fit``).

    Attributes:
        best: the free keys' best values (dotted key → value).
        intervals: each key's 95 % interval as text (profile likelihood).
        verdicts: each key's verdict: determined, weakly determined or
            undetermined by the curve.
        best_rms: RMS error of the force at the best values (γ·length², force per unit width).
        start_rms: RMS error at the case's own values.
        best_case: the case at the best values (resolved).
        files: ``fit.md``, ``fit.csv``, ``curves.csv``, ``profiles.csv``,
            ``search.csv``, ``best.toml`` as ``soilcut fit`` writes them.
    """

    def __init__(self, d: dict[str, Any]) -> None:
        self.best: dict[str, float] = d["best"]
        self.intervals: dict[str, str] = d["intervals"]
        self.verdicts: dict[str, str] = d["verdicts"]
        self.best_rms: float = d["best_rms"]
        self.start_rms: float = d["start_rms"]
        self.files: dict[str, str] = d["files"]
        self.best_case = Case(self.files["best.toml"])

    def __repr__(self) -> str:
        return (
            f"FitResult(best={self.best}, best_rms={self.best_rms:.4g}, "
            f"start_rms={self.start_rms:.4g})"
        )


def _measured(measured: Any) -> list[tuple[float, float]]:
    if isinstance(measured, (str, bytes, os.PathLike)):
        raise TypeError(
            "measured: expected the curve's numbers (a DataFrame with columns u, force, a "
            f"tuple (u, force) or an N×2 array), not a path ({measured!r}): read the file "
            "first, e.g. pandas.read_csv(path)"
        )
    if hasattr(measured, "columns") and "u" in measured.columns and "force" in measured.columns:
        u, p = measured["u"], measured["force"]
    elif isinstance(measured, tuple) and len(measured) == 2:
        u, p = measured
    else:
        a = np.asarray(measured, dtype=float)
        if a.ndim != 2 or a.shape[1] != 2:
            raise ValueError(
                "measured: expected a DataFrame with columns u, force, a tuple (u, force) "
                "of arrays or an N×2 array"
            )
        u, p = a[:, 0], a[:, 1]
    u, p = np.asarray(u, dtype=float), np.asarray(p, dtype=float)
    if u.shape != p.shape or u.ndim != 1:
        raise ValueError("measured: u and force must be 1-D arrays of one length")
    for name, values in (("u", u), ("force", p)):
        bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise ValueError(
                f"measured: {name}[{bad[0]}] is {values[bad[0]]}: every value must be a "
                "finite number"
            )
    return list(zip(u.tolist(), p.tolist()))


def fit(
    case: Case,
    measured: Any,
    free: Sequence[str],
    *,
    bounds: Mapping[str, tuple[float, float]] | None = None,
    width: float | None = None,
    objective: str = "raw",
    method: str = "de",
    evaluations: int = _soilcut.FIT_EVALUATIONS,
    population: int = 0,
    polish: int = _soilcut.FIT_POLISH_ITERATIONS,
    profile_points: int = _soilcut.FIT_PROFILE_GRID,
    seed: int = 0,
    jobs: int = 0,
) -> FitResult:
    """Fits the ``free`` keys of ``case`` to a measured force-displacement
    curve, as ``soilcut fit`` does: a seeded global search of
    ``evaluations`` runs over the bounds (``population`` 0: the method's
    default),
    a Nelder-Mead polish of ``polish`` iterations, then each key's profile
    on ``profile_points`` values for its interval (0: none), on ``jobs``
    threads; the result does not depend on ``jobs``.

    Args:
        measured: the blade displacement u (length) and the force per unit
            width (γ·length², force per unit width): a DataFrame with columns ``u`` and
            ``force``, a tuple ``(u, force)`` or an N×2 array.
        free: dotted keys to fit; they start at the case's values.
        bounds: dotted key → (lo, hi), replacing a key's default bounds.
        width: the measured force is the total over this blade width:
            it is divided by it.
        objective: ``raw``, ``smooth:W`` or ``means:W`` (W a length), as
            ``soilcut fit --objective``.
        method: the global search, ``de`` (differential evolution) or
            ``cmaes`` (CMA-ES with restarts), as ``soilcut fit --method``.
    """
    points = _measured(measured)
    bounds_list = [(k, float(lo), float(hi)) for k, (lo, hi) in (bounds or {}).items()]
    budget = (evaluations, population, polish, profile_points)
    width = None if width is None else float(width)
    d = _soilcut.fit(
        native_of(case),
        points,
        width,
        list(free),
        bounds_list,
        objective,
        method,
        budget,
        seed,
        jobs,
    )
    return FitResult(d)


def analytic(case: Case) -> dict[str, dict[str, Any] | None]:
    """The analytical baselines of the case's initial flat ground, as
    ``soilcut analytic`` prints them: ``rankine`` (smooth vertical wall),
    ``coulomb`` (trial wedge, c = a = q = 0) and ``fee`` (Reece's
    Fundamental Earthmoving Equation, McKyes' factors). Each is a dict of
    ``force`` (per unit width, γ·length²), ``force_norm`` (P/(γ0 d²)),
    ``force_h``, ``force_v`` (positive upward), ``failure_angle_deg`` and,
    for the FEE, ``factors`` (``n_gamma``, ``n_c``, ``n_a``, ``n_q``); None
    where no wedge is admissible. With ``blade.width`` also ``mckyes_ali``
    (McKyes & Ali's blade of finite width: ``force`` per blade,
    ``force_norm`` P/(γ0 d² w), its ``factors`` Nγ3 … Nq3, ``rupture``, the
    rupture distance (length), and ``crescent_angle_deg``)."""
    return _soilcut.analytic(native_of(case))


class Landscape(NamedTuple):
    """Every candidate mechanism of one increment (``soilcut landscape --at``)."""

    u: float
    """Blade displacement of the increment (length)."""
    candidates: dict[str, np.ndarray]
    """The columns of ``landscape.csv``, one row per candidate, nearest the
    blade first: ``x_emergence``, ``distance_over_d`` ((x − u)/d),
    ``y_emergence`` (length), ``beta_deg``, ``force`` (γ·length², force per
    unit width), ``force_norm`` (P/(γ0 d²)), ``force_over_least``,
    ``friction_deg``, ``dilation_deg``."""


def landscape(case: Case, at: float) -> Landscape:
    """The force of every candidate band at u/d = ``at`` (0 to
    run.travel / blade.depth): the increment evaluated first at u ≥ at·d, as
    ``soilcut landscape --at`` takes it. The forces are those the search
    compares, at the start of the increment; under the midpoint force
    (``run.time_scheme``, the vertex ground's default) the run records the
    chosen band's force half an increment on."""
    u, candidates = _soilcut.landscape(native_of(case), float(at))
    return Landscape(u, candidates)


class LandscapeMap(NamedTuple):
    """Landscapes through the run, binned by distance ahead of the tip
    (``soilcut landscape --every``)."""

    columns: dict[str, np.ndarray]
    """The columns of ``landscape_map.csv``, one row per landscape and
    distance bin of 0.05 d: ``u_over_d`` of the landscape,
    ``distance_over_d`` (the bin's start ahead of the tip) and
    ``force_over_least`` (the least P / P* of the bin's candidates)."""
    far_ties: int
    """How many landscapes hold a band more than 1 d from the least whose
    force comes within 1 % of it (the band jumps of docs/model.md §12)."""


def landscape_map(case: Case, every: float) -> LandscapeMap:
    """The landscape at u/d = 0, ``every``, 2 ``every``, … (above 0, at most
    run.travel / blade.depth; each at the first increment at or beyond),
    each binned by distance ahead of the tip, as ``soilcut landscape
    --every`` takes them."""
    columns, far = _soilcut.landscape_map(native_of(case), float(every))
    return LandscapeMap(columns, far)


class Bounds(NamedTuple):
    """Rigorous limit-analysis bounds on the ground as it stands at one
    instant, beside soilcut's force there (``soilcut bounds --at``)."""

    columns: dict[str, np.ndarray]
    """The columns of ``bounds.csv`` (one row): ``u``, ``u_over_d``,
    ``depth``, ``face_height`` (length), ``soilcut``, ``lower``, ``upper``
    (horizontal forces, γ·length² per unit width; NaN for a bound not
    found), ``soilcut_over_lower``, ``soilcut_over_upper``, ``half_width``,
    ``mesh``, ``triangles``, ``lower_seconds``, ``upper_seconds`` (s),
    ``soilcut_force`` (resultant), ``beta_deg``, ``friction_deg``."""
    lower_status: str
    """``"Solved"``, or the solver's status (``"PrimalInfeasible"``: no
    stress field on the mesh carries the ground's own weight with its
    strength)."""
    upper_status: str
    """The same for the upper bound."""

    def __getitem__(self, key):  # type: ignore[override]
        """A column's one value by name (``b["lower"]``), or a field by index."""
        if isinstance(key, str):
            return float(self.columns[key][0])
        return tuple.__getitem__(self, key)


def bounds(
    case: Case,
    at: float,
    *,
    mesh: int = _soilcut.BOUNDS_MESH,
    floor: str = _soilcut.BOUNDS_FLOOR,
    strength: str = _soilcut.BOUNDS_STRENGTH,
    field: str = _soilcut.BOUNDS_FIELD,
) -> Bounds:
    """Lower and upper bounds (finite-element limit analysis) on the
    horizontal force the ground as it stands before the increment at u/d =
    ``at`` can carry, beside soilcut's force of that increment, as
    ``soilcut bounds --at`` computes them: ``mesh`` N in [1, 64], ``floor``
    "rigid" (soilcut's floor at the tip level) or "soil", ``strength``
    "associated" or "davis", ``field`` "columns" (each column its node's φ)
    or "slope" (each column at least the slope it stands at; docs/model.md
    §18)."""
    columns, lower, upper = _soilcut.bounds(
        native_of(case), float(at), mesh=mesh, floor=floor, strength=strength, field=field
    )
    return Bounds(columns, lower, upper)
