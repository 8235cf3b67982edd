//! `soilcut.Simulation`: one case stepped increment by increment from
//! Python (a controller's loop), copied, pickled and restored from
//! snapshots (docs/model.md §17).

use crate::case::Case;
use crate::convert::arrays;
use crate::errors::{advance_error, detached, detached_map, snapshot_error};
use crate::step::Step;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyTuple};
use soilcut_io::{case_from_note, profile_columns, LoadedCase};
use soilcut_model::Until;

/// A running simulation of one case.
#[pyclass(module = "soilcut._soilcut")]
#[derive(Clone)]
pub struct Simulation {
    sim: soilcut_model::Simulation,
    /// The case in both forms, as steered so far; `None` for a simulation
    /// restored from a snapshot made without the case's text (by the Rust
    /// library's `snapshot`).
    loaded: Option<LoadedCase>,
}

#[pymethods]
impl Simulation {
    /// Sets up flat ground for `case` (a `soilcut.Case`, or the text of a
    /// case file).
    #[new]
    fn new(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<Self> {
        let loaded = Case::extract(case)?.get().loaded.clone();
        crate::errors::warn_accuracy(py, &loaded)?;
        let sim = soilcut_model::Simulation::start(&loaded.case);
        Ok(Simulation {
            sim,
            loaded: Some(loaded),
        })
    }

    /// The state as bytes (`soilcut.Simulation.from_snapshot` restores it),
    /// with the case file's text.
    fn snapshot<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        let text = self.loaded.as_ref().map(LoadedCase::resolved_toml);
        let bytes = self
            .sim
            .snapshot_with_note(text.unwrap_or_default().as_bytes());
        PyBytes::new(py, &bytes)
    }

    /// A simulation restored from `snapshot()`'s bytes; raises
    /// `soilcut.SnapshotError` for bytes it cannot restore.
    #[staticmethod]
    fn from_snapshot(py: Python<'_>, data: &[u8]) -> PyResult<Self> {
        let (sim, note) = soilcut_model::Simulation::from_snapshot_with_note(data)
            .map_err(|e| snapshot_error(py, e.to_string()))?;
        let loaded =
            case_from_note(&note, sim.case()).map_err(|e| snapshot_error(py, e.to_string()))?;
        Ok(Simulation { sim, loaded })
    }

    /// An independent copy (the state is cloned, not shared).
    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    /// Pickles as its snapshot.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let restore = slf.get_type().getattr("from_snapshot")?;
        let data = slf.borrow().snapshot(py);
        PyTuple::new(py, [restore, PyTuple::new(py, [data])?.into_any()])
    }

    /// Runs the increments that bring the blade to displacement `x` (the
    /// first whole increment at or beyond it) and returns their records;
    /// with `depth`, the tip goes linearly to that depth at x
    /// (`Simulation::advance_to` of soilcut-model).
    #[pyo3(signature = (x, depth=None))]
    fn advance_to(
        &mut self,
        py: Python<'_>,
        x: &Bound<'_, PyAny>,
        depth: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Vec<Step>> {
        let x = number_argument("advance_to", "x", x)?;
        let depth = depth
            .map(|d| number_argument("advance_to", "depth", d))
            .transpose()?;
        let sim = &mut self.sim;
        let made = detached_map(py, || sim.advance_to(x, depth), advance_error);
        // The case may be steered even if an increment failed.
        self.loaded = self.loaded.take().map(|l| l.steered(self.sim.case()));
        Ok(made?.into_iter().map(Step).collect())
    }

    /// Advances the blade by one increment and returns its record.
    fn step(&mut self, py: Python<'_>) -> PyResult<Step> {
        let sim = &mut self.sim;
        detached(py, || sim.step()).map(Step)
    }

    /// Advances by up to `n` increments without returning their records;
    /// returns how many were made.
    fn advance(&mut self, py: Python<'_>, n: &Bound<'_, PyAny>) -> PyResult<usize> {
        let n = count_argument("advance", "n", n)?;
        let sim = &mut self.sim;
        detached(py, || {
            let until = Until::Increments(sim.steps_done().saturating_add(n));
            sim.drive(until, &mut ())
        })
    }

    /// The free surface from the face to the end of the domain: arrays x,
    /// y (length, the centreline), accumulated_shear (length), unit_weight
    /// (force/length³), ridge_height (length: the side heaps' crest beside
    /// a blade of finite width, 0 in plane strain).
    fn surface<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        arrays(py, &profile_columns(&self.sim.profile()))
    }

    /// The case's name, the increments done of all, the blade's position
    /// and the tip's depth.
    fn __repr__(&self) -> String {
        let name = self
            .loaded
            .as_ref()
            .map_or("(restored)", |l| l.case.name.as_str());
        format!(
            // {:?}: the shortest round trip, as Python's repr of a float.
            "Simulation({name:?}: {} of {} increments, u = {:?}, tip depth {:?})",
            self.sim.steps_done(),
            self.sim.case().steps(),
            self.sim.blade_position(),
            self.sim.tip_depth()
        )
    }

    /// Blade displacement u (length): the face is at x = u.
    #[getter]
    fn blade_position(&self) -> f64 {
        self.sim.blade_position()
    }

    /// Increments done so far.
    #[getter]
    fn steps_done(&self) -> usize {
        self.sim.steps_done()
    }

    /// Increments of the whole case.
    #[getter]
    fn steps(&self) -> usize {
        self.sim.case().steps()
    }

    /// Whether the case's travel has been reached.
    #[getter]
    fn is_done(&self) -> bool {
        self.sim.is_done()
    }

    /// Depth of the blade tip now (length).
    #[getter]
    fn tip_depth(&self) -> f64 {
        self.sim.tip_depth()
    }

    /// Weight of the soil ahead of the blade now (γ·length² per unit width;
    /// per blade with `blade.width`).
    #[getter]
    fn mass(&self) -> f64 {
        self.sim.mass()
    }

    /// Weight of the soil spilled around the blade's edges so far (0 in
    /// plane strain; units of `mass`).
    #[getter]
    fn mass_spilled(&self) -> f64 {
        self.sim.mass_spilled()
    }

    /// The case, every default filled in (a `soilcut.Case`).
    #[getter]
    fn case<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let Some(loaded) = &self.loaded else {
            return Err(PyRuntimeError::new_err(
                "restored from a snapshot made without the case file's text: its case is not known as a case file",
            ));
        };
        let native = Bound::new(py, Case::resolved_of(loaded))?;
        py.import("soilcut")?
            .getattr("Case")?
            .call_method1("_from_native", (native,))
    }

    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__(&mut self, py: Python<'_>) -> PyResult<Option<Step>> {
        if self.sim.is_done() {
            return Ok(None);
        }
        self.step(py).map(Some)
    }
}

/// A number given as `method`'s argument `name`; anything else is a
/// `TypeError` naming them (Python's own message names neither).
fn number_argument(method: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    value.extract::<f64>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{method}: {name} must be a number (a length), not {}",
            type_name(value)
        ))
    })
}

/// A count given as `method`'s argument `name`: a whole number >= 0.
fn count_argument(method: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<usize> {
    let n = value.extract::<i64>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{method}: {name} must be a whole number >= 0 (increments), not {}",
            type_name(value)
        ))
    })?;
    usize::try_from(n).map_err(|_| {
        PyValueError::new_err(format!(
            "{method}: {name} must be a whole number >= 0 (increments), got {n}"
        ))
    })
}

fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .name()
        .map_or_else(|_| "that".to_string(), |n| n.to_string())
}
