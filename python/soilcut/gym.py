"""A gymnasium environment: steer the depth of a vertical blade or tine.

    import gymnasium
    import soilcut.gym                    # registers soilcut/Cutting-v0
    env = gymnasium.make("soilcut/Cutting-v0")
    obs, info = env.reset(seed=1)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

gymnasium is an optional dependency (``pip install gymnasium``); ``import
soilcut`` works without it. See :class:`CuttingEnv` for the spaces, the
reward and the termination.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

try:
    import gymnasium
    from gymnasium import spaces
except ImportError as error:  # the package stays usable without it
    raise ImportError(
        "soilcut.gym needs gymnasium, an optional dependency: pip install gymnasium"
    ) from error

from . import _soilcut
from ._case import Case, PathLike, case_of, native_of
from ._errors import StepError
from ._soilcut import Simulation, Step

__all__ = ["ENV_ID", "OBSERVATION_BOUND", "CuttingEnv", "default_case"]

ENV_ID = "soilcut/Cutting-v0"

# The bound of the observation's forces (× F0) and heights (× d): finite, as
# gymnasium's checker asks, and far beyond any cut in range (the tine at its
# full depth before a developed pile: about 35 F0); a value beyond it is
# clipped to it.
OBSERVATION_BOUND = 1000.0

# The narrow tine of cases/tools/tine.toml (w = 50 mm, d = 150 mm, dry sand,
# the original model; forces per tine in N, lengths in mm) at d/100 instead
# of the original model's default d/250, so that an episode of 3 d runs in
# seconds: the package does not ship the repository's cases, so the case is
# written out.
_TINE = """\
name = "tine-gym"
title = "Narrow vertical tine, w = 50 mm, d = 150 mm, dry sand, at d/100"
model = "original"

[blade]
depth = 150.0
wall_friction = 20.0
width = 50.0

[soil]
unit_weight = 1.57e-5
friction = { peak = 38.0, residual = 33.0 }
residual_shear = 30.0
repose = 33.0

