#!/usr/bin/env python3
"""soilcut against the DEM cuts of validation/dem/ (stdlib only).

Usage: python3 validation/compare.py OUT

OUT holds, for every cut NAME of CUTS, the soilcut runs OUT/NAME-u1 ... OUT/NAME-u5
(travel 1 d ... 5 d, or fewer: as far as the cut goes), written by
validation/run.sh. Prints the figures docs/validation.md quotes (markdown
tables), writes validation/dem/results/cut_*_measured.csv (the DEM's
resultant force as `soilcut compare` and `soilcut fit` read it: u in mm, force
per unit width in units of gamma0 mm^2 with gamma0 = 1) and the surface
pictures docs/img/validation_surface_*.svg.

Definitions (the same for soilcut and the DEM):
- force: resultant blade force per unit width over gamma0 d^2;
- soilcut first peak: the first of summary.json's peaks (an interior local
  maximum with a prominence of at least 5 % of the largest force);
- DEM first peak: the largest value of the DEM force, smoothed over +-0.1 d,
  for u <= 1 d;
- mean force per unit of u/d: the mean over [k, k+1) d;
- slope of the rise: least-squares slope of the force against u/d over [1, end];
- pile: the highest point of the ground in front of the face (for the raked
  blade from 4 d back along the face, which carries soil behind the tip),
  how far ahead of the tip it lies, and the mean slope of its front between
  80 % and 20 % of that height;
- force direction: atan of the vertical (upward on the blade) over the
  horizontal blade force, each summed over the cut (for a vertical blade,
  the face friction mobilised);
- reach: the furthest point ahead of the tip where the ground stands at least
  0.1 d above the level surface (soilcut also records the slip line's
  emergence, x_emergence - u).
"""
import csv
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEM = ROOT / "validation" / "dem" / "results"
IMG = ROOT / "docs" / "img"
CUTS = {"vertical": (20.0, 90.0), "raked30": (20.0, 30.0), "deep": (25.0, 90.0)}


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def smooth(values, k):
    out = []
    for i in range(len(values)):
        w = values[max(0, i - k) : i + k + 1]
        out.append(sum(w) / len(w))
    return out


def window_means(u, f):
    means, k = [], 0
    while True:
        sel = [y for x, y in zip(u, f) if k <= x < k + 1]
        if not sel:
            return means
        means.append(sum(sel) / len(sel))
        k += 1


def slope(u, f, lo):
    pts = [(x, y) for x, y in zip(u, f) if x >= lo]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    den = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / den


def pile(points, start, depth, tip):
    """Height, front slope and crest of the pile and the reach of raised ground, from `start`
    on (crest and reach measured from the tip)."""
    ahead = sorted((x, y) for x, y in points if x > start)
    if not ahead:
        return float("nan"), float("nan"), float("nan"), float("nan")
    k = max(range(len(ahead)), key=lambda i: ahead[i][1])
    top = ahead[k][1]
    front = [(x, y) for x, y in ahead[k:] if 0.2 * top <= y <= 0.8 * top]
    s = slope([p[0] for p in front], [p[1] for p in front], -1e9) if len(front) > 1 else float("nan")
    raised = [x for x, y in ahead if y >= 0.1 * depth]
    reach = max(raised) - tip if raised else 0.0
    return top, s, reach, ahead[k][0] - tip


def dem_cut(name):
    f = rows(DEM / f"cut_{name}_forces.csv")
    u = [float(r["u_over_d"]) for r in f]
    force = [float(r["force_norm"]) for r in f]
    ratio = sum(float(r["force_v_N_per_m"]) for r in f) / sum(float(r["force_h_N_per_m"]) for r in f)
    surf = {}
    for r in rows(DEM / f"cut_{name}_surface.csv"):
        surf.setdefault(round(float(r["u_over_d"]) * 2) / 2, []).append((float(r["x_mm"]), float(r["y_mm"])))
    return u, force, surf, math.degrees(math.atan(ratio))


