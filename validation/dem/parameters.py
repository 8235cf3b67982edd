#!/usr/bin/env python3
"""soilcut's soil parameters from the DEM element tests (stdlib only).

Usage: python3 validation/dem/parameters.py

Reads results/biaxial.csv and results/repose.json and prints the case keys of
cases/validation/*.toml with where each comes from. Definitions (plane strain,
compression positive, gamma = eps_1 - eps_3, eps_v = eps_1 + eps_3, every
series smoothed over +-5 records, i.e. +-1 % of axial strain):

- mobilised friction sin(phi) = (s1 - s3) / (s1 + s3);
- dilation sin(psi) = -d(eps_v) / d(gamma);
- initial (phi_c, psi_c): phi at the characteristic state (largest eps_v,
  where contraction turns into dilation) and the mean dilation angle of the
  contractive branch before it, sin(psi_c) = -eps_v,max / gamma_char;
- peak (phi_p, psi_p): the largest phi, and the largest psi within +-1 % of
  axial strain of it; gamma_p the shear strain there;
- residual (phi_r, psi_r): the means over the last third of the test
  (eps_1 >= 0.2), the critical state; gamma_r the first shear strain after
  the peak where phi is within 0.5 degrees of phi_r;
- shears in a band of width dB: u_p = gamma_p dB, u_r = gamma_r dB (the
  band's shear as that of the element test: a choice, the DEM band width is
  not measured, dB = BAND_D50 d50 with d50 the mean grain diameter);
- repose: the slope of the heap of results/repose.json.
"""
import csv
import json
import math
from pathlib import Path

HERE = Path(__file__).resolve().parent / "results"
D50 = 2.0  # mean grain diameter (mm)
BAND_D50 = 5.0  # band width in grain diameters (choice)
WALL_FRICTION = 20.0  # blade-grain contact friction (degrees), set in grains.py


def smooth(v, k=5):
    return [sum(v[max(0, i - k) : i + k + 1]) / len(v[max(0, i - k) : i + k + 1]) for i in range(len(v))]


def biaxial():
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader((HERE / "biaxial.csv").open())]
    e1 = [r["eps_axial"] for r in rows]
    gam = [r["eps_axial"] - r["eps_lateral"] for r in rows]
    ev = smooth([r["eps_vol"] for r in rows])
    phi = smooth([r["mobilised_friction_deg"] for r in rows])
    psi = [0.0] * len(rows)
    for i in range(1, len(rows) - 1):
        ratio = -(ev[i + 1] - ev[i - 1]) / (gam[i + 1] - gam[i - 1])
        psi[i] = math.degrees(math.asin(max(-1.0, min(1.0, ratio))))
    psi = smooth(psi)
    c = max(range(len(rows) // 2), key=lambda i: ev[i])
    p = max(range(len(rows)), key=lambda i: phi[i])
    tail = [i for i in range(len(rows)) if e1[i] >= 0.2]
    phi_r = sum(phi[i] for i in tail) / len(tail)
    psi_r = sum(psi[i] for i in tail) / len(tail)
    r = next(i for i in range(p, len(rows)) if phi[i] <= phi_r + 0.5)
    near = [i for i in range(len(rows)) if abs(e1[i] - e1[p]) <= 0.01]
    return {
        "phi_c": phi[c],
        "psi_c": math.degrees(math.asin(-ev[c] / gam[c])),
        "gamma_c": gam[c],
        "phi_p": phi[p],
        "psi_p": max(psi[i] for i in near),
        "gamma_p": gam[p],
        "phi_r": phi_r,
        "psi_r": psi_r,
        "gamma_r": gam[r],
    }


def main():
    b = biaxial()
    repose = json.loads((HERE / "repose.json").read_text())["repose_deg"] if (HERE / "repose.json").exists() else None
    band = BAND_D50 * D50
    print("| key | value | from |")
    print("|---|---|---|")
    print(f"| soil.friction.initial | {b['phi_c']:.1f} | biaxial: φ at the characteristic state (γ = {b['gamma_c']:.4f}) |")
    print(f"| soil.friction.peak | {b['phi_p']:.1f} | biaxial: largest φ (γ = {b['gamma_p']:.4f}) |")
    print(f"| soil.friction.residual | {b['phi_r']:.1f} | biaxial: mean φ for ε1 ≥ 0.2 |")
    print(f"| soil.dilation.initial | {b['psi_c']:.1f} | biaxial: mean ψ of the contractive branch |")
    print(f"| soil.dilation.peak | {b['psi_p']:.1f} | biaxial: largest ψ within ±1 % ε1 of the peak |")
    print(f"| soil.dilation.residual | {b['psi_r']:.1f} | biaxial: mean ψ for ε1 ≥ 0.2 |")
    print(f"| soil.peak_shear | {b['gamma_p'] * band:.2f} | γp dB, dB = {BAND_D50:g} d50 = {band:g} mm |")
    print(f"| soil.residual_shear | {b['gamma_r'] * band:.2f} | γr dB (γr = {b['gamma_r']:.4f}: φ within 0.5° of φr) |")
    if repose is not None:
        print(f"| soil.repose | {repose:.1f} | heap test |")
    print(f"| blade.wall_friction | {WALL_FRICTION:g} | blade-grain contact friction, set |")
    print(f"| soil.d50, soil.band_width_d50 | {D50:g}, {BAND_D50:g} | mean grain diameter; band width: choice |")


if __name__ == "__main__":
    main()
