#!/usr/bin/env bash
# Prints the figures that README.md and docs/performance.md quote from
# command output, so that they are copied from a run, not remembered:
#   1. the landscape of Table 1 HS at u/d = 4, d/500 (README, "The landscape
#      of minimum effort"), and the rows of docs/performance.md's table
#      ("the minimum is flat") at d/200, d/500, d/1000 and u/d = 2, 4, 4.5;
#   2. the landscape maps of Table 1 HS and Table 1 S with --every 0.05 at
#      d/500, as the README's command (README: "in how many landscapes ...");
#   3. examples/mpc.py's full run: its wall time and printed figures
#      (README, "Planning and reinforcement learning"), with the Python of
#      $SOILCUT_VENV (default .venv) if the package is installed there.
# From the repository root: bash docs/scripts/readme_numbers.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p soilcut
soilcut=${CARGO_TARGET_DIR:-target}/release/soilcut
out=out/readme-numbers

# "u/d = 4.000: 16206 candidates; least ... (β = ...); 8 within 0.1 %,
# 8512 within 1 % over 21.60 d; outputs in ..." as a row of the table.
row() {
    sed -E 's/^u\/d = ([0-9.]+): ([0-9]+) candidates; .*; ([0-9]+) within 0\.1 %, ([0-9]+) within 1 % over ([0-9.]+) d;.*/| \1 | \2 | \3 | \4 | \5 d |/'
}

echo "landscapes of Table 1 HS (increment | u/d | candidates | within 0.1 % | within 1 % | span):"
for n in 200 500 1000; do
    increment=$(python3 -c "print(20 / $n)")
    for at in 2 4 4.5; do
        printf '| d/%s ' "$n"
        "$soilcut" landscape cases/paper/table1-hs.toml --at "$at" \
            --set run.increment="$increment" --set run.ground=nodes --force --out "$out/landscape" | row
    done
done

echo
echo "landscape maps, --every 0.05 at d/500:"
for name in table1-hs table1-s; do
    printf '%s: ' "$name"
    "$soilcut" landscape "cases/paper/$name.toml" --every 0.05 --set run.increment=0.04 --set run.ground=nodes \
        --force --out "$out/map-$name"
done

venv="${SOILCUT_VENV:-.venv}"
echo
if "$venv/bin/python" -c "import soilcut, matplotlib" 2>/dev/null; then
    echo "examples/mpc.py (full run):"
    start=$(date +%s.%N)
    "$venv/bin/python" examples/mpc.py --out "$out/mpc.png"
    echo "wall time: $(python3 -c "print(f'{$(date +%s.%N) - $start:.1f} s')")"
else
    echo "examples/mpc.py: skipped ($venv has no soilcut or matplotlib: run scripts/test first)"
fi
