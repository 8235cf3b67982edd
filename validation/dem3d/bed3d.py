"""Rain and level the 3D grain bed of the half-bin (bin3d.py); saves
beds/bed3d_TAG.yade.gz (not committed) and results/beds/bed3d_TAG.json.

Run (from the repository root):
    nice -n 10 yade -n -j1 -x validation/dem3d/bed3d.py [--seed S] [--ratio R]

As bed.py in 3D: grains rained from a jittered cubic lattice (PITCH mean
radii, no overlaps) with the low raining friction, settled, cut level at
HEIGHT, given their working friction and settled again.
"""

import json
import math
import os
import random
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import bin3d as b3  # noqa: E402
import yade  # noqa: E402
from bin3d import g  # noqa: E402
from yade import O, utils  # noqa: E402

START = time.time()


def cloud(rows, seed):
    """Centres and radii on a jittered cubic lattice filling the half-bin's plan."""
    rng = random.Random(seed)
    r0 = g.RADIUS
    pitch = g.PITCH * r0
    nx = int((b3.X_END - b3.X_START) / pitch)
    nz = int(b3.HALF_WIDTH / pitch)
    slack = max(pitch - 2 * r0 * (1 + g.FUZZ), 0.0)
    out = []
    for j in range(rows):
        for k in range(nz):
            for i in range(nx):
                r = r0 * (1 + g.FUZZ * (2 * rng.random() - 1))
                jx = (rng.random() - 0.5) * slack
                jz = (rng.random() - 0.5) * slack
                out.append(
                    (
                        (
                            b3.X_START + (i + 0.5) * pitch + jx,
                            1.3 * r0 + (j + 0.5) * pitch,
                            (k + 0.5) * pitch + jz,
                        ),
                        r,
                    )
                )
    return out


def settle(limit, cap, chunk=1000):
    done = 0
    while done < cap:
        t = time.time()
        O.run(chunk, True)
        done += chunk
        ub = utils.unbalancedForce()
        print(
            f"iter {O.iter}  unbalanced {ub:.4f}  {chunk / (time.time() - t):.1f} steps/s  "
            f"{sum(1 for b in O.bodies if b.dynamic)} grains",
            flush=True,
        )
        if ub < limit:
            break
    return done


def weight(x0, x1, y0, y1, z0, z1):
    """Unit weight (N/m^3) and solid fraction of the grains whose centres lie in the box."""
    mass = solid = 0.0
    n = 0
    for b in O.bodies:
        if not b.dynamic:
            continue
        p = b.state.pos
        if x0 <= p[0] < x1 and y0 <= p[1] < y1 and z0 <= p[2] < z1:
            mass += b.state.mass
            solid += 4.0 / 3.0 * math.pi * b.shape.radius**3
            n += 1
    vol = (x1 - x0) * (y1 - y0) * (z1 - z0)
    return mass * g.GRAVITY / vol, solid / vol, n


def main():
    b3.configure(sys.argv[1:])
    grain, _, wall = g.materials(O, yade.CohFrictMat)
    r = g.RADIUS
    L, W = b3.X_END - b3.X_START, b3.HALF_WIDTH
    xc = (b3.X_START + b3.X_END) / 2
    cloud_solid = 4.0 / 3.0 * math.pi * (1 + g.FUZZ**2) / g.PITCH**3  # ~0.24
    rows = int(math.ceil(1.1 * b3.HEIGHT * 0.62 / cloud_solid / (g.PITCH * r)))
    top = 1.3 * r + (rows + 1) * g.PITCH * r
    ids = {}
    ids["floor"] = O.bodies.append(
        utils.box((xc, -r, W / 2), (L / 2 + 2 * r, r, W / 2 + 2 * r), fixed=True, material=grain)
    )
    ids["start_wall"] = O.bodies.append(
        utils.box(
            (b3.X_START - r, top / 2, W / 2), (r, top / 2, W / 2 + 2 * r), fixed=True, material=wall
        )
    )
    ids["end_wall"] = O.bodies.append(
        utils.box(
            (b3.X_END + r, top / 2, W / 2), (r, top / 2, W / 2 + 2 * r), fixed=True, material=wall
        )
    )
    ids["symmetry_wall"] = O.bodies.append(
        utils.box((xc, top / 2, -r), (L / 2 + 2 * r, top / 2, r), fixed=True, material=wall)
    )
    ids["side_wall"] = O.bodies.append(
        utils.box((xc, top / 2, W + r), (L / 2 + 2 * r, top / 2, r), fixed=True, material=wall)
    )
    for c, rad in cloud(rows, g.SEED):
        O.bodies.append(utils.sphere(c, rad, material=grain))
    print(f"cloud: {len(O.bodies) - 5} grains, {rows} rows", flush=True)
    g.set_friction(O, g.DEPOSIT_FRICTION)
    O.engines = g.engines(O, yade, [])
    O.dt = 0.5 * utils.PWaveTimeStep()
    steps = settle(0.01, 60000)
    for b in list(O.bodies):
        if b.dynamic and b.state.pos[1] > b3.HEIGHT:
            O.bodies.erase(b.id)
    g.set_friction(O, g.FRICTION)
    steps += settle(0.005, 40000)
    d = b3.DEPTH
    # the ground: the highest grain top in every D x D column, its mean the level
    tops = {}
    for b in O.bodies:
        if b.dynamic:
            p = b.state.pos
            key = (int((p[0] - b3.X_START) // (2 * r)), int(p[2] // (2 * r)))
            tops[key] = max(tops.get(key, -1.0), p[1] + b.shape.radius)
    vals = list(tops.values())
    level = sum(vals) / len(vals)
    noise = math.sqrt(sum((v - level) ** 2 for v in vals) / (len(vals) - 1))
    # unit weights: the interior (away from walls, floor and surface) and the cut's regions
    bulk = weight(0.0, 6 * d, 2 * r, level - 2 * r, 2 * r, W - 2 * r)
    cut = {}
    for w_over_d in (1, 3):
        cut[f"w{w_over_d}"] = weight(0.0, 3 * d, level - d, level, 0.0, w_over_d * d / 2)
    O.save(g.path("beds", f"bed3d_{b3.tag()}.yade.gz"))
    summary = {
        "wall_time_s": time.time() - START,
        "yade_version": yade.config.version if hasattr(yade, "config") else "unknown",
        "seed": g.SEED,
        "ratio_d_over_D": g.RATIO,
        "mean_diameter_m": 2 * r,
        "grains": sum(1 for b in O.bodies if b.dynamic),
        "steps": steps,
        "dt_s": O.dt,
        "x_start_m": b3.X_START,
        "x_end_m": b3.X_END,
        "height_m": b3.HEIGHT,
        "half_width_m": W,
        "depth_m": d,
        "surface_level_m": level,
        "surface_noise_sd_m": noise,
        "bulk_unit_weight_N_per_m3": bulk[0],
        "bulk_solid_fraction": bulk[1],
        "bulk_grains": bulk[2],
        "cut_region": {
            k: {
                "unit_weight_N_per_m3": v[0],
                "solid_fraction": v[1],
                "porosity": 1 - v[1],
                "grains": v[2],
            }
            for k, v in cut.items()
        },
        "body_ids": ids,
    }
    with open(g.path("results", "beds", f"bed3d_{b3.tag()}.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary), flush=True)


main()
