"""Plane-strain biaxial test on the bed's grains (periodic cell, one layer).

Run: yade -n -j1 -x biaxial.py SIGMA [--seed S] [--damping C] [--dt-factor F] [--out DIR]
(SIGMA: the confining stress in Pa)

The grains are compacted isotropically to SIGMA0 with the bed's raining
friction (about the bed's density), given their working
friction, then compressed in y at a constant strain rate while sigma_x stays
SIGMA0 and z does not strain. Writes results/element/biaxial_SIGMA.csv (strains
and stresses, compression positive, every 0.2 % of axial strain, raw) and
results/element/biaxial_SIGMA.json (the run's figures); parameters.py turns the
curves into soilcut's parameters.

Issue 31's settings (grains.py): --damping sets the damping of the shear
only (the packing is compacted with the reference damping 0.2, as the beds
are rained with it), --dt-factor the time step; --out DIR writes to
results/DIR instead of results/element (parameters.py reads
results/element only).
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

SIGMA0 = 300.0  # confining stress (Pa), set from the command line
SIDE = 0.098  # cell side (m) of the loose cloud (NUM grains)
# cell thickness (m): the periodic collider needs > 2.1 largest bounding boxes
DEPTH_Z = 2.6 * 2 * g.RADIUS * (1 + g.FUZZ)
COMPACT_STRESS = 300.0  # isotropic stress (Pa) of the compaction, the same for every test
# axial strain rate (1/s) at 300 Pa: inertial number ~ 1e-3; scaled as sqrt(SIGMA0) to keep it
RATE_300 = 0.2
NUM = 1200  # grains: the noise of phi at the critical state falls as 1 / sqrt(NUM)
STRAIN = 0.50  # final axial strain: long enough for a steady critical state
# Contact friction while compacting: the bed's raining friction, which gives
# about the bed's density (solid fraction of disks 0.81 here, 0.82 in bed.json;
# frictionless compaction gives 0.84).
COMPACT_FRICTION = g.DEPOSIT_FRICTION


def yade_stress(sigma):
    """Yade divides by the cell volume; the slab's stress is per THICKNESS."""
    return sigma * g.THICKNESS / DEPTH_Z


START = time.time()


