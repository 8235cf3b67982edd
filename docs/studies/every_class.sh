#!/usr/bin/env bash
# Every class of case at its shipped defaults, judged by the ensemble rule
# (docs/model.md §12.1) against a reference ensemble of its own (issue 38):
# for each case below, an ensemble of 7 perturbed runs on the reference
# grid (nodes every increment, the exhaustive search, d/2000) and one at
# the defaults its class resolves to (`soilcut check` names them), then
# `soilcut accuracy` of the second against the first.
#
#   bash docs/studies/every_class.sh SOILCUT RUNS
#
# SOILCUT the binary, RUNS where the ensembles go (resumable: an ensemble
# whose ensemble.csv exists is judged again, not rerun: NAME/ref-d2000 and
# NAME/defaults; a row whose reference is another row's may link its
# ref-d2000 to it). Writes docs/studies/every-class/table.md. The reference
# ensembles are the long part (about 1-10 minutes of one core each).
set -euo pipefail
cd "$(dirname "$0")/../.."
soilcut=$1 runs=$2
out=docs/studies/every-class/table.md
mkdir -p "$runs" "$(dirname "$out")"

# shellcheck source=docs/studies/ensemble_rule.sh
source docs/studies/ensemble_rule.sh

{
  rows_head
  row table1-s "refined, softening" cases/paper/table1-s.toml
  row table1-hs "refined, hardening-softening" cases/paper/table1-hs.toml
  row fig5 "refined, hardening-softening" cases/paper/fig5.toml
  row fig8b "refined, never softening" cases/paper/fig8b.toml
  row fig8b-rake60 "refined, never softening, raked (Fig. 8b, α = 60°)" cases/paper/fig8b.toml --set blade.rake=60
  row fig8b-vertices-explicit "never softening on vertices d/25, explicit (not the default: slower)" cases/paper/fig8b.toml --set 'run.time_scheme="explicit"'
  row fig5-bin "soil bin (Fig. 5 with bin.length = 8 d)" cases/paper/fig5.toml --set bin.length=160
  row validation-vertical "soil bin (DEM's, 10 d)" cases/validation/vertical.toml
  row validation-deep "soil bin (DEM's, 8 d)" cases/validation/deep.toml
  row scoop "depth path (the scoop)" cases/tools/scoop.toml
  row fig5-rake60 "raked blade (Fig. 5, α = 60°)" cases/paper/fig5.toml --set blade.rake=60
  row fig5-w40 "finite width (Fig. 5, w = 40 mm)" cases/paper/fig5.toml --set blade.width=40
  row original "original model" cases/paper/original.toml
  row tine "original model, finite width (the tine)" cases/tools/tine.toml
  row dozer "original model, finite width (the dozer)" cases/tools/dozer.toml
  row original-nonsoftening "original model, never softening (φr = φp; on vertices d/25 since issue 49)" cases/paper/original.toml --set soil.friction.residual=35
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
