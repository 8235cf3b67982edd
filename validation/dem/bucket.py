"""The bucket dig of digs/bucket.json through a rained bed (bed.py first): the
force and moment on the bucket, its fill and the ground.

Run: yade -n -j1 -x bucket.py [--seed S] [--ratio R] [--long] [--damping C] [--speed V]
                              [--travel T] [--checkpoint T] [--resume] [--out DIR]
(options: grains.py; --speed defaults to the dig's, 0.02 m/s; --travel T stops
after T d of s, a part of the dig; --checkpoint T: every T d of s; --out DIR:
results/DIR instead of results/bucket).

The bucket: its profile (dig.py) as rigid facets, one per chord (the plate
one, the arc ARC_SEGMENTS), each a triangle whose base is the chord in the
grains' plane z = 0 and whose apex stands FACET_HEIGHT radii out of it, so a
grain at z = 0 touches the chord itself, from either side (facets are
two-sided: the plate's outer side holds the grains off as its inner side
does). Facet-grain contacts take the blade's material (friction 20 deg).
Every time step the facets' velocities are set so that they reach the
dig's pose of the next step exactly: the motion is prescribed, never
integrated from forces. Grains that overlap the bucket or lie in it at the
start are removed. The bin's start wall (x = -40 mm), which the bucket's
back overhangs at the start, is cut down to START_WALL_TOP above the
levelled surface (`python3 dig.py` prints the margin).

Records, with RUN = bucket_TAG_vV[SETTINGS] (TAG the bed's, V the speed in
mm/s, SETTINGS grains.settings()), in results/bucket (or results/OUT):

- RUN_forces.csv, every record_every_d (0.02 d) of the progress s, which is
  the lip's path length (the tool moves at ds/dt = V: a fixed time step of
  0.02 d / V; the lip's own path length since the start is `lip_path_mm`):
  the pose at the record's end (pivot x, y, theta; the lip's x, y), the mean
  over the interval of the force of the grains on the bucket (fx, fy, N per
  m of width, and over gamma d^2), of its moment about the pivot
  (counter-clockwise positive, N m per m, and over gamma d^3) and of the
  end wall's horizontal force, and, at the record's end, the grains whose
  centres lie in the bucket (the region bounded by the profile and the
  chord rim-lip): their mass (kg per m of width), the area it fills at the
  bed's bulk density (mm^2, mass / (gamma / g)) and their number.
- RUN_surface.csv: the ground every surface_every_d (0.25 d) of s and at the
  end (the highest grain top in every D-wide column, the grains in the
  bucket left out; x from the lip's start, y from the levelled surface, mm).
- RUN.json: the run's figures, versions, seed, the dig file's sha256, and
  `finished` (false while a run is under way: written at every checkpoint
  with the records so far).

Checkpoints as cut.py's: Yade's state and the recorder's in
checkpoints/RUN.{yade.gz,pkl} (committed at a session's end: README.md); --resume continues from them
(or starts from the bed when there is none).
"""

import hashlib
import json
import math
import os
import pickle
import sys
import time
import types

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import dig as D  # noqa: E402
import grains as g  # noqa: E402
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

ARC_SEGMENTS = 18  # chords of the 180-degree arc (10 degrees, 5.2 mm: 2.6 D)
FACET_HEIGHT = 3.0  # a facet's apex out of the grains' plane (mean radii)
START_WALL_TOP = 0.010  # the start wall's top above the levelled surface (m)
SAMPLE = 10  # time steps between force samples
MM = 1e-3


