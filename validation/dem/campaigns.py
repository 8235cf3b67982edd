"""The DEM's campaigns: where each one's cuts and element tests are, and which
one soilcut is compared with (stdlib only; imported by summarise.py,
parameters.py, mechanism.py and ../compare.py).

- `reference`: the campaign of issue 20, Cundall's non-viscous damping 0.2,
  the cuts at 40 mm/s (results/cuts/, results/element/). Its force depends
  on the blade's speed (issue 31; docs/validation.md).
- `damp0`: the same cuts and element tests without damping in the cut and
  the shear (`--damping 0`), whose force does not depend on the speed; the
  cuts compared with soilcut run at 20 mm/s (results/damp0/,
  results/element_damp0/).

YARDSTICK is the campaign soilcut's keys (cases/validation/), the
validation test's bands (validation/bands.json) and docs/validation.md's
tables come from: `damp0` since issue 31.
"""

import sys
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"

CAMPAIGNS = {
    # cuts, element: folders of results/; speed (m/s) and damping of the cuts
    # compared with soilcut; suffix: of this campaign's output files.
    "reference": {
        "cuts": "cuts",
        "element": "element",
        "speed": 0.04,
        "damping": 0.2,
        "suffix": "",
    },
    "damp0": {
        "cuts": "damp0",
        "element": "element_damp0",
        "speed": 0.02,
        "damping": 0.0,
        "suffix": "_damp0",
    },
}
YARDSTICK = "damp0"


def config_key(meta):
    """A cut's configuration: cut, d/D, slab, short or long bin, speed (when not 40 mm/s),
    and the numerical settings that differ from the defaults (as in the run names)."""
    settings = ""
    if meta.get("damping", 0.2) != 0.2:
        settings += "_damp{:g}".format(meta["damping"])
    if not meta.get("damp_gravity", True):
        settings += "_undampedg"
    if meta.get("young_Pa", 5.0e5) != 5.0e5:
        settings += "_E{:g}".format(meta["young_Pa"])
    if meta.get("dt_factor", 0.5) != 0.5:
        settings += "_dt{:g}".format(meta["dt_factor"])
    return "{}_r{:g}{}{}{}".format(
        meta["name"],
        meta["ratio_d_over_D"],
        bin_suffix(meta),
        "" if meta["speed_m_per_s"] == 0.04 else "_v{:g}".format(meta["speed_m_per_s"] * 1e3),
        settings,
    )


def bin_suffix(meta):
    """The slab and bin of a run's name and bed tag: [_slab<N>][_short|_long]."""
    return "{}{}{}".format(
        f"_slab{meta['slab_layers']:d}" if meta["slab_layers"] else "",
        "_short" if "_short" in meta["run"] else "",
        "_long" if "_long" in meta["run"] else "",
    )


def compared_key(name, campaign):
    """The configuration of cut `name` that a campaign compares with soilcut
    (d/D = 10, monolayer, full bin, the campaign's speed and damping)."""
    c = CAMPAIGNS[campaign]
    return config_key(
        {
            "name": name,
            "ratio_d_over_D": 10.0,
            "slab_layers": 0,
            "run": "",
            "speed_m_per_s": c["speed"],
            "damping": c["damping"],
        }
    )


def bed_tag(meta):
    """The bed a cut ran in (grains.tag()): r<ratio>_s<seed>[_slab<N>][_short|_long]."""
    return "r{:g}_s{:d}{}".format(meta["ratio_d_over_D"], meta["seed"], bin_suffix(meta))


def campaign_option(argv, default="reference"):
    """`--campaign NAME` taken out of argv (a list, changed in place)."""
    name = default
    if "--campaign" in argv:
        i = argv.index("--campaign")
        name = argv[i + 1]
        del argv[i : i + 2]
    if name not in CAMPAIGNS:
        sys.exit("--campaign must be one of " + ", ".join(CAMPAIGNS))
    return name
