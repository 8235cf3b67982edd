#!/usr/bin/env python3
"""The paper's parametric study (issue 52): Morris, then Sobol on what matters.

Two soils of the refined model at the shipped defaults of their class:
softening (Fig. 5's sand, cases/paper/fig5.toml) and hardening (Fig. 8b's
loose sand with its residual values left out, so it never softens:
docs/studies/sensitivity/fig8b-hardening.toml). Every soil key of the
refined model that can move a force per unit width, plus the face
friction, the rake and the depth, over the ranges of KEYS (README.md says
why each), and the dummy input.

Phases (each resumable: a phase whose folder has a complete summary.json
is read, not rerun):

- morris: `soilcut sensitivity --method morris`, r = 20 trajectories,
  K = 6 members a point (the command's default), into morris-SOIL/;
- sobol: the TOP keys with the largest screening score (each output's
  μ* over its largest μ*, the largest over the outputs the screening's
  ensembles resolve: those whose ensemble mean's chaos share is below
  BOUND), Sobol with N = 512 base points and the dummy (the hardening
  soil's with the second-order indices too: its runs are four times
  cheaper), K by the rule of docs/guide/sensitivity.md from the chaos
  shares Morris measured but at least 2, so that each Sobol study
  measures its own chaos share, into sobol-SOIL/;
- page: study.md, the tables every interpretation in README.md quotes.

Standard library only:

    python3 docs/studies/sensitivity_study.py --soilcut target/release/soilcut
"""

import argparse
import csv
import json
import os
import subprocess
import time

OUT = "docs/studies/sensitivity"
SOILS = {
    "softening": "cases/paper/fig5.toml",
    "hardening": "docs/studies/sensitivity/fig8b-hardening.toml",
}
# Ranges a user would meet around each case (README.md, "The ranges").
KEYS = {
    "softening": [
        "soil.friction.initial=15:25",
        "soil.friction.peak=36:44",
        "soil.friction.residual=28:34",
        "soil.dilation.initial=-8:-2",
        "soil.dilation.peak=6:14",
        "soil.dilation.residual=-2:2",
        "soil.peak_shear=1:3",
        "soil.residual_shear=3.5:6",
        "soil.repose=26:34",
        "soil.d50=0.35:0.7",
        "soil.band_width_d50=5:20",
        "blade.wall_friction=0:14",
        "blade.rake=60:90",
        "blade.depth=15:25",
    ],
    "hardening": [
        "soil.friction.initial=15:25",
        "soil.friction.peak=28:38",
        "soil.dilation.initial=-8:-2",
        "soil.dilation.peak=-2:4",
        "soil.peak_shear=0.3:0.9",
        "soil.residual_shear=1:2",
        "soil.repose=28:38",
        "soil.d50=0.1:0.3",
        "soil.band_width_d50=5:25",
        "blade.wall_friction=0:14",
        "blade.rake=60:90",
        "blade.depth=20:30",
    ],
}
TRAJECTORIES = 20
MORRIS_MEMBERS = 6
BASE_POINTS = 512
TOP = 8
SECOND_ORDER = {"softening": False, "hardening": True}
# The rule's bound on the ensemble mean's chaos share (docs/guide/sensitivity.md).
BOUND = 0.05


def folder(phase, soil):
    return os.path.join(OUT, f"{phase}-{soil}")


def summary(path):
    """The phase's summary.json when it is complete, else None."""
    try:
        with open(os.path.join(path, "summary.json")) as f:
            s = json.load(f)
    except (OSError, ValueError):
        return None
    return s if s.get("complete") else None


def same_keys(s, keys):
    """Whether summary `s` is of the ranges `keys` (KEY=lo:hi)."""
    held = [(k["key"], k["lo"], k["hi"]) for k in s["keys"]]
    given = [(key, *map(float, span.split(":"))) for key, span in (k.split("=") for k in keys)]
    return held == given


