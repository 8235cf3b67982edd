"""Type stubs of the extension module ``soilcut._soilcut`` (crates/python).

The public names are re-exported by ``soilcut``: :class:`Simulation` and
:class:`Step`. The rest are the package's internals. The test
``python/tests/test_stubs.py`` checks this file against the built
extension: every name, method and parameter on one side is on the other.
"""

import os
from collections.abc import Iterator
from typing import Any

import numpy as np

from ._case import Case

__version__: str
FIT_EVALUATIONS: int
BOUNDS_MESH: int
BOUNDS_FLOOR: str
BOUNDS_STRENGTH: str
BOUNDS_FIELD: str
"""Default runs of a fit's global search (``soilcut fit --evaluations``)."""
FIT_POLISH_ITERATIONS: int
"""Default Nelder-Mead iterations of a fit's polish (``--polish``)."""
FIT_PROFILE_GRID: int
"""Default grid of a fit's profiles (``--profile-points``)."""
SENSITIVITY_SOBOL_SAMPLES: int
"""Default Sobol base points N of a sensitivity study (``--samples``)."""
SENSITIVITY_TRAJECTORIES: int
"""Default Morris trajectories r of a sensitivity study (``--samples``)."""
SENSITIVITY_LEVELS: int
"""Default levels p of Morris's grid (``--levels``)."""
SENSITIVITY_MEMBERS: int
"""Default members K of each point of a sensitivity study (``--members``)."""

class Step:
    """One increment (a row of ``history.csv``): forces per unit width
    (γ·length², force per unit width), or per blade with ``blade.width``
    (γ·length³), lengths in the case's unit, angles in degrees. Its
    attributes are the columns of ``history.csv`` (:attr:`fields`), served
    by ``__getattr__`` from the one list of them (soilcut-io's ``HISTORY``)."""

    fields: tuple[str, ...]
    """The names of the record's values, ``history.csv``'s columns in order."""

    @property
    def step(self) -> int:
        """Increment number, from 1."""
    @property
    def u(self) -> float:
        """Blade displacement u at which the mechanism was evaluated (length)."""
    @property
    def u_over_d(self) -> float:
        """u / d, d = blade.depth."""
    @property
    def force(self) -> float:
        """Resultant blade force P per unit width (γ·length², force per unit width)."""
    @property
    def force_norm(self) -> float:
        """P/(γ0 d²), d = blade.depth."""
    @property
    def force_h(self) -> float:
        """Horizontal (draft) component of P (γ·length², force per unit width)."""
    @property
    def force_v(self) -> float:
        """Vertical component of P, positive upward (γ·length², force per unit width)."""
    @property
    def beta_deg(self) -> float:
        """β*, the angle of the least-force slip line or band (degrees)."""
    @property
    def friction_deg(self) -> float:
        """Friction angle mobilised on the band (degrees)."""
    @property
    def dilation_deg(self) -> float:
        """Dilation angle on the band (degrees)."""
    @property
    def x_emergence(self) -> float:
        """x of the band's emergence point at the surface (length)."""
    @property
    def y_emergence(self) -> float:
        """y of the emergence point (length)."""
    @property
    def depth(self) -> float:
        """Depth of the blade tip during the increment (length)."""
    @property
    def slip(self) -> float:
        """Slip along the band in this increment (length)."""
    @property
    def dilation_area(self) -> float:
        """Area added by dilation in this increment (length²)."""
    @property
    def mass(self) -> float:
        """Weight of the soil ahead of the blade after the increment
        (γ·length² per unit width; per blade with ``blade.width``)."""
    @property
    def mass_spilled(self) -> float:
        """Weight of the soil spilled around the blade's edges so far (0 in
        plane strain; units of ``mass``)."""
    @property
    def weight(self) -> float:
        """W, the weight of the chosen mechanism's block at the start of the
        increment (units of ``mass``)."""
    @property
    def force_factor(self) -> float:
        """P/W, both per unit width: Eq. (1)'s factor without cohesion,
        adhesion, surcharge or side crescents (dimensionless)."""
    @property
    def face_friction_deg(self) -> float:
        """The face force's angle from the face's normal, the wall friction
        the block mobilises (degrees; positive: the block rises along the
        face)."""
    @property
    def moment(self) -> float:
        """M, the moment of the face force about the tool's pivot, the force
        a third up its contact from the cutting edge (force × length per
        unit width or per blade; counter-clockwise positive, the sense of a
        bucket's curl)."""
    @property
    def tool_x(self) -> float:
        """x of the tool's pivot (length; the cutting edge for a blade)."""
    @property
    def tool_y(self) -> float:
        """y of the tool's pivot (length; y = 0 the undisturbed surface)."""
    @property
    def tool_rotation(self) -> float:
        """The tool's rotation (degrees, counter-clockwise; 0 for a blade)."""
    def __getattr__(self, name: str) -> Any: ...
    def __dir__(self) -> list[str]: ...
    def __repr__(self) -> str: ...

