#!/usr/bin/env python3
"""The DEM's rate study (issue 31): one table from every run of results/rate/
(stdlib only).

Usage: python3 validation/dem/rate.py

Reads results/rate/RUN.json, RUN_forces.csv and RUN_energy.csv (cut.py
--out rate --energy: the short runs of jobs-rate.txt), the same in
results/damp0/ (jobs-damp0.txt: the runs of 2 d without damping) and the
earlier speed series of the vertical cut in the
bed of seed 14 (results/cuts/vertical_r10_s14{,_v20,_v10}), and writes
results/rate/summary.md and results/rate/summary.json:

- per run: its numerical settings (damping, whether gravity is damped,
  contact modulus E, time step over the P-wave step), the blade speed, the
  seed, the mean force_norm (the face's resultant over gamma d^2) over
  u in [0, 0.5) d, [0, 1) d and [1, 2) d when the run reaches them, the
  energy budget at the end (the work of the numerical damping, of contact
  friction, the rise of the grains' potential energy and their kinetic
  energy, each as a share of the blade's work on the grains) and the wall
  time;
- per configuration (settings and speed) with runs of several seeds: the
  mean and sample standard deviation of the [0, 1) d and [1, 2) d means over
  the seeds, and for each halving of the speed whether the means change by
  less than one standard deviation (the larger of the two speeds'), and
  the change over its standard error, sqrt(sd1^2 / n1 + sd2^2 / n2);
- the expectation from the inertial number: I = (v / t) D / sqrt(p / rho_s),
  t the band thickness of the vertical cut at 40 mm/s (results/summary.json,
  the mean over u = 0.5 to 1 d), D = 2 mm, p = gamma d / 2, and the mu(I)
  law of Jop, Forterre and Pouliquen (2006) with their glass-bead constants
  (mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I0 = 0.279), its friction
  increase added to the element tests' peak friction (tan phi_p,
  phi_p = 42.3 deg) and turned into a force with Coulomb's passive
  coefficient for a vertical wall with wall friction 20 deg and level
  ground: the force ratio mu(I) predicts between two speeds; beside it the
  momentum the blade gives the soil it moves, (gamma / g) d v^2 per unit
  width, over gamma d^2;
- the element tests of results/element_DIR (biaxial.py --damping C --out
  element_DIR) reduced by parameters.py's rule (its function `test`), beside
  the reference tests at the same confining stresses.
"""

import csv
import json
import math
import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent / "results"
RATE = HERE / "rate"
EARLIER = ("vertical_r10_s14", "vertical_r10_s14_v20", "vertical_r10_s14_v10")
DEFAULTS = {"damping": 0.2, "damp_gravity": True, "young_Pa": 5.0e5, "dt_factor": 0.5}
PHI_P = 42.3  # the element tests' peak friction angle (deg), results/element/parameters.json
DELTA = 20.0  # blade-grain friction (deg)
RHO = 2650.0  # grain density (kg/m^3)
SHARES = ("damping", "friction", "potential", "kinetic", "rest")


def mean_in(rows, lo, hi, key="force_norm"):
    sel = [r[key] for r in rows if lo <= r["u_over_d"] < hi]
    return statistics.fmean(sel) if len(sel) >= int(round((hi - lo) / 0.02)) - 1 else None


