//! `soilcut.run(case, ensemble=N)`: the ensemble of `soilcut-study`, held
//! as a native handle that hands out its files and writes its folder.

use crate::errors::warn_accuracy;
use crate::run::output_error;
use crate::study::{base, study_error};
use pyo3::prelude::*;
use soilcut_study::ensemble::{member_folder, Ensemble, EnsembleResult};
use soilcut_study::no_progress;
use std::path::PathBuf;

/// A finished ensemble (the extension's side of `soilcut.Ensemble`).
#[pyclass(frozen, module = "soilcut._soilcut")]
pub struct EnsembleRun {
    result: EnsembleResult,
}

#[pymethods]
impl EnsembleRun {
    /// `ensemble.csv`, `summary.json` and `timing.csv`, as (name, contents).
    fn files(&self) -> Vec<(&'static str, String)> {
        vec![
            ("ensemble.csv", self.result.ensemble_csv()),
            ("summary.json", self.result.summary_json()),
            ("timing.csv", self.result.timing_csv()),
        ]
    }

    /// Each member's folder name and files, in the order of k.
    fn members(&self) -> Vec<(String, Vec<(&'static str, String)>)> {
        self.result
            .members
            .iter()
            .map(|m| (member_folder(m.k), m.run.files.clone()))
            .collect()
    }

    /// Writes the folder `soilcut run --ensemble` writes.
    fn write(&self, py: Python<'_>, folder: PathBuf, force: bool, pictures: bool) -> PyResult<()> {
        py.detach(|| self.result.write(&folder, force, pictures))
            .map_err(output_error)
    }
}

/// Runs the ensemble of `members` members of the case `text` on `jobs`
/// threads, without the interpreter.
#[pyfunction]
pub fn ensemble(py: Python<'_>, text: &str, members: usize, jobs: usize) -> PyResult<EnsembleRun> {
    let base = base(py, text)?;
    let case = base
        .load(&[])
        .map_err(|e| crate::errors::case_error(py, &e))?
        .case;
    warn_accuracy(py, &case)?;
    let study = Ensemble {
        base,
        members,
        jobs,
    };
    let result = py
        .detach(|| study.run(&no_progress))
        .map_err(|e| study_error(py, e))?;
    Ok(EnsembleRun { result })
}
