//! Cases the vertex ground once lost soil on, stopped on or panicked on
//! (issue 38), each run at the vertex ground's defaults: a band much
//! thinner than the vertex spacing, and a band that stays at one emergence
//! point for many increments while it dilates.

use crate::common;
use soilcut_model::{AngleLaw, Case, Simulation};

/// The law through (initial, peak, residual), degrees.
fn law(initial: f64, peak: f64, residual: f64) -> AngleLaw {
    AngleLaw {
        initial,
        peak,
        residual,
    }
}

/// The "thin-band" case: d = 1, dB = `band_width_d50` d50, at the
/// vertex ground's defaults (d/350, vertices d/50, the midpoint force).
fn thin_band(band_width_d50: f64) -> Case {
    let mut case = crate::common::refined("table1-s", 1.45, 350.0);
    case.blade.depth = 1.0;
    case.blade.wall_friction = 2.93;
    case.soil.unit_weight = 15000.0;
    case.soil.friction = law(19.92, 41.81, 32.99);
    case.soil.dilation = law(-7.80, 18.94, -1.47);
    case.soil.repose = 32.99;
    case.soil.peak_shear = 0.02933;
    case.soil.residual_shear = 0.05081;
    case.soil.band_width = band_width_d50 * 0.008312;
    defaults_on_vertices(case, 1.45)
}

/// `case` at the vertex ground's defaults over `travel_depths`.
fn defaults_on_vertices(mut case: Case, travel_depths: f64) -> Case {
    case.run.travel = travel_depths * case.blade.depth;
    crate::common::at_vertex_defaults(case)
}

/// Runs `case` to its end, checking after every increment that the mass
/// is kept to 1e-11 and that no piece weighs nothing or less.
fn runs_with_its_mass(case: &Case) {
    let mut sim = Simulation::new(case).expect("a valid case");
    let m0 = sim.initial_mass();
    while !sim.is_done() {
        let record = sim
            .step()
            .unwrap_or_else(|e| panic!("{}: stopped: {e}", case.name));
        let drift = (record.mass - m0).abs() / m0;
        assert!(drift < 1e-11, "step {}: mass drift {drift:e}", record.step);
        let light = sim.profile().iter().find(|p| p.unit_weight <= 0.0).copied();
        assert!(light.is_none(), "step {}: {light:?}", record.step);
    }
}

#[test]
fn a_band_thinner_than_the_vertices_keeps_the_mass() {
    // dB = d/200, d/300 and d/600 against vertices d/50 apart: the band's
    // upper boundary lies within the snap of the emergence vertex, which
    // once took it and left the band no pieces to weigh (drift 1e-3 at
    // d/200, 3e-2 at d/300).
    for n in [0.6, 0.4, 0.2] {
        runs_with_its_mass(&thin_band(n));
    }
}

#[test]
fn a_band_that_stays_and_dilates_keeps_its_soil() {
    // The "panic" case to the last digit: a long flat band that
    // stays at one emergence point for about a hundred increments while
    // it dilates (ψr = 4.6°). The block's columns once weighed the band's
    // dilation under them at their own γ, the band's few pieces at the
    // emergence point paid for it, their γ fell below zero and a later
    // footprint's mean φ passed −90° (a panic in `trig::sin_cos`).
    let mut case = crate::common::refined("table1-s", 1.0, 250.0);
    case.name = "panic".into();
    case.blade.depth = 0.2;
    case.blade.wall_friction = 25.39902906109709;
    case.soil.friction = law(39.71448531646739, 42.78621574339553, 33.13312119129891);
    case.soil.dilation = law(3.665056311319976, 19.844050473281914, 4.618852557796412);
    case.soil.peak_shear = 0.007151137083216861;
    case.soil.residual_shear = 0.0707413879947521;
    case.soil.band_width = 10.439456416938903 * 0.0032162916841882135;
    case.soil.repose = 42.21746898551972;
    case.soil.surcharge = 0.006764476154435983;
    case.choices.band_angles = soilcut_model::BandAngleRule::AngleOfMeanShear;
    let mut case = defaults_on_vertices(case, 0.6390666354180224 / 0.2);
    case.run.increment = 0.0008;
    case.run
        .vertices_mut()
        .expect("on the vertex ground")
        .samples_per_band = 1.0;
    runs_with_its_mass(&case);
}

