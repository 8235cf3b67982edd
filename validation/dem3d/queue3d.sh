#!/bin/sh
# The campaign's cuts one after another (one Yade process at a time), from the repository root:
#   nohup sh validation/dem3d/queue3d.sh W [W ...] > validation/dem3d/logs/queue.log 2>&1 &
# The bed (bed3d.py) must exist. Extra options: set OPTS, e.g. OPTS="--seed 15".
for w in "$@"; do
    nice -n 10 yade -n -j1 -x validation/dem3d/cut3d.py "$w" --dt-factor 0.7 $OPTS \
        > validation/dem3d/logs/cut3d_w${w}${OPTS:+_$(echo $OPTS | tr -d ' -')}.log 2>&1
done