def read_rows(path):
    with path.open() as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def run_row(meta, folder):
    rows = read_rows(folder / (meta["run"] + "_forces.csv"))
    out = {"run": meta["run"], "cut": meta["name"], "seed": meta["seed"]}
    out["speed_mm_s"] = meta["speed_m_per_s"] * 1e3
    for key, default in DEFAULTS.items():
        out[key] = meta.get(key, default)
    out["travel_d"] = meta["travel_mm"] / meta["depth_mm"]
    out["half_0"] = mean_in(rows, 0.0, 0.5)
    out["window_0"] = mean_in(rows, 0.0, 1.0)
    out["window_1"] = mean_in(rows, 1.0, 2.0)
    # the share of the blade's draft over [0, 0.5) d that is not the face's (its bottom, back)
    face = mean_in(rows, 0.0, 0.5, "force_h_N_per_m")
    out["bottom_share"] = 1 - face / mean_in(rows, 0.0, 0.5, "force_h_all_N_per_m")
    out["wall_time_s"] = meta["wall_time_s"]
    out["folder"] = folder.name
    energy = folder / (meta["run"] + "_energy.csv")
    if energy.exists():
        last = read_rows(energy)[-1]
        work = last["blade_work_J_per_m"]
        out["damping_share"] = last["nonviscDamp_J_per_m"] / work
        # the blade's work and that work less the damping's, per unit travel, over gamma d^2:
        # the mean draft of every contact of the blade and the part of it the damping leaves
        norm = meta["unit_weight_N_per_m3"] * (meta["depth_mm"] * 1e-3) ** 2 * last["u_mm"] * 1e-3
        out["work_draft"] = work / norm
        out["work_draft_undamped"] = (work - last["nonviscDamp_J_per_m"]) / norm
        out["friction_share"] = (last["plastDissip_J_per_m"] + last["shearDissip_J_per_m"]) / work
        # Yade's gravWork: -g.v m dt summed, the rise of the grains' potential energy
        out["potential_share"] = last["gravWork_J_per_m"] / work
        if "grains_kinetic_J_per_m" in last:
            out["kinetic_share"] = last["grains_kinetic_J_per_m"] / work
            out["rest_share"] = 1 - sum(
                out[k]
                for k in ("damping_share", "friction_share", "potential_share", "kinetic_share")
            )
    return out


def settings_label(r):
    parts = []
    if r["damping"] != DEFAULTS["damping"]:
        parts.append("damping {:g}".format(r["damping"]))
    if not r["damp_gravity"]:
        parts.append("gravity undamped")
    if r["young_Pa"] != DEFAULTS["young_Pa"]:
        parts.append("E = %g MPa" % (r["young_Pa"] / 1e6))
    if r["dt_factor"] != DEFAULTS["dt_factor"]:
        parts.append("dt = {:g} dt_P".format(r["dt_factor"]))
    return ", ".join(parts) or "reference"


def passive(phi_deg, delta_deg=DELTA):
    """Coulomb's passive coefficient, vertical wall, level ground."""
    p, d = math.radians(phi_deg), math.radians(delta_deg)
    root = math.sqrt(math.sin(p + d) * math.sin(p) / math.cos(d))
    return math.cos(p) ** 2 / (math.cos(d) * (1 - root) ** 2)


def mu_of_i(i):
    mu_s, mu_2, i0 = math.tan(math.radians(20.9)), math.tan(math.radians(32.76)), 0.279
    return mu_s + (mu_2 - mu_s) / (i0 / i + 1)


def expectation(speeds):
    summary = json.loads((HERE / "summary.json").read_text())["vertical_r10"]
    thickness = summary["mean_band_thickness_mm"]["mean"] * 1e-3
    gamma = json.loads((HERE / "beds" / "bed_r10_s14.json").read_text())["unit_weight_N_per_m3"]
    p = gamma * 0.020 / 2
    diameter = 0.002
    out = []
    base = None
    for v in sorted(speeds):
        i = (v * 1e-3 / thickness) * diameter / math.sqrt(p / RHO)
        extra = mu_of_i(i) - mu_of_i(1e-9)
        phi = math.degrees(math.atan(math.tan(math.radians(PHI_P)) + extra))
        k = passive(phi)
        if base is None:
            base = passive(PHI_P)
        out.append(
            {
                "speed_mm_s": v,
                "inertial_number": i,
                "mu_increase": extra,
                "phi_deg": phi,
                "force_over_quasi_static": k / base,
                # the momentum the blade gives the soil it moves, (gamma / g) d v^2 per unit
                # width, over gamma d^2: the pile's momentum as a force
                "momentum_norm": (v * 1e-3) ** 2 / (9.81 * 0.020),
            }
        )
    return {"band_thickness_mm": thickness * 1e3, "p_Pa": p, "rows": out}


