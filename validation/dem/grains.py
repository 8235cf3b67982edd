"""The grains, contact law and bin shared by every DEM script (Yade, SI units).

Every script takes the same options after its name (`configure`):

    --seed S      the random seed of the bed (default 14)
    --ratio R     d / D: the blade depth d = 20 mm over the mean grain
                  diameter D (default 10, D = 2 mm)
    --slab N      0 (default): one layer of spheres in the plane z = 0 whose
                  out-of-plane translation and in-plane-axis rotations are
                  blocked (what two frictionless side walls one grain apart
                  impose: a Schneebeli-type 2D analogue); N >= 3: a slab N
                  lattice layers thick (N x 1.3 D) between two frictionless
                  side walls, the grains free in 3D
    --speed V     blade speed in m/s (cut.py only, default 0.04)
    --travel T    the blade's travel in d (cut.py only; default: the cut's)
    --short       the short, shallow bin (bed.py makes it, cut.py cuts it):
                  end wall at 140 mm, bed 60 mm deep (7 d and 2 d from the
                  tip of a 20 mm cut), for the costly beds (d/D = 15, the
                  slab) and 1 d of travel
    --long        the long bin (bed.py makes it, cut.py cuts it): end wall
                  at 300 mm (15 d from the tip's start for d = 20 mm), the
                  same 75 mm deep bed, grains and raining, for the cuts to
                  5 d; cut.py's blade is 5 d tall in it (3.5 d otherwise)

The numerical settings (issue 31's rate study; the defaults are those of
every earlier run, and a run's name records each one that differs):

    --damping C       Cundall's non-viscous damping (default 0.2)
    --undamped-gravity  exclude gravity from the damping (Yade's
                      NewtonIntegrator.dampGravity = False; default: damped)
    --young E         the contact modulus in Pa (default 5e5); cut.py
                      rescales the stiffness of the bed's contacts to it and
                      settles the bed again before the cut
    --dt-factor F     the time step over Yade's P-wave time step (default 0.5)
    --energy          track the energy budget (cut.py: the blade's work, the
                      damping's and friction's dissipation; bookkeeping only)
    --out DIR         results/DIR instead of results/cuts (cut.py) or
                      results/element (biaxial.py)
    --checkpoint T    save the state every T d of travel (cut.py; 0: never)
    --resume          continue a cut from its last checkpoint (cut.py)

Forces per unit width and the in-plane unit weight use the same slab
thickness (`THICKNESS`), so P / (gamma d^2) does not depend on it.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))
DEPTH_REF = 0.020  # the blade depth d the grain size is set from (m)
SEED = 14
RATIO = 10.0  # d / D
SLAB = 0  # 0: monolayer; else lattice layers between frictionless side walls
SPEED = 0.04  # blade speed (m/s)
TRAVEL = None  # travel in d (None: the cut's own)
SHORT = False  # the short bin (bed.py)
LONG = False  # the long bin (bed.py)
RADIUS = 1.0e-3  # mean grain radius (m), set by configure from RATIO
FUZZ = 0.25  # radii uniform in RADIUS * (1 -/+ FUZZ)
DENSITY = 2650.0  # grain density (kg/m^3)
YOUNG = 5.0e5  # contact modulus (Pa): kn ~ YOUNG * r, so kn / (p D) does not depend on D
POISSON = 0.3  # ks / kn
FRICTION = 30.0  # grain-grain contact friction (degrees)
ETA_ROLL = 0.3  # rolling resistance: rolling moment <= ETA_ROLL * r * Fn
DEPOSIT_FRICTION = 5.0  # contact friction while raining the bed (denser packing)
BLADE_FRICTION = 20.0  # blade-grain contact friction (degrees), set
DAMPING = 0.2  # Cundall's non-viscous damping
DAMP_GRAVITY = True  # gravity is damped with the contact forces (Yade's default)
DT_FACTOR = 0.5  # time step over the P-wave time step
ENERGY = False  # track the energy budget (cut.py)
OUT = None  # results/OUT instead of the script's own folder (cut.py: cuts)
CHECKPOINT = 0.0  # checkpoint interval in d (cut.py; 0: none)
RESUME = False  # continue from the last checkpoint (cut.py)
GRAVITY = 9.81
PITCH = 2.6  # lattice pitch of the rained cloud in mean radii (no overlaps at FUZZ)
THICKNESS = 2.0 * RADIUS  # slab thickness that turns forces into forces per unit width


def configure(argv):
    """Reads the options of the module docstring from argv; returns the positional words."""
    global SEED, RATIO, SLAB, SPEED, TRAVEL, SHORT, LONG, RADIUS, THICKNESS
    global DAMPING, DAMP_GRAVITY, YOUNG, DT_FACTOR, ENERGY, OUT, CHECKPOINT, RESUME
    words, i = [], 0
    flags = ("--short", "--long", "--undamped-gravity", "--energy", "--resume")
    while i < len(argv):
        a = argv[i]
        if a in (
            "--seed",
            "--ratio",
            "--slab",
            "--speed",
            "--travel",
            "--damping",
            "--young",
            "--dt-factor",
            "--out",
            "--checkpoint",
        ):
            v = argv[i + 1]
            if a == "--seed":
                SEED = int(v)
            elif a == "--ratio":
                RATIO = float(v)
            elif a == "--slab":
                SLAB = int(v)
            elif a == "--travel":
                TRAVEL = float(v)
            elif a == "--damping":
                DAMPING = float(v)
            elif a == "--young":
                YOUNG = float(v)
            elif a == "--dt-factor":
                DT_FACTOR = float(v)
            elif a == "--out":
                OUT = v
            elif a == "--checkpoint":
                CHECKPOINT = float(v)
            else:
                SPEED = float(v)
            i += 2
        elif a in flags:
            if a == "--short":
                SHORT = True
            elif a == "--long":
                LONG = True
            elif a == "--undamped-gravity":
                DAMP_GRAVITY = False
            elif a == "--energy":
                ENERGY = True
            else:
                RESUME = True
            i += 1
        else:
            words.append(a)
            i += 1
    if 0 < SLAB < 3:
        raise SystemExit("--slab must be 0 (monolayer) or >= 3 layers")
    if SHORT and LONG:
        raise SystemExit("--short and --long are two bins: one at a time")
    RADIUS = DEPTH_REF / RATIO / 2
    THICKNESS = 2.0 * RADIUS if SLAB == 0 else SLAB * PITCH * RADIUS
    return words


def tag():
    """The name of a bed: r<ratio>_s<seed>[_slab<N>][_short|_long]."""
    slab = f"_slab{SLAB}" if SLAB else ""
    short = "_short" if SHORT else ""
    long = "_long" if LONG else ""
    return f"r{RATIO:g}_s{SEED}{slab}{short}{long}"


def settings():
    """The numerical settings that differ from the defaults, as a run-name suffix
    (empty for the defaults, so earlier runs keep their names)."""
    out = ""
    if DAMPING != 0.2:
        out += f"_damp{DAMPING:g}"
    if not DAMP_GRAVITY:
        out += "_undampedg"
    if YOUNG != 5.0e5:
        out += f"_E{YOUNG:g}"
    if DT_FACTOR != 0.5:
        out += f"_dt{DT_FACTOR:g}"
    return out


def path(*parts):
    p = os.path.join(HERE, *parts)
    os.makedirs(os.path.dirname(p), exist_ok=True)
    return p


def materials(omega, CohFrictMat):
    """Append the grain, blade and frictionless wall materials; returns their ids."""
    common = dict(
        young=YOUNG,
        poisson=POISSON,
        density=DENSITY,
        normalCohesion=0.0,
        shearCohesion=0.0,
        isCohesive=False,
    )
    grain = omega.materials.append(
        CohFrictMat(
            frictionAngle=math.radians(FRICTION),
            momentRotationLaw=True,
            etaRoll=ETA_ROLL,
            label="grain",
            **common,
        )
    )
    blade = omega.materials.append(
        CohFrictMat(
            frictionAngle=math.radians(BLADE_FRICTION),
            momentRotationLaw=False,
            label="blade",
            **common,
        )
    )
    wall = omega.materials.append(
        CohFrictMat(frictionAngle=0.0, momentRotationLaw=False, label="wall", **common)
    )
    return grain, blade, wall


def half_z():
    """Half the out-of-plane extent of the bin's boxes (m): past the slab."""
    return 5 * RADIUS if SLAB == 0 else THICKNESS / 2 + 3 * RADIUS


