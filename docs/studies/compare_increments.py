#!/usr/bin/env python3
"""How much each run of a `soilcut sweep` changes when the increment is
refined: two sweep tables of the same sample (same --vary, --sample and
--seed, different run.increment) compared run by run (standard library only).

Usage: python3 docs/studies/compare_increments.py COARSE/sweep.csv FINE/sweep.csv

Prints, for each summary figure, the median and 95th percentile of
|fine − coarse| / |fine| over the runs that are "ok" in both, and the
Spearman rank correlation between the two tables' values of the figure
(1: the runs are ordered alike at both increments).
"""

import csv
import sys

from rank_correlations import spearman

FIGURES = [
    "initial_force_norm",
    "max_force_norm",
    "final_force_norm",
    "mean_force_norm_last_half",
    "u_over_d_at_max",
    "peaks",
    "band_jumps",
]


def rows(path):
    with open(path, newline="") as f:
        return {r["run"]: r for r in csv.DictReader(f) if r["status"] == "ok"}


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def main():
    coarse, fine = rows(sys.argv[1]), rows(sys.argv[2])
    runs = sorted(set(coarse) & set(fine), key=int)
    for r in runs:
        keys = [k for k in coarse[r] if k.startswith(("soil.", "blade.", "run.", "choices."))]
        if any(coarse[r][k] != fine[r][k] for k in keys):
            sys.exit(f"run {r}: the two tables are not the same sample")
    print(f"{len(runs)} runs ok in both\n")
    print("| figure | median relative change | 95th percentile | rank correlation |")
    print("|---|---|---|---|")
    for name in FIGURES:
        a = [float(coarse[r][name]) for r in runs]
        b = [float(fine[r][name]) for r in runs]
        change = [abs(y - x) / abs(y) if y != 0 else abs(y - x) for x, y in zip(a, b)]
        print(
            f"| {name} | {100 * percentile(change, 0.5):.1f} % "
            f"| {100 * percentile(change, 0.95):.1f} % | {spearman(a, b):+.2f} |"
        )


if __name__ == "__main__":
    main()
