"""The grains, contact law and bin shared by every DEM script (Yade, SI units).

A quasi-2D bed: one layer of spheres in the plane z = 0 whose out-of-plane
translation and in-plane-axis rotations are blocked (blockedDOFs 'zXY'),
which is what two frictionless side walls one grain apart impose. Forces per
unit width and the in-plane unit weight use the same slab thickness
(`THICKNESS`), so P / (gamma d^2) does not depend on it.
"""

import math

SEED = 14
RADIUS = 1.0e-3  # mean grain radius (m); mean diameter D = 2 mm
FUZZ = 0.25  # radii uniform in RADIUS * (1 -/+ FUZZ)
DENSITY = 2650.0  # grain density (kg/m^3)
YOUNG = 5.0e5  # contact modulus (Pa): kn ~ YOUNG * r; overlaps ~ 4e-3 D at 1 kPa
POISSON = 0.3  # ks / kn
FRICTION = 30.0  # grain-grain contact friction (degrees)
ETA_ROLL = 0.3  # rolling resistance: rolling moment <= ETA_ROLL * r * Fn
DEPOSIT_FRICTION = 5.0  # contact friction while raining the bed (denser packing)
BLADE_FRICTION = 20.0  # blade-grain contact friction (degrees), set
DAMPING = 0.2  # Cundall's non-viscous damping
GRAVITY = 9.81
THICKNESS = 2.0 * RADIUS  # slab thickness that turns forces into forces per unit width


def materials(O, CohFrictMat):
    """Append the grain, blade and frictionless wall materials; returns their ids."""
    common = dict(young=YOUNG, poisson=POISSON, density=DENSITY, normalCohesion=0.0,
                  shearCohesion=0.0, isCohesive=False)
    grain = O.materials.append(CohFrictMat(frictionAngle=math.radians(FRICTION),
                                           momentRotationLaw=True, etaRoll=ETA_ROLL,
                                           label='grain', **common))
    blade = O.materials.append(CohFrictMat(frictionAngle=math.radians(BLADE_FRICTION),
                                           momentRotationLaw=False, label='blade', **common))
    wall = O.materials.append(CohFrictMat(frictionAngle=0.0, momentRotationLaw=False,
                                          label='wall', **common))
    return grain, blade, wall


def flatten(O):
    """Constrain every dynamic sphere to the plane z = 0."""
    for b in O.bodies:
        if b.dynamic:
            b.state.blockedDOFs = 'zXY'
            b.state.vel = b.state.vel * 0


def set_friction(O, degrees):
    """Set the grain contact friction on the material and on every existing contact."""
    t = math.tan(math.radians(degrees))
    O.materials['grain'].frictionAngle = math.radians(degrees)
    for i in O.interactions:
        if not i.isReal:
            continue
        m1 = O.bodies[i.id1].material
        m2 = O.bodies[i.id2].material
        if m1.label == 'grain' and m2.label == 'grain':
            i.phys.tangensOfFrictionAngle = t


def area_weight(O, x0, x1, y0, y1):
    """In-plane weight per unit area (N/m^3 once divided by THICKNESS) of the grains whose
    centres lie in the window; returns (gamma, solid fraction of disks)."""
    mass = 0.0
    disk = 0.0
    for b in O.bodies:
        if not b.dynamic:
            continue
        p = b.state.pos
        if x0 <= p[0] < x1 and y0 <= p[1] < y1:
            mass += b.state.mass
            disk += math.pi * b.shape.radius ** 2
    area = (x1 - x0) * (y1 - y0)
    return mass * GRAVITY / area / THICKNESS, disk / area


def surface(O, x0, x1, width):
    """Ground surface: the highest grain top in each column of `width`, as (x, y) pairs
    (columns with no grain are left out)."""
    n = int(round((x1 - x0) / width))
    top = [None] * n
    for b in O.bodies:
        if not b.dynamic:
            continue
        p = b.state.pos
        k = int((p[0] - x0) // width)
        if 0 <= k < n:
            h = p[1] + b.shape.radius
            if top[k] is None or h > top[k]:
                top[k] = h
    return [(x0 + (k + 0.5) * width, h) for k, h in enumerate(top) if h is not None]


def engines(O, yade, extra, gravity=True, periodic=False):
    """The engine list: collider, sphere/box contacts with rolling resistance, integrator."""
    g = (0.0, -GRAVITY, 0.0) if gravity else (0.0, 0.0, 0.0)
    bounds = [yade.Bo1_Sphere_Aabb(), yade.Bo1_Box_Aabb()]
    geoms = [yade.Ig2_Sphere_Sphere_ScGeom6D(), yade.Ig2_Box_Sphere_ScGeom6D()]
    return ([yade.ForceResetter(),
             yade.InsertionSortCollider(bounds, verletDist=0.1 * RADIUS),
             yade.InteractionLoop(geoms, [yade.Ip2_CohFrictMat_CohFrictMat_CohFrictPhys()],
                                  [yade.Law2_ScGeom6D_CohFrictPhys_CohesionMoment(
                                      useIncrementalForm=True, always_use_moment_law=True)])]
            + extra
            + [yade.NewtonIntegrator(damping=DAMPING, gravity=g, label='newton')])


def write_csv(path, header, rows):
    with open(path, 'w') as f:
        f.write(','.join(header) + '\n')
        for r in rows:
            f.write(','.join(fmt(v) for v in r) + '\n')


def fmt(v):
    if isinstance(v, float):
        return '%.6g' % v
    return str(v)


def rain_cloud(x0, x1, y0, rows, seed):
    """Grain centres and radii on a jittered lattice (spacing 2.6 mean radii, no overlaps):
    the loose cloud that is rained. Radii uniform in RADIUS (1 -/+ FUZZ)."""
    import random

    rng = random.Random(seed)
    pitch = 2.6 * RADIUS * (1 + FUZZ) / 1.25
    cols = int((x1 - x0) / pitch)
    slack = pitch - 2 * RADIUS * (1 + FUZZ)
    out = []
    for j in range(rows):
        for i in range(cols):
            r = RADIUS * (1 + FUZZ * (2 * rng.random() - 1))
            jx = (rng.random() - 0.5) * max(slack, 0.0)
            out.append(((x0 + (i + 0.5) * pitch + jx, y0 + (j + 0.5) * pitch, 0.0), r))
    return out
