#!/usr/bin/env python3
"""soilcut beside the DEM cuts of validation/dem/ (stdlib only).

Usage: python3 validation/compare.py OUT [--campaign damp0|reference]

OUT holds, for every cut NAME of CUTS, soilcut ensembles written by
validation/run.sh: OUT/NAME (the element-test keys, the default face
friction), OUT/NAME-sign (the same with `choices.face_friction = "sign"`,
the rule before issue 20) and OUT/NAME-fitted (friction angles fitted to
the vertical DEM cut). The DEM's numbers come from a campaign's summary
(validation/dem/campaigns.py; validation/dem/summarise.py --campaign C):
by default the yardstick's, `damp0` (the cuts without numerical damping at
20 mm/s, results/summary_damp0.json), or `reference` (the damped cuts at
40 mm/s, results/summary.json), mean ± standard deviation over seeds.
Prints the tables docs/validation.md quotes and, for the yardstick only,
writes validation/bands.json, the band of soilcut / DEM ratios that
crates/io/tests/validation.rs holds soilcut to, and the ground pictures
docs/img/validation_surface_<name>.svg.

Definitions (the same for soilcut and the DEM):
- force: the resultant on the blade's face per unit width over gamma0 d^2
  (the DEM's blade-bottom contacts excluded); h and v its horizontal (draft)
  and vertical (upward on the blade) parts;
- window k: the mean over u in [k, k+1) d; soilcut's is its ensemble's mean
  and standard deviation over 7 perturbed members (docs/model.md §12.1);
- first force: soilcut's first increment (Coulomb's wedge at the angles it
  uses where the block rises along the face) and the DEM's mean over
  u in [0.05, 0.25] d (its first mobilisation);
- mechanism at u (every 0.5 d): soilcut's beta* and emergence ahead of the
  tip (x_emergence - u) averaged over the 0.25 d before u, the DEM's from
  validation/dem/mechanism.py over the same interval; the pile's height
  above the level ground ahead of the face and the slope of its front
  between 80 % and 20 % of that height (soilcut: frames.csv nearest u).
"""

import csv
import json
import math
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "validation" / "dem"))
from campaigns import (  # noqa: E402 (after the path is set)
    CAMPAIGNS,
    YARDSTICK,
    campaign_option,
    compared_key,
    config_key,
)
from campaigns import RESULTS as DEM  # noqa: E402

CUTS = {"vertical": (20.0, 90.0), "raked30": (20.0, 30.0), "deep": (25.0, 90.0)}
AT = (0.5, 1.0, 1.5, 2.0)


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def spread(values):
    v = [x for x in values if x is not None and math.isfinite(x)]
    return (
        (statistics.fmean(v), statistics.stdev(v) if len(v) > 1 else 0.0) if v else (math.nan, 0.0)
    )


def members(folder):
    return sorted(p for p in folder.iterdir() if p.is_dir() and p.name.startswith("k"))


def window(history, key, k, depth):
    sel = [r[key] for r in history if k <= r["u_over_d"] < k + 1]
    return statistics.fmean(sel) / (depth**2 if key != "force_norm" else 1.0) if sel else math.nan


def pile(points, face):
    """(height, front slope in degrees) of the ground ahead of x = face."""
    ahead = sorted((x, y) for x, y in points if x > face)
    if not ahead:
        return math.nan, math.nan
    k = max(range(len(ahead)), key=lambda i: ahead[i][1])
    top = ahead[k][1]
    front = [(x, y) for x, y in ahead[k:] if 0.2 * top <= y <= 0.8 * top]
    if top <= 0 or len(front) < 3:
        return top, math.nan
    mx = statistics.fmean(p[0] for p in front)
    my = statistics.fmean(p[1] for p in front)
    s = sum((p[0] - mx) * (p[1] - my) for p in front) / sum((p[0] - mx) ** 2 for p in front)
    return top, math.degrees(math.atan(-s))


