"""A controller's tick from Python (issue 39): ``Simulation.advance_to``
by d/1000 of travel on the pile developed over the first 3 d, the way a
controller or the gym environment drives the blade.

For each case at its defaults, a simulation is developed to u = 3 d once
and copied for every repetition; each repetition makes ``--ticks`` calls
of ``advance_to(u + d/1000)``, unsteered (``depth=None``) and steered (the
tip 0.1 % shallower each tick, a depth path made and checked every call).
An increment (d/350 at the defaults) is computed every third or fourth
tick, so the mean tick is about a third of an increment and the worst is
one whole increment; the steered ticks between increments hold their
depth for the next one. Prints the mean and the worst tick, µs: the least of
each over the repetitions, as on a shared machine the least is the least
disturbed: a machine shared with other work preempts the process for
whole scheduler slices (4 ms and more), which the worst tick then shows.

    python python/benches/control_tick.py [--ticks 600] [--repeat 5]
"""

from __future__ import annotations

import argparse
import copy
import pathlib
import platform
import time

import soilcut

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = ["paper/fig5.toml", "paper/table1-hs.toml"]


def ticks(developed: soilcut.Simulation, n: int, steered: bool, d: float) -> tuple[float, float]:
    """Mean and worst of ``n`` ticks on a copy of ``developed``, µs."""
    sim = copy.copy(developed)
    depth = d
    worst = 0.0
    # The controller's own clock: the blade asked to u + k d/1000, which
    # the simulation reaches by whole increments.
    x = sim.blade_position
    start = time.perf_counter()
    for _ in range(n):
        x += d / 1000
        if steered:
            depth *= 0.999
        # A new depth at every tick: one between increments is held for
        # the next increment (docs/model.md §17.2).
        begin = time.perf_counter()
        sim.advance_to(x, depth if steered else None)
        worst = max(worst, time.perf_counter() - begin)
    return 1e6 * (time.perf_counter() - start) / n, 1e6 * worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--ticks", type=int, default=600)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    python = platform.python_version()
    print(f"Python {python}, {args.ticks} ticks of d/1000, least of {args.repeat}")
    print("| case | tick | mean (µs) | worst (µs) |")
    print("|---|---|---|---|")
    for name in CASES:
        case = soilcut.Case.from_file(ROOT / "cases" / name)
        d = case["blade.depth"]
        developed = soilcut.Simulation(case)
        developed.advance_to(3 * d)
        for steered in (False, True):
            runs = [ticks(developed, args.ticks, steered, d) for _ in range(args.repeat)]
            mean = min(r[0] for r in runs)
            worst = min(r[1] for r in runs)
            label = "steered" if steered else "unsteered"
            print(f"| {name} | {label} | {mean:.1f} | {worst:.0f} |")


if __name__ == "__main__":
    main()
