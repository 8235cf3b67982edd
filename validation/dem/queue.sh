#!/usr/bin/env bash
# Runs DEM jobs one after another on one core, each line of a job list a
# script and its options (e.g. "cut.py vertical --seed 15"), logs in logs/,
# skipping jobs whose log ends with a finished run (a bed: whose state file
# beds/bed_TAG.yade.gz is here), niced (nice -n 19: the lowest priority,
# the machine's other work first), each
# log appended to (a cut with --checkpoint T --resume continues from its last
# checkpoint when the queue is started again). Two queues may run side by
# side (one core each) if their beds are made before their cuts.
#   bash validation/dem/queue.sh JOBS_FILE   (from any folder)
set -uo pipefail
jobs="$(realpath "$1")"  # the list, from where the queue is started
cd "$(dirname "$0")"
mkdir -p logs results
yade --version > results/yade_version.txt 2>/dev/null || true
while read -r script args; do
  [ -z "$script" ] || [ "${script:0:1}" = "#" ] && continue
  log="logs/${script%.py}_$(echo "$args" | tr -s ' -' '_' | sed 's/^_//').log"
  if [ "$script" = bed.py ]; then
    # a bed is made unless its state file is here (beds/ is not committed)
    seed=14 ratio=10 slab="" short="" long=""
    set -- $args
    while [ $# -gt 0 ]; do
      case "$1" in
        --seed) seed=$2; shift ;;
        --ratio) ratio=$2; shift ;;
        --slab) slab="_slab$2"; shift ;;
        --short) short="_short" ;;
        --long) long="_long" ;;
      esac
      shift
    done
    [ -f "beds/bed_r${ratio}_s${seed}${slab}${short}${long}.yade.gz" ] && continue
  elif [ -f "$log" ] && grep -q '"wall_time_s"' "$log"; then
    continue
  fi
  echo "$(date +%T) start $script $args" >> logs/queue.log
  nice -n 19 yade -n -j1 -x "$script" $args >> "$log" 2>&1
  echo "$(date +%T) end $script $args rc=$?" >> logs/queue.log
done < "$jobs"
