//! `soilcut bounds`: the bracket beside soilcut's force, its files, and
//! its refusals of bad input.

use soilcut_io::BOUNDS_HEADER;
use soilcut_model::analytic::Wedge;
use std::path::Path;
use std::process::{Command, Output};

/// A short case of the original model (100 increments).
const BASE: &str = include_str!("../../io/testdata/original.toml");
/// Constant friction: the ground at u = 0 is flat, φ = 35°, φw = 10°.
const CONSTANT: [&str; 2] = ["--set", "soil.friction={ peak = 35, residual = 35 }"];

fn soilcut(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn sandbox() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("case.toml"), BASE).unwrap();
    dir
}

/// The numbers of the one row of `bounds.csv`, by column name.
fn row(dir: &Path) -> impl Fn(&str) -> f64 {
    let text = std::fs::read_to_string(dir.join("bounds.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    assert_eq!(header.join(","), BOUNDS_HEADER);
    let values: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    move |name| values[header.iter().position(|h| h == name).unwrap()]
}

#[test]
fn first_increment_is_coulomb_and_lies_within_the_bracket() {
    let dir = sandbox();
    let mut args = vec![
        "bounds",
        "case.toml",
        "--at",
        "0",
        "--mesh",
        "4",
        "--out",
        "b",
    ];
    args.extend(CONSTANT);
    let o = soilcut(dir.path(), &args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let get = row(&dir.path().join("b"));
    let wedge = Wedge {
        unit_weight: 1.0,
        depth: 20.0,
        friction: 35f64.to_radians(),
        wall_friction: 10f64.to_radians(),
        rake: 90f64.to_radians(),
        cohesion: 0.0,
        adhesion: 0.0,
        surcharge: 0.0,
    };
    let coulomb = wedge.coulomb().unwrap().force_h;
    let (soil, lower, upper) = (get("soilcut"), get("lower"), get("upper"));
    // The first increment is Coulomb's planar wedge (to its angle step).
    assert!(
        (soil - coulomb).abs() < 1e-4 * coulomb,
        "{soil} vs {coulomb}"
    );
    // Never below the lower bound; not below the upper by more than the bracket.
    assert!(
        lower <= soil && soil >= upper - (upper - lower),
        "{lower} {soil} {upper}"
    );
    assert!((get("soilcut_over_lower") - soil / lower).abs() < 1e-12);
    assert_eq!(get("mesh"), 4.0);
    assert!(get("lower_seconds") > 0.0 && get("upper_seconds") > 0.0);
    for name in ["bounds.json", "case.resolved.toml", "bounds.png"] {
        assert!(dir.path().join("b").join(name).is_file(), "{name}");
    }
}

/// A short refined case with associated flow: φ = ψ = 35° at every shear,
/// a repose angle below φ (so the pile can stand).
const REFINED: &str = include_str!("../../io/testdata/refined.toml");
const ASSOCIATED: [&str; 6] = [
    "--set",
    "soil.friction={ initial = 35, peak = 35, residual = 35 }",
    "--set",
    "soil.dilation={ initial = 35, peak = 35, residual = 35 }",
    "--set",
    "soil.repose=30",
];

/// For associated flow soilcut's band is a mechanism of the upper bound's
/// kind: its force is never below the lower bound, and not above the
/// (coarse) upper bound by more than 2 % (N = 6: on N = 4 the lower bound
/// finds no field for the pile from u/d = 0.5 on).
#[test]
fn associated_soil_is_never_below_the_lower_bound() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("case.toml"), REFINED).unwrap();
    let mut args = vec![
        "bounds",
        "case.toml",
        "--every",
        "0.25",
        "--mesh",
        "6",
        "--out",
        "b",
    ];
    args.extend(ASSOCIATED);
    let o = soilcut(dir.path(), &args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(dir.path().join("b/bounds.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 4, "u/d = 0, 0.25, 0.5, 0.75");
    for r in rows {
        let (lower, upper, soil) = (r[at("lower")], r[at("upper")], r[at("soilcut")]);
        assert!(
            lower <= soil && soil <= 1.02 * upper,
            "{lower} {soil} {upper}"
        );
    }
}

/// Exit code 2, one stderr line naming `key`, and no output folder.
fn assert_refused(extra: &[&str], key: &str) {
    let dir = sandbox();
    let mut args = vec!["bounds", "case.toml", "--out", "b"];
    args.extend(extra);
    let o = soilcut(dir.path(), &args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains(key), "{err}");
    assert!(!dir.path().join("b").exists());
}

#[test]
fn bad_input_is_refused_naming_the_key_and_range() {
    assert_refused(
        &["--at", "0", "--mesh", "0"],
        "--mesh must be an integer from 1 to 64",
    );
    assert_refused(&["--at", "0", "--mesh", "65"], "--mesh");
    assert_refused(&["--at", "-1"], "--at must be a number from 0 to");
    assert_refused(&["--every", "0"], "--every must be a number above 0");
    assert_refused(
        &["--at", "0", "--set", "blade.width=40"],
        "blade.width = 40",
    );
}
