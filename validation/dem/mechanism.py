#!/usr/bin/env python3
"""The mechanism of a DEM cut from its grain field (numpy; not Yade).

Usage: python3 validation/dem/mechanism.py [--campaign reference|damp0] RUN [RUN ...]
       (RUN: cut.py's run name)

Reads fields/RUN.npz (cut.py's grain field, not committed: a run's field is
on the machine that ran it) and RUN.json / RUN_surface.csv in the campaign's
folder (campaigns.py: results/cuts/, the default, or results/damp0/) and writes
results/mechanism/RUN.csv, one row per 0.25 d of travel (the interval ending
at u). Definitions, stated before any cut was compared with soilcut:

- speed ratio r of a grain: its displacement over the interval divided by
  the blade's; the moving block is the grains with r >= 0.5 ahead of the face;
- boundary: in every slice one mean diameter D high between the tip's level
  and the ground, the furthest grain ahead of the face with r >= 0.5;
  `beta_deg` the angle from the horizontal of the least-squares line through
  these points and the tip (the band's angle, soilcut's beta*);
- `emergence_mm`: how far ahead of the tip the furthest moving grain lies
  within 2 D of the ground (soilcut's x_emergence - u);
- `band_thickness_mm`: across the boundary line, the mean r of the grains
  in D-wide bins of signed distance from -10 D to 10 D; the distance between
  where it falls through 0.8 and 0.2 of the block's mean r (bins -10 D to
  -6 D), divided by 0.6 (the full width of a linear ramp);
- `pile_height_mm`, `pile_ahead_mm`, `pile_slope_deg`: the highest point of
  the ground ahead of the face, how far ahead of the tip, and the slope of
  the least-squares line through the ground ahead of it between 80 % and
  20 % of its height above the level;
- `block_ratio`: the block's mean r (1: it moves with the blade).
"""

import csv
import json
import math
import sys
from pathlib import Path

import numpy as np
from campaigns import CAMPAIGNS, bed_tag, campaign_option

HERE = Path(__file__).resolve().parent
MOVING = 0.5


def line_fit(x, y):
    """Least-squares slope and intercept of y on x."""
    a = np.vstack([x, np.ones_like(x)]).T
    return np.linalg.lstsq(a, y, rcond=None)[0]


def pile(ground, tip_x, face_x):
    """(height, ahead of the tip, front slope in degrees) of the ground ahead of the face."""
    ahead = [(x, y) for x, y in ground if x > face_x]
    if not ahead:
        return math.nan, math.nan, math.nan
    xt, top = max(ahead, key=lambda p: p[1])
    front = [(x, y) for x, y in ahead if x > xt and 0.2 * top <= y <= 0.8 * top]
    slope = math.nan
    if top > 0 and len(front) >= 3:
        s, _ = line_fit(np.array([p[0] for p in front]), np.array([p[1] for p in front]))
        slope = math.degrees(math.atan(-s))
    return top, xt - tip_x, slope


def flagged(meta, p0, p1, du, tip_x):
    """The grains of an interval: (ok, x, y, r, ahead, moving), ok the grains
    present at both ends (a mask of p1's rows), x, y their positions at the end,
    r their speed ratios, `ahead` those ahead of the face and `moving` the
    moving block's (r >= MOVING, ahead of the face, not below the tip's level
    by more than D); the last four over the ok grains."""
    d = meta["depth_mm"] * 1e-3
    D = meta["mean_diameter_m"]
    cot = 1.0 / math.tan(math.radians(meta["rake_deg"]))
    tip_y = meta["surface_level_m"] - d
    ok = ~np.isnan(p0[:, 0]) & ~np.isnan(p1[:, 0])
    x, y = p1[ok, 0], p1[ok, 1]
    r = np.hypot(*(p1[ok] - p0[ok]).T) / du
    face = tip_x - (y - tip_y) * cot  # the face's x at height y
    ahead = x > face
    moving = ahead & (r >= MOVING) & (y >= tip_y - D)
    return ok, x, y, r, ahead, moving


