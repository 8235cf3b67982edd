#!/usr/bin/env bash
# Every DEM run of the validation, one after another on one core, into
# results/ (logs in results/*.log). About 1 to 2 hours in all on an idle
# core (bed 3 min, biaxial 5 min, repose 5 min, each cut 15 to 30 min).
#   bash validation/dem/run_all.sh
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p results
yade --version > results/yade_version.txt
run() { yade -n -j1 -x "$@" > "results/${1%.py}${2:+_$2}.log" 2>&1; }
run bed.py
run biaxial.py
run cut.py vertical
run repose.py
run cut.py raked30
run cut.py deep
