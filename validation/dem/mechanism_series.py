#!/usr/bin/env python3
"""The DEM's mechanism every 0.25 d of travel, with the friction angle the block
mobilises (issue 40 item 1; numpy, not Yade).

Usage: python3 validation/dem/mechanism_series.py [--out DIR] [RUN ...]
       python3 -m doctest validation/dem/mechanism_series.py   (the formulas' checks)

Reads the cuts of results/DIR (default `long`: jobs-long.txt's runs), every
one there, or the RUNs named: a finished run from RUN.json, RUN_forces.csv,
RUN_surface.csv and its grain field fields/RUN.npz; an unfinished one from
its last checkpoint, checkpoints/RUN.pkl (the recorder's forces, ground and
field so far; neither fields/ nor checkpoints/ is committed). Writes

- results/DIR/RUN_mechanism.csv, one row per interval of 0.25 d ending at u:
  `u_over_d`; `W_norm`, the moving block's weight per unit width over
  gamma d^2 (the grains mechanism.flagged flags: ahead of the face, speed
  ratio >= 0.5 over the interval, the pile on the block included);
  `P_h_norm`, `P_v_norm`, the face's force over the interval (its mean,
  cut.py's face-only force: h against the motion, v upward on the blade;
  over gamma d^2); `P_inclination_deg` = atan(v / h), from the horizontal;
  `delta_deg`, the wall friction mobilised on the face (the same for the
  vertical face; from the face's normal for a raked one, below);
  `beta_deg`, `emergence_over_d` (ahead of the tip), `block_ratio`: the
  band's angle, where it reaches the ground and the block's speed ratio
  (mechanism.interval); `pile_height_over_d`, `pile_ahead_over_d`,
  `pile_slope_deg` (mechanism.pile), `pile_area_over_d2` (the ground's rise
  above the level, signed, summed over the columns from the face to 10 d
  ahead of the tip: the swept soil u d and the block's dilation);
  `phi_mob_deg`, the friction angle the block mobilises on the band (below);
  `wall_rise_norm`, the end wall's force over the interval less its mean
  over the first 0.1 d, over gamma d^2 (whether the far wall is loaded);
  `W_band_norm`, `phi_mob_band_deg`: the same weight and angle counting only
  the moving grains above the band's line (within D of it): W_norm also
  counts the grains rolling down the pile's front beyond the emergence,
  which the band does not carry, and a larger W gives a smaller phi;
- results/DIR/RUN_profile.csv: the ground ahead of the face every 0.25 d
  (`u_over_d`, `x_ahead_over_d` from the tip, `height_over_d` above the
  level; D-wide columns, to 10 d ahead of the tip);
- results/DIR/mechanism_NAME_mean.csv for every cut NAME (vertical, raked30,
  deep) with runs there: per 0.25 d, the number of seeds `n` and the mean and
  sample standard deviation (`_sd`) of every column over them.

The mobilised friction angle. The block is rigid, slides up a straight band
through the tip at beta from the horizontal, and is loaded by its weight W,
the blade's force on it, F = (h, -v) (the face's measured force reversed),
and the reaction of the soil below the band, R, at phi from the band's
normal against the sliding. With s = (cos beta, sin beta) along the band
and n = (-sin beta, cos beta) its normal into the block, R = N (n - tan(phi) s),
and F + W + R = 0 gives R = (-h, v + W), so

    tan(phi) = -(R.s) / (R.n) = (h cos beta - (v + W) sin beta) / (h sin beta + (v + W) cos beta)
             = cot(beta + theta),  theta = atan((v + W) / h),
    phi = 90 deg - beta - atan((v + W) / h).

It holds for any rake: the face enters only through the measured (h, v).
Written with the face's force P at the wall friction delta from the face's
normal, the face leaning back at alpha from the horizontal (normal into the
soil (sin alpha, cos alpha)), the blade's force on the soil is
P (sin(alpha + delta), cos(alpha + delta)), so h = P sin(alpha + delta) and
v = -P cos(alpha + delta), and the balance is Coulomb's wedge (passive,
no cohesion, adhesion or surcharge):

    P = W sin(beta + phi) / sin(alpha + beta + phi + delta),
    vertical face (alpha = 90 deg): P = W sin(beta + phi) / cos(beta + phi + delta);
    delta = atan((h cos alpha + v sin alpha) / (h sin alpha - v cos alpha))
          (= atan(v / h) for the vertical face).

The DEM's band is curved and the block is not quite rigid (block_ratio), so
phi_mob is the friction angle of the straight-band wedge that carries the
measured force with the measured block: Coulomb's equivalent, not the
soil's peak angle. The block's momentum change is left out (its speed is
the blade's, 20 mm/s, once formed).

Checks (Coulomb's wedge at a known phi returns it):

>>> for alpha, delta in ((90.0, 20.0), (30.0, 15.0), (60.0, -5.0)):
...     h, v = wedge_force(1.7, 35.0, 32.0, delta, alpha)
...     print(round(mobilised_phi(h, v, 1.7, 35.0), 9), round(wall_friction(h, v, alpha), 9))
32.0 20.0
32.0 15.0
32.0 -5.0
>>> h, v = wedge_force(1.0, 30.0, 30.0, 0.0, 90.0)  # smooth wall: P = W tan(beta + phi)
>>> round(h, 12), abs(round(v, 12)), round(math.tan(math.radians(60.0)), 12)
(1.732050807569, 0.0, 1.732050807569)
"""

