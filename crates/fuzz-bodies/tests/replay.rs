//! The committed fuzz corpus, replayed on stable: every file of
//! `fuzz/corpus/<target>/` through its target's body, as `cargo fuzz run`
//! would feed it. Each crash the fuzzer found is in the corpus, so this
//! guards its fix.

use soilcut_fuzz_bodies::{case_toml, measured_csv, set_override, Outcome};
use std::collections::BTreeSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// Replays the corpus of `target` and returns the outcomes it reached.
fn replay(target: &str, body: fn(&[u8]) -> Outcome) -> BTreeSet<Outcome> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz/corpus")
        .join(target);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    // A corpus lost or emptied would pass silently otherwise.
    assert!(files.len() >= 10, "{target}: only {} inputs", files.len());
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