def side_walls(omega, utils, x0, x1, height, wall):
    """The slab's two frictionless side walls (nothing for a monolayer)."""
    if SLAB == 0:
        return []
    out = []
    for side in (-1, 1):
        z = side * (THICKNESS / 2 + RADIUS)
        out.append(
            omega.bodies.append(
                utils.box(
                    ((x0 + x1) / 2, height / 2, z),
                    ((x1 - x0) / 2 + 4 * RADIUS, height / 2, RADIUS),
                    fixed=True,
                    material=wall,
                )
            )
        )
    return out


def flatten(omega):
    """Constrain every dynamic sphere to the plane z = 0 (monolayer only)."""
    for b in omega.bodies:
        if b.dynamic:
            if SLAB == 0:
                b.state.blockedDOFs = "zXY"
            b.state.vel = b.state.vel * 0


def set_friction(omega, degrees):
    """Set the grain contact friction on the material and on every existing contact."""
    t = math.tan(math.radians(degrees))
    omega.materials["grain"].frictionAngle = math.radians(degrees)
    for i in omega.interactions:
        if not i.isReal:
            continue
        m1 = omega.bodies[i.id1].material
        m2 = omega.bodies[i.id2].material
        if m1.label == "grain" and m2.label == "grain":
            i.phys.tangensOfFrictionAngle = t


