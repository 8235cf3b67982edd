#!/usr/bin/env python3
"""The 3D cuts' forces and piles (numpy only).

Usage: /usr/bin/python3 validation/dem3d/summarise3d.py

Reads results/beds/bed3d_*.json, results/cuts/w*_*.json and _forces.csv, and
fields/*.npz (cut3d.py's grain fields), and writes:

- results/force_wW.csv (the reference seed, 14) and results/force_wW_sS.csv
  (any other seed): u_over_d, draft_N, vertical_N, wall_N (the face's
  contacts, the whole blade and bin, N) and draft_all_N, vertical_all_N
  (every contact of the blade);
- results/pile_wW.csv (seed 14): the ground at u = 1, 2, 3 d. Rows of kind
  `centre`: x (from the face, in d) and y (height above the bed's level, in
  d), the mean of the column tops in the strip z < w/4 of the centreline;
  rows of kind `across`: z (from the centreline, in d) and y at x = 0.25,
  0.5, 1 d ahead of the face;
- results/summary.json: per width (and seed) the bed's figures, the force
  windows, the wall's share, the ridge and the spilled share.

The ground is detected as in the 2D campaign, in 3D: the highest grain top
(centre height + radius) among the grains whose centres lie in a column D
long (x) and D wide (z), D the mean diameter. `centre` rows: columns centred
every D/2 along x (windows D long, overlapping), the tops averaged over the
strip's D-wide columns in z. `across` rows: one column D long about the
station, every D in z. Heights are from the bed's level (the mean column top
of the settled bed before the cut, bed3d.py). The noise is the standard
deviation of a single column top in the settled bed (`surface_noise_sd_m`),
divided by the square root of the columns averaged.
"""

import csv
import json
import math
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
STATIONS = (0.25, 0.5, 1.0)  # x ahead of the face for the lateral profiles (d)
XWIN = 0.25  # half-length of the x window of a lateral profile (d)
SNAPS = (1.0, 2.0, 3.0)  # travel of the pile records (d)
SIDES = 2.0  # half-bin to the whole bin


def read_forces(run):
    rows = list(csv.DictReader((RES / "cuts" / f"{run}_forces.csv").open()))
    if len(rows) < 10:
        return None
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def windows(f, norm, last):
    out = {}
    u = f["u_over_d"]
    start = f["wall_N"][u <= 0.1].mean()
    for k in range(last):
        sel = (u > k) & (u <= k + 1 + 1e-9) if k == 0 else (u > k + 1e-9) & (u <= k + 1 + 1e-9)
        if sel.sum() < 10:
            continue
        d = f["draft_N"][sel]
        out[f"window_{k}"] = {
            "draft_N": d.mean(),
            "draft_sd_N": d.std(ddof=1),
            "draft_norm": d.mean() / norm,
            "draft_sd_norm": d.std(ddof=1) / norm,
            "vertical_N": f["vertical_N"][sel].mean(),
            "vertical_norm": f["vertical_N"][sel].mean() / norm,
            "draft_all_N": f["draft_all_N"][sel].mean(),
            "draft_all_norm": f["draft_all_N"][sel].mean() / norm,
            "wall_N": f["wall_N"][sel].mean(),
            "wall_share": (f["wall_N"][sel].mean() - start) / d.mean(),
            "records": int(sel.sum()),
            "window_complete": bool(sel.sum() >= 49),
        }
    return out


def column_tops(pos, rad, x0, x1, z0, z1):
    """The highest grain top among the grains whose centres lie in the box (nan if none)."""
    sel = (pos[:, 0] >= x0) & (pos[:, 0] < x1) & (pos[:, 2] >= z0) & (pos[:, 2] < z1)
    return (pos[sel, 1] + rad[sel]).max() if sel.any() else np.nan


def centre_profile(pos, rad, face, bed, w):
    """The centreline ground: x from the face (d), mean column top over the strip z < w/4 (d
    above the level), columns D long centred every D/2."""
    d, D = bed["depth_m"], bed["mean_diameter_m"]
    level = bed["surface_level_m"]
    strip = max(1, int(round(w / 4 / D)))  # D-wide columns within z < w/4
    out = []
    x = bed["x_start_m"] + D / 2
    while x + D / 2 <= bed["x_end_m"] + 1e-12:
        tops = [
            column_tops(pos, rad, x - D / 2, x + D / 2, j * D, (j + 1) * D) for j in range(strip)
        ]
        tops = [t for t in tops if np.isfinite(t)]
        if tops:
            out.append(((x - face) / d, (np.mean(tops) - level) / d))
        x += D / 2
    return out, strip