class Bucket:
    """The facets and their prescribed motion: world (m) from the dig (mm)."""

    def __init__(self, dig, level, facets, tool, t0):
        self.dig, self.level, self.facets, self.tool, self.t0 = dig, level, facets, tool, t0
        self.theta = None  # the facets' rotation now (degrees)

    def s(self, t):
        """The progress (mm) at time t (s)."""
        return (t - self.t0) * g.SPEED / MM

    def world(self, at, p):
        """A tool-frame point (mm) at pose `at` in Yade's frame (m)."""
        x, y = D.to_world(self.dig, at, p)
        return x * MM, self.level + y * MM

    def local(self, at, q):
        """A point of Yade's frame (m) in the tool frame at pose `at` (mm)."""
        return D.to_tool(self.dig, at, (q[0] / MM, (q[1] - self.level) / MM))

    def move(self):
        """Set every facet's velocity so that this step ends on the next pose."""
        dt = O.dt
        at = D.pose(self.dig, self.s(O.time + dt))
        if self.theta is None:
            self.theta = D.pose(self.dig, self.s(O.time))[2]
        spin = math.radians(at[2] - self.theta) / dt
        for fid, p in zip(self.facets, self.tool):
            st = O.bodies[fid].state
            x, y = self.world(at, p)
            st.vel = yade.Vector3((x - st.pos[0]) / dt, (y - st.pos[1]) / dt, 0.0)
            st.angVel = yade.Vector3(0.0, 0.0, spin)
        self.theta = at[2]

    def pivot(self, at):
        return self.world(at, self.dig["pivot"])

    def load(self):
        """Force (x, y) and moment about the pivot (z) of the grains on the bucket (N, N m)."""
        px, py = self.pivot(D.pose(self.dig, self.s(O.time)))
        fx = fy = mz = 0.0
        for fid in self.facets:
            for i in O.interactions.withBody(fid):
                if not i.isReal:
                    continue
                f = i.phys.normalForce + i.phys.shearForce  # on id2
                sign = 1.0 if i.id2 == fid else -1.0
                c = i.geom.contactPoint
                fx += sign * f[0]
                fy += sign * f[1]
                mz += (c[0] - px) * sign * f[1] - (c[1] - py) * sign * f[0]
        return fx, fy, mz

    def carried(self, at):
        """The grains whose centres lie in the bucket at pose `at`."""
        return [
            b
            for b in O.bodies
            if b is not None and b.dynamic and D.inside(self.dig, self.local(at, b.state.pos))
        ]


def build(dig, level):
    """The bucket's facets at the dig's first pose (Yade's frame)."""
    at = D.pose(dig, 0.0)
    chords = D.profile(dig, ARC_SEGMENTS)
    half = Bucket(dig, level, [], [], O.time)
    h = FACET_HEIGHT * g.RADIUS
    for a, b in zip(chords, chords[1:]):
        (ax, ay), (bx, by) = half.world(at, a), half.world(at, b)
        body = utils.facet(
            [(ax, ay, 0.0), (bx, by, 0.0), ((ax + bx) / 2, (ay + by) / 2, h)],
            fixed=True,
            material=O.materials["blade"],
        )
        half.facets.append(O.bodies.append(body))
        half.tool.append(half.local(at, body.state.pos))
    return half


def clear_start(bucket, chords):
    """Remove the grains that overlap the bucket or lie in it at the start."""
    at = D.pose(bucket.dig, 0.0)
    pts = [bucket.world(at, p) for p in chords]
    gone = 0
    for b in list(O.bodies):
        if not b.dynamic:
            continue
        p, r = b.state.pos, b.shape.radius
        near = min(segment_distance(p, a, c) for a, c in zip(pts, pts[1:]))
        if near < r or D.inside(bucket.dig, bucket.local(at, p)):
            O.bodies.erase(b.id)
            gone += 1
    return gone


def segment_distance(p, a, b):
    """In-plane distance (m) from p to the segment ab."""
    ux, uy = b[0] - a[0], b[1] - a[1]
    t = ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / (ux * ux + uy * uy)
    t = min(max(t, 0.0), 1.0)
    return math.hypot(p[0] - a[0] - t * ux, p[1] - a[1] - t * uy)


