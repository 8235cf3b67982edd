//! Variance-based sensitivity of a case's outputs to its keys: Morris
//! screening (elementary effects μ*, σ, μ) and Sobol first-order and total
//! indices (Saltelli's design on a scrambled Sobol sequence, Saltelli's
//! 2010 S1 and Jansen's ST estimators) and, on request, second-order
//! indices (Saltelli 2002), each with seeded bootstrap intervals; SALib
//! gives the same indices on the same samples
//! (python/tests/test_sensitivity.py).
//!
//! Chaos-aware: with `members` K > 1 each design point is an ensemble of K
//! members perturbed by the ensembles' rule ([`crate::ensemble`]), the
//! indices are those of the ensemble mean, and each output's chaos share
//! is the members' mean variance within a point over the variance of every
//! run's output: an index below it is below the noise.
//!
//! A study of a case also runs its tornado ([`tornado`]): each key at the
//! ends of its range, the others at the case's values.
//!
//! Runs go through [`BaseCase::run`] in parallel; results are collected in
//! the design's order, so any number of threads gives the same files.

use crate::error::StudyError;
use crate::run::BaseCase;
use crate::sample::Vary;

mod analysis;
pub mod bootstrap;
mod check;
pub mod design;
mod files;
pub mod function;
pub mod morris;
mod outputs;
mod pictures;
mod plan;
mod runs;
pub mod sequence;
pub mod sobol;
pub mod tornado;

pub use analysis::{Indices, OutputIndices};
pub use function::Function;
pub use outputs::{MEANINGS, OUTPUTS, UNITS};
pub use plan::{Plan, Point, Run, RunRow};
pub use runs::SensitivityResult;

/// The name of the input that no run reads (`dummy`).
pub const DUMMY: &str = "dummy";
/// Fewest base points of a Sobol design.
pub const MIN_SOBOL_SAMPLES: usize = 16;
/// Fewest Morris trajectories (σ needs two).
pub const MIN_TRAJECTORIES: usize = 2;
/// Morris levels by default.
pub const DEFAULT_LEVELS: usize = 4;
/// Sobol base points N by default.
pub const DEFAULT_SOBOL_SAMPLES: usize = 512;
/// Morris trajectories r by default.
pub const DEFAULT_TRAJECTORIES: usize = 20;
/// Members of each point of a case's study by default: the least K whose
/// ensemble mean's chaos share is below 5 % of the design's variance for
/// every force output of Fig. 5, as measured by
/// `docs/studies/sensitivity_members.py` (docs/guide/sensitivity.md, "The
/// chaos share").
pub const DEFAULT_MEMBERS: usize = 6;

/// The method and its design.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Morris screening on a grid of `levels` levels (even).
    Morris {
        /// p, the levels of the grid.
        levels: usize,
    },
    /// Sobol first-order and total indices, and with `second_order` those
    /// of every pair of inputs.
    Sobol {
        /// Also S2 of every pair (2d + 2 runs a base point, not d + 2).
        second_order: bool,
    },
}

impl Method {
    /// `morris` (on `levels` levels) or `sobol` (with the second-order
    /// indices if `second_order`; refused with morris, whose design has
    /// none).
    pub fn named(name: &str, levels: usize, second_order: bool) -> Result<Method, StudyError> {
        match name {
            "morris" if second_order => Err(StudyError::Spec(
                "--second-order: second-order indices are Sobol's; use --method sobol".into(),
            )),
            "morris" => Ok(Method::Morris { levels }),
            "sobol" => Ok(Method::Sobol { second_order }),
            _ => Err(StudyError::Spec(format!(
                "--method {name}: expected morris or sobol"
            ))),
        }
    }

    /// Its sample size by default: [`DEFAULT_TRAJECTORIES`] or
    /// [`DEFAULT_SOBOL_SAMPLES`].
    pub fn default_samples(self) -> usize {
        match self {
            Method::Morris { .. } => DEFAULT_TRAJECTORIES,
            Method::Sobol { .. } => DEFAULT_SOBOL_SAMPLES,
        }
    }
}

/// What each design point runs.
#[derive(Clone, Debug)]
pub enum Model {
    /// The case with the point's keys set.
    Case(BaseCase),
    /// A function of known indices, for checking the estimators.
    Function(Function),
}

/// One varied key and its range lo < hi.
#[derive(Clone, Debug, PartialEq)]
pub struct Range {
    /// The case key.
    pub key: String,
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

impl Range {
    /// `key=lo:hi` (as `--vary`), lo < hi.
    pub fn parse(text: &str) -> Result<Range, StudyError> {
        let vary: Vary = text.parse()?;
        match vary.values {
            crate::sample::Values::Range { lo, hi } => Range::new(&vary.key, lo, hi),
            _ => Err(StudyError::Spec(format!(
                "--vary {text}: expected key=lo:hi (a sensitivity study samples the interval)"
            ))),
        }
    }

    /// `key` over [lo, hi], finite numbers with lo < hi.
    pub fn new(key: &str, lo: f64, hi: f64) -> Result<Range, StudyError> {
        if lo.is_finite() && hi.is_finite() && lo < hi {
            Ok(Range {
                key: key.to_string(),
                lo,
                hi,
            })
        } else {
            Err(StudyError::Spec(format!(
                "--vary {key}={lo}:{hi}: a range needs finite lo < hi"
            )))
        }
    }
}

/// A sensitivity study to run.
#[derive(Clone, Debug)]
pub struct Sensitivity {
    /// What each run is.
    pub model: Model,
    /// The varied keys.
    pub ranges: Vec<Range>,
    /// Morris or Sobol.
    pub method: Method,
    /// Morris: trajectories r; Sobol: base points N (a power of 2).
    pub samples: usize,
    /// Members K of each design point's ensemble (1: one run).
    pub members: usize,
    /// Add the input [`DUMMY`] that no run reads.
    pub dummy: bool,
    /// Seed of the design and the bootstrap.
    pub seed: u64,
    /// Worker threads (0: one per core).
    pub jobs: usize,
}

impl Sensitivity {
    /// The inputs: the varied keys, then [`DUMMY`] if asked for.
    pub fn keys(&self) -> Vec<String> {
        let mut keys: Vec<String> = self.ranges.iter().map(|r| r.key.clone()).collect();
        if self.dummy {
            keys.push(DUMMY.to_string());
        }
        keys
    }

    /// Runs the study will make: design points (r (d + 1) Morris, N (d + 2)
    /// or N (2d + 2) Sobol, d inputs) and, for a case, the tornado's 2 k + 1
    /// points (k keys), each × members.
    pub fn runs(&self) -> usize {
        let d = self.keys().len();
        let points = match self.method {
            Method::Morris { .. } => self.samples.saturating_mul(d + 1),
            Method::Sobol { second_order } => self
                .samples
                .saturating_mul(design::rows_per_point(d, second_order)),
        };
        let tornado = match self.model {
            Model::Case(_) => 2 * self.ranges.len() + 1,
            Model::Function(_) => 0,
        };
        points.saturating_add(tornado).saturating_mul(self.members)
    }

    /// Refuses what would make the study fail or mean nothing, before
    /// any run: a range with lo ≥ hi, a key the case cannot hold, a sample
    /// size below the method's least, an odd number of levels, too many runs.
    pub fn check(&self) -> Result<(), StudyError> {
        check::check(self)
    }
}
