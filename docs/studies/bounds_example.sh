#!/bin/sh
# The guide's bounds examples (docs/guide/bounds.md) with their wall times:
# Fig. 5 at u/d = 1 and every 0.5 d through the run, N = 12, each column at
# least as strong as the slope it stands at (--field slope), and the same
# run with each column its own φ (--field columns, the default).
# Writes docs/studies/bounds/example.txt (each command, its table and its
# wall time in seconds).
# Usage: sh docs/studies/bounds_example.sh [path/to/soilcut]
set -eu
soilcut=${1:-target/release/soilcut}
dir=docs/studies/bounds
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$dir"
out="$dir/example.txt"
: > "$out"
for args in "--at 1 --mesh 12 --field slope" "--every 0.5 --mesh 12 --field slope" \
  "--every 0.5 --mesh 12 --field columns"; do
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  "$soilcut" bounds cases/paper/fig5.toml $args --out "$tmp/b" --force > "$tmp/table"
  end=$(date +%s.%N)
  {
    echo "\$ soilcut bounds cases/paper/fig5.toml $args"
    grep -v '^outputs in' "$tmp/table"
    awk -v s="$start" -v e="$end" 'BEGIN { printf "wall time: %.1f s\n\n", e - s }'
  } >> "$out"
done
cat "$out"
