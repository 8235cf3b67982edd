"""What Python adds to a step of the simulation.

Runs the same increments of one case twice, on fresh simulations:
``Simulation.advance(n)`` (the loop in Rust, one call) and a Python loop of
``Simulation.step()`` (one call, one record object and one release of the
interpreter per increment), and ``for step in sim``. The per-step overhead
is the difference of the totals divided by the increments; each total is
the least of several repetitions (the steps are identical every time, so
the least is the least disturbed).

    python python/benches/step_overhead.py [--repeat 30] [--increment 1.0]
"""

from __future__ import annotations

import argparse
import pathlib
import platform
import time

import soilcut

ROOT = pathlib.Path(__file__).resolve().parents[2]


def timed(case, body):
    sim = soilcut.Simulation(case)
    start = time.perf_counter()
    body(sim)
    return time.perf_counter() - start, sim.steps_done


def rust_loop(sim):
    sim.advance(sim.steps)


def python_step(sim):
    step = sim.step
    for _ in range(sim.steps):
        step()


def python_iter(sim):
    for _ in sim:
        pass


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=30)
    parser.add_argument("--increment", type=float, default=1.0)
    parser.add_argument("--travel", type=float, default=100.0)
    args = parser.parse_args()
    case = soilcut.Case.from_file(ROOT / "cases/paper/original.toml").update(
        {"run.increment": args.increment, "run.travel": args.travel}
    )
    best = {}
    for _ in range(args.repeat):
        for name, body in [("rust", rust_loop), ("step", python_step), ("iter", python_iter)]:
            seconds, steps = timed(case, body)
            best[name] = min(best.get(name, seconds), seconds)
    per = {name: 1e6 * s / steps for name, s in best.items()}
    print(
        f"case: cases/paper/original.toml, run.increment={args.increment}, "
        f"run.travel={args.travel}: {steps} increments, best of {args.repeat}"
    )
    print(f"python {platform.python_version()}, {platform.machine()}")
    print("| loop | µs per increment | Python's overhead, µs per increment |")
    print("|---|---|---|")
    print(f"| `sim.advance(n)` (Rust) | {per['rust']:.2f} | – |")
    print(f"| `sim.step()` from Python | {per['step']:.2f} | {per['step'] - per['rust']:.2f} |")
    print(f"| `for step in sim` | {per['iter']:.2f} | {per['iter'] - per['rust']:.2f} |")


if __name__ == "__main__":
    main()
