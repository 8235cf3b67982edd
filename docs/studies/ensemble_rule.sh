#!/usr/bin/env bash
# Sourced by the studies that judge a case's defaults by the ensemble rule
# (docs/model.md §12.1): every_class.sh and default_families.sh. Needs
# $soilcut (the binary) and $runs (where the ensembles go) set.
#
# ensemble FOLDER CASE [ARGS]: 7 perturbed runs of CASE into FOLDER, unless
#   FOLDER/ensemble.csv exists (resumable); with JUDGE_ONLY=1 set, none
#   (it fails where they are missing, and the row says "pending").
# row NAME CLASS CASE [--set ...]: the reference ensemble (nodes every
#   increment, the exhaustive search, d/2000) in $runs/NAME/ref-d2000, the
#   ensemble at the defaults in $runs/NAME/defaults, and the table row of
#   `soilcut accuracy` of the second against the first.
# rows_head: the header of a table of such rows.

ensemble() { # folder, case file, extra arguments
  local folder=$1 file=$2
  shift 2
  [ -f "$folder/ensemble.csv" ] && return
  # JUDGE_ONLY=1: judge what has run, run nothing.
  [ -n "${JUDGE_ONLY:-}" ] && return 1
  nice -n 10 "$soilcut" run "$file" --ensemble 7 --jobs 1 "$@" --no-plots --quiet --force --out "$folder"
}

row() { # name, class, case file, extra --set arguments
  local name=$1 class=$2 file=$3
  shift 3
  local d v
  d=$(grep -m1 '^depth' "$file" | awk '{print $3}')
  v=$(python3 -c "print(repr($d / 2000))")
  if ! ensemble "$runs/$name/ref-d2000" "$file" "$@" --set run.ground=nodes \
    --set run.increment="$v" || ! ensemble "$runs/$name/defaults" "$file" "$@"; then
    echo "| $name | $class | not run yet | – | – | – | – | – | pending |"
    return
  fi
  local ground
  ground=$("$soilcut" check "$file" "$@" | tail -1 | sed -E 's/^ +//; s/\|/\\|/g')
  "$soilcut" accuracy "$runs/$name/defaults" "$runs/$name/ref-d2000" --json |
    python3 -c '
import csv, json, statistics, sys
name, klass, ground, runs = sys.argv[1:]
a = json.load(sys.stdin)
folder = f"{runs}/{name}"
ours = json.load(open(f"{folder}/defaults/summary.json"))["mean_force_norm"]
ref = json.load(open(f"{folder}/ref-d2000/summary.json"))["mean_force_norm"]
def wall(f):
    return statistics.median(float(r["wall_time_s"]) for r in csv.DictReader(open(f"{folder}/{f}/timing.csv")))
verdict = "yes" if a["accurate"] else "no"
ours_wall, ref_wall, worst = wall("defaults"), wall("ref-d2000"), a["worst_ratio"]
mean, sd, ref_mean, ref_sd = ours["mean"], ours["std"], ref["mean"], ref["std"]
print(f"| {name} | {klass} | {ground} | {ours_wall:.3f} | {mean:.4f} ± {sd:.4f} | {ref_wall:.1f} | {ref_mean:.4f} ± {ref_sd:.4f} | {worst:.2f} | {verdict} |")
' "$name" "$class" "$ground" "$runs"
}

rows_head() {
  echo "| case | class | defaults (\`soilcut check\`) | median wall time a member (s) | whole-run mean ± sd | reference's median wall time (s) | reference (d/2000) mean ± sd | worst deviation / tolerance | accurate |"
  echo "|---|---|---|---|---|---|---|---|---|"
}
