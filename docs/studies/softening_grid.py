#!/usr/bin/env python3
"""Why the coarse node grid needs soil that does not soften (docs/model.md §9).

Runs Table 1 S as shipped, without its softening (φr = φp = 35°) and without
its dilation (ψ = 0), each on the reference grid at d/1000 (the converged
value here) and at node spacing h = d/100 and d/200 with k = h / v0 = 1, 2,
5, 10 increments per node, and prints, for each run, the largest deviation
of a unit-window mean of P/(γ0 d²) from the converged one and every
window's deviation, in %. Standard library only:

    python3 docs/studies/softening_grid.py --soilcut target/release/soilcut --out DIR
"""

import argparse
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from time_to_accuracy import deviation, wall_time, window_means  # noqa: E402

CASE = Path("cases/paper/table1-s.toml")
DEPTH = 20.0
VARIANTS = {
    "as shipped": [],
    "no softening (φr = φp)": ["soil.friction.residual=35.0"],
    "no dilation (ψ = 0)": ["soil.dilation={initial=0.0,peak=0.0,residual=0.0}"],
}
# (d/h, k)
GRIDS = [(100, 1), (100, 2), (100, 5), (100, 10), (200, 1), (200, 2), (200, 5)]


def run(soilcut, folder, per_v0, per_h, sets):
    if not (folder / "history.csv").exists():
        cmd = [soilcut, "run", str(CASE), "--out", str(folder), "--force", "--quiet", "--no-plots"]
        cmd += [
            "--set",
            f"run.increment={DEPTH / per_v0!r}",
            "--set",
            f"run.node_spacing={DEPTH / per_h!r}",
        ]
        for s in sets:
            cmd += ["--set", s]
        subprocess.run(cmd, check=True)
    return folder


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", default="out/softening-grid")
    a = p.parse_args()
    out = Path(a.out)
    print("| soil | d/h | k = h/v0 | largest deviation | per window | time |")
    print("|---|---|---|---|---|---|")
    for i, (name, sets) in enumerate(VARIANTS.items()):
        converged = window_means(run(a.soilcut, out / f"{i}-converged", 1000, 1000, sets))
        for per_h, k in GRIDS:
            folder = run(a.soilcut, out / f"{i}-{per_h}-{k}", per_h * k, per_h, sets)
            means = window_means(folder)
            windows = " ".join(f"{(m / c - 1) * 100:+.2f}" for m, c in zip(means, converged))
            dev = deviation(means, converged)
            print(
                f"| {name} | {per_h} | {k} | {dev:.2f} % | {windows} | {wall_time(folder):.2f} s |",
                flush=True,
            )


if __name__ == "__main__":
    main()
