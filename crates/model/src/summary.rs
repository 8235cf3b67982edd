//! Figures of a finished run, for `summary.json` and parameter studies.

use crate::case::Case;
use crate::peaks::find_peaks;
use crate::simulation::StepRecord;

/// Minimum prominence of a reported force peak, as a fraction of the largest
/// normalised force of the run (see `peaks`).
pub const PEAK_PROMINENCE: f64 = 0.05;

/// A distinct peak of the force history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    pub u_over_d: f64,
    pub force_norm: f64,
    /// Index into the history.
    pub index: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// P/(γ0 d²) of the first increment (Coulomb's wedge on flat ground).
    pub initial_force_norm: f64,
    pub max_force_norm: f64,
    pub u_over_d_at_max: f64,
    pub final_force_norm: f64,
    pub peaks: Vec<Peak>,
    /// (mass after the last increment − initial mass) / initial mass.
    pub mass_drift_rel: f64,
    pub steps: usize,
}

impl Summary {
    pub fn new(case: &Case, history: &[StepRecord], initial_mass: f64) -> Self {
        let d = case.blade.depth;
        let forces: Vec<f64> = history.iter().map(|r| r.force_norm).collect();
        let (max_index, max_force_norm) =
            forces
                .iter()
                .copied()
                .enumerate()
                .fold((0, f64::NEG_INFINITY), |best, (i, f)| {
                    if f > best.1 {
                        (i, f)
                    } else {
                        best
                    }
                });
        let peaks = find_peaks(&forces, PEAK_PROMINENCE * max_force_norm)
            .into_iter()
            .map(|i| Peak {
                u_over_d: history[i].u / d,
                force_norm: forces[i],
                index: i,
            })
            .collect();
        let final_mass = history.last().map_or(initial_mass, |r| r.mass);
        Summary {
            initial_force_norm: forces.first().copied().unwrap_or(f64::NAN),
            max_force_norm,
            u_over_d_at_max: history.get(max_index).map_or(f64::NAN, |r| r.u / d),
            final_force_norm: forces.last().copied().unwrap_or(f64::NAN),
            peaks,
            mass_drift_rel: (final_mass - initial_mass) / initial_mass,
            steps: history.len(),
        }
    }
}
