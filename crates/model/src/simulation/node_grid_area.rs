//! The node grid's area against the band's dilation (docs/model.md §4):
//! its nodes are the model's own state, read here inside the crate.

use super::{Discretised, Simulation};
use crate::common;
use crate::AngleLaw;

/// Area of soil in front of the blade on the node grid.
fn area(sim: &Simulation) -> f64 {
    let Discretised::Nodes(grid) = &sim.ground else {
        panic!("common::refined runs on the node grid")
    };
    grid.surface.area(sim.steps_done())
}

#[test]
fn mass_is_conserved_and_area_grows_by_the_band_dilation() {
    for which in ["fig5", "table1-hs", "table1-s"] {
        let case = common::refined(which, 1.5, 100.0);
        let (history, sim) = common::run(&case);
        let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
        assert!(drift.abs() < 1e-9, "{which}: mass drift {drift:e}");
        let d = case.blade.depth;
        let initial_area = sim.initial_mass() / case.soil.unit_weight;
        let area = area(&sim);
        let dilation: f64 = history.iter().map(|r| r.dilation_area).sum();
        assert!(
            dilation.abs() > 1e-3 * d * d,
            "{which}: the band must change volume"
        );
        let mismatch = (area - initial_area - dilation).abs() / initial_area;
        assert!(
            mismatch < 1e-9,
            "{which}: area gain ≠ dilation ({mismatch:e})"
        );
    }
}

#[test]
fn without_dilation_area_is_conserved() {
    let mut case = common::refined("fig5", 1.5, 100.0);
    case.soil.dilation = AngleLaw::constant(0.0);
    let (history, sim) = common::run(&case);
    let initial_area = sim.initial_mass() / case.soil.unit_weight;
    let drift = (area(&sim) - initial_area) / initial_area;
    assert!(drift.abs() < 1e-12, "area drift {drift:e}");
    assert!(history.iter().all(|r| r.dilation_area == 0.0));
}

/// With ψ ≠ 0 the area the ground gains is the band's dilation, at every
/// increment; and that gain converges when the increment is halved (its
/// discretisation error shrinks): Table 1 S over 2 d.
#[test]
fn area_gain_is_the_dilation_and_converges_with_the_increment() {
    let gain = |per_depth: f64| {
        let case = common::refined("table1-s", 2.0, per_depth);
        let (history, sim) = common::run(&case);
        let initial_area = sim.initial_mass() / case.soil.unit_weight;
        let gained = area(&sim) - initial_area;
        let dilation: f64 = history.iter().map(|r| r.dilation_area).sum();
        assert!(
            (gained - dilation).abs() < 1e-9 * initial_area,
            "{per_depth}"
        );
        gained
    };
    // Measured with M26's dilation gap (issue 38): 64.54 at d/100, 64.04,
    // 63.64 and 63.71 at d/800; d/100 is not yet in the asymptotic range.
    let (coarse, mid, fine) = (gain(200.0), gain(400.0), gain(800.0));
    assert!(coarse > 0.0, "dilatant band: the ground grows");
    let (first, second) = ((coarse - mid).abs(), (mid - fine).abs());
    assert!(second < 0.5 * first, "changes {first} then {second}");
}