def interval(meta, p0, p1, du, tip_x, ground):
    d = meta["depth_mm"] * 1e-3
    D = meta["mean_diameter_m"]
    level = meta["surface_level_m"]
    cot = 1.0 / math.tan(math.radians(meta["rake_deg"]))
    tip_y = level - d
    _, x, y, r, ahead, moving = flagged(meta, p0, p1, du, tip_x)
    # the ground at each grain's column, for the slices and the emergence
    gx = np.array([q[0] for q in ground]) * 1e-3
    gy = np.array([q[1] for q in ground]) * 1e-3 + level
    top_at = np.interp(x, gx, gy)
    bx, by = [tip_x], [tip_y]
    for k in range(int((gy.max() - tip_y) / D) + 1):
        lo = tip_y + k * D
        sel = moving & (y >= lo) & (y < lo + D) & (y <= top_at)
        if sel.any():
            i = np.argmax(x[sel])
            bx.append(x[sel][i])
            by.append(y[sel][i])
    bx, by = np.array(bx), np.array(by)
    # the line through the tip: y - tip_y = t (x - tip_x), least squares in t
    dx, dy = bx - tip_x, by - tip_y
    t = float(np.sum(dx * dy) / np.sum(dx * dx)) if np.sum(dx * dx) > 0 else math.nan
    beta = math.degrees(math.atan(t))
    near_top = moving & (y >= top_at - 2 * D)
    emergence = (x[near_top].max() - tip_x) if near_top.any() else math.nan
    # signed distance to the line (positive ahead of / below it)
    n = np.array([t, -1.0]) / math.hypot(t, 1.0)
    dist = (x - tip_x) * n[0] + (y - tip_y) * n[1]
    zone = ahead & (y >= tip_y) & (y <= top_at)
    bins = np.arange(-10, 11) * D
    means = []
    for a, b in zip(bins[:-1], bins[1:]):
        sel = zone & (dist >= a) & (dist < b)
        means.append(r[sel].mean() if sel.sum() >= 3 else math.nan)
    means = np.array(means)
    centres = (bins[:-1] + bins[1:]) / 2
    inside = np.nanmean(means[:4])
    thickness = math.nan
    if inside > 0:
        hi = crossing(centres, means, 0.8 * inside)
        lo = crossing(centres, means, 0.2 * inside)
        if hi is not None and lo is not None and lo > hi:
            thickness = (lo - hi) / 0.6
    height, pile_ahead, slope = pile(
        [(q[0] * 1e-3, q[1] * 1e-3) for q in ground], tip_x, tip_x - d * cot
    )
    block = ahead & (dist < -3 * D) & (y >= tip_y) & (y <= top_at)
    return (
        beta,
        emergence * 1e3,
        thickness * 1e3,
        height * 1e3,
        pile_ahead * 1e3,
        slope,
        float(r[block].mean()) if block.any() else math.nan,
    )


def crossing(x, v, level):
    """The first x where v falls through `level` (linear between bins)."""
    for i in range(len(v) - 1):
        if np.isnan(v[i]) or np.isnan(v[i + 1]):
            continue
        if v[i] >= level > v[i + 1]:
            return x[i] + (v[i] - level) / (v[i] - v[i + 1]) * (x[i + 1] - x[i])
    return None


def analyse(run, campaign="reference"):
    folder = HERE / "results" / CAMPAIGNS[campaign]["cuts"]
    meta = json.loads((folder / (run + ".json")).read_text())
    bed = json.loads((HERE / "results" / "beds" / (f"bed_{bed_tag(meta)}.json")).read_text())
    meta["surface_level_m"] = bed["surface_level_m"]
    f = np.load(HERE / "fields" / (run + ".npz"))
    u, pos = f["u"], f["pos"]
    grounds = {}
    with open(folder / (run + "_surface.csv")) as fh:
        for row in csv.DictReader(fh):
            grounds.setdefault(round(float(row["u_over_d"]), 2), []).append(
                (float(row["x_mm"]), float(row["y_mm"]))
            )
    d = meta["depth_mm"] * 1e-3
    out = []
    for k in range(1, len(u)):
        s = round(u[k] / d / 0.25) * 0.25
        ground = grounds.get(round(s, 2)) or grounds[min(grounds, key=lambda v: abs(v - s))]
        row = interval(meta, pos[k - 1], pos[k], u[k] - u[k - 1], u[k], ground)
        out.append((u[k] / d,) + row)
    path = HERE / "results" / "mechanism" / (run + ".csv")
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w") as fh:
        fh.write(
            "u_over_d,beta_deg,emergence_mm,band_thickness_mm,pile_height_mm,pile_ahead_mm,"
            "pile_slope_deg,block_ratio\n"
        )
        for r in out:
            fh.write(",".join(f"{v:.4g}" for v in r) + "\n")
    return out


def main():
    campaign = campaign_option(sys.argv)
    for run in sys.argv[1:]:
        if not (HERE / "fields" / (run + ".npz")).exists():
            print(
                f"{run}: no grain field fields/{run}.npz (not committed; rerun the cut to make it)",
                file=sys.stderr,
            )
            continue
        for r in analyse(run, campaign):
            print(run, " ".join(f"{v:.3g}" for v in r))


if __name__ == "__main__":
    main()
