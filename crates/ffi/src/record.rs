//! The plain C structs the entry points fill: one increment's record (the
//! `history.csv` columns) and the simulation's state.

use serde::de::value::MapDeserializer;
use serde::{Deserialize, Deserializer};
use soilcut_io::HISTORY;
use soilcut_model::{Simulation, StepRecord};
use std::os::raw::c_int;

/// One increment: the columns of `history.csv`, in its order and with its
/// names. Lengths are in the case's length unit, angles in degrees, forces
/// per unit width in γ·length² and masses (weights) per unit width in
/// γ·length²; with `blade.width` forces and masses are per blade
/// (γ·length³).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SoilcutStep {
    /// Increment number, from 1.
    #[serde(deserialize_with = "whole")]
    pub step: u64,
    /// Blade displacement at which the increment's mechanism is evaluated
    /// (length; 0 for step 1).
    pub u: f64,
    /// u / d, d = `blade.depth` (dimensionless).
    pub u_over_d: f64,
    /// P*, the resultant blade force of the least-force mechanism
    /// (γ·length² per unit width; γ·length³ per blade with `blade.width`).
    pub force: f64,
    /// P* / (γ0 d²), d = `blade.depth` (P* / (γ0 d² w) with `blade.width`;
    /// dimensionless).
    pub force_norm: f64,
    /// Horizontal (draft) component of P* (units of `force`).
    pub force_h: f64,
    /// Vertical component of P*, upward on the blade (units of `force`).
    pub force_v: f64,
    /// β*, the slip line's (lower band boundary's) angle above the
    /// horizontal (degrees).
    pub beta_deg: f64,
    /// x where the slip line meets the surface (length; x = 0 is the
    /// blade's start).
    pub x_emergence: f64,
    /// Weight of the ground that existed at the start, ahead of the blade
    /// after the increment (γ·length² per unit width; γ·length³ per blade).
    pub mass: f64,
    /// y of the emergence point (length; y = 0 is the undisturbed surface).
    pub y_emergence: f64,
    /// Friction angle of the chosen mechanism (degrees).
    pub friction_deg: f64,
    /// Δut, the tangential slip of the slip line (band) in this increment
    /// (length).
    pub slip: f64,
    /// Dilation angle ψ of the chosen band (degrees; 0 in the original
    /// model).
    pub dilation_deg: f64,
    /// Area added by the band's dilation in this increment (length²;
    /// negative: compaction).
    pub dilation_area: f64,
    /// Depth of the blade tip during the increment (length).
    pub depth: f64,
    /// Weight of the soil spilled around the edges of a blade of finite
    /// width so far (units of `mass`; 0 in plane strain).
    pub mass_spilled: f64,
    /// W, the weight of the chosen mechanism's block at the start of the
    /// increment (units of `mass`).
    pub weight: f64,
    /// P* / W, both per unit width: Eq. (1)'s factor without cohesion,
    /// adhesion, surcharge or side crescents (dimensionless).
    pub force_factor: f64,
    /// The face force's angle from the face's normal, the wall friction
    /// the block mobilises (degrees; positive: the block rises along the
    /// face).
    pub face_friction_deg: f64,
    /// M, the moment of the face force about the tool's pivot, the force a
    /// third up its contact from the cutting edge (units of `force` ×
    /// length; counter-clockwise positive, the sense of a bucket's curl).
    pub moment: f64,
    /// x of the tool's pivot (length; the cutting edge for a blade).
    pub tool_x: f64,
    /// y of the tool's pivot (length).
    pub tool_y: f64,
    /// The tool's rotation (degrees, counter-clockwise; 0 for a blade).
    pub tool_rotation: f64,
}

impl SoilcutStep {
    /// The record as `history.csv` writes it: each field the value of the
    /// column of its name in soilcut-io's `HISTORY` (a field without a
    /// column, or a column without a field, fails here, in every test
    /// that steps).
    pub(crate) fn new(r: &StepRecord) -> Self {
        let columns = HISTORY.iter().map(|&(name, value)| (name, value(r)));
        let fields: MapDeserializer<'_, _, serde::de::value::Error> = MapDeserializer::new(columns);
        SoilcutStep::deserialize(fields)
            .expect("a field of SoilcutStep for every column of history.csv")
    }

    /// The numbers of the record after `step`, in the order of its fields
    /// (`history.csv`'s columns), for Rust callers that compare or check
    /// them all.
    pub fn values(&self) -> [f64; HISTORY.len() - 1] {
        /// The record's layout read as its numbers.
        #[repr(C)]
        struct Numbers {
            _step: u64,
            values: [f64; HISTORY.len() - 1],
        }
        // SAFETY: both are repr(C) and of one size (transmute checks it at
        // compile time): a u64, then one f64 per further column; every bit
        // pattern is a valid f64.
        let numbers: Numbers = unsafe { std::mem::transmute(*self) };
        numbers.values
    }
}

/// The increment number, a whole number in the record's column of numbers.
fn whole<'de, D: Deserializer<'de>>(value: D) -> Result<u64, D::Error> {
    f64::deserialize(value).map(|step| step as u64)
}

/// Where a simulation is now.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SoilcutState {
    /// Increments done so far.
    pub steps_done: u64,
    /// Increments of the whole case, ⌈travel / increment⌉.
    pub steps_total: u64,
    /// 1 once the case's travel has been reached, else 0.
    pub done: c_int,
    /// Blade displacement u (length): the face is at x = u.
    pub blade_position: f64,
    /// Depth of the blade tip now (length).
    pub tip_depth: f64,
    /// Weight of the soil ahead of the blade now (units of
    /// `SoilcutStep.mass`).
    pub mass: f64,
    /// Weight of the soil spilled into the side heaps so far (units of
    /// `SoilcutStep.mass`; 0 in plane strain).
    pub mass_spilled: f64,
    /// Weight of the soil at the start (units of `SoilcutStep.mass`).
    pub initial_mass: f64,
}

impl SoilcutState {
    pub(crate) fn new(sim: &Simulation) -> Self {
        SoilcutState {
            steps_done: sim.steps_done() as u64,
            steps_total: sim.case().steps() as u64,
            done: c_int::from(sim.is_done()),
            blade_position: sim.blade_position(),
            tip_depth: sim.tip_depth(),
            mass: sim.mass(),
            mass_spilled: sim.mass_spilled(),
            initial_mass: sim.initial_mass(),
        }
    }
}