def area_weight(omega, x0, x1, y0, y1):
    """In-plane unit weight (N/m^3 of the slab) of the grains whose centres lie
    in the window; returns (gamma, solid fraction of disks or spheres)."""
    mass = 0.0
    solid = 0.0
    for b in omega.bodies:
        if not b.dynamic:
            continue
        p = b.state.pos
        if x0 <= p[0] < x1 and y0 <= p[1] < y1:
            mass += b.state.mass
            r = b.shape.radius
            solid += math.pi * r**2 if SLAB == 0 else 4.0 / 3.0 * math.pi * r**3
    area = (x1 - x0) * (y1 - y0)
    volume = area if SLAB == 0 else area * THICKNESS
    return mass * GRAVITY / area / THICKNESS, solid / volume


def surface(omega, x0, x1, width):
    """Ground surface: the highest grain top in each column of `width`, as (x, y) pairs
    (columns with no grain are left out)."""
    n = int(round((x1 - x0) / width))
    top = [None] * n
    for b in omega.bodies:
        if not b.dynamic:
            continue
        p = b.state.pos
        k = int((p[0] - x0) // width)
        if 0 <= k < n:
            h = p[1] + b.shape.radius
            if top[k] is None or h > top[k]:
                top[k] = h
    return [(x0 + (k + 0.5) * width, h) for k, h in enumerate(top) if h is not None]


def engines(omega, yade, extra, gravity=True, facets=False):
    """The engine list: collider, sphere/box contacts with rolling resistance, integrator;
    with `facets`, sphere/facet contacts too (bucket.py's tool)."""
    g = (0.0, -GRAVITY, 0.0) if gravity else (0.0, 0.0, 0.0)
    bounds = [yade.Bo1_Sphere_Aabb(), yade.Bo1_Box_Aabb()]
    geoms = [yade.Ig2_Sphere_Sphere_ScGeom6D(), yade.Ig2_Box_Sphere_ScGeom6D()]
    if facets:
        bounds.append(yade.Bo1_Facet_Aabb())
        geoms.append(yade.Ig2_Facet_Sphere_ScGeom6D())
    return (
        [
            yade.ForceResetter(),
            yade.InsertionSortCollider(bounds, verletDist=0.1 * RADIUS),
            yade.InteractionLoop(
                geoms,
                [yade.Ip2_CohFrictMat_CohFrictMat_CohFrictPhys()],
                [
                    yade.Law2_ScGeom6D_CohFrictPhys_CohesionMoment(
                        useIncrementalForm=True, always_use_moment_law=True
                    )
                ],
            ),
        ]
        + extra
        + [
            yade.NewtonIntegrator(
                damping=DAMPING, gravity=g, dampGravity=DAMP_GRAVITY, label="newton"
            )
        ]
    )


FACE_COS = math.cos(math.radians(45.0))  # a contact is on the face within 45 degrees of its normal


def face_force(omega, bid, normal):
    """Force (x, y) of the grains on body `bid` through its face's contacts:
    those whose direction from the body to the grain lies within 45 degrees
    of the face's outward `normal` (x, y), so that the blade's bottom, back
    and edges are left out (the cut scripts' face-only force)."""
    fx = fy = 0.0
    for i in omega.interactions.withBody(bid):
        if not i.isReal:
            continue
        f = i.phys.normalForce + i.phys.shearForce  # on id2; -f on id1
        n = i.geom.normal  # from id1 to id2
        sign = 1.0 if i.id2 == bid else -1.0
        # the direction from the blade to the grain
        out = (-sign * n[0], -sign * n[1])
        if out[0] * normal[0] + out[1] * normal[1] >= FACE_COS:
            fx += sign * f[0]
            fy += sign * f[1]
    return fx, fy


def contact_sum_x(omega, bid):
    """x force on body `bid` summed over its real contacts (to check against
    O.forces, which also holds what is not a contact)."""
    return sum(
        (1.0 if i.id2 == bid else -1.0) * (i.phys.normalForce + i.phys.shearForce)[0]
        for i in omega.interactions.withBody(bid)
        if i.isReal
    )


def write_csv(path, header, rows):
    with open(path, "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(fmt(v) for v in r) + "\n")


def fmt(v):
    if isinstance(v, float):
        return f"{v:.6g}"
    return str(v)


def rain_cloud(x0, x1, y0, rows, seed):
    """Grain centres and radii on a jittered lattice (PITCH mean radii, no overlaps):
    the loose cloud that is rained; SLAB layers of it across a slab. Radii
    uniform in RADIUS (1 -/+ FUZZ)."""
    import random

    rng = random.Random(seed)
    pitch = PITCH * RADIUS
    cols = int((x1 - x0) / pitch)
    slack = pitch - 2 * RADIUS * (1 + FUZZ)
    layers = [0.0] if SLAB == 0 else [(k + 0.5) * pitch - THICKNESS / 2 for k in range(SLAB)]
    out = []
    for j in range(rows):
        for z in layers:
            for i in range(cols):
                r = RADIUS * (1 + FUZZ * (2 * rng.random() - 1))
                jx = (rng.random() - 0.5) * max(slack, 0.0)
                out.append(((x0 + (i + 0.5) * pitch + jx, y0 + (j + 0.5) * pitch, z), r))
    return out


def settle(omega, utils, limit, chunk=2000, cap=200000):
    """Run until the unbalanced force ratio is below `limit` (or `cap` steps)."""
    done = 0
    while done < cap:
        omega.run(chunk, True)
        done += chunk
        if utils.unbalancedForce() < limit:
            return done
    return done
