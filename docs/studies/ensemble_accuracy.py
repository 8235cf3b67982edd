#!/usr/bin/env python3
"""Time to accuracy in the ensemble sense (docs/performance.md, docs/model.md §12).

For each paper case and the tine and dozer of cases/tools/, runs an ensemble
of 7 perturbed runs (`soilcut run --ensemble 7`) for each scheme below, and
for the case as shipped (scheme "defaults": the increment, node spacing and
search its class of case defaults to, docs/model.md §9), and judges it
against the reference grid's ensemble at d/2000 with `soilcut accuracy`
(the rule: every unit-window ensemble mean within clamp(2 standard
errors of the difference, 1 %, 2.5 %), the whole-run mean within 1 %).

    python3 docs/studies/ensemble_accuracy.py --soilcut target/release/soilcut --out DIR

writes DIR/runs.csv (one row per case and scheme: d/v0, d/h, the median
member wall time, the whole-run ensemble mean and standard deviation, the
worst window's |deviation| / tolerance and the verdict) and DIR/table.md.
Ensembles are kept under DIR/runs/ (or --runs) and reused when present.
Standard library only.
"""

import argparse
import csv
import json
import statistics
import subprocess
from pathlib import Path

import tomllib
from time_to_accuracy import depth_of  # the same folder: the case file's blade depth

# The paper's cases (cases/paper/) and the tools of finite width whose soil
# softens (cases/tools/).
CASES = ["original", "table1-s", "fig8b", "table1-hs", "fig5", "tools/tine", "tools/dozer"]
REFERENCE = 2000
DEFAULTS = "defaults"
# (name, d/v0, d/h, run.samples_per_band): the reference grid (h = v0) and
# the coarse grid, with the exhaustive search (0) or the sampled one.
SCHEMES = [
    ("reference d/250", 250, 250, 0),
    ("reference d/500", 500, 500, 0),
    ("reference d/750", 750, 750, 0),
    ("reference d/1000", 1000, 1000, 0),
    ("coarse d/500, h d/25", 500, 25, 0),
    ("coarse d/1000, h d/25", 1000, 25, 0),
    ("sampled d/1000", 1000, 1000, 8),
    ("sampled d/1250", 1250, 1250, 8),
    ("sampled d/1500", 1500, 1500, 8),
    ("coarse d/1250, h d/25", 1250, 25, 8),
    ("coarse d/1500, h d/25", 1500, 25, 8),
    # The case as shipped: its increment, node spacing and search are the
    # defaults for its class of case (docs/model.md §9, issue 28), read
    # back from the run's case.resolved.toml.
    (DEFAULTS, None, None, None),
]


def ensemble(soilcut, case, depth, scheme, folder, jobs):
    """The ensemble folder, run unless it exists."""
    per_v0, per_h, samples = scheme
    if not (folder / "ensemble.csv").exists():
        cmd = [soilcut, "run", str(case), "--ensemble", "7", "--jobs", str(jobs)]
        if per_v0 is not None:
            v0 = depth / per_v0
            h = v0 * round((depth / per_h) / v0)
            cmd += ["--set", f"run.increment={v0!r}", "--set", f"run.node_spacing={h!r}"]
            cmd += ["--set", f"run.samples_per_band={samples}"]
        cmd += ["--no-plots", "--quiet", "--force", "--out", str(folder)]
        subprocess.run(cmd, check=True)
    return folder


def resolved_grid(folder, depth):
    """d/v0, d/h (of the vertices on the vertex ground, else of the nodes),
    run.samples_per_band and the defaults' label of the ensemble's middle
    member, as its case.resolved.toml gives them."""
    resolved = tomllib.loads((folder / "k+0" / "case.resolved.toml").read_text())
    run = resolved["run"]
    per_v0 = round(depth / run["increment"])
    vertices = run.get("vertex_spacing", 0.0)
    spacing, ground = (vertices, "vertices") if vertices > 0 else (run["node_spacing"], "h")
    per_h, samples = round(depth / spacing), round(run["samples_per_band"])
    # A slip line (the original model) has no band width to sample.
    search = "exhaustive" if resolved["model"] == "original" else f"K {samples}"
    label = f"{DEFAULTS} (d/{per_v0}, {ground} d/{per_h}, {search}"
    if run.get("time_scheme", "explicit") != "explicit":
        label += f", {run['time_scheme']}"
    return per_v0, per_h, samples, label + ")"


def median_wall_time(folder):
    with open(folder / "timing.csv") as f:
        return statistics.median(float(r["wall_time_s"]) for r in csv.DictReader(f))


def judge(soilcut, folder, reference):
    out = subprocess.run(
        [soilcut, "accuracy", str(folder), str(reference), "--json"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return json.loads(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", type=Path, default=Path("docs/studies/ensemble-accuracy"))
    p.add_argument("--runs", type=Path, help="where the ensembles go [OUT/runs]")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--cases", nargs="*", default=CASES)
    p.add_argument(
        "--schemes", nargs="*", help="only the schemes of these names (the table keeps the others)"
    )
    args = p.parse_args()
    runs = args.runs or args.out / "runs"
    rows = []
    for name in args.cases:
        case = Path("cases") / (name if "/" in name else f"paper/{name}")
        case = case.with_suffix(".toml")
        d = depth_of(case)
        reference = (REFERENCE, REFERENCE, 0)
        ref = ensemble(args.soilcut, case, d, reference, runs / name / "ref-d2000", args.jobs)
        ref_time = median_wall_time(ref)
        ref_mean = json.loads((ref / "summary.json").read_text())["mean_force_norm"]
        rows.append(
            [name, f"reference d/{REFERENCE}", REFERENCE, REFERENCE, 0, ref_time]
            + [ref_mean["mean"], ref_mean["std"], 0.0, "reference"]
        )
        for scheme, per_v0, per_h, samples in SCHEMES:
            if per_v0 is None:
                tag = DEFAULTS
            else:
                tag = f"v{per_v0}-h{per_h}" + (f"-s{samples}" if samples else "")
            if args.schemes and scheme not in args.schemes and not (runs / name / tag).exists():
                continue
            folder = runs / name / tag
            folder = ensemble(args.soilcut, case, d, (per_v0, per_h, samples), folder, args.jobs)
            if per_v0 is None:
                per_v0, per_h, samples, scheme = resolved_grid(folder, d)
            verdict = judge(args.soilcut, folder, ref)
            whole = json.loads((folder / "summary.json").read_text())["mean_force_norm"]
            rows.append(
                [name, scheme, per_v0, per_h, samples, median_wall_time(folder)]
                + [whole["mean"], whole["std"], verdict["worst_ratio"]]
                + ["yes" if verdict["accurate"] else "no"]
            )
    write(args.out, rows)


def write(out, rows):
    out.mkdir(parents=True, exist_ok=True)
    header = ["case", "scheme", "d_over_v0", "d_over_h", "samples_per_band"]
    header += ["median_member_wall_time_s"]
    header += ["mean_force_norm", "std_force_norm", "worst_deviation_over_tolerance", "accurate"]
    with open(out / "runs.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    lines = [
        "| case | scheme | median wall time a member (s) | whole-run mean ± sd "
        "| worst deviation / tolerance | accurate |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r[0]} | {r[1]} | {r[5]:.3f} | {r[6]:.4f} ± {r[7]:.4f} | {r[8]:.2f} | {r[9]} |"
        )
    (out / "table.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