class Simulation:
    """A running simulation of one case, stepped from Python (a control
    loop): ``for step in Simulation(case): ...``, or to blade positions
    (:meth:`advance_to`). Each step runs with the interpreter released.
    Copies (``copy.copy``, ``copy.deepcopy``), pickles and
    :meth:`snapshot` bytes continue bit for bit as the original would: a
    planner branches from them."""

    def __init__(self, case: CaseLike) -> None:
        """Flat ground for ``case`` (a :class:`soilcut.Case` or a case file's
        text); raises :class:`soilcut.CaseError` for a case the model cannot
        simulate, and warns with :class:`soilcut.AccuracyWarning` where its
        grid is known to cost accuracy (as ``soilcut run`` warns)."""
    def step(self) -> Step:
        """Advances the blade by one increment (``run.increment``) and
        returns its record. Raises :class:`soilcut.StepError` if no
        mechanism is admissible or once the travel is reached
        (:meth:`advance_to` goes beyond it)."""
    def advance(self, n: int) -> int:
        """Advances by up to ``n`` increments without returning their
        records; returns how many were made. Raises ``ValueError`` for
        ``n`` < 0 and ``TypeError`` for an ``n`` that is not a whole
        number, naming the argument."""
    def advance_to(self, x: float, depth: float | None = None) -> list[Step]:
        """Runs the increments that bring the blade to displacement ``x``
        (length) and returns their records: up to the first whole increment
        at or beyond ``x`` (u = n·v0, n = ⌈x/v0⌉ with x within 10⁻⁹ of a
        whole number counting as it; the rule of ``run.travel``), none if
        the blade is there already. An increment is never shortened: the
        grid is tied to whole increments. Beyond ``run.travel`` the travel
        becomes ``x``. With ``depth`` (length) the tip goes linearly from
        its depth now to ``depth`` at ``x`` and stays there: the case's
        depth path ahead of the blade is replaced; at an ``x`` the blade
        has passed (a controller's tick between increments), ``depth`` is
        held for the next increment, which takes the tip there (vertical blades only;
        deeper than ``run.increment`` and the band width, no deeper than
        the case's deepest tip depth, which sets the ground the simulation
        holds). ``sim.case`` shows the steered case. Raises ``TypeError``
        naming the argument for an ``x`` or ``depth`` that is not a number,
        ``ValueError`` for a bad ``x`` (NaN, negative, behind the blade's last whole
        increment) or ``depth``, :class:`soilcut.CaseError` if the steered
        case does not validate (nothing changes then) and
        :class:`soilcut.StepError` if an increment has no admissible
        mechanism (the increments before it stay made, and their records
        are the error's ``steps``)."""
    def snapshot(self) -> bytes:
        """The state as bytes, with the case file's text: everything that
        determines the rest of the run, so that
        :meth:`from_snapshot` continues bit for bit as this simulation
        would. Tied to this version of soilcut (``docs/model.md`` §17)."""
    @staticmethod
    def from_snapshot(data: bytes) -> Simulation:
        """The simulation a :meth:`snapshot` holds: also one made through
        the C ABI (``soilcut_snapshot``), which carries the case's text too,
        or by the Rust library's ``Simulation::snapshot``, whose :attr:`case`
        is then unknown. Raises
        :class:`soilcut.SnapshotError` for bytes that are not a snapshot of
        this version, truncated or corrupt."""
    def __copy__(self) -> Simulation:
        """An independent copy of the state (``copy.copy`` and
        ``copy.deepcopy`` alike: a simulation shares nothing)."""
    def __deepcopy__(self, _memo: Any) -> Simulation: ...
    def __repr__(self) -> str:
        """The case's name, the increments done of all, the blade's
        position and the tip's depth."""
    def __reduce__(self) -> tuple[Any, tuple[bytes]]:
        """Pickles as :meth:`snapshot`, unpickles by :meth:`from_snapshot`."""
    def surface(self) -> dict[str, np.ndarray]:
        """The free surface from the face to the end of the domain: ``x``,
        ``y`` (the centreline), ``accumulated_shear`` (length),
        ``unit_weight`` (force/length³), ``ridge_height`` (length: the side
        heaps' crest beside a blade of finite width, 0 in plane strain)."""
    @property
    def blade_position(self) -> float:
        """Blade displacement u (length): the face is at x = u."""
    @property
    def steps_done(self) -> int:
        """Increments done so far."""
    @property
    def steps(self) -> int:
        """Increments of the whole case."""
    @property
    def is_done(self) -> bool:
        """Whether the case's travel has been reached."""
    @property
    def tip_depth(self) -> float:
        """Depth of the blade tip now (length)."""
    @property
    def mass(self) -> float:
        """Weight of the soil ahead of the blade now (γ·length² per unit
        width; per blade with ``blade.width``)."""
    @property
    def mass_spilled(self) -> float:
        """Weight of the soil spilled around the blade's edges so far (0 in
        plane strain; units of ``mass``)."""
    @property
    def case(self) -> Case:
        """The case, every default filled in, as :meth:`advance_to` has
        steered it (its depth path and travel). ``RuntimeError`` for a
        simulation restored from a snapshot of the Rust library's
        ``Simulation::snapshot``, which carries no case file text."""
    def __iter__(self) -> Iterator[Step]: ...
    def __next__(self) -> Step: ...

