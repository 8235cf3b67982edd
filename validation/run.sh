#!/usr/bin/env bash
# soilcut beside the DEM cuts: runs cases/validation/*.toml to u = 1 ... 5 d
# (each travel its own run, so that profile.csv is the ground at that u),
# overlays the force curves on the DEM's (soilcut compare) and prints the
# figures docs/validation.md quotes (validation/compare.py). From the
# repository root:   bash validation/run.sh      (about a minute)
# The DEM results it reads are committed in validation/dem/results/; to
# rerun the DEM itself see validation/dem/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p soilcut
soilcut=${CARGO_TARGET_DIR:-target}/release/soilcut
out=out/validation
mkdir -p "$out"
lastrun() {
  local case=cases/validation/$1.toml d travel
  d=$(grep -E '^depth' "$case" | sed 's/[^0-9.]*\([0-9.]*\).*/\1/')
  travel=$(grep -E '^travel' "$case" | sed 's/[^0-9.]*\([0-9.]*\).*/\1/')
  python3 -c "print(round($travel / $d))"
}
for name in vertical raked30 deep; do
  case=cases/validation/$name.toml
  d=$(grep -E '^depth' "$case" | sed 's/[^0-9.]*\([0-9.]*\).*/\1/')
  for k in $(seq 1 "$(lastrun "$name")"); do
    "$soilcut" run "$case" --quiet --no-plots --force --out "$out/$name-u$k" \
      --set "run.travel=$(python3 -c "print($k * $d)")" >/dev/null
  done
done
# Calibrate on the vertical cut (friction angles only), predict the others.
"$soilcut" fit cases/validation/vertical.toml --set run.travel=100.1 \
  --measured validation/dem/results/cut_vertical_measured.csv \
  --free soil.friction.initial,soil.friction.peak,soil.friction.residual \
  --starts 2 --iterations 60 --quiet --force --out "$out/fit-vertical" >/dev/null
friction=$(python3 -c "import tomllib; f = tomllib.load(open('$out/fit-vertical/best.toml', 'rb'))['soil']['friction']; print('{ initial = %r, peak = %r, residual = %r }' % (f['initial'], f['peak'], f['residual']))")
for name in vertical raked30 deep; do
  "$soilcut" run "cases/validation/$name.toml" --quiet --no-plots --force --out "$out/$name-fitted" \
    --set "soil.friction=$friction" --set 'title="friction angles fitted to the vertical DEM cut"' >/dev/null
done
python3 validation/compare.py "$out"
for name in vertical raked30 deep; do
  [ -f "validation/dem/results/cut_${name}_measured.csv" ] || continue
  "$soilcut" compare "$out/$name-u$(lastrun "$name")" "$out/$name-fitted" --measured "validation/dem/results/cut_${name}_measured.csv" \
    --out "docs/img/validation_force_$name.png"
done
