#!/usr/bin/env python3
"""soilcut's mechanism every increment beside the DEM's every 0.25 d, to the
DEM's travel, under four band rules (issue 40 items 2 and 4; stdlib only).

Usage: python3 validation/mechanism_compare.py OUT [--run] [--soilcut PATH]

With --run it first runs, for every cut <name> of the validation (vertical,
raked30, deep) and every band rule <rule> (`choices.band_angles`: the paper's
`mean-of-angles`, the default, and `angle-of-mean-shear`; and, beyond the
paper, `choices.band_strength`'s `crossed-columns` and
`crossed-columns-unfloored`: docs/model.md §20), an ensemble of 7
perturbed members (docs/model.md §12.1) of cases/validation/<name>.toml to the
DEM's travel (vertical 5 d, raked30 and deep 2 d: the last interval of
validation/dem/results/long/<name>_*_mechanism.csv), into OUT/<name>-<rule>; the
vertical cut's end wall at 15 d from the tip's start (`bin.length`), as the
DEM's long bin's (validation/dem/grains.py --long), the others' as their
cases' (the DEM's raked and deep cuts ran in the usual bin). PATH is the
command line, by default target/release/soilcut (or under
$CARGO_TARGET_DIR). Without --run it reads OUT as written.

Prints, soilcut's ensemble mean ± sd over its 7 members beside the DEM's
mean ± sd over its 3 seeds:
- per unit window [k, k+1) d: the force P/(γ0 d²), the block's weight
  W/(γ0 d²), Eq. (1)'s factor P/W, the face's mobilised friction δ, the
  friction angle φ the block mobilises; then β, the emergence ahead of the
  tip, the pile's height, its top's distance ahead of the tip and its area;
- the same every 0.25 d (the interval (u − 0.25, u] d of the DEM's rows);
- the verdict's numbers: soilcut / DEM of every quantity per window, under
  every rule (angles and the pile top's position as differences); the
  force's growth from the first window; the force's distance from the
  DEM's seeds' mean in their sd; and what makes P differ, P = W ×
  P/W with Eq. (1)'s factor sin(β + φ)/sin(α + β + φ + δ) at soilcut's
  window means changed by one of the DEM's angles at a time.

Definitions, the DEM's in validation/dem/mechanism_series.py's docstring:
- soilcut's per-increment quantities are history.csv's: force_norm, weight
  (over γ0 d²), force_factor, face_friction_deg, beta_deg, (x_emergence − u)
  / d; φ is back-computed with the DEM's formula, φ = 90° − β −
  atan((v + W)/h) (which returns friction_deg, the band's angle, at every
  increment: crates/io/tests/mechanism_columns.rs); a window's or an
  interval's value is the mean over the increments that start in it (u in
  [k, k+1) d, or [u − 0.25, u) d), then mean ± sd over the members;
- the DEM's force is the resultant of the face's mean force over an
  interval, hypot(P_h_norm, P_v_norm); its P/W that over W_norm (the moving
  block the mechanism script flags, the pile on it included); δ its
  delta_deg; a window's value is the mean of its four intervals (ending in
  (k, k+1] d) per seed, then mean ± sd over the seeds; β, the emergence and
  φ leave out intervals in which no band has formed (β ≤ 0: the raked cut's
  first 0.25 d);
- the pile, for both as mechanism.py's `pile` and mechanism_series.py
  define it: the ground ahead of the face at the level (x > u − d cot α, u
  the tip's x), its highest point (height over d, its x − u over d), and its
  area above the level from there to 10 d ahead of the tip (over d²);
  soilcut's from frames.csv at the frame nearest the interval's end u (the
  frames fall on multiples of 0.25 d), by the trapezoid rule.
"""

