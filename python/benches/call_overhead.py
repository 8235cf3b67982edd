"""What the package adds around the engine: the cost of the calls a
notebook or a sweep driver makes on a case, and of a run's result.

Times, per call, the least over several repetitions (each repetition makes
the same calls, so the least is the least disturbed): ``Case.set`` of one
key, reading a key (``case["soil.repose"]``), and ``soilcut.run`` of a case
of one increment (so the engine's own work is small beside the package's:
parsing the case, handing out the result). Run it against two builds
of the package to compare them: the ratio of two figures of one run is what
to quote on a shared machine.

    python python/benches/call_overhead.py [--repeat 20] [--calls 200]
"""

from __future__ import annotations

import argparse
import pathlib
import platform
import time

import soilcut

ROOT = pathlib.Path(__file__).resolve().parents[2]


def per_call(body, calls: int, repeat: int) -> float:
    """The least over ``repeat`` of the mean time of ``calls`` calls, µs."""
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(calls):
            body()
        best = min(best, (time.perf_counter() - start) / calls)
    return 1e6 * best


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("--calls", type=int, default=200)
    args = parser.parse_args()
    case = soilcut.Case.from_file(ROOT / "cases/paper/original.toml")
    d = case["blade.depth"]
    one = case.update({"run.increment": 1.0, "run.travel": 1.0, "run.vertex_spacing": d / 20})
    rows = [
        ('`case.set("soil.repose", 31)`', lambda: case.set("soil.repose", 31)),
        ('`case["soil.repose"]`', lambda: case["soil.repose"]),
        ("`soilcut.run(case)`, 1 increment at d/20", lambda: soilcut.run(one)),
    ]
    print(
        f"soilcut {soilcut.__version__}, python {platform.python_version()}, best of {args.repeat}"
    )
    print("| call | µs per call |")
    print("|---|---|")
    for name, body in rows:
        calls = max(1, args.calls // 10) if "run" in name else args.calls
        print(f"| {name} | {per_call(body, calls, args.repeat):.1f} |")


if __name__ == "__main__":
    main()
