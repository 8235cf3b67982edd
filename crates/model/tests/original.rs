//! The original model's reported features: conservation and softening.

use crate::common;

use soilcut_model::Summary;

#[test]
fn area_is_conserved_to_round_off() {
    let case = common::original(5.0, 100.0);
    let (history, sim) = common::run(&case);
    let summary = Summary::new(&case, &history, sim.initial_mass());
    assert!(
        summary.mass_drift_rel.abs() < 1e-12,
        "{:e}",
        summary.mass_drift_rel
    );
}

#[test]
fn band_stays_while_softening_then_jumps() {
    let case = common::original(5.0, 250.0);
    let (history, sim) = common::run(&case);
    let summary = Summary::new(&case, &history, sim.initial_mass());
    assert!(
        summary.peaks.len() >= 2,
        "distinct peaks: {:?}",
        summary.peaks
    );
    // Right after the first jump the band stays put while the force falls.
    let jump = summary.band_jumps[0];
    let x = history[jump].x_emergence;
    let stay = history[jump..]
        .iter()
        .take_while(|r| r.x_emergence == x)
        .count();
    assert!(stay > 10, "band stays only {stay} increments");
    let during = &history[jump..jump + stay];
    let lowest = during.iter().map(|r| r.force).fold(f64::INFINITY, f64::min);
    assert!(
        lowest < 0.97 * history[jump].force,
        "force must fall while the band softens"
    );
    assert!(during
        .windows(2)
        .all(|w| w[1].friction_deg <= w[0].friction_deg));
    assert!((during[stay - 1].friction_deg - case.soil.friction.residual).abs() < 1e-9);
}