def element_tests():
    """parameters.py's reduction of every biaxial test in results/element and in the
    results/element_* folders of the rate study, for the tests run in the latter."""
    sys.path.insert(0, str(HERE.parent))
    import parameters

    out = []
    folders = sorted(p for p in HERE.glob("element_*") if p.is_dir())
    done = {float(p.stem.split("_")[1]) for f in folders for p in f.glob("biaxial_*.csv")}
    for folder in [HERE / "element"] + folders:
        for path in sorted(folder.glob("biaxial_*.csv"), key=lambda p: float(p.stem[8:])):
            sigma = float(path.stem.split("_")[1])
            if sigma in done:
                t = parameters.test(path)
                keys = ("phi_p", "phi_r", "noise_deg")
                out.append({"folder": folder.name, "sigma_Pa": sigma, **{k: t[k] for k in keys}})
    return out


def fmt(x, digits=2):
    if x is None:
        return "–"
    return f"{x:.{digits}f}"


def main():
    runs = []
    for name in EARLIER:
        meta = json.loads((HERE / "cuts" / (name + ".json")).read_text())
        row = run_row(meta, HERE / "cuts")
        runs.append(row)
    for folder in (RATE, HERE / "damp0"):
        for path in sorted(folder.glob("*.json")):
            if path.name != "summary.json":
                runs.append(run_row(json.loads(path.read_text()), folder))
    for r in runs:
        r["settings"] = settings_label(r)
    runs.sort(
        key=lambda r: (
            r["cut"] != "vertical",
            r["cut"],
            r["settings"] != "reference",
            r["settings"],
            -r["speed_mm_s"],
            r["seed"],
            r["travel_d"],
            r["folder"],
        )
    )
    lines = [
        "# The DEM's rate dependence (issue 31)",
        "",
        "Made by `python3 validation/dem/rate.py` from `results/rate/` and the earlier",
        "speed series in `results/cuts/` (folder `cuts`). Force: the mean of force_norm",
        "(the face's resultant over gamma d^2) over the window; energy: shares of the",
        "blade's work on the grains at the end of the run (damping: Cundall's non-viscous",
        "damping; friction: sliding at the contacts; potential: the grains' rise;",
        "kinetic: what they still carry; rest: what Yade does not count, the elastic",
        "energy stored and the rolling resistance's dissipation). W: the blade's work on",
        "the grains (every contact, the bottom's too) over the travel and gamma d^2, the",
        "mean draft it implies; W − damping: the same less the damping's work. bottom:",
        "the share of the blade's draft over [0, 0.5) d that is not the face's.",
        "",
        "| cut | settings | speed (mm/s) | seed | travel (d) | [0,0.5) d | [0,1) d | [1,2) d "
        "| bottom | W | W − damping | damping | friction | potential | kinetic | rest "
        "| wall time (s) | folder |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in runs:
        cells = [
            r["cut"],
            r["settings"],
            f"{r['speed_mm_s']:g}",
            str(r["seed"]),
            f"{r['travel_d']:g}",
        ]
        cells += [fmt(r[k]) for k in ("half_0", "window_0", "window_1")]
        cells += [fmt(r.get(k)) for k in ("bottom_share", "work_draft", "work_draft_undamped")]
        cells += [fmt(r.get(k + "_share")) for k in SHARES]
        cells += [f"{r['wall_time_s']:.0f}", r["folder"]]
        lines.append("| " + " | ".join(cells) + " |")
    groups = {}
    for r in runs:
        if r["folder"] != "cuts" and r["window_0"] is not None:
            groups.setdefault((r["cut"], r["settings"], r["speed_mm_s"]), []).append(r)
    multi = {k: v for k, v in groups.items() if len(v) >= 2}
    table = []
    if multi:
        lines += [
            "",
            "Over seeds (runs of at least 1 d; mean ± sample standard deviation):",
            "",
            "| cut | settings | speed (mm/s) | seeds | [0,1) d | [1,2) d |",
            "|---|---|---|---|---|---|",
        ]
        for (cut, label, v), rs in sorted(multi.items(), key=lambda kv: kv[0][:2] + (-kv[0][2],)):
            row = {"cut": cut, "settings": label, "speed_mm_s": v}
            row["seeds"] = sorted(r["seed"] for r in rs)
            cells = []
            for w in ("window_0", "window_1"):
                vals = [r[w] for r in rs if r[w] is not None]
                if len(vals) >= 2:
                    row[w] = {
                        "mean": statistics.fmean(vals),
                        "sd": statistics.stdev(vals),
                        "n": len(vals),
                    }
                    cells.append("{:.2f} ± {:.2f}".format(row[w]["mean"], row[w]["sd"]))
                else:
                    cells.append("–")
            table.append(row)
            lines.append(f"| {cut} | {label} | {v:g} | {len(rs)} | {cells[0]} | {cells[1]} |")
        checks = []
        for row in table:
            slower = [
                t
                for t in table
                if (t["cut"], t["settings"]) == (row["cut"], row["settings"])
                and abs(t["speed_mm_s"] - row["speed_mm_s"] / 2) < 1e-9
            ]
            for t in slower:
                for w in ("window_0", "window_1"):
                    if w in row and w in t:
                        change = t[w]["mean"] - row[w]["mean"]
                        sd = max(row[w]["sd"], t[w]["sd"])
                        # the change over its standard error (n seeds at each speed)
                        error = math.sqrt(
                            row[w]["sd"] ** 2 / row[w]["n"] + t[w]["sd"] ** 2 / t[w]["n"]
                        )
                        checks.append(
                            (
                                row["cut"],
                                row["settings"],
                                row["speed_mm_s"],
                                t["speed_mm_s"],
                                w,
                                change,
                                sd,
                                abs(change) < sd,
                                change / error,
                            )
                        )
        if checks:
            lines += [
                "",
                "Halving the speed (change of the seeds' mean against the larger",
                "standard deviation of the two speeds):",
                "",
                "| cut | settings | speeds (mm/s) | window | change | sd | within one sd "
                "| change / its standard error |",
                "|---|---|---|---|---|---|---|---|",
            ]
            for cut, label, v1, v2, w, change, sd, ok, z in checks:
                lines.append(
                    "| {} | {} | {:g} → {:g} | {} | {:+.2f} | {:.2f} | {} | {:+.1f} |".format(
                        cut,
                        label,
                        v1,
                        v2,
                        "[0,1) d" if w == "window_0" else "[1,2) d",
                        change,
                        sd,
                        "yes" if ok else "no",
                        z,
                    )
                )
    # the pivot docs/validation.md quotes: the [0,0.5) d means of the 0.5 d runs
    short = [r for r in runs if r["folder"] == "rate" and r["travel_d"] == 0.5]
    speeds = sorted({r["speed_mm_s"] for r in short}, reverse=True)
    labels = []
    for r in short:
        if r["settings"] not in labels:
            labels.append(r["settings"])
    lines += [
        "",
        "The [0,0.5) d means of the runs over 0.5 d (seed 14), by setting and speed,",
        "with the damping's share of the blade's work in brackets:",
        "",
        "| settings | " + " | ".join(f"{v:g} mm/s" for v in speeds) + " |",
        "|---|" + "---|" * len(speeds),
    ]
    for label in labels:
        cells = []
        for v in speeds:
            sel = [r for r in short if r["settings"] == label and r["speed_mm_s"] == v]
            cells.append(f"{sel[0]['half_0']:.2f} ({sel[0]['damping_share']:.2f})" if sel else "")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    # the noise of a 0.5 d mean in one bed: realisations that differ by the time step only
    noise = {}
    for base in ("reference", "damping 0"):
        variants = [base] + [
            (base + ", " if base != "reference" else "") + f"dt = {f} dt_P" for f in (0.45, 0.55)
        ]
        real = [
            r["half_0"]
            for r in runs
            if r["folder"] == "rate"
            and r["travel_d"] == 0.5
            and r["speed_mm_s"] == 40
            and r["settings"] in variants
        ]
        if len(real) >= 2:
            noise[base] = {
                "mean": statistics.fmean(real),
                "sd": statistics.stdev(real),
                "n": len(real),
                "values": real,
            }
    if noise:
        lines += [
            "",
            "The noise of a [0,0.5) d mean in one bed, from realisations at 40 mm/s that differ",
            "by the time step only (0.45, 0.5, 0.55 dt_P): "
            + "; ".join(
                f"{k} {v['mean']:.2f} ± {v['sd']:.2f} (n = {v['n']})" for k, v in noise.items()
            )
            + ".",
        ]
    ratios = {}
    for label in ("reference", "damping 0"):
        sel = {
            r["speed_mm_s"]: r["half_0"]
            for r in runs
            if r["folder"] == "rate" and r["travel_d"] == 0.5 and r["settings"] == label
        }
        if 40 in sel and 10 in sel:
            ratios[label] = sel[40] / sel[10]
    exp = expectation([10.0, 20.0, 40.0, 80.0])
    by_speed = {e["speed_mm_s"]: e["force_over_quasi_static"] for e in exp["rows"]}
    ratios["mu(I)"] = by_speed[40.0] / by_speed[10.0]
    lines += [
        "",
        "The [0,0.5) d mean at 40 mm/s over that at 10 mm/s: "
        + ", ".join(f"{k} {v:.2f}" for k, v in ratios.items())
        + ".",
    ]
    lines += [
        "",
        "What the inertial number leads one to expect (mu(I) of Jop et al. 2006 on",
        "the element tests' phi_p = {:.1f}°, Coulomb's passive wedge, band {:.1f} mm thick,".format(
            PHI_P, exp["band_thickness_mm"]
        ),
        "p = gamma d / 2 = {:.0f} Pa):".format(exp["p_Pa"]),
        "",
        "| speed (mm/s) | I | mu increase | phi (°) | force / quasi-static "
        "| momentum flux / (gamma d^2) |",
        "|---|---|---|---|---|---|",
    ]
    for e in exp["rows"]:
        lines.append(
            "| {:g} | {:.1e} | {:.4f} | {:.2f} | {:.3f} | {:.1e} |".format(
                e["speed_mm_s"],
                e["inertial_number"],
                e["mu_increase"],
                e["phi_deg"],
                e["force_over_quasi_static"],
                e["momentum_norm"],
            )
        )
    element = element_tests()
    if element:
        lines += [
            "",
            "The element tests with the damping of the shear changed (results/element_DIR,",
            "biaxial.py --damping), reduced by parameters.py's rule beside the reference's",
            "(results/element): peak and critical-state friction angles (°):",
            "",
            "| tests | σ3 (Pa) | φp | φr (noise) |",
            "|---|---|---|---|",
        ]
        for e in element:
            lines.append(
                f"| {e['folder']} | {e['sigma_Pa']:g} | {e['phi_p']:.1f} "
                f"| {e['phi_r']:.1f} (± {e['noise_deg']:.1f}) |"
            )
    (RATE / "summary.md").write_text("\n".join(lines) + "\n")
    out = {
        "runs": runs,
        "seeds": table,
        "noise": noise,
        "ratios": ratios,
        "expectation": exp,
        "element": element,
    }
    (RATE / "summary.json").write_text(json.dumps(out, indent=1) + "\n")
    print("\n".join(lines))


main()
