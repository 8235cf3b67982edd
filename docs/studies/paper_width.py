#!/usr/bin/env python3
"""Does soil spilling around the blade's edges explain why soilcut's force
rises faster than the paper's curves? (issue 21, docs/reproduction.md,
"Where it differs")

The paper's experiment cut with a 360 mm blade at 25.4 mm depth, w/d = 14.2.
Plane strain keeps the whole pile in front of the blade; a blade of that
width loses part of it sideways (docs/model.md §16.5) and gains the side
crescents' force (§16.2). This runs every paper case as an ensemble of 7
perturbed members (`soilcut run --ensemble 7`, docs/model.md §12.1) in
plane strain, at the experiment's w/d = 14.2 and, to show the trend, at
w/d = 3, and writes docs/studies/paper-width/README.md and results.csv:
the unit-window ensemble means of P/(γ0 d²) (P/(γ0 d² w) with a width) with
their standard deviation over the members, the rise from the first window to
the last, and the share of the soil swept that has spilled by the end.
Standard library only:

    python3 docs/studies/paper_width.py --soilcut target/release/soilcut
"""

import argparse
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import tomllib

CASES = ["original", "fig5", "table1-hs", "table1-s", "fig8b"]
# The experiment's width over its depth, 360 mm / 25.4 mm, and a narrow blade.
WIDTHS = [None, 360.0 / 25.4, 3.0]
MEMBERS = 7
DOC = Path("docs/studies/paper-width")


def label(ratio):
    return "plane strain" if ratio is None else f"w/d = {ratio:.1f}"


def run(soilcut, case, ratio, folder):
    if not (folder / "ensemble.csv").exists():
        cmd = [soilcut, "run", case, "--out", str(folder), "--force", "--quiet", "--no-plots"]
        cmd += ["--ensemble", str(MEMBERS), "--jobs", "1"]
        if ratio is not None:
            depth = tomllib.loads(Path(case).read_text())["blade"]["depth"]
            cmd += ["--set", f"blade.width={ratio * depth!r}"]
        subprocess.run(cmd, check=True)
    return folder


def windows(folder):
    """[(mean, sd)] of the unit-window means over the members."""
    with open(folder / "ensemble.csv", newline="") as f:
        return [(float(r["mean"]), float(r["std"])) for r in csv.DictReader(f)]


def spilled(folder):
    """(mean, sd) over the members of the spilled share of the soil swept,
    γ0 d u w at the end of the run."""
    summary = json.loads((folder / "summary.json").read_text())
    shares = []
    for name in summary["perturbation"]["folders"]:
        member = folder / name
        case = tomllib.loads((member / "case.resolved.toml").read_text())
        with open(member / "history.csv", newline="") as f:
            last = list(csv.DictReader(f))[-1]
        blade, soil = case["blade"], case["soil"]
        travel = float(last["u"]) + case["run"]["increment"]
        swept = soil["unit_weight"] * blade["depth"] * travel * blade["width"]
        shares.append(float(last["mass_spilled"]) / swept)
    mean = sum(shares) / len(shares)
    sd = math.sqrt(sum((s - mean) ** 2 for s in shares) / (len(shares) - 1))
    return mean, sd


def rise(w):
    """Last window mean over the first, with its spread propagated."""
    (a, sa), (b, sb) = w[0], w[-1]
    ratio = b / a
    return ratio, ratio * math.hypot(sa / a, sb / b)


def write(results, version):
    DOC.mkdir(parents=True, exist_ok=True)
    with open(DOC / "results.csv", "w", newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(["case", "width", "figure", "mean", "sd"])
        for (case, ratio), r in results.items():
            for k, (m, s) in enumerate(r["windows"]):
                out.writerow([case, label(ratio), f"window_{k}_{k + 1}", repr(m), repr(s)])
            out.writerow([case, label(ratio), "rise", *map(repr, r["rise"])])
            out.writerow([case, label(ratio), "spilled_share", *map(repr, r["spilled"])])
    lines = [
        "# Side spill and the rise of the force (issue 21)",
        "",
        "Written by `python3 docs/studies/paper_width.py --soilcut target/release/soilcut`",
        f"({version}); every figure is also in [results.csv](results.csv). Each row is an",
        f"ensemble of {MEMBERS} members (`soilcut run --ensemble {MEMBERS}`), mean ± standard",
        "deviation over the members. Forces are P/(γ0 d²) in plane strain and",
        "P/(γ0 d² w) with a width: the force per unit width either way. The rise is the",
        "last unit window's mean over the first's; the spilled share is the soil in the",
        "side heaps over all the soil the blade has met, at the end of the run.",
        "",
        "| case | blade | unit-window means | rise | spilled share |",
        "|---|---|---|---|---|",
    ]
    for (case, ratio), r in results.items():
        means = " · ".join(f"{m:.2f} ± {s:.2f}" for m, s in r["windows"])
        spill = (
            "–" if ratio is None else f"{100 * r['spilled'][0]:.3f} ± {100 * r['spilled'][1]:.3f} %"
        )
        lines.append(
            f"| {case} | {label(ratio)} | {means} | "
            f"{r['rise'][0]:.3f} ± {r['rise'][1]:.3f} | {spill} |"
        )
    notes = DOC / "notes.md"
    if notes.exists():
        lines += ["", notes.read_text().rstrip()]
    (DOC / "README.md").write_text("\n".join(lines) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", default="out/paper-width")
    a = p.parse_args()
    out = Path(a.out)
    version = subprocess.run(
        [a.soilcut, "--version"], check=True, capture_output=True, text=True
    ).stdout.strip()
    results = {}
    for name in CASES:
        for ratio in WIDTHS:
            folder = out / f"{name}-{'plane' if ratio is None else f'w{ratio:.1f}'}"
            run(a.soilcut, f"cases/paper/{name}.toml", ratio, folder)
            w = windows(folder)
            results[(name, ratio)] = {
                "windows": w,
                "rise": rise(w),
                "spilled": (0.0, 0.0) if ratio is None else spilled(folder),
            }
            print(name, label(ratio), file=sys.stderr, flush=True)
    write(results, version)


if __name__ == "__main__":
    main()