class NativeCase:
    """A case file parsed once: its table and the model's case
    (:class:`soilcut.Case` wraps it; every function below takes it)."""

    @staticmethod
    def from_toml(text: str) -> NativeCase: ...
    @staticmethod
    def from_file(path: str | os.PathLike[str]) -> NativeCase: ...
    @staticmethod
    def from_dict(d: dict[str, Any]) -> NativeCase: ...
    @staticmethod
    def of(case: CaseLike) -> NativeCase: ...
    def set_keys(self, pairs: list[tuple[str, Any]]) -> NativeCase: ...
    def to_toml(self) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    def resolved(self) -> NativeCase: ...
    def resolved_toml(self) -> str: ...
    def get(self, key: str) -> Any: ...
    def names(self) -> tuple[str, str, str]: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> tuple[Any, tuple[str]]: ...

class RunRecords:
    """A finished run, held natively (:class:`soilcut.RunResult` wraps it):
    its numbers as arrays and its files for ``save``."""

    def history(self) -> dict[str, np.ndarray]: ...
    def profile(self) -> dict[str, np.ndarray]: ...
    def frames(self) -> dict[str, np.ndarray]: ...
    def summary(self) -> dict[str, Any]: ...
    def case(self) -> NativeCase: ...
    def files(self) -> list[tuple[str, str]]: ...
    @staticmethod
    def from_files(files: list[tuple[str, str]]) -> RunRecords: ...
    def write(self, folder: str, force: bool, pictures: bool) -> None: ...

class EnsembleRun:
    """A finished ensemble, held natively (:class:`soilcut.Ensemble` wraps it)."""

    def windows(self) -> dict[str, np.ndarray]: ...
    def summary(self) -> dict[str, Any]: ...
    def members(self) -> list[tuple[str, RunRecords]]: ...
    def write(self, folder: str, force: bool, pictures: bool) -> None: ...

CaseLike = NativeCase | Case | str | os.PathLike[str]

SensitivityRun = tuple[bool, int, int, list[tuple[str, float]]]
"""A run of a sensitivity study: (tornado, point, k, the keys it sets)."""
SensitivityRow = tuple[int, int, list[float] | None, str | None, float]
"""A run's row: (point, k, outputs or None, error or None, wall time s)."""

class SensitivityStudy:
    """A checked sensitivity study and its plan (:func:`soilcut.sensitivity`
    runs it)."""

    def __init__(
        self,
        case: CaseLike,
        vary: list[tuple[str, Any]],
        method: str,
        samples: int | None,
        levels: int,
        second_order: bool,
        members: int,
        dummy: bool,
        seed: int,
        jobs: int,
    ) -> None: ...
    def runs(self) -> list[SensitivityRun]: ...
    def run(self, pictures: str | os.PathLike[str] | None = None) -> dict[str, Any]: ...
    def analyse(
        self, rows: list[SensitivityRow], pictures: str | os.PathLike[str] | None = None
    ) -> dict[str, Any]: ...

def sensitivity_run(case: CaseLike, run: SensitivityRun) -> SensitivityRow: ...
def run(case: CaseLike) -> RunRecords: ...
def ensemble(case: CaseLike, members: int, jobs: int) -> EnsembleRun: ...
def csv_columns(name: str, text: str) -> dict[str, np.ndarray]: ...
def analytic(case: CaseLike) -> dict[str, dict[str, Any] | None]: ...
def sweep_points(
    case: CaseLike, varies: list[tuple[str, Any]], sample: str, seed: int
) -> tuple[list[str], list[list[Any]]]: ...
def sweep_run(
    case: CaseLike, varies: list[tuple[str, Any]], sample: str, seed: int, jobs: int
) -> dict[str, Any]: ...
def sweep_check(case: CaseLike, keys: list[str], values: list[Any]) -> None: ...
def sweep_row(
    case: CaseLike, keys: list[str], values: list[Any], run: int, total: int
) -> tuple[dict[str, Any], float]: ...
def fit(
    case: CaseLike,
    measured: list[tuple[float, float]],
    width: float | None,
    free: list[str],
    bounds: list[tuple[str, float, float]],
    objective: str,
    method: str,
    budget: tuple[int, int, int, int],
    seed: int,
    jobs: int,
) -> dict[str, Any]: ...
def landscape(case: CaseLike, at: float) -> tuple[float, dict[str, np.ndarray]]: ...
def perturbation(case: CaseLike, k: float) -> tuple[str, float]: ...
def landscape_map(case: CaseLike, every: float) -> tuple[dict[str, np.ndarray], int]: ...
def bounds(
    case: CaseLike,
    at: float,
    mesh: int = ...,
    floor: str = ...,
    strength: str = ...,
    field: str = ...,
) -> tuple[dict[str, np.ndarray], str, str]: ...
