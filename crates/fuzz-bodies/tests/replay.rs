//! The committed fuzz corpus, replayed on stable: every file of
//! `fuzz/corpus/<target>/` (minimised by `cargo fuzz cmin`) and of
//! `fuzz/regressions/<target>/` (each crash the fuzzer found, kept apart so
//! that no minimisation drops it) through its target's body, as
//! `cargo fuzz run` would feed it.

use soilcut_fuzz_bodies::{case_toml, ffi_calls, measured_csv, set_override, Outcome};
use std::collections::BTreeSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

fn inputs(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    files
}

/// Replays the corpus of `target` and returns the outcomes it reached.
fn replay(target: &str, body: fn(&[u8]) -> Outcome) -> BTreeSet<Outcome> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let corpus = inputs(&root.join("corpus").join(target));
    // A corpus lost or emptied would pass silently otherwise.
    assert!(corpus.len() >= 10, "{target}: only {} inputs", corpus.len());
    let regressions = root.join("regressions").join(target);
    let mut files = corpus;
    if regressions.exists() {
        files.extend(inputs(&regressions));
    }
    let mut reached = BTreeSet::new();
    let mut failed = Vec::new();
    for file in &files {
        let data = std::fs::read(file).unwrap();
        match catch_unwind(AssertUnwindSafe(|| body(&data))) {
            Ok(outcome) => {
                reached.insert(outcome);
            }
            Err(_) => failed.push(file.display().to_string()),
        }
    }
    assert!(failed.is_empty(), "{target}: failed on {failed:#?}");
    reached
}

// Each corpus reaches every stage of its body: a check no input reaches
// would pass without checking anything.

fn reaches(target: &str, body: fn(&[u8]) -> Outcome, stages: &[Outcome]) {
    let reached = replay(target, body);
    for stage in stages {
        assert!(reached.contains(stage), "no input {stage:?}: {reached:?}");
    }
}

#[test]
fn case_toml_corpus() {
    use Outcome::*;
    reaches(
        "case_toml",
        case_toml,
        &[Refused, Accepted, Created, Stepped],
    );
}

#[test]
fn set_override_corpus() {
    use Outcome::*;
    reaches("set_override", set_override, &[Refused, Created, Stepped]);
}

#[test]
fn measured_csv_corpus() {
    use Outcome::*;
    reaches("measured_csv", measured_csv, &[Refused, Accepted]);
}

#[test]
fn ffi_calls_corpus() {
    use Outcome::*;
    reaches(
        "ffi_calls",
        ffi_calls,
        &[Refused, Created, Stepped, Restored],
    );
}
