"""A blade cut through a rained bed (bed.py first): forces, ground and grain field.

Run: yade -n -j1 -x cut.py NAME [--seed S] [--ratio R] [--slab N] [--short | --long]
                              [--speed V] [--travel T]
                              [--damping C] [--undamped-gravity] [--young E] [--dt-factor F]
                              [--energy] [--out DIR] [--checkpoint T] [--resume]
NAME: vertical | raked30 | deep (table CUTS); options: grains.py.

The blade's tip starts at x = 0, depth d below the levelled surface, and moves
in +x at constant depth and speed to the travel. The face leans back at the
rake angle alpha (90: vertical); it reaches BLADE_HEIGHT d above the tip
(LONG_BLADE_HEIGHT in the long bin, --long, where the pile of a 5 d cut
would come near the top of the shorter one). Writes, with RUN = NAME_TAG[_vV][SETTINGS]
(TAG the bed's, V the speed in mm/s when not the default, SETTINGS the
numerical settings that differ from the defaults, grains.settings()), in
results/cuts (or results/OUT with --out OUT):

- results/cuts/RUN_forces.csv: per 0.02 d of travel, the mean force on the
  blade's soil-side face only (contacts whose normal is within 45 degrees of
  the face's; the blade's bottom and back excluded), horizontal (draft,
  positive against the motion) and vertical (upward on the blade), N per m
  of width, their resultant over gamma d^2; the same for every contact of
  the blade (`_all`); and the end wall's horizontal force (N/m).
- results/cuts/RUN_surface.csv: the ground every 0.25 d (highest grain top
  in every D-wide column, x from the tip's start and y from the levelled
  surface, mm).
- fields/RUN.npz (not committed; 1-5 MB): every grain's in-plane position
  every 0.25 d (u: the travels, m; pos: positions, m; radius: radii, m),
  read by mechanism.py and mechanism_series.py. A checkpoint holds the
  field so far (and, since the long runs, the radii), so an unfinished run
  can be reduced from checkpoints/RUN.pkl.
- results/cuts/RUN.json: the run's figures and its wall time.
- with --energy, results/cuts/RUN_energy.csv: per 0.02 d, the cumulative
  work of the blade on the grains (from every contact of the blade) and
  Yade's energy budget since the blade started (J per m of width;
  nonviscDamp: the damping's work, shearDissip: sliding at the contacts,
  gravWork: the rise of the grains' potential energy; Yade leaves out the
  rolling resistance's dissipation, the elastic energy and, here, the
  kinetic energy, which is computed from the grains: grains_kinetic).

Checkpoints (--checkpoint T): every T d of travel the run stops between two
time steps, saves Yade's state to checkpoints/RUN.yade.gz and the
recorder's to checkpoints/RUN.pkl (neither committed), and goes on; the
same command with --resume loads them and continues to the end (and starts
from the bed when there is no checkpoint yet), so a long
cut can run over several sessions. The wall time in the JSON adds up the
sessions. A resumed run is not bit-identical to an uninterrupted one after
the checkpoint (Yade rebuilds its contact list on loading); it is another
realisation of the same cut.
"""

import json
import math
import os
import pickle
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import grains as g  # noqa: E402
import numpy as np  # noqa: E402
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

CUTS = {  # depth d (m), rake alpha (degrees), travel (in d; --travel overrides)
    "vertical": (0.020, 90.0, 2.0),
    "raked30": (0.020, 30.0, 2.0),
    "deep": (0.025, 90.0, 2.0),
}
HALF_THICKNESS = 0.5e-3  # blade half-thickness (m)
BLADE_HEIGHT = 3.5  # the blade's top above its tip (in d)
LONG_BLADE_HEIGHT = 5.0  # the same in the long bin (--long)
RECORD = 0.02  # force record interval (in d)
FIELD = 0.25  # surface and field record interval (in d)
ENERGY_KEYS = ("nonviscDamp", "plastDissip", "shearDissip", "kinetic", "gravWork", "elastPotential")


