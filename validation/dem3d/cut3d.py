"""A vertical blade of finite width cut through the 3D half-bin bed (bed3d.py first).

Run (from the repository root):
    nice -n 10 yade -n -j1 -x validation/dem3d/cut3d.py W [--seed S] [--ratio R] [--speed V] [--travel T]
W: the blade width over its depth, w/d (1 or 3); travel default 3 d, speed
0.04 m/s (grains.py's options); --dt-factor F: the time step over
utils.PWaveTimeStep() (default 0.5 as in 2D; the campaign ran 0.7);
--half-width H: cut the bed's half-bin down to H d wide (the grains beyond
erased, the side wall moved in, RELAX steps of relaxation before the cut).

The blade: a rigid box 2 mm thick, its soil-side face in the plane x = 0 at the
start, from the tip (depth d = 20 mm below the bed's level) to 3.5 d above
it, from the symmetry wall z = 0 to z = w/2 (half of the blade), contact
friction BLADE_FRICTION, moved in +x at constant depth and speed. Grains
that overlap it or lie behind its face above the tip's level are removed
(the slot it was inserted into). Writes, RUN = w<W>_TAG[_vV]:

- results/cuts/RUN_forces.csv: per 0.02 d of travel, the mean over the
  record of the force of the grains on the blade, doubled to the whole
  blade (N): horizontal (draft, positive against the motion) and vertical
  (upward on the blade) of the face's contacts (contact normal within 45
  degrees of the face's, as cut.py: the blade's bottom, back and side edge
  excluded) and of all its contacts (`_all`); the end wall's horizontal
  force, doubled (N).
- fields/RUN.npz (not committed, ~3 MB): every grain's position every 0.5 d
  of travel and the radii, read by summarise3d.py.
- results/cuts/RUN.json: the run's figures and its wall time.
"""

import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import bin3d as b3  # noqa: E402
import numpy as np  # noqa: E402
import yade  # noqa: E402
from bin3d import g  # noqa: E402
from yade import O, utils  # noqa: E402

HALF_THICKNESS = 1.0e-3  # blade half-thickness (m)
RECORD = 0.02  # force record interval (in d)
FIELD = 0.5  # grain field record interval (in d)
SIDES = 2.0  # the half-bin's forces doubled to the whole blade and bin
RELAX = 500  # steps of relaxation after trimming the bed to a narrower half-bin (--half-width)
DT_FACTOR = 0.5  # time step over utils.PWaveTimeStep() (2D campaign: 0.5); --dt-factor F


class Recorder:
    def __init__(self, run, blade, wall):
        self.run, self.blade, self.wall = run, blade, wall
        self.d = b3.DEPTH
        self.sum = [0.0] * 5
        self.count = 0
        self.next_force = RECORD
        self.next_field = 0.0
        self.forces, self.fields, self.field_u = [], [], []
        self.ids = [b.id for b in O.bodies if b.dynamic]
        self.start = time.time()
        self.u0 = blade.state.pos[0]
        self.checked = 0
        self.iter0 = O.iter
        self.meta = None  # the run's figures, written with every field record

    def travel(self):
        return self.blade.state.pos[0] - self.u0

    def face_force(self):
        """Force of the grains on the face's contacts (x, y): the direction from
        the blade to the grain within 45 degrees of +x."""
        return g.face_force(O, self.blade.id, (1.0, 0.0))

    def sample(self):
        total = O.forces.f(self.blade.id)
        fx, fy = self.face_force()
        if self.checked < 3 and abs(total[0]) > 0:
            allx = g.contact_sum_x(O, self.blade.id)
            print(f"check: contact sum {allx:.6g}, O.forces {total[0]:.6g}", flush=True)
            self.checked += 1
        wall = O.forces.f(self.wall)[0]
        for k, v in enumerate((-fx, fy, -total[0], total[1], wall)):
            self.sum[k] += SIDES * v
        self.count += 1
        s = self.travel() / self.d
        if s >= self.next_field - 1e-9:
            self.record_field(s)
            self.next_field += FIELD
        if s >= self.next_force - 1e-9:
            self.forces.append((s,) + tuple(x / self.count for x in self.sum))
            self.sum = [0.0] * 5
            self.count = 0
            self.next_force += RECORD
            if len(self.forces) % 5 == 0:  # every 0.1 d: the record so far on disk
                self.write_forces()
                if self.meta is not None:
                    self.write_meta(False)
                print(
                    f"  u/d = {s:.2f}  draft {self.forces[-1][1]:.3f} N  kinetic {utils.kineticEnergy():.3g} J  unbalanced {utils.unbalancedForce():.3g}  {(O.iter - self.iter0) / (time.time() - self.start):.1f} steps/s",
                    flush=True,
                )

    def record_field(self, s):
        pos = np.full((len(self.ids), 3), np.nan)
        for k, bid in enumerate(self.ids):
            b = O.bodies[bid]
            if b is not None:
                pos[k] = (b.state.pos[0], b.state.pos[1], b.state.pos[2])
        self.fields.append(pos)
        self.field_u.append(self.travel())
        last = self.forces[-1] if self.forces else (0, 0, 0, 0, 0, 0)
        print(
            f"u/d = {s:.2f}  iter {O.iter}  wall {time.time() - self.start:.0f} s  "
            f"draft {last[1]:.2f} N  end wall {last[5]:.2f} N",
            flush=True,
        )
        self.write()
        if self.meta is not None:
            self.write_meta(False)

    def write_meta(self, complete):
        m = dict(
            self.meta,
            travel_reached_m=self.travel(),
            complete=complete,
            wall_time_s=time.time() - self.start,
        )
        with open(g.path("results", "cuts", self.run + ".json"), "w") as f:
            json.dump(m, f, indent=1)
        return m

    def write_forces(self):
        g.write_csv(
            g.path("results", "cuts", self.run) + "_forces.csv",
            ["u_over_d", "draft_N", "vertical_N", "draft_all_N", "vertical_all_N", "wall_N"],
            self.forces,
        )

    def write(self):
        self.write_forces()
        radii = np.array(
            [O.bodies[i].shape.radius if O.bodies[i] is not None else np.nan for i in self.ids]
        )
        np.savez_compressed(
            g.path("fields", self.run + ".npz"),
            u=np.array(self.field_u),
            pos=np.array(self.fields),
            radius=radii,
        )


