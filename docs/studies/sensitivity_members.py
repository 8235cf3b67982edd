#!/usr/bin/env python3
"""How many members a sensitivity study's design points need (issue 52).

Runs `soilcut sensitivity` on Fig. 5 with the same Sobol design (three
keys, the same seed) at K = 1, 2, 4 and 8 members a point, and writes
into --out (docs/studies/sensitivity-members by default):

- chaos.csv: each output's chaos share c (the members' mean variance
  within a point over the variance of every run) at each K >= 2, and the
  chaos share of the ensemble mean against the design's variance,
  (c / K) / (1 - c): the part of the variance of the points' ensemble
  means, relative to what the keys put there, that the chaos still puts
  there;
- intervals.csv: each output's mean width of the 95 % intervals of S1
  and ST over the keys, at each K;
- members.md: both tables and the default K by the rule of
  docs/guide/sensitivity.md: the least K whose ensemble mean's chaos
  share is below 5 % of the design variance for every force output
  (c measured at K = 8, the best estimate);
- k1/ ... k8/: each study's summary.json, indices.csv and sensitivity.md.

Standard library only:

    python3 docs/studies/sensitivity_members.py --soilcut target/release/soilcut
"""

import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

MEMBERS = (1, 2, 4, 8)
KEYS = (
    "soil.friction.peak=35:45",
    "soil.peak_shear=1:3",
    "blade.wall_friction=5:15",
)
# The rule's bound on the ensemble mean's chaos share.
BOUND = 0.05


def study(soilcut, out, members, args):
    """Runs one study into `out`; returns its wall time in seconds."""
    command = [soilcut, "sensitivity", "cases/paper/fig5.toml", "--method", "sobol"]
    command += ["--samples", str(args.samples), "--seed", str(args.seed)]
    command += ["--members", str(members), "--jobs", str(args.jobs), "-q"]
    command += ["--out", out, "--force"]
    for key in KEYS:
        command += ["--vary", key]
    for setting in args.set:
        command += ["--set", setting]
    start = time.monotonic()
    subprocess.run(command, check=True)
    return time.monotonic() - start


def is_force(name):
    return "force_norm" in name


def interval_widths(path):
    """Mean S1 and ST interval widths by output (None where empty)."""
    widths = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if not row["S1_low"]:
                widths.setdefault(row["output"], None)
                continue
            s1 = float(row["S1_high"]) - float(row["S1_low"])
            st = float(row["ST_high"]) - float(row["ST_low"])
            widths.setdefault(row["output"], []).append((s1, st))
    return {
        name: None if w is None else tuple(sum(x) / len(w) for x in zip(*w))
        for name, w in widths.items()
    }


def ensemble_share(c, k):
    return (c / k) / (1.0 - c)


def chosen(shares):
    """The least K of the rule from each force output's share at K = 8."""
    worst = max(c for name, c in shares.items() if is_force(name) and c is not None)
    k = 1
    while ensemble_share(worst, k) >= BOUND:
        k += 1
    return k, worst


def number(x, digits=4):
    return "–" if x is None else f"{x:.{digits}f}"


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


def blank(x):
    return "" if x is None else x


def row(name, cells):
    return f"| {name} | " + " | ".join(cells) + " |"


def chaos_lines(outputs, shares):
    ks = MEMBERS[1:]
    head = [f"c, K = {m}" for m in ks] + [f"mean's, K = {m}" for m in ks]
    lines = [row("output", head), "|---|" + "---|" * len(head)]
    for name in outputs:
        cs = [shares[m][name] for m in ks]
        means = [None if c is None else ensemble_share(c, m) for c, m in zip(cs, ks)]
        lines.append(row(name, [number(x) for x in cs + means]))
    return lines


def pair(p):
    return "–" if p is None else f"{p[0]:.3f} / {p[1]:.3f}"


def interval_lines(outputs, widths):
    lines = [row("output", [f"K = {m}" for m in MEMBERS]), "|---|" + "---|" * len(MEMBERS)]
    for name in outputs:
        lines.append(row(name, [pair(widths[m][name]) for m in MEMBERS]))
    return lines


def header_lines(times, args):
    settings = ", ".join(f"`{s}`" for s in args.set)
    keys = ", ".join(f"`{k}`" for k in KEYS)
    walls = ", ".join(f"K = {m}: {times[m]:.0f} s" for m in MEMBERS)
    return [
        "# Members a design point needs: Fig. 5, three keys",
        "",
        f"Written by `python3 docs/studies/sensitivity_members.py {' '.join(sys.argv[1:])}`:",
        f"Sobol, N = {args.samples} base points, seed {args.seed}, keys {keys},",
        f"settings {settings}. Wall time: {walls} ({args.jobs} jobs).",
    ]


def report(summaries, widths, times, args):
    outputs = [o["output"] for o in summaries[MEMBERS[-1]]["outputs"]]
    shares = {
        m: {o["output"]: o["chaos_share"] for o in summaries[m]["outputs"]} for m in MEMBERS[1:]
    }
    k, worst = chosen(shares[MEMBERS[-1]])
    chaos = [
        [name, m, blank(c), "" if c is None else ensemble_share(c, m)]
        for name in outputs
        for m, c in ((m, shares[m][name]) for m in MEMBERS[1:])
    ]
    header = ["output", "members", "chaos_share", "ensemble_mean_share"]
    write_csv(os.path.join(args.out, "chaos.csv"), header, chaos)
    intervals = [[name, m, *(widths[m][name] or ("", ""))] for name in outputs for m in MEMBERS]
    header = ["output", "members", "S1_width", "ST_width"]
    write_csv(os.path.join(args.out, "intervals.csv"), header, intervals)
    lines = header_lines(times, args)
    lines += ["", "## Chaos share c (each K) and the ensemble mean's, (c / K) / (1 − c)", ""]
    lines += chaos_lines(outputs, shares)
    lines += ["", "## Mean width of the 95 % intervals over the keys, S1 / ST", ""]
    lines += interval_lines(outputs, widths)
    lines += [
        "",
        f"Rule: the least K with (c / K) / (1 − c) < {BOUND} for every force output",
        f"(`*force_norm*`), c measured at K = {MEMBERS[-1]}: the largest is {worst:.4f},",
        f"so K = {k}.",
        "",
    ]
    with open(os.path.join(args.out, "members.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--soilcut", default="target/release/soilcut")
    parser.add_argument("--out", default="docs/studies/sensitivity-members")
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument(
        "--set",
        action="append",
        default=None,
        help="a case setting for every run (default: d/50 over 5 d, vertices d/25 apart)",
    )
    args = parser.parse_args()
    if args.set is None:
        args.set = ["run.increment=0.4", "run.vertex_spacing=0.8"]
    os.makedirs(args.out, exist_ok=True)
    summaries, widths, times = {}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for m in MEMBERS:
            run = os.path.join(tmp, f"k{m}")
            times[m] = study(args.soilcut, run, m, args)
            kept = os.path.join(args.out, f"k{m}")
            os.makedirs(kept, exist_ok=True)
            for name in ("summary.json", "indices.csv", "sensitivity.md"):
                shutil.copy(os.path.join(run, name), kept)
            with open(os.path.join(run, "summary.json")) as f:
                summaries[m] = json.load(f)
            widths[m] = interval_widths(os.path.join(run, "indices.csv"))
    report(summaries, widths, times, args)


if __name__ == "__main__":
    main()
