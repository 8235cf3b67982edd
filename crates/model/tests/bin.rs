//! The soil bin's end wall (`bin.length`): no slip line emerges beyond it,
//! the pile stops at it, soil is conserved, and a bin too short for the
//! travel fails with a clear error.

use crate::common;

use soilcut_model::{Simulation, StepError};

#[test]
fn a_wall_beyond_every_mechanism_changes_nothing() {
    // On the node grid, and on the vertex ground (which grows its ground
    // as the search needs, up to the wall).
    for case in [
        common::original(2.0, 50.0),
        common::at_vertex_defaults(common::refined("fig5", 2.0, 350.0)),
    ] {
        let (free, _) = common::run(&case);
        let mut walled = case.clone();
        walled.bin.length = Some(60.0 * case.blade.depth);
        let (bounded, _) = common::run(&walled);
        assert_eq!(free, bounded, "{}", case.name);
    }
}

#[test]
fn slip_lines_stop_at_the_wall_and_the_pile_against_it_keeps_its_mass() {
    for mut case in [
        common::original(3.0, 50.0),
        common::refined("table1-hs", 3.0, 50.0),
    ] {
        let d = case.blade.depth;
        let wall = 6.0 * d;
        case.bin.length = Some(wall);
        let (history, sim) = common::run(&case);
        assert!(history.iter().all(|r| r.x_emergence < wall));
        // Unbounded, the same cut's bands reach beyond where the wall stands.
        case.bin.length = None;
        let (free, _) = common::run(&case);
        assert!(free.iter().any(|r| r.x_emergence > wall), "{}", case.name);
        let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
        assert!(drift.abs() < 1e-12, "{}: drift {drift:e}", case.name);
        let profile = sim.profile();
        let last = profile.last().unwrap();
        assert!((last.x - wall).abs() < 1e-9, "ground ends at {}", last.x);
    }
}

#[test]
fn a_bin_too_short_for_the_travel_fails_clearly() {
    let mut case = common::original(4.0, 50.0);
    case.bin.length = Some(case.run.travel + 2.0 * case.run.increment);
    let mut sim = Simulation::new(&case).unwrap();
    let err = sim.run_to_end(|_| {}).unwrap_err();
    assert!(matches!(err, StepError::NoMechanismBeforeWall { .. }));
    assert!(err.to_string().contains("bin.length"), "{err}");
}

#[test]
fn bin_length_is_validated() {
    let mut case = common::original(3.0, 50.0);
    case.bin.length = Some(case.run.travel);
    assert_eq!(case.validate().unwrap_err().key, "bin.length");
    case.bin.length = Some(f64::NAN);
    assert_eq!(case.validate().unwrap_err().key, "bin.length");
    case.bin.length = Some(10.0 * case.blade.depth);
    assert!(case.validate().is_ok());
    case.blade.rake = 60.0;
    let e = case.validate().unwrap_err();
    assert_eq!(e.key, "bin.length");
    assert!(e.message.contains("vertical"), "{}", e.message);
}

#[test]
fn on_the_vertex_ground_bands_stop_at_the_wall_and_the_pile_keeps_its_mass() {
    for which in ["table1-hs", "fig5"] {
        let mut case = common::at_vertex_defaults(common::refined(which, 3.0, 350.0));
        let d = case.blade.depth;
        let wall = 5.0 * d;
        case.bin.length = Some(wall);
        let (history, sim) = common::run(&case);
        assert!(history.iter().all(|r| r.x_emergence < wall), "{which}");
        case.bin.length = None;
        let (free, _) = common::run(&case);
        assert!(free.iter().any(|r| r.x_emergence > wall), "{which}");
        let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
        assert!(drift.abs() < 1e-11, "{which}: drift {drift:e}");
        let profile = sim.profile();
        let last = profile.last().unwrap();
        assert_eq!(last.x, wall, "{which}: the ground ends at the wall");
        // The pile stands against the wall: the soil there rose.
        assert!(last.y > 0.0, "{which}: {last:?}");
    }
}

#[test]
fn on_the_vertex_ground_a_bin_too_short_for_the_travel_fails_clearly() {
    let mut case = common::at_vertex_defaults(common::refined("table1-hs", 4.0, 350.0));
    case.bin.length = Some(case.run.travel + 2.0 * case.blade.depth / 50.0);
    let mut sim = Simulation::new(&case).unwrap();
    let err = sim.run_to_end(|_| {}).unwrap_err();
    assert!(
        matches!(err, StepError::NoMechanismBeforeWall { .. }),
        "{err}"
    );
    assert!(err.to_string().contains("bin.length"), "{err}");
}
