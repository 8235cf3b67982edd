#!/usr/bin/env bash
# soilcut beside the DEM cuts: for every cut of cases/validation/ an ensemble
# of 7 perturbed runs (docs/model.md §12.1) with the element-test keys, the
# same with the face friction rule before issue 20 (choices.face_friction =
# "sign"), and one with the friction angles fitted to the vertical DEM cut;
# prints the figures docs/validation.md quotes (validation/compare.py) and
# draws the force curves beside the DEM's seed mean. From the repository
# root:   bash validation/run.sh      (a few minutes)
# The DEM is the yardstick campaign (validation/dem/campaigns.py: `damp0`,
# the cuts without numerical damping at 20 mm/s; its seed means are
# validation/dem/results/cut_<name>_damp0_mean.csv, from summarise.py
# --campaign damp0).
#         bash validation/run.sh reference
# is the "before" record of issue 31: the keys of the damped element tests
# (parameters.py --campaign reference, written to out/validation-reference/
# cases/) beside the damped DEM cuts at 40 mm/s, fitted to the damped
# vertical cut (cut_vertical_mean.csv); no former face friction rule, no
# pictures, and the bands are printed, not written.
# The DEM results it reads are committed in validation/dem/results/; to
# rerun the DEM itself see validation/dem/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p soilcut
soilcut=${CARGO_TARGET_DIR:-target}/release/soilcut
campaign=${1:-}
if [ "$campaign" = reference ]; then
  out=out/validation-reference
  cases=$out/cases
  python3 validation/dem/parameters.py --campaign reference --cases "$cases" >/dev/null
else
  out=out/validation
  cases=cases/validation
fi
mkdir -p "$out"
suffix=$(cd validation/dem && python3 -c "from campaigns import CAMPAIGNS, YARDSTICK; print(CAMPAIGNS['$campaign' or YARDSTICK]['suffix'])")
ensemble() { "$soilcut" run "$@" --ensemble 7 --quiet --no-plots --force >/dev/null; }
peak() { python3 -c "import tomllib; print(tomllib.load(open('$cases/$1.toml', 'rb'))['soil']['friction']['peak'])"; }
for name in vertical raked30 deep; do
  # Coulomb's wedge at the case's initial and peak friction angles.
  "$soilcut" analytic "$cases/$name.toml" > "$out/$name-analytic.txt"
  "$soilcut" analytic "$cases/$name.toml" --set "soil.friction.initial=$(peak "$name")" \
    > "$out/$name-analytic-peak.txt"
  ensemble "$cases/$name.toml" --out "$out/$name" --set 'title="element-test keys"'
  [ "$campaign" = reference ] && continue
  ensemble "$cases/$name.toml" --out "$out/$name-sign" --set choices.face_friction=sign \
    --set 'title="element-test keys, former face friction rule (sign)"'
done
# Calibrate on the vertical cut (friction angles only), predict the others.
calibrated=vertical
"$soilcut" fit "$cases/$calibrated.toml" \
  --measured "validation/dem/results/cut_vertical${suffix}_mean.csv" \
  --free soil.friction.initial,soil.friction.peak,soil.friction.residual \
  --objective means:5 --evaluations 160 --polish 20 --profile-points 0 --jobs 2 \
  --quiet --force --out "$out/fit-vertical" >/dev/null
friction=$(python3 -c "import tomllib; f = tomllib.load(open('$out/fit-vertical/best.toml', 'rb'))['soil']['friction']; print('{ initial = %r, peak = %r, residual = %r }' % (f['initial'], f['peak'], f['residual']))")
echo "fitted on the vertical cut: soil.friction = $friction"
for name in vertical raked30 deep; do
  ensemble "$cases/$name.toml" --out "$out/$name-fitted" \
    --set "soil.friction=$friction" --set 'title="friction angles fitted to the vertical DEM cut"'
done
python3 validation/compare.py "$out" ${campaign:+--campaign "$campaign"}
[ "$campaign" = reference ] && exit
for name in vertical raked30 deep; do
  [ -f "validation/dem/results/cut_${name}${suffix}_mean.csv" ] || continue
  "$soilcut" compare "$out/$name/k+0" "$out/$name-sign/k+0" "$out/$name-fitted/k+0" \
    --measured "validation/dem/results/cut_${name}${suffix}_mean.csv" \
    --out "docs/img/validation_force_$name.png" >/dev/null
done