def soilcut_numbers(folder, depth, rake):
    """Per member: windows of force_norm, h, v; first force; mechanism at AT."""
    out = []
    for m in members(folder):
        h = rows(m / "history.csv")
        n = {"first": h[0]["force_norm"]}
        half = [r["force_norm"] for r in h if r["u_over_d"] < 0.5]
        n["half_0"] = statistics.fmean(half)
        for k in range(2):
            n[f"window_{k}"] = window(h, "force_norm", k, depth)
            n[f"window_h_{k}"] = window(h, "force_h", k, depth)
            n[f"window_v_{k}"] = window(h, "force_v", k, depth)
        frames = {}
        for r in rows(m / "frames.csv"):
            frames.setdefault(r["u"], []).append((r["x"], r["y"]))
        back = 0.0 if rake == 90.0 else depth / math.tan(math.radians(rake))
        for at in AT:
            sel = [r for r in h if at - 0.25 < r["u_over_d"] <= at]
            if sel:
                n[f"beta@{at}"] = statistics.fmean(r["beta_deg"] for r in sel)
                n[f"emergence@{at}"] = statistics.fmean(r["x_emergence"] - r["u"] for r in sel)
            u = min(frames, key=lambda x: abs(x - at * depth))
            n[f"pile_height@{at}"], n[f"pile_slope@{at}"] = pile(frames[u], u - back)
        out.append(n)
    return out


def coulomb(path):
    """P/(γ0 d²) and β* of Coulomb's wedge in a `soilcut analytic` printout."""
    for line in path.read_text().splitlines():
        if line.startswith("Coulomb"):
            cells = line.split(")", 1)[1].split()
            return float(cells[1]), float(cells[4])
    return math.nan, math.nan


def svg(name, depth, dem_surf, model_surf):
    """Ground surfaces at u = 1, 2 d: every DEM seed dashed, soilcut's k+0 member solid."""
    x0, x1, y0, y1, w, h = -2.0, 6.0, -1.2, 2.4, 800, 360

    def px(x):
        return (x / depth - x0) / (x1 - x0) * w

    def py(y):
        return h - (y / depth - y0) / (y1 - y0) * h

    colours = {1.0: "#1b9e77", 2.0: "#d95f02"}
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h + 40}" font-family="sans-serif" font-size="12">',
        f'<rect width="{w}" height="{h + 40}" fill="white"/>',
        f'<line x1="0" y1="{py(0):.1f}" x2="{w}" y2="{py(0):.1f}" stroke="#bbb"/>',
    ]
    for k in range(int(x0), int(x1) + 1):
        out.append(f'<text x="{px(k * depth):.1f}" y="{h + 15}" text-anchor="middle">{k}</text>')
    out.append(
        f'<text x="{w / 2}" y="{h + 32}" text-anchor="middle">x / d (dashed: DEM seeds, solid: soilcut; green u = 1 d, orange u = 2 d)</text>'
    )
    for u, c in colours.items():
        lines = [(pts, ' stroke-dasharray="4 3"') for pts in dem_surf.get(u, [])] + [
            (model_surf.get(u, []), "")
        ]
        for pts, dash in lines:
            pts = [p for p in sorted(pts) if x0 * depth <= p[0] <= x1 * depth]
            if pts:
                line = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts)
                out.append(
                    f'<polyline points="{line}" fill="none" stroke="{c}" stroke-width="1.5"{dash}/>'
                )
    out.append("</svg>")
    (ROOT / "docs" / "img" / f"validation_surface_{name}.svg").write_text("\n".join(out) + "\n")


def surfaces(name, folder, depth, campaign):
    """The DEM seeds' grounds and soilcut's (frames.csv of k+0) at u = 1 and 2 d."""
    dem_surf = {}
    cuts = DEM / CAMPAIGNS[campaign]["cuts"]
    for meta in (json.loads(p.read_text()) for p in sorted(cuts.glob(f"{name}_r10_s*.json"))):
        if config_key(meta) != compared_key(name, campaign):
            continue
        by_u = {}
        for r in rows(cuts / (meta["run"] + "_surface.csv")):
            by_u.setdefault(round(r["u_over_d"], 2), []).append((r["x_mm"], r["y_mm"]))
        for u in (1.0, 2.0):
            if u in by_u:
                dem_surf.setdefault(u, []).append(by_u[u])
    frames = {}
    for r in rows(folder / "k+0" / "frames.csv"):
        frames.setdefault(r["u"], []).append((r["x"], r["y"]))
    model_surf = {u: frames[min(frames, key=lambda x: abs(x - u * depth))] for u in (1.0, 2.0)}
    return dem_surf, model_surf


