//! `soilcut sensitivity` on a shipped case, short and coarse.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn fig5() -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    root.join("cases/paper/fig5.toml").display().to_string()
}

fn soilcut(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .output()
        .unwrap()
}

/// Fig. 5 over u/d = 1 at d/50 (vertices d/25 apart): about 50 increments a run.
const COARSE: [&str; 6] = [
    "--set",
    "run.travel=20",
    "--set",
    "run.increment=0.4",
    "--set",
    "run.vertex_spacing=0.8",
];

/// Runs `args` on the coarse case, which must succeed.
fn coarse(mut args: Vec<&str>) {
    args.extend(COARSE);
    let done = soilcut(&args);
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(done.status.success(), "{stderr}");
}

/// Sobol indices of three keys and the dummy, N = 16 (96 runs); the
/// folder `out` written.
fn sobol(out: &Path, jobs: &str, seed: &str) -> PathBuf {
    let case = fig5();
    let o = out.display().to_string();
    let args = vec![
        "sensitivity",
        &case,
        "--method",
        "sobol",
        "--samples",
        "16",
        "--dummy",
        "-q",
        "--vary",
        "soil.friction.peak=35:45",
        "--vary",
        "soil.peak_shear=1:3",
        "--vary",
        "blade.wall_friction=5:15",
        "--jobs",
        jobs,
        "--seed",
        seed,
        "--out",
        &o,
    ];
    coarse(args);
    out.to_path_buf()
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

#[test]
fn indices_do_not_depend_on_threads_and_the_dummy_s_are_zero() {
    let tmp = tempfile::tempdir().unwrap();
    let one = sobol(&tmp.path().join("j1"), "1", "3");
    let two = sobol(&tmp.path().join("j2"), "2", "3");
    let other = sobol(&tmp.path().join("s4"), "2", "4");
    for name in [
        "indices.csv",
        "samples.csv",
        "summary.json",
        "sensitivity.md",
    ] {
        assert_eq!(read(&one, name), read(&two, name), "{name}");
    }
    assert_ne!(read(&one, "indices.csv"), read(&other, "indices.csv"));
    let indices = read(&one, "indices.csv");
    let rows: Vec<Vec<&str>> = indices
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 3 * 4, "three outputs, four inputs");
    for row in &rows {
        let v: Vec<f64> = row[2..].iter().map(|x| x.parse().unwrap()).collect();
        assert!(v[5] >= v[1], "{row:?}: ST above S1 within the intervals");
        if row[1] == "dummy" {
            assert!(
                v[1] <= 0.0 && 0.0 <= v[2] && v[4] <= 0.0 && 0.0 <= v[5],
                "{row:?}"
            );
        }
    }
    let samples = read(&one, "samples.csv");
    assert_eq!(samples.lines().count(), 1 + 16 * 5 + 16);
    assert!(read(&one, "summary.json").contains("\"complete\": true"));
}

#[test]
fn members_give_each_output_a_chaos_share() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("m");
    let (case, o) = (fig5(), out.display().to_string());
    let args = vec![
        "sensitivity",
        &case,
        "--method",
        "morris",
        "--samples",
        "3",
        "--members",
        "3",
        "--vary",
        "soil.friction.peak=35:45",
        "--vary",
        "blade.wall_friction=5:15",
        "-q",
        "--out",
        &o,
    ];
    coarse(args);
    let summary: serde_json::Value = serde_json::from_str(&read(&out, "summary.json")).unwrap();
    assert_eq!(summary["runs"], 3 * 3 * 3);
    for o in summary["outputs"].as_array().unwrap() {
        let share = o["chaos_share"].as_f64().unwrap();
        assert!((0.0..1.0).contains(&share), "{o}");
    }
    let samples = read(&out, "samples.csv");
    let ks: Vec<&str> = samples
        .lines()
        .skip(1)
        .take(3)
        .map(|l| l.split(',').nth(2).unwrap())
        .collect();
    assert_eq!(ks, ["-1", "0", "1"]);
    assert!(read(&out, "indices.csv")
        .starts_with("output,key,mu_star,mu_star_low,mu_star_high,sigma,mu\n"));
}

#[test]
fn bad_designs_exit_2_naming_the_argument_before_any_run() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("bad");
    let (case, o) = (fig5(), out.display().to_string());
    for (extra, named) in [
        (
            ["--vary", "soil.friction.peak=45:45", "--samples", "16"],
            "--vary soil.friction.peak=45:45",
        ),
        (
            ["--vary", "soil.friction.peak=abc:45", "--samples", "16"],
            "--vary soil.friction.peak=abc:45",
        ),
        (
            ["--vary", "soil.frict=30:40", "--samples", "16"],
            "--vary soil.frict=30:40",
        ),
        (
            ["--vary", "soil.friction.peak=35:45", "--samples", "12"],
            "--samples 12",
        ),
    ] {
        let mut args = vec!["sensitivity", &case, "--method", "sobol", "--out", &o];
        args.extend(extra);
        let done = soilcut(&args);
        let stderr = String::from_utf8_lossy(&done.stderr);
        assert_eq!(done.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(named), "{stderr}");
        assert!(!out.exists(), "nothing written for {named}");
    }
}
