//! The C and C++ examples (crates/ffi/examples/c/run.c and
//! crates/ffi/examples/cpp/run.cpp), built with the system's compilers
//! (`cc` and `c++`, or `$CC` and `$CXX`) against the libraries cargo built
//! for this test (the static one for C, the shared one for C++), run on
//! cases/paper/original.toml cut short, and compared with `soilcut run`'s
//! history.csv: every column, bit for bit.
//!
//! `soilcut run` writes history.csv through `soilcut_io::record_files`,
//! which this test calls; with `SOILCUT_BIN` set to a built `soilcut`
//! (scripts/test sets it) it also runs the command line itself and
//! compares the files.

use soilcut_io::{read_case, record_files, HISTORY_HEADER};
use soilcut_model::Simulation;
use std::path::{Path, PathBuf};
use std::process::Command;

const SETS: [&str; 2] = ["run.travel=2", "run.increment=0.04"];

fn manifest() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn case() -> PathBuf {
    manifest().join("../../cases/paper/original.toml")
}

/// The folder holding the libsoilcut_ffi cargo built with this test:
/// the test runs from target/<profile>/deps, beside them.
fn library_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's path");
    exe.ancestors()
        .skip(1)
        .take(2)
        .find(|dir| dir.join(static_library()).exists())
        .unwrap_or_else(|| {
            panic!(
                "no {} beside {} or in its parent: cargo builds it with the crate (crate-type staticlib)",
                static_library(),
                exe.display()
            )
        })
        .to_path_buf()
}

fn static_library() -> &'static str {
    if cfg!(windows) {
        "soilcut_ffi.lib"
    } else {
        "libsoilcut_ffi.a"
    }
}

/// Runs a compiler, failing with a clear message if it is missing.
fn compile(compiler_var: &str, default: &str, args: &[String]) {
    let compiler = std::env::var(compiler_var).unwrap_or_else(|_| default.to_string());
    let output = Command::new(&compiler).args(args).output().unwrap_or_else(|e| {
        panic!(
            "cannot run the compiler `{compiler}` ({e}): the C and C++ examples need `cc` and `c++` \
             on PATH (or ${compiler_var}); install gcc/g++ or clang"
        )
    });
    assert!(
        output.status.success(),
        "`{compiler} {}` failed:\n{}",
        args.join(" "),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Runs a built example on the case; returns its stdout.
fn run(program: &Path) -> String {
    let case = case();
    // cargo's library path would put an older libsoilcut_ffi (`cargo
    // build`'s, in target/<profile>) before this test's: the rpath decides.
    let output = Command::new(program)
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("DYLD_LIBRARY_PATH")
        .arg(&case)
        .args(SETS)
        .output()
        .expect("run the example");
    assert!(
        output.status.success(),
        "{} failed: {}",
        program.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).expect("UTF-8 output")
}

/// `soilcut run`'s history.csv for the case.
fn reference() -> String {
    let overrides: Vec<_> = SETS.iter().map(|s| s.parse().unwrap()).collect();
    let loaded = read_case(&case(), &overrides).unwrap();
    let mut sim = Simulation::new(&loaded.case).unwrap();
    let run = record_files(&loaded, &mut sim, || {}).unwrap();
    let history = run
        .files
        .iter()
        .find(|(name, _)| *name == "history.csv")
        .map(|(_, text)| text.clone())
        .unwrap();
    if let Some(bin) = std::env::var_os("SOILCUT_BIN") {
        let out = tempfile::tempdir().unwrap();
        let mut command = Command::new(bin);
        command.args(["run", "--no-plots", "--quiet", "--out"]);
        command.arg(out.path().join("run")).arg(case());
        for set in SETS {
            command.args(["--set", set]);
        }
        let status = command.status().expect("run SOILCUT_BIN");
        assert!(status.success());
        let written = std::fs::read_to_string(out.path().join("run/history.csv")).unwrap();
        assert_eq!(written, history, "soilcut run's history.csv");
    }
    history
}

/// The rows of a CSV text with `HISTORY_HEADER`, as the bits of each number.
fn rows(text: &str) -> Vec<Vec<u64>> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(HISTORY_HEADER));
    lines
        .map(|line| {
            let mut fields = line.split(',');
            let step: u64 = fields.next().unwrap().parse().unwrap();
            let mut row = vec![step];
            row.extend(fields.map(|f| {
                f.parse::<f64>()
                    .unwrap_or_else(|e| panic!("{f:?}: {e}"))
                    .to_bits()
            }));
            assert_eq!(row.len(), HISTORY_HEADER.split(',').count(), "{line}");
            row
        })
        .collect()
}

