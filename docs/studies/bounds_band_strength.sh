#!/bin/sh
# soilcut's force beside the rigorous bounds under each band strength
# (`choices.band_strength`, docs/model.md §20): Fig. 5 every depth at
# N = 8, the bounds with each column at least as strong as the slope it
# stands at (--field slope, §18.5), the paper's rule and the two crossed
# rules. Writes docs/studies/bounds/band_strength.txt (each command and its
# table). About a minute a rule.
# Usage: sh docs/studies/bounds_band_strength.sh [path/to/soilcut]
set -eu
soilcut=${1:-target/release/soilcut}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=docs/studies/bounds/band_strength.txt
: > "$out"
for rule in footprint crossed-columns crossed-columns-unfloored; do
  args="--every 1 --mesh 8 --field slope --set choices.band_strength=\"$rule\""
  {
    echo "\$ soilcut bounds cases/paper/fig5.toml $args"
    "$soilcut" bounds cases/paper/fig5.toml --every 1 --mesh 8 --field slope \
      --set "choices.band_strength=\"$rule\"" --out "$tmp/b" --force | grep -v '^outputs in'
    echo
  } >> "$out"
done
cat "$out"
