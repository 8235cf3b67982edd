//! Figures of a finished run, for `summary.json` and parameter studies.

use crate::case::Case;
use crate::peaks::find_peaks;
use crate::simulation::{ProfilePoint, StepRecord};

/// Minimum prominence of a reported force peak, as a fraction of the largest
/// normalised force of the run (see `peaks`).
pub const PEAK_PROMINENCE: f64 = 0.05;

/// A band jump is a move of the emergence point, relative to the ground,
/// longer than this many blade depths from one increment to the next.
pub const JUMP_DEPTHS: f64 = 0.25;

/// Accumulated shear above this fraction of `soil.residual_shear` counts a
/// piece of the surface as sheared (`sheared_fraction`).
pub const SHEARED_THRESHOLD: f64 = 0.05;

/// Length ahead of the blade's final position, in blade depths, over which
/// `sheared_fraction` is measured.
pub const SHEARED_REACH_DEPTHS: f64 = 5.0;

/// A distinct peak of the force history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    /// Blade displacement over the depth, u/d.
    pub u_over_d: f64,
    /// P/(γ0 d²) at the peak.
    pub force_norm: f64,
    /// Index into the history.
    pub index: usize,
}

/// Figures of a finished run (`summary.json`).
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// P/(γ0 d²) of the first increment (Coulomb's wedge on flat ground).
    pub initial_force_norm: f64,
    /// Largest P/(γ0 d²) of the run.
    pub max_force_norm: f64,
    /// u/d where it occurs (first occurrence).
    pub u_over_d_at_max: f64,
    /// P/(γ0 d²) of the last increment.
    pub final_force_norm: f64,
    /// Distinct peaks of P/(γ0 d²) (`PEAK_PROMINENCE`).
    pub peaks: Vec<Peak>,
    /// (mass after the last increment − initial mass) / initial mass.
    pub mass_drift_rel: f64,
    /// Increments run.
    pub steps: usize,
    /// Indices into the history of the band jumps (see `JUMP_DEPTHS`).
    pub band_jumps: Vec<usize>,
    /// Total area added by band dilation (negative: compaction).
    pub dilation_area: f64,
}

impl Summary {
    /// The figures of `history` for `case`, with the mass before the first
    /// increment.
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
        let final_mass = history
            .last()
            .map_or(initial_mass, |r| r.mass + r.mass_spilled);
        Summary {
            initial_force_norm: forces.first().copied().unwrap_or(f64::NAN),
            max_force_norm,
            u_over_d_at_max: history.get(max_index).map_or(f64::NAN, |r| r.u / d),
            final_force_norm: forces.last().copied().unwrap_or(f64::NAN),
            peaks,
            mass_drift_rel: (final_mass - initial_mass) / initial_mass,
            steps: history.len(),
            band_jumps: band_jumps(history, JUMP_DEPTHS * d),
            dilation_area: history.iter().map(|r| r.dilation_area).sum(),
        }
    }
}

/// Increments whose emergence point lies more than `length` away from the
/// previous one.
pub fn band_jumps(history: &[StepRecord], length: f64) -> Vec<usize> {
    (1..history.len())
        .filter(|&i| (history[i].x_emergence - history[i - 1].x_emergence).abs() > length)
        .collect()
}

/// Fraction of the length of the surface within `SHEARED_REACH_DEPTHS`
/// depths ahead of the blade whose accumulated shear exceeds
/// `SHEARED_THRESHOLD` ur, each piece between two profile points taking
/// the state of its first (the vertex ground's pieces, and the node grid's
/// nodes to the next): high where successive bands gave the appearance of
/// continuous shearing, low where bands stayed at distinct locations. By
/// length, not by points, because the vertex ground's points crowd where
/// bands emerged.
pub fn sheared_fraction(case: &Case, profile: &[ProfilePoint]) -> f64 {
    let Some(face) = profile.first() else {
        return f64::NAN;
    };
    let reach = face.x + SHEARED_REACH_DEPTHS * case.blade.depth;
    let threshold = SHEARED_THRESHOLD * case.soil.residual_shear;
    let (mut sheared, mut total) = (0.0, 0.0);
    for pair in profile.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        if a.x >= reach {
            break;
        }
        let length = b.x.min(reach) - a.x;
        total += length;
        if a.accumulated_shear > threshold {
            sheared += length;
        }
    }
    sheared / total
}
