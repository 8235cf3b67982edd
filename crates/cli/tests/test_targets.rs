//! Every crate whose integration tests are one binary (`autotests = false`
//! and `tests/main.rs`, one link instead of one a file) declares every file
//! and folder of its `tests/` as a module of `tests/main.rs`: cargo no
//! longer finds them itself, and a file left out would never run.

use std::fs;
use std::path::Path;

/// The modules a `tests/` folder holds: `name.rs` files but `main.rs`, and
/// folders with a `mod.rs`.
fn modules(tests: &Path) -> Vec<String> {
    let mut names = Vec::new();
    for entry in fs::read_dir(tests).expect("tests/") {
        let path = entry.expect("an entry").path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let is_file = path.extension().is_some_and(|e| e == "rs") && stem != "main";
        if is_file || path.join("mod.rs").is_file() {
            names.push(stem);
        }
    }
    names.sort();
    names
}

#[test]
fn every_test_file_is_a_module_of_its_crates_test_binary() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut merged = 0;
    let mut missing = Vec::new();
    for entry in fs::read_dir(&crates).expect("crates/") {
        let dir = entry.expect("an entry").path();
        let Ok(manifest) = fs::read_to_string(dir.join("Cargo.toml")) else {
            continue;
        };
        if !manifest.contains("autotests = false") {
            continue;
        }
        merged += 1;
        let main = fs::read_to_string(dir.join("tests/main.rs")).expect("tests/main.rs");
        for module in modules(&dir.join("tests")) {
            if !main.lines().any(|l| l == format!("mod {module};")) {
                missing.push(format!("{}: tests/{module}", dir.display()));
            }
        }
    }
    assert!(merged >= 6, "only {merged} crates with one test binary");
    assert!(
        missing.is_empty(),
        "not in tests/main.rs:\n{}",
        missing.join("\n")
    );
}
