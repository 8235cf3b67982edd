//! A step whose record is not finite stops the run (issue 50): the
//! state is poisoned by hand here, since no case soilcut knows of makes it.

use super::{Discretised, Simulation, StepError};
use crate::common;

#[test]
fn a_step_that_is_not_finite_stops_the_run_and_every_later_step() {
    let mut sim = Simulation::new(&common::original(1.0, 50.0)).expect("valid case");
    for _ in 0..5 {
        sim.step().expect("an admissible mechanism");
    }
    let Discretised::Nodes(grid) = &mut sim.ground else {
        panic!("the original model runs on the node grid")
    };
    // What the search does not read but the mass sums.
    grid.surface.trench_mass = f64::NAN;
    let e = sim.step().expect_err("a NaN mass stops the run");
    let StepError::NotFinite {
        step, u, quantity, ..
    } = e
    else {
        panic!("{e}")
    };
    assert_eq!(
        (step, u, quantity),
        (6, 5.0 * sim.case().run.increment, "mass")
    );
    assert!(e.to_string().contains("increment 6"), "{e}");
    assert_eq!(sim.steps_done(), 5);
    // The same error (compared as text: its value is NaN, equal to nothing).
    let again = |r: Result<(), StepError>| r.map_err(|e| e.to_string());
    assert_eq!(again(sim.step().map(drop)), Err(e.to_string()));
    assert_eq!(again(sim.landscape().map(drop)), Err(e.to_string()));
}