fn s(p: &Path) -> String {
    p.to_str().expect("UTF-8 paths").to_string()
}

/// Builds the C example at `program` against the static library, with the
/// system libraries Rust's standard library needs.
fn build_c(program: &Path) {
    let mut args = vec![
        "-std=c99".to_string(),
        "-Wall".into(),
        "-Wextra".into(),
        "-pedantic".into(),
        "-Werror".into(),
        format!("-I{}", s(&manifest().join("include"))),
        s(&manifest().join("../../crates/ffi/examples/c/run.c")),
        s(&library_dir().join(static_library())),
        "-o".into(),
        s(program),
    ];
    if cfg!(target_os = "macos") {
        args.extend(["-framework".into(), "CoreFoundation".into()]);
    } else {
        args.extend(["-lpthread".into(), "-ldl".into(), "-lm".into()]);
    }
    compile("CC", "cc", &args);
}

/// Builds the C++ example at `program` against the shared library, found
/// at run time by its rpath.
fn build_cpp(program: &Path) {
    let lib = library_dir();
    let args = [
        "-std=c++17".to_string(),
        "-Wall".into(),
        "-Wextra".into(),
        "-pedantic".into(),
        "-Werror".into(),
        format!("-I{}", s(&manifest().join("include"))),
        s(&manifest().join("../../crates/ffi/examples/cpp/run.cpp")),
        format!("-L{}", s(&lib)),
        "-lsoilcut_ffi".into(),
        format!("-Wl,-rpath,{}", s(&lib)),
        "-o".into(),
        s(program),
    ];
    compile("CXX", "c++", &args);
}

#[test]
fn the_c_and_cpp_examples_equal_soilcut_run_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let (c_program, cpp_program) = (dir.path().join("run-c"), dir.path().join("run-cpp"));
    build_c(&c_program);
    build_cpp(&cpp_program);
    let expected = rows(&reference());
    assert_eq!(expected.len(), 50, "travel 2 in increments of 0.04");
    for program in [&c_program, &cpp_program] {
        let got = rows(&run(program));
        assert_eq!(got.len(), expected.len(), "{}", program.display());
        for (g, e) in got.iter().zip(&expected) {
            assert_eq!(g, e, "{}: increment {}", program.display(), e[0]);
        }
    }
}

#[test]
fn the_c_and_cpp_examples_report_a_bad_key_naming_the_file_once() {
    let dir = tempfile::tempdir().unwrap();
    let (c_program, cpp_program) = (dir.path().join("run-c"), dir.path().join("run-cpp"));
    build_c(&c_program);
    build_cpp(&cpp_program);
    for program in [&c_program, &cpp_program] {
        let output = Command::new(program)
            .env_remove("LD_LIBRARY_PATH")
            .arg(case())
            .arg("blade.rake=10")
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2));
        let stderr = String::from_utf8_lossy(&output.stderr);
        let expected = format!("error: {}: blade.rake: ", s(&case()));
        assert!(stderr.starts_with(&expected), "{stderr}");
        assert_eq!(stderr.matches(&s(&case())).count(), 1, "{stderr}");
        assert!(output.stdout.is_empty());
    }
}
