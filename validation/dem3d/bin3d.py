"""The three-dimensional bin shared by bed3d.py and cut3d.py (Yade, SI units).

The grains and the contact law are those of the 2D campaign, imported from
validation/dem/grains.py (density, YOUNG, POISSON, FRICTION, ETA_ROLL,
BLADE_FRICTION, DAMPING, FUZZ, the raining friction and `configure`); only the
geometry differs, and it is here.

Half of a soil bin is modelled: a frictionless symmetry wall at z = 0 (the
blade's centreline), the bin's frictionless side wall at z = HALF_WIDTH. The
blade's tip starts at x = 0, depth d = 20 mm below the levelled surface.

Options (after the script's name): --seed S (default 14), --ratio R = d/D
(default 5 here: D = 4 mm, coarse), the others of grains.py where they apply.
"""

import os
import sys

HERE3 = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE3, "..", "dem"))
import grains as g  # noqa: E402

DEPTH = g.DEPTH_REF  # blade tip depth d (m): 20 mm, as in 2D
X_START = -0.25 * DEPTH  # start wall (m): just behind the blade's back (vertical blade)
X_END = 7.0 * DEPTH  # end wall (m): 7 d from the tip's start, 4 d ahead of the face after 3 d
HEIGHT = 3.0 * DEPTH  # levelled bed height (m): the floor 2 d below the tip
HALF_WIDTH = 4.5 * DEPTH  # half-bin width (m): w/2 + 3 d for w = 3 d (w = d: 5.5 d beside the edge)


def configure(argv):
    """grains.configure with d/D = 5 unless --ratio is given; returns the positional words."""
    argv = list(argv)
    if "--ratio" not in argv:
        argv += ["--ratio", "5"]
    words = g.configure(argv)
    g.HERE = HERE3  # grains.path() writes under validation/dem3d/
    return words


def tag():
    return f"r{g.RATIO:g}_s{g.SEED}"
