#!/usr/bin/env bash
# Redraws the README's pictures of cases/paper/original.toml
# (docs/img/force.png, beta.png, deformation.png) from a run at the case's
# own settings, docs/img/envelope.png from an ensemble of Table 1 HS, and
# the landscapes of Table 1 HS and S (docs/img/landscape.png,
# landscape_map_hs.png, landscape_map_s.png; README, docs/performance.md,
# docs/reproduction.md). From the repository root:
#   bash docs/scripts/readme_figures.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p soilcut
soilcut=${CARGO_TARGET_DIR:-target}/release/soilcut
out=out/readme-figures
"$soilcut" run cases/paper/original.toml --quiet --force --out "$out"
for name in force beta deformation; do
  cp "$out/plots/$name.png" "docs/img/$name.png"
done
# The force envelope of an ensemble (README, "Ensembles"): Table 1 HS at its
# defaults, 7 perturbed members.
"$soilcut" run cases/paper/table1-hs.toml --ensemble 7 --quiet --force --out "$out-ensemble"
cp "$out-ensemble/plots/envelope.png" docs/img/envelope.png
# Every candidate's force at u/d = 4, and the maps through the run, at d/500
# (set explicitly: the default increment is d/1250 since issue 28).
"$soilcut" landscape cases/paper/table1-hs.toml --at 4 --set run.increment=0.04 --set run.ground=nodes --force \
  --out "$out-landscape" >/dev/null
cp "$out-landscape/landscape.png" docs/img/landscape.png
for name in hs s; do
  "$soilcut" landscape "cases/paper/table1-$name.toml" --every 0.05 --set run.increment=0.04 --set run.ground=nodes --force \
    --out "$out-map-$name" >/dev/null
  cp "$out-map-$name/landscape_map.png" "docs/img/landscape_map_$name.png"
done
# The bounds' fields (README, "Rigorous bounds"): the original case at u/d = 2.
"$soilcut" bounds cases/paper/original.toml --at 2 --force --out "$out-bounds" >/dev/null
cp "$out-bounds/bounds.png" docs/img/bounds.png
