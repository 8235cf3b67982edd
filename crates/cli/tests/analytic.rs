//! `soilcut analytic`, the baselines in `summary.json`, and the keys of the
//! extended model (rake, cohesion, adhesion, surcharge).

use std::path::PathBuf;
use std::process::{Command, Output};

const BASE: &str = include_str!("../../io/testdata/original.toml");

fn soilcut(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn sandbox() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("case.toml");
    std::fs::write(&case, BASE).unwrap();
    (dir, case)
}

/// The literature's FEE example: α = 60°, φw = 20°, φ = 35°, γ = 17.66,
/// d = 0.5: F = 8.03 at β* = 28.11°.
const FEE_EXAMPLE: [&str; 14] = [
    "--set",
    "blade.depth=0.5",
    "--set",
    "soil.unit_weight=17.66",
    "--set",
    "soil.friction={ peak = 35, residual = 35 }",
    "--set",
    "blade.wall_friction=20",
    "--set",
    "blade.rake=60",
    "--set",
    "run.increment=0.01",
    "--set",
    "run.travel=0.5",
];

#[test]
fn analytic_prints_the_fee_example() {
    let (dir, _) = sandbox();
    let mut args = vec!["analytic", "case.toml"];
    args.extend(FEE_EXAMPLE);
    let o = soilcut(dir.path(), &args);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let fee = out
        .lines()
        .find(|l| l.starts_with("FEE"))
        .expect("an FEE row");
    let numbers: Vec<f64> = fee
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    assert!((numbers[0] - 8.03).abs() < 5e-3, "{fee}");
    assert!((numbers[2] - 7.91).abs() < 5e-3, "{fee}");
    assert!((numbers[4] - 28.11).abs() < 0.01, "{fee}");
    assert!(out.contains("Nγ = 1.8196"), "{out}");
}

#[test]
fn rake_outside_its_range_is_refused() {
    let (dir, _) = sandbox();
    for command in ["run", "check", "analytic"] {
        for rake in ["10", "95"] {
            let set = format!("blade.rake={rake}");
            let o = soilcut(dir.path(), &[command, "case.toml", "--set", &set]);
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{err}");
            let named = format!("error: --set {set}: blade.rake: ");
            assert!(err.starts_with(&named), "{err}");
            assert!(err.contains("[20°, 90°]"), "{err}");
            assert_eq!(err.lines().count(), 1);
        }
    }
    // Eq. (1) must grow with φ: sin(α − φw) > 0.
    let o = soilcut(
        dir.path(),
        &[
            "check",
            "case.toml",
            "--set",
            "blade.rake=30",
            "--set",
            "soil.repose=20",
            "--set",
            "blade.wall_friction=31",
        ],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: --set blade.wall_friction=31: blade.wall_friction: "),
        "{err}"
    );
    // A face flatter than the repose (a tine or scraper) is a valid case.
    let o = soilcut(
        dir.path(),
        &["check", "case.toml", "--set", "blade.rake=25"],
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!dir.path().join("out").exists());
}

#[test]
fn negative_loads_are_refused() {
    let (dir, _) = sandbox();
    for key in ["soil.cohesion", "blade.adhesion", "soil.surcharge"] {
        let o = soilcut(
            dir.path(),
            &["run", "case.toml", "--set", &format!("{key}=-1")],
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.starts_with(&format!("error: --set {key}=-1: {key}: ")),
            "{err}"
        );
    }
}

#[test]
fn summary_carries_the_baselines_beside_the_first_force() {
    let (dir, _) = sandbox();
    let o = soilcut(
        dir.path(),
        &[
            "run",
            "case.toml",
            "--no-plots",
            "-q",
            "--out",
            "o",
            "--set",
            "soil.cohesion=2",
            "--set",
            "soil.surcharge=1",
            "--set",
            "run.increment=0.05",
            "--set",
            "run.travel=0.5",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(dir.path().join("o/summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
    let simulated = summary["simulated_initial_force"].as_f64().unwrap();
    let fee = summary["baselines"]["fee"]["force"].as_f64().unwrap();
    let rankine = summary["baselines"]["rankine"]["force"].as_f64().unwrap();
    assert!(
        (simulated - fee).abs() < 1e-3 * fee,
        "{simulated} vs FEE {fee}"
    );
    assert!(
        rankine < fee,
        "a smooth wall needs less force: {rankine} vs {fee}"
    );
}

#[test]
fn bad_depth_paths_are_refused() {
    let (dir, _) = sandbox();
    for (path, says) in [
        ("[[0, 10], [0, 15]]", "u must increase"),
        ("[[0, 10], [20, 15], [15, 5]]", "u must increase"),
        ("[[0, -1]]", "depth in [1e-20, 1e20] (got [0.0, -1.0])"),
        ("[[0, 10], [20, nan]]", "finite"),
    ] {
        let set = format!("blade.depth_path={path}");
        let o = soilcut(dir.path(), &["run", "case.toml", "--set", &set]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{path}: {err}");
        assert!(
            err.starts_with(&format!("error: --set {set}: blade.depth_path: ")),
            "{err}"
        );
        assert!(err.contains(says), "{path}: {err}");
    }
    let o = soilcut(
        dir.path(),
        &[
            "check",
            "case.toml",
            "--set",
            "blade.depth_path=[[0, 10], [20, 20]]",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!dir.path().join("out").exists());
}
