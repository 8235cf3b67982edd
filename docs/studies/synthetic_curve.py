#!/usr/bin/env python3
"""A synthetic measured curve from a soilcut run: the run's force (per unit
width) linearly interpolated at N points evenly spaced in u over the run,
each multiplied by 1 + r n with n standard normal (seeded), written as a
CSV with the columns u,force (standard library only). With --weights, a
third column weight = (mean |force| / force)^2 makes the relative noise of
one level for `soilcut fit`.

Usage: python3 docs/studies/synthetic_curve.py RUN/history.csv OUT.csv \
    [--points 100] [--noise 0.02] [--seed 1] [--weights]

The first point is at u = travel / N (the first increment), the last at the
run's final u.
"""

import argparse
import csv
import random


def history(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [(float(r["u"]), float(r["force"])) for r in rows]


def interpolate(curve, x):
    if x <= curve[0][0]:
        return curve[0][1]
    for (x0, y0), (x1, y1) in zip(curve, curve[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return curve[-1][1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("history")
    parser.add_argument("out")
    parser.add_argument("--points", type=int, default=100)
    parser.add_argument("--noise", type=float, default=0.02)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--weights", action="store_true")
    args = parser.parse_args()
    curve = history(args.history)
    rng = random.Random(args.seed)
    travel = curve[-1][0]
    points = []
    for k in range(1, args.points + 1):
        u = travel * k / args.points
        force = interpolate(curve, u) * (1.0 + args.noise * rng.gauss(0.0, 1.0))
        points.append((u, force))
    mean = sum(abs(p) for _, p in points) / len(points)
    with open(args.out, "w", newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(["u", "force", "weight"] if args.weights else ["u", "force"])
        for u, force in points:
            row = [repr(u), repr(force)]
            if args.weights:
                row.append(repr((mean / force) ** 2))
            out.writerow(row)


if __name__ == "__main__":
    main()