class Recorder:
    def __init__(self, run, depth, blade, normal, bed):
        self.run, self.depth, self.blade, self.normal = run, depth, blade, normal
        self.gamma, self.level = bed["unit_weight_N_per_m3"], bed["surface_level_m"]
        self.x_end, self.wall = bed["x_end_m"], bed["end_wall_id"]
        self.sum = [0.0] * 5
        self.count = 0
        self.next_force = RECORD
        self.next_field = 0.0
        self.forces, self.surfaces, self.fields, self.field_u = [], [], [], []
        self.ids = [b.id for b in O.bodies if b.dynamic]
        self.start = time.time()
        self.before = 0.0  # wall time of earlier sessions (resumed runs)
        self.u0 = blade.state.pos[0]
        self.checked = 0
        self.work = 0.0  # work of the blade on the grains (J), every contact
        self.last_u = 0.0
        self.energies = []

    KEEP = (
        "sum",
        "count",
        "next_force",
        "next_field",
        "forces",
        "surfaces",
        "fields",
        "field_u",
        "ids",
        "u0",
        "checked",
        "work",
        "last_u",
        "energies",
    )

    def state(self):
        """What a checkpoint keeps of the recorder."""
        out = {k: getattr(self, k) for k in self.KEEP}
        out["wall_s"] = self.before + time.time() - self.start
        return out

    def restore(self, state):
        for k in self.KEEP:
            setattr(self, k, state[k])
        self.before = state["wall_s"]
        self.start = time.time()

    def elapsed(self):
        return self.before + time.time() - self.start

    def travel(self):
        return self.blade.state.pos[0] - self.u0

    def face_force(self):
        """Force of the grains on the blade's soil-side face (x, y)."""
        return g.face_force(O, self.blade.id, self.normal)

    def sample(self):
        total = O.forces.f(self.blade.id)
        fx, fy = self.face_force()
        if self.checked < 3 and abs(total[0]) > 0:
            allx = g.contact_sum_x(O, self.blade.id)
            print(f"check: contact sum {allx:.6g}, O.forces {total[0]:.6g}", flush=True)
            self.checked += 1
        wall = O.forces.f(self.wall)[0]
        u = self.travel()
        self.work += -total[0] * (u - self.last_u)  # the blade moves in +x only
        self.last_u = u
        for k, v in enumerate((-fx, fy, -total[0], total[1], wall)):
            self.sum[k] += v / g.THICKNESS
        self.count += 1
        s = self.travel() / self.depth
        if s >= self.next_field - 1e-9:
            self.record_field(s)
            self.next_field += FIELD
        if s >= self.next_force - 1e-9:
            h, v, ha, va, w = (x / self.count for x in self.sum)
            norm = self.gamma * self.depth**2
            self.forces.append(
                (
                    self.travel() * 1e3,
                    s,
                    h,
                    v,
                    math.hypot(h, v) / norm,
                    h / norm,
                    v / norm,
                    ha,
                    va,
                    w,
                )
            )
            self.sum = [0.0] * 5
            self.count = 0
            self.next_force += RECORD
            if g.ENERGY:
                e = O.energy
                self.energies.append(
                    [self.travel() * 1e3, s, self.work / g.THICKNESS]
                    + [e[k] / g.THICKNESS if k in e.keys() else 0.0 for k in ENERGY_KEYS]
                    + [kinetic() / g.THICKNESS]
                )

    def record_field(self, s):
        for x, y in g.surface(O, -0.040, self.x_end, 2 * g.RADIUS):
            self.surfaces.append((s, x * 1e3, (y - self.level) * 1e3))
        pos = np.full((len(self.ids), 2), np.nan)
        for k, bid in enumerate(self.ids):
            b = O.bodies[bid]
            if b is not None:
                pos[k] = (b.state.pos[0], b.state.pos[1])
        self.fields.append(pos)
        self.field_u.append(self.travel())
        print(f"u/d = {s:.2f}  iter {O.iter}  wall {self.elapsed():.0f} s", flush=True)

    def write(self):
        base = g.path("results", g.OUT or "cuts", self.run)
        if g.ENERGY:
            g.write_csv(
                base + "_energy.csv",
                ["u_mm", "u_over_d", "blade_work_J_per_m"]
                + [f"{k}_J_per_m" for k in ENERGY_KEYS]
                + ["grains_kinetic_J_per_m"],
                self.energies,
            )
        g.write_csv(
            base + "_forces.csv",
            [
                "u_mm",
                "u_over_d",
                "force_h_N_per_m",
                "force_v_N_per_m",
                "force_norm",
                "force_h_norm",
                "force_v_norm",
                "force_h_all_N_per_m",
                "force_v_all_N_per_m",
                "end_wall_N_per_m",
            ],
            self.forces,
        )
        g.write_csv(base + "_surface.csv", ["u_over_d", "x_mm", "y_mm"], self.surfaces)
        radii = np.array(self.radii())
        np.savez_compressed(
            g.path("fields", self.run + ".npz"),
            u=np.array(self.field_u),
            pos=np.array(self.fields),
            radius=radii,
        )

    def radii(self):
        """The radii of the recorded grains (m; NaN for a grain removed for the trench)."""
        return [O.bodies[i].shape.radius if O.bodies[i] is not None else math.nan for i in self.ids]


