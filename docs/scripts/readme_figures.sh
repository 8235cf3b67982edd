#!/usr/bin/env bash
# Redraws the README's pictures of cases/paper/original.toml
# (docs/img/force.png, beta.png, deformation.png) from a run at the case's
# own settings. From the repository root:
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
