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
pub mod avalanche;
pub mod band;
pub mod case;
pub mod crescent;
mod discretisation;
pub mod face_friction;
mod force_bounds;
pub mod grid;
pub mod ground;
pub mod kinematics;
pub mod landscape;
mod laws;
pub mod mass;
pub mod material;
pub mod mechanism;
pub mod peaks;
pub mod rake;
mod repose;
pub mod search;
pub mod simulation;
pub mod spill;
pub mod step;
mod stopping;
pub mod summary;
pub mod surface;
pub mod trig;

pub use case::{
    AngleLaw, BandAngleRule, BandShearRule, BandStrengthRule, Bin, Blade, Case, CaseError, Choices,
    Class, FaceFrictionRule, Ground, GroundKind, Model, Run, RunKeys, Soil, TimeScheme,
    UnitWeightRule, VertexGround, DEFAULT_SAMPLES_PER_BAND, MAGNITUDE, NODE_INCREMENTS_PER_DEPTH,
    NON_SOFTENING_SAMPLES_PER_BAND, NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH,
    NON_SOFTENING_VERTICES_PER_DEPTH, ORIGINAL_INCREMENTS_PER_DEPTH, RAKED_VERTICES_PER_DEPTH,
    VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH, VERTEX_INCREMENTS_PER_DEPTH, VERTICES_PER_DEPTH,
};
pub use landscape::Candidate;
pub use simulation::{
    AdvanceError, ProfilePoint, Simulation, SnapshotError, StepError, StepRecord,
};
pub use summary::{Peak, Summary};