def kinetic():
    """The grains' kinetic energy (J), translation and rotation."""
    out = 0.0
    for b in O.bodies:
        if b is not None and b.dynamic:
            st = b.state
            out += 0.5 * st.mass * st.vel.squaredNorm() + 0.5 * st.inertia.dot(
                yade.Vector3(*(w * w for w in st.angVel))
            )
    return out


def blade_body(tip, alpha, length, material):
    """A thin box whose soil-side face passes through the tip at `alpha` from the horizontal."""
    a = math.radians(alpha)
    along = (-math.cos(a), math.sin(a))
    normal = (math.sin(a), math.cos(a))
    centre = (
        tip[0] + along[0] * length / 2 - normal[0] * HALF_THICKNESS,
        tip[1] + along[1] * length / 2 - normal[1] * HALF_THICKNESS,
        0.0,
    )
    turn = yade.Quaternion((0, 0, 1), math.pi / 2 - a)
    return utils.box(
        centre,
        (HALF_THICKNESS, length / 2, g.half_z() - 2 * g.RADIUS),
        orientation=turn,
        fixed=True,
        material=material,
    ), normal


def checkpoint_paths(run):
    return g.path("checkpoints", run + ".yade.gz"), g.path("checkpoints", run + ".pkl")


def save_checkpoint(run, argv, rec, it0, steps):
    """Yade's state and the recorder's, written beside and then moved over the last ones."""
    state, extra = checkpoint_paths(run)
    O.save(state + ".tmp.yade.gz")
    with open(extra + ".tmp", "wb") as f:
        pickle.dump(
            {
                "argv": argv,
                "it0": it0,
                "steps": steps,
                "blade": rec.blade.id,
                "recorder": rec.state(),
                "radius": rec.radii(),
            },
            f,
        )
    os.replace(state + ".tmp.yade.gz", state)
    os.replace(extra + ".tmp", extra)
    print(f"checkpoint at u/d = {rec.travel() / rec.depth:.3f}, iter {O.iter}", flush=True)


def rescale_stiffness(factor):
    """Multiply the stiffness of the bed's contacts by `factor` (--young), then settle
    with the reference damping 0.2, as the bed was (without damping it would not
    come to rest)."""
    for i in O.interactions:
        if i.isReal:
            i.phys.kn *= factor
            i.phys.ks *= factor
            i.phys.kr *= factor
            i.phys.ktw *= factor
    cut_damping, g.DAMPING = g.DAMPING, 0.2
    O.engines = g.engines(O, yade, [])
    O.dt = g.DT_FACTOR * utils.PWaveTimeStep()
    steps = g.settle(O, utils, 0.005)
    g.DAMPING = cut_damping
    return steps


