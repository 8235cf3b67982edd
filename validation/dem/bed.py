"""Rain and level the grain bed of the soil bin; saves beds/bed_TAG.yade.gz and
results/beds/bed_TAG.json (TAG: grains.tag(), options: grains.py).

Run: yade -n -j1 -x bed.py [--seed S] [--ratio R] [--slab N] [--short | --long]

The bin: a rough floor at y = 0, frictionless end walls at x = X_START and
x = X_END (10 d ahead of the blade's start at x = 0 for d = 20 mm; the end
wall's force is recorded by cut.py, which shows where the wall acts), the
bed levelled at HEIGHT (the floor 2.75 d below the tip of a 20 mm cut,
2 d below a 25 mm one; --short: end wall at 140 mm, bed 60 mm; --long: end
wall at 300 mm, 15 d from the start, the same bed height). Grains rained
from a jittered lattice with a low contact friction, levelled, then given
their working friction and settled.
"""

import json
import math
import sys
import time

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(sys.argv[0])))
import grains as g  # noqa: E402
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

X_START = -0.040  # left end (m): room behind the start for the raked blade's face
X_END = 0.200  # far end wall (m); 0.140 in the short bin (--short), 0.300 in the long (--long)
HEIGHT = 0.075  # levelled bed height (m); 0.060 in the short bin
START = time.time()


def main():
    global X_END, HEIGHT
    g.configure(sys.argv[1:])
    if g.SHORT:
        X_END, HEIGHT = 0.140, 0.060
    if g.LONG:
        X_END = 0.300
    grain, _, wall = g.materials(O, yade.CohFrictMat)
    hz = g.half_z()
    length = X_END - X_START
    top = 2.2 * HEIGHT / 0.58  # the lattice's height: the packed bed is ~0.58 of it
    floor = O.bodies.append(
        utils.box(
            ((X_START + X_END) / 2, -g.RADIUS, 0),
            (length / 2 + 2 * g.RADIUS, g.RADIUS, hz),
            fixed=True,
            material=grain,
        )
    )
    left = O.bodies.append(
        utils.box(
            (X_START - g.RADIUS, top / 2, 0), (g.RADIUS, top / 2, hz), fixed=True, material=wall
        )
    )
    right = O.bodies.append(
        utils.box(
            (X_END + g.RADIUS, top / 2, 0), (g.RADIUS, top / 2, hz), fixed=True, material=wall
        )
    )
    sides = g.side_walls(O, utils, X_START, X_END, top, wall)
    rows = int(math.ceil(1.1 * HEIGHT / 0.58 / (g.PITCH * g.RADIUS)))
    for c, r in g.rain_cloud(X_START, X_END, g.RADIUS * 1.3, rows, g.SEED):
        O.bodies.append(utils.sphere(c, r, material=grain))
    g.flatten(O)
    g.set_friction(O, g.DEPOSIT_FRICTION)
    O.engines = g.engines(O, yade, [])
    O.dt = 0.5 * utils.PWaveTimeStep()
    steps = g.settle(O, utils, 0.01)
    for b in list(O.bodies):
        if b.dynamic and b.state.pos[1] > HEIGHT:
            O.bodies.erase(b.id)
    g.set_friction(O, g.FRICTION)
    steps += g.settle(O, utils, 0.005)
    gamma, solid = g.area_weight(O, 0.0, X_END - 0.02, 0.004, HEIGHT - 0.004)
    ground = g.surface(O, 0.0, X_END, 2 * g.RADIUS)
    level = sum(y for _, y in ground) / len(ground)
    O.save(g.path("beds", f"bed_{g.tag()}.yade.gz"))
    summary = {
        "wall_time_s": time.time() - START,
        "yade_version": yade.config.version if hasattr(yade, "config") else "unknown",
        "seed": g.SEED,
        "ratio_d_over_D": g.RATIO,
        "slab_layers": g.SLAB,
        "thickness_m": g.THICKNESS,
        "mean_diameter_m": 2 * g.RADIUS,
        "grains": sum(1 for b in O.bodies if b.dynamic),
        "steps": steps,
        "dt_s": O.dt,
        "unit_weight_N_per_m3": gamma,
        "solid_fraction": solid,
        "surface_level_m": level,
        "x_start_m": X_START,
        "x_end_m": X_END,
        "floor_id": floor,
        "end_wall_id": right,
        "start_wall_id": left,
        "side_wall_ids": sides,
    }
    with open(g.path("results", "beds", f"bed_{g.tag()}.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary), flush=True)


main()
