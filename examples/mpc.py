"""Model-predictive depth control of a tine from snapshots.

From a developed pile (the tine of cases/tools/tine.toml has cut 2 d at a
constant depth), plan the tip's depth: at each planning step, copy the
simulation once per candidate depth rate, run each copy over the horizon
(d of travel, the tip going linearly at that rate), score it by the soil
moved per unit of work and reject it if its draft exceeds the force limit,
then apply the best candidate's first half (d/2) and plan again (if no
candidate is admissible, the one of the least draft). The same travel cut
at the constant start depth is the baseline.

    soil moved  M = γ0 w ∫ depth du    (the soil the tip cuts loose; the
                                        soil spilled around the tine counts)
    work        W = ∫ P_h du           (the draft times the travel)
    objective   d · M / W              (dimensionless)

Both integrals are sums over the increments' records (depth, force_h) times
run.increment. The copies are ``copy.copy`` of a ``soilcut.Simulation``
(a snapshot restored: each continues bit for bit as the original would).

    python examples/mpc.py                 # 3 d planned, 7 rates
    python examples/mpc.py --quick         # 1 d planned, 3 rates (the tests)
    python examples/mpc.py --out mpc.png   # the picture's path

SOILCUT_MPC_QUICK=1 in the environment is --quick. Prints a table of the
planning steps and saves a picture (default: mpc.png next to this script)
of the chosen depth path and its draft against the baseline's.
"""

from __future__ import annotations

import argparse
import copy
import os
import pathlib
from dataclasses import dataclass, field

import numpy as np

import soilcut

HERE = pathlib.Path(__file__).resolve().parent
TINE = HERE.parent / "cases" / "tools" / "tine.toml"

D = 150.0  # blade.depth of the tine (mm): the reference and deepest depth
START = 0.7 * D  # the depth of the developed pile and of the baseline
DEPTHS = (0.4 * D, D)  # the depths the planner may steer to
FORCE_LIMIT = 12.0  # the largest admissible draft, in units of F0 = γ0 d² w


@dataclass
class Path:
    """The increments of a depth path: u, depth and draft, and M and W."""

    u: list[float] = field(default_factory=list)
    depth: list[float] = field(default_factory=list)
    force_h: list[float] = field(default_factory=list)

    def extend(self, records: list[soilcut.Step]) -> Path:
        for r in records:
            self.u.append(r.u)
            self.depth.append(r.depth)
            self.force_h.append(r.force_h)
        return self

    def moved(self, gamma0: float, width: float, v0: float) -> float:
        return gamma0 * width * sum(self.depth) * v0

    def work(self, v0: float) -> float:
        return sum(self.force_h) * v0

    def peak(self) -> float:
        return max(self.force_h, default=0.0)


def tine() -> soilcut.Case:
    """The tine at d/100 (1.5 mm increments; the original model's default
    d/250 takes 2.5 times as many, the picture the same to the eye), its tip
    at START."""
    case = soilcut.Case.from_file(TINE)
    return case.update({"run.increment": D / 100, "blade.depth_path": [[0.0, START]]})