def main():
    name = g.configure(sys.argv[1:])[-1]
    depth, alpha, travel = CUTS[name]
    travel = (g.TRAVEL or travel) * depth
    run = "{}_{}{}{}".format(
        name, g.tag(), "" if g.SPEED == 0.04 else "_v%g" % (g.SPEED * 1e3), g.settings()
    )
    with open(g.path("results", "beds", f"bed_{g.tag()}.json")) as f:
        bed = json.load(f)
    normal = (math.sin(math.radians(alpha)), math.cos(math.radians(alpha)))
    argv = [a for a in sys.argv[1:] if a != "--resume"]
    state, extra = checkpoint_paths(run)
    resumed = g.RESUME and os.path.exists(extra)
    if g.RESUME and not resumed:
        print(f"no checkpoint of {run}: starting from the bed", flush=True)
    if resumed:
        with open(extra, "rb") as f:
            saved = pickle.load(f)
        if saved["argv"] != argv:
            raise SystemExit("the checkpoint was made with {}".format(" ".join(saved["argv"])))
        O.load(state)
        blade = O.bodies[saved["blade"]]
        rec = Recorder(run, depth, blade, normal, bed)
        rec.restore(saved["recorder"])
        it0, steps = saved["it0"], saved["steps"]
        settle_steps = None
        print(f"resumed at u/d = {rec.travel() / depth:.3f}, iter {O.iter}", flush=True)
    else:
        O.load(g.path("beds", f"bed_{g.tag()}.yade.gz"))
        settle_steps = 0
        if g.YOUNG != 5.0e5:
            for m in O.materials:
                m.young = g.YOUNG
            settle_steps = rescale_stiffness(g.YOUNG / 5.0e5)
        level = bed["surface_level_m"]
        tip = (0.0, level - depth)
        height = LONG_BLADE_HEIGHT if g.LONG else BLADE_HEIGHT
        length = height * depth / math.sin(math.radians(alpha))
        body, normal = blade_body(tip, alpha, length, O.materials["blade"])
        for b in list(O.bodies):
            if not b.dynamic:
                continue
            p, r = b.state.pos, b.shape.radius
            behind = (p[0] - tip[0]) * normal[0] + (p[1] - tip[1]) * normal[1] < r
            if behind and p[1] > tip[1] - r:
                O.bodies.erase(b.id)
        blade_id = O.bodies.append(body)
        blade = O.bodies[blade_id]
        blade.state.vel = yade.Vector3(g.SPEED, 0, 0)
        rec = Recorder(run, depth, blade, normal, bed)
        O.engines = g.engines(O, yade, [yade.PyRunner(iterPeriod=10, command="rec.sample()")])
        O.dt = g.DT_FACTOR * utils.PWaveTimeStep()
        if g.ENERGY:
            O.trackEnergy = True
            O.energy.clear()
        it0 = O.iter
        steps = int(travel / g.SPEED / O.dt) + 20
    globals()["rec"] = rec
    chunk = int(g.CHECKPOINT * depth / g.SPEED / O.dt) if g.CHECKPOINT > 0 else steps
    while O.iter - it0 < steps:
        O.run(min(chunk, steps - (O.iter - it0)), True)
        if g.CHECKPOINT > 0:
            save_checkpoint(run, argv, rec, it0, steps)
    rec.write()
    meta = {
        "yade_version": bed["yade_version"],
        "seed": g.SEED,
        "name": name,
        "run": run,
        "ratio_d_over_D": g.RATIO,
        "slab_layers": g.SLAB,
        "thickness_m": g.THICKNESS,
        "mean_diameter_m": 2 * g.RADIUS,
        "grains": bed["grains"],
        "depth_mm": depth * 1e3,
        "rake_deg": alpha,
        "travel_mm": travel * 1e3,
        "speed_m_per_s": g.SPEED,
        "dt_s": O.dt,
        "steps": steps,
        "unit_weight_N_per_m3": bed["unit_weight_N_per_m3"],
        "solid_fraction": bed["solid_fraction"],
        "floor_below_tip_mm": (bed["surface_level_m"] - depth) * 1e3,
        "end_wall_mm": bed["x_end_m"] * 1e3,
        "wall_time_s": rec.elapsed(),
    }
    if g.LONG:
        meta["blade_height_d"] = LONG_BLADE_HEIGHT
    if g.settings() or g.ENERGY or g.CHECKPOINT or g.RESUME:
        meta.update(
            {
                "damping": g.DAMPING,
                "damp_gravity": g.DAMP_GRAVITY,
                "young_Pa": g.YOUNG,
                "dt_factor": g.DT_FACTOR,
                "settle_steps_after_rescale": settle_steps,
                "checkpoint_every_d": g.CHECKPOINT,
                "resumed": resumed,
                "command": "yade -n -j1 -x cut.py " + " ".join(sys.argv[1:]),
            }
        )
    with open(g.path("results", g.OUT or "cuts", run + ".json"), "w") as f:
        json.dump(meta, f, indent=1)
    print(json.dumps(meta), flush=True)


main()
