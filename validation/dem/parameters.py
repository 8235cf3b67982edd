#!/usr/bin/env python3
"""soilcut's soil parameters from the DEM element tests and the DEM's band (stdlib only).

Usage: python3 validation/dem/parameters.py [--campaign reference|damp0] [--cases DIR]

Reads a campaign's element tests (campaigns.py: `reference`, the default,
results/element/; `damp0`, the shear undamped, results/element_damp0/),
biaxial_*.csv (raw records every 0.2 % of axial strain), results/repose.json
and results/mechanism/*.csv, writes ELEMENT/parameters.json and, for the
campaign soilcut is compared with (campaigns.YARDSTICK, `damp0` since
issue 31), the case files cases/validation/*.toml (with --cases DIR: the
campaign's case files in DIR instead, for any campaign), and prints the
tables of docs/validation.md.
The rule, fixed before any cut was compared with soilcut (plane strain,
compression positive, gamma = eps_1 - eps_3, eps_v = eps_1 + eps_3):

- elastic part: isotropic plane-strain elasticity fitted to the first record
  (eps_1 = 0.2 %): nu from eps_3 / eps_1 = -nu / (1 - nu), E from
  eps_1 = q (1 - nu^2) / E, q = s1 - s3; the plastic strains are
  eps_v^p = eps_v - q (1 + nu)(1 - 2 nu) / E and gamma^p = gamma - q (1 + nu) / E;
- mobilised friction sin(phi) = (s1 - s3) / (s1 + s3), raw;
- dilation sin(psi) = -d eps_v^p / d gamma^p, the least-squares slope over
  gamma^p +- 0.01 (a derivative needs a window; it is stated, not tuned);
- initial (phi_c, psi_c): phi where eps_v^p is largest (the characteristic
  state, where plastic contraction turns into dilation) and the mean plastic
  dilation before it, sin(psi_c) = -eps_v^p,max / gamma^p there; where the
  plastic strain dilates from the first record on (no contractive branch),
  the first record and the dilation of the first plastic strain (psi there);
- peak (phi_p, psi_p): the largest raw phi for eps_1 <= 0.2 (before the
  critical-state windows), the largest psi within +- 0.01 of gamma^p of
  it; gamma_p = gamma^p there;
- residual (phi_r, psi_r): the means over eps_1 in [0.3, 0.5], the
  critical state (`noise_deg`: the standard deviation of the raw phi there;
  `drift_deg`: the mean over [0.4, 0.5] less the mean over [0.3, 0.4), which
  a steady state keeps within the noise); gamma_r the first gamma^p after
  the peak from which the mean phi over the next 0.02 of eps_1 is within
  0.5 degree of phi_r;
- the keys of a cut: every angle and gamma interpolated linearly in sigma_3
  at gamma_0 d / 2 (the mean vertical stress along a band from the tip to
  the surface) between the two tests that bracket it;
- band: dB the mean of the DEM band thickness (mechanism.py) over every
  interval of the vertical d/D = 10 monolayer cuts in the full bin at the
  default speed (the calibration cut), u >= 0.5 d,
  but at most 0.9 d (soilcut's band is thinner than the cut is deep);
  (issue 31: the campaign's own cuts at its speed where their mechanism has
  been measured; where it has not, the `reference` campaign's band, and the
  printout says so;)
  u_p = gamma_p dB, u_r = gamma_r dB;
- repose: the heap test (results/repose.json); the DEM pile's own front
  slope is reported beside it (docs/validation.md).
"""

import csv
import json
import math
import statistics
import sys
from pathlib import Path

from campaigns import (
    CAMPAIGNS,
    YARDSTICK,
    campaign_option,
    compared_key,
    config_key,
)
from campaigns import (
    RESULTS as HERE,
)

D50 = 2.0  # mean grain diameter (mm) at d/D = 10
WALL_FRICTION = 20.0  # blade-grain contact friction (degrees), set in grains.py
CUTS = {"vertical": (20.0, 90.0), "raked30": (20.0, 30.0), "deep": (25.0, 90.0)}  # depth (mm), rake
CASES = Path(__file__).resolve().parent.parent.parent / "cases" / "validation"
X_END = 200.0  # the DEM bin's end wall ahead of the tip's start (mm), bed.py
TRAVEL = 2.0  # the DEM cuts' travel (in d), cut.py


def slope(x, y):
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else 0.0


def asind(v):
    return math.degrees(math.asin(max(-1.0, min(1.0, v))))


