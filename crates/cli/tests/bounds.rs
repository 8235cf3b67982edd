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

/// `soilcut ARGS…` in `dir`.
pub(crate) fn soilcut(dir: &Path, args: &[&str]) -> Output {
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

/// The rows of `bounds.csv` in `dir`, each a lookup of its numbers by
/// column name.
fn rows(dir: &Path) -> Vec<impl Fn(&str) -> f64> {
    let text = std::fs::read_to_string(dir.join("bounds.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), BOUNDS_HEADER);
    let header: Vec<String> = BOUNDS_HEADER.split(',').map(String::from).collect();
    lines
        .map(|line| {
            let values: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
            let header = header.clone();
            move |name: &str| values[header.iter().position(|h| h == name).unwrap()]
        })
        .collect()
}

/// Runs `soilcut bounds case.toml` with `args` in a folder holding `case`
/// and returns the rows of its `bounds.csv`.
fn bounds_rows(case: &str, args: &[&str]) -> Vec<impl Fn(&str) -> f64> {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("case.toml"), case).unwrap();
    let mut all = vec!["bounds", "case.toml", "--out", "b"];
    all.extend(args);
    let o = soilcut(dir.path(), &all);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for name in ["bounds.json", "case.resolved.toml"] {
        assert!(dir.path().join("b").join(name).is_file(), "{name}");
    }
    // One instant's fields are drawn, or the instants through the run.
    let one = args.contains(&"--at");
    assert_eq!(dir.path().join("b/bounds.png").is_file(), one);
    assert_eq!(dir.path().join("b/bounds_every.png").is_file(), !one);
    rows(&dir.path().join("b"))
}

#[test]
fn first_increment_is_coulomb_and_lies_within_the_bracket() {
    let mut args = vec!["--at", "0", "--mesh", "4"];
    args.extend(CONSTANT);
    let get = bounds_rows(BASE, &args).remove(0);
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
    let mut args = vec!["--every", "0.25", "--mesh", "6"];
    args.extend(ASSOCIATED);
    let rows = bounds_rows(REFINED, &args);
    assert_eq!(rows.len(), 4, "u/d = 0, 0.25, 0.5, 0.75");
    for get in rows {
        let (lower, upper, soil) = (get("lower"), get("upper"), get("soilcut"));
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
        &["--at", "0", "--set", "blade.rake=20"],
        "blade.rake = 20: the bounds take a rake in [30, 90] degrees",
    );
    assert_refused(
        &["--at", "0", "--set", "blade.width=40"],
        "blade.width = 40",
    );
}

/// Fig. 5 to u/d = 1: hardening soil, whose fresh soil (φc = 20°) is
/// pushed up against the face at the repose angle 30°.
const FIG5: &str = include_str!("../../../cases/paper/fig5.toml");

/// With each column its own φ the pile cannot stand from the second
/// instant on: no bounds, the status and the reason said; with the slope
/// field both bounds exist at every instant, the lower below the upper,
/// and the field only strengthens (the first instant, flat ground, is the
/// same).
#[test]
fn a_pile_steeper_than_its_soil_has_no_bounds_and_the_slope_field_has_both() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("case.toml"), FIG5).unwrap();
    let run = |field: &str, out: &str| {
        let o = soilcut(
            dir.path(),
            &[
                "bounds",
                "case.toml",
                "--every",
                "0.5",
                "--mesh",
                "3",
                "--set",
                "run.travel=21",
                "--field",
                field,
                "--out",
                out,
            ],
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let json: serde_json::Value = serde_json::from_slice(
            &std::fs::read(dir.path().join(out).join("bounds.json")).unwrap(),
        )
        .unwrap();
        assert_eq!(json["field"], field);
        (
            String::from_utf8(o.stdout).unwrap(),
            json,
            rows(&dir.path().join(out)),
        )
    };
    let (text, json, own) = run("columns", "own");
    assert_eq!(own.len(), 3, "u/d = 0, 0.5, 1");
    for (k, get) in own.iter().enumerate().skip(1) {
        assert!(get("lower").is_nan() && get("upper").is_nan());
        let instant = &json["instants"][k];
        assert_eq!(instant["lower_status"], "SteepGround");
        assert_eq!(instant["upper_status"], "SteepGround");
    }
    assert_eq!(
        text.matches("the ground cannot stand under its own weight")
            .count(),
        2,
        "{text}"
    );
    assert!(
        text.contains("slopes at 30.00° on soil of φ = 20.00°"),
        "{text}"
    );
    let (_, json, slope) = run("slope", "slope");
    for (k, get) in slope.iter().enumerate() {
        let (lower, upper) = (get("lower"), get("upper"));
        assert!(
            0.0 < lower && lower <= upper,
            "u/d = {}: {lower} {upper}",
            get("u_over_d")
        );
        assert_eq!(json["instants"][k]["upper_status"], "Solved");
    }
    assert_eq!(slope[0]("lower"), own[0]("lower"));
    assert_eq!(slope[0]("upper"), own[0]("upper"));
}

#[test]
fn a_field_other_than_columns_or_slope_is_refused() {
    let dir = sandbox();
    let o = soilcut(
        dir.path(),
        &[
            "bounds",
            "case.toml",
            "--at",
            "0",
            "--field",
            "mean",
            "--out",
            "b",
        ],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--field") && err.contains("columns") && err.contains("slope"),
        "{err}"
    );
    assert!(!dir.path().join("b").exists());
}