def main():
    global DT_FACTOR
    argv = sys.argv[1:]
    half_width = None
    if "--half-width" in argv:
        k = argv.index("--half-width")
        half_width = float(argv[k + 1]) * b3.DEPTH
        del argv[k : k + 2]
    if "--dt-factor" in argv:
        k = argv.index("--dt-factor")
        DT_FACTOR = float(argv[k + 1])
        del argv[k : k + 2]
    words = b3.configure(argv)
    w = float(words[-1]) * b3.DEPTH
    travel = (g.TRAVEL or 3.0) * b3.DEPTH
    tag = b3.tag()
    run = "w{:g}_{}{}".format(
        w / b3.DEPTH, tag, "" if g.SPEED == 0.04 else "_v%g" % (g.SPEED * 1e3)
    )
    with open(g.path("results", "beds", f"bed3d_{tag}.json")) as f:
        bed = json.load(f)
    O.load(g.path("beds", f"bed3d_{tag}.yade.gz"))
    level = bed["surface_level_m"]
    tip = level - b3.DEPTH
    O.dt = DT_FACTOR * utils.PWaveTimeStep()
    trimmed = 0
    if half_width is not None and half_width < b3.HALF_WIDTH:
        # a narrower half-bin cut from the bed: the grains beyond erased, the side wall
        # moved in to touch the outermost, a short relaxation under gravity
        for b in list(O.bodies):
            if b.dynamic and b.state.pos[2] + b.shape.radius > half_width:
                O.bodies.erase(b.id)
                trimmed += 1
        side = O.bodies[bed["body_ids"]["side_wall"]]
        side.state.pos = yade.Vector3(side.state.pos[0], side.state.pos[1], half_width + g.RADIUS)
        O.engines = g.engines(O, yade, [])
        O.run(RELAX, True)
        print(
            f"trimmed to a half-bin {half_width * 1e3:.1f} mm wide: {trimmed} grains erased, "
            f"{RELAX} steps relaxed, unbalanced {utils.unbalancedForce():.3g}",
            flush=True,
        )
    else:
        half_width = b3.HALF_WIDTH
    height = 3.5 * b3.DEPTH
    z0 = -2 * g.RADIUS  # the box reaches into the symmetry wall (boxes do not interact)
    erased = 0
    for b in list(O.bodies):
        if not b.dynamic:
            continue
        p, r = b.state.pos, b.shape.radius
        if p[0] < r and p[1] > tip - r and p[2] < w / 2 + r:
            O.bodies.erase(b.id)
            erased += 1
    body = utils.box(
        (-HALF_THICKNESS, tip + height / 2, (z0 + w / 2) / 2),
        (HALF_THICKNESS, height / 2, (w / 2 - z0) / 2),
        fixed=True,
        material=O.materials["blade"],
    )
    blade = O.bodies[O.bodies.append(body)]
    blade.state.vel = yade.Vector3(g.SPEED, 0, 0)
    rec = Recorder(run, blade, bed["body_ids"]["end_wall"])
    globals()["rec"] = rec
    O.engines = g.engines(O, yade, [yade.PyRunner(iterPeriod=10, command="rec.sample()")])
    steps = int(travel / g.SPEED / O.dt) + 20
    print(
        f"run {run}: {len(rec.ids)} grains ({erased} erased), dt {O.dt:.3g} s, {steps} steps",
        flush=True,
    )
    rec.meta = {
        "yade_version": bed["yade_version"],
        "seed": g.SEED,
        "run": run,
        "bed": "bed3d_" + tag,
        "ratio_d_over_D": g.RATIO,
        "mean_diameter_m": 2 * g.RADIUS,
        "grains": len(rec.ids),
        "erased_for_slot": erased,
        "depth_m": b3.DEPTH,
        "width_m": w,
        "half_bin_width_m": half_width,
        "trimmed_grains": trimmed,
        "travel_m": travel,
        "speed_m_per_s": g.SPEED,
        "dt_s": O.dt,
        "dt_over_pwave": DT_FACTOR,
        "steps": steps,
        "tip_y_m": tip,
        "surface_level_m": level,
        "floor_below_tip_m": tip,
        "end_wall_x_m": b3.X_END,
        "start_wall_x_m": b3.X_START,
    }
    O.run(steps, True)
    rec.record_field(rec.travel() / b3.DEPTH)
    print(json.dumps(rec.write_meta(True)), flush=True)


main()
