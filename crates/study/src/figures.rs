//! The summary figures of one run, as a sweep reports them.

use crate::run::RunResult;

/// Names of the figures, in the order of [`Figures::values`] (the columns
/// of `sweep.csv` after the varied keys).
pub const NAMES: [&str; 9] = [
    "initial_force_norm",
    "max_force_norm",
    "u_over_d_at_max",
    "final_force_norm",
    "peaks",
    "mean_force_norm_last_half",
    "mass_drift_rel",
    "band_jumps",
    "steps",
];

/// What each figure means, for the documentation of `sweep.csv`.
pub const MEANINGS: [&str; 9] = [
    "P/(γ0 d²) of the first increment",
    "largest P/(γ0 d²) of the run",
    "u/d of the largest force",
    "P/(γ0 d²) of the last increment",
    "number of distinct force peaks (prominence ≥ 5 % of the largest force, as in summary.json)",
    "mean P/(γ0 d²) over the last half of the increments (index ≥ steps/2)",
    "(final − initial mass) / initial mass",
    "increments whose emergence point moved more than d/4 (as in summary.json)",
    "increments run",
];

/// The axis labels of the figures in pictures, symbol and unit (forces
/// over γ0 d², dimensionless; counts).
pub const LABELS: [&str; 9] = [
    "first P/(γ₀d²) (–)",
    "largest P/(γ₀d²) (–)",
    "u/d at the largest force (–)",
    "last P/(γ₀d²) (–)",
    "force peaks (count)",
    "mean P/(γ₀d²), last half (–)",
    "mass drift Δm/m₀ (–)",
    "band jumps (count)",
    "increments (count)",
];

/// A case key as an axis label: the key with its unit, by the kind of
/// quantity its last part names (the case's own length and force units).
pub fn key_label(key: &str) -> String {
    let last = key.rsplit('.').next().unwrap_or(key);
    let parent = key.rsplit('.').nth(1).unwrap_or("");
    let unit = match (parent, last) {
        ("friction" | "dilation", _) | (_, "wall_friction" | "rake" | "repose") => "°",
        (_, "unit_weight") => "force/length³",
        (_, "cohesion" | "adhesion" | "surcharge") => "force/length²",
        (
            _,
            "d50" | "band_width" | "depth" | "width" | "increment" | "travel" | "vertex_spacing"
            | "length" | "peak_shear" | "residual_shear",
        ) => "length",
        _ => "–",
    };
    format!("{key} ({unit})")
}

/// Summary figures of a finished run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figures {
    /// P/(γ0 d²) of the first increment.
    pub initial_force_norm: f64,
    /// Largest P/(γ0 d²).
    pub max_force_norm: f64,
    /// u/d where it occurs.
    pub u_over_d_at_max: f64,
    /// P/(γ0 d²) of the last increment.
    pub final_force_norm: f64,
    /// Number of distinct force peaks.
    pub peaks: usize,
    /// Mean P/(γ0 d²) over the increments from steps/2 on.
    pub mean_force_norm_last_half: f64,
    /// (final mass − initial mass) / initial mass.
    pub mass_drift_rel: f64,
    /// Increments whose emergence point jumped more than d/4.
    pub band_jumps: usize,
    /// Increments run.
    pub steps: usize,
}

impl Figures {
    /// The figures of a finished run.
    pub fn of(run: &RunResult) -> Self {
        let s = &run.summary;
        let forces: Vec<f64> = run.history.iter().map(|r| r.force_norm).collect();
        Figures {
            initial_force_norm: s.initial_force_norm,
            max_force_norm: s.max_force_norm,
            u_over_d_at_max: s.u_over_d_at_max,
            final_force_norm: s.final_force_norm,
            peaks: s.peaks.len(),
            mean_force_norm_last_half: mean(&forces[forces.len() / 2..]),
            mass_drift_rel: s.mass_drift_rel,
            band_jumps: s.band_jumps.len(),
            steps: s.steps,
        }
    }

    /// The figures in the order of [`NAMES`].
    pub fn values(&self) -> [f64; 9] {
        [
            self.initial_force_norm,
            self.max_force_norm,
            self.u_over_d_at_max,
            self.final_force_norm,
            self.peaks as f64,
            self.mean_force_norm_last_half,
            self.mass_drift_rel,
            self.band_jumps as f64,
            self.steps as f64,
        ]
    }
}

/// The number of unit windows k ≤ u/d < k + 1 in a run of `travel` at
/// depth `depth` (a last, partial window is left out).
pub fn unit_windows(travel: f64, depth: f64) -> usize {
    ((travel / depth) * (1.0 + 1e-9)).floor().max(1.0) as usize
}

/// The forces of `force`, pairs (u/d, P/(γ0 d²)), in the window
/// k ≤ u/d < k + 1.
pub fn in_window(force: &[(f64, f64)], k: usize) -> Vec<f64> {
    let (lo, hi) = (k as f64, (k + 1) as f64);
    force
        .iter()
        .filter(|p| p.0 >= lo && p.0 < hi)
        .map(|p| p.1)
        .collect()
}

/// The mean P/(γ0 d²) of `force` over each of the first `windows` unit
/// windows (NaN for an empty one).
pub fn window_means(force: &[(f64, f64)], windows: usize) -> Vec<f64> {
    (0..windows).map(|k| mean(&in_window(force, k))).collect()
}

/// The arithmetic mean (NaN for no values).
pub fn mean(values: &[f64]) -> f64 {
    if values.is_empty() {
        f64::NAN
    } else {
        values.iter().sum::<f64>() / values.len() as f64
    }
}
