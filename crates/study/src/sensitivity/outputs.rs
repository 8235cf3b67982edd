//! What a sensitivity study measures of each run of a case: the first,
//! the largest and the mean normalised force P/(γ0 d²).

use crate::figures::mean;
use crate::run::RunResult;

/// The outputs of a run of a case, in the order of `outputs_of`.
pub const OUTPUTS: [&str; 3] = ["initial_force_norm", "max_force_norm", "mean_force_norm"];

/// What each output is (all P/(γ0 d²), dimensionless).
pub const MEANINGS: [&str; 3] = [
    "P/(γ0 d²) of the first increment",
    "largest P/(γ0 d²) of the run",
    "mean P/(γ0 d²) over every increment of the run",
];

/// The outputs of a finished run: first, largest and mean P/(γ0 d²).
pub fn outputs_of(run: &RunResult) -> [f64; 3] {
    let forces: Vec<f64> = run.history.iter().map(|r| r.force_norm).collect();
    [
        run.summary.initial_force_norm,
        run.summary.max_force_norm,
        mean(&forces),
    ]
}
