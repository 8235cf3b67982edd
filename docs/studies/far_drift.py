#!/usr/bin/env python3
"""How far bands' forces drift from one increment to the next (issue 39).

For Fig. 5 and Table 1 HS at their defaults, at u/d = 1.5, 3 and 4.5,
takes the landscape (every first-stage candidate, `soilcut.landscape`) at
that increment and at the 1, 2, 4 and 8 increments after it, and prints,
for the candidates emerging more than 5 d ahead of the blade (the far
bands the search must look at every increment because the minimum is
flat, docs/performance.md):

- how far above the least force they lie (the median and 5th
  percentile of P / P_least − 1);
- how much each one's force has changed k increments later (its
  landscape's force interpolated at the same emergence point, x fixed in
  the ground): the median, 95th percentile and largest |ΔP / P|.

Those two numbers size the next step of issue 39, bounds carried across
increments: a far candidate whose force lay a gap g above the least needs
evaluating again only once its drift could have closed that gap. Needs
the Python package (`pip install ./python`):

    python3 docs/studies/far_drift.py
"""

import numpy as np

import soilcut

AHEAD = 5.0
LAGS = (1, 2, 4, 8)


def percent(values, q):
    return 100.0 * np.percentile(values, q)


def drift(case, at):
    """One line of figures for `case` at u/d = `at`."""
    d = float(case["blade.depth"])
    v0 = float(case.resolved()["run.increment"])
    lands = [soilcut.landscape(case, at + k * v0 / d) for k in (0, *LAGS)]
    first = lands[0].candidates
    far = first["distance_over_d"] > AHEAD
    x, force = first["x_emergence"][far], first["force"][far]
    gap = force / first["force"].min() - 1.0
    parts = [
        f"{far.sum()} far candidates, above the least by {percent(gap, 50):.2f} % "
        f"(median), {percent(gap, 5):.2f} % (5th percentile)"
    ]
    for k, land in zip(LAGS, lands[1:]):
        later = land.candidates
        order = np.argsort(later["x_emergence"])
        moved = np.interp(x, later["x_emergence"][order], later["force"][order])
        change = np.abs(moved / force - 1.0)
        parts.append(
            f"after {k}: {percent(change, 50):.3f} / {percent(change, 95):.3f} / "
            f"{100.0 * change.max():.3f} %"
        )
    return "; ".join(parts)


def main():
    print("|ΔP/P| of far candidates: median / 95th percentile / largest, after k increments")
    for name in ("fig5", "table1-hs"):
        case = soilcut.Case.from_file(f"cases/paper/{name}.toml")
        for at in (1.5, 3.0, 4.5):
            print(f"{name}, u/d {at}: {drift(case, at)}")


if __name__ == "__main__":
    main()
