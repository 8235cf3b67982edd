#!/usr/bin/env bash
# The vertex ground (issue 28, docs/model.md §1.2, §2.12) judged by the ensemble rule:
# for each paper case it supports, ensembles of 7 (`soilcut run --ensemble 7`)
# under the explicit rule at increments d/250, d/500 and d/1250 with
# vertices d/50 apart, and Fig. 5 and Table 1 HS at d/1250 with vertices
# d/25 and d/100 apart and at d/2500 with vertices d/50 apart; then under
# the midpoint force (`run.time_scheme`) the refined cases at d/250 to
# d/1250 with vertices d/50 apart, and the softening ones at d/300 and the
# default d/350 with vertices d/25 and d/100 apart; each against
# the reference grid's ensemble at d/2000 of docs/studies/ensemble-accuracy/
# (made by ensemble_accuracy.py into its --runs folder).
#
#   bash docs/studies/vertex_ground.sh SOILCUT RUNS REFERENCE_RUNS
#
# SOILCUT the binary, RUNS where the ensembles go (resumable: an ensemble
# whose summary.json exists is judged again, not rerun), REFERENCE_RUNS the
# ensemble-accuracy runs (CASE/ref-d2000). Writes
# docs/studies/vertex-ground/table.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
soilcut=$1 runs=$2 reference=$3
out=docs/studies/vertex-ground/table.md
mkdir -p "$runs" "$(dirname "$out")"

row() { # case, time scheme, increments per depth, vertex spacings per depth
  local case=$1 scheme=$2 per_v=$3 per_h=$4
  local d
  d=$(grep -m1 '^depth' "cases/paper/$case.toml" | awk '{print $3}')
  local v h folder=$runs/$case/$scheme-v$per_v-h$per_h
  v=$(python3 -c "print($d / $per_v)")
  h=$(python3 -c "print($d / $per_h)")
  if [ ! -f "$folder/summary.json" ]; then
    nice -n 10 "$soilcut" run "cases/paper/$case.toml" --ensemble 7 --jobs 1 \
      --set run.increment="$v" --set run.vertex_spacing="$h" \
      --set run.time_scheme="$scheme" --out "$folder" --force -q
  fi
  "$soilcut" accuracy "$folder" "$reference/$case/ref-d2000" --json |
    python3 -c '
import csv, json, statistics, sys
case, scheme, per_v, per_h, folder = sys.argv[1:]
a = json.load(sys.stdin)
s = json.load(open(folder + "/summary.json"))["mean_force_norm"]
rows = list(csv.DictReader(open(folder + "/timing.csv")))
wall = statistics.median(float(r["wall_time_s"]) for r in rows)
verdict = "yes" if a["accurate"] else "no"
mean, sd, worst = s["mean"], s["std"], a["worst_ratio"]
print(f"| {case} | {scheme} | d/{per_v} | d/{per_h} | {wall:.3f} | {mean:.4f} ± {sd:.4f} | {worst:.2f} | {verdict} |")
' "$case" "$scheme" "$per_v" "$per_h" "$folder"
}

{
  echo "| case | time scheme | increment | vertex spacing | median wall time a member (s) | whole-run mean ± sd | worst deviation / tolerance | accurate |"
  echo "|---|---|---|---|---|---|---|---|"
  for case in original table1-s fig8b table1-hs fig5; do
    for per_v in 250 500 1250; do row "$case" explicit "$per_v" 50; done
  done
  for case in table1-hs fig5; do
    for per_h in 25 100; do row "$case" explicit 1250 "$per_h"; done
    row "$case" explicit 2500 50
  done
  for case in table1-s fig8b table1-hs fig5; do
    for per_v in 250 300 350 400 500 1250; do row "$case" midpoint-force "$per_v" 50; done
  done
  for case in table1-s table1-hs fig5; do
    for per_v in 300 350; do
      for per_h in 25 100; do row "$case" midpoint-force "$per_v" "$per_h"; done
    done
  done
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