def run(quick: bool, out: pathlib.Path) -> dict:
    """Plans, prints the table, saves the picture; returns the figures."""
    case = tine()
    v0 = case["run.increment"]
    gamma0, width = case["soil.unit_weight"], case["blade.width"]
    f0 = gamma0 * D**2 * width
    limit = FORCE_LIMIT * f0
    rates = [-0.5, 0.0, 0.5] if quick else list(np.linspace(-0.5, 0.5, 7))
    planned = 1.0 * D if quick else 3.0 * D
    horizon, applied = D, D / 2

    def objective(p: Path) -> float:
        work = p.work(v0)
        return D * p.moved(gamma0, width, v0) / work if work > 0 else 0.0

    sim = soilcut.Simulation(case)
    sim.advance_to(2.0 * D)  # the developed pile
    u_start = sim.blade_position
    baseline = Path().extend(copy.copy(sim).advance_to(u_start + planned, depth=START))

    chosen, tried = Path(), []
    print(
        f"planning {planned / D:g} d from u = {u_start / D:g} d: {len(rates)} rates, horizon"
        f" {horizon / D:g} d, {applied / D:g} d applied, draft limit {FORCE_LIMIT:g} F0"
    )
    print(" u/d    depth/d  rate   d·M/W   peak P_h/F0  admissible")
    while sim.blade_position < u_start + planned - 1e-9:
        u0, d0 = sim.blade_position, sim.tip_depth
        best = None
        admissible = 0
        for rate in rates:
            target = float(np.clip(d0 + rate * horizon, *DEPTHS))
            branch = copy.copy(sim)
            first = branch.advance_to(u0 + applied, depth=d0 + (target - d0) / 2)
            kept = copy.copy(branch)  # the state after the part to apply
            rest = branch.advance_to(u0 + horizon, depth=target)
            path = Path().extend(first + rest)
            tried.append((rate, path))
            ok = path.peak() <= limit
            admissible += ok
            # The best admissible score; without one, the least draft.
            key = (ok, objective(path) if ok else -path.peak())
            if best is None or key > best[0]:
                best = (key, rate, kept, first, path)
        _, rate, sim, first, path = best
        chosen.extend(first)
        print(
            f"{u0 / D:5.2f}  {d0 / D:7.3f}  {rate:+5.2f}  {objective(path):6.4f}"
            f"  {path.peak() / f0:11.3f}  {admissible}/{len(rates)}"
        )

    figures = {
        "objective": objective(chosen),
        "baseline_objective": objective(baseline),
        "peak": chosen.peak() / f0,
        "baseline_peak": baseline.peak() / f0,
        "limit": FORCE_LIMIT,
        "u": np.array(chosen.u),
        "depth": np.array(chosen.depth),
        "baseline_u": np.array(baseline.u),
        "picture": out,
    }
    print(
        f"planned:  d·M/W = {figures['objective']:.4f}, peak draft {figures['peak']:.3f} F0\n"
        f"constant: d·M/W = {figures['baseline_objective']:.4f}, "
        f"peak draft {figures['baseline_peak']:.3f} F0 (depth {START / D:g} d)"
    )
    picture(chosen, baseline, tried, f0, out)
    print(f"picture: {out}")
    return figures


def picture(chosen: Path, baseline: Path, tried: list, f0: float, out: pathlib.Path) -> None:
    """The chosen depth path over the candidates tried, and the drafts."""
    import matplotlib

    matplotlib.use("Agg")  # no display: the tests and CI write files only
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for _, p in tried:
        top.plot(np.array(p.u) / D, np.array(p.depth) / D, color="0.8", lw=0.8)
    top.plot(np.array(baseline.u) / D, np.array(baseline.depth) / D, "k--", label="constant")
    top.plot(np.array(chosen.u) / D, np.array(chosen.depth) / D, "C0", lw=2, label="planned")
    top.invert_yaxis()
    top.set_ylabel("tip depth / d")
    top.legend(loc="lower left")
    top.set_title("Planned depth path (grey: candidates tried)")
    bottom.plot(np.array(baseline.u) / D, np.array(baseline.force_h) / f0, "k--", lw=0.8)
    bottom.plot(np.array(chosen.u) / D, np.array(chosen.force_h) / f0, "C0", lw=1)
    bottom.axhline(FORCE_LIMIT, color="C3", label="limit")
    bottom.set_xlabel("u / d")
    bottom.set_ylabel("draft $P_h$ / ($\\gamma_0 d^2 w$)")
    bottom.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv: list[str] | None = None) -> dict:
    """The command line; returns :func:`run`'s figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1 d planned with 3 rates")
    parser.add_argument("--out", type=pathlib.Path, default=HERE / "mpc.png")
    args = parser.parse_args(argv)
    # The picture is drawn last: without matplotlib, say so before planning.
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        parser.error("draws its picture with matplotlib: pip install matplotlib")
    quick = args.quick or os.environ.get("SOILCUT_MPC_QUICK") == "1"
    return run(quick, args.out)


if __name__ == "__main__":
    main()
