//! Shared set-up of the benchmarks: the shipped cases, read from `cases/`.

use soilcut_model::{Case, Simulation};
use std::path::Path;

/// A shipped case, `cases/<path>`, with `--set`-style overrides.
pub fn shipped_case(path: &str, overrides: &[&str]) -> Case {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
    let overrides: Vec<soilcut_io::Override> = overrides
        .iter()
        .map(|s| s.parse().expect("a valid override"))
        .collect();
    soilcut_io::read_case(&root.join(path), &overrides)
        .expect("a valid shipped case")
        .case
        .into_case()
}

/// A simulation of `case` stepped to u = `depths` blade depths: a
/// developed pile, for timing single steps.
pub fn developed(case: &Case, depths: f64) -> Simulation {
    let mut sim = Simulation::new(case).expect("valid case");
    while sim.blade_position() < depths * case.blade.depth {
        sim.step().expect("admissible mechanism");
    }
    sim
}

/// Runs a case to the end; returns the candidate evaluations it took.
pub fn run(case: &Case) -> u64 {
    let mut sim = Simulation::new(case).expect("valid case");
    sim.run_to_end(|_| {}).expect("admissible mechanism");
    sim.evaluations()
}
