#!/usr/bin/env python3
"""Every DEM cut's numbers, with their spread over seeds (stdlib only).

Usage: python3 validation/dem/summarise.py [--campaign reference|damp0]

Reads a campaign's cuts (campaigns.py: `reference`, the default,
results/cuts/; `damp0`, the undamped cuts of issue 31, results/damp0/),
RUN.json and RUN_forces.csv, and results/mechanism/RUN.csv where there is
one (run mechanism.py first), and writes results/summary.json
(results/summary_damp0.json): for every configuration (cut, d/D, slab,
speed, numerical settings; campaigns.config_key) the seeds run and, over them, the
mean, sample standard deviation and count of

- `window_k`: the mean of force_norm (the face's resultant over gamma d^2,
  blade-bottom contacts excluded) over u in [k, k+1) d, and of its
  horizontal and vertical parts (`window_h_k`, `window_v_k`);
- `half_0`: the mean force_norm over u in [0, 0.5) d (the speed series);
- `early`: the mean force_norm over u in [0.05, 0.25] d, the DEM's first
  mobilisation, beside Coulomb's wedge (the first increment of soilcut);
- `wall_share_k`: the end wall's horizontal force over window k less its
  mean over the first 0.1 d, as a share of the blade's mean draft over the
  window (both N/m): how much of the blade's push the far wall takes;
- the mechanism's columns at every 0.25 d (mechanism.py) and their means
  over the intervals ending at u = 0.5, 0.75 and 1 d (`mean_*`: the part
  of the travel every configuration has);
- `inertial_number`: I = (v / t) D sqrt(rho_s / p) in the band, v the blade
  speed, t the band's mean thickness, D the mean diameter, rho_s = 2650
  kg/m^3 the grains' density and p = gamma0 d / 2 the mean vertical stress
  along the band;
- `wall_time_s` of each run.
It also writes results/cut_NAME_mean.csv (cut_NAME_damp0_mean.csv) for the
configuration the campaign compares with soilcut (d/D = 10 monolayer cuts
at the campaign's speed): the seeds' mean force per record (u in mm, force per unit
width in units of gamma0 mm^2 with gamma0 = 1: what `soilcut fit` and
`soilcut compare --measured` read). It prints the tables docs/validation.md
quotes.
"""

import csv
import json
import math
import statistics
import sys

from campaigns import CAMPAIGNS, campaign_option, compared_key, config_key
from campaigns import RESULTS as HERE

MECH = (
    "beta_deg",
    "emergence_mm",
    "band_thickness_mm",
    "pile_height_mm",
    "pile_ahead_mm",
    "pile_slope_deg",
    "block_ratio",
)


def spread(values):
    v = [x for x in values if x is not None and math.isfinite(x)]
    if not v:
        return None
    return {
        "mean": statistics.fmean(v),
        "sd": statistics.stdev(v) if len(v) > 1 else 0.0,
        "n": len(v),
    }


def run_numbers(meta):
    rows = rows_of(meta)
    out = {}
    last = int(math.floor(rows[-1]["u_over_d"] + 1e-6))
    for k in range(last):
        sel = [r for r in rows if k <= r["u_over_d"] < k + 1]
        if len(sel) >= 25:
            out[f"window_{k}"] = statistics.fmean(r["force_norm"] for r in sel)
            out[f"window_h_{k}"] = statistics.fmean(r["force_h_norm"] for r in sel)
            out[f"window_v_{k}"] = statistics.fmean(r["force_v_norm"] for r in sel)
    half = [r["force_norm"] for r in rows if r["u_over_d"] < 0.5]
    out["half_0"] = statistics.fmean(half)
    early = [r["force_norm"] for r in rows if 0.05 <= r["u_over_d"] <= 0.25]
    out["early"] = statistics.fmean(early)
    start = statistics.fmean(r["end_wall_N_per_m"] for r in rows if r["u_over_d"] <= 0.1)
    for k in range(last):
        sel = [r for r in rows if k <= r["u_over_d"] < k + 1]
        if len(sel) >= 25:
            wall = statistics.fmean(r["end_wall_N_per_m"] for r in sel) - start
            out[f"wall_share_{k}"] = wall / statistics.fmean(r["force_h_N_per_m"] for r in sel)
    mech = HERE / "mechanism" / (meta["run"] + ".csv")
    if mech.exists():
        m = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(mech.open())]
        for row in m:
            for key in MECH:
                out[f"{key}@{row['u_over_d']:.2f}"] = row[key]
        for key in MECH:
            vals = [
                r[key]
                for r in m
                if 0.5 - 1e-9 <= r["u_over_d"] <= 1.0 + 1e-9 and math.isfinite(r[key])
            ]
            out[f"mean_{key}"] = statistics.fmean(vals) if vals else None
        t = out.get("mean_band_thickness_mm")
        if t:
            p = meta["unit_weight_N_per_m3"] * meta["depth_mm"] * 1e-3 / 2
            out["inertial_number"] = (
                meta["speed_m_per_s"] / (t * 1e-3) * meta["mean_diameter_m"] * math.sqrt(2650.0 / p)
            )
    out["wall_time_s"] = meta["wall_time_s"]
    return out


