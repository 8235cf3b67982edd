#!/usr/bin/env python3
"""Figures for docs/reproduction.md from finished soilcut runs (stdlib only).

Usage: python3 docs/scripts/analyse.py OUTDIR [OUTDIR ...]

For each run folder (written by `soilcut run`) prints the summary figures,
the mean normalised force over each unit of u/d, the initial-stage β* swings,
the longest stay of the band at one location, far-band excursions (and the
force at those after u/d = 1), the band
jump nearest each peak, the slope of the window means and, for a variant, its
window means against the shipped run's.
"""

import csv
import json
import sys
from pathlib import Path


def load(run):
    run = Path(run)
    summary = json.loads((run / "summary.json").read_text())
    rows = list(csv.DictReader((run / "history.csv").open()))

    def col(name):
        return [float(r[name]) for r in rows]

    names = ("u_over_d", "force_norm", "beta_deg", "x_emergence", "u", "friction_deg")
    return summary, {k: col(k) for k in names}


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
    """Bands more than `far` depths ahead of the blade that last < `brief`
    increments: how many, how many of one increment, the furthest (depths),
    and for each after u/d = 1 (first increment i, last j) the force at i
    and at j + 1 as changes from the force at i − 1."""
    ahead = [(x - u) / depth for x, u in zip(h["x_emergence"], h["u"])]
    f, v = h["force_norm"], h["u_over_d"]
    count, single, late, run = 0, 0, [], 0
    for k, a in enumerate(ahead + [0.0]):
        if a > far:
            run += 1
            continue
        if 0 < run < brief:
            count += 1
            single += run == 1
            i = k - run
            if v[i] > 1.0 and i > 0 and k < len(f):
                late.append((f[i] / f[i - 1] - 1, f[k] / f[i - 1] - 1))
        run = 0
    return count, single, max(ahead), late


def spread(changes):
    """Least, median and largest of `changes` (fractions) in %, and how many
    are negative."""
    c = sorted(changes)
    return f"{100 * c[0]:+.2f} % to {100 * c[-1]:+.2f} % (median {100 * c[len(c) // 2]:+.2f} %, {sum(x < 0 for x in c)} down)"


def initial_range(h, depth, until=0.5):
    """Least and largest β* for u/d < until, each with its emergence point's
    distance ahead of the blade (length)."""
    rows = [
        (b, x - u)
        for v, b, x, u in zip(h["u_over_d"], h["beta_deg"], h["x_emergence"], h["u"])
        if v < until
    ]
    return min(rows), max(rows)


def after_first_peak(s, h, span=0.2):
    """From the first peak to the least force within `span` depths after it:
    the increments, how many emerge within 1 length unit of the most common
    emergence point (rounded), that point, the forces and the band's φ at both
    ends."""
    if not s["peaks"]:
        return None
    u = h["u_over_d"]
    p = min(range(len(u)), key=lambda i: abs(u[i] - s["peaks"][0]["u_over_d"]))
    after = [i for i in range(p, len(u)) if u[i] <= u[p] + span]
    m = min(after, key=lambda i: h["force_norm"][i])
    xs = [round(h["x_emergence"][i]) for i in range(p, m + 1)]
    mode = max(set(xs), key=xs.count)
    near = sum(abs(h["x_emergence"][i] - mode) <= 1.0 for i in range(p, m + 1))
    f, phi = h["force_norm"], h["friction_deg"]
    return m - p + 1, near, mode, (u[p], f[p], phi[p]), (u[m], f[m], phi[m])


def peak_jumps(s, h, depth, after=0.4):
    """For each peak: the nearest band jump (an increment whose emergence point
    lies more than 0.25 d from the previous one, the summary's rule), in
    increments from the peak (negative: before it), how far ahead of the blade
    the band emerges after that jump (depths), and the least force within
    `after` depths after the peak as a change from the peak (fraction)."""
    u, f, x = h["u_over_d"], h["force_norm"], h["x_emergence"]
    jumps = [i for i in range(1, len(x)) if abs(x[i] - x[i - 1]) > 0.25 * depth]
    rows = []
    for pk in s["peaks"]:
        p = min(range(len(u)), key=lambda i: abs(u[i] - pk["u_over_d"]))
        least = min(f[i] for i in range(p, len(u)) if u[i] <= u[p] + after)
        if jumps:
            j = min(jumps, key=lambda i: (abs(i - p), i))
            rows.append((u[p], j - p, (x[j] - h["u"][j]) / depth, least / f[p] - 1))
        else:
            rows.append((u[p], None, None, least / f[p] - 1))
    return rows