import ast
import csv
import importlib
import json
import math
import pickle
import statistics
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import grains  # noqa: E402
from campaigns import bed_tag  # noqa: E402
from mechanism import flagged, interval  # noqa: E402

FIELD = 0.25  # the field's interval (in d), cut.py's FIELD
SLACK = 0.01  # half cut.py's RECORD (d): a force record and a field taken at the same step
# carry the same u, which the forces file rounds to 6 digits
AHEAD = 10.0  # the profile's and pile area's reach ahead of the tip (in d)
COLUMNS = (
    "u_over_d",
    "W_norm",
    "P_h_norm",
    "P_v_norm",
    "P_inclination_deg",
    "delta_deg",
    "beta_deg",
    "emergence_over_d",
    "block_ratio",
    "pile_height_over_d",
    "pile_ahead_over_d",
    "pile_slope_deg",
    "pile_area_over_d2",
    "phi_mob_deg",
    "wall_rise_norm",
    "W_band_norm",
    "phi_mob_band_deg",
)


def wedge_force(w, beta, phi, delta, alpha):
    """Coulomb's passive wedge (degrees): the face's force (h, v) on the blade,
    h against the motion, v upward, from P = W sin(beta + phi) / sin(alpha +
    beta + phi + delta) at delta from the face's normal."""
    a, b, f, dl = (math.radians(t) for t in (alpha, beta, phi, delta))
    p = w * math.sin(b + f) / math.sin(a + b + f + dl)
    return p * math.sin(a + dl), -p * math.cos(a + dl)


def mobilised_phi(h, v, w, beta):
    """The friction angle (degrees) on a straight band at beta (degrees) that
    balances the block's weight w and the face's force (h, v) on the blade:
    90 - beta - atan((v + w) / h)."""
    return 90.0 - beta - math.degrees(math.atan2(v + w, h))


def wall_friction(h, v, alpha):
    """The face's force's angle (degrees) from the normal of a face at alpha:
    the wall friction it mobilises (positive: the soil rises along the face)."""
    a = math.radians(alpha)
    return math.degrees(
        math.atan2(h * math.cos(a) + v * math.sin(a), h * math.sin(a) - v * math.cos(a))
    )


