//! `soilcut.Step`: one increment's record, as `Simulation` returns it.

use pyo3::prelude::*;
use soilcut_model::StepRecord;

/// One increment (a row of `history.csv`): forces and masses per unit width
/// in the case's units (γ·length²), per blade with `blade.width`
/// (γ·length³), lengths in the case's unit, angles in degrees.
#[pyclass(module = "soilcut._soilcut", frozen)]
pub struct Step(pub StepRecord);

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
