//! The band's strength from the columns it crosses (M53,
//! `choices.band_strength = "crossed-columns"`, docs/model.md §20): its
//! flat-ground limit (Coulomb's wedge on fresh soil), its angles against an
//! independent computation on the ground a run made, the mass over a run,
//! and its refusal where it has no columns.

use crate::common;

use soilcut_model::{AngleLaw, BandAngleRule, BandStrengthRule, Case, Simulation, StepRecord};

/// `case` under the crossed columns.
fn crossed(mut case: Case) -> Case {
    case.choices.band_strength = BandStrengthRule::CrossedColumns;
    case
}

/// Table 1 S (softening only) on the vertex ground, vertices d/50 apart,
/// its pile standing at θr = 40°, steeper than any φ(ut) of its soil
/// (35° → 30°): the floor of M53 holds the pile's columns.
fn steep_pile(travel_depths: f64) -> Case {
    let mut case = common::on_vertices(common::refined("table1-s", travel_depths, 250.0), 50.0);
    case.soil.repose = 40.0;
    crossed(case)
}

/// φ of the law at ut (degrees), written out here: linear from the
/// initial value to the peak over [0, up), to the residual over [up, ur),
/// the residual beyond (docs/model.md (M23)).
fn law(angle: &AngleLaw, ut: f64, (up, ur): (f64, f64)) -> f64 {
    if ut < up {
        angle.initial + (angle.peak - angle.initial) * ut / up
    } else if ut < ur {
        angle.peak + (angle.residual - angle.peak) * (ut - up) / (ur - up)
    } else {
        angle.residual
    }
}

#[test]
fn the_first_increment_on_fresh_flat_ground_is_coulombs_wedge() {
    // Fresh flat ground: every column at φ0, standing at 0°, so the band's
    // φ is φ0 wherever it emerges and the least is Coulomb's wedge, as the
    // paper's rule's (the vertices d/50 apart: within 1e-4, as there).
    for (which, phi0) in [("fig5", 20.0), ("table1-s", 35.0), ("table1-hs", 20.0)] {
        let case = crossed(common::on_vertices(
            common::refined(which, 0.5, 250.0),
            50.0,
        ));
        let first = Simulation::new(&case).unwrap().step().unwrap();
        let expected = 0.5 * common::coulomb_kp(phi0, case.blade.wall_friction);
        let rel = (first.force_norm - expected) / expected;
        assert!(
            (-1e-12..1e-4).contains(&rel),
            "{which}: {} vs {expected}",
            first.force_norm
        );
        assert!(
            (first.friction_deg - phi0).abs() < 1e-9,
            "{which}: {first:?}"
        );
        // The paper's rule gives the same increment bit for bit in force.
        let mut paper = case.clone();
        paper.choices.band_strength = BandStrengthRule::Footprint;
        let theirs = Simulation::new(&paper).unwrap().step().unwrap();
        assert_eq!(first.force, theirs.force, "{which}");
        assert_eq!(first.x_emergence, theirs.x_emergence, "{which}");
    }
}

#[test]
fn the_band_takes_the_length_weighted_mean_of_the_columns_it_crosses() {
    // At every increment to 1.5 d: the band's φ and ψ equal the mean over
    // the pieces from the face to its emergence point, weighted by their
    // length along x, of max(φ(ut), the piece's slope angle up to θr) and
    // ψ(ut), computed here from the profile before the step; unfloored,
    // of φ(ut) and ψ(ut).
    let floored = steep_pile(1.5);
    let mut unfloored = floored.clone();
    unfloored.choices.band_strength = BandStrengthRule::CrossedColumnsUnfloored;
    let (a, b) = (angles_match(&floored, 40.0), angles_match(&unfloored, 0.0));
    assert!(a != b, "the floor changes the run");
}

/// Checks every increment's band angles of `case` against the
/// length-weighted mean with the floor's cap `cap` (degrees); returns the
/// run's forces.
fn angles_match(case: &Case, cap: f64) -> Vec<f64> {
    let soil = case.soil.clone();
    let shears = (soil.peak_shear, soil.residual_shear);
    let mut sim = Simulation::new(case).unwrap();
    let (mut floored, mut checked, mut forces) = (0, 0, Vec::new());
    while !sim.is_done() {
        let ground = sim.profile();
        let step = sim.step().unwrap();
        let xe = step.x_emergence;
        let x0 = ground[0].x;
        let (mut phi, mut psi) = (0.0, 0.0);
        for piece in ground.windows(2) {
            let (a, b) = (&piece[0], &piece[1]);
            let overlap = b.x.min(xe) - a.x;
            if overlap <= 0.0 {
                break;
            }
            let ut = a.accumulated_shear;
            let standing = ((b.y - a.y) / (b.x - a.x)).abs().atan().to_degrees();
            let strength = law(&soil.friction, ut, shears);
            if standing.min(cap) > strength {
                floored += 1;
            }
            phi += strength.max(standing.min(cap)) * overlap;
            psi += law(&soil.dilation, ut, shears) * overlap;
        }
        let run = xe - x0;
        let (phi, psi) = (phi / run, psi / run);
        assert!(
            (step.friction_deg - phi).abs() < 1e-9 * phi,
            "step {}: φ {} vs {phi}",
            step.step,
            step.friction_deg
        );
        assert!(
            (step.dilation_deg - psi).abs() < 1e-9 * phi,
            "step {}: ψ {} vs {psi}",
            step.step,
            step.dilation_deg
        );
        checked += 1;
        forces.push(step.force);
    }
    // The floor was at work where there is one: the pile's columns stand
    // steeper than their φ.
    assert!(checked > 100, "{checked}");
    assert_eq!(floored > 0, cap > 0.0, "{floored} of {checked}");
    forces
}

