//! `soilcut._soilcut`: the Python extension of soilcut. Type conversions
//! only, over `soilcut-model`, `soilcut-io`, `soilcut-study` and
//! `soilcut-bounds`; the
//! Python package `soilcut` (python/soilcut) builds its API on it. Every
//! simulation runs with the interpreter released (`Python::detach`).

mod bounds;
mod case;
mod convert;
mod ensemble;
mod errors;
mod run;
mod sensitivity;
mod simulation;
mod step;
mod study;

use pyo3::prelude::*;

#[pymodule]
fn _soilcut(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // The fit's default budgets, the library's (as `soilcut fit`'s).
    m.add("FIT_EVALUATIONS", soilcut_study::fit::EVALUATIONS)?;
    m.add(
        "FIT_POLISH_ITERATIONS",
        soilcut_study::fit::POLISH_ITERATIONS,
    )?;
    m.add("FIT_PROFILE_GRID", soilcut_study::fit::PROFILE_GRID)?;
    // The bounds' default options, the library's (as `soilcut bounds`'s).
    let bounds = soilcut_bounds::instant::Options::default();
    m.add("BOUNDS_MESH", bounds.mesh)?;
    m.add("BOUNDS_FLOOR", bounds.floor.name())?;
    m.add("BOUNDS_STRENGTH", bounds.strength.name())?;
    m.add("BOUNDS_FIELD", bounds.field.name())?;
    // The sensitivity study's defaults, the library's (as `soilcut
    // sensitivity`'s).
    use soilcut_study::sensitivity as sens;
    m.add("SENSITIVITY_SOBOL_SAMPLES", sens::DEFAULT_SOBOL_SAMPLES)?;
    m.add("SENSITIVITY_TRAJECTORIES", sens::DEFAULT_TRAJECTORIES)?;
    m.add("SENSITIVITY_LEVELS", sens::DEFAULT_LEVELS)?;
    m.add("SENSITIVITY_MEMBERS", sens::DEFAULT_MEMBERS)?;
    m.add_class::<case::Case>()?;
    m.add_class::<run::RunRecords>()?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(run::csv_columns, m)?)?;
    m.add_function(wrap_pyfunction!(study::analytic, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep_points, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep_run, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep_check, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep_row, m)?)?;
    m.add_function(wrap_pyfunction!(study::fit, m)?)?;
    m.add_class::<sensitivity::SensitivityStudy>()?;
    m.add_function(wrap_pyfunction!(sensitivity::sensitivity_run, m)?)?;
    m.add_function(wrap_pyfunction!(study::landscape, m)?)?;
    m.add_function(wrap_pyfunction!(study::landscape_map, m)?)?;
    m.add_function(wrap_pyfunction!(bounds::bounds, m)?)?;
    m.add_function(wrap_pyfunction!(ensemble::ensemble, m)?)?;
    m.add_function(wrap_pyfunction!(ensemble::perturbation, m)?)?;
    m.add_class::<ensemble::EnsembleRun>()?;
    m.add_class::<simulation::Simulation>()?;
    m.add_class::<step::Step>()?;
    Ok(())
}
