//! `soilcut sweep`, `fit` and `converge` on a short, coarse case.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn refined() -> String {
    workspace()
        .join("crates/io/testdata/refined.toml")
        .display()
        .to_string()
}

fn soilcut(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .output()
        .unwrap()
}

fn ok(o: &Output) {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

const SHORT: [&str; 4] = ["--set", "run.travel=10", "--set", "run.increment=1"];

fn sweep(out: &Path, jobs: &str, extra: &[&str]) -> Output {
    let case = refined();
    let out = out.display().to_string();
    let mut args = vec![
        "sweep",
        &case,
        "--vary",
        "soil.friction.peak=31:40",
        "--vary",
        "soil.friction.initial=20,33",
        "--sample",
        "lhs:6",
        "--seed",
        "4",
        "--jobs",
        jobs,
        "--out",
        &out,
    ];
    args.extend(SHORT);
    args.extend(extra);
    soilcut(&args)
}

#[test]
fn sweep_files_do_not_depend_on_the_thread_count() {
    let tmp = tempfile::tempdir().unwrap();
    let (a, b) = (tmp.path().join("a"), tmp.path().join("b"));
    ok(&sweep(&a, "1", &[]));
    ok(&sweep(&b, "2", &["--keep-runs"]));
    for file in [
        "sweep.csv",
        "sweep-soil.friction.peak.png",
        "sweep-soil.friction.initial.png",
    ] {
        assert_eq!(
            std::fs::read(a.join(file)).unwrap(),
            std::fs::read(b.join(file)).unwrap(),
            "{file}"
        );
    }
    let csv = std::fs::read_to_string(a.join("sweep.csv")).unwrap();
    assert_eq!(csv.lines().count(), 7);
    // φc = 33° above φp for some draws: those runs are rows with errors.
    let failed: Vec<&str> = csv.lines().filter(|l| l.contains(",failed,")).collect();
    assert!(!failed.is_empty(), "{csv}");
    assert!(failed
        .iter()
        .all(|l| l.contains("soil.friction.initial: must be <=")));
    let kept = std::fs::read_dir(b.join("runs")).unwrap().count();
    assert_eq!(kept, 6 - failed.len());
    assert!(!a.join("runs").exists());
    let o = sweep(&a, "1", &[]);
    assert_eq!(o.status.code(), Some(2), "occupied output folder");
    ok(&sweep(&a, "1", &["--force"]));
    let leftovers = std::fs::read_dir(tmp.path()).unwrap().count();
    assert_eq!(leftovers, 2, "no staging folders left behind");
}

/// A `--vary` or `--free` key no run can set is refused before any run,
/// named as the argument, with the nearest key; no folder made.
#[test]
fn an_unknown_study_key_names_the_nearest_before_any_run() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("x").display().to_string();
    let lab = tmp.path().join("lab.csv");
    std::fs::write(&lab, "u,force\n0,1\n10,2\n").unwrap();
    let (case, lab) = (refined(), lab.display().to_string());
    let free = "soil.friction.peak,soil.friction.peek";
    let fit = ["fit", &case, "--measured", &lab, "--free", free];
    let sweep = ["sweep", &case, "--vary", "soil.frict=30:40:2", "", ""];
    for (command, named, nearest) in [
        (
            sweep,
            "--vary soil.frict=30:40:2: soil.frict",
            "soil.friction",
        ),
        (
            fit,
            "--free soil.friction.peek: soil.friction.peek",
            "soil.friction.peak",
        ),
    ] {
        let mut args: Vec<&str> = command.into_iter().filter(|a| !a.is_empty()).collect();
        args.extend(["--out", &out]);
        args.extend(SHORT);
        let o = soilcut(&args);
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        let expected = format!("error: {named}: unknown key (nearest: `{nearest}`;");
        assert!(err.starts_with(&expected), "{err}");
        assert!(o.stdout.is_empty() && !tmp.path().join("x").exists());
    }
}

#[test]
fn a_sweep_whose_every_run_fails_exits_2_with_its_files() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("x");
    let case = refined();
    let at = out.display().to_string();
    // φc above φp in every run.
    let mut args = vec![
        "sweep",
        &case,
        "--vary",
        "soil.friction.initial=50,55",
        "--out",
        &at,
    ];
    args.extend(SHORT);
    let o = soilcut(&args);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("every run failed; the first: soil.friction.initial"),
        "{err}"
    );
    let csv = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    assert_eq!(csv.lines().filter(|l| l.contains(",failed,")).count(), 2);
    assert!(
        !out.join("sweep-soil.friction.initial.png").exists(),
        "no picture without a point"
    );
    // One run that works is a sweep that works.
    args[3] = "soil.friction.initial=20,55";
    args.push("--force");
    ok(&soilcut(&args));
}

#[test]
fn bad_study_arguments_exit_2() {
    let tmp = tempfile::tempdir().unwrap();
    let case = refined();
    let out = tmp.path().join("x").display().to_string();
    let bad_method = vec![
        "fit",
        &case,
        "--measured",
        "lab.csv",
        "--free",
        "soil.friction.peak",
        "--method",
        "pso",
        "--out",
        &out,
    ];
    for args in [
        vec![
            "sweep",
            &case,
            "--vary",
            "soil.friction.peak=30:45",
            "--out",
            &out,
        ],
        vec![
            "sweep",
            &case,
            "--vary",
            "soil.friction.peak=a:b:c",
            "--out",
            &out,
        ],
        vec![
            "sweep", &case, "--vary", "x=1,2", "--sample", "lhs:0", "--out", &out,
        ],
        vec!["converge", &case, "--levels", "0", "--out", &out],
        bad_method.clone(),
    ] {
        let o = soilcut(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.starts_with("error: ") && err.lines().count() == 1,
            "{err}"
        );
    }
    let err = String::from_utf8_lossy(&soilcut(&bad_method).stderr).to_string();
    assert!(
        err.contains("--method pso: expected de (differential evolution) or cmaes (CMA-ES)"),
        "{err}"
    );
    assert!(!tmp.path().join("x").exists());
}

