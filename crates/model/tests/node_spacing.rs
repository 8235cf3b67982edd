//! The coarse node grid (node spacing h a whole multiple of the increment
//! v0): the same physics as the reference grid h = v0, discretised on fewer
//! nodes. Mass stays exact, the first increment is Coulomb's wedge, and the
//! results approach the reference grid's as h shrinks.

use crate::common;

use soilcut_model::{Case, Simulation};

/// `case` with v0 = d / `per_v0` and h = d / `per_h`.
fn with_grid(mut case: Case, per_v0: f64, per_h: f64) -> Case {
    let d = case.blade.depth;
    case.run.increment = d / per_v0;
    case.run.node_spacing = d / per_h;
    case
}

fn relative_mass_drift(sim: &Simulation) -> f64 {
    (sim.mass() - sim.initial_mass()) / sim.initial_mass()
}

/// Mean P/(γ0 d²) over each unit of u/d.
fn window_means(case: &Case) -> Vec<f64> {
    let (history, _) = common::run(case);
    let d = case.blade.depth;
    common::window_means(&history, d, (case.run.travel / d).round() as usize)
}

fn largest_deviation(a: &[f64], reference: &[f64]) -> f64 {
    a.iter()
        .zip(reference)
        .map(|(x, r)| (x / r - 1.0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn mass_is_exact_on_a_coarse_grid() {
    let cases = [
        common::refined("fig5", 1.5, 100.0),
        common::refined("table1-hs", 1.5, 100.0),
        common::refined("table1-s", 1.5, 100.0),
        common::original(1.5, 100.0),
    ];
    for case in cases {
        for k in [2.0, 5.0] {
            let case = with_grid(case.clone(), 50.0 * k, 50.0);
            let (history, sim) = common::run(&case);
            let drift = relative_mass_drift(&sim);
            assert!(drift.abs() < 1e-12, "{} k={k}: drift {drift:e}", case.name);
            let initial_area = sim.initial_mass() / case.soil.unit_weight;
            let surface = sim.surface().expect("the node grid");
            let area = surface.area(surface.face.node);
            let dilation: f64 = history.iter().map(|r| r.dilation_area).sum();
            let mismatch = (area - initial_area - dilation).abs() / initial_area;
            assert!(
                mismatch < 1e-12,
                "{} k={k}: area ≠ dilation ({mismatch:e})",
                case.name
            );
        }
    }
}

#[test]
fn mass_is_exact_with_a_raked_blade_and_a_depth_path() {
    let mut raked = common::refined("table1-hs", 1.5, 100.0);
    raked.blade.rake = 60.0;
    raked.soil.repose = 25.0;
    let mut deepening = common::original(1.5, 100.0);
    deepening.blade.depth_path = vec![[0.0, 10.0], [20.0, 20.0]];
    for case in [raked, deepening] {
        let case = with_grid(case, 200.0, 50.0);
        let (_, sim) = common::run(&case);
        let drift = relative_mass_drift(&sim);
        assert!(drift.abs() < 1e-12, "{}: drift {drift:e}", case.name);
    }
}

#[test]
fn first_increment_is_coulomb_on_a_coarse_grid() {
    for (phi, phi_w) in [(20.0, 10.0), (30.0, 0.0), (35.0, 10.0), (25.0, 5.0)] {
        let mut case = with_grid(common::original(1.0, 100.0), 800.0, 200.0);
        case.soil.friction.initial = phi;
        case.soil.friction.peak = phi;
        case.soil.friction.residual = phi;
        case.blade.wall_friction = phi_w;
        let got = Simulation::new(&case).unwrap().step().unwrap().force_norm;
        let expected = 0.5 * common::coulomb_kp(phi, phi_w);
        let rel = (got - expected) / expected;
        assert!(
            (0.0..1e-6).contains(&rel),
            "φ={phi} φw={phi_w}: {got} vs {expected} ({rel:e})"
        );
    }
}

#[test]
fn coarse_grids_approach_the_reference_grid_in_hardening_sand() {
    // Fig. 8b's loose sand hardens and never softens: there the coarse
    // grid converges to the reference grid's limit (docs/model.md §9).
    let case = common::refined("fig8b", 2.0, 100.0);
    let reference = window_means(&with_grid(case.clone(), 1000.0, 1000.0));
    let deviation = |per_h| {
        largest_deviation(
            &window_means(&with_grid(case.clone(), 1000.0, per_h)),
            &reference,
        )
    };
    let (coarse, finer) = (deviation(25.0), deviation(100.0));
    assert!(coarse < 0.01, "h = d/25 within 1 % of h = v0: {coarse}");
    assert!(finer < coarse, "h = d/100: {finer}, h = d/25: {coarse}");
}

#[test]
fn node_spacing_must_be_a_whole_multiple_of_the_increment() {
    for per_h in [250.0, 80.0, 1000.0] {
        let case = with_grid(common::original(1.0, 100.0), 200.0, per_h);
        let err = case.validate().expect_err("not a whole multiple");
        assert_eq!(err.key, "run.node_spacing", "{err}");
        assert!(err.to_string().contains("whole multiple"), "{err}");
    }
    let case = with_grid(common::original(1.0, 100.0), 200.0, 40.0);
    assert!(case.validate().is_ok());
}
