//! The committed fuzz corpus, replayed on stable: every file of
//! `fuzz/corpus/<target>/` (minimised by `cargo fuzz cmin`) and of
//! `fuzz/regressions/<target>/` (each crash the fuzzer found, kept apart so
//! that no minimisation drops it) through its target's body, as
//! `cargo fuzz run` would feed it.

use soilcut_fuzz_bodies::{case_toml, measured_csv, set_override, Outcome};
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

#[test]
fn case_toml_corpus() {
    let reached = replay("case_toml", case_toml);
    for stage in [
        Outcome::Refused,
        Outcome::Accepted,
        Outcome::Created,
        Outcome::Stepped,
    ] {
        assert!(reached.contains(&stage), "no input {stage:?}: {reached:?}");
    }
}

#[test]
fn set_override_corpus() {
    let reached = replay("set_override", set_override);
    for stage in [Outcome::Refused, Outcome::Created, Outcome::Stepped] {
        assert!(reached.contains(&stage), "no input {stage:?}: {reached:?}");
    }
}

#[test]
fn measured_csv_corpus() {
    let reached = replay("measured_csv", measured_csv);
    for stage in [Outcome::Refused, Outcome::Accepted] {
        assert!(reached.contains(&stage), "no input {stage:?}: {reached:?}");
    }
}
