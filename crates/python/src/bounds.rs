//! The limit-analysis bounds of `soilcut bounds --at` (soilcut-bounds):
//! argument checks and the instant's solve by soilcut-io and soilcut-bounds,
//! its numbers as `bounds.csv`'s columns.

use crate::case::Case;
use crate::convert::arrays;
use crate::errors::{case_message, detached_map, step_error};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_bounds::{instant, InstantError, Options, SolveError};
use soilcut_io::{bounds_columns, bounds_options, check_landscape_at};

fn instant_error(py: Python<'_>, e: InstantError) -> PyErr {
    match e {
        InstantError::Step(e) => step_error(py, e),
        InstantError::Case(_) => case_message(py, e.to_string()),
        e => PyValueError::new_err(e.to_string()),
    }
}

fn status<T>(bound: &Result<T, SolveError>) -> String {
    bound
        .as_ref()
        .map_or_else(|e| e.status.clone(), |_| "Solved".into())
}

/// `bounds.csv`'s columns (one row) of the instant at u/d = `at`, and the
/// solver's status of the lower and the upper bound.
#[pyfunction]
#[pyo3(signature = (
    case,
    at,
    mesh = Options::default().mesh as i64,
    floor = Options::default().floor.name(),
    strength = Options::default().strength.name(),
    field = Options::default().field.name(),
))]
pub fn bounds<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    at: f64,
    mesh: i64,
    floor: &str,
    strength: &str,
    field: &str,
) -> PyResult<(Bound<'py, PyDict>, String, String)> {
    let native = Case::extract(case)?;
    let case = &native.get().loaded.case;
    check_landscape_at(case, "at", at).map_err(PyValueError::new_err)?;
    let options =
        bounds_options("", mesh, floor, strength, field).map_err(PyValueError::new_err)?;
    let one = detached_map(py, || instant::at(case, at, options), instant_error)?;
    let (lower, upper) = (status(&one.bracket.lower), status(&one.bracket.upper));
    let columns = bounds_columns(std::slice::from_ref(&one), case.blade.depth);
    Ok((arrays(py, &columns)?, lower, upper))
}
