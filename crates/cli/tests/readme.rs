//! What a new user meets first, kept as it should be (issue 29): the
//! README's shell examples run as written and in order, the default build
//! is the command line's, and `scripts/test` says what it is doing.
//!
//! Every line of every `sh` block of README.md and of the user guide's
//! chapters ([`documents`]: docs/guide/, in its table of contents' order;
//! continuations joined, comments dropped) is one of:
//!
//! 1. `soilcut ARGS` or `cargo run --release -- ARGS`: run with the
//!    release build `scripts/test` names in `SOILCUT_BIN` (about 2 minutes
//!    on two cores; this test build's `soilcut` without it, several times
//!    slower), from a temporary folder that holds a copy of
//!    `cases/` (the outputs land there, never in the repository), in the
//!    order of the README; it must succeed;
//! 2. a build, install or test step ([`BUILD_STEPS`]): not run here, CI
//!    runs each itself (`.ci/run`, `scripts/test`, the C ABI's example
//!    test `crates/ffi/tests/examples.rs`), and `soilcut` stands for what
//!    `cargo install` puts on the PATH;
//! 3. Python (`python -c`): `python/tests/test_readme.py` runs it, with the
//!    README's `python` blocks.
//!
//! Any other line fails the test: a new kind of example must say here how
//! it is checked.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The lines that build, install or test, by their start.
const BUILD_STEPS: &[&str] = &[
    "cargo install ",
    "cargo build ",
    "cargo bench ",
    "cargo doc ",
    "./scripts/test",
    "./scripts/guide",
    "pip install ",
    "python3 -m venv ",
    ".venv/bin/python docs/scripts/",
    "cc ",
    "c++ ",
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The text of the README, then of the user guide's chapters in the order
/// of docs/guide/index.md's table of contents (its entries in docs/guide/;
/// the documents beside the guide, as `/model`, have no examples to run).
pub fn documents() -> String {
    let guide = root().join("docs/guide");
    let index = std::fs::read_to_string(guide.join("index.md")).unwrap();
    let chapters = index
        .split("```{toctree}")
        .nth(1)
        .and_then(|t| t.split("```").next())
        .expect("a toctree in docs/guide/index.md");
    let mut text = std::fs::read_to_string(root().join("README.md")).unwrap();
    for entry in chapters.lines().map(str::trim) {
        if entry.is_empty() || entry.starts_with([':', '/']) {
            continue;
        }
        let chapter = guide.join(format!("{entry}.md"));
        text.push('\n');
        text.push_str(&std::fs::read_to_string(&chapter).unwrap());
    }
    text
}

/// The commands of the README's `sh` blocks, in order: continuation lines
/// joined, comments and blank lines dropped.
fn shell_lines(readme: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut inside = false;
    let mut pending = String::new();
    for line in readme.lines() {
        let fence = line.trim_start();
        if fence.starts_with("```") {
            inside = fence == "```sh";
            continue;
        }
        if !inside {
            continue;
        }
        let code = line.split(" #").next().unwrap_or("").trim();
        if code.starts_with('#') || (code.is_empty() && pending.is_empty()) {
            continue;
        }
        match code.strip_suffix('\\') {
            Some(start) => pending.push_str(start),
            None => {
                pending.push_str(code);
                lines.push(std::mem::take(&mut pending).trim().to_string());
            }
        }
    }
    lines
}

/// A command line's words (no quoting is used by the examples it runs).
fn words(line: &str) -> Vec<&str> {
    assert!(!line.contains(['"', '\'', '$', '|', '&', ';']), "{line}");
    line.split_whitespace().collect()
}

/// The arguments of `soilcut` for a line it runs, or `None` for a build step.
fn soilcut_args(line: &str) -> Option<Vec<&str>> {
    if let Some(args) = line.strip_prefix("soilcut ") {
        return Some(words(args));
    }
    if let Some(args) = line.strip_prefix("cargo run --release -- ") {
        return Some(words(args));
    }
    let known = BUILD_STEPS.iter().any(|s| line.starts_with(s)) || line.starts_with("python -c ");
    assert!(
        known,
        "README line neither run nor listed as a build step: {line}"
    );
    None
}

/// Copies a folder and everything in it (also for the runs `plots.rs`
/// shares).
pub fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

#[test]
fn readme_shell_examples_run_in_order() {
    let readme = documents();
    let tmp = tempfile::tempdir().unwrap();
    copy_dir(&root().join("cases"), &tmp.path().join("cases"));
    let soilcut = std::env::var("SOILCUT_BIN").unwrap_or(env!("CARGO_BIN_EXE_soilcut").into());
    let mut ran = 0;
    for line in shell_lines(&readme) {
        let Some(args) = soilcut_args(&line) else {
            continue;
        };
        let o = Command::new(&soilcut)
            .args(&args)
            .current_dir(tmp.path())
            .output()
            .unwrap();
        assert!(
            o.status.success(),
            "{line}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        ran += 1;
    }
    // The Quick start, Usage, ensembles, pictures, landscape and studies.
    assert!(ran >= 20, "only {ran} commands found");
    let out = tmp.path().join("out");
    for made in [
        "original",
        "fine",
        "table1-hs-map",
        "table1-hs-jobs1",
        "lab",
    ] {
        assert!(out.join(made).is_dir(), "out/{made}");
    }
    // The guide's fit finds its synthetic truth, φp = 38°, to 0.1°.
    let fit = std::fs::read_to_string(out.join("table1-hs-fit/fit.md")).unwrap();
    let best: f64 = fit
        .lines()
        .find(|l| l.starts_with("| `soil.friction.peak` |"))
        .and_then(|l| l.split('|').nth(2))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("no best φp in fit.md:\n{fit}"));
    assert!(
        (best - 38.0).abs() <= 0.1,
        "the guide's fit found φp = {best}"
    );
    // Beside the cases, only out/, which git ignores: nothing lands in
    // the repository's root.
    let mut left: Vec<String> = std::fs::read_dir(tmp.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(left, ["cases", "out"]);
}

/// `cargo install` builds what the tests ran on (Cargo.lock's versions),
/// and the examples' compilers write into target/, which git ignores.
#[test]
fn the_build_steps_are_locked_and_write_into_target() {
    let readme = documents();
    let lines = shell_lines(&readme);
    let installs: Vec<&String> = lines
        .iter()
        .filter(|l| l.starts_with("cargo install "))
        .collect();
    assert!(!installs.is_empty());
    for line in installs {
        assert!(line.contains(" --locked"), "{line}");
    }
    let compiles: Vec<&String> = lines
        .iter()
        .filter(|l| l.starts_with("cc ") || l.starts_with("c++ "))
        .collect();
    assert_eq!(compiles.len(), 2, "the C and the C++ example");
    for line in compiles {
        let out = line.split_whitespace().skip_while(|w| *w != "-o").nth(1);
        assert!(out.is_some_and(|o| o.starts_with("target/")), "{line}");
    }
}

#[test]
fn the_lines_are_read_as_a_shell_reads_them() {
    let text = "x\n```sh\nsoilcut run a.toml \\\n    --set k=1   # note\n# alone\n\ncc x.c\n```\n```python\nsoilcut no\n```\n";
    assert_eq!(
        shell_lines(text),
        ["soilcut run a.toml --set k=1", "cc x.c"]
    );
    assert_eq!(soilcut_args("cc x.c"), None);
    let unknown = std::panic::catch_unwind(|| soilcut_args("rm -rf out"));
    assert!(unknown.is_err(), "an unlisted line is refused");
}

/// `cargo run` and `cargo build` without `-p` build the command line and
/// the pure libraries only: the README's first command builds what it runs.
#[test]
fn the_default_build_has_no_python_c_abi_bench_or_fuzz_crate() {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let o = Command::new(cargo)
        .args([
            "tree",
            "--offline",
            "-e",
            "normal,build",
            "--prefix",
            "none",
        ])
        .current_dir(root())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let tree = String::from_utf8_lossy(&o.stdout);
    assert!(tree.lines().any(|l| l.starts_with("soilcut v")), "{tree}");
    for absent in [
        "pyo3 ",
        "numpy ",
        "soilcut-python ",
        "soilcut-ffi ",
        "soilcut-bench ",
        "soilcut-fuzz-bodies ",
        "divan ",
    ] {
        assert!(
            !tree.lines().any(|l| l.starts_with(absent)),
            "{absent}in the default build"
        );
    }
}

/// Each step of `scripts/test` that builds, installs or tests says so on
/// stderr before it starts (`step ...`): the builds print nothing (-q) and
/// take minutes on a fresh clone.
#[test]
fn scripts_test_says_what_it_is_doing() {
    let script = std::fs::read_to_string(root().join("scripts/test")).unwrap();
    let long = [
        "-m venv",
        "pip install",
        "cargo build",
        "cargo test",
        "pytest",
    ];
    let mut previous = String::new();
    let mut checked = 0;
    let mut logical = String::new();
    for line in script.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(start) = line.strip_suffix('\\') {
            logical.push_str(start);
            continue;
        }
        logical.push_str(line);
        let command = std::mem::take(&mut logical);
        if !command.starts_with("step ") && long.iter().any(|l| command.contains(l)) {
            assert!(
                previous.starts_with("step "),
                "scripts/test runs `{command}` without saying so first"
            );
            checked += 1;
        }
        previous = command;
    }
    assert!(checked >= 5, "{checked} long steps found");
}

/// The guide is built in CI, warnings as errors, and its chapters are
/// among the documents whose examples run.
#[test]
fn ci_builds_the_guide_with_warnings_as_errors() {
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    assert!(ci.contains("./scripts/guide\n"), "{ci}");
    let script = std::fs::read_to_string(root().join("scripts/guide")).unwrap();
    assert!(script.contains("sphinx-build\" -E -W "), "{script}");
    let text = documents();
    assert!(text.contains("# Python API reference") && text.contains("# The command line"));
}

/// CI lints and checks the formatting of every Python file (the package,
/// examples, docs/, fuzz/, validation/) by the one ruff.toml.
#[test]
fn ci_runs_ruff_over_every_python_file() {
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    for command in ["ruff\" check .\n", "ruff\" format --check .\n"] {
        assert!(ci.contains(command), "{command:?} not in .ci/run");
    }
    let config = std::fs::read_to_string(root().join("ruff.toml")).unwrap();
    assert!(!config.contains("exclude = [\"validation") && !config.contains("extend-exclude"));
}

/// Every page of docs/ and of the guide opens with its title: a bullet
/// above validation.md's title contradicted the same bullet in its Limits.
#[test]
fn every_page_opens_with_its_title() {
    let mut pages = 0;
    for dir in ["docs", "docs/guide"] {
        for entry in std::fs::read_dir(root().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "md") {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(text.starts_with("# "), "{}", path.display());
            pages += 1;
        }
    }
    assert!(pages >= 10, "{pages} pages");
}