def write_mean(name, metas, campaign):
    """The seeds' mean force curve, record by record (the records are 0.02 d apart in all)."""
    # the records within each cut's nominal travel (the last one may pass it by a step)
    curves = [[r for r in rows_of(m) if r["u_mm"] <= m["travel_mm"]] for m in metas]
    n = min(len(c) for c in curves)
    d = metas[0]["depth_mm"]
    with open(HERE / f"cut_{name}{CAMPAIGNS[campaign]['suffix']}_mean.csv", "w") as f:
        f.write("u,force\n")
        for i in range(n):
            u = statistics.fmean(c[i]["u_mm"] for c in curves)
            force = statistics.fmean(c[i]["force_norm"] for c in curves) * d * d
            f.write(f"{u:.6g},{force:.6g}\n")


def rows_of(meta):
    return [
        {k: float(v) for k, v in r.items()}
        for r in csv.DictReader((meta["folder"] / (meta["run"] + "_forces.csv")).open())
    ]


def main(campaign):
    configs = {}
    folder = HERE / CAMPAIGNS[campaign]["cuts"]
    for path in sorted(folder.glob("*.json")):
        meta = json.loads(path.read_text())
        meta["folder"] = folder
        configs.setdefault(config_key(meta), []).append((meta, run_numbers(meta)))
    for name in ("vertical", "raked30", "deep"):
        if compared_key(name, campaign) in configs:
            write_mean(name, [m for m, _ in configs[compared_key(name, campaign)]], campaign)
    summary = {}
    for key, runs in sorted(configs.items()):
        numbers = sorted({k for _, n in runs for k in n})
        entry = {
            "seeds": [m["seed"] for m, _ in runs],
            "grains": [m["grains"] for m, _ in runs],
            "speed_m_per_s": runs[0][0]["speed_m_per_s"],
            "depth_mm": runs[0][0]["depth_mm"],
            "rake_deg": runs[0][0]["rake_deg"],
        }
        for k in numbers:
            entry[k] = spread([n.get(k) for _, n in runs])
        summary[key] = entry
    (HERE / f"summary{CAMPAIGNS[campaign]['suffix']}.json").write_text(
        json.dumps(summary, indent=1, sort_keys=True) + "\n"
    )

    def fmt(s):
        return (
            "–"
            if s is None
            else (f"{s['mean']:.2f} ± {s['sd']:.2f}" if s["n"] > 1 else f"{s['mean']:.2f}")
        )

    print(
        "| configuration | seeds | early | [0,0.5) d | [0,1) d | [1,2) d | [2,3) d | h [0,1) | v [0,1) | h [1,2) | v [1,2) | wall share [0,1) | [1,2) | wall time (s) |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for key, e in summary.items():
        print(
            f"| {key} | {len(e['seeds'])} | {fmt(e.get('early'))} | {fmt(e.get('half_0'))} | {fmt(e.get('window_0'))} | "
            f"{fmt(e.get('window_1'))} | {fmt(e.get('window_2'))} | {fmt(e.get('window_h_0'))} | "
            f"{fmt(e.get('window_v_0'))} | {fmt(e.get('window_h_1'))} | {fmt(e.get('window_v_1'))} | "
            f"{fmt(e.get('wall_share_0'))} | {fmt(e.get('wall_share_1'))} | "
            f"{fmt(e.get('wall_time_s'))} |"
        )
    print()
    print(
        "| configuration | β (°) | emergence ahead of tip (mm) | band thickness (mm) | pile height (mm) | pile slope (°) | block speed ratio | inertial number |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for key, e in summary.items():
        inertial = e.get("inertial_number")
        print(
            f"| {key} | "
            + " | ".join(fmt(e.get(f"mean_{m}")) for m in MECH[:4] + MECH[5:])
            + (f" | {inertial['mean']:.1e} |" if inertial else " | – |")
        )


if __name__ == "__main__":
    main(campaign_option(sys.argv))
