//! `soilcut.run`: a case run to its end. The result is a native handle
//! holding the run's numbers (`soilcut_io::RunTables`, from which its files
//! are written) and its files, for `save` and pickling.

use crate::case::Case;
use crate::convert::{arrays, json};
use crate::errors::{case_error, detached, python_words, step_error, stopped_error};
use pyo3::exceptions::{PyFileExistsError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_io::{record_case, Columns, LoadedCase, OutputError, RecordedRun, RunTables};
use std::path::PathBuf;

/// A finished run (the extension's side of `soilcut.RunResult`).
#[pyclass(frozen, module = "soilcut._soilcut")]
pub struct RunRecords {
    loaded: LoadedCase,
    /// (name, contents): history.csv, profile.csv, summary.json,
    /// case.resolved.toml, frames.csv.
    files: Vec<(String, String)>,
    tables: RunTables,
}

impl RunRecords {
    pub fn new(loaded: LoadedCase, run: &RecordedRun) -> Self {
        RunRecords {
            loaded,
            files: run
                .files
                .iter()
                .map(|(n, c)| (n.to_string(), c.clone()))
                .collect(),
            tables: run.tables.clone(),
        }
    }
}

#[pymethods]
impl RunRecords {
    /// `history.csv`'s columns as float64 arrays.
    fn history<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        arrays(py, &self.tables.history)
    }

    /// `profile.csv`'s columns as float64 arrays.
    fn profile<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        arrays(py, &self.tables.profile)
    }

    /// `frames.csv`'s columns as float64 arrays.
    fn frames<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        arrays(py, &self.tables.frames)
    }

    /// `summary.json` as a dict.
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json(py, &self.tables.summary)
    }

    /// The case as run, every default filled in.
    fn case(&self) -> Case {
        Case::resolved_of(&self.loaded)
    }

    /// The files `soilcut run` writes, as (name, contents).
    fn files(&self) -> Vec<(String, String)> {
        self.files.clone()
    }

    /// A run restored from `files()` (unpickling): its numbers are read
    /// back from the files' text, which holds them exactly.
    #[staticmethod]
    fn from_files(py: Python<'_>, files: Vec<(String, String)>) -> PyResult<Self> {
        let tables = RunTables::from_files(&files)
            .map_err(|e| PyValueError::new_err(format!("{}: {e}", e.path.display())))?;
        let (_, resolved) = files
            .iter()
            .find(|(n, _)| n == "case.resolved.toml")
            .ok_or_else(|| PyValueError::new_err("case.resolved.toml: the file is missing"))?;
        let loaded = soilcut_io::parse_case(resolved, &[]).map_err(|e| case_error(py, &e))?;
        Ok(RunRecords {
            loaded,
            files,
            tables,
        })
    }

    /// Writes the run's folder as `soilcut run` does: the files and, if
    /// `pictures`, the plots and the animation drawn from them. An existing,
    /// non-empty `folder` is replaced only if `force`.
    fn write(&self, py: Python<'_>, folder: PathBuf, force: bool, pictures: bool) -> PyResult<()> {
        let files: Vec<(&str, String)> = self
            .files
            .iter()
            .map(|(n, c)| (n.as_str(), c.clone()))
            .collect();
        py.detach(|| soilcut_io::write_run_dir(&folder, &files, force, pictures))
            .map_err(output_error)
    }
}

/// Runs the case to its end without the interpreter.
#[pyfunction]
pub fn run(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<RunRecords> {
    let case = Case::extract(case)?;
    let loaded = &case.get().loaded;
    crate::errors::warn_accuracy(py, loaded)?;
    let run = detached(py, || Ok(record_case(loaded, || {})))?;
    let records = RunRecords::new(loaded.clone(), &run);
    match run.stopped {
        None => Ok(records),
        Some(e) if run.history.is_empty() => Err(step_error(py, e)),
        Some(e) => Err(stopped_error(
            py,
            e,
            run.history,
            Py::new(py, records)?.into_any(),
        )),
    }
}

/// The columns of one of soilcut's CSV files of numbers (history.csv,
/// profile.csv, frames.csv, landscape.csv) as float64 arrays, by name: to
/// read a folder the command line wrote.
#[pyfunction]
pub fn csv_columns<'py>(py: Python<'py>, name: &str, text: &str) -> PyResult<Bound<'py, PyDict>> {
    let c =
        Columns::parse(name, text).map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    arrays(py, &c)
}

/// An output folder's error as Python's: `FileExistsError` for an occupied
/// folder (or a file, or with `force` a folder soilcut did not write, or
/// one another process writes, or one that appeared while writing),
/// `ValueError` for one without a name or with too long a name, `OSError`
/// for I/O.
pub fn output_error(e: OutputError) -> PyErr {
    let path = e.path().display();
    // The io crate's own message, in the words of `save(folder)`.
    let told = format!("{path}: {}", python_words(&e.to_string()));
    match e {
        OutputError::Exists(_) => PyFileExistsError::new_err(format!(
            "{path}: the folder exists and is not empty; pass force=True to replace it (only a folder soilcut wrote)"
        )),
        OutputError::NotAFolder(_) => PyFileExistsError::new_err(format!(
            "{path}: exists and is not a folder (a file); soilcut never replaces a file: choose another folder"
        )),
        OutputError::NotOurs(_) => PyFileExistsError::new_err(format!(
            "{path}: the folder exists and soilcut did not write it (it holds no {} file); force=True replaces only soilcut's own output folders: choose another folder",
            soilcut_io::OUTPUT_MARKER
        )),
        OutputError::Unnamed(_) | OutputError::NameTooLong(..) => {
            PyValueError::new_err(told)
        }
        OutputError::Busy(..) | OutputError::Appeared { .. } => {
            PyFileExistsError::new_err(told)
        }
        OutputError::Unusable { .. } | OutputError::Io { .. } => {
            PyOSError::new_err(told)
        }
    }
}
