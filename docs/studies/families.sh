#!/usr/bin/env bash
# Each class's defaults over a family of cases of that class (issue 50,
# item 8): a default is a claim about its class, so it must hold with
# margin on several soils, rakes, bins, depth paths, widths and face
# frictions, not on the one case it was chosen on. Every row is judged as
# in every_class.sh (an ensemble of 7 at the defaults against the
# reference grid's ensemble at d/2000, docs/model.md §12.1); a class holds
# with margin when every row of its family deviates by at most MARGIN
# (0.8) of its tolerance in every unit window. The second table judges,
# against the same references, other ensembles of the failing rows: finer
# vertex grounds, the node grid at d/1500, and the reference grid itself
# with d50 1 % larger (a change the physics cannot tell from none).
#
#   bash docs/studies/families.sh SOILCUT RUNS
#
# SOILCUT the binary, RUNS where the ensembles go (resumable: a finished
# ensemble is judged again, not rerun; JUDGE_ONLY=1 judges what has run and
# marks the rest pending). A row whose runs are not in RUNS but which
# families.md already judges keeps its line, so the study resumes on another
# machine; delete a line to have its row run again. Writes
# docs/studies/every-class/families.md. About five hours of one core, most
# of it the reference ensembles.
set -euo pipefail
cd "$(dirname "$0")/../.."
soilcut=$1 runs=$2
out=docs/studies/every-class/families.md
margin=0.8
mkdir -p "$runs" "$(dirname "$out")"

# shellcheck source=docs/studies/ensemble_rule.sh
source docs/studies/ensemble_rule.sh

# kept NAME SECOND: the judged line of families.md whose first two cells are
# NAME and SECOND, when RUNS has no runs of NAME.
kept() {
  [ -f "$out" ] && [ ! -d "$runs/$1" ] || return 1
  grep -m1 -F "| $1 | $2 |" "$out" | grep -v pending
}

# family_row: row, or its line kept from families.md.
family_row() { kept "$1" "$2" || row "$@"; }

# against NAME TAG CASE [ARGS]: an ensemble of CASE with ARGS, judged
# against NAME's reference ensemble.
against() {
  local name=$1 tag=$2 file=$3
  shift 3
  kept "$name" "$tag" && return
  if ! ensemble "$runs/$name/$tag" "$file" "$@"; then
    echo "| $name | $tag | \`$*\` | not run yet | pending |"
    return
  fi
  "$soilcut" accuracy "$runs/$name/$tag" "$runs/$name/ref-d2000" --json |
    python3 -c '
import json, sys
a = json.load(sys.stdin)
name, tag, args = sys.argv[1:]
windows = ", ".join("%+.2f %%" % (w["deviation"] * 100) for w in a["windows"])
print("| %s | %s | `%s` | %s | %.2f |" % (name, tag, args, windows, a["worst_ratio"]))
' "$name" "$tag" "$*"
}

