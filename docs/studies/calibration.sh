#!/bin/sh
# The calibration studies: one soil (Fig. 8b's loose sand with the truth
# φc = 22°, φp = 34°, up = 0.8; φr = 30°, ur = 2.0 fixed) cut at two depths,
# d = 25.4 and 38.1 mm, over 2 d at d/100. Each test's synthetic measured
# curve is 100 points with 2 % noise (seeds 1 and 2), weighted 1/P² (the
# noise is a fraction of the force). Fitted from
# (26.4°, 40.8°, 0.96): the shallow test alone, the deep test alone, and
# both at once. Writes docs/studies/calibration-{shallow,deep,two-depths}/
# and prints each fit's time.
# Usage: sh docs/studies/calibration.sh [path/to/soilcut] [extra fit options]
set -eu
soilcut=${1:-target/release/soilcut}
shift || true
here=docs/studies
case_dir=$here/calibration-cases
tmp=$(mktemp -d)
truth="--set soil.friction.initial=22 --set soil.friction.peak=34 --set soil.peak_shear=0.8"
seed=1
for depth in shallow deep; do
    # shellcheck disable=SC2086
    "$soilcut" run "$case_dir/$depth.toml" $truth --no-plots -q --out "$tmp/$depth"
    python3 "$here/synthetic_curve.py" "$tmp/$depth/history.csv" "$case_dir/$depth.synthetic.csv" \
        --points 100 --noise 0.02 --seed $seed --weights
    seed=$((seed + 1))
done
free=soil.friction.initial,soil.friction.peak,soil.peak_shear
# Each fit writes a fresh folder, which then replaces the study's (soilcut
# replaces only folders it marked as its own, and the committed ones carry
# no mark).
fit() {
    out=$1
    shift
    /usr/bin/time -f "$out: wall %e s, user %U s" "$soilcut" fit "$@" --free $free \
        --seed 1 --jobs 2 --quiet --out "$tmp/$out"
    rm -rf "${here:?}/$out"
    mv "$tmp/$out" "$here/$out"
    rm -f "$here/$out/.soilcut"
}
fit calibration-shallow "$case_dir/shallow.toml" --measured "$case_dir/shallow.synthetic.csv" "$@"
fit calibration-deep "$case_dir/deep.toml" --measured "$case_dir/deep.synthetic.csv" "$@"
fit calibration-two-depths "$case_dir/shallow.toml" --measured "$case_dir/shallow.synthetic.csv" \
    --also "$case_dir/deep.toml=$case_dir/deep.synthetic.csv" "$@"
rm -r "$tmp"
