//! The first increment on flat ground is Coulomb's passive wedge:
//! P / (γ0 d²) = ½ Kp, Kp = cos²φ / (cos φw [1 − √(sin(φ+φw) sin φ / cos φw)]²).
//!
//! The grid limits β to the angles of the nodes (x_j = j v0); the error in P
//! is second order in the angle step, so d / v0 = 2000 nodes per depth puts
//! it below 1e-6.

use crate::common;

use soilcut_model::Simulation;

fn first_force_norm(phi: f64, phi_w: f64, per_depth: f64) -> f64 {
    let mut case = common::original(1.0, per_depth);
    case.soil.friction.initial = phi;
    case.soil.friction.peak = phi;
    case.soil.friction.residual = phi;
    case.blade.wall_friction = phi_w;
    Simulation::new(&case).unwrap().step().unwrap().force_norm
}

#[test]
fn matches_coulomb_passive_wedge() {
    for (phi, phi_w) in [
        (20.0, 10.0),
        (30.0, 0.0),
        (35.0, 10.0),
        (40.0, 20.0),
        (25.0, 5.0),
    ] {
        let expected = 0.5 * common::coulomb_kp(phi, phi_w);
        let got = first_force_norm(phi, phi_w, 2000.0);
        let rel = (got - expected).abs() / expected;
        assert!(
            rel < 1e-6,
            "φ={phi} φw={phi_w}: {got} vs {expected} (rel {rel:e})"
        );
        assert!(
            got >= expected * (1.0 - 1e-12),
            "grid search cannot beat the exact minimum"
        );
    }
}

/// The model's first force against the values quoted outside it: the
/// paper's hardening-softening runs start "from roughly 1.3" (φc = 20°,
/// φw = 10°, docs/model.md §2.10: 1.3177 at the default increment d/500),
/// and a smooth wall at φ = 30° is Rankine's ½ Kp = 1.5.
#[test]
fn paper_reference_values() {
    let paper = first_force_norm(20.0, 10.0, 500.0);
    assert!((paper - 1.3177).abs() < 5e-5, "{paper}");
    let rankine = first_force_norm(30.0, 0.0, 2000.0);
    assert!((rankine - 1.5).abs() < 1e-6, "{rankine}");
}

#[test]
fn error_shrinks_with_refinement() {
    let expected = 0.5 * common::coulomb_kp(20.0, 10.0);
    let coarse = first_force_norm(20.0, 10.0, 50.0) - expected;
    let fine = first_force_norm(20.0, 10.0, 400.0) - expected;
    assert!(
        coarse > 0.0 && fine >= 0.0 && fine < coarse / 10.0,
        "{coarse} {fine}"
    );
}

/// With cohesion, adhesion and a surcharge the first increment on flat
/// ground is the least force of the trial wedge (FEE) for a vertical blade.
#[test]
fn cohesion_adhesion_and_surcharge_match_the_trial_wedge() {
    for (c, a, q) in [
        (2.0, 0.0, 0.0),
        (0.0, 1.5, 0.0),
        (0.0, 0.0, 3.0),
        (1.0, 0.5, 2.0),
    ] {
        let mut case = common::original(0.05, 2000.0);
        case.soil.friction = soilcut_model::AngleLaw::constant(30.0);
        case.soil.cohesion = c;
        case.blade.adhesion = a;
        case.soil.surcharge = q;
        let expected = soilcut_model::analytic::Wedge::of_case(&case)
            .fee()
            .unwrap();
        let got = Simulation::new(&case).unwrap().step().unwrap();
        let rel = (got.force - expected.force).abs() / expected.force;
        assert!(
            rel < 1e-4,
            "c={c} a={a} q={q}: {} vs {}",
            got.force,
            expected.force
        );
        let beta = expected.failure_angle.to_degrees();
        assert!(
            (got.beta_deg - beta).abs() < 0.05,
            "β* {} vs {beta}",
            got.beta_deg
        );
    }
}
