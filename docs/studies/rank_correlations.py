#!/usr/bin/env python3
"""Spearman rank correlations of a `soilcut sweep` table (standard library only).

Usage: python3 docs/studies/rank_correlations.py [docs/studies/table1-hs-lhs1000/sweep.csv]

Uses the runs whose status is "ok": each column is ranked (ties get the
average of their ranks) and the Pearson correlation of the ranks is printed
as the Markdown table of docs/studies/README.md (rows: figures, columns: the
varied keys).
"""

import csv
import math
import sys

PARAMETERS = [
    ("soil.friction.initial", "φc"),
    ("soil.friction.peak", "φp"),
    ("soil.dilation.initial", "ψc"),
    ("soil.peak_shear", "up"),
    ("soil.band_width_d50", "N = dB/d50"),
]
FIGURES = [
    "initial_force_norm",
    "max_force_norm",
    "mean_force_norm_last_half",
    "peaks",
    "band_jumps",
]


def ranks(values):
    """Ranks 1..n; tied values get the mean of the ranks they span."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    result = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        mean_rank = (i + j) / 2 + 1
        for k in range(i, j + 1):
            result[order[k]] = mean_rank
        i = j + 1
    return result


def pearson(x, y):
    n = len(x)
    mx = sum(x) / n
    my = sum(y) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx = sum((a - mx) ** 2 for a in x)
    syy = sum((b - my) ** 2 for b in y)
    return sxy / math.sqrt(sxx * syy)


def spearman(x, y):
    return pearson(ranks(x), ranks(y))


def signed(r):
    text = f"{r:+.2f}"
    return text.replace("-", "\u2212")  # the README's minus sign


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/studies/table1-hs-lhs1000/sweep.csv"
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    ok = [row for row in rows if row["status"] == "ok"]
    print(f"{len(ok)} of {len(rows)} runs finished (status ok)\n")
    print("| figure | " + " | ".join(label for _, label in PARAMETERS) + " |")
    print("|---|" + "---|" * len(PARAMETERS))
    columns = {key: [float(row[key]) for row in ok] for key, _ in PARAMETERS}
    for figure in FIGURES:
        y = [float(row[figure]) for row in ok]
        cells = [signed(spearman(columns[key], y)) for key, _ in PARAMETERS]
        print(f"| {figure} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