def lower_start_wall(bed):
    """Cut the start wall down to START_WALL_TOP above the surface (the bucket's
    back overhangs it; no grain reaches that high behind the bucket)."""
    wall = O.bodies[bed["start_wall_id"]]
    half = (bed["surface_level_m"] + START_WALL_TOP) / 2
    e = wall.shape.extents
    wall.shape.extents = yade.Vector3(e[0], half, e[2])
    wall.state.pos = yade.Vector3(wall.state.pos[0], half, wall.state.pos[2])


class Recorder:
    """Window means of the load, the fill and the ground, by progress s."""

    KEEP = (
        "sum",
        "count",
        "next_force",
        "next_surface",
        "forces",
        "surfaces",
        "lip_path",
        "last_lip",
    )

    def __init__(self, bucket, bed):
        self.bucket, self.dig = bucket, bucket.dig
        self.gamma, self.wall, self.x_end = (
            bed["unit_weight_N_per_m3"],
            bed["end_wall_id"],
            bed["x_end_m"],
        )
        self.sum, self.count = [0.0] * 4, 0
        self.next_force = bucket.dig["record_every_d"] * bucket.dig["depth"]
        self.next_surface = 0.0
        self.forces, self.surfaces = [], []
        self.lip_path, self.last_lip = 0.0, None
        self.start, self.before = time.time(), 0.0
        self.checked = 0

    def state(self):
        out = {k: getattr(self, k) for k in self.KEEP}
        out["wall_s"] = self.elapsed()
        return out

    def restore(self, state):
        for k in self.KEEP:
            setattr(self, k, state[k])
        self.before, self.start = state["wall_s"], time.time()

    def elapsed(self):
        return self.before + time.time() - self.start

    def step(self):
        """Every step: the bucket's motion; every SAMPLE steps: a sample."""
        self.bucket.move()
        if O.iter % SAMPLE == 0:
            self.sample()

    def sample(self):
        fx, fy, mz = self.bucket.load()
        if self.checked < 3 and fx:
            total = sum(O.forces.f(i)[0] for i in self.bucket.facets)
            print(f"check: contact sum {fx:.6g}, O.forces {total:.6g}", flush=True)
            self.checked += 1
        for k, v in enumerate((fx, fy, mz, O.forces.f(self.wall)[0])):
            self.sum[k] += v / g.THICKNESS
        self.count += 1
        s = self.bucket.s(O.time)
        at = D.pose(self.dig, s)
        lip = self.bucket.world(at, self.dig["profile"]["lip"])
        if self.last_lip is not None:
            self.lip_path += math.dist(lip, self.last_lip) / MM
        self.last_lip = lip
        d = self.dig["depth"]
        if s >= self.next_surface - 1e-9:
            self.record_surface(s)
            self.next_surface += self.dig["surface_every_d"] * d
        if s >= self.next_force - 1e-9:
            self.record(s, at, lip)
            self.next_force += self.dig["record_every_d"] * d

    def record(self, s, at, lip):
        fx, fy, mz, wall = (v / self.count for v in self.sum)
        d = self.dig["depth"] * MM
        grains = self.bucket.carried(at)
        mass = sum(b.state.mass for b in grains) / g.THICKNESS
        area = mass / (self.gamma / g.GRAVITY) / MM**2
        self.forces.append(
            (
                s,
                s / self.dig["depth"],
                D.phase(self.dig, s) + 1,
                self.lip_path,
                *at,
                lip[0] / MM,
                (lip[1] - self.bucket.level) / MM,
                fx,
                fy,
                fx / (self.gamma * d**2),
                fy / (self.gamma * d**2),
                mz,
                mz / (self.gamma * d**3),
                mass,
                area,
                len(grains),
                wall,
            )
        )
        self.sum, self.count = [0.0] * 4, 0

    def record_surface(self, s):
        """The ground, without the grains the bucket carries."""
        held = {b.id for b in self.bucket.carried(D.pose(self.dig, s))}
        ground = types.SimpleNamespace(
            bodies=[b for b in O.bodies if b is not None and b.id not in held]
        )
        for x, y in g.surface(ground, -0.040, self.x_end, 2 * g.RADIUS):
            self.surfaces.append((s / self.dig["depth"], x / MM, (y - self.bucket.level) / MM))
        print(
            f"s/d = {s / self.dig['depth']:.2f}  iter {O.iter}  wall {self.elapsed():.0f} s",
            flush=True,
        )

    def finish(self):
        """The last, partial interval and the final ground."""
        s = self.bucket.s(O.time)
        at = D.pose(self.dig, s)
        if self.count:
            self.record(s, at, self.bucket.world(at, self.dig["profile"]["lip"]))
        if not self.surfaces or self.surfaces[-1][0] < s / self.dig["depth"] - 1e-9:
            self.record_surface(s)

    def write(self, base):
        g.write_csv(base + "_forces.csv", FORCE_HEADER, self.forces)
        g.write_csv(base + "_surface.csv", ["s_over_d", "x_mm", "y_mm"], self.surfaces)