import csv
import math
import statistics
import subprocess
import sys
from os import environ
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEM = ROOT / "validation" / "dem" / "results" / "long"
CUTS = {"vertical": (20.0, 90.0), "raked30": (20.0, 30.0), "deep": (25.0, 90.0)}
# rule: the key that sets it
RULES = {
    "mean-of-angles": 'choices.band_angles="mean-of-angles"',
    "angle-of-mean-shear": 'choices.band_angles="angle-of-mean-shear"',
    "crossed-columns": 'choices.band_strength="crossed-columns"',
    "crossed-columns-unfloored": 'choices.band_strength="crossed-columns-unfloored"',
}
MEMBERS = 7
LONG_BIN = 15.0  # d: the DEM's long bin's end wall ahead of the tip's start
AHEAD = 10.0  # d: the pile area's reach ahead of the tip (mechanism_series.py)
STEP = 0.25  # d: the DEM's interval
# (key, label, digits): the force quantities, then the geometry
FORCES = (
    ("P", "P/(γ0 d²)", 2),
    ("W", "W/(γ0 d²)", 2),
    ("F", "P/W", 2),
    ("delta", "δ (°)", 1),
    ("phi", "φ mobilised (°)", 1),
)
GEOMETRY = (
    ("beta", "β (°)", 1),
    ("emergence", "emergence − tip (d)", 2),
    ("pile_h", "pile height (d)", 2),
    ("pile_x", "pile top − tip (d)", 2),
    ("pile_a", "pile area (d²)", 2),
)
BAND = ("beta", "emergence", "phi")  # undefined where no band has formed


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def spread(values):
    v = [x for x in values if x is not None and math.isfinite(x)]
    if not v:
        return math.nan, math.nan
    return statistics.fmean(v), statistics.stdev(v) if len(v) > 1 else 0.0


def fmt(ms, digits):
    m, s = ms
    return f"{m:.{digits}f} ± {s:.{digits}f}" if math.isfinite(m) else "–"


def eq1(beta, phi, delta, alpha):
    """Eq. (1)'s factor P/W (degrees): sin(β + φ) / sin(α + β + φ + δ)."""
    b, f, d, a = (math.radians(t) for t in (beta, phi, delta, alpha))
    return math.sin(b + f) / math.sin(a + b + f + d)


def mobilised_phi(h, v, w, beta):
    """mechanism_series.py's `mobilised_phi`: 90 − β − atan((v + W)/h), degrees."""
    return 90.0 - beta - math.degrees(math.atan2(v + w, h))


def dem_runs(name):
    """Per DEM seed: {u: quantities} every 0.25 d (u the interval's end, in d)."""
    out = []
    for path in sorted(DEM.glob(f"{name}_r10_s*_mechanism.csv")):
        series = {}
        for r in rows(path):
            u = round(r["u_over_d"] / STEP) * STEP
            p = math.hypot(r["P_h_norm"], r["P_v_norm"])
            band = r["beta_deg"] > 0.0
            series[u] = {
                "P": p,
                "W": r["W_norm"],
                "F": p / r["W_norm"] if r["W_norm"] > 0 else math.nan,
                "delta": r["delta_deg"],
                "phi": r["phi_mob_deg"] if band else math.nan,
                "beta": r["beta_deg"] if band else math.nan,
                "emergence": r["emergence_over_d"] if band else math.nan,
                "pile_h": r["pile_height_over_d"],
                "pile_x": r["pile_ahead_over_d"],
                "pile_a": r["pile_area_over_d2"],
                "W_band": r["W_band_norm"],
                "phi_band": r["phi_mob_band_deg"] if band else math.nan,
            }
        out.append(series)
    return out


def pile(points, face, tip, depth):
    """(height, top − tip, area) over d, d and d² of the ground x > face, the
    area to AHEAD d beyond the tip (trapezoids; zero beyond the frame)."""
    ahead = sorted((x, y) for x, y in points if x > face - 1e-9 * depth)
    if not ahead:
        return math.nan, math.nan, math.nan
    xt, top = max(ahead, key=lambda p: p[1])
    end = tip + AHEAD * depth
    area = 0.0
    for (x0, y0), (x1, y1) in zip(ahead, ahead[1:]):
        if x0 >= end:
            break
        if x1 > end:
            y1 = y0 + (y1 - y0) * (end - x0) / (x1 - x0)
            x1 = end
        area += 0.5 * (y0 + y1) * (x1 - x0)
    return top / depth, (xt - tip) / depth, area / depth**2


def member(folder, depth, rake):
    """One soilcut member: ({u: quantities} every 0.25 d, per-increment rows)."""
    steps = []
    for r in rows(folder / "history.csv"):
        scale = r["force"] / r["force_norm"]  # γ0 d²
        h, v, w = r["force_h"] / scale, r["force_v"] / scale, r["weight"] / scale
        steps.append(
            {
                "u": r["u_over_d"],
                "P": r["force_norm"],
                "W": w,
                "F": r["force_factor"],
                "delta": r["face_friction_deg"],
                "phi": mobilised_phi(h, v, w, r["beta_deg"]),
                "beta": r["beta_deg"],
                "emergence": (r["x_emergence"] - r["u"]) / depth,
            }
        )
    frames = {}
    for r in rows(folder / "frames.csv"):
        frames.setdefault(r["u"], []).append((r["x"], r["y"]))
    back = depth / math.tan(math.radians(rake))
    series = {}
    end = max(s["u"] for s in steps)
    for k in range(1, int(end / STEP + 1e-9) + 2):
        u = k * STEP
        sel = [s for s in steps if u - STEP - 1e-9 <= s["u"] < u - 1e-9]
        if len(sel) == 0:
            continue
        q = {key: statistics.fmean(s[key] for s in sel) for key in sel[0] if key != "u"}
        at = min(frames, key=lambda x: abs(x - u * depth))
        q["pile_h"], q["pile_x"], q["pile_a"] = pile(frames[at], at - back, at, depth)
        series[u] = q
    return series


