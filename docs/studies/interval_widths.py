#!/usr/bin/env python3
"""The intervals of several `soilcut fit` folders side by side (standard
library only): for each free key and folder, the best value, the 95 %
interval and its width, from the folders' fit.csv.

Usage: python3 docs/studies/interval_widths.py FOLDER... [KEY=TRUTH ...]
"""

import csv
import sys


def main():
    folders = [a for a in sys.argv[1:] if "=" not in a]
    truth = dict(a.split("=", 1) for a in sys.argv[1:] if "=" in a)
    print("| key | truth | fit | best | 95 % interval | width | verdict |")
    print("|---|---|---|---|---|---|---|")
    rows = {}
    for folder in folders:
        with open(f"{folder}/fit.csv", newline="") as f:
            for r in csv.DictReader(f):
                rows.setdefault(r["key"], []).append((folder, r))
    for key, fits in rows.items():
        for folder, r in fits:
            lower, upper = r["lower"], r["upper"]
            if lower and upper:
                interval = f"{float(lower):.4f} to {float(upper):.4f}"
                width = f"{float(upper) - float(lower):.4f}"
            else:
                interval, width = "reaches a bound", ""
            name = folder.rstrip("/").split("/")[-1]
            best = f"{float(r['best']):.4f}"
            verdict = r["verdict"]
            print(
                f"| `{key}` | {truth.get(key, '')} | {name} | {best} | {interval} | {width} | {verdict} |"
            )


if __name__ == "__main__":
    main()