#[test]
fn a_missing_measured_curve_is_named_as_such() {
    let tmp = tempfile::tempdir().unwrap();
    let (case, out) = (refined(), tmp.path().join("x").display().to_string());
    let nope = tmp.path().join("nope.csv").display().to_string();
    let args = [
        "fit",
        &case,
        "--measured",
        &nope,
        "--free",
        "soil.friction.peak",
        "--out",
        &out,
    ];
    let o = soilcut(&args);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.starts_with(&format!("error: {nope}: cannot read the measured curve: ")),
        "{err}"
    );
}

#[test]
fn fit_and_converge_write_their_files() {
    let tmp = tempfile::tempdir().unwrap();
    let case = refined();
    let truth = tmp.path().join("truth");
    let mut args = vec!["run", &case, "--no-plots", "-q", "--out"];
    let truth_s = truth.display().to_string();
    args.push(&truth_s);
    args.extend(SHORT);
    ok(&soilcut(&args));
    let measured = truth.join("history.csv").display().to_string();
    let also = format!("{case}={measured}");
    let fit = |out: &Path, jobs: &str| {
        let out = out.display().to_string();
        let mut args = vec![
            "fit",
            &case,
            "--measured",
            &measured,
            "--also",
            &also,
            "--free",
            "soil.friction.peak",
            "--set",
            "soil.friction.peak=38",
            "--objective",
            "smooth:2",
            "--evaluations",
            "16",
            "--polish",
            "4",
            "--profile-points",
            "3",
            "--jobs",
            jobs,
            "--out",
            &out,
        ];
        args.extend(SHORT);
        soilcut(&args)
    };
    let (a, b) = (tmp.path().join("fa"), tmp.path().join("fb"));
    ok(&fit(&a, "1"));
    ok(&fit(&b, "2"));
    for file in [
        "fit.csv",
        "fit.md",
        "curves.csv",
        "profiles.csv",
        "search.csv",
        "best.toml",
        "best-2.toml",
        "fit.png",
        "search.png",
    ] {
        assert_eq!(
            std::fs::read(a.join(file)).unwrap(),
            std::fs::read(b.join(file)).unwrap(),
            "{file}"
        );
    }
    let best = a.join("best.toml").display().to_string();
    ok(&soilcut(&["check", &best]));
    let c = tmp.path().join("c").display().to_string();
    let mut args = vec!["converge", &case, "--levels", "2", "--out", &c];
    args.extend(SHORT);
    ok(&soilcut(&args));
    let csv = std::fs::read_to_string(tmp.path().join("c/converge.csv")).unwrap();
    assert_eq!(csv.lines().count(), 3);
    assert!(tmp.path().join("c/converge.png").exists());
}

/// Issue 50 item 6: a fit of a chaotic curve that lands beside the truth
/// must not report a narrow interval about where it landed. Without the
/// chaos's share of the threshold, these one-key fits of a synthetic truth
/// (φp = 38) land at φp ≈ 37.89, RMS 3, with an interval of a few
/// hundredths about it.
#[test]
fn a_fit_s_interval_holds_the_truth_its_chaos_cannot_tell_apart() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace()
        .join("cases/paper/table1-hs.toml")
        .display()
        .to_string();
    let coarse = ["--set", "run.increment=0.8", "--set", "run.travel=40"];
    let truth = tmp.path().join("truth").display().to_string();
    let mut args = vec![
        "run",
        &case,
        "--set",
        "soil.friction.peak=38",
        "--no-plots",
        "-q",
    ];
    args.extend(["--out", &truth]);
    args.extend(coarse);
    ok(&soilcut(&args));
    let measured = format!("{truth}/history.csv");
    for seed in ["0", "1"] {
        let out = tmp.path().join(format!("fit-{seed}"));
        let out_s = out.display().to_string();
        let mut args = vec!["fit", &case, "--measured", &measured];
        args.extend(["--free", "soil.friction.peak", "--seed", seed, "-q"]);
        args.extend([
            "--evaluations",
            "40",
            "--polish",
            "10",
            "--profile-points",
            "5",
        ]);
        args.extend(["--out", &out_s]);
        args.extend(coarse);
        ok(&soilcut(&args));
        let fit = std::fs::read_to_string(out.join("fit.csv")).unwrap();
        let row: Vec<&str> = fit.lines().nth(1).unwrap().split(',').collect();
        let bound = |i: usize| row[i].parse::<f64>().ok();
        let (lower, upper) = (bound(5), bound(6));
        assert!(
            lower.is_none_or(|l| l <= 38.0) && upper.is_none_or(|u| u >= 38.0),
            "seed {seed}: {fit}"
        );
        let report = std::fs::read_to_string(out.join("fit.md")).unwrap();
        assert!(
            report.contains("the chaos sets it"),
            "seed {seed}: {report}"
        );
    }
}
