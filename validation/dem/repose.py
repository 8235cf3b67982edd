"""Angle of repose of the bed's grains: a column released on the rough floor.

Run: yade -n -j1 -x repose.py      (about 3 minutes on one core)

Grains rained as the bed is (low friction, then the working friction) into a
column WIDTH wide against a frictionless wall, on a rough floor; the
retaining wall on the other side is removed and the grains run out until at
rest. The angle of repose is the slope of the straight line fitted to the
final surface between 20 % and 80 % of its height. Writes
results/repose_surface.csv and results/repose.json.
"""

import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import grains as g  # noqa: E402
import yade  # noqa: E402
from yade import O, pack, utils  # noqa: E402

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))
WIDTH = 0.040
FLOOR = 0.200
CLOUD_TOP = 0.120


def settle(limit, cap):
    done = 0
    while done < cap:
        O.run(2000, True)
        done += 2000
        if utils.unbalancedForce() < limit:
            break
    return done


START = time.time()


def main():
    grain, _, wall = g.materials(O, yade.CohFrictMat)
    half_z = 5 * g.RADIUS
    O.bodies.append(
        [
            utils.box(
                (FLOOR / 2, -g.RADIUS, 0),
                (FLOOR / 2 + 2 * g.RADIUS, g.RADIUS, half_z),
                fixed=True,
                material=grain,
            ),
            utils.box((-g.RADIUS, 0.1, 0), (g.RADIUS, 0.1, half_z), fixed=True, material=wall),
        ]
    )
    gate = O.bodies.append(
        utils.box((WIDTH + g.RADIUS, 0.1, 0), (g.RADIUS, 0.1, half_z), fixed=True, material=wall)
    )
    sp = pack.SpherePack()
    sp.makeCloud(
        (g.RADIUS * 1.3, g.RADIUS * 1.3, 0),
        (WIDTH - g.RADIUS * 1.3, CLOUD_TOP, 0),
        rMean=g.RADIUS,
        rRelFuzz=g.FUZZ,
        num=700,
        seed=g.SEED,
    )
    for c, r in sp:
        O.bodies.append(utils.sphere(c, r, material=grain))
    g.flatten(O)
    g.set_friction(O, g.DEPOSIT_FRICTION)
    O.engines = g.engines(O, yade, [])
    O.dt = 0.5 * utils.PWaveTimeStep()
    settle(0.01, 40000)
    g.set_friction(O, g.FRICTION)
    settle(0.01, 20000)
    O.bodies.erase(gate)
    O.run(20000, True)  # the run-out (0.5 s) before the rest test
    steps = 20000 + settle(0.01, 60000)
    top = g.surface(O, 0.0, FLOOR, 2 * g.RADIUS)
    g.write_csv(
        os.path.join(HERE, "results", "repose_surface.csv"),
        ["x_mm", "y_mm"],
        [(x * 1e3, y * 1e3) for x, y in top],
    )
    hmax = max(y for _, y in top)
    pts = [(x, y) for x, y in top if 0.2 * hmax <= y <= 0.8 * hmax and x > 2 * g.RADIUS]
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    slope = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
    summary = {
        "wall_time_s": time.time() - START,
        "yade_version": yade.config.version,
        "seed": g.SEED,
        "grains": len(sp),
        "repose_deg": math.degrees(math.atan(-slope)),
        "fit_points": n,
        "heap_height_mm": hmax * 1e3,
        "steps_after_release": steps,
    }
    with open(os.path.join(HERE, "results", "repose.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary))


main()