def window_slopes(means):
    """Change of the mean force from each unit window of u/d to the next (per d)."""
    return [b - a for a, b in zip(means, means[1:])]


def against_shipped(run, means):
    """For a variant folder CASE-VARIANT beside the shipped CASE: the relative
    change of each window mean from the shipped run's."""
    run = Path(run)
    for variant in ("-angle-of-mean-shear", "-by-position", "-per-node-formula", "-explicit"):
        if run.name.endswith(variant):
            base = run.parent / run.name[: -len(variant)]
            if (base / "history.csv").exists():
                _, hb = load(base)
                return base, [m / b - 1 for m, b in zip(means, window_means(hb))]
    return None


def main():
    for run in sys.argv[1:]:
        s, h = load(run)
        depth = h["u"][1] / h["u_over_d"][1]
        peaks = " ".join(f"({p['u_over_d']:.2f}, {p['force_norm']:.2f})" for p in s["peaks"])
        means = " ".join(f"{m:.3f}" for m in window_means(h))
        stay, at = longest_stay(h, depth)
        far, single, furthest, late = far_excursions(h, depth)
        print(
            f"{run}: initial {s['initial_force_norm']:.4f}; max {s['max_force_norm']:.2f} at u/d {s['u_over_d_at_max']:.2f}; "
            f"peaks {peaks or 'none'}; band jumps {s['band_jumps']}; sheared_fraction {s['sheared_fraction']:.2f}; "
            f"mass_drift_rel {s['mass_drift_rel']:.1e}; dilation_area {s['dilation_area']:.1f}; "
            f"mean force per unit u/d [{means}]; beta swings (u/d<0.5) {beta_swings(h)}; "
            f"longest stay {stay} increments from u/d {at:.2f}; brief far bands (>4 d ahead) {far} ({single} of one increment), furthest {furthest:.1f} d"
        )
        if late:
            print(
                f"  brief far bands after u/d 1: {len(late)}; force at the first increment against the one before: "
                f"{spread([a for a, _ in late])}; the increment after each: {spread([b for _, b in late])}"
            )
        (b0, x0), (b1, x1) = initial_range(h, depth)
        print(
            f"  initial stage (u/d < 0.5): beta* from {b0:.1f} deg ({x0:.0f} ahead, {x0 / depth:.1f} d) to {b1:.1f} deg ({x1:.0f} ahead)"
        )
        stay = after_first_peak(s, h)
        if stay:
            n, near, x, (u0, f0, p0), (u1, f1, p1) = stay
            print(
                f"  after the first peak: {near} of {n} increments emerge within 1 of x = {x}; "
                f"force {f0:.2f} at u/d {u0:.2f} to {f1:.2f} at u/d {u1:.2f}; band phi {p0:.1f} to {p1:.1f} deg"
            )
        if s["peaks"]:
            parts = []
            for up, k, ahead, drop in peak_jumps(s, h, depth):
                jump = (
                    "no band jump"
                    if k is None
                    else f"nearest band jump {k:+d} increments, to {ahead:.1f} d ahead"
                )
                parts.append(
                    f"u/d {up:.2f}: {jump}, least force within 0.4 d after {100 * drop:+.0f} %"
                )
            print("  at each peak: " + "; ".join(parts))
        slopes = " ".join(f"{d:.2f}" for d in window_slopes(window_means(h)))
        print(f"  slope of the window means (per d): {slopes}")
        cmp = against_shipped(run, window_means(h))
        if cmp:
            base, rel = cmp
            print(f"  window means against {base}: " + " ".join(f"{100 * r:+.1f} %" for r in rel))


if __name__ == "__main__":
    main()
