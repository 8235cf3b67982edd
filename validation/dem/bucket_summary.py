"""The bucket digs' seed means: every 0.02 d and per phase (bucket.py's records).

Run: python3 bucket_summary.py [--out DIR]   (plain Python; DIR: results/DIR,
default bucket)

Reads every results/DIR/bucket_TAG_..._forces.csv with its RUN.json and groups
the runs that differ only in their seed (the `_s<seed>` of the name). Writes,
per group G (the run name with the seed left out):

- results/DIR/G_mean.csv: for the k-th record of every run (k x 0.02 d of
  the lip's path; the seeds' time steps differ, so their records' s differ
  by less than one force sample, 0.0003 d), the number of seeds n, the mean
  s/d, and the mean and standard deviation over the seeds of the force of
  the grains on the bucket over gamma d^2 (fx, fy, the resultant), of the
  moment about the pivot over gamma d^3 and of the fill (kg per m and mm^2).
- results/DIR/G_summary.json: per phase and seed, the peak resultant force
  (over gamma d^2) and where (s/d), the peak moment (the largest in
  magnitude, signed) and where, and the fill at the phase's end; their seed
  means and standard deviations; a run's phase counts once its records
  pass the phase's end, so an unfinished run adds the phases it finished.

The standard deviation is the sample one (n - 1); with one seed it is 0.
"""

import csv
import glob
import json
import math
import os
import re
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SEED = re.compile(r"_s(\d+)")
MEAN_KEYS = ("fx_norm", "fy_norm", "force_norm", "moment_norm", "fill_kg_per_m", "fill_area_mm2")


class SummaryError(ValueError):
    """Results that cannot be summarised (the message names the file)."""


def read_run(path):
    """A run's records (floats) and its JSON."""
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    for r in rows:
        r["force_norm"] = math.hypot(r["fx_norm"], r["fy_norm"])
        if not all(math.isfinite(v) for v in r.values()):
            raise SummaryError(f"{path}: a record at s = {r['s_mm']} mm is not finite")
    with open(path.replace("_forces.csv", ".json")) as f:
        return rows, json.load(f)


def groups(folder):
    """{group name: {seed: (rows, meta)}} of the runs in `folder`."""
    out = {}
    for path in sorted(glob.glob(os.path.join(folder, "bucket_*_forces.csv"))):
        name = os.path.basename(path)[: -len("_forces.csv")]
        m = SEED.search(name)
        if m is None:
            raise SummaryError(f"{path}: no _s<seed> in the run's name")
        group = SEED.sub("", name, count=1)
        out.setdefault(group, {})[int(m.group(1))] = read_run(path)
    if not out:
        raise SummaryError(f"{folder}: no bucket_*_forces.csv")
    return out


def spread(values):
    """(mean, sample standard deviation) of a list."""
    return statistics.fmean(values), statistics.stdev(values) if len(values) > 1 else 0.0


def mean_rows(runs):
    """The seed means and spreads of every record index any run reached."""
    longest = max(len(rows) for rows, _ in runs.values())
    out = []
    for k in range(longest):
        at = [rows[k] for rows, _ in runs.values() if k < len(rows)]
        row = [len(at), statistics.fmean(r["s_over_d"] for r in at), int(at[0]["phase"])]
        for key in MEAN_KEYS:
            row += list(spread([r[key] for r in at]))
        out.append(row)
    return out


def phase_figures(rows, ends, depth):
    """Per phase that the run finished: its peaks and its fill at the end."""
    out = {}
    last = rows[-1]["s_mm"] if rows else 0.0
    for ph, end in enumerate(ends, start=1):
        mine = [r for r in rows if int(r["phase"]) == ph]
        if not mine or last < end - 0.02 * depth:  # not passed yet
            continue
        peak = max(mine, key=lambda r: r["force_norm"])
        turn = max(mine, key=lambda r: abs(r["moment_norm"]))
        out[ph] = {
            "peak_force_norm": peak["force_norm"],
            "peak_force_at_s_over_d": peak["s_over_d"],
            "peak_moment_norm": turn["moment_norm"],
            "peak_moment_at_s_over_d": turn["s_over_d"],
            "fill_end_kg_per_m": mine[-1]["fill_kg_per_m"],
            "fill_end_area_mm2": mine[-1]["fill_area_mm2"],
        }
    return out


def summary(runs, dig):
    ends = [p["s"] for p in dig["poses"][1:]]
    names = [p.get("phase", str(k)) for k, p in enumerate(dig["poses"][1:], start=1)]
    seeds = {
        s: {
            "finished": meta["finished"],
            "s_reached_over_d": meta["s_reached_mm"] / dig["depth"],
            "phases": phase_figures(rows, ends, dig["depth"]),
        }
        for s, (rows, meta) in sorted(runs.items())
    }
    phases = {}
    for ph, name in enumerate(names, start=1):
        have = [v["phases"][ph] for v in seeds.values() if ph in v["phases"]]
        if have:
            figures = {k: dict(zip(("mean", "sd"), spread([h[k] for h in have]))) for k in have[0]}
            phases[name] = {"phase": ph, "seeds": len(have), **figures}
    return {"seeds": seeds, "phases": phases}


def main():
    args = sys.argv[1:]
    out = args[args.index("--out") + 1] if "--out" in args else "bucket"
    folder = os.path.join(HERE, "results", out)
    with open(os.path.join(HERE, "digs", "bucket.json")) as f:
        dig = json.load(f)
    header = ["n", "s_over_d", "phase"] + [f"{k}_{m}" for k in MEAN_KEYS for m in ("mean", "sd")]
    for group, runs in groups(folder).items():
        with open(os.path.join(folder, group + "_mean.csv"), "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(header)
            w.writerows(
                [f"{v:.6g}" if isinstance(v, float) else v for v in r] for r in mean_rows(runs)
            )
        result = summary(runs, dig)
        with open(os.path.join(folder, group + "_summary.json"), "w") as f:
            json.dump(result, f, indent=1)
        print(group)
        for seed, v in result["seeds"].items():
            done = "finished" if v["finished"] else "unfinished"
            print(f"- seed {seed}: {done}, s/d reached {v['s_reached_over_d']:.2f}")
        print_table(result["phases"])


def print_table(phases):
    """The phases' seed means ± standard deviations, as a Markdown table."""
    print("\n| phase | seeds | peak F/(γd²) | at s/d | peak M/(γd³) | at s/d | fill at end (mm²) |")
    print("|---|---|---|---|---|---|---|")
    for name, p in phases.items():
        cells = [f"{p['phase']} {name}", str(p["seeds"])]
        cells += [fig(p, k) for k in ("peak_force_norm", "peak_force_at_s_over_d")]
        cells += [fig(p, k) for k in ("peak_moment_norm", "peak_moment_at_s_over_d")]
        cells.append(fig(p, "fill_end_area_mm2", 0))
        print("| " + " | ".join(cells) + " |")


def fig(p, key, digits=2):
    return f"{p[key]['mean']:.{digits}f} ± {p[key]['sd']:.{digits}f}"


if __name__ == "__main__":
    main()