s=cases/paper/table1-s.toml hs=cases/paper/table1-hs.toml f5=cases/paper/fig5.toml
f8=cases/paper/fig8b.toml vv=cases/validation/vertical.toml vd=cases/validation/deep.toml
o=cases/paper/original.toml sc=cases/tools/scoop.toml dp=cases/tools/deepening.toml
never=(--set soil.friction.residual=40 --set soil.dilation.residual=10)
{
  rows_head
  family_row table1-s "softening, vertical" "$s"
  family_row table1-s-d50-0.3 "softening, vertical" "$s" --set soil.d50=0.3
  family_row table1-hs "softening, vertical" "$hs"
  family_row table1-hs-wall15 "softening, vertical" "$hs" --set blade.wall_friction=15
  family_row fig5 "softening, vertical" "$f5"
  family_row fig5-wall15 "softening, vertical" "$f5" --set blade.wall_friction=15
  family_row fig5-rake45 "softening, raked" "$f5" --set blade.rake=45
  family_row fig5-rake60 "softening, raked" "$f5" --set blade.rake=60
  family_row fig5-rake75 "softening, raked" "$f5" --set blade.rake=75
  family_row table1-s-rake45 "softening, raked" "$s" --set blade.rake=45
  family_row table1-s-rake60 "softening, raked" "$s" --set blade.rake=60
  family_row table1-hs-rake60 "softening, raked" "$hs" --set blade.rake=60
  family_row fig5-bin8 "softening, bin" "$f5" --set bin.length=160
  family_row fig5-bin10 "softening, bin" "$f5" --set bin.length=200
  family_row table1-s-bin6-travel3 "softening, bin" "$s" --set bin.length=120 --set run.travel=60
  family_row table1-hs-bin8 "softening, bin" "$hs" --set bin.length=160
  family_row validation-vertical "softening, bin" "$vv"
  family_row validation-deep "softening, bin" "$vd"
  family_row fig8b "never softening" "$f8"
  family_row fig8b-rake45 "never softening" "$f8" --set blade.rake=45
  family_row fig8b-rake60 "never softening" "$f8" --set blade.rake=60
  family_row fig8b-rake75 "never softening" "$f8" --set blade.rake=75
  family_row fig5-never "never softening" "$f5" "${never[@]}"
  family_row table1-hs-never "never softening" "$hs" --set soil.friction.residual=35
  family_row original "original model" "$o"
  family_row original-rake60 "original model" "$o" --set blade.rake=60
  family_row original-phi40 "original model" "$o" --set soil.friction.peak=40 --set soil.friction.residual=34
  family_row original-bin8 "original model" "$o" --set bin.length=160
  family_row original-bin10 "original model" "$o" --set bin.length=200
  family_row original-phi40-bin8 "original model" "$o" --set soil.friction.peak=40 --set soil.friction.residual=34 --set bin.length=160
  family_row original-bin7-travel4 "original model" "$o" --set bin.length=140 --set run.travel=80
  family_row tine "original model" cases/tools/tine.toml
  family_row dozer "original model" cases/tools/dozer.toml
  family_row scoop "depth path" "$sc"
  family_row scoop-wall15 "depth path" "$sc" --set blade.wall_friction=15
  family_row deepening "depth path" "$dp"
  family_row deepening-phi40 "depth path" "$dp" --set soil.friction.peak=40 --set soil.friction.residual=34
  family_row fig5-rising "depth path" "$f5" --set 'blade.depth_path=[[0.0, 20.0], [50.0, 12.0]]'
  family_row table1-s-deepening "depth path" "$s" --set 'blade.depth_path=[[0.0, 8.0], [60.0, 20.0]]'
  family_row fig5-w20 "finite width" "$f5" --set blade.width=20
  family_row fig5-w40 "finite width" "$f5" --set blade.width=40
  family_row fig5-w80 "finite width" "$f5" --set blade.width=80
  family_row table1-s-w40 "finite width" "$s" --set blade.width=40
  family_row table1-hs-w40 "finite width" "$hs" --set blade.width=40
  family_row fig8b-w40 "finite width" "$f8" --set blade.width=40
} > "$out.rows"
{
  echo "# Each class's defaults over a family of cases"
  echo
  echo "Made by \`bash docs/studies/families.sh SOILCUT RUNS\` (see README.md)."
  echo
  cat "$out.rows"
  echo
  echo "| class | rows judged | rows pending | worst deviation / tolerance (row) | holds with margin (≤ $margin) |"
  echo "|---|---|---|---|---|"
  awk -F' \\| ' -v margin="$margin" 'NR > 2 && NF > 8 {
      c = $2; if (!(c in order)) { order[c] = ++k; name[k] = c; n[c] = 0; p[c] = 0 }
      if ($9 ~ /pending/) { p[c]++; next }
      n[c]++; if (!(c in w) || $8 + 0 > w[c]) { w[c] = $8 + 0; at[c] = $1 } }
    END { for (i = 1; i <= k; i++) { c = name[i]; sub(/^\| /, "", at[c])
      if (!n[c]) { printf "| %s | 0 | %d | – | pending |\n", c, p[c]; continue }
      verdict = w[c] <= margin ? (p[c] ? "so far" : "yes") : "no"
      printf "| %s | %d | %d | %.2f (%s) | %s |\n", c, n[c], p[c], w[c], at[c], verdict } }' "$out.rows"
  echo
  echo "Other ensembles of the failing rows against the same references (deviation of each unit window's mean):"
  echo
  echo "| case | ensemble | overrides | deviation per unit window | worst / tolerance |"
  echo "|---|---|---|---|---|"
  against fig5-bin10 h100v700 "$f5" --set bin.length=200 --set run.vertex_spacing=0.2 --set run.increment=0.028571428571428571
  against fig5-bin10 h400v2000 "$f5" --set bin.length=200 --set run.vertex_spacing=0.05 --set run.increment=0.01
  against fig5-bin10 n1500 "$f5" --set bin.length=200 --set run.ground=nodes --set run.increment=0.013333333333333334
  against fig5-bin10 ref-d50p1 "$f5" --set bin.length=200 --set run.ground=nodes --set run.increment=0.01 --set soil.d50=0.606
  against fig5-wall15 ref-d50p1 "$f5" --set blade.wall_friction=15 --set run.ground=nodes --set run.increment=0.01 --set soil.d50=0.606
  against table1-s-d50-0.3 h100 "$s" --set soil.d50=0.3 --set run.vertex_spacing=0.2
  against table1-s-d50-0.3 h200 "$s" --set soil.d50=0.3 --set run.vertex_spacing=0.1
  against fig5-w20 h100 "$f5" --set blade.width=20 --set run.vertex_spacing=0.2
  against fig5-w20 h200v700 "$f5" --set blade.width=20 --set run.vertex_spacing=0.1 --set run.increment=0.028571428571428571
  against original-bin8 h50v250 "$o" --set bin.length=160 --set run.vertex_spacing=0.4 --set run.increment=0.08
  against original-bin8 v1000 "$o" --set bin.length=160 --set run.increment=0.02
  against original-bin8 h400v2000 "$o" --set bin.length=160 --set run.vertex_spacing=0.05 --set run.increment=0.01
  against original-bin8 n1500 "$o" --set bin.length=160 --set run.ground=nodes --set run.increment=0.013333333333333334
} > "$out.new"
rm "$out.rows"
mv "$out.new" "$out"
cat "$out"
