//! A blade that deepens while it cuts (`blade.depth_path`).

mod common;

use soilcut_model::Simulation;

/// The original model's soil, the tip going from 10 to 20 over the first
/// 40 of travel, then constant.
fn deepening(per_depth: f64) -> soilcut_model::Case {
    let mut case = common::original(3.0, per_depth);
    case.blade.depth_path = vec![[0.0, 10.0], [40.0, 20.0]];
    case
}

#[test]
fn first_increment_is_coulomb_at_the_starting_depth() {
    let case = deepening(200.0);
    let record = Simulation::new(&case).unwrap().step().unwrap();
    let expected = 0.5 * common::coulomb_kp(35.0, 10.0) * 10.0 * 10.0;
    assert!((record.force - expected).abs() < 1e-3 * expected);
    assert_eq!(record.depth, 10.0);
}

#[test]
fn soil_is_conserved_counting_what_the_tip_passes_over() {
    let case = deepening(100.0);
    let (history, sim) = common::run(&case);
    let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
    assert!(drift.abs() < 1e-12, "drift {drift:e}");
    let last = history.last().unwrap();
    assert_eq!(last.depth, 20.0);
    assert!(history.windows(2).all(|w| w[1].depth >= w[0].depth));
}

#[test]
fn force_grows_with_depth_as_its_square() {
    // While the tip deepens the force follows d² times the growing pile's
    // share: the slope of log P against log d over the deepening is 2.9
    // here, not 1 (proportional) nor 4.
    let case = deepening(100.0);
    let (history, _) = common::run(&case);
    let deepening: Vec<_> = history.iter().filter(|r| r.u < 40.0).collect();
    let (a, b) = (deepening[0], deepening[deepening.len() - 1]);
    let slope = (b.force / a.force).ln() / (b.depth / a.depth).ln();
    assert!((2.0..3.5).contains(&slope), "log-log slope {slope}");
}
