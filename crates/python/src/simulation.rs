//! `soilcut.Simulation`: one case stepped increment by increment from
//! Python (a controller's loop), and `soilcut.Step`, one increment's record.

use crate::case::load;
use crate::convert::columns;
use crate::errors::{case_error, detached};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use soilcut_model::StepRecord;

/// A running simulation of one case.
#[pyclass(module = "soilcut._soilcut")]
pub struct Simulation {
    sim: soilcut_model::Simulation,
    resolved: String,
}

/// One increment (a row of `history.csv`): forces and masses per unit width
/// in the case's units (γ·length²), per blade with `blade.width`
/// (γ·length³), lengths in the case's unit, angles in degrees.
#[pyclass(module = "soilcut._soilcut", frozen)]
pub struct Step(StepRecord);

#[pymethods]
impl Simulation {
    /// Sets up flat ground for `case` (a `soilcut.Case`, or the text of a
    /// case file).
    #[new]
    fn new(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<Self> {
        let text: String = match case.extract::<String>() {
            Ok(text) => text,
            Err(_) => case.call_method0("to_toml")?.extract()?,
        };
        let loaded = load(py, &text)?;
        crate::errors::warn_accuracy(py, &loaded.case)?;
        let sim =
            soilcut_model::Simulation::new(&loaded.case).map_err(|e| case_error(py, &e.into()))?;
        Ok(Simulation {
            sim,
            resolved: loaded.resolved_toml(),
        })
    }

    /// Advances the blade by one increment and returns its record.
    fn step(&mut self, py: Python<'_>) -> PyResult<Step> {
        if self.sim.is_done() {
            return Err(PyRuntimeError::new_err(format!(
                "the case's travel has been reached ({} increments)",
                self.sim.steps_done()
            )));
        }
        let sim = &mut self.sim;
        detached(py, || sim.step()).map(Step)
    }

    /// Advances by up to `n` increments without returning their records;
    /// returns how many were made.
    fn advance(&mut self, py: Python<'_>, n: usize) -> PyResult<usize> {
        let sim = &mut self.sim;
        detached(py, || {
            let mut made = 0;
            while made < n && !sim.is_done() {
                sim.step()?;
                made += 1;
            }
            Ok(made)
        })
    }

    /// The free surface from the face to the end of the domain: arrays x,
    /// y (length, the centreline), accumulated_shear (length), unit_weight
    /// (force/length³), ridge_height (length: the side heaps' crest beside
    /// a blade of finite width, 0 in plane strain).
    fn surface<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = self.sim.profile();
        let column = |f: fn(&soilcut_model::ProfilePoint) -> f64| p.iter().map(f).collect();
        columns(
            py,
            vec![
                ("x".into(), column(|q| q.x)),
                ("y".into(), column(|q| q.y)),
                ("accumulated_shear".into(), column(|q| q.accumulated_shear)),
                ("unit_weight".into(), column(|q| q.unit_weight)),
                ("ridge_height".into(), column(|q| q.ridge_height)),
            ],
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
        py.import("soilcut")?
            .getattr("Case")?
            .call1((self.resolved.as_str(),))
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

#[pymethods]
impl Step {
    /// Increment number, from 1.
    #[getter]
    fn step(&self) -> usize {
        self.0.step
    }
    /// Blade displacement u at which the mechanism was evaluated (length).
    #[getter]
    fn u(&self) -> f64 {
        self.0.u
    }
    /// Resultant blade force P per unit width (γ·length², force per unit width).
    #[getter]
    fn force(&self) -> f64 {
        self.0.force
    }
    /// P/(γ0 d²), d = blade.depth.
    #[getter]
    fn force_norm(&self) -> f64 {
        self.0.force_norm
    }
    /// Horizontal (draft) component of P (γ·length², force per unit width).
    #[getter]
    fn force_h(&self) -> f64 {
        self.0.force_h
    }
    /// Vertical component of P, positive upward (γ·length², force per unit width).
    #[getter]
    fn force_v(&self) -> f64 {
        self.0.force_v
    }
    /// β*, the angle of the least-force slip line or band (degrees).
    #[getter]
    fn beta_deg(&self) -> f64 {
        self.0.beta_deg
    }
    /// Friction angle mobilised on the band (degrees).
    #[getter]
    fn friction_deg(&self) -> f64 {
        self.0.friction_deg
    }
    /// Dilation angle on the band (degrees).
    #[getter]
    fn dilation_deg(&self) -> f64 {
        self.0.dilation_deg
    }
    /// x of the emergence point of the band at the surface (length).
    #[getter]
    fn x_emergence(&self) -> f64 {
        self.0.x_emergence
    }
    /// y of the emergence point (length).
    #[getter]
    fn y_emergence(&self) -> f64 {
        self.0.y_emergence
    }
    /// Depth of the blade tip during the increment (length).
    #[getter]
    fn depth(&self) -> f64 {
        self.0.depth
    }
    /// Slip along the band in this increment (length).
    #[getter]
    fn slip(&self) -> f64 {
        self.0.slip
    }
    /// Area added by dilation in this increment (length²).
    #[getter]
    fn dilation_area(&self) -> f64 {
        self.0.dilation_area
    }
    /// Weight of the soil ahead of the blade after the increment
    /// (γ·length² per unit width; γ·length³ per blade with `blade.width`).
    #[getter]
    fn mass(&self) -> f64 {
        self.0.mass
    }

    /// Weight of the soil spilled around the blade's edges so far (0 in
    /// plane strain; units of `mass`).
    #[getter]
    fn mass_spilled(&self) -> f64 {
        self.0.mass_spilled
    }

    fn __repr__(&self) -> String {
        let r = &self.0;
        format!(
            "Step(step={}, u={}, force={}, force_norm={}, beta_deg={}, x_emergence={})",
            r.step, r.u, r.force, r.force_norm, r.beta_deg, r.x_emergence
        )
    }
}