def test(path):
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(path.open())]
    e1 = [r["eps_axial"] for r in rows]
    e3 = [r["eps_lateral"] for r in rows]
    s1 = [r["sigma_axial_Pa"] for r in rows]
    s3 = [r["sigma_lateral_Pa"] for r in rows]
    phi = [r["mobilised_friction_deg"] for r in rows]
    q0 = s1[0] - s3[0]
    nu = -(e3[0] / e1[0]) / (1 - e3[0] / e1[0])
    young = q0 * (1 - nu**2) / e1[0]
    q = [a - b for a, b in zip(s1, s3)]
    evp = [a + b - qq * (1 + nu) * (1 - 2 * nu) / young for a, b, qq in zip(e1, e3, q)]
    gp = [a - b - qq * (1 + nu) / young for a, b, qq in zip(e1, e3, q)]
    psi = []
    for i in range(len(rows)):
        w = [k for k in range(len(rows)) if abs(gp[k] - gp[i]) <= 0.01]
        psi.append(asind(-slope([gp[k] for k in w], [evp[k] for k in w])) if len(w) >= 3 else 0.0)
    c = max(range(len(rows) // 2), key=lambda i: evp[i])
    p = max((i for i in range(len(rows)) if e1[i] <= 0.2), key=lambda i: phi[i])
    late = [i for i in range(len(rows)) if e1[i] >= 0.4]
    before = [i for i in range(len(rows)) if 0.3 <= e1[i] < 0.4]
    last = before + late
    phi_r = sum(phi[i] for i in last) / len(last)
    drift = (sum(phi[i] for i in late) / len(late)) - sum(phi[i] for i in before) / len(before)
    psi_r = asind(-slope([gp[i] for i in last], [evp[i] for i in last]))
    r = p
    for i in range(p, len(rows)):
        ahead = [phi[k] for k in range(i, len(rows)) if e1[k] <= e1[i] + 0.02]
        if abs(sum(ahead) / len(ahead) - phi_r) <= 0.5:
            r = i
            break
    near = [i for i in range(len(rows)) if abs(gp[i] - gp[p]) <= 0.01]
    return {
        "young_Pa": young,
        "poisson": nu,
        "phi_c": phi[c],
        "psi_c": asind(-evp[c] / gp[c]) if c > 0 else psi[0],
        "gamma_c": gp[c],
        "phi_p": phi[p],
        "psi_p": max(psi[i] for i in near),
        "gamma_p": gp[p],
        "phi_r": phi_r,
        "psi_r": psi_r,
        "gamma_r": gp[r],
        "drift_deg": drift,
        "noise_deg": statistics.stdev(phi[i] for i in last),
        "eps_v_first_over_eps_1": (e1[0] + e3[0]) / e1[0],
    }


def interpolate(tests, sigma, key):
    s = sorted(tests)
    lo = max([v for v in s if v <= sigma], default=s[0])
    hi = min([v for v in s if v >= sigma], default=s[-1])
    if hi == lo:
        return tests[lo][key]
    f = (sigma - lo) / (hi - lo)
    return tests[lo][key] * (1 - f) + tests[hi][key] * f


def band_width(campaign):
    """Mean DEM band thickness (mm) over the vertical d/D = 10 monolayer cuts of a
    campaign at its speed (the cuts whose mechanism has been measured), and the
    number of intervals."""
    values = []
    runs = [
        json.loads(p.read_text())
        for p in sorted((HERE / CAMPAIGNS[campaign]["cuts"]).glob("*.json"))
    ]
    for meta in runs:
        path = HERE / "mechanism" / (meta["run"] + ".csv")
        if config_key(meta) != compared_key("vertical", campaign) or not path.exists():
            continue
        for row in csv.DictReader(path.open()):
            t = float(row["band_thickness_mm"])
            if float(row["u_over_d"]) >= 0.5 and math.isfinite(t):
                values.append(t)
    if not values:
        return None, 0
    return sum(values) / len(values), len(values)


def main(campaign, cases):
    element = HERE / CAMPAIGNS[campaign]["element"]
    tests = {}
    for path in sorted(element.glob("biaxial_*.csv")):
        tests[float(path.stem.split("_")[1])] = test(path)
    bed = json.loads((HERE / "beds" / "bed_r10_s14.json").read_text())
    repose = json.loads((HERE / "repose.json").read_text())["repose_deg"]
    band, n = band_width(campaign)
    band_from = campaign
    if band is None and campaign != "reference":
        band, n = band_width("reference")
        band_from = "reference"
    print(
        "| σ3 (Pa) | solid fraction | E (kPa) | ν | εv/ε1 first | φc | ψc | φp | ψp | γp | φr (noise) | ψr | γr | drift of φr |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for s, t in sorted(tests.items()):
        solid = json.loads((element / f"biaxial_{s:g}.json").read_text())[
            "solid_fraction_before_shear"
        ]
        print(
            f"| {s:g} | {solid:.3f} | {t['young_Pa'] / 1e3:.0f} | {t['poisson']:.2f} | {t['eps_v_first_over_eps_1']:.2f} | "
            f"{t['phi_c']:.1f} | {t['psi_c']:.1f} | {t['phi_p']:.1f} | {t['psi_p']:.1f} | {t['gamma_p']:.3f} | "
            f"{t['phi_r']:.1f} (± {t['noise_deg']:.1f}) | {t['psi_r']:.1f} | {t['gamma_r']:.3f} | {t['drift_deg']:+.1f} |"
        )
    keys = {}
    for name, (depth, _) in CUTS.items():
        sigma = bed["unit_weight_N_per_m3"] * depth * 1e-3 / 2
        k = {
            key: interpolate(tests, sigma, key)
            for key in ("phi_c", "psi_c", "phi_p", "psi_p", "gamma_p", "phi_r", "psi_r", "gamma_r")
        }
        k["sigma_Pa"] = sigma
        if band is not None:
            width = min(band, 0.9 * depth)
            k["band_width_mm"] = width
            k["peak_shear_mm"] = k["gamma_p"] * width
            k["residual_shear_mm"] = k["gamma_r"] * width
        k["repose"] = repose
        keys[name] = k
    print()
    print(
        f"band width dB = {band if band is None else round(band, 2)} mm (mean of {n} intervals"
        + (
            ""
            if band_from == campaign
            else f" of the {band_from} campaign's cuts: no mechanism of the {campaign} cuts"
        )
        + f"), repose {repose:.1f}°, wall friction {WALL_FRICTION:g}° (set)"
    )
    print("| cut | σ* (Pa) | φc | φp | φr | ψc | ψp | ψr | up (mm) | ur (mm) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, k in keys.items():
        print(
            f"| {name} | {k['sigma_Pa']:.0f} | {k['phi_c']:.1f} | {k['phi_p']:.1f} | {k['phi_r']:.1f} | "
            f"{k['psi_c']:.1f} | {k['psi_p']:.1f} | {k['psi_r']:.1f} | "
            f"{k.get('peak_shear_mm', math.nan):.2f} | {k.get('residual_shear_mm', math.nan):.2f} |"
        )
    out = {"tests": {f"{s:g}": t for s, t in sorted(tests.items())}, "keys": keys}
    if band_from != campaign:
        out["band_from"] = band_from
    (element / "parameters.json").write_text(json.dumps(out, indent=1) + "\n")
    if cases is None and campaign == YARDSTICK:
        cases = CASES
    if band is not None and cases is not None:
        cases.mkdir(parents=True, exist_ok=True)
        for name, k in keys.items():
            write_case(cases, name, k, bed, campaign, band_from)


def write_case(cases, name, k, bed, campaign, band_from):
    """cases/validation/<name>.toml from the rule's keys: nothing else is set."""
    depth, rake = CUTS[name]
    wall = (
        f"\n[bin]\nlength = {X_END:g}  # the DEM bin's end wall ahead of the tip's start\n"
        if rake == 90.0
        else ""
    )
    element = CAMPAIGNS[campaign]["element"]
    text = f"""# The DEM soil-bin cut {name} of validation/dem/ (docs/validation.md), with
# soilcut's keys from the DEM's element tests (the {campaign} campaign,
# results/{element}/) and its measured band (the {band_from} campaign's
# cuts) only, written by
# python3 validation/dem/parameters.py --campaign {campaign}
# (the rule is in its header): never tuned to the cut. Lengths in mm; unit
# weight 1 (forces in γ0·mm²; the DEM's γ0 is {bed["unit_weight_N_per_m3"]:.0f} N/m³ per unit width
# of its slab).
name = "validation-{name}"
title = "DEM validation: {name}, d = {depth:g} mm, α = {rake:g}°, to u = {TRAVEL:g} d"
model = "refined"

[blade]
depth = {depth:g}
wall_friction = {WALL_FRICTION:g}  # blade-grain contact friction, set in the DEM
rake = {rake:g}

[soil]
unit_weight = 1.0
# biaxial tests interpolated at σ3 = γ0 d / 2 = {k["sigma_Pa"]:.0f} Pa
friction = {{ initial = {k["phi_c"]:.1f}, peak = {k["phi_p"]:.1f}, residual = {k["phi_r"]:.1f} }}
dilation = {{ initial = {k["psi_c"]:.1f}, peak = {k["psi_p"]:.1f}, residual = {k["psi_r"]:.1f} }}
peak_shear = {k["peak_shear_mm"]:.2f}      # γp dB, γp = {k["gamma_p"]:.4f}
residual_shear = {k["residual_shear_mm"]:.2f}  # γr dB, γr = {k["gamma_r"]:.4f}
repose = {k["repose"]:.1f}  # heap test
d50 = {D50:g}  # mean grain diameter
band_width = {k["band_width_mm"]:.2f}  # the DEM's band (mechanism.py), at most 0.9 d
{wall}
[run]
travel = {TRAVEL * depth:g}
"""
    (cases / f"{name}.toml").write_text(text)


if __name__ == "__main__":
    chosen = campaign_option(sys.argv)
    main(chosen, Path(sys.argv[sys.argv.index("--cases") + 1]) if "--cases" in sys.argv else None)
