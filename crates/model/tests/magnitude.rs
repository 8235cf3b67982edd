//! `Case::validate`'s magnitude bounds (`MAGNITUDE`): a value just beyond
//! them is refused naming its key and the range; a case at them runs with
//! finite forces and masses. Without them `soil.unit_weight = 1e306` gave
//! an infinite initial mass (docs/fuzzing.md).

use crate::common;

use common::original;
use soilcut_model::case::MAX_VERTICES;
use soilcut_model::{Case, Simulation, MAGNITUDE};

const LEAST: f64 = MAGNITUDE[0];
const GREATEST: f64 = MAGNITUDE[1];

/// Sets one key of a case.
type Setter = fn(&mut Case, f64);

/// The keys a magnitude bound holds for, with how to set each on a case.
fn keys() -> Vec<(&'static str, Setter)> {
    vec![
        ("blade.depth", |c, v| c.blade.depth = v),
        ("blade.width", |c, v| c.blade.width = Some(v)),
        ("blade.adhesion", |c, v| c.blade.adhesion = v),
        ("soil.unit_weight", |c, v| c.soil.unit_weight = v),
        ("soil.cohesion", |c, v| c.soil.cohesion = v),
        ("soil.surcharge", |c, v| c.soil.surcharge = v),
        ("soil.residual_shear", |c, v| c.soil.residual_shear = v),
        ("run.travel", |c, v| c.run.travel = v),
        ("bin.length", |c, v| c.bin.length = Some(v)),
    ]
}

fn refused(case: &Case, key: &str) {
    let e = case.validate().expect_err(key);
    assert_eq!(e.key, key, "{e}");
    assert!(e.message.contains("[1e-20, 1e20]"), "{e}");
}

#[test]
fn values_just_beyond_the_magnitudes_are_refused_naming_the_key() {
    assert_eq!(MAGNITUDE, [1e-20, 1e20]);
    for (key, set) in keys() {
        for value in [GREATEST * (1.0 + 1e-15), 1e306] {
            let mut case = original(1.0, 100.0);
            set(&mut case, value);
            refused(&case, key);
        }
    }
    // Below the least magnitude: the keys that must be > 0.
    for (key, set) in keys().into_iter().take(2) {
        let mut case = original(1.0, 100.0);
        set(&mut case, LEAST * (1.0 - 1e-15));
        refused(&case, key);
    }
    let mut case = original(1.0, 100.0);
    case.soil.unit_weight = 0.99e-20;
    refused(&case, "soil.unit_weight");
    case = original(1.0, 100.0);
    case.soil.cohesion = 1e-300;
    refused(&case, "soil.cohesion");
    case = original(1.0, 100.0);
    case.blade.depth_path = vec![[0.0, 10.0], [1e21, 20.0]];
    let e = case.validate().unwrap_err();
    assert_eq!(e.key, "blade.depth_path", "{e}");
    assert!(e.message.contains("point 1"), "{e}");
}

/// The original test case with its lengths scaled so that the depth is
/// `depth` (and its node spacing depth / 100), its unit weight and loads
/// `gamma` and `stress`, and a blade `width` wide.
fn scaled(depth: f64, gamma: f64, stress: f64, width: Option<f64>) -> Case {
    let mut case = original(0.1, 100.0);
    let k = depth / case.blade.depth;
    case.blade.depth = depth;
    case.blade.width = width;
    case.run.travel *= k;
    case.run.increment *= k;
    case.soil.residual_shear *= k;
    case.soil.unit_weight = gamma;
    case.soil.cohesion = stress;
    case.soil.surcharge = stress;
    case
}

fn runs_finite(case: &Case) {
    case.validate().unwrap();
    let mut sim = Simulation::new(case).unwrap();
    let initial = sim.initial_mass();
    assert!(initial.is_finite() && initial > 0.0, "{initial}");
    for _ in 0..3 {
        let r = sim.step().unwrap();
        for v in [r.force, r.force_norm, r.force_h, r.force_v, r.mass] {
            assert!(v.is_finite(), "{r:?}");
        }
        assert!(r.force > 0.0 && r.force_norm > 0.0, "{r:?}");
        assert!(((r.mass + r.mass_spilled) / initial - 1.0).abs() < 1e-9);
    }
}

#[test]
fn cases_at_the_magnitudes_run_with_finite_forces() {
    // The most: a blade 1e20 deep and wide in soil of unit weight, cohesion
    // and surcharge 1e20, a force of some 1e80 (with the depths at
    // 1e20 the spacing is 1e18; the width's crescents weigh γ d³).
    runs_finite(&scaled(GREATEST, GREATEST, GREATEST, None));
    runs_finite(&scaled(GREATEST, GREATEST, GREATEST, Some(GREATEST)));
    // The least: increment and node spacing 1e-20, unit weight and loads
    // 1e-20, a force of some 1e-56.
    runs_finite(&scaled(100.0 * LEAST, LEAST, LEAST, None));
    runs_finite(&scaled(100.0 * LEAST, LEAST, LEAST, Some(100.0 * LEAST)));
    // The widest ratios: a deep blade in the lightest soil with the
    // greatest cohesion, and the reverse.
    runs_finite(&scaled(GREATEST, LEAST, GREATEST, None));
    runs_finite(&scaled(100.0 * LEAST, GREATEST, LEAST, Some(GREATEST)));
}

#[test]
fn a_ground_of_more_points_than_the_bound_is_refused_naming_its_spacing() {
    // A vertex spacing of 1e-12 asked for 1.8e14 vertices (a panic on
    // allocation); it is refused naming `run.vertex_spacing`, as too fine
    // a node grid is refused naming `run.increment`, its spacing.
    let too_fine = |case: &Case, key: &str| {
        let e = case.validate().expect_err(key);
        assert_eq!(e.key, key, "{e}");
        assert!(e.message.contains("too fine"), "{e}");
    };
    // At an increment of the spacing: vertices closer than a quarter of
    // it are refused on their own (`run.vertex_spacing`'s range).
    let mut vertices = crate::common::on_vertices(original(1.0, 250.0), 50.0);
    let reach = vertices.run.travel + 8.0 * vertices.blade.depth;
    let mut at_spacing = |h: f64| {
        vertices.run.increment = h;
        vertices
            .run
            .vertices_mut()
            .expect("on the vertex ground")
            .spacing = h;
        vertices.clone()
    };
    too_fine(
        &at_spacing(reach / (2.0 * MAX_VERTICES)),
        "run.vertex_spacing",
    );
    // Just inside the bound, the vertex ground is taken.
    assert!(at_spacing(reach / (0.9 * MAX_VERTICES)).validate().is_ok());
    let mut nodes = original(1.0, 250.0);
    nodes.run.ground = soilcut_model::Ground::Nodes;
    nodes.run.increment = 2e-6;
    too_fine(&nodes, "run.increment");
}
