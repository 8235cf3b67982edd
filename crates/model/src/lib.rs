//! soilcut-model: the soil cutting simulation of Jin & Hambleton,
//! "Simulation of the Cutting Process in Softening and Hardening Soils",
//! by sequential limit analysis. A pure library: no files, no terminal.
//!
//! Start from a [`Case`], create a [`Simulation`] and call
//! [`Simulation::step`] (or [`Simulation::run_to_end`]).

#![warn(missing_docs)]

// The integration tests' case builders (tests/common.rs) in unit tests.
#[cfg(test)]
extern crate self as soilcut_model;

/// The integration tests' case builders, for the unit tests too.
#[cfg(test)]
#[path = "../tests/common.rs"]
mod common;

pub mod accuracy;
pub mod analytic;
pub mod band;
pub mod case;
pub mod crescent;
mod discretisation;
pub mod face_friction;
mod force_bounds;
pub mod landscape;
mod laws;
pub mod mass;
pub mod material;
pub mod mechanism;
pub mod node_grid;
pub mod peaks;
pub mod rake;
mod repose;
pub mod side_heaps;
pub mod simulation;
pub mod step;
mod stopping;
pub mod summary;
pub mod tool;
pub mod trig;
pub mod vertices;

pub use case::{
    AngleLaw, BandAngleRule, BandShearRule, BandStrengthRule, Bin, Blade, Case, CaseError, Choices,
    Class, FaceFrictionRule, Ground, GroundKind, Model, Run, RunKeys, Soil, TimeScheme,
    UnitWeightRule, ValidCase, VertexGround, DEFAULT_SAMPLES_PER_BAND, MAGNITUDE,
    NODE_INCREMENTS_PER_DEPTH, NON_SOFTENING_SAMPLES_PER_BAND,
    NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH, NON_SOFTENING_VERTICES_PER_DEPTH,
    ORIGINAL_INCREMENTS_PER_DEPTH, RAKED_VERTICES_PER_DEPTH, VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH,
    VERTEX_INCREMENTS_PER_DEPTH, VERTICES_PER_DEPTH,
};
pub use landscape::Candidate;
pub use simulation::{
    AdvanceError, Observer, ProfilePoint, Simulation, SnapshotError, StepError, StepRecord, Until,
};
pub use summary::{Peak, Summary};
