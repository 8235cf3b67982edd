#!/usr/bin/env bash
# The fuzzing campaign (docs/fuzzing.md), one target at a time, niced:
#
#   fuzz/campaign.sh SECONDS [TARGET...]    # default: every target
#
# Each target runs for SECONDS from the committed corpus (fuzz/corpus/),
# adding what it finds to a working copy (work/<target> here, ignored by
# git); the working copy is then minimised (cargo fuzz cmin) back into the
# committed corpus, which is what to commit. A crash stops its target: the
# input is in artifacts/<target>/ here and the log in logs/<target>.log.
# Inputs that crashed once are in fuzz/regressions/, which the run reads
# too but which no minimisation touches (cmin renames and drops files).
# The figures for docs/fuzzing.md are the last lines of each log
# (stat::number_of_executed_units, cov, ft, corp). Needs nightly and
# cargo-fuzz (cargo install cargo-fuzz).
set -uo pipefail
cd "$(dirname "$0")"

seconds="${1:?usage: fuzz/campaign.sh SECONDS [TARGET...]}"
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(case_toml set_override measured_csv ffi_calls)
# Several jobs or workers would compete with everything else on the
# machine: one process, niced. -timeout: an input slower than 10 s is a
# finding (the bodies bound the model's cost); -rss_limit_mb: libFuzzer's
# default, stated.
# No sanitizer by default: the code fuzzed is safe Rust (and the parsers'
# own fuzzing covers their unsafe), and AddressSanitizer would halve the
# executions; FUZZ_SANITIZER=address to use it.
build=(-s "${FUZZ_SANITIZER:-none}")
flags=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1)

mkdir -p logs work
status=0
for t in "${targets[@]}"; do
    rm -rf "work/$t"
    cp -r "corpus/$t" "work/$t"
    # The schema's words (keys, names, separators): from raw bytes alone
    # the fuzzer rarely spells a valid key and gets little past the parser.
    dict=()
    [ -f "dicts/$t.dict" ] && dict=(-dict="dicts/$t.dict")
    echo "== $t: ${seconds} s ($(date -u +%FT%TZ))"
    extra=()
    [ -d "regressions/$t" ] && extra=("regressions/$t")
    if nice -n 10 cargo +nightly fuzz run "${build[@]}" "$t" "work/$t" "${extra[@]}" -- "${flags[@]}" "${dict[@]}" >"logs/$t.log" 2>&1; then
        before=$(ls "corpus/$t" | wc -l)
        # By edges only (-use_counters=0): the same edges as by hit
        # counts, in a quarter of the files (2 827 to 710 for case_toml).
        nice -n 10 cargo +nightly fuzz cmin "${build[@]}" "$t" "work/$t" -- -use_counters=0 \
            >>"logs/$t.log" 2>&1
        rm -rf "corpus/$t"
        cp -r "work/$t" "corpus/$t"
        echo "   no crash; corpus $before -> $(ls "corpus/$t" | wc -l) files, $(cat "corpus/$t"/* | wc -c) bytes"
    else
        status=1
        echo "   CRASH (or error): see logs/$t.log and artifacts/$t/ in fuzz/"
    fi
    grep -E "^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)|^#[0-9]+.*DONE" "logs/$t.log" | sed 's/^/   /'
done
exit $status
