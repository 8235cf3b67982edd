//! `soilcut.run(case, ensemble=N)`: the ensemble of `soilcut-study`, held
//! as a native handle that hands out its numbers, its members and writes
//! its folder.

use crate::case::Case;
use crate::convert::{arrays, json};
use crate::errors::warn_accuracy;
use crate::run::{output_error, RunRecords};
use crate::study::study_error;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_study::ensemble::{member_folder, members_of, Ensemble, EnsembleResult, Perturbation};
use soilcut_study::no_progress;
use std::path::PathBuf;

/// A finished ensemble (the extension's side of `soilcut.Ensemble`).
#[pyclass(frozen, module = "soilcut._soilcut")]
pub struct EnsembleRun {
    result: EnsembleResult,
}

#[pymethods]
impl EnsembleRun {
    /// `ensemble.csv`'s columns as float64 arrays (NaN where the file is
    /// empty).
    fn windows<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        arrays(py, &self.result.window_columns())
    }

    /// `summary.json` as a dict.
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json(py, &self.result.summary_value())
    }

    /// Each member's folder name and run, in the order of k.
    fn members(&self) -> Vec<(String, RunRecords)> {
        self.result
            .members
            .iter()
            .map(|m| {
                (
                    member_folder(m.k),
                    RunRecords::new(m.loaded.clone(), &m.run),
                )
            })
            .collect()
    }

    /// Writes the folder `soilcut run --ensemble` writes.
    fn write(&self, py: Python<'_>, folder: PathBuf, force: bool, pictures: bool) -> PyResult<()> {
        py.detach(|| self.result.write(&folder, force, pictures))
            .map_err(output_error)
    }
}

/// Runs the ensemble of `members` members of `case` on `jobs` threads,
/// without the interpreter.
/// The ensembles' perturbation of `case` (docs/model.md §12.1) at a real
/// k: `(key, value)`, the key the ensembles perturb and its value at k.
#[pyfunction]
pub fn perturbation(py: Python<'_>, case: &Bound<'_, PyAny>, k: f64) -> PyResult<(String, f64)> {
    let native = Case::extract(case)?;
    let loaded = &native.get().loaded;
    let p = Perturbation::of(loaded).map_err(|e| study_error(py, e))?;
    let value = p.value_at(k);
    Ok((p.key, value))
}

#[pyfunction]
pub fn ensemble(
    py: Python<'_>,
    case: &Bound<'_, PyAny>,
    members: i64,
    jobs: usize,
) -> PyResult<EnsembleRun> {
    let members = members_of(members, "ensemble").map_err(|e| study_error(py, e))?;
    let case = Case::extract(case)?;
    warn_accuracy(py, &case.get().loaded)?;
    let study = Ensemble {
        base: case.get().base(py)?,
        members,
        jobs,
    };
    let result = py
        .detach(|| study.run(&no_progress))
        .map_err(|e| study_error(py, e))?;
    Ok(EnsembleRun { result })
}
