#!/usr/bin/env python3
"""What the mobilised face friction changes (issue 20, docs/model.md §2.6).

Runs the five paper cases and the three former DEM validation cases
(docs/studies/face-friction/cases/, the cases before issue 20's DEM
campaign, in which the defect was found) under both
face friction rules (both with `run.time_scheme = "explicit"`),
`choices.face_friction = "sign"` (the rule before issue 20) and
`"mobilised"` (the default since, (M41)), and writes
docs/studies/face-friction/README.md and results.csv: the first force, the
largest force, the whole-run mean of P/(γ0 d²), the mean over each unit
window of u/d (the figures docs/reproduction.md rests on,
docs/scripts/analyse.py) and the number of increments whose chosen block
sinks along the face (full −φw) or is partly mobilised (|m| < 1), for both
rules side by side.

A case whose two single runs write the same history.csv, bit for bit, is
reported from those runs. Every other case is run as an ensemble of 7
imperceptibly perturbed members under each rule (`soilcut run --ensemble 7`,
docs/model.md §12.1), since the model's chaos moves late window means by
1-2 %, and quoted as the ensemble mean ± its standard deviation over the
members. Standard library only:

    python3 docs/studies/face_friction.py --soilcut target/release/soilcut
"""

import argparse
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import tomllib

CASES = [
    "cases/paper/original.toml",
    "cases/paper/fig5.toml",
    "cases/paper/table1-hs.toml",
    "cases/paper/table1-s.toml",
    "cases/paper/fig8b.toml",
    "docs/studies/face-friction/cases/vertical-former.toml",
    "docs/studies/face-friction/cases/deep-former.toml",
    "docs/studies/face-friction/cases/raked30-former.toml",
]
RULES = ("sign", "mobilised")
MEMBERS = 7
DOC = Path("docs/studies/face-friction")


def run(soilcut, case, rule, folder, ensemble=False):
    if (folder / "summary.json").exists():
        return folder
    cmd = [soilcut, "run", case, "--out", str(folder), "--force", "--quiet", "--no-plots"]
    # Both rules under the explicit time scheme: the sign rule has no
    # midpoint force (docs/model.md §2.12), so that only the rule differs.
    cmd += ["--set", f"choices.face_friction={rule}", "--set", "run.time_scheme=explicit"]
    if ensemble:
        cmd += ["--ensemble", str(MEMBERS), "--jobs", "1"]
    subprocess.run(cmd, check=True)
    return folder


def history(folder):
    with open(folder / "history.csv", newline="") as f:
        return list(csv.DictReader(f))


def mobilisations(folder):
    """m of each increment's chosen block, from the recorded direction of
    the force: ω = atan2(force_v, force_h) = m φw + α − 90° (M12, M41)."""
    case = tomllib.loads((folder / "case.resolved.toml").read_text())
    phi_w = math.radians(case["blade"]["wall_friction"])
    offset = math.radians(case["blade"]["rake"] - 90.0)
    return [
        (math.atan2(float(r["force_v"]), float(r["force_h"])) - offset) / phi_w
        for r in history(folder)
    ]


def figures(folder):
    """The figures of one run."""
    rows = history(folder)
    forces = [float(r["force_norm"]) for r in rows]
    sums, counts = {}, {}
    for r, f in zip(rows, forces):
        w = int(float(r["u_over_d"]))
        sums[w] = sums.get(w, 0.0) + f
        counts[w] = counts.get(w, 0) + 1
    m = mobilisations(folder)
    return {
        "first": forces[0],
        "largest": max(forces),
        "mean": sum(forces) / len(forces),
        "windows": [sums[w] / counts[w] for w in sorted(sums)],
        "sinking": sum(1 for x in m if x <= -1.0 + 1e-9),
        "partial": sum(1 for x in m if abs(x) < 1.0 - 1e-9),
        "increments": len(rows),
    }


def spread(values):
    mean = sum(values) / len(values)
    sd = (
        math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))
        if len(values) > 1
        else 0.0
    )
    return mean, sd


def member_folders(folder):
    summary = json.loads((folder / "summary.json").read_text())
    return [folder / name for name in summary["perturbation"]["folders"]]


def measure(soilcut, out, case):
    """{rule: {figure: (mean, sd)}} and how it was measured."""
    name = Path(case).stem
    single = {rule: run(soilcut, case, rule, out / f"{name}-{rule}") for rule in RULES}
    same = (single["sign"] / "history.csv").read_bytes() == (
        single["mobilised"] / "history.csv"
    ).read_bytes()
    result = {}
    for rule in RULES:
        if same:
            folders = [single[rule]]
        else:
            folders = member_folders(
                run(soilcut, case, rule, out / f"{name}-{rule}-ensemble", ensemble=True)
            )
        members = [figures(f) for f in folders]
        fig = {
            key: spread([m[key] for m in members])
            for key in ("first", "largest", "mean", "sinking", "partial")
        }
        windows = len(members[0]["windows"])
        fig["windows"] = [spread([m["windows"][k] for m in members]) for k in range(windows)]
        fig["increments"] = members[0]["increments"]
        result[rule] = fig
    return result, "single runs, identical histories" if same else f"ensembles of {MEMBERS}"


