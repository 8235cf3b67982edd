#!/bin/sh
# The measured comparison of the global searches of `soilcut fit`,
# differential evolution (de) and CMA-ES (cmaes), on the synthetic recovery
# problems of the test suite (crates/study/tests/synthetic): truths 1 to 4
# (3 to 5 free keys of the refined case, 2 % noise, weighted 1/P², a start
# anywhere in the bounds), search seeds 1 to 3, budgets of 300 and 1000
# runs, d = 20 over 1 d at d/100. The search alone, without the polish and
# the profiles, each method at its default population, and CMA-ES with the
# population of differential evolution (cmaes-large). Writes
# docs/studies/calibration-methods/{runs.csv,summary.md} and prints the table.
# Usage: sh docs/studies/calibration_methods.sh [jobs]
set -eu
jobs=${1:-2}
cargo build --release -q -p soilcut-study --example calibration_methods
/usr/bin/time -f "wall %e s, user %U s" \
    "${CARGO_TARGET_DIR:-target}/release/examples/calibration_methods" \
    docs/studies/calibration-methods 1,2,3,4 1,2,3 300,1000 "$jobs" \
    run.travel=20 run.increment=0.2
