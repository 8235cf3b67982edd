#!/bin/sh
# The calibration example of issue 12: a synthetic measured curve from
# Fig. 8b over 2 d (truth φc = 22°, φp = 34°, up = 0.8 with φr = 30°,
# ur = 2.0), 100 points with 2 % noise, fitted from (26.4°, 40.8°, 0.96)
# with --seed 1 on 2 threads. Writes docs/studies/calibration-fig8b-<increment>/
# and its synthetic curve calibration-fig8b-<increment>.synthetic.csv (the
# fit's --measured).
# Usage: [INCREMENT=0.254] sh docs/studies/calibration-fig8b.sh [path/to/soilcut] [extra fit options]
# (INCREMENT: run.increment of truth and fit; default the case's d/500;
# the folder is then calibration-fig8b-<INCREMENT>).
set -eu
soilcut=${1:-target/release/soilcut}
shift || true
increment=${INCREMENT:-0.0508}
out=calibration-fig8b
[ "$increment" = 0.0508 ] || out=calibration-fig8b-$increment
here=docs/studies
tmp=$(mktemp -d)
truth="--set soil.friction.initial=22 --set soil.friction.peak=34 --set soil.peak_shear=0.8"
fixed="--set soil.friction.residual=30 --set soil.residual_shear=2.0 --set run.travel=50.8 --set run.increment=$increment"
# shellcheck disable=SC2086
"$soilcut" run cases/paper/fig8b.toml $truth $fixed --no-plots -q --out "$tmp/truth"
python3 "$here/synthetic_curve.py" "$tmp/truth/history.csv" "$here/$out.synthetic.csv" \
    --points 100 --noise 0.02 --seed 1
# shellcheck disable=SC2086
/usr/bin/time -f "wall %e s, user %U s" "$soilcut" fit cases/paper/fig8b.toml \
    --measured "$here/$out.synthetic.csv" $fixed \
    --set soil.friction.initial=26.4 --set soil.friction.peak=40.8 --set soil.peak_shear=0.96 \
    --free soil.friction.initial,soil.friction.peak,soil.peak_shear \
    --seed 1 --jobs 2 --quiet --out "$tmp/$out" "$@"
# The fresh folder replaces the study's (soilcut replaces only folders it
# marked as its own, and the committed one carries no mark).
rm -rf "${here:?}/$out"
mv "$tmp/$out" "$here/$out"
rm -f "$here/$out/.soilcut"
rm -r "$tmp"