def study(args, soil, phase, method, samples, members, keys, extra=()):
    """Runs one `soilcut sensitivity` unless its folder is complete and of
    the same keys and members."""
    out = folder(phase, soil)
    done = summary(out)
    if done is None or not same_keys(done, keys) or done["members"] != members:
        command = [args.soilcut, "sensitivity", SOILS[soil], "--method", method]
        command += ["--samples", str(samples), "--members", str(members), "--dummy"]
        command += ["--seed", str(args.seed), "--jobs", str(args.jobs), "-q"]
        command += ["--out", out, "--force", *extra]
        for key in keys:
            command += ["--vary", key]
        start = time.monotonic()
        subprocess.run(command, check=True)
        with open(os.path.join(out, "command.json"), "w") as f:
            json.dump({"command": command[1:], "wall_time_s": time.monotonic() - start}, f)
            f.write("\n")
    return summary(out)


def read_indices(path):
    with open(os.path.join(path, "indices.csv"), newline="") as f:
        return list(csv.DictReader(f))


def is_force(name):
    return "force_norm" in name


def resolved(s):
    """The outputs whose ensemble mean's chaos share is below BOUND."""
    k = s["members"]
    return {
        o["output"]
        for o in s["outputs"]
        if o["chaos_share"] is not None and (o["chaos_share"] / k) / (1 - o["chaos_share"]) < BOUND
    }


def screening(rows, outputs):
    """Each key's score: max over `outputs` of μ* / (that output's largest
    μ*) (an output some run lacks, with no μ*, is left out)."""
    rows = [r for r in rows if r["mu_star"] and r["output"] in outputs]
    largest = {}
    for r in rows:
        largest[r["output"]] = max(largest.get(r["output"], 0.0), float(r["mu_star"]))
    score = {}
    for r in rows:
        top = largest[r["output"]]
        share = float(r["mu_star"]) / top if top > 0 else 0.0
        score[r["key"]] = max(score.get(r["key"], 0.0), share)
    return score


def members_for(s):
    """The least K with (c / K) / (1 − c) < BOUND for every force output,
    and at least 2 (so the chaos share is measured)."""
    shares = [o["chaos_share"] for o in s["outputs"] if is_force(o["output"])]
    worst = max(c for c in shares if c is not None)
    k = 2
    while (worst / k) / (1.0 - worst) >= BOUND:
        k += 1
    return k, worst


def chosen_keys(soil):
    path = folder("morris", soil)
    score = screening(read_indices(path), resolved(summary(path)))
    ranked = sorted((k for k in score if k != "dummy"), key=lambda k: -score[k])
    by_name = {k.split("=")[0]: k for k in KEYS[soil]}
    return [by_name[k] for k in ranked[:TOP]], score


def wall(path):
    with open(os.path.join(path, "command.json")) as f:
        return json.load(f)["wall_time_s"]


def number(x, digits=3):
    return "–" if x in (None, "") else f"{float(x):.{digits}f}"


def table(head, rows):
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    return lines + ["| " + " | ".join(r) + " |" for r in rows]


def morris_lines(soil):
    path = folder("morris", soil)
    s, rows = summary(path), read_indices(path)
    outputs = [o["output"] for o in s["outputs"]]
    chaos = {o["output"]: o["chaos_share"] for o in s["outputs"]}
    keys = [r["key"] for r in rows if r["output"] == outputs[0]]
    score = screening(rows, resolved(s))
    outputs = [o for o in outputs if any(r["mu_star"] for r in rows if r["output"] == o)]
    largest = {o: max(float(r["mu_star"]) for r in rows if r["output"] == o) for o in outputs}
    cell = {(r["output"], r["key"]): float(r["mu_star"]) for r in rows if r["mu_star"]}
    body = [
        [f"`{k}`"]
        + [number(cell[o, k] / largest[o] if largest[o] > 0 else 0.0, 2) for o in outputs]
        + [number(score[k], 2)]
        for k in sorted(keys, key=lambda k: -score[k])
    ]
    body.append(["chaos share c"] + [number(chaos[o]) for o in outputs] + [""])
    k = s["members"]
    body.append(
        ["ensemble mean's, (c / K) / (1 − c)"]
        + [number((chaos[o] / k) / (1 - chaos[o])) for o in outputs]
        + [""]
    )
    head = ["key"] + [f"`{o}`" for o in outputs] + ["score"]
    runs = s["runs"] + s["tornado_runs"]
    lines = [
        f"### {soil}: Morris, r = {s['samples']}, {s['levels']} levels, K = {s['members']}",
        "",
        f"{s['design_points']} design points × K = {runs - s['tornado_runs']} runs, and the"
        f" tornado's {s['tornado_runs']}, in {wall(path):.0f} s"
        f" ({runs / wall(path):.1f} runs/s). μ* of each key over the largest μ* of each"
        " output (1 = the key that moves it most); `score`, the largest over the outputs,"
        " ranks the keys, over the outputs whose ensemble mean's chaos share (the last"
        f" row) is below {BOUND}; the last rows are each output's chaos share. Folder:"
        f" [morris-{soil}/](morris-{soil}/).",
        "",
    ]
    return lines + table(head, body)


