#!/usr/bin/env python3
"""Time to accuracy of the two node grids (docs/performance.md).

For each paper case, runs soilcut on the reference grid (node spacing h equal
to the increment v0) and on coarse grids (h a whole multiple of v0), and
compares every unit-window mean of P/(γ0 d²) (u/d in [0, 1), [1, 2), ...)
with a converged run: the reference grid at d/2000 (`--converged`).

    python3 docs/studies/time_to_accuracy.py --soilcut target/release/soilcut --out DIR

writes runs.csv (one row per run: case, scheme, d/v0, d/h, wall_time_s, the
largest window deviation in %) and table.md (for each case and scheme, the
fastest run within 5, 2, 1 and 0.5 % of every converged window mean). Runs
are kept under OUT/runs/ (or --runs) unless --clean; an existing run is
reused. Standard library only.
"""

import argparse
import csv
import json
import shutil
import subprocess
import sys
from pathlib import Path

CASES = ["original", "table1-s", "fig8b", "table1-hs", "fig5"]
REFERENCE = [100, 200, 500, 1000]
# (d/v0, d/h) with h a whole multiple of v0.
COARSE = [
    (200, 25),
    (200, 50),
    (500, 25),
    (500, 50),
    (500, 100),
    (1000, 25),
    (1000, 50),
    (1000, 100),
    (1000, 200),
    (2000, 50),
    (2000, 100),
    (2000, 200),
]
THRESHOLDS = [5.0, 2.0, 1.0, 0.5]


def depth_of(case: Path) -> float:
    for line in case.read_text().splitlines():
        key, _, value = line.partition("=")
        if key.strip() == "depth":
            return float(value.split("#")[0])
    raise SystemExit(f"{case}: no blade depth")


def run(soilcut, case, depth, per_v0, per_h, folder):
    if not (folder / "history.csv").exists():
        cmd = [
            soilcut,
            "run",
            str(case),
            "--set",
            f"run.increment={depth / per_v0!r}",
            "--set",
            f"run.node_spacing={depth / per_h!r}",
            "--out",
            str(folder),
            "--force",
        ]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return folder


def window_means(folder):
    sums, counts = {}, {}
    with open(folder / "history.csv", newline="") as f:
        for row in csv.DictReader(f):
            w = int(float(row["u_over_d"]))
            sums[w] = sums.get(w, 0.0) + float(row["force_norm"])
            counts[w] = counts.get(w, 0) + 1
    return [sums[w] / counts[w] for w in sorted(sums)]


def wall_time(folder):
    return json.loads((folder / "summary.json").read_text())["wall_time_s"]


def deviation(means, converged):
    return max(abs(m / c - 1.0) * 100.0 for m, c in zip(means, converged))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", default="out/time-to-accuracy")
    p.add_argument("--cases", default=",".join(CASES))
    p.add_argument("--converged", type=int, default=2000, help="d/v0 of the converged run")
    p.add_argument("--runs", help="folder for the runs (default OUT/runs)")
    p.add_argument("--clean", action="store_true", help="delete the runs afterwards")
    a = p.parse_args()
    out = Path(a.out)
    runs = Path(a.runs) if a.runs else out / "runs"
    runs.mkdir(parents=True, exist_ok=True)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name in a.cases.split(","):
        case = Path("cases/paper") / f"{name}.toml"
        d = depth_of(case)
        conv = run(a.soilcut, case, d, a.converged, a.converged, runs / f"{name}-ref-{a.converged}")
        converged = window_means(conv)
        settings = [("reference", n, n) for n in REFERENCE] + [("coarse", v, h) for v, h in COARSE]
        for scheme, per_v0, per_h in settings:
            folder = run(a.soilcut, case, d, per_v0, per_h, runs / f"{name}-{per_v0}-{per_h}")
            dev = deviation(window_means(folder), converged)
            rows.append([name, scheme, per_v0, per_h, wall_time(folder), dev])
            print(
                f"{name} {scheme} d/{per_v0} h=d/{per_h}: {dev:.2f} % in {wall_time(folder):.3f} s",
                file=sys.stderr,
            )
    with open(out / "runs.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(
            [
                "case",
                "scheme",
                "d_over_increment",
                "d_over_node_spacing",
                "wall_time_s",
                "max_window_deviation_pct",
            ]
        )
        w.writerows(rows)
    (out / "table.md").write_text(table(rows))
    if a.clean:
        shutil.rmtree(runs)


def table(rows):
    lines = [
        "| case | scheme | " + " | ".join(f"≤ {t} %" for t in THRESHOLDS) + " |",
        "|---|---|" + "---|" * len(THRESHOLDS),
    ]
    for name in dict.fromkeys(r[0] for r in rows):
        for scheme in ["reference", "coarse"]:
            cells = []
            for t in THRESHOLDS:
                ok = [r for r in rows if r[0] == name and r[1] == scheme and r[5] <= t]
                if ok:
                    best = min(ok, key=lambda r: r[4])
                    cells.append(f"{best[4]:.3f} s (d/{best[2]}, h = d/{best[3]})")
                else:
                    cells.append("not reached")
            lines.append(f"| {name} | {scheme} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
