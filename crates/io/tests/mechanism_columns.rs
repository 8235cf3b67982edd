//! `history.csv`'s mechanism columns (`weight`, `force_factor`,
//! `face_friction_deg`) hold the physics they name, read by their column
//! names, on the three DEM validation cuts (cases/validation/), under both
//! band rules, on both grounds:
//!
//! - on the first increment, flat fresh ground, the block is Coulomb's
//!   wedge, W = ½ γ0 d² (cot β + cot α), its soil at φc, and P/W is
//!   Eq. (1)'s factor sin(β + φ) / sin(α + β + φ + δ) at that β, δ the face
//!   friction;
//! - at every increment, the face friction is the angle of the force
//!   (force_h, force_v) from the face's normal, P = W × factor, and the
//!   friction angle the block mobilises, back-computed from (h, v), W and
//!   β as validation/dem/mechanism_series.py reduces the DEM's,
//!   φ = 90° − β − atan((v + W) / h), is the band's `friction_deg`: Eq. (1)
//!   is the balance of a rigid block on a straight band, so the DEM's
//!   reduction applied to soilcut returns soilcut's band strength.

use soilcut_io::{history_value, read_case, Override};
use soilcut_model::{Case, Simulation, StepRecord};
use std::path::Path;

const CUTS: [&str; 3] = ["vertical", "raked30", "deep"];

fn case(name: &str, set: &[&str]) -> Case {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let file = root.join(format!("cases/validation/{name}.toml"));
    let set: Vec<Override> = set.iter().map(|s| s.parse().unwrap()).collect();
    read_case(&file, &set).unwrap().case.into_case()
}

fn column(r: &StepRecord, name: &str) -> f64 {
    history_value(r, name).unwrap_or_else(|| panic!("history.csv has a column {name}"))
}

/// The wall friction (degrees) of the face force (h, v) on a face at α
/// (degrees) from the horizontal: its angle from the face's normal
/// (mechanism_series.py's `wall_friction`).
fn wall_friction(h: f64, v: f64, alpha: f64) -> f64 {
    let a = alpha.to_radians();
    (h * a.cos() + v * a.sin())
        .atan2(h * a.sin() - v * a.cos())
        .to_degrees()
}

/// The friction angle (degrees) a rigid block of weight w on a straight
/// band at β (degrees) mobilises under the face force (h, v)
/// (mechanism_series.py's `mobilised_phi`).
fn mobilised_phi(h: f64, v: f64, w: f64, beta: f64) -> f64 {
    90.0 - beta - (v + w).atan2(h).to_degrees()
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * (1.0 + b.abs()),
        "{what}: {a} against {b}"
    );
}

/// The balance of every increment of `history` on a face at `alpha`.
fn balance(history: &[StepRecord], alpha: f64, what: &str) {
    for r in history {
        let (h, v, w) = (r.force_h, r.force_v, column(r, "weight"));
        let beta = r.beta_deg;
        let what = format!("{what}, increment {}", r.step);
        assert!(w > 0.0 && w < r.mass, "{what}: W = {w} within the ground");
        close(column(r, "force_factor") * w, r.force, 1e-12, &what);
        close(
            wall_friction(h, v, alpha),
            column(r, "face_friction_deg"),
            1e-9,
            &format!("{what}: face friction"),
        );
        close(
            mobilised_phi(h, v, w, beta),
            r.friction_deg,
            1e-9,
            &format!("{what}: the mobilised φ"),
        );
    }
}

#[test]
fn the_first_block_is_coulombs_wedge_and_its_factor_eq_1s() {
    for name in CUTS {
        for rule in ["mean-of-angles", "angle-of-mean-shear"] {
            for ground in [&[][..], &["run.ground=\"nodes\""][..]] {
                let band = format!("choices.band_angles=\"{rule}\"");
                let set: Vec<&str> = [&[band.as_str()][..], ground].concat();
                let c = case(name, &set);
                let r = Simulation::new(&c).unwrap().step().unwrap();
                let what = format!("{name}, {rule}, {set:?}");
                let (d, alpha, gamma) = (c.blade.depth, c.blade.rake, c.soil.unit_weight);
                let beta = r.beta_deg.to_radians();
                let cot_alpha = 1.0 / alpha.to_radians().tan();
                let wedge = 0.5 * gamma * d * d * (1.0 / beta.tan() + cot_alpha);
                close(column(&r, "weight"), wedge, 1e-9, &format!("{what}: W"));
                // Fresh soil: the band at φc; the face friction at most φw.
                close(r.friction_deg, c.soil.friction.initial, 1e-12, &what);
                let delta = column(&r, "face_friction_deg");
                assert!(
                    delta.abs() <= c.blade.wall_friction + 1e-12,
                    "{what}: δ = {delta}"
                );
                let (phi, a) = (r.friction_deg.to_radians(), alpha.to_radians());
                let factor = (beta + phi).sin() / (a + beta + phi + delta.to_radians()).sin();
                close(
                    column(&r, "force_factor"),
                    factor,
                    1e-9,
                    &format!("{what}: P/W"),
                );
            }
        }
    }
}

#[test]
fn every_increment_balances_the_block_the_dem_reduction_reads() {
    for name in CUTS {
        for rule in ["mean-of-angles", "angle-of-mean-shear"] {
            let band = format!("choices.band_angles=\"{rule}\"");
            // Two depths on the vertex ground (the band softens and moves);
            // a quarter depth on nodes (d/1250 increments).
            for (ground, travel) in [(&[][..], 2.0), (&["run.ground=\"nodes\""][..], 0.25)] {
                let d = case(name, &[]).blade.depth;
                let travel = format!("run.travel={}", travel * d);
                let set: Vec<&str> = [&[band.as_str(), travel.as_str()][..], ground].concat();
                let c = case(name, &set);
                let history = Simulation::new(&c).unwrap().run_to_end(|_| {}).unwrap();
                assert!(history.len() > 50);
                balance(&history, c.blade.rake, &format!("{name}, {set:?}"));
            }
        }
    }
}