def lateral_profile(pos, rad, xs, bed):
    """The ground across the bin at xs (m): for every D-wide z column, the mean of the column
    tops of the D-long x columns in xs -/+ XWIN d, then a running mean over 3 z columns
    (z from the centreline in d, height above the level in d)."""
    d, D = bed["depth_m"], bed["mean_diameter_m"]
    level = bed["surface_level_m"]
    nz = int(bed["half_width_m"] // D)
    nx = max(1, int(2 * XWIN * d // D))
    x0 = xs - nx * D / 2
    raw = []
    for j in range(nz):
        t = [
            column_tops(pos, rad, x0 + i * D, x0 + (i + 1) * D, j * D, (j + 1) * D)
            for i in range(nx)
        ]
        t = [v for v in t if np.isfinite(v)]
        raw.append((np.mean(t) - level) / d if t else np.nan)
    raw = np.array(raw)
    smooth = np.array([np.nanmean(raw[max(0, j - 1) : j + 2]) for j in range(nz)])
    return [((j + 0.5) * D / d, raw[j], smooth[j]) for j in range(nz)], nx


def ridge(profile, w, d, threshold):
    """Beside the blade (z > w/2): the peak of the smoothed profile, its z, the lateral extent
    beyond the edge (from the edge out to the first z whose smoothed height is below
    threshold), and the far field's mean (z > w/2 + 2.5 d: the reference check)."""
    beside = [(z, y) for z, _, y in profile if z * d >= w / 2 and np.isfinite(y)]
    if not beside:
        return None
    zp, yp = max(beside, key=lambda t: t[1])
    extent = None
    for z, y in beside:
        if y < threshold:
            extent = z - w / 2 / d
            break
    inside = [y for z, y, _ in profile if z * d < w / 2 and np.isfinite(y)]
    far = [y for z, y, _ in profile if z * d > w / 2 + 2.5 * d and np.isfinite(y)]
    return {
        "peak_height_d": yp,
        "peak_z_d": zp,
        "extent_beyond_edge_d": extent,
        "inside_mean_height_d": float(np.mean(inside)) if inside else None,
        "far_field_mean_height_d": float(np.mean(far)) if far else None,
    }


def noise(pos0, rad, bed, w):
    """The methods' noise in the settled bed before the cut (u = 0): the standard deviation
    of the centreline heights over 0.5 d <= x < 6 d, and of the smoothed lateral
    profile's heights at x = 1.5, 2.5 ... 5.5 d (d)."""
    c, _ = centre_profile(pos0, rad, 0.0, bed, w)
    cy = [y for x, y in c if 0.5 <= x < 6.0]
    ly = []
    for s in (1.5, 2.5, 3.5, 4.5, 5.5):
        prof, _ = lateral_profile(pos0, rad, s * bed["depth_m"], bed)
        ly += [y for _, _, y in prof if np.isfinite(y)]
    return {
        "centre_sd_d": float(np.std(cy, ddof=1)),
        "centre_mean_d": float(np.mean(cy)),
        "lateral_sd_d": float(np.std(ly, ddof=1)),
        "lateral_mean_d": float(np.mean(ly)),
    }


def spilled(pos, rad, pos0, face, bed, w, gamma_grain):
    """Weight (N, whole bin) of the grains whose centres lie above the bed's level, less
    the same per unit of plan area in the settled bed before the cut, by region."""
    level = bed["surface_level_m"]
    bed["depth_m"]
    W = bed["half_width_m"]
    ok0 = np.isfinite(pos0[:, 0])
    a0 = (bed["x_end_m"] - bed["x_start_m"]) * W
    vol = 4.0 / 3.0 * math.pi * rad**3
    base = (vol[ok0 & (pos0[:, 1] > level)].sum() * gamma_grain) / a0  # N/m^2 of plan
    ok = np.isfinite(pos[:, 0])
    above = ok & (pos[:, 1] > level)
    x, z = pos[:, 0], pos[:, 2]
    regions = {
        "ahead_inside": (x >= face) & (z < w / 2),
        "ahead_outside": (x >= face) & (z >= w / 2),
        "behind_outside": (x < face) & (z >= w / 2),
        "behind_inside": (x < face) & (z < w / 2),
    }
    areas = {
        "ahead_inside": (bed["x_end_m"] - face) * w / 2,
        "ahead_outside": (bed["x_end_m"] - face) * (W - w / 2),
        "behind_inside": (face - bed["x_start_m"]) * w / 2,
        "behind_outside": (face - bed["x_start_m"]) * (W - w / 2),
    }
    out = {
        k: SIDES * (vol[above & m].sum() * gamma_grain - base * areas[k])
        for k, m in regions.items()
    }
    ahead = out["ahead_inside"] + out["ahead_outside"]
    out["ahead_outside_share"] = out["ahead_outside"] / ahead if ahead > 0 else None
    total = sum(out[k] for k in regions)
    out["outside_share_incl_behind"] = (
        (out["ahead_outside"] + out["behind_outside"]) / total if total > 0 else None
    )
    out["baseline_N_per_m2"] = base
    return out


def main():
    beds = {p.stem: json.loads(p.read_text()) for p in (RES / "beds").glob("bed3d_*.json")}
    summary = {}
    for path in sorted((RES / "cuts").glob("w*_*.json")):
        meta = json.loads(path.read_text())
        bed = dict(beds[meta["bed"]], half_width_m=meta["half_bin_width_m"])
        run = meta["run"]
        wd = meta["width_m"] / meta["depth_m"]
        key = f"w{wd:g}"
        cut = bed["cut_region"].get(key)
        gamma = cut["unit_weight_N_per_m3"]
        d, w = meta["depth_m"], meta["width_m"]
        norm = gamma * d * d * w
        f = read_forces(run)
        if f is None:
            continue
        ref = meta["seed"] == 14
        name = f"force_{key}.csv" if ref else f"force_{key}_s{meta['seed']}.csv"
        cols = ["u_over_d", "draft_N", "vertical_N", "wall_N", "draft_all_N", "vertical_all_N"]
        with open(RES / name, "w") as out:
            out.write(",".join(cols) + "\n")
            for i in range(len(f["u_over_d"])):
                out.write(",".join(f"{f[c][i]:.6g}" for c in cols) + "\n")
        entry = {
            "seed": meta["seed"],
            "d_m": d,
            "w_m": w,
            "w_over_d": wd,
            "D_m": meta["mean_diameter_m"],
            "d_over_D": meta["ratio_d_over_D"],
            "speed_m_per_s": meta["speed_m_per_s"],
            "grains": meta["grains"],
            "wall_time_cut_s": meta["wall_time_s"],
            "wall_time_bed_s": bed["wall_time_s"],
            "gamma0_N_per_m3": gamma,
            "porosity": cut["porosity"],
            "gamma0_region": "grain centres in 0 <= x < 3 d, level - d <= y < level, |z| < w/2",
            "gamma0_bulk_N_per_m3": bed["bulk_unit_weight_N_per_m3"],
            "porosity_bulk": 1 - bed["bulk_solid_fraction"],
            "half_bin_width_m": meta["half_bin_width_m"],
            "end_wall_x_m": meta["end_wall_x_m"],
            "floor_below_tip_m": meta["floor_below_tip_m"],
            "norm_N": norm,
            "norm": "gamma0 d^2 w",
            "travel_d": float(f["u_over_d"][-1]),
            "complete": meta.get("complete", True),
            "dt_over_pwave": meta.get("dt_over_pwave"),
            "trimmed_grains": meta.get("trimmed_grains", 0),
        }
        entry.update(windows(f, norm, 3))
        field = HERE / "fields" / f"{run}.npz"
        if field.exists():
            z = np.load(field)
            u = z["u"] / d
            pos, rad = z["pos"], z["radius"]
            gamma_grain = 2650.0 * 9.81
            ok = np.isfinite(pos[0][:, 0])
            nz = noise(pos[0][ok], rad[ok], bed, w)
            entry["surface_noise"] = nz
            rows = []
            entry["pile"] = {}
            for s in SNAPS:
                k = int(np.argmin(abs(u - s)))
                if abs(u[k] - s) > 0.05:
                    continue
                face = z["u"][k]
                ok = np.isfinite(pos[k][:, 0])
                pk, rk = pos[k][ok], rad[ok]
                centre, strip = centre_profile(pk, rk, face, bed, w)
                for x, y in centre:
                    rows.append(("centre", s, "", x, y, ""))
                fig = {"centre_strip_columns": strip}
                ahead = [(x, y) for x, y in centre if x >= 0]
                if ahead:
                    xp, yp = max(ahead, key=lambda t: t[1])
                    fig["centre_peak_height_d"] = yp
                    fig["centre_peak_x_d"] = xp
                    fig["centre_mean_height_0_1d"] = float(
                        np.mean([y for x, y in ahead if x < 1.0])
                    )
                    fig["centre_pile_front_x_d"] = next(
                        (x for x, y in ahead if x > xp and y < 2 * nz["centre_sd_d"]), None
                    )
                for st in STATIONS:
                    prof, nx = lateral_profile(pk, rk, face + st * d, bed)
                    for zz, y, ys in prof:
                        rows.append(("across", s, st, zz, y, ys))
                    fig[f"ridge_at_{st:g}d"] = ridge(prof, w, d, 2 * nz["lateral_sd_d"])
                sp = spilled(pos[k], rad, pos[0], face, bed, w, gamma_grain)
                sp["swept_weight_N"] = gamma * d * d * w * s
                fig["spilled"] = sp
                entry["pile"][f"u_{s:g}d"] = fig
            if ref:
                with open(RES / f"pile_{key}.csv", "w") as out:
                    out.write("kind,u_over_d,x_station_d,coord_d,y_d,y_smoothed_d\n")
                    for kind, s, st, c, y, ys in rows:
                        out.write(
                            f"{kind},{s:g},{st if st == '' else f'{st:g}'},{c:.4f},{y:.4f},"
                            f"{'' if ys == '' else f'{ys:.4f}'}\n"
                        )
        summary.setdefault(key, {})[f"seed_{meta['seed']}"] = entry
    for e in summary.values():
        seeds = [v for k, v in e.items() if k.startswith("seed_")]
        if len(seeds) > 1:
            e["seed_spread"] = {}
            for k in range(3):
                vals = [s[f"window_{k}"]["draft_norm"] for s in seeds if f"window_{k}" in s]
                if len(vals) > 1:
                    e["seed_spread"][f"window_{k}_draft_norm"] = {
                        "mean": float(np.mean(vals)),
                        "sd": float(np.std(vals, ddof=1)),
                        "n": len(vals),
                    }
    (RES / "summary.json").write_text(
        json.dumps(summary, indent=1, sort_keys=True, default=float) + "\n"
    )
    for key, e in sorted(summary.items()):
        for sk, s in sorted(e.items()):
            if not sk.startswith("seed_"):
                continue
            print(
                f"{key} {sk}: gamma0 {s['gamma0_N_per_m3']:.0f} N/m3, porosity {s['porosity']:.3f}, "
                f"grains {s['grains']}, cut {s['wall_time_cut_s']:.0f} s"
            )
            for k in range(3):
                wdw = s.get(f"window_{k}")
                if wdw:
                    print(
                        f"  [{k},{k + 1}) d: draft {wdw['draft_N']:.3f} N (sd {wdw['draft_sd_N']:.3f}), "
                        f"P/(g d2 w) {wdw['draft_norm']:.2f} (sd {wdw['draft_sd_norm']:.2f}), "
                        f"vertical {wdw['vertical_N']:.3f} N, all-contacts {wdw['draft_all_N']:.3f} N, "
                        f"wall share {wdw['wall_share']:.2f}"
                    )
            for u, fig in s.get("pile", {}).items():
                print(
                    f"  {u}: centre peak {fig.get('centre_peak_height_d', float('nan')):.2f} d at "
                    f"{fig.get('centre_peak_x_d', float('nan')):.2f} d, front {fig.get('centre_pile_front_x_d')}"
                )
                for st in STATIONS:
                    print(f"    ridge at {st:g} d: {fig[f'ridge_at_{st:g}d']}")
                sp = fig["spilled"]
                print(
                    f"    spilled: ahead inside {sp['ahead_inside']:.3f} N, ahead outside {sp['ahead_outside']:.3f} N, "
                    f"behind outside {sp['behind_outside']:.3f} N, share {sp['ahead_outside_share']}, "
                    f"swept {sp['swept_weight_N']:.3f} N"
                )
        if "seed_spread" in e:
            print(f"  seed spread: {e['seed_spread']}")


if __name__ == "__main__":
    main()