def cell(value, digits=3):
    mean, sd = value
    # Members that differ only by round-off count as equal.
    return (
        f"{mean:.{digits}f}" if sd <= 1e-12 * abs(mean) else f"{mean:.{digits}f} ± {sd:.{digits}f}"
    )


def count(value):
    mean, sd = value
    return f"{mean:.0f}" if sd == 0.0 else f"{mean:.1f} ± {sd:.1f}"


def write(results, soilcut_version):
    DOC.mkdir(parents=True, exist_ok=True)
    with open(DOC / "results.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "rule", "measured_by", "figure", "mean", "sd"])
        for case, (res, how) in results.items():
            for rule in RULES:
                fig = res[rule]
                for key in ("first", "largest", "mean", "sinking", "partial"):
                    w.writerow([case, rule, how, key, repr(fig[key][0]), repr(fig[key][1])])
                for k, v in enumerate(fig["windows"]):
                    w.writerow([case, rule, how, f"window_{k}_{k + 1}", repr(v[0]), repr(v[1])])
    lines = [
        "# What the mobilised face friction changes (issue 20)",
        "",
        "Written by `python3 docs/studies/face_friction.py --soilcut target/release/soilcut`",
        f"({soilcut_version}); every figure is also in [results.csv](results.csv).",
        "The face friction's rules are docs/model.md §2.6: `sign` is the rule before",
        "issue 20 (±φw, −φw at zero slip, (M9)), `mobilised` the default since",
        "(m = clamp(s / 0.05, −1, 1), (M41)). Both run under the explicit time",
        'scheme (`run.time_scheme = "explicit"`; the sign rule has no midpoint',
        "force, docs/model.md §2.12), at the increment the cases then default to",
        "(d/500 on the vertex ground), so that only the rule differs.",
        "",
        "Forces are P/(γ0 d²). Cases whose two histories are identical bit for bit",
        "are single runs; the others are ensembles of 7 members (`soilcut run",
        "--ensemble 7`, soil.d50 × (1 + 0.001 k)), mean ± standard deviation over",
        'the members. "sinking" counts the increments whose chosen block has the',
        'full −φw, "partial" those with |m| < 1 (from the recorded force direction,',
        "ω = atan2(force_v, force_h)), out of the run's increments.",
        "",
        "| case | measured by | rule | first force | largest force | whole-run mean"
        " | unit-window means | sinking | partial | increments |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for case, (res, how) in results.items():
        for rule in RULES:
            fig = res[rule]
            windows = " · ".join(cell(v, 2) for v in fig["windows"])
            lines.append(
                f"| {case} | {how} | {rule} | {cell(fig['first'], 4)} | {cell(fig['largest'])} | "
                f"{cell(fig['mean'])} | {windows} | {count(fig['sinking'])} | "
                f"{count(fig['partial'])} | {fig['increments']} |"
            )
    lines += [
        "",
        "Change of the mobilised rule's figure from the sign rule's, in % (ensemble means):",
        "",
    ]
    lines += [
        "| case | first force | largest force | whole-run mean | unit-window means |",
        "|---|---|---|---|---|",
    ]
    for case, (res, _) in results.items():
        a, b = res["sign"], res["mobilised"]
        changes = [100.0 * (b[k][0] / a[k][0] - 1.0) for k in ("first", "largest", "mean")]
        windows = " · ".join(
            f"{100.0 * (y[0] / x[0] - 1.0):+.2f}" for x, y in zip(a["windows"], b["windows"])
        )
        lines.append(f"| {case} | " + " | ".join(f"{c:+.2f}" for c in changes) + f" | {windows} |")
    notes = DOC / "notes.md"
    if notes.exists():
        lines += ["", notes.read_text().rstrip()]
    (DOC / "README.md").write_text("\n".join(lines) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default="target/release/soilcut")
    p.add_argument("--out", default="out/face-friction")
    a = p.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    version = subprocess.run(
        [a.soilcut, "--version"], check=True, capture_output=True, text=True
    ).stdout.strip()
    results = {}
    for case in CASES:
        results[case] = measure(a.soilcut, out, case)
        print(case, results[case][1], file=sys.stderr, flush=True)
    write(results, version)


if __name__ == "__main__":
    main()
