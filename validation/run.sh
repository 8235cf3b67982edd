#!/usr/bin/env bash
# soilcut beside the DEM cuts: for every cut of cases/validation/ an ensemble
# of 7 perturbed runs (docs/model.md §12.1) with the element-test keys, the
# same with the face friction rule before issue 20 (choices.face_friction =
# "sign"), and one with the friction angles fitted to the vertical DEM cut;
# prints the figures docs/validation.md quotes (validation/compare.py) and
# draws the force curves beside the DEM's seed mean. From the repository
# root:   bash validation/run.sh      (a few minutes)
# The DEM results it reads are committed in validation/dem/results/; to
# rerun the DEM itself see validation/dem/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p soilcut
soilcut=${CARGO_TARGET_DIR:-target}/release/soilcut
out=out/validation
mkdir -p "$out"
ensemble() { "$soilcut" run "$@" --ensemble 7 --quiet --no-plots --force >/dev/null; }
peak() { python3 -c "import tomllib; print(tomllib.load(open('cases/validation/$1.toml', 'rb'))['soil']['friction']['peak'])"; }
for name in vertical raked30 deep; do
  # Coulomb's wedge at the case's initial and peak friction angles.
  "$soilcut" analytic "cases/validation/$name.toml" > "$out/$name-analytic.txt"
  "$soilcut" analytic "cases/validation/$name.toml" --set "soil.friction.initial=$(peak "$name")" \
    > "$out/$name-analytic-peak.txt"
  ensemble "cases/validation/$name.toml" --out "$out/$name" --set 'title="element-test keys"'
  ensemble "cases/validation/$name.toml" --out "$out/$name-sign" --set choices.face_friction=sign \
    --set 'title="element-test keys, former face friction rule (sign)"'
done
# Calibrate on the vertical cut (friction angles only), predict the others.
"$soilcut" fit cases/validation/vertical.toml \
  --measured validation/dem/results/cut_vertical_mean.csv \
  --free soil.friction.initial,soil.friction.peak,soil.friction.residual \
  --objective means:5 --evaluations 160 --polish 20 --profile-points 0 --jobs 2 \
  --quiet --force --out "$out/fit-vertical" >/dev/null
friction=$(python3 -c "import tomllib; f = tomllib.load(open('$out/fit-vertical/best.toml', 'rb'))['soil']['friction']; print('{ initial = %r, peak = %r, residual = %r }' % (f['initial'], f['peak'], f['residual']))")
echo "fitted on the vertical cut: soil.friction = $friction"
for name in vertical raked30 deep; do
  ensemble "cases/validation/$name.toml" --out "$out/$name-fitted" \
    --set "soil.friction=$friction" --set 'title="friction angles fitted to the vertical DEM cut"'
done
python3 validation/compare.py "$out"
for name in vertical raked30 deep; do
  [ -f "validation/dem/results/cut_${name}_mean.csv" ] || continue
  "$soilcut" compare "$out/$name/k+0" "$out/$name-sign/k+0" "$out/$name-fitted/k+0" \
    --measured "validation/dem/results/cut_${name}_mean.csv" \
    --out "docs/img/validation_force_$name.png" >/dev/null
done