FORCE_HEADER = (
    "s_mm,s_over_d,phase,lip_path_mm,x_mm,y_mm,theta_deg,lip_x_mm,lip_y_mm,"
    "fx_N_per_m,fy_N_per_m,fx_norm,fy_norm,moment_N_m_per_m,moment_norm,"
    "fill_kg_per_m,fill_area_mm2,fill_grains,end_wall_N_per_m"
).split(",")


def checkpoint_paths(run):
    return g.path("checkpoints", run + ".yade.gz"), g.path("checkpoints", run + ".pkl")


def save(run, argv, bucket, rec, run_steps):
    """Yade's state and the bucket's and recorder's, moved over the last ones."""
    state, extra = checkpoint_paths(run)
    O.save(state + ".tmp.yade.gz")
    keep = {k: getattr(bucket, k) for k in ("facets", "tool", "t0", "theta")}
    with open(extra + ".tmp", "wb") as f:
        pickle.dump({"argv": argv, "steps": run_steps, "bucket": keep, "recorder": rec.state()}, f)
    os.replace(state + ".tmp.yade.gz", state)
    os.replace(extra + ".tmp", extra)
    print(
        f"checkpoint at s/d = {bucket.s(O.time) / bucket.dig['depth']:.3f}, iter {O.iter}",
        flush=True,
    )


def start(dig, bed):
    """A fresh run from the bed: the bucket placed, the grains cleared, the engines."""
    O.load(g.path("beds", f"bed_{g.tag()}.yade.gz"))
    lower_start_wall(bed)
    bucket = build(dig, bed["surface_level_m"])
    gone = clear_start(bucket, D.profile(dig, ARC_SEGMENTS))
    O.engines = g.engines(O, yade, [yade.PyRunner(iterPeriod=1, command="rec.step()")], facets=True)
    O.dt = g.DT_FACTOR * utils.PWaveTimeStep()
    bucket.t0 = O.time
    steps = int(math.ceil(stop(dig) * MM / g.SPEED / O.dt)) + 1
    return bucket, Recorder(bucket, bed), (O.iter, steps, gone)


def resume(dig, bed, run, argv):
    """The run from its checkpoint."""
    state, extra = checkpoint_paths(run)
    with open(extra, "rb") as f:
        saved = pickle.load(f)
    if saved["argv"] != argv:
        raise SystemExit("the checkpoint was made with {}".format(" ".join(saved["argv"])))
    O.load(state)
    b = saved["bucket"]
    bucket = Bucket(dig, bed["surface_level_m"], b["facets"], b["tool"], b["t0"])
    bucket.theta = b["theta"]
    rec = Recorder(bucket, bed)
    rec.restore(saved["recorder"])
    print(f"resumed at s/d = {bucket.s(O.time) / dig['depth']:.3f}, iter {O.iter}", flush=True)
    return bucket, rec, saved["steps"]


def stop(dig):
    """Where the run stops (mm of s): --travel T (in d) for a part of the dig, else its end."""
    end = dig["poses"][-1]["s"]
    return min(g.TRAVEL * dig["depth"], end) if g.TRAVEL else end


