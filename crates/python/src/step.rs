//! `soilcut.Step`: one increment's record, as `Simulation` returns it.

use pyo3::exceptions::PyAttributeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::IntoPyObjectExt;
use soilcut_io::{history_value, HISTORY};
use soilcut_model::StepRecord;

/// One increment (a row of `history.csv`): forces and masses per unit width
/// in the case's units (γ·length²), per blade with `blade.width`
/// (γ·length³), lengths in the case's unit, angles in degrees. Its
/// attributes are the columns of `history.csv` (`Step.fields`): `step` a
/// whole number, the others floats.
#[pyclass(module = "soilcut._soilcut", frozen)]
pub struct Step(pub StepRecord);

/// The columns of `history.csv`, in order.
fn names() -> impl ExactSizeIterator<Item = &'static str> {
    HISTORY.iter().map(|(name, _)| *name)
}

#[pymethods]
impl Step {
    /// The names of the record's values, `history.csv`'s columns in order.
    #[classattr]
    fn fields(py: Python<'_>) -> PyResult<Py<PyTuple>> {
        Ok(PyTuple::new(py, names())?.unbind())
    }

    /// The value of the column `name` of `history.csv`.
    fn __getattr__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        if name == "step" {
            return self.0.step.into_py_any(py);
        }
        match history_value(&self.0, name) {
            Some(value) => value.into_py_any(py),
            None => Err(PyAttributeError::new_err(format!(
                "'Step' object has no attribute '{name}'"
            ))),
        }
    }

    fn __dir__(&self) -> Vec<&'static str> {
        names().collect()
    }

    fn __repr__(&self) -> String {
        let r = &self.0;
        format!(
            "Step(step={}, u={}, force={}, force_norm={}, beta_deg={}, x_emergence={})",
            r.step, r.u, r.force, r.force_norm, r.beta_deg, r.x_emergence
        )
    }
}