[run]
travel = 450.0
increment = 1.5
"""


def default_case() -> Case:
    """The environment's default case: the tine of ``cases/tools/tine.toml``
    (w = 50 mm, d = 150 mm, dry sand, the original model) at
    ``run.increment`` = d/100 = 1.5 mm, over a travel of 3 d."""
    return Case.from_toml(_TINE)


class CuttingEnv(gymnasium.Env):
    """Cut with a vertical blade and steer its tip's depth
    (``soilcut/Cutting-v0``).

    Lengths are normalised by d = ``blade.depth`` of the case (the
    reference depth, also the deepest the tip may go: the simulation holds
    the ground down to it) and forces by F0 = γ0 d² w (w = ``blade.width``,
    1 in plane strain: F0 is the unit of ``force_norm``).

    **Episode.** :meth:`reset` puts the blade on flat ground with its tip
    at a start depth and no travel made. Each :meth:`step` advances the
    blade by ``step_travel`` (× d; the last step stops at the travel)
    with :meth:`soilcut.Simulation.advance_to`, the tip going linearly from
    its depth to depth + rate × travel of the step, clipped to
    [``depth_range``] (× d). The episode's travel is ``travel`` (× d),
    by default the case's ``run.travel``.

    **Action.** ``Box(-max_rate, max_rate, (1,), float32)``: the depth
    rate dd/du (positive deepens). Actions outside the box are clipped to
    it (gymnasium's convention for ``Box`` actions); ``info["clipped"]``
    says whether the action or the depth was clipped. A NaN raises
    ``ValueError``.

    **Observation.** ``Box(float32)`` of 5 + len(``offsets``) values:

    ======  =====================================  =================
    index   value                                  bounds
    ======  =====================================  =================
    0       P / F0, the resultant force            [0, B]
    1       P_h / F0, the draft (horizontal)       [-B, B]
    2       P_v / F0, vertical, positive upward    [-B, B]
    3       tip depth / d                          ``depth_range``
    4       travel made / episode travel           [0, 1]
    5...    ground height y / d at ``offsets``     [-1, B]
            × d ahead of the face (y = 0 is the
            original ground; the centreline)
    ======  =====================================  =================

    The forces are those of the step's last increment (0 after
    :meth:`reset`, before the blade has moved). B =
    ``OBSERVATION_BOUND`` (1000), far beyond any cut in range; a value
    beyond a bound is clipped to it.

    **Reward.** Soil moved per unit of work over the step, less a penalty
    above the force limit::

        reward = d · M / W − overload_penalty · max(0, P_h,max / P_limit − 1)

    with M = γ0 w Σ depth·v0 the weight of soil the tip has cut loose (the
    area swept below the original ground, ∫ depth du, times γ0 and the
    width; with ``blade.width`` the soil that spills around the edges
    counts as moved too), W = Σ P_h·v0 the work of the draft over the
    step's increments (v0 = ``run.increment``), P_h,max the largest draft
    of the step's increments and P_limit = ``force_limit`` × F0. d · M / W
    is dimensionless (the inverse of the specific energy of cutting,
    scaled by γ0 d; 0 if W ≤ 0).

    **Termination.** ``terminated`` when the episode's travel is reached,
    or when an increment has no admissible mechanism
    (:class:`soilcut.StepError`): the episode then ends with the reward
    ``-failure_penalty`` and ``info["error"]`` holds the message; ``info``
    and the observation count the step's increments made before the one
    that failed.
    ``truncated`` is never set by the environment (wrap it in a
    ``TimeLimit`` for that). A step after the end raises ``RuntimeError``.

    **Seeding.** ``reset(seed=...)`` draws, from the environment's
    generator, the start depth uniformly in ``start_depth`` (× d) and the
    ensembles' imperceptible perturbation (``docs/model.md`` §12.1):
    ``blade.wall_friction`` + 0.01° k in the original model, ``soil.d50``
    (or ``soil.band_width``) × (1 + 0.001 k) in the refined one, with k
    uniform in [-3, 3]. ``options={"depth": x}`` sets the start depth (× d)
    instead, ``options={"perturb": False}`` runs the case unperturbed. The
    same seed gives the same episode bit for bit.

    ``info`` holds ``u`` (the blade's displacement), ``depth`` (length),
    ``soil_moved`` (M), ``work`` (W), ``max_force_h`` (P_h,max),
    ``clipped`` and, after a failure, ``error``.
    """

    metadata: dict[str, Any] = {"render_modes": []}

    def __init__(
        self,
        case: Case | PathLike | None = None,
        *,
        travel: float | None = None,
        step_travel: float = 0.1,
        max_rate: float = 0.5,
        depth_range: tuple[float, float] = (0.4, 1.0),
        start_depth: tuple[float, float] = (0.5, 1.0),
        force_limit: float = 12.0,
        overload_penalty: float = 1.0,
        failure_penalty: float = 1.0,
        offsets: Sequence[float] = (0.25, 0.5, 1.0, 1.5, 2.0, 3.0),
    ) -> None:
        """The environment for ``case`` (a vertical blade, as a
        :class:`Case` or a case file's path or text; by default
        :func:`default_case`). Lengths are in units of d = ``blade.depth``:
        ``travel`` (the episode's; None: the case's ``run.travel``),
        ``step_travel``, ``depth_range`` (the depths the tip may be
        steered to, at most 1: the simulation holds ground down to d),
        ``start_depth`` (the range reset draws from) and ``offsets`` (where
        the ground ahead of the face is observed); ``max_rate`` bounds the
        action, dd/du; ``force_limit`` is in units of F0 = γ0 d² w;
        ``overload_penalty`` and ``failure_penalty`` scale the reward's
        penalties. Raises ``ValueError`` for an inclined blade or arguments
        out of range, :class:`soilcut.CaseError` (a ``ValueError``) for a
        ``depth_range`` too shallow for the case (its lower end must exceed
        ``run.increment`` and the band width)."""
        self.case = default_case() if case is None else case_of(case)
        resolved = self.case.resolved()
        if resolved["blade.rake"] != 90.0:
            raise ValueError("CuttingEnv steers the tip's depth, which needs blade.rake = 90")
        self.d = float(resolved["blade.depth"])
        self.v0 = float(resolved["run.increment"])
        width = resolved.to_dict()["blade"].get("width")
        self.width = 1.0 if width is None else float(width)
        self.gamma0 = float(resolved["soil.unit_weight"])
        self.f0 = self.gamma0 * self.d**2 * self.width
        self.travel = float(resolved["run.travel"]) if travel is None else travel * self.d
        self.step_travel = step_travel * self.d
        lo, hi = depth_range
        if not 0 < lo <= hi <= 1:
            raise ValueError(
                f"depth_range must satisfy 0 < low <= high <= 1 (× blade.depth), got {depth_range}"
            )
        if not lo <= start_depth[0] <= start_depth[1] <= hi:
            raise ValueError(f"start_depth {start_depth} must lie within depth_range {depth_range}")
        if not (max_rate > 0 and self.step_travel > 0 and self.travel > 0 and force_limit > 0):
            raise ValueError("max_rate, step_travel, travel and force_limit must be > 0")
        self.depth_range = (lo * self.d, hi * self.d)
        self.case.set("blade.depth_path", [[0.0, lo * self.d]])  # validates the shallowest
        self.start_depth = start_depth
        self.force_limit = force_limit * self.f0
        self.overload_penalty = overload_penalty
        self.failure_penalty = failure_penalty
        self.offsets = np.asarray(offsets, dtype=float)

        self.action_space = spaces.Box(-max_rate, max_rate, shape=(1,), dtype=np.float32)
        n = len(self.offsets)
        big = OBSERVATION_BOUND
        low = np.array([0.0, -big, -big, lo, 0.0] + [-1.0] * n, dtype=np.float32)
        high = np.array([big, big, big, hi, 1.0] + [big] * n, dtype=np.float32)
        self.observation_space = spaces.Box(low, high, dtype=np.float32)
        self.sim: Simulation | None = None
        self._last: Step | None = None
        self._steps = 0
        self._ended = False

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """A new episode on flat ground (see the class's Seeding)."""
        super().reset(seed=seed)
        options = options or {}
        draw = self.np_random.uniform(*self.start_depth)
        k = self.np_random.uniform(-3.0, 3.0)
        depth = float(options.get("depth", draw)) * self.d
        lo, hi = self.depth_range
        if not lo <= depth <= hi:
            raise ValueError(f"options['depth'] = {depth / self.d} is outside depth_range")
        # The start depth replaces any depth path of the case: the actions
        # steer the tip from there.
        changes: dict[str, Any] = {"run.travel": self.travel, "blade.depth_path": [[0.0, depth]]}
        if options.get("perturb", True):
            key, value = _soilcut.perturbation(native_of(self.case), float(k))
            changes[key] = value
        self.sim = Simulation(self.case.update(changes))
        self._last = None
        self._steps = 0
        self._ended = False
        info = {"u": 0.0, "depth": depth, "soil_moved": 0.0, "work": 0.0}
        return self._observation(), info

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """Advances the blade by ``step_travel`` at the depth rate
        ``action`` (see the class's docstring)."""
        if self.sim is None:
            raise RuntimeError("call reset() before step()")
        if self._ended:
            raise RuntimeError("the episode has ended: call reset()")
        given = np.asarray(action, dtype=float)
        if given.shape not in ((1,), ()):
            raise ValueError(
                f"action: expected one depth rate (shape (1,), as action_space), got shape "
                f"{given.shape}"
            )
        rate = float(given.reshape(-1)[0])
        if math.isnan(rate):
            raise ValueError("the action (a depth rate) is NaN")
        bound = float(self.action_space.high[0])
        clipped = abs(rate) > bound
        rate = min(max(rate, -bound), bound)
        self._steps += 1
        # Targets on a fixed grid from u = 0, so that rounding to whole
        # increments (advance_to's rule) does not accumulate.
        x = min(self._steps * self.step_travel, self.travel)
        u0 = self.sim.blade_position
        wanted = self.sim.tip_depth + rate * (x - u0)
        lo, hi = self.depth_range
        depth = min(max(wanted, lo), hi)
        clipped = clipped or depth != wanted
        info: dict[str, Any] = {"clipped": clipped}
        try:
            records = self.sim.advance_to(x, depth=depth)
            error = None
        except StepError as failure:
            # The increments before the failed one were made: their records
            # come with the error, and the episode ends here.
            records, error = failure.steps, str(failure)
        moved = self.gamma0 * self.width * sum(r.depth for r in records) * self.v0
        work = sum(r.force_h for r in records) * self.v0
        peak = max((r.force_h for r in records), default=0.0)
        if records:
            self._last = records[-1]
        info.update(
            u=self.sim.blade_position,
            depth=self.sim.tip_depth,
            soil_moved=moved,
            work=work,
            max_force_h=peak,
        )
        if error is not None:
            info["error"] = error
            self._ended = True
            return self._observation(), -float(self.failure_penalty), True, False, info
        efficiency = self.d * moved / work if work > 0 else 0.0
        overload = max(0.0, peak / self.force_limit - 1.0)
        reward = efficiency - self.overload_penalty * overload
        terminated = self.sim.blade_position >= self.travel * (1 - 1e-12)
        self._ended = terminated
        return self._observation(), float(reward), bool(terminated), False, info

    def _observation(self) -> np.ndarray:
        sim = self.sim
        assert sim is not None
        last = self._last
        forces = (0.0, 0.0, 0.0) if last is None else (last.force, last.force_h, last.force_v)
        surface = sim.surface()
        ahead = sim.blade_position + self.offsets * self.d
        heights = np.interp(ahead, surface["x"], surface["y"]) / self.d
        done = min(sim.blade_position / self.travel, 1.0)
        values = [f / self.f0 for f in forces] + [sim.tip_depth / self.d, done]
        obs = np.concatenate([values, heights]).astype(np.float32)
        # float32 rounding may put a value on a bound a hair outside it.
        return np.clip(obs, self.observation_space.low, self.observation_space.high)


gymnasium.register(id=ENV_ID, entry_point=CuttingEnv)