def soilcut_run(folder):
    h = rows(folder / "history.csv")
    p = rows(folder / "profile.csv")
    summary = json.loads((folder / "summary.json").read_text())
    return h, [(float(r["x"]), float(r["y"])) for r in p], summary


def interpolate(xs, ys, x):
    """ys at x, linear between the samples (xs increasing), None outside them."""
    if not xs or x < xs[0] or x > xs[-1]:
        return None
    lo, hi = 0, len(xs) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    if xs[hi] == xs[lo]:
        return ys[lo]
    t = (x - xs[lo]) / (xs[hi] - xs[lo])
    return ys[lo] + t * (ys[hi] - ys[lo])


def rms(folder, u, force):
    """RMS difference of the DEM force and soilcut's (run `folder`), and their mean ratio."""
    h = rows(folder / "history.csv")
    su = [float(r["u_over_d"]) for r in h]
    sf = [float(r["force_norm"]) for r in h]
    pairs = [(interpolate(su, sf, x), y) for x, y in zip(u, force)]
    pairs = [(a, b) for a, b in pairs if a is not None]
    err = (sum((a - b) ** 2 for a, b in pairs) / len(pairs)) ** 0.5
    return err, sum(a for a, _ in pairs) / sum(b for _, b in pairs)


def write_measured(name, depth, u, force):
    with open(DEM / f"cut_{name}_measured.csv", "w") as f:
        f.write("u,force\n")
        for x, y in zip(u, force):
            f.write(f"{x * depth:.6g},{y * depth * depth:.6g}\n")