def meta(dig, bed, run, rec, run_steps, finished, resumed):
    _, steps, gone = run_steps
    with open(D.DIG, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    s = rec.bucket.s(O.time)
    return {
        "run": run,
        "finished": finished,
        "s_reached_mm": min(s, dig["poses"][-1]["s"]),
        "s_end_mm": dig["poses"][-1]["s"],
        "s_stop_mm": stop(dig),
        "versions": {"yade": bed["yade_version"], "python": sys.version.split()[0]},
        "seed": g.SEED,
        "dig": "digs/bucket.json",
        "dig_sha256": sha,
        "ratio_d_over_D": g.RATIO,
        "slab_layers": g.SLAB,
        "thickness_m": g.THICKNESS,
        "grains": bed["grains"],
        "grains_removed_at_start": gone,
        "unit_weight_N_per_m3": bed["unit_weight_N_per_m3"],
        "solid_fraction": bed["solid_fraction"],
        "end_wall_mm": bed["x_end_m"] * 1e3,
        "start_wall_top_mm": START_WALL_TOP * 1e3,
        "arc_segments": ARC_SEGMENTS,
        "speed_m_per_s": g.SPEED,
        "damping": g.DAMPING,
        "damp_gravity": g.DAMP_GRAVITY,
        "young_Pa": g.YOUNG,
        "dt_factor": g.DT_FACTOR,
        "dt_s": O.dt,
        "steps": steps,
        "checkpoint_every_d": g.CHECKPOINT,
        "resumed": resumed,
        "command": "yade -n -j1 -x bucket.py " + " ".join(sys.argv[1:]),
        "wall_time_s": rec.elapsed(),
    }


def main():
    argv = sys.argv[1:]
    g.configure(argv)
    dig = D.load()
    if "--speed" not in argv:
        g.SPEED = dig["speed"] * MM
    if g.YOUNG != 5.0e5:
        raise SystemExit("--young: bucket.py cuts the bed at its own stiffness (5e5) only")
    run = f"bucket_{g.tag()}_v{g.SPEED / MM:g}{g.settings()}"
    with open(g.path("results", "beds", f"bed_{g.tag()}.json")) as f:
        bed = json.load(f)
    level = bed["surface_level_m"]
    margins = D.check(
        dig, bed["x_end_m"] / MM, -level / MM, bed["x_start_m"] / MM, START_WALL_TOP / MM
    )
    if min(margins.values()) < 0:
        raise SystemExit(f"the dig does not fit the bin of bed_{g.tag()}: {margins}")
    keep = [a for a in argv if a != "--resume"]
    resumed = g.RESUME and os.path.exists(checkpoint_paths(run)[1])
    if resumed:
        bucket, rec, run_steps = resume(dig, bed, run, keep)
    else:
        if g.RESUME:
            print(f"no checkpoint of {run}: starting from the bed", flush=True)
        bucket, rec, run_steps = start(dig, bed)
    globals()["rec"] = rec
    base = g.path("results", g.OUT or "bucket", run)
    it0, steps, _ = run_steps
    chunk = int(g.CHECKPOINT * dig["depth"] * MM / g.SPEED / O.dt) if g.CHECKPOINT > 0 else steps
    while O.iter - it0 < steps:
        O.run(min(chunk, steps - (O.iter - it0)), True)
        if g.CHECKPOINT > 0 and O.iter - it0 < steps:
            save(run, keep, bucket, rec, run_steps)
            rec.write(base)
            write_meta(base, meta(dig, bed, run, rec, run_steps, False, resumed))
    rec.finish()
    rec.write(base)
    out = meta(dig, bed, run, rec, run_steps, True, resumed)
    write_meta(base, out)
    print(json.dumps(out), flush=True)


def write_meta(base, out):
    with open(base + ".json", "w") as f:
        json.dump(out, f, indent=1)


main()
