"""Rain and level the grain bed of the soil bin; saves bed.yade.gz and bed.json.

Run: yade -n -j1 -x bed.py      (about 3 minutes on one core)

The bin: a rough floor at y = 0, frictionless end walls at x = X_START and
x = X_END (the far end wall, 9 d ahead of the blade's start at x = 0 for
d = 20 mm), grains rained from a jittered lattice with a low contact friction,
levelled at y = HEIGHT, then given their working friction and settled.
"""

import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import grains as g  # noqa: E402
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

X_START = -0.040  # left end (m): room behind the start for the raked blade's face
X_END = 0.180  # far end wall (m): 9 d ahead of the start for d = 20 mm
HEIGHT = 0.036  # levelled bed height (m)
ROWS = 26  # lattice rows rained: enough grains to level at HEIGHT


def settle(limit, chunk=2000, cap=200000):
    """Run until the unbalanced force ratio is below `limit` (or `cap` steps)."""
    done = 0
    while done < cap:
        O.run(chunk, True)
        done += chunk
        if utils.unbalancedForce() < limit:
            return done
    return done


START = time.time()


def main():
    grain, _, wall = g.materials(O, yade.CohFrictMat)
    half_z = 5 * g.RADIUS
    length = X_END - X_START
    O.bodies.append([
        utils.box(((X_START + X_END) / 2, -g.RADIUS, 0), (length / 2 + 2 * g.RADIUS, g.RADIUS, half_z),
                  fixed=True, material=grain),
        utils.box((X_START - g.RADIUS, 0.1, 0), (g.RADIUS, 0.1, half_z), fixed=True, material=wall),
        utils.box((X_END + g.RADIUS, 0.1, 0), (g.RADIUS, 0.1, half_z), fixed=True, material=wall),
    ])
    for c, r in g.rain_cloud(X_START, X_END, g.RADIUS * 1.3, ROWS, g.SEED):
        O.bodies.append(utils.sphere(c, r, material=grain))
    g.flatten(O)
    g.set_friction(O, g.DEPOSIT_FRICTION)
    O.engines = g.engines(O, yade, [])
    O.dt = 0.5 * utils.PWaveTimeStep()
    steps = settle(0.01)
    for b in list(O.bodies):
        if b.dynamic and b.state.pos[1] > HEIGHT:
            O.bodies.erase(b.id)
    g.set_friction(O, g.FRICTION)
    steps += settle(0.005)
    gamma, solid = g.area_weight(O, 0.0, 0.18, 0.004, HEIGHT - 0.004)
    top = g.surface(O, 0.0, X_END, 2 * g.RADIUS)
    level = sum(y for _, y in top) / len(top)
    O.save(os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), 'bed.yade.gz'))
    summary = {
        'wall_time_s': time.time() - START,
        'yade_version': yade.config.version if hasattr(yade, 'config') else 'unknown',
        'seed': g.SEED,
        'grains': sum(1 for b in O.bodies if b.dynamic),
        'steps': steps,
        'dt_s': O.dt,
        'unit_weight_N_per_m3': gamma,
        'solid_fraction_disks': solid,
        'surface_level_m': level,
        'x_start_m': X_START,
        'x_end_m': X_END,
    }
    with open(os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), 'results', 'bed.json'), 'w') as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary))


main()
