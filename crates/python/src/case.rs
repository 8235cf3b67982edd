//! Case files: the text of a case is the Python `Case`; reading and
//! validating it is `soilcut-io`'s (the same as the command line's).

use crate::convert::{dict, table, to_toml};
use crate::errors::{case_error, case_message};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_io::{parse_case, LoadedCase};
use soilcut_study::run::override_of;

/// Reads and validates a case file's text.
pub fn load(py: Python<'_>, text: &str) -> PyResult<LoadedCase> {
    parse_case(text, &[]).map_err(|e| case_error(py, &e))
}

fn parse_table(py: Python<'_>, text: &str) -> PyResult<toml::Table> {
    // A text that does not parse is reported as `parse_case` reports it.
    text.parse::<toml::Table>().map_err(|_| {
        load(py, text)
            .err()
            .unwrap_or_else(|| case_message(py, "case: not a TOML table"))
    })
}

fn table_text(py: Python<'_>, table: &toml::Table) -> PyResult<String> {
    toml::to_string(table).map_err(|e| case_message(py, format!("case: {e}")))
}

/// Validates a case and returns its `case.resolved.toml`.
#[pyfunction]
pub fn resolve(py: Python<'_>, text: &str) -> PyResult<String> {
    Ok(load(py, text)?.resolved_toml())
}

/// The case with each `(key, value)` of `pairs` set as `--set key=value`
/// sets it, then validated; returns the new text.
#[pyfunction]
pub fn set_keys(
    py: Python<'_>,
    text: &str,
    pairs: Vec<(String, Bound<'_, PyAny>)>,
) -> PyResult<String> {
    let mut table = parse_table(py, text)?;
    for (key, value) in &pairs {
        let value = to_toml(key, value)?;
        let set = override_of(key, &value).map_err(|e| case_message(py, e))?;
        set.apply(&mut table).map_err(|e| case_error(py, &e))?;
    }
    let text = table_text(py, &table)?;
    load(py, &text)?;
    Ok(text)
}

/// The case file's table as nested dicts.
#[pyfunction]
pub fn to_dict<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyDict>> {
    dict(py, &parse_table(py, text)?)
}

/// A case file's text from nested dicts, validated.
#[pyfunction]
pub fn from_dict(py: Python<'_>, d: &Bound<'_, PyDict>) -> PyResult<String> {
    let text = table_text(py, &table("", d)?)?;
    load(py, &text)?;
    Ok(text)
}