def svg(name, depth, dem_surf, model_surf):
    """Ground surfaces at u = 1 ... 5 d: DEM dashed, soilcut solid (x, y in units of d)."""
    x0, x1, y0, y1, w, h = -2.0, 9.0, -1.2, 3.6, 880, 384
    px = lambda x: (x / depth - x0) / (x1 - x0) * w
    py = lambda y: h - (y / depth - y0) / (y1 - y0) * h
    colours = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"]
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h + 40}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h + 40}" fill="white"/>',
           f'<line x1="0" y1="{py(0):.1f}" x2="{w}" y2="{py(0):.1f}" stroke="#bbb"/>']
    for k in range(int(x0), int(x1) + 1):
        out.append(f'<text x="{px(k * depth):.1f}" y="{h + 15}" text-anchor="middle">{k}</text>')
    out.append(f'<text x="{w / 2}" y="{h + 32}" text-anchor="middle">x / d (dashed: DEM, solid: soilcut; colours: u = 1 ... 5 d)</text>')
    for i, k in enumerate(sorted(model_surf)):
        c = colours[i % len(colours)]
        for pts, dash in ((dem_surf.get(float(k), []), ' stroke-dasharray="4 3"'), (model_surf[k], "")):
            pts = [p for p in sorted(pts) if x0 * depth <= p[0] <= x1 * depth]
            pts = pts[:: max(1, len(pts) // 300)]
            if pts:
                line = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts)
                out.append(f'<polyline points="{line}" fill="none" stroke="{c}" stroke-width="1.5"{dash}/>')
    out.append("</svg>")
    (IMG / f"validation_surface_{name}.svg").write_text("\n".join(out) + "\n")


def main(out):
    out = Path(out)
    print("| cut | first force: soilcut | Coulomb | FEE | soilcut first peak (at u/d) | DEM first peak (at u/d) | force direction atan(ΣFv/ΣFh): soilcut / DEM |")
    print("|---|---|---|---|---|---|---|")
    table2, table3 = [], []
    for name, (depth, rake) in CUTS.items():
        runs = sorted(out.glob(f"{name}-u*"), key=lambda p: int(p.name.rsplit("-u", 1)[1]))
        if not runs:
            continue
        have_dem = (DEM / f"cut_{name}_forces.csv").exists()
        u, force, dem_surf, mobilised = dem_cut(name) if have_dem else ([], [], {}, float("nan"))
        if have_dem:
            write_measured(name, depth, u, force)
        h, _, summary = soilcut_run(runs[-1])
        su = [float(r["u_over_d"]) for r in h]
        sf = [float(r["force_norm"]) for r in h]
        base = summary.get("baselines", {})
        coulomb = base.get("coulomb", {}).get("force_norm", float("nan"))
        fee = base.get("fee", {}).get("force_norm", float("nan"))
        direction = math.degrees(math.atan(sum(float(r["force_v"]) for r in h) / sum(float(r["force_h"]) for r in h)))
        first = summary["peaks"][0] if summary["peaks"] else {"force_norm": float("nan"), "u_over_d": float("nan")}
        dem_peak = "pending"
        if have_dem:
            sm = smooth(force, 5)
            k = max((i for i in range(len(u)) if u[i] <= 1.0), key=lambda i: sm[i])
            dem_peak = f"{sm[k]:.3f} ({u[k]:.2f})"
        print(f"| {name} | {sf[0]:.3f} | {coulomb:.3f} | {fee:.3f} | {first['force_norm']:.3f} ({first['u_over_d']:.2f}) "
              f"| {dem_peak} | {direction:.1f}° / {mobilised:.1f}° |")
        dm, mm = window_means(u, force), window_means(su, sf)
        dm += [float("nan")] * (len(mm) - len(dm))
        table2.append(f"| {name} | " + " | ".join(f"{a:.2f} / {b:.2f}" for a, b in zip(mm, dm))
                      + " |" * (5 - len(mm)) + f" | {slope(su, sf, 1.0):.3f} / {slope(u, force, 1.0):.3f} |")
        model_surf = {}
        for run in runs:
            kd = int(run.name.rsplit("-u", 1)[1])
            hk, prof, _ = soilcut_run(run)
            model_surf[kd] = prof
            face = kd * depth
            # A raked face carries soil behind the tip: look from 4 d back along it.
            back = 0.0 if rake == 90.0 else 4.0 * depth / math.tan(math.radians(rake))
            mt, ms, mr, mc = pile(prof, face - back - 1e-9, depth, face)
            dt, ds, dr, dc = pile(dem_surf.get(float(kd), []), face - back + 1.0, depth, face)
            emerge = float(hk[-1]["x_emergence"]) - float(hk[-1]["u"])
            table3.append(f"| {name} | {kd} | {mt / depth:.2f} / {dt / depth:.2f} | {mc / depth:.2f} / {dc / depth:.2f} "
                          f"| {-ms:.2f} / {-ds:.2f} "
                          f"| {mr / depth:.2f} / {dr / depth:.2f} | {emerge / depth:.2f} |")
        svg(name, depth, dem_surf, model_surf)
    print()
    print("Fit on the vertical cut, prediction of the others: RMS difference from the DEM force and")
    print("soilcut's mean force over the DEM's (element-test parameters; fitted to the vertical cut):")
    print()
    print("| cut | element tests: RMS | mean ratio | fitted: RMS | mean ratio |")
    print("|---|---|---|---|---|")
    for name in CUTS:
        fitted = out / f"{name}-fitted"
        runs = sorted(out.glob(f"{name}-u*"), key=lambda p: int(p.name.rsplit("-u", 1)[1]))
        if not (DEM / f"cut_{name}_forces.csv").exists() or not runs or not fitted.exists():
            continue
        u, force, _, _ = dem_cut(name)
        a, b = rms(runs[-1], u, force), rms(fitted, u, force)
        print(f"| {name} | {a[0]:.2f} | {a[1]:.2f} | {b[0]:.2f} | {b[1]:.2f} |")
    print()
    print("Mean force per unit of u/d, soilcut / DEM, and the slope of the rise over u/d >= 1:")
    print()
    print("| cut | [0,1) | [1,2) | [2,3) | [3,4) | [4,5) | slope |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(table2))
    print()
    print("Pile and reach at u = k d, soilcut / DEM (in units of d; the pile front slope as tan):")
    print()
    print("| cut | u/d | pile height | crest ahead of the tip | front slope | reach of raised ground | soilcut emergence ahead |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(table3))


if __name__ == "__main__":
    main(sys.argv[1])
