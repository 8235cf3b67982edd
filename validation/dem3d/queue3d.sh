#!/bin/sh
# The whole 3D campaign, one Yade process at a time, from the repository root:
#   nohup sh validation/dem3d/queue3d.sh > queue3d.log 2>&1 &
# then: /usr/bin/python3 validation/dem3d/summarise3d.py
# SEED=15 sh validation/dem3d/queue3d.sh 1   reruns only w/d = 1 in the bed of seed 15.
SEED=${SEED:-14}
WIDTHS=${*:-3 1}
L=validation/dem3d/logs
HERE=$(dirname "$0")
[ -f "$HERE/beds/bed3d_r5_s$SEED.yade.gz" ] ||
    nice -n 10 yade -n -j1 -x validation/dem3d/bed3d.py --seed $SEED > $L/bed3d_r5_s$SEED.log 2>&1
for w in $WIDTHS; do
    case $w in
        1) opts="--dt-factor 0.8 --half-width 3.5" ;;  # half-bin w/2 + 3 d; the larger step for time
        *) opts="--dt-factor 0.7" ;;
    esac
    nice -n 10 yade -n -j1 -x validation/dem3d/cut3d.py $w --seed $SEED $opts \
        > $L/cut3d_w${w}_s$SEED.log 2>&1
done
