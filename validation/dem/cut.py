"""A blade cut through the rained bed (bed.py first): forces and ground surface.

Run: yade -n -j1 -x cut.py NAME       NAME: vertical | raked30 | deep
(about 20 to 30 minutes each on one core; the log prints the wall time)

The blade's tip starts at x = 0, depth d below the levelled surface, and moves
in +x at constant depth and speed SPEED to the travel. The face leans back at
the rake angle alpha (90: vertical). Writes results/cut_NAME_forces.csv (the
mean force on the blade over every 0.02 d of travel, per unit width) and
results/cut_NAME_surface.csv (the ground surface every 0.5 d), lengths in mm
with x from the tip's start and y from the levelled surface.
"""

import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import grains as g  # noqa: E402
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

CUTS = {  # depth d (m), rake alpha (degrees), travel (m)
    'vertical': (0.020, 90.0, 0.100),
    'raked30': (0.020, 30.0, 0.100),
    'deep': (0.025, 90.0, 0.075),
}
SPEED = 0.04  # blade speed (m/s): inertial number ~ 1e-2 in the bands, v^2/(g d) < 0.01
HALF_THICKNESS = 0.5e-3  # blade half-thickness (m)
RECORD = 0.02  # force record interval (in d)
SURFACE = 0.5  # surface record interval (in d)
HERE = os.path.dirname(os.path.abspath(sys.argv[0]))


class Recorder:
    def __init__(self, name, depth, blade, x_end, gamma, level):
        self.name, self.depth, self.blade, self.x_end = name, depth, blade, x_end
        self.gamma, self.level = gamma, level
        self.sum = [0.0, 0.0]
        self.count = 0
        self.next_force = RECORD
        self.next_surface = 0.0
        self.forces = []
        self.surfaces = []
        self.start = time.time()
        self.u0 = blade.state.pos[0]

    def travel(self):
        return self.blade.state.pos[0] - self.u0

    def sample(self):
        f = O.forces.f(self.blade.id)
        self.sum[0] += -f[0] / g.THICKNESS
        self.sum[1] += f[1] / g.THICKNESS
        self.count += 1
        s = self.travel() / self.depth
        if s >= self.next_surface - 1e-9:
            self.record_surface(s)
            self.next_surface += SURFACE
        if s >= self.next_force - 1e-9:
            h, v = self.sum[0] / self.count, self.sum[1] / self.count
            norm = self.gamma * self.depth ** 2
            self.forces.append((self.travel() * 1e3, s, h, v, math.hypot(h, v) / norm, h / norm, v / norm))
            self.sum = [0.0, 0.0]
            self.count = 0
            self.next_force += RECORD

    def record_surface(self, s):
        for x, y in g.surface(O, -0.040, self.x_end, 2 * g.RADIUS):
            self.surfaces.append((s, x * 1e3, (y - self.level) * 1e3))
        print('u/d = %.2f  iter %d  wall %.0f s' % (s, O.iter, time.time() - self.start), flush=True)

    def write(self):
        g.write_csv(os.path.join(HERE, 'results', 'cut_%s_forces.csv' % self.name),
                    ['u_mm', 'u_over_d', 'force_h_N_per_m', 'force_v_N_per_m', 'force_norm',
                     'force_h_norm', 'force_v_norm'], self.forces)
        g.write_csv(os.path.join(HERE, 'results', 'cut_%s_surface.csv' % self.name),
                    ['u_over_d', 'x_mm', 'y_mm'], self.surfaces)


def blade_body(tip, alpha, length, material):
    """A thin box whose soil-side face passes through the tip at `alpha` from the horizontal."""
    a = math.radians(alpha)
    along = (-math.cos(a), math.sin(a))
    normal = (math.sin(a), math.cos(a))
    centre = (tip[0] + along[0] * length / 2 - normal[0] * HALF_THICKNESS,
              tip[1] + along[1] * length / 2 - normal[1] * HALF_THICKNESS, 0.0)
    turn = yade.Quaternion((0, 0, 1), math.pi / 2 - a)
    return utils.box(centre, (HALF_THICKNESS, length / 2, 5 * g.RADIUS), orientation=turn,
                     fixed=True, material=material), normal


def main():
    name = sys.argv[-1]
    depth, alpha, travel = CUTS[name]
    with open(os.path.join(HERE, 'results', 'bed.json')) as f:
        bed = json.load(f)
    O.load(os.path.join(HERE, 'bed.yade.gz'))
    level = bed['surface_level_m']
    tip = (0.0, level - depth)
    length = 3.5 * depth / math.sin(math.radians(alpha))
    body, normal = blade_body(tip, alpha, length, O.materials['blade'])
    for b in list(O.bodies):
        if not b.dynamic:
            continue
        p, r = b.state.pos, b.shape.radius
        behind = (p[0] - tip[0]) * normal[0] + (p[1] - tip[1]) * normal[1] < r
        if behind and p[1] > tip[1] - r:
            O.bodies.erase(b.id)
    blade_id = O.bodies.append(body)
    blade = O.bodies[blade_id]
    blade.state.vel = yade.Vector3(SPEED, 0, 0)
    rec = Recorder(name, depth, blade, bed['x_end_m'], bed['unit_weight_N_per_m3'], level)
    O.engines = g.engines(O, yade, [yade.PyRunner(iterPeriod=10, command='rec.sample()')])
    O.dt = 0.5 * utils.PWaveTimeStep()
    globals()['rec'] = rec
    steps = int(travel / SPEED / O.dt) + 20
    O.run(steps, True)
    rec.write()
    meta = {'yade_version': bed['yade_version'], 'seed': bed['seed'], 'name': name,
            'depth_mm': depth * 1e3, 'rake_deg': alpha, 'travel_mm': travel * 1e3,
            'speed_m_per_s': SPEED, 'dt_s': O.dt, 'steps': steps,
            'unit_weight_N_per_m3': bed['unit_weight_N_per_m3'],
            'end_wall_mm': bed['x_end_m'] * 1e3, 'wall_time_s': time.time() - rec.start}
    with open(os.path.join(HERE, 'results', 'cut_%s.json' % name), 'w') as f:
        json.dump(meta, f, indent=1)
    print(json.dumps(meta))


main()