def window(series, k, key):
    """The mean of a series' intervals ending in (k, k + 1] d."""
    vals = [q[key] for u, q in series.items() if k < u <= k + 1 + 1e-9]
    vals = [v for v in vals if math.isfinite(v)]
    return statistics.fmean(vals) if vals else math.nan


def run(out, soilcut):
    for name, (depth, _) in CUTS.items():
        travel = max(max(s) for s in dem_runs(name))
        for rule, key in RULES.items():
            cmd = [
                str(soilcut),
                "run",
                str(ROOT / "cases" / "validation" / f"{name}.toml"),
                "--ensemble",
                str(MEMBERS),
                "--quiet",
                "--no-plots",
                "--force",
                "--out",
                str(out / f"{name}-{rule}"),
                "--set",
                f"run.travel={travel * depth:g}",
                "--set",
                key,
                "--set",
                f'title="{name} to {travel:g} d, band rule {rule} (validation/mechanism_compare.py)"',
            ]
            if name == "vertical":
                cmd += ["--set", f"bin.length={LONG_BIN * depth:g}"]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def table(title, quantities, lines):
    print(title)
    print()
    print("| cut | rule | u/d | " + " | ".join(label for _, label, _ in quantities) + " |")
    print("|---|---|---|" + "---|" * len(quantities))
    print("\n".join(lines))
    print()


