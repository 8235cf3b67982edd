//! The indices of a sensitivity study's outputs, from every run's values:
//! the estimators on each design point's ensemble mean, and each output's
//! chaos share.

use super::bootstrap;
use super::morris::{morris_indices, MorrisIndex};
use super::sobol::{sobol_indices, SobolIndices};
use super::{Method, Sensitivity};
use crate::figures::mean;

/// The indices of every input for one output.
#[derive(Clone, Debug, PartialEq)]
pub enum Indices {
    /// μ*, μ, σ per input.
    Morris(Vec<MorrisIndex>),
    /// S1, ST per input (and S2 per pair); `None` for an output that does
    /// not vary.
    Sobol(Option<SobolIndices>),
    /// No indices: the output is not defined in this many runs (a band
    /// spacing where a run has fewer than two force peaks).
    Undefined {
        /// Runs without the output.
        runs: usize,
    },
}

/// One output's analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputIndices {
    /// The output's name.
    pub name: String,
    /// Indices of its ensemble mean.
    pub indices: Indices,
    /// Mean within-point variance of the members / variance of every
    /// run's output (None with one member, no variance, or no indices).
    pub chaos_share: Option<f64>,
}

/// The indices of output `o` of every run (`values`, the design's order,
/// `members` runs a point, the runs of `unit`'s points): those of the
/// ensemble means, and the chaos share; none if a run lacks it.
pub fn output_indices(
    s: &Sensitivity,
    unit: &[Vec<f64>],
    values: &[&[f64]],
    o: usize,
    name: &str,
) -> OutputIndices {
    let members = values.len() / unit.len();
    let all: Vec<f64> = values.iter().map(|v| v[o]).collect();
    let undefined = all.iter().filter(|x| !x.is_finite()).count();
    if undefined > 0 {
        return OutputIndices {
            name: name.to_string(),
            indices: Indices::Undefined { runs: undefined },
            chaos_share: None,
        };
    }
    let means: Vec<f64> = all.chunks(members).map(mean).collect();
    let d = s.keys().len();
    let (resamples, seed) = (bootstrap::RESAMPLES, s.seed);
    let indices = match s.method {
        Method::Morris { levels } => {
            Indices::Morris(morris_indices(unit, &means, d, levels, resamples, seed))
        }
        Method::Sobol { second_order } => {
            Indices::Sobol(sobol_indices(&means, d, second_order, resamples, seed))
        }
    };
    OutputIndices {
        name: name.to_string(),
        indices,
        chaos_share: chaos_share(&all, members),
    }
}

/// Mean over the points of the members' variance (n − 1) over the
/// variance (n) of every run (`all`, `members` runs a point); None for
/// one member or outputs that do not vary.
pub fn chaos_share(all: &[f64], members: usize) -> Option<f64> {
    if members < 2 {
        return None;
    }
    let within: Vec<f64> = all
        .chunks(members)
        .map(|m| bootstrap::sd(m).powi(2))
        .collect();
    let m = mean(all);
    let total = all.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / all.len() as f64;
    (total > 0.0).then(|| mean(&within) / total)
}
