//! A run never lies, never hangs and never runs out of memory (issue 50):
//! no exit 0 with a number that is not finite in its outputs, and a case
//! that would loop without end or grow without bound is refused by
//! `check` and by `run` (exit 2, naming the key and its range, no output
//! folder) before anything is run.

use crate::bounds::soilcut;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn case(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

/// `COMMAND CASE --set S…` with the `--set` of each of `sets`.
fn with_sets<'a>(command: &'a str, rel: &'a Path, sets: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![command, rel.to_str().unwrap()];
    for s in sets {
        args.extend(["--set", s]);
    }
    args
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Issue 50's Fig. 5 with its lengths × 0.2775 over 2 d: from increment 64
/// the mass was NaN and every force 0, `mass_drift_rel` null, exit 0.
#[test]
fn fig5_scaled_down_writes_only_finite_numbers() {
    let sets = [
        "blade.depth=5.549742791184853",
        "soil.peak_shear=0.5549742791184853",
        "soil.residual_shear=1.1099485582369706",
        "soil.d50=0.1664922837355456",
        "run.travel=11.099485582369706",
    ];
    let dir = tempfile::tempdir().unwrap();
    let file = case("cases/paper/fig5.toml");
    let mut args = with_sets("run", &file, &sets);
    args.extend(["--no-plots", "--out", "out"]);
    let o = soilcut(dir.path(), &args);
    assert!(o.status.success(), "{:?}: {}", o.status, stderr(&o));
    let out = dir.path().join("out");
    for name in ["history.csv", "profile.csv", "frames.csv", "summary.json"] {
        let text = std::fs::read_to_string(out.join(name)).unwrap();
        for word in ["NaN", "inf", "null"] {
            assert!(!text.contains(word), "{name} holds {word}");
        }
    }
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    assert_eq!(
        history.lines().count(),
        701,
        "700 increments and the header"
    );
}

/// `check` and `run` of `rel` with `sets` both exit 2 with one line naming
/// `key` and containing `range`, and `run` writes no folder.
fn refused(rel: &str, sets: &[&str], key: &str, range: &str) {
    let dir = tempfile::tempdir().unwrap();
    let file = case(rel);
    for command in ["check", "run"] {
        let mut args = with_sets(command, &file, sets);
        if command == "run" {
            args.extend(["--no-plots", "--out", "out"]);
        }
        let o = soilcut(dir.path(), &args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{command} {rel} {sets:?}: {err}");
        assert!(err.contains(key) && err.contains(range), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    assert!(
        !dir.path().join("out").exists(),
        "a folder for a refused case"
    );
}

/// The hangs `check` accepted: an increment far below the round-off of
/// the ground's abscissae, where the golden-section search of the vertex
/// ground could not narrow its bracket to the increment and never ended.
#[test]
fn an_increment_below_round_off_is_refused() {
    let sets = ["run.increment=1e-15", "run.travel=1e-14"];
    refused(
        "cases/paper/original.toml",
        &sets,
        "run.increment",
        ">= 1e-9",
    );
    let deep = ["blade.depth=9.2e18"];
    refused(
        "cases/tools/cohesive.toml",
        &deep,
        "run.increment",
        ">= 1e-9",
    );
}

/// The cases that grew without bound (aborted at 4 GiB), refused before
/// the run naming the key and its bound (docs/guide/case-keys.md,
/// "Limits").
#[test]
fn a_case_beyond_the_memory_bounds_is_refused() {
    let fig5 = "cases/paper/fig5.toml";
    refused(
        fig5,
        &["blade.depth=9.2e18"],
        "soil.band_width",
        "samples per depth",
    );
    let thin = ["soil.band_width=1e-6"];
    refused(
        "cases/validation/deep.toml",
        &thin,
        "soil.band_width",
        "samples per depth",
    );
    let samples = ["run.samples_per_band=1e9"];
    refused(fig5, &samples, "run.samples_per_band", "[0, 1000]");
    let fine = ["run.vertex_spacing=1e-4"];
    refused(fig5, &fine, "run.vertex_spacing", "run.increment / 4");
    let vertices = ["run.vertex_spacing=4e-5", "run.increment=1e-4"];
    refused(fig5, &vertices, "run.vertex_spacing", "1e6 vertices");
    let steps = ["run.increment=1e-5", "run.vertex_spacing=1"];
    refused(fig5, &steps, "run.increment", "1e6 increments");
}

/// A sweep of 1e8 runs, by a grid or by a sample, is refused before any
/// run naming the option and the bound, with no folder. Run under a
/// memory limit of 1 GiB, so that a regression fails instead of taking
/// the machine's memory.
#[test]
fn a_sweep_of_a_hundred_million_runs_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = case("cases/paper/original.toml");
    for (option, value) in [
        ("--vary", "soil.friction.peak=30:40:100000000"),
        ("--sample", "lhs:100000000"),
    ] {
        let mut args = vec!["sweep", file.to_str().unwrap(), option, value];
        if option == "--sample" {
            args.extend(["--vary", "soil.friction.peak=30:40"]);
        }
        args.extend(["--out", "out"]);
        let limited = format!(
            "ulimit -v 1048576; exec \"{}\" \"$@\"",
            env!("CARGO_BIN_EXE_soilcut")
        );
        let o = Command::new("sh")
            .args(["-c", &limited, "soilcut"])
            .args(&args)
            .current_dir(dir.path())
            .output()
            .unwrap();
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{option} {value}: {err}");
        assert!(err.contains(option) && err.contains("1e5 runs"), "{err}");
        assert!(!dir.path().join("out").exists(), "{option}: a folder");
    }
}