#[test]
fn the_crossed_columns_differ_from_the_footprint_once_the_soil_is_sheared() {
    let case = steep_pile(1.0);
    let mut paper = case.clone();
    paper.choices.band_strength = BandStrengthRule::Footprint;
    let (ours, _) = common::run(&case);
    let (theirs, _) = common::run(&paper);
    // The first increment on fresh ground the same (its recorded φ, the
    // mean of the columns' φ0, to round-off), the later ones not.
    let parted = ours
        .iter()
        .zip(&theirs)
        .position(|(a, b)| a.force != b.force);
    assert!(parted.is_some_and(|i| i >= 1), "{parted:?}");
}

/// Every increment's mass within 1e-12 of the initial mass `m0`.
fn mass_is_kept(history: &[StepRecord], m0: f64) {
    for r in history {
        let drift = (r.mass - m0).abs() / m0;
        assert!(drift < 1e-12, "step {}: {}", r.step, r.mass);
    }
}

#[test]
fn a_run_under_the_crossed_columns_keeps_its_mass() {
    // The steep pile, Fig. 5's hardening-softening soil under the midpoint
    // force, a blade raked at 60° (the standing angle in the blade's
    // plane, not the ground's sheared coordinates), and the steep pile
    // unfloored.
    let mut fig5 = crossed(common::on_vertices(
        common::refined("fig5", 2.0, 250.0),
        50.0,
    ));
    fig5.run
        .vertices_mut()
        .expect("on the vertex ground")
        .time_scheme = soilcut_model::TimeScheme::MidpointForce;
    let mut raked = steep_pile(1.0);
    raked.blade.rake = 60.0;
    let mut unfloored = steep_pile(2.0);
    unfloored.choices.band_strength = BandStrengthRule::CrossedColumnsUnfloored;
    for case in [steep_pile(2.0), fig5, raked, unfloored] {
        let (history, sim) = common::run(&case);
        mass_is_kept(&history, sim.initial_mass());
    }
}

#[test]
fn the_crossed_columns_are_refused_where_there_are_no_columns() {
    // The node grid: its nodes are no columns a band crosses.
    let mut nodes = steep_pile(0.5);
    nodes.run.ground = soilcut_model::Ground::Nodes;
    let e = Simulation::new(&nodes).expect_err("refused on the node grid");
    assert!(format!("{e}").contains("choices.band_strength"), "{e}");
    // The angle of the mean shear: each column's φ is floored on its own.
    let mut mean_shear = steep_pile(0.5);
    mean_shear.choices.band_angles = BandAngleRule::AngleOfMeanShear;
    let e = Simulation::new(&mean_shear).expect_err("refused");
    assert!(format!("{e}").contains("choices.band_strength"), "{e}");
    let mut unfloored = nodes.clone();
    unfloored.choices.band_strength = BandStrengthRule::CrossedColumnsUnfloored;
    let e = Simulation::new(&unfloored).expect_err("refused on the node grid");
    assert!(format!("{e}").contains("choices.band_strength"), "{e}");
}

#[test]
fn the_midpoint_force_shears_only_the_footprint_of_the_crossed_columns() {
    // Table 1 S (softening) under the crossed columns: the first increment
    // whose band crosses sheared soil parts from the explicit rule, with
    // the same band (the search chose it at the start) and a lower φ, by
    // no more than the law's steepest slope times ½ Δut: only the
    // footprint's columns shear over the increment, a part of those the
    // band crosses.
    let case = crossed(common::on_vertices(
        common::refined("table1-s", 0.5, 250.0),
        50.0,
    ));
    let mut midpoint = case.clone();
    midpoint
        .run
        .vertices_mut()
        .expect("on the vertex ground")
        .time_scheme = soilcut_model::TimeScheme::MidpointForce;
    let (mut e, mut m) = (
        Simulation::new(&case).unwrap(),
        Simulation::new(&midpoint).unwrap(),
    );
    let (same, a, b) = loop {
        let (a, b) = (e.step().unwrap(), m.step().unwrap());
        if a.force != b.force {
            break (e.steps_done() - 1, a, b);
        }
        assert!(!e.is_done(), "the two rules never part");
    };
    assert!(same >= 1, "the first increment is fresh: explicit");
    assert_eq!((a.x_emergence, a.beta_deg), (b.x_emergence, b.beta_deg));
    let f = case.soil.friction;
    let steepest = (f.peak - f.residual) / (case.soil.residual_shear - case.soil.peak_shear);
    let moved = a.friction_deg - b.friction_deg;
    assert!(
        b.force < a.force && moved > 0.0 && moved < steepest * 0.5 * a.slip,
        "{moved} degrees: {a:?} vs {b:?}"
    );
}