def fmt(m, s, digits=2):
    return f"{m:.{digits}f} ± {s:.{digits}f}" if math.isfinite(m) else "–"


def dem(summary, key):
    e = summary.get(key)
    return (e["mean"], e["sd"]) if e else (math.nan, 0.0)


def main(out, campaign):
    out = Path(out)
    c = CAMPAIGNS[campaign]
    summary = json.loads((DEM / f"summary{c['suffix']}.json").read_text())
    print(
        f"DEM campaign: {campaign} (results/{c['cuts']}/, the cuts at {c['speed'] * 1e3:g} mm/s, damping {c['damping']:g})"
    )
    print()
    bands = {}
    print(
        "Forces (P/(γ0 d²); soilcut: ensemble mean ± sd over 7 members; DEM: mean ± sd over seeds):"
    )
    print()
    print(
        "| cut | rule | soilcut first | DEM early | soilcut [0,1) | DEM [0,1) | ratio | soilcut [1,2) | DEM [1,2) | ratio |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    components, mechanism, first = [], [], []
    default = {}  # each cut's members under the element-test keys, for the speed table
    for name, (depth, rake) in CUTS.items():
        d = summary.get(compared_key(name, campaign))
        if d is None:
            continue
        for rule in ("", "-sign", "-fitted"):
            folder = out / f"{name}{rule}"
            if not folder.exists():
                continue
            s = soilcut_numbers(folder, depth, rake)
            if rule == "":
                default[name] = s
                if campaign == YARDSTICK:
                    svg(name, depth, *surfaces(name, folder, depth, campaign))

            def get(key, s=s):
                return spread([n.get(key) for n in s])

            cells = [fmt(*get("first")), fmt(*dem(d, "early"))]
            for k in range(2):
                sm, dm = get(f"window_{k}")[0], dem(d, f"window_{k}")[0]
                cells += [fmt(*get(f"window_{k}")), fmt(*dem(d, f"window_{k}")), f"{sm / dm:.2f}"]
                if rule == "":
                    # The band the test holds soilcut to: the ratio ± twice the
                    # combined relative spread of the two sides.
                    rel = math.hypot(get(f"window_{k}")[1] / sm, dem(d, f"window_{k}")[1] / dm)
                    bands[f"{name}_window_{k}"] = {
                        "dem": dm,
                        "low": sm / dm * (1 - 2 * rel) - 0.01,
                        "high": sm / dm * (1 + 2 * rel) + 0.01,
                    }
            label = {"": "mobilised", "-sign": "sign (old)", "-fitted": "fitted φ"}[rule]
            print(f"| {name} | {label} | " + " | ".join(cells) + " |")
            if rule == "":
                (c0, b0), (cp, bp) = (
                    coulomb(out / f"{name}-analytic.txt"),
                    coulomb(out / f"{name}-analytic-peak.txt"),
                )
                first.append(
                    f"| {name} | {fmt(*get('first'), 3)} | {c0:.3f} (β = {b0:.1f}°) | "
                    f"{cp:.3f} (β = {bp:.1f}°) | {fmt(*dem(d, 'early'))} |"
                )
                components.append(
                    f"| {name} | "
                    + " | ".join(
                        f"{fmt(*get(f'window_{p}_{k}'))} / {fmt(*dem(d, f'window_{p}_{k}'))}"
                        for k in range(2)
                        for p in ("h", "v")
                    )
                    + " |"
                )
                for at in AT:
                    key = f"{at:.2f}"
                    mechanism.append(
                        f"| {name} | {at:g} | {fmt(*get(f'beta@{at}'), 1)} / {fmt(*dem(d, f'beta_deg@{key}'), 1)} | "
                        f"{fmt(get(f'emergence@{at}')[0] / depth, get(f'emergence@{at}')[1] / depth)} / "
                        f"{fmt(dem(d, f'emergence_mm@{key}')[0] / depth, dem(d, f'emergence_mm@{key}')[1] / depth)} | "
                        f"{fmt(get(f'pile_height@{at}')[0] / depth, get(f'pile_height@{at}')[1] / depth)} / "
                        f"{fmt(dem(d, f'pile_height_mm@{key}')[0] / depth, dem(d, f'pile_height_mm@{key}')[1] / depth)} | "
                        f"{fmt(*get(f'pile_slope@{at}'), 1)} / {fmt(*dem(d, f'pile_slope_deg@{key}'), 1)} |"
                    )
    print()
    print(
        "First force (P/(γ0 d²)): soilcut's first increment, Coulomb's wedge at the initial and the peak"
    )
    print(
        "friction angle (a block rising along the face, φw = 20°), the DEM's mean over u in [0.05, 0.25] d:"
    )
    print()
    print("| cut | soilcut first | Coulomb at φc | Coulomb at φp | DEM early |")
    print("|---|---|---|---|---|")
    print("\n".join(first))
    print()
    print("Horizontal and vertical parts (over γ0 d²), soilcut / DEM:")
    print()
    print("| cut | h [0,1) | v [0,1) | h [1,2) | v [1,2) |")
    print("|---|---|---|---|---|")
    print("\n".join(components))
    print()
    print("Mechanism, soilcut / DEM (lengths over d, angles in degrees):")
    print()
    print("| cut | u/d | β | emergence ahead of the tip | pile height | pile front slope |")
    print("|---|---|---|---|---|---|")
    print("\n".join(mechanism))
    keys = [
        config_key(
            {
                "name": "vertical",
                "ratio_d_over_D": 10.0,
                "slab_layers": 0,
                "run": "",
                "speed_m_per_s": v,
                "damping": c["damping"],
            }
        )
        for v in (0.04, 0.02, 0.01)
    ]
    speeds = [
        (f"{summary[key]['speed_m_per_s'] * 1e3:g} mm/s", summary[key])
        for key in keys
        if key in summary
    ]
    if speeds and "vertical" in default:
        s = default["vertical"]
        print()
        print(
            "The vertical cut's mean force over [0, 0.5) d against the DEM blade's speed (DEM: mean ± sd over"
        )
        print(
            "the seeds run at each speed, n in summarise.py's table), and soilcut's (element-test keys):"
        )
        print()
        print("| " + " | ".join(f"DEM at {label}" for label, _ in speeds) + " | soilcut |")
        print("|" + "---|" * (len(speeds) + 1))
        print(
            "| "
            + " | ".join(fmt(*dem(e, "half_0")) for _, e in speeds)
            + f" | {fmt(*spread([n['half_0'] for n in s]))} |"
        )
    print()
    if campaign == YARDSTICK:
        print(
            "The band crates/io/tests/validation.rs holds soilcut to (soilcut / DEM over [0, 1) d):"
        )
    else:
        print(
            f"The band against the {campaign} campaign (soilcut / DEM over [0, 1) d; not written:"
        )
        print(f"the test holds soilcut to the {YARDSTICK} campaign's):")
    print()
    print("| cut | band | ensemble ratio |")
    print("|---|---|---|")
    for key, b in sorted(bands.items()):
        if key.endswith("_window_0"):
            mid = (b["low"] + b["high"]) / 2
            print(f"| {key[: -len('_window_0')]} | {b['low']:.2f}-{b['high']:.2f} | {mid:.2f} |")
    if campaign == YARDSTICK:
        (ROOT / "validation" / "bands.json").write_text(
            json.dumps(bands, indent=1, sort_keys=True) + "\n"
        )


if __name__ == "__main__":
    chosen = campaign_option(sys.argv, YARDSTICK)
    main(sys.argv[1], chosen)