def interval(row, low, high):
    return "–" if not row[low] else f"{float(row[low]):.3f} to {float(row[high]):.3f}"


def sobol_lines(soil):
    path = folder("sobol", soil)
    s, rows = summary(path), read_indices(path)
    chaos = {o["output"]: o["chaos_share"] for o in s["outputs"]}
    k = s["members"]
    runs = s["runs"] + s["tornado_runs"]
    head = ["output", "key", "S1", "S1 95 %", "ST", "ST 95 %", "ST − S1", "chaos c", "mean's"]
    body = []
    for r in rows:
        c = chaos[r["output"]]
        mean_share = None if c is None else (c / k) / (1.0 - c)
        gap = None if not r["S1"] else float(r["ST"]) - float(r["S1"])
        body.append(
            [f"`{r['output']}`", f"`{r['key']}`", number(r["S1"]), interval(r, "S1_low", "S1_high")]
            + [number(r["ST"]), interval(r, "ST_low", "ST_high"), number(gap)]
            + [number(c), number(mean_share)]
        )
    lines = [
        f"### {soil}: Sobol, N = {s['samples']}, K = {k}",
        "",
        f"{s['design_points']} design points × K = {s['runs']} runs, and the tornado's"
        f" {s['tornado_runs']}: {runs} runs in {wall(path):.0f} s ({runs / wall(path):.2f}"
        f" runs/s, --jobs {s.get('jobs', '2')}). `chaos c`: the members' share of the"
        " variance of every run; `mean's`: (c / K) / (1 − c), the chaos's share left in"
        f" the ensemble means the indices are taken of. Folder: [sobol-{soil}/](sobol-{soil}/).",
        "",
    ]
    return lines + table(head, body)


def page(args):
    lines = [
        "# The parametric study: tables",
        "",
        "Written by `python3 docs/studies/sensitivity_study.py --soilcut SOILCUT`"
        f" (SOILCUT a release build of this commit, --jobs {args.jobs}, --seed {args.seed});"
        " README.md reads them.",
        "",
        "## Screening (Morris)",
        "",
    ]
    for soil in SOILS:
        lines += morris_lines(soil) + [""]
        k, worst = members_for(summary(folder("morris", soil)))
        keys, _ = chosen_keys(soil)
        lines += [
            f"Chosen for Sobol: {', '.join(f'`{x}`' for x in keys)}; the largest force"
            f" output's chaos share {worst:.4f} gives K = {k}.",
            "",
        ]
    lines += ["## Variance (Sobol)", ""]
    for soil in SOILS:
        lines += sobol_lines(soil) + [""]
    with open(os.path.join(OUT, "study.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--soilcut", default="target/release/soilcut")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--phase", choices=("morris", "sobol", "page", "all"), default="all")
    parser.add_argument("--soil", choices=tuple(SOILS), action="append")
    args = parser.parse_args()
    soils = args.soil or list(SOILS)
    if args.phase in ("morris", "all"):
        for soil in soils:
            study(args, soil, "morris", "morris", TRAJECTORIES, MORRIS_MEMBERS, KEYS[soil])
    if args.phase in ("sobol", "all"):
        for soil in soils:
            k, _ = members_for(summary(folder("morris", soil)))
            keys, _ = chosen_keys(soil)
            extra = ["--second-order"] if SECOND_ORDER[soil] else []
            study(args, soil, "sobol", "sobol", BASE_POINTS, k, keys, extra)
    if args.phase in ("page", "all"):
        page(args)


if __name__ == "__main__":
    main()