def main():
    global SIGMA0
    SIGMA0 = float(g.configure(sys.argv[1:])[-1])
    O.periodic = True
    O.cell.setBox(SIDE, SIDE, DEPTH_Z)
    g.materials(O, yade.CohFrictMat)
    sp = pack.SpherePack()
    sp.makeCloud(
        (0, 0, DEPTH_Z / 2),
        (SIDE, SIDE, DEPTH_Z / 2),
        rMean=g.RADIUS,
        rRelFuzz=g.FUZZ,
        num=NUM,
        periodic=True,
        seed=g.SEED,
    )
    for c, r in sp:
        O.bodies.append(utils.sphere(c, r, material=O.materials["grain"]))
    g.flatten(O)
    servo = Servo(yade_stress(COMPACT_STRESS))
    globals()["servo"] = servo
    shear_damping = g.DAMPING
    g.DAMPING = 0.2  # compaction with the reference damping (the beds are rained with it)
    O.engines = g.engines(
        O, yade, [yade.PyRunner(iterPeriod=10, command="servo.act()")], gravity=False
    )
    O.dt = g.DT_FACTOR * utils.PWaveTimeStep()
    g.set_friction(O, COMPACT_FRICTION)
    servo.compact(COMPACT_FRICTION)
    g.set_friction(O, g.FRICTION)
    servo.compact(g.FRICTION)
    # Unloaded isotropically to SIGMA0: the packing of every test is the
    # one compacted at COMPACT_STRESS (the bed's density at every stress).
    servo.retarget(yade_stress(SIGMA0))
    servo.compact(g.FRICTION)
    dense = solid_fraction()
    g.DAMPING = shear_damping
    O.engines[-1].damping = shear_damping
    rows = servo.shear()
    out = g.OUT or "element"
    g.write_csv(
        g.path("results", out, f"biaxial_{SIGMA0:g}.csv"),
        [
            "eps_axial",
            "eps_lateral",
            "eps_vol",
            "sigma_axial_Pa",
            "sigma_lateral_Pa",
            "mobilised_friction_deg",
        ],
        rows,
    )
    summary = dict(
        {
            "wall_time_s": time.time() - START,
            "yade_version": yade.config.version,
            "seed": g.SEED,
            "sigma0_Pa": SIGMA0,
            "grains": len(sp),
            "solid_fraction_before_shear": dense,
            "solid_fraction_after_shear": solid_fraction(),
            "strain_rate_per_s": rate(),
        }
    )
    if g.DAMPING != 0.2 or g.DT_FACTOR != 0.5:
        summary.update(
            {
                "shear_damping": g.DAMPING,
                "dt_factor": g.DT_FACTOR,
                "dt_s": O.dt,
                "command": "yade -n -j1 -x biaxial.py " + " ".join(sys.argv[1:]),
            }
        )
    # The friction and dilation angles: parameters.py.
    with open(g.path("results", out, f"biaxial_{SIGMA0:g}.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary))


def rate():
    """The axial strain rate (1/s) that keeps the inertial number at about 1e-3."""
    return RATE_300 * math.sqrt(SIGMA0 / 300.0)


def solid_fraction():
    h = O.cell.hSize
    return sum(math.pi * b.shape.radius**2 for b in O.bodies) / (h[0, 0] * h[1, 1])


class Servo:
    """Strain rates of the periodic cell (velGrad) that hold the servoed in-plane
    stresses at the target; the cell does not strain out of plane."""

    GAIN = 2.0  # strain rate (1/s) per unit relative stress error
    MAX_RATE = 1.0

    def __init__(self, target):
        self.target = target  # compressive, Yade's (volume) units
        self.axial_rate = None  # None: y servoed too; else the imposed compression rate

    def retarget(self, target):
        self.target = target

    def rate(self, measured):
        r = self.GAIN * (measured - self.target) / self.target
        return max(-self.MAX_RATE, min(self.MAX_RATE, r))

    def act(self):
        st = utils.getStress()
        vg = yade.Matrix3.Zero
        vg[0, 0] = self.rate(-st[0, 0])
        vg[1, 1] = self.rate(-st[1, 1]) if self.axial_rate is None else -self.axial_rate
        O.cell.velGrad = vg

    def compact(self, friction):
        """Both in-plane stresses at SIGMA0 until the packing is at rest."""
        self.axial_rate = None
        for _ in range(80):
            O.run(1000, True)
            st = utils.getStress()
            err = max(abs(-st[0, 0] - self.target), abs(-st[1, 1] - self.target)) / self.target
            if utils.unbalancedForce() < 0.02 and err < 0.03:
                return
        stress = self.target * g.THICKNESS / DEPTH_Z
        print(
            f"compaction at friction {friction:g} to {stress:.0f} Pa: "
            f"unbalanced {utils.unbalancedForce():.3g}, stress error {err:.3g}",
            flush=True,
        )

    def shear(self):
        """Axial compression in y at RATE, sigma_x held; rows every 0.2 % of strain."""
        h0 = O.cell.hSize
        lx0, ly0 = h0[0, 0], h0[1, 1]
        self.axial_rate = rate()
        scale = DEPTH_Z / g.THICKNESS
        rows = []
        step = max(1, int(0.002 / rate() / O.dt))
        while True:
            O.run(step, True)
            h = O.cell.hSize
            e1 = -math.log(h[1, 1] / ly0)
            e3 = -math.log(h[0, 0] / lx0)
            st = utils.getStress()
            s1, s3 = -st[1, 1] * scale, -st[0, 0] * scale
            ratio = (s1 - s3) / (s1 + s3) if s1 + s3 > 0 else 0.0
            phi = math.degrees(math.asin(max(-1.0, min(1.0, ratio))))
            rows.append((e1, e3, e1 + e3, s1, s3, phi))
            if len(rows) % 25 == 0:
                print(f"eps1 {e1:.3f}  s1 {s1:.1f}  s3 {s3:.1f}  phi {phi:.1f}", flush=True)
            if e1 >= STRAIN:
                return rows


main()