def main(argv):
    out = Path(argv[0])
    soilcut = Path(environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "release" / "soilcut"
    if "--soilcut" in argv:
        soilcut = Path(argv[argv.index("--soilcut") + 1])
    if "--run" in argv:
        run(out, soilcut)
    rows_w = {"forces": [], "geometry": []}
    rows_i = {"forces": [], "geometry": []}
    ratios, band_only, sensitivity, growth, seeds = [], [], [], [], []
    dem_label = "DEM (3 seeds)"
    for name, (depth, rake) in CUTS.items():
        dem = dem_runs(name)
        travel = max(max(s) for s in dem)
        dem_label = f"DEM ({len(dem)} seeds)"
        windows = range(int(round(travel)))
        for w in windows:
            band_only.append(
                f"| {name} | [{w}, {w + 1}) | "
                + " | ".join(
                    fmt(spread([window(s, w, key) for s in dem]), digits)
                    for key, digits in (("W", 2), ("W_band", 2), ("phi", 1), ("phi_band", 1))
                )
                + " |"
            )
        for rule in RULES:
            folder = out / f"{name}-{rule}"
            runs = [
                member(m, depth, rake)
                for m in sorted(folder.iterdir())
                if m.is_dir() and m.name.startswith("k")
            ]
            for group, quantities in (("forces", FORCES), ("geometry", GEOMETRY)):
                for w in windows:
                    cells = [
                        f"{fmt(spread([window(s, w, key) for s in runs]), d)} / "
                        f"{fmt(spread([window(s, w, key) for s in dem]), d)}"
                        for key, _, d in quantities
                    ]
                    rows_w[group].append(
                        f"| {name} | {rule} | [{w}, {w + 1}) | " + " | ".join(cells) + " |"
                    )
                for k in range(1, int(round(travel / STEP)) + 1):
                    u = k * STEP
                    cells = [
                        f"{fmt(spread([s.get(u, {}).get(key) for s in runs]), d)} / "
                        f"{fmt(spread([s.get(u, {}).get(key) for s in dem]), d)}"
                        for key, _, d in quantities
                    ]
                    rows_i[group].append(f"| {name} | {rule} | {u:g} | " + " | ".join(cells) + " |")
            for w in windows:
                cells, sm, dm = [], {}, {}
                for key, _, _ in FORCES + GEOMETRY:
                    sm[key] = spread([window(s, w, key) for s in runs])[0]
                    dm[key] = spread([window(s, w, key) for s in dem])[0]
                    if key in ("delta", "phi", "beta"):
                        cells.append(f"{sm[key] - dm[key]:+.1f}°")
                    elif key in ("pile_x",):
                        cells.append(f"{sm[key] - dm[key]:+.2f}")
                    else:
                        cells.append(f"{sm[key] / dm[key]:.2f}")
                ratios.append(f"| {name} | {rule} | [{w}, {w + 1}) | " + " | ".join(cells) + " |")
                # Eq. (1)'s factor at soilcut's window means, and the factor
                # by which it changes with one of the DEM's angles instead.
                own = eq1(sm["beta"], sm["phi"], sm["delta"], rake)
                swaps = [
                    eq1(
                        dm["beta"] if k == "beta" else sm["beta"],
                        dm["phi"] if k == "phi" else sm["phi"],
                        dm["delta"] if k == "delta" else sm["delta"],
                        rake,
                    )
                    / own
                    for k in ("delta", "phi", "beta")
                ]
                sensitivity.append(
                    f"| {name} | {rule} | [{w}, {w + 1}) | {sm['P'] / dm['P']:.2f} | "
                    f"{sm['W'] / dm['W']:.2f} | {sm['F'] / dm['F']:.2f} | "
                    + " | ".join(f"{x:.2f}" for x in swaps)
                    + " |"
                )
            # The window's force against the DEM's seed spread: soilcut's
            # ensemble mean less the seeds' mean, in the seeds' sd.
            seeds.append(
                f"| {name} | {rule} | "
                + " | ".join(
                    "{:+.1f}".format((spread([window(s, w, "P") for s in runs])[0] - dp[0]) / dp[1])
                    for w in windows
                    for dp in [spread([window(s, w, "P") for s in dem])]
                )
                + " |"
            )
            growth.append(
                f"| {name} | {rule} | "
                + " | ".join(
                    f"{spread([window(s, w, 'P') / window(s, 0, 'P') for s in runs])[0]:.2f} / "
                    f"{spread([window(s, w, 'P') / window(s, 0, 'P') for s in dem])[0]:.2f}"
                    for w in windows
                    if w > 0
                )
                + " |"
            )
    print(f"soilcut: mean ± sd over {MEMBERS} members; {dem_label}: mean ± sd over seeds.")
    print("Each cell soilcut / DEM.")
    print()
    table("Per unit window, the block and its forces:", FORCES, rows_w["forces"])
    table("Per unit window, the band and the pile:", GEOMETRY, rows_w["geometry"])
    print("soilcut against the DEM per window: ratios soilcut / DEM, differences in degrees:")
    print()
    every = FORCES + GEOMETRY
    print("| cut | rule | window | " + " | ".join(label for _, label, _ in every) + " |")
    print("|---|---|---|" + "---|" * len(every))
    print("\n".join(ratios))
    print()
    print("The force's growth, soilcut / DEM: the window's mean force over the first's")
    print("(per member and per seed, then the mean):")
    print()
    print("| cut | rule | [1, 2) | [2, 3) | [3, 4) | [4, 5) |")
    print("|---|---|---|---|---|---|")
    print("\n".join(growth))
    print()
    print("The force against the DEM's seed spread: (soilcut's mean − the seeds' mean) / the")
    print("seeds' sd, per window (within ±1: inside the spread):")
    print()
    print("| cut | rule | [0, 1) | [1, 2) | [2, 3) | [3, 4) | [4, 5) |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(seeds))
    print()
    print("What makes P differ: P = W × P/W; Eq. (1)'s factor at soilcut's window means of")
    print("β, φ and δ changes by the factor shown when one of them takes the DEM's value:")
    print()
    print(
        "| cut | rule | window | P ratio | W ratio | P/W ratio | × DEM's δ | × DEM's φ | × DEM's β |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    print("\n".join(sensitivity))
    print()
    print("The DEM's block with and without the grains rolling down the pile's front")
    print("(W_norm and W_band_norm over γ0 d², and the φ each gives):")
    print()
    print("| cut | window | W | W above the band | φ mobilised (°) | φ above the band (°) |")
    print("|---|---|---|---|---|---|")
    print("\n".join(band_only))
    print()
    table(
        "Every 0.25 d (u the interval's end), the block and its forces:", FORCES, rows_i["forces"]
    )
    table("Every 0.25 d, the band and the pile:", GEOMETRY, rows_i["geometry"])


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1].startswith("-"):
        sys.exit(__doc__.split("\n\n")[1])
    main(sys.argv[1:])