def cut_table():
    """cut.py's CUTS (depth, rake, travel per cut), read without Yade."""
    tree = ast.parse((HERE / "cut.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "CUTS":
            return ast.literal_eval(node.value)
    raise SystemExit("cut.py has no CUTS")


def from_checkpoint(run):
    """An unfinished run's meta, forces, ground and field from checkpoints/RUN.pkl."""
    with open(HERE / "checkpoints" / (run + ".pkl"), "rb") as f:
        saved = pickle.load(f)
    importlib.reload(grains)  # the defaults again: configure sets only what argv names
    name = grains.configure(list(saved["argv"]))[-1]
    depth, rake, _ = cut_table()[name]
    rec = saved["recorder"]
    meta = {
        "name": name,
        "run": run,
        "seed": grains.SEED,
        "ratio_d_over_D": grains.RATIO,
        "slab_layers": grains.SLAB,
        "thickness_m": grains.THICKNESS,
        "mean_diameter_m": 2 * grains.RADIUS,
        "depth_mm": depth * 1e3,
        "rake_deg": rake,
        "speed_m_per_s": grains.SPEED,
        "finished": False,
    }
    forces = [{"u_over_d": r[1], "h": r[2], "v": r[3], "wall": r[9]} for r in rec["forces"]]
    grounds = {}
    for s, x, y in rec["surfaces"]:
        grounds.setdefault(round(s / FIELD) * FIELD, []).append((x, y))
    field = (np.array(rec["field_u"]), np.array(rec["fields"]), np.array(saved["radius"]))
    return meta, forces, grounds, field


def from_results(folder, run):
    """A finished run's meta, forces, ground and field."""
    meta = json.loads((folder / (run + ".json")).read_text())
    meta["finished"] = True
    with open(folder / (run + "_forces.csv")) as f:
        forces = [
            {
                "u_over_d": float(r["u_over_d"]),
                "h": float(r["force_h_N_per_m"]),
                "v": float(r["force_v_N_per_m"]),
                "wall": float(r["end_wall_N_per_m"]),
            }
            for r in csv.DictReader(f)
        ]
    grounds = {}
    with open(folder / (run + "_surface.csv")) as f:
        for r in csv.DictReader(f):
            s = round(float(r["u_over_d"]) / FIELD) * FIELD
            grounds.setdefault(s, []).append((float(r["x_mm"]), float(r["y_mm"])))
    z = np.load(HERE / "fields" / (run + ".npz"))
    return meta, forces, grounds, (z["u"], z["pos"], z["radius"])


def series(meta, forces, grounds, field):
    """The rows of RUN_mechanism.csv and RUN_profile.csv."""
    bed = json.loads((HERE / "results" / "beds" / f"bed_{bed_tag(meta)}.json").read_text())
    meta["surface_level_m"] = bed["surface_level_m"]
    gamma = bed["unit_weight_N_per_m3"]
    d = meta["depth_mm"] * 1e-3
    norm = gamma * d * d
    alpha = meta["rake_deg"]
    cot = 1.0 / math.tan(math.radians(alpha))
    u, pos, radius = field
    weight = grains.DENSITY * 4.0 / 3.0 * math.pi * radius**3 * grains.GRAVITY / meta["thickness_m"]
    wall0 = statistics.fmean(r["wall"] for r in forces if r["u_over_d"] <= 0.1)
    rows, profile = [], []
    for k in range(1, len(u)):
        s0, s = u[k - 1] / d, u[k] / d
        key = round(s / FIELD) * FIELD
        sel = [r for r in forces if s0 + SLACK < r["u_over_d"] <= s + SLACK]
        if key not in grounds or not sel:
            continue
        tip_x = u[k]
        ground = grounds[key]
        beta, emergence, _, height, ahead, slope, block = interval(
            meta, pos[k - 1], pos[k], u[k] - u[k - 1], tip_x, ground
        )
        ok, *_, moving = flagged(meta, pos[k - 1], pos[k], u[k] - u[k - 1], tip_x)
        w = float(np.sum(weight[ok][moving]))  # N per m of width
        # the part of it on the band's side of the line through the tip at beta
        # (within D): without the grains rolling down the pile's front beyond it
        t = math.radians(beta)
        x, y = pos[k][ok, 0], pos[k][ok, 1]
        tip_y = meta["surface_level_m"] - d
        below = (x - tip_x) * math.sin(t) - (y - tip_y) * math.cos(t)  # distance below the line
        w_band = float(np.sum(weight[ok][moving & (below <= meta["mean_diameter_m"])]))
        h = statistics.fmean(r["h"] for r in sel)
        v = statistics.fmean(r["v"] for r in sel)
        wall = statistics.fmean(r["wall"] for r in sel) - wall0
        face = tip_x - d * cot  # the face's x at the level
        front = sorted(
            (x * 1e-3, y * 1e-3) for x, y in ground if face < x * 1e-3 <= tip_x + AHEAD * d
        )
        area = sum(y for _, y in front) * meta["mean_diameter_m"] if front else math.nan
        rows.append(
            (
                s,
                w / norm,
                h / norm,
                v / norm,
                math.degrees(math.atan2(v, h)),
                wall_friction(h, v, alpha),
                beta,
                emergence * 1e-3 / d,
                block,
                height * 1e-3 / d,
                ahead * 1e-3 / d,
                slope,
                area / d**2,
                mobilised_phi(h, v, w, beta),
                wall / norm,
                w_band / norm,
                mobilised_phi(h, v, w_band, beta),
            )
        )
        profile += [(s, (x - tip_x) / d, y / d) for x, y in front]
    return rows, profile


def write(path, header, rows):
    with open(path, "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(f"{v:.5g}" for v in r) + "\n")


def reduced(path):
    """The rows of a committed RUN_mechanism.csv, as `series` makes them."""
    with path.open() as f:
        lines = f.read().split("\n")
    return [[float(v) for v in line.split(",")] for line in lines[1:] if line]


def means(folder, results):
    """mechanism_NAME_mean.csv: per 0.25 d the seeds' mean and standard deviation."""
    for name in sorted({m["name"] for m, _ in results}):
        runs = [rows for m, rows in results if m["name"] == name]
        keys = sorted({round(r[0] / FIELD) * FIELD for rows in runs for r in rows})
        header = ["u_over_d", "n"] + [c + t for c in COLUMNS[1:] for t in ("", "_sd")]
        out = []
        for key in keys:
            at = [r for rows in runs for r in rows if round(r[0] / FIELD) * FIELD == key]
            line = [key, len(at)]
            for j in range(1, len(COLUMNS)):
                vals = [r[j] for r in at if math.isfinite(r[j])]
                line += [
                    statistics.fmean(vals) if vals else math.nan,
                    statistics.stdev(vals) if len(vals) > 1 else math.nan,
                ]
            out.append(line)
        write(folder / f"mechanism_{name}_mean.csv", header, out)
        print(f"{folder.name}/mechanism_{name}_mean.csv: {len(runs)} runs, {len(out)} rows")


def main(argv):
    out = "long"
    if "--out" in argv:
        i = argv.index("--out")
        out = argv[i + 1]
        del argv[i : i + 2]
    folder = HERE / "results" / out
    folder.mkdir(parents=True, exist_ok=True)
    finished = {p.stem for p in folder.glob("*.json")}
    runs = argv or sorted(
        finished
        | {
            p.stem
            for p in (HERE / "checkpoints").glob("*.pkl")
            if f"--out {out} " in " ".join(pickle.load(p.open("rb"))["argv"]) + " "
        }
    )
    results = []
    for run in runs:
        if run in finished and (HERE / "fields" / (run + ".npz")).exists():
            data = from_results(folder, run)
        elif (HERE / "checkpoints" / (run + ".pkl")).exists():
            data = from_checkpoint(run)
        elif (folder / (run + "_mechanism.csv")).exists():
            # Reduced before and its field since lost: its committed series
            # still counts in the means.
            rows = reduced(folder / (run + "_mechanism.csv"))
            print(f"{run}: {len(rows)} intervals from its committed series (no field)")
            results.append(({"name": run.split("_r")[0]}, rows))
            continue
        else:
            print(f"{run}: no field (fields/{run}.npz) and no checkpoint", file=sys.stderr)
            continue
        rows, profile = series(*data)
        meta = data[0]
        write(folder / (run + "_mechanism.csv"), COLUMNS, rows)
        write(
            folder / (run + "_profile.csv"),
            ("u_over_d", "x_ahead_over_d", "height_over_d"),
            profile,
        )
        state = "finished" if meta["finished"] else "unfinished (last checkpoint)"
        print(f"{run}: {len(rows)} intervals to u = {rows[-1][0] if rows else 0:.2f} d, {state}")
        results.append((meta, rows))
    means(folder, results)


if __name__ == "__main__":
    main(sys.argv[1:])
