#!/usr/bin/env python3
"""soilcut beside the three-dimensional DEM cuts of blades of finite width
(issue 21, docs/validation.md, "Blades of finite width").

Runs cases/validation/vertical.toml (the DEM soil's keys from its element
tests, never tuned to a cut) with `blade.width` = w, the 3D bin's end wall
(`bin.length`) and 3 d of travel, as an ensemble of 7 perturbed members
(`soilcut run --ensemble 7`, docs/model.md §12.1), for w/d = 1 and 3 and in
plane strain; reads the DEM's results/summary.json, force_wW.csv and
pile_wW.csv (summarise3d.py); writes results/compare3d.json and prints the
table docs/validation.md quotes: the draft per blade over unit windows of
travel, in N and as P_h/(γ0 d² w), soilcut's ensemble mean ± its standard
deviation beside the DEM's window mean ± the standard deviation of its
record, and the ratio; and the pile: the centreline height 0.25 d ahead of
the face, the side heaps' crest there and the spilled share of the soil met.
Standard library only:

    python3 validation/dem3d/compare3d.py --soilcut target/release/soilcut
"""

import argparse
import csv
import json
import math
import subprocess
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
CASE = ROOT / "cases" / "validation" / "vertical.toml"
RATIOS = (1.0, 3.0)
MEMBERS = 7
DEPTH = 20.0  # mm, the DEM's d
TRAVEL = 3  # in d
STATIONS = (0.25, 0.5, 1.0)  # x ahead of the face of the DEM's lateral profiles (d)


def run(soilcut, out, ratio, wall_mm):
    folder = out / ("plane" if ratio is None else f"w{ratio:g}")
    if not (folder / "ensemble.csv").exists():
        cmd = [soilcut, "run", str(CASE), "--out", str(folder), "--force", "--quiet"]
        cmd += ["--no-plots", "--ensemble", str(MEMBERS), "--jobs", "1"]
        cmd += ["--set", f"run.travel={TRAVEL * DEPTH}", "--set", f"bin.length={wall_mm}"]
        if ratio is not None:
            cmd += ["--set", f"blade.width={ratio * DEPTH}"]
        subprocess.run(cmd, check=True)
    summary = json.loads((folder / "summary.json").read_text())
    return [folder / name for name in summary["perturbation"]["folders"]]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def spread(values):
    mean = sum(values) / len(values)
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / max(len(values) - 1, 1))
    return mean, sd


def member_figures(folder, width):
    """Draft window means per blade (case units), and the pile at the end."""
    h = rows(folder / "history.csv")
    windows = []
    for k in range(TRAVEL):
        sel = [float(r["force_h"]) for r in h if k <= float(r["u_over_d"]) < k + 1]
        windows.append(sum(sel) / len(sel))
    p = rows(folder / "profile.csv")
    face = float(p[0]["x"])

    def ahead(r):
        return (float(r["x"]) - face) / DEPTH

    def crest(x):
        return float(min(p, key=lambda r: abs(ahead(r) - x))["ridge_height"]) / DEPTH

    near = [float(r["y"]) / DEPTH for r in p if ahead(r) < 1.0]
    figures = {
        "windows": windows,
        "centre_mean_height_0_1d": sum(near) / len(near),
        "pile_front_d": max(ahead(r) for r in p if float(r["y"]) > 0.02 * DEPTH),
    }
    if width:
        # Case units: γ0 = 1; the swept soil is γ0 d u w.
        swept = DEPTH * TRAVEL * DEPTH * width
        figures["spilled_share"] = float(h[-1]["mass_spilled"]) / swept
        figures.update({f"crest_at_{x:g}d": crest(x) for x in STATIONS})
    return figures


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--soilcut", default=str(ROOT / "target" / "release" / "soilcut"))
    p.add_argument("--out", default=str(ROOT / "out" / "dem3d"))
    a = p.parse_args()
    out = Path(a.out)
    dem = json.loads((HERE / "results" / "summary.json").read_text())
    result = {}
    for ratio in RATIOS:
        key = f"w{ratio:g}"
        if key not in dem:
            continue
        d = dem[key]["seed_14"]
        gamma = d["gamma0_N_per_m3"]
        w_mm = ratio * DEPTH
        # Case units: γ0 = 1, mm; per blade γ0·mm³ → N.
        to_newton = gamma * 1e-9
        members = run(a.soilcut, out, ratio, 1000.0 * d["end_wall_x_m"])
        sims = [member_figures(f, w_mm) for f in members]
        plane = [
            member_figures(f, None) for f in run(a.soilcut, out, None, 1000.0 * d["end_wall_x_m"])
        ]
        table = []
        for k in range(TRAVEL):
            sim = spread([m["windows"][k] * to_newton for m in sims])
            ps = spread([m["windows"][k] * w_mm * to_newton for m in plane])
            dw = d.get(f"window_{k}")
            table.append(
                {
                    "window": [k, k + 1],
                    "soilcut_N": sim,
                    "soilcut_norm": [v / d["norm_N"] for v in sim],
                    "plane_strain_times_w_N": ps,
                    "dem_N": None if dw is None else [dw["draft_N"], dw["draft_sd_N"]],
                    "dem_norm": None if dw is None else dw["draft_norm"],
                    "dem_wall_share": None if dw is None else dw["wall_share"],
                    "ratio": None if dw is None else sim[0] / dw["draft_N"],
                }
            )
        pile = d["pile"]["u_3d"]
        soil_pile = {k: spread([m[k] for m in sims]) for k in sims[0] if k != "windows"}
        result[key] = {
            "unit_weight_N_per_m3": gamma,
            "width_mm": w_mm,
            "windows": table,
            "soilcut_pile": soil_pile,
            "dem_pile": {
                "centre_mean_height_0_1d": pile["centre_mean_height_0_1d"],
                "pile_front_d": pile["centre_pile_front_x_d"],
                "spilled_share": pile["spilled"]["outside_share_incl_behind"],
                **{f"crest_at_{x:g}d": pile[f"ridge_at_{x:g}d"]["peak_height_d"] for x in STATIONS},
            },
        }
        for r in table:
            dem_cell = "–" if r["dem_N"] is None else f"{r['dem_N'][0]:.2f} ± {r['dem_N'][1]:.2f}"
            ratio_cell = "–" if r["ratio"] is None else f"{r['ratio']:.2f}"
            print(
                f"| w/d = {ratio:g} | [{r['window'][0]}, {r['window'][1]}) "
                f"| {r['soilcut_N'][0]:.2f} ± {r['soilcut_N'][1]:.2f} "
                f"| {r['plane_strain_times_w_N'][0]:.2f} | {dem_cell} | {ratio_cell} |"
            )
        for k, v in result[key]["dem_pile"].items():
            print(
                f"| w/d = {ratio:g} | {k} | {soil_pile[k][0]:.2f} ± {soil_pile[k][1]:.2f} | {v:.2f} |"
            )
    (HERE / "results" / "compare3d.json").write_text(json.dumps(result, indent=1) + "\n")


if __name__ == "__main__":
    main()