/// A controller that pulls the tip up faster than the face can hold soil
/// (from 20 to 0.3 in one increment of d/500; the C ABI's fuzz corpus):
/// the tip path's strip is taken from as much ground as keeps the face
/// vertex at the tip's new depth, so every force after it is positive
/// and the soil is kept (before: the face sank 0.34 below the tip and the
/// forces went negative).
#[test]
fn a_tip_pulled_up_at_once_keeps_the_face_at_the_tip() {
    let case = common::original(5.0, 500.0);
    let case = common::on_vertices(case, 50.0);
    let mut sim = Simulation::new(&case).unwrap();
    let mut history = sim.advance_to(0.04, Some(0.3)).unwrap();
    history.extend(sim.advance_to(2.0, Some(0.3)).unwrap());
    for r in &history {
        assert!(r.force > 0.0, "step {}: force {}", r.step, r.force);
        let drift = r.mass / sim.initial_mass() - 1.0;
        assert!(drift.abs() < 1e-12, "step {}: drift {drift:e}", r.step);
    }
    let face = sim.profile()[0].y;
    assert!(face >= -0.3 - 1e-12, "the face at {face}, below the tip");
    // Pulled up over three increments of d/100, the soil above the tip at
    // the face is thinner than v0: no band emerges within v0 of the face,
    // which would carry the face over its emergence point (a piece of no
    // length, and the mass NaN, before).
    let case = common::original(5.0, 100.0);
    let mut sim = Simulation::new(&common::on_vertices(case, 50.0)).unwrap();
    let history = sim.advance_to(1.6, Some(1.0)).unwrap();
    for r in &history {
        let drift = r.mass / sim.initial_mass() - 1.0;
        assert!(r.force >= 0.0 && drift.abs() < 1e-12, "{r:?}");
    }
    // One v0 ahead of the face to round-off is within it (the face at
    // 0.4 + 0.2, the band at 0.6000000000000001: the mass went NaN): the
    // run stops with no mechanism, as the node grid does an increment
    // earlier, and keeps its soil.
    let case = common::original(1.0, 100.0);
    let mut sim = Simulation::new(&common::on_vertices(case, 50.0)).unwrap();
    sim.advance_to(0.04, Some(1.0)).unwrap();
    let stopped = sim.advance_to(1.2, Some(0.5));
    assert!(stopped.is_err(), "{stopped:?}");
    assert!((sim.mass() / sim.initial_mass() - 1.0).abs() < 1e-12);
}

/// Issue 50's case: Fig. 5 with every length × 0.2775 (d = 5.5497…) over
/// 2 d at the vertex ground's defaults. Its ground, 10 d over d/50, ended
/// in a piece of length 0 (10 d / (d/50) rounds to 500.00000000000006);
/// the search grew the ground past it, and at increment 64 a band emerging
/// beyond it gave that piece 0 / 0 for its unit weight: the mass NaN and
/// every force 0 from there, behind a run that finished.
#[test]
fn fig5_scaled_down_keeps_every_number_finite() {
    let mut case = common::refined("fig5", 2.0, 350.0);
    let d = 5.549742791184853;
    let scale = d / case.blade.depth;
    case.blade.depth = d;
    case.soil.peak_shear *= scale;
    case.soil.residual_shear = 1.1099485582369706;
    case.soil.band_width = 15.0 * 0.1664922837355456;
    let case = defaults_on_vertices(case, 2.0);
    assert_eq!(case.run.travel, 11.099485582369706);
    let mut sim = Simulation::new(&case).expect("a valid case");
    let history = sim.run_to_end(|_| {}).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(history.len(), 700);
    for r in &history {
        assert_eq!(r.not_finite(), None, "{r:?}");
        let drift = r.mass / sim.initial_mass() - 1.0;
        assert!(drift.abs() < 1e-11, "step {}: drift {drift:e}", r.step);
    }
}
