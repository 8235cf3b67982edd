//! `soilcut.run`: a case run to its end, returned as the files
//! `soilcut run` writes (the Python package reads its arrays from them, so
//! they are the files' numbers exactly).

use crate::case::load;
use crate::convert::columns;
use crate::errors::detached;
use pyo3::exceptions::{PyFileExistsError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_io::{record_files, OutputError, Table};
use soilcut_model::Simulation;
use std::path::{Path, PathBuf};

/// The run's files: `(name, contents)` of history.csv, profile.csv,
/// summary.json, case.resolved.toml and frames.csv. Runs without the
/// interpreter.
#[pyfunction]
pub fn run(py: Python<'_>, text: &str) -> PyResult<Vec<(&'static str, String)>> {
    let loaded = load(py, text)?;
    crate::errors::warn_accuracy(py, &loaded.case)?;
    let mut sim =
        Simulation::new(&loaded.case).map_err(|e| crate::errors::case_error(py, &e.into()))?;
    detached(py, || Ok(record_files(&loaded, &mut sim, || {})?.files))
}

/// The columns of a CSV file of numbers (history.csv, profile.csv,
/// frames.csv, landscape.csv) as float64 arrays, by name.
#[pyfunction]
pub fn csv_columns<'py>(py: Python<'py>, name: &str, text: &str) -> PyResult<Bound<'py, PyDict>> {
    let table = Table::parse(Path::new(name), text)
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    let named = table
        .header()
        .iter()
        .map(|c| Ok((c.clone(), table.column(c)?)))
        .collect::<Result<Vec<_>, soilcut_io::RunFilesError>>()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    columns(py, named)
}

/// Writes a run's folder as `soilcut run` does: the files and, if
/// `pictures`, the plots and the animation drawn from them. An existing,
/// non-empty `folder` is replaced only if `force`.
#[pyfunction]
pub fn write_run_dir(
    py: Python<'_>,
    folder: PathBuf,
    files: Vec<(String, String)>,
    force: bool,
    pictures: bool,
) -> PyResult<()> {
    let files: Vec<(&str, String)> = files.iter().map(|(n, c)| (n.as_str(), c.clone())).collect();
    py.detach(|| soilcut_io::write_run_dir(&folder, &files, force, pictures))
        .map_err(output_error)
}

/// An output folder's error as Python's: `FileExistsError` for an occupied
/// folder, `ValueError` for one without a name, `OSError` for I/O.
pub fn output_error(e: OutputError) -> PyErr {
    let path = e.path().display();
    match e {
        OutputError::Exists(_) => PyFileExistsError::new_err(format!(
            "{path}: the folder exists and is not empty; pass force=True to replace it"
        )),
        OutputError::Unnamed(_) => PyValueError::new_err(format!("{path}: {e}")),
        OutputError::Io { .. } => PyOSError::new_err(format!("{path}: {e}")),
    }
}
