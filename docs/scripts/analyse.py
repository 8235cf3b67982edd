#!/usr/bin/env python3
"""Figures for docs/reproduction.md from finished soilcut runs (stdlib only).

Usage: python3 docs/scripts/analyse.py OUTDIR [OUTDIR ...]

For each run folder (written by `soilcut run`) prints the summary figures,
the mean normalised force over each unit of u/d, the initial-stage β* swings,
the longest stay of the band at one location, and far-band excursions.
"""
import csv
import json
import sys
from pathlib import Path


def load(run):
    run = Path(run)
    summary = json.loads((run / "summary.json").read_text())
    rows = list(csv.DictReader((run / "history.csv").open()))
    col = lambda name: [float(r[name]) for r in rows]
    return summary, {k: col(k) for k in ("u_over_d", "force_norm", "beta_deg", "x_emergence", "u")}


def window_means(h):
    means = []
    k = 0
    while True:
        sel = [f for u, f in zip(h["u_over_d"], h["force_norm"]) if k <= u < k + 1]
        if not sel:
            return means
        means.append(sum(sel) / len(sel))
        k += 1


def beta_swings(h, until=0.5, size=10.0):
    """Reversals of β* larger than `size` degrees for u/d < until."""
    betas = [b for u, b in zip(h["u_over_d"], h["beta_deg"]) if u < until]
    swings, last, direction = 0, betas[0], 0
    for b in betas[1:]:
        if abs(b - last) >= size:
            d = 1 if b > last else -1
            if d != direction:
                swings += 1
                direction = d
            last = b
    return swings


def longest_stay(h, depth):
    """Longest run of increments with the same emergence point (ground frame)."""
    best, start, run = (0, 0.0), 0, 1
    x = h["x_emergence"]
    for i in range(1, len(x) + 1):
        if i < len(x) and x[i] == x[i - 1]:
            run += 1
            continue
        if run > best[0]:
            best = (run, h["u_over_d"][start])
        start, run = i, 1
    return best


def far_excursions(h, depth, far=4.0, brief=25):
    """Bands more than `far` depths ahead of the blade that last < `brief` increments."""
    ahead = [(x - u) / depth for x, u in zip(h["x_emergence"], h["u"])]
    count, run = 0, 0
    for a in ahead + [0.0]:
        if a > far:
            run += 1
        else:
            if 0 < run < brief:
                count += 1
            run = 0
    return count, max(ahead)


def main():
    for run in sys.argv[1:]:
        s, h = load(run)
        depth = h["u"][1] / h["u_over_d"][1]
        peaks = " ".join(f"({p['u_over_d']:.2f}, {p['force_norm']:.2f})" for p in s["peaks"])
        means = " ".join(f"{m:.3f}" for m in window_means(h))
        stay, at = longest_stay(h, depth)
        far, furthest = far_excursions(h, depth)
        print(f"{run}: initial {s['initial_force_norm']:.4f}; max {s['max_force_norm']:.2f} at u/d {s['u_over_d_at_max']:.2f}; "
              f"peaks {peaks or 'none'}; band jumps {s['band_jumps']}; sheared_fraction {s['sheared_fraction']:.2f}; "
              f"mass_drift_rel {s['mass_drift_rel']:.1e}; dilation_area {s['dilation_area']:.1f}; "
              f"mean force per unit u/d [{means}]; beta swings (u/d<0.5) {beta_swings(h)}; "
              f"longest stay {stay} increments from u/d {at:.2f}; brief far bands (>4 d ahead) {far}, furthest {furthest:.1f} d")


if __name__ == "__main__":
    main()
