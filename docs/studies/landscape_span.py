#!/usr/bin/env python3
"""How much ground competes for the least force (issue 28, docs/performance.md).

For each case and increment, runs `soilcut landscape CASE --every E` (every
admissible candidate's force at u/d = 0, E, 2E, ...) and `soilcut run`, and
reports, over the landscapes of the run:

* the length of ground (in d, from the landscape map's d/20 bins) on which
  some candidate comes within 1 % and within 5 % of the least force: that
  ground holds candidates no exact bound can skip, whatever the
  representation, since their forces really are that close;
* the farthest such bin ahead of the blade;
* the run's candidate evaluations per increment (`summary.json`) and its
  wall time.

    python3 docs/studies/landscape_span.py --soilcut target/release/soilcut \
        --out docs/studies/landscape-span --runs out/landscape-span-runs

writes OUT/spans.csv (one row per case, increment and landscape) and
OUT/table.md. Standard library only; runs are kept under --runs and reused.
"""

import argparse
import csv
import json
import statistics
import subprocess
from collections import defaultdict
from pathlib import Path

from time_to_accuracy import depth_of  # the same folder: the case file's blade depth

CASES = ["original", "table1-s", "fig8b", "table1-hs", "fig5"]
# d / v0 of the runs: the default and twice as fine.
LEVELS = [500, 1000]
EVERY = 0.25
BIN = 0.05  # the landscape map's bin, in d
THRESHOLDS = [1.01, 1.05]


def landscape(soilcut, case, v0, folder):
    if not (folder / "landscape_map.csv").exists():
        cmd = [soilcut, "landscape", str(case), "--every", str(EVERY)]
        cmd += ["--set", f"run.increment={v0!r}", "--set", "run.ground=nodes"]
        cmd += ["--force", "--out", str(folder)]
        subprocess.run(cmd, check=True, capture_output=True)
    spans = defaultdict(lambda: {t: [] for t in THRESHOLDS})
    with open(folder / "landscape_map.csv") as f:
        for r in csv.DictReader(f):
            u, dist, ratio = (
                float(r[k]) for k in ("u_over_d", "distance_over_d", "force_over_least")
            )
            for t in THRESHOLDS:
                if ratio <= t:
                    spans[u][t].append(dist)
    return spans


def run(soilcut, case, v0, folder):
    if not (folder / "summary.json").exists():
        cmd = [soilcut, "run", str(case), "--set", f"run.increment={v0!r}"]
        cmd += ["--set", "run.ground=nodes", "--no-plots", "--quiet", "--force"]
        cmd += ["--out", str(folder)]
        subprocess.run(cmd, check=True)
    return json.loads((folder / "summary.json").read_text())


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", type=Path, default=Path("docs/studies/landscape-span"))
    p.add_argument("--runs", type=Path, help="where the runs go [OUT/runs]")
    p.add_argument("--cases", nargs="*", default=CASES)
    args = p.parse_args()
    runs = args.runs or args.out / "runs"
    rows, table = [], []
    for name in args.cases:
        case = Path("cases/paper") / f"{name}.toml"
        d = depth_of(case)
        for level in LEVELS:
            v0 = d / level
            spans = landscape(args.soilcut, case, v0, runs / name / f"landscape-d{level}")
            summary = run(args.soilcut, case, v0, runs / name / f"run-d{level}")
            per_step = summary["candidate_evaluations"] / summary["steps"]
            lengths = {t: [] for t in THRESHOLDS}
            far = []
            for u in sorted(spans):
                near = spans[u]
                for t in THRESHOLDS:
                    lengths[t].append(BIN * len(near[t]))
                far.append(max(near[THRESHOLDS[0]], default=0.0))
                rows.append([name, level, u] + [BIN * len(near[t]) for t in THRESHOLDS] + [far[-1]])
            table.append(
                [name, level, per_step, summary["wall_time_s"]]
                + [statistics.median(lengths[t]) for t in THRESHOLDS]
                + [max(lengths[THRESHOLDS[0]]), max(far)]
            )
    write(args.out, rows, table)


def write(out, rows, table):
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "spans.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "d_over_v0", "u_over_d", "span_1pc_d", "span_5pc_d", "farthest_1pc_d"])
        w.writerows(rows)
    lines = [
        "| case | d/v0 | evaluations an increment | wall time (s) | ground within 1 % (d), "
        "median | within 5 % (d), median | within 1 %, largest (d) | farthest within 1 % (d) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in table:
        lines.append(
            f"| {r[0]} | {r[1]} | {r[2]:.0f} | {r[3]:.2f} | {r[4]:.2f} | {r[5]:.2f} "
            f"| {r[6]:.2f} | {r[7]:.2f} |"
        )
    (out / "table.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
