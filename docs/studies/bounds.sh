#!/bin/sh
# Is one shear band enough? soilcut's force beside the rigorous bounds of
# the ground as it stands (soilcut bounds, docs/model.md §18), for every
# paper case and the validation cases at u/d = 0, 0.25, 0.5, 1, 2, 3, 4
# (those within the case's travel) and at the increment where the band
# jumps furthest ahead, on the rigid floor with associated strength and
# with Davis's reduced strength, each on both strength fields (--field
# columns: each column its node's φ; slope: at least the slope it stands
# at). Writes docs/studies/bounds/results.csv (one row per case, instant,
# strength and field: the columns of bounds.csv after case, strength,
# field; lower_status and upper_status from bounds.json last) and prints it
# as a Markdown table.
# Usage: sh docs/studies/bounds.sh [path/to/soilcut] [mesh N, default 8]
set -eu
soilcut=${1:-target/release/soilcut}
mesh=${2:-8}
dir=docs/studies/bounds
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$dir"
header=""
rows="$tmp/rows.csv"
: > "$rows"

# u/d of the increment whose band emerges furthest ahead of the previous one's.
furthest_jump() {
  "$soilcut" run "$1" --quiet --no-plots --out "$tmp/run" --force >/dev/null
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { x = $c["x_emergence"]; if (NR > 2 && x - last > best) { best = x - last; at = $c["u_over_d"] } last = x }
    END { print at }' "$tmp/run/history.csv"
}

for case in cases/paper/original.toml cases/paper/fig5.toml cases/paper/table1-hs.toml \
  cases/paper/table1-s.toml cases/paper/fig8b.toml cases/validation/vertical.toml \
  cases/validation/deep.toml cases/validation/raked30.toml; do
  name=$(basename "$case" .toml)
  travel=$(awk -F'[=#]' '/^travel/ { gsub(/ /, "", $2); print $2 }' "$case")
  depth=$(awk -F'[=#]' '/^depth/ { gsub(/ /, "", $2); print $2; exit }' "$case")
  jump=$(furthest_jump "$case")
  for at in 0 0.25 0.5 1 2 3 4 "$jump"; do
    inside=$(awk -v a="$at" -v t="$travel" -v d="$depth" 'BEGIN { print (a * d <= t) ? 1 : 0 }')
    [ "$inside" = 1 ] || continue
    for field in columns slope; do
      for strength in associated davis; do
        "$soilcut" bounds "$case" --at "$at" --mesh "$mesh" --strength "$strength" --field "$field" \
          --out "$tmp/b" --force >/dev/null 2>&1 || { echo "$name u/d=$at $strength $field: failed" >&2; continue; }
        header=$(head -1 "$tmp/b/bounds.csv")
        status=$(awk -F'"' '/"lower_status"/ { lo = $4 } /"upper_status"/ { up = $4 } END { print lo "," up }' "$tmp/b/bounds.json")
        tail -n +2 "$tmp/b/bounds.csv" | sed "s/^/$name,$strength,$field,/; s/\$/,$status/" >> "$rows"
      done
    done
  done
done
{ echo "case,strength,field,$header,lower_status,upper_status"; cat "$rows"; } > "$dir/results.csv"

awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i;
    print "| case | strength | field | u/d | lower | upper | soilcut | soilcut/lower | soilcut/upper | ± | triangles | s |";
    print "|---|---|---|---|---|---|---|---|---|---|---|---|"; next }
  { printf "| %s | %s | %s | %.3f | %.1f | %.1f | %.1f | %.3f | %.3f | %.1f %% | %d | %.1f |\n",
      $c["case"], $c["strength"], $c["field"], $c["u_over_d"], $c["lower"], $c["upper"], $c["soilcut"],
      $c["soilcut_over_lower"], $c["soilcut_over_upper"], 100 * $c["half_width"], $c["triangles"],
      $c["lower_seconds"] + $c["upper_seconds"] }' "$dir/results.csv"
