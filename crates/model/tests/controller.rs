//! A controller commands a depth at every tick, most ticks between
//! increments: the command holds until the next increment takes it
//! (docs/model.md §17.2, issue 50 item 7), and the run is the one of the
//! case with the depth path it gained.

use crate::common;

use soilcut_model::{Case, Simulation, StepRecord};

/// Ticks of d/1000 to `travel_depths` d, the tip commanded at every tick
/// along a half sine from d up to 0.8 d and back: the records and the
/// case steered.
fn controlled(case: &Case, travel_depths: f64) -> (Vec<StepRecord>, Case) {
    let d = case.blade.depth;
    let mut sim = Simulation::new(case).unwrap();
    let mut records = Vec::new();
    let ticks = (1000.0 * travel_depths) as usize;
    for k in 1..=ticks {
        let x = k as f64 * d / 1000.0;
        let depth = d * (1.0 - 0.2 * (k as f64 / ticks as f64 * std::f64::consts::PI).sin());
        let made = sim
            .advance_to(x, Some(depth))
            .unwrap_or_else(|e| panic!("tick {k}, x = {x}: {e}"));
        records.extend(made);
    }
    (records, sim.case().clone().into_case())
}

#[test]
fn a_depth_commanded_between_increments_holds_until_the_next_one() {
    let nodes = common::original(1.0, 50.0);
    let vertices = common::on_vertices(common::refined("fig5", 0.5, 50.0), 25.0);
    for (case, steps) in [(nodes, 50), (vertices, 25)] {
        let (records, steered) = controlled(&case, case.run.travel / case.blade.depth);
        assert_eq!(records.len(), steps);
        // The tip did move: the commands were taken, not dropped.
        let least = records.iter().map(|r| r.depth).fold(f64::MAX, f64::min);
        assert!(least < 0.85 * 20.0, "{}: {least}", case.name);
        // The steered run is the run of the case it leaves, bit for bit.
        let (again, _) = common::run(&steered);
        assert_eq!(again, records, "{}", case.name);
    }
}

#[test]
fn a_held_depth_is_taken_by_the_next_increment_whoever_makes_it() {
    let c = common::original(1.0, 50.0);
    let (d, v0) = (c.blade.depth, c.run.increment);
    let mut sim = Simulation::new(&c).unwrap();
    sim.advance_to(2.5 * v0, None).unwrap();
    let u0 = sim.blade_position();
    // Behind the blade (x < u0), no increment: the command is held, and a
    // later one between the same increments replaces it.
    assert!(sim.advance_to(2.6 * v0, Some(0.9 * d)).unwrap().is_empty());
    assert!(sim.advance_to(2.8 * v0, Some(0.8 * d)).unwrap().is_empty());
    assert_eq!(sim.tip_depth(), d);
    let path = &sim.case().blade.depth_path;
    assert_eq!(path, &vec![[u0, d], [u0 + v0, 0.8 * d]]);
    let restored = Simulation::from_snapshot(&sim.snapshot()).unwrap();
    assert_eq!(restored.case(), sim.case());
    // The increment starts from the tip where it is and takes it there.
    assert_eq!(sim.step().unwrap().depth, d);
    assert_eq!(sim.tip_depth(), 0.8 * d);
    assert_eq!(sim.step().unwrap().depth, 0.8 * d);
}

/// Steered only on the ticks that take an increment (what a controller
/// did before the commands between increments were held): the path's new
/// points start where the increments made have read it, u_j + v0 one bit
/// beyond the blade at (j + 1) v0 at times, so the steered case still
/// runs as the session did.
#[test]
fn a_case_steered_on_increments_alone_runs_as_the_session_did() {
    let case = common::original(1.0, 50.0);
    let d = case.blade.depth;
    let mut sim = Simulation::new(&case).unwrap();
    let mut records = Vec::new();
    for k in 1..=1000 {
        let x = k as f64 * d / 1000.0;
        let depth = d * (1.0 - 0.2 * (k as f64 / 1000.0 * std::f64::consts::PI).sin());
        let steer = x > sim.blade_position() * (1.0 + 1e-9);
        records.extend(sim.advance_to(x, steer.then_some(depth)).unwrap());
    }
    let (again, _) = common::run(sim.case());
    assert_eq!(again, records);
}
