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


def member_figures(folder):
    """Draft window means per blade (case units), and the pile at the end."""
    h = rows(folder / "history.csv")
    windows = []
    for k in range(TRAVEL):
        sel = [float(r["force_h"]) for r in h if k <= float(r["u_over_d"]) < k + 1]
        windows.append(sum(sel) / len(sel))
    last = h[-1]
    met = float(last["mass"]) + float(last["mass_spilled"])
    p = rows(folder / "profile.csv")
    face = float(p[0]["x"])
    near = min(p, key=lambda r: abs(float(r["x"]) - face - 0.25 * DEPTH))
    return {
        "windows": windows,
        "centre": float(near["y"]) / DEPTH,
        "crest": float(near["ridge_height"]) / DEPTH,
        "spilled": float(last["mass_spilled"]) / met,
    }


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
        d = dem[key]
        gamma = d["unit_weight_N_per_m3"]
        wall_mm = 1000.0 * d["end_wall_m"]
        w_mm = ratio * DEPTH
        # Case units: γ0 = 1, mm; per blade γ0·mm³ → N.
        to_newton = gamma * 1e-9
        norm = gamma * (DEPTH * 1e-3) ** 2 * (w_mm * 1e-3)
        members = [member_figures(f) for f in run(a.soilcut, out, ratio, wall_mm)]
        plane = [member_figures(f) for f in run(a.soilcut, out, None, wall_mm)]
        rows_out = []
        for k in range(TRAVEL):
            sim = spread([m["windows"][k] * to_newton for m in members])
            ps = spread([m["windows"][k] * w_mm * to_newton for m in plane])
            dw = d["windows"].get(f"window_{k}")
            rows_out.append(
                {
                    "window": [k, k + 1],
                    "soilcut_N": sim,
                    "soilcut_norm": [sim[0] / norm, sim[1] / norm],
                    "plane_strain_times_w_N": ps,
                    "dem_N": None if dw is None else [dw["mean_N"], dw["std_N"]],
                    "ratio": None if dw is None else sim[0] / dw["mean_N"],
                }
            )
        result[key] = {
            "unit_weight_N_per_m3": gamma,
            "width_mm": w_mm,
            "end_wall_mm": wall_mm,
            "windows": rows_out,
            "soilcut_pile": {
                k: spread([m[k] for m in members]) for k in ("centre", "crest", "spilled")
            },
            "dem_pile": d.get("pile"),
        }
        for r in rows_out:
            dem_cell = "–" if r["dem_N"] is None else f"{r['dem_N'][0]:.2f} ± {r['dem_N'][1]:.2f}"
            ratio_cell = "–" if r["ratio"] is None else f"{r['ratio']:.2f}"
            print(
                f"| w/d = {ratio:g} | [{r['window'][0]}, {r['window'][1]}) "
                f"| {r['soilcut_N'][0]:.2f} ± {r['soilcut_N'][1]:.2f} "
                f"| {r['plane_strain_times_w_N'][0]:.2f} | {dem_cell} | {ratio_cell} |"
            )
    (HERE / "results" / "compare3d.json").write_text(json.dumps(result, indent=1) + "\n")


if __name__ == "__main__":
    main()
