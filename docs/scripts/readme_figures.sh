#!/usr/bin/env bash
# Redraws the README's pictures of cases/paper/original.toml
# (docs/img/force.png, beta.png, deformation.png) from a run at the case's
# own settings, and docs/img/envelope.png from an ensemble of Table 1 HS. From the repository root:
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
# The bounds' fields (README, "Rigorous bounds"): the original case at u/d = 2.
"$soilcut" bounds cases/paper/original.toml --at 2 --force --out "$out-bounds" >/dev/null
cp "$out-bounds/bounds.png" docs/img/bounds.png
