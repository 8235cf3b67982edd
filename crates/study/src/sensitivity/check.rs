//! The checks of a sensitivity study before any run.

use super::{Method, Model, Sensitivity};
use super::{DEFAULT_LEVELS, MIN_SOBOL_SAMPLES, MIN_TRAJECTORIES};
use crate::error::StudyError;
use crate::sample::MAX_RUNS;

fn spec(message: String) -> StudyError {
    StudyError::Spec(message)
}

/// Refuses, before any run: no keys, a key twice, a sample size below the
/// estimator's least (Sobol: N a power of 2, ≥ 16, at most 10 inputs;
/// Morris: r ≥ 2, an even p ≥ 2), K = 0, more than [`MAX_RUNS`] runs, a
/// key no run can set.
pub fn check(s: &Sensitivity) -> Result<(), StudyError> {
    let keys = s.keys();
    if s.ranges.is_empty() {
        return Err(spec("give at least one --vary key=lo:hi".into()));
    }
    if let Some((i, k)) = keys
        .iter()
        .enumerate()
        .find(|(i, k)| keys[..*i].contains(k))
    {
        let what = if i == s.ranges.len() {
            "--dummy's input"
        } else {
            "the key"
        };
        return Err(spec(format!("--vary {k}: {what} is varied twice")));
    }
    let n = s.samples;
    match s.method {
        Method::Sobol { .. } if n < MIN_SOBOL_SAMPLES || !n.is_power_of_two() => {
            Err(spec(format!(
            "--samples {n}: Sobol indices need N a power of 2 and at least {MIN_SOBOL_SAMPLES} \
             (SALib's guidance: 500 or more per input)"
        )))
        }
        Method::Sobol { .. } if 2 * keys.len() > super::sequence::MAX_DIMENSIONS => {
            Err(spec(format!(
            "--vary: {} inputs; Sobol indices take at most {} (the sequence's dimensions / 2): \
             screen them first with --method morris",
            keys.len(),
            super::sequence::MAX_DIMENSIONS / 2
        )))
        }
        Method::Morris { .. } if n < MIN_TRAJECTORIES => Err(spec(format!(
            "--samples {n}: Morris needs at least {MIN_TRAJECTORIES} trajectories (σ), \
             10 to 50 usual"
        ))),
        Method::Morris { levels } if levels < 2 || levels % 2 == 1 => Err(spec(format!(
            "--levels {levels}: Morris's grid needs an even number of levels >= 2 \
             ({DEFAULT_LEVELS} usual)"
        ))),
        _ => Ok(()),
    }?;
    if s.members == 0 {
        return Err(spec("--members 0: give 1 (one run a point) or more".into()));
    }
    if s.runs() > MAX_RUNS {
        return Err(spec(format!(
            "--samples {n}: {} runs; a study takes at most {MAX_RUNS} (1e5 runs)",
            s.runs()
        )));
    }
    check_model(s)
}

fn check_model(s: &Sensitivity) -> Result<(), StudyError> {
    match &s.model {
        Model::Case(base) => {
            let keys: Vec<String> = s.ranges.iter().map(|r| r.key.clone()).collect();
            let values: Vec<toml::Value> =
                s.ranges.iter().map(|r| toml::Value::Float(r.lo)).collect();
            crate::sweep::check_keys(base, &keys, &values)
        }
        Model::Function(f) if s.members > 1 => Err(spec(format!(
            "--members {}: a test function ({f:?}) has no chaos to sample",
            s.members
        ))),
        Model::Function(f) => match f.inputs() {
            Some(n) if n != s.ranges.len() => Err(spec(format!(
                "--vary: {f:?} takes {n} inputs, {} given",
                s.ranges.len()
            ))),
            _ => Ok(()),
        },
    }
}
