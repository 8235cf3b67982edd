//! What a sensitivity study measures of each run of a case: the forces
//! (the first, the largest, the mean, and the mean over each unit window
//! of travel), the spacing of successive bands, the final band angle, and
//! the pile's height and area. Each is of a run's history and final
//! profile, in the units of docs/guide/sensitivity.md's output table; the
//! order below is that of samples.csv's and indices.csv's outputs.

use crate::figures::{mean, unit_windows, window_means};
use crate::run::RunResult;
use soilcut_model::{ProfilePoint, StepRecord, Summary};

/// The outputs every run of a case has, in order; the unit windows'
/// (`mean_force_norm_w1` …) follow them.
pub const OUTPUTS: [&str; 7] = [
    "initial_force_norm",
    "max_force_norm",
    "mean_force_norm",
    "band_spacing",
    "final_beta_deg",
    "pile_height",
    "pile_area",
];

/// The unit of each of [`OUTPUTS`] (the windows' are P/(γ0 d²), –).
pub const UNITS: [&str; 7] = ["–", "–", "–", "–", "°", "–", "–"];

/// What each of [`OUTPUTS`] is.
pub const MEANINGS: [&str; 7] = [
    "P/(γ0 d²) of the first increment",
    "largest P/(γ0 d²) of the run",
    "mean P/(γ0 d²) over every increment of the run",
    "mean distance between the emergence points of successive bands / d",
    "β*, the band's angle above the horizontal, in the last increment",
    "the final surface's greatest height above the original surface / d",
    "the final surface's area above the original surface / d²",
];

/// The name of unit window `w` (from 0: 0 ≤ u/d < 1 is `mean_force_norm_w1`).
pub fn window_name(w: usize) -> String {
    format!("mean_force_norm_w{}", w + 1)
}

/// The unit of the output `name` (– for a unit window's and a test
/// function's).
pub fn unit_of(name: &str) -> &'static str {
    OUTPUTS
        .iter()
        .position(|o| *o == name)
        .map_or("–", |i| UNITS[i])
}

/// The outputs' names with `windows` unit windows.
pub fn names(windows: usize) -> Vec<String> {
    let fixed = OUTPUTS.iter().map(|s| s.to_string());
    fixed.chain((0..windows).map(window_name)).collect()
}

/// The outputs of a finished run: [`OUTPUTS`], then the mean P/(γ0 d²)
/// over every full unit window of its travel. A figure the run does not
/// have (the band spacing of a run with fewer than two force peaks) is NaN.
pub fn outputs_of(run: &RunResult) -> Vec<f64> {
    let d = run.loaded.case.blade.depth;
    let h = &run.history;
    let forces: Vec<f64> = h.iter().map(|r| r.force_norm).collect();
    let mut out = vec![
        run.summary.initial_force_norm,
        run.summary.max_force_norm,
        mean(&forces),
        band_spacing(h, &run.summary, d),
        h.last().map_or(f64::NAN, |r| r.beta_deg),
        pile_height(&run.profile) / d,
        pile_area(&run.profile) / (d * d),
    ];
    let force: Vec<(f64, f64)> = h.iter().map(|r| (r.u / d, r.force_norm)).collect();
    out.extend(window_means(
        &force,
        unit_windows(run.loaded.case.run.travel, d),
    ));
    out
}

/// The mean distance between successive bands' emergence points / d. A
/// band event is a distinct force peak (`summary.json`'s `peaks`, by
/// peaks.rs's prominence): the band that takes over after it is read at
/// the least force between that peak and the next (or the run's end),
/// where it has just formed. Its emergence point there, not the one of
/// the increment after the peak: for a few increments after a peak the
/// least force flips between bands near and far. NaN with fewer than two
/// peaks.
pub fn band_spacing(history: &[StepRecord], summary: &Summary, d: f64) -> f64 {
    let peaks: Vec<usize> = summary.peaks.iter().map(|p| p.index).collect();
    if peaks.len() < 2 {
        return f64::NAN;
    }
    let ends = peaks[1..].iter().copied().chain([history.len()]);
    let formed: Vec<f64> = peaks
        .iter()
        .zip(ends)
        .map(|(&from, to)| {
            let trough = (from..to)
                .min_by(|&a, &b| history[a].force_norm.total_cmp(&history[b].force_norm))
                .unwrap_or(from);
            history[trough].x_emergence
        })
        .collect();
    let (first, last) = (formed[0], formed[formed.len() - 1]);
    (last - first) / ((formed.len() - 1) as f64 * d)
}

/// The greatest height of the surface above the original one (0 if it
/// is nowhere above).
pub fn pile_height(profile: &[ProfilePoint]) -> f64 {
    profile.iter().map(|p| p.y).fold(0.0, f64::max)
}

/// The area between the surface and the original one where the surface
/// is above it: the polyline's positive part, each piece that crosses
/// y = 0 cut where it does.
pub fn pile_area(profile: &[ProfilePoint]) -> f64 {
    profile
        .windows(2)
        .map(|pair| {
            let (a, b) = ((pair[0].x, pair[0].y), (pair[1].x, pair[1].y));
            let width = b.0 - a.0;
            match (a.1 > 0.0, b.1 > 0.0) {
                (true, true) => 0.5 * (a.1 + b.1) * width,
                (false, false) => 0.0,
                // The triangle of the part above: its base is the share
                // of the width on the positive side.
                _ => {
                    let top = a.1.max(b.1);
                    0.5 * top * width * top / (a.1 - b.1).abs()
                }
            }
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(x: f64, y: f64) -> ProfilePoint {
        ProfilePoint {
            x,
            y,
            accumulated_shear: 0.0,
            unit_weight: 1.0,
            ridge_height: 0.0,
        }
    }

    #[test]
    fn the_pile_is_the_surface_above_the_original_one() {
        // A triangle of height 2 on [0, 2], then ground sunk below 0.
        let profile = [
            point(0.0, 0.0),
            point(1.0, 2.0),
            point(2.0, 0.0),
            point(3.0, -1.0),
        ];
        assert_eq!(pile_height(&profile), 2.0);
        assert_eq!(pile_area(&profile), 2.0);
        // A piece crossing 0 counts its part above: 1 × 1/2 × 1/2.
        let crossing = [point(0.0, 1.0), point(2.0, -1.0)];
        assert_eq!(pile_area(&crossing), 0.5);
        assert_eq!(pile_height(&[point(0.0, -1.0)]), 0.0);
    }

    fn record(step: usize, force_norm: f64, x_emergence: f64) -> StepRecord {
        StepRecord {
            step,
            u: step as f64,
            u_over_d: step as f64,
            force: force_norm,
            force_norm,
            force_h: force_norm,
            force_v: 0.0,
            beta_deg: 20.0,
            x_emergence,
            mass: 1.0,
            y_emergence: 0.0,
            friction_deg: 30.0,
            slip: 0.0,
            dilation_deg: 0.0,
            dilation_area: 0.0,
            depth: 1.0,
            mass_spilled: 0.0,
            weight: 1.0,
            force_factor: 1.0,
            face_friction_deg: 0.0,
            moment: 0.0,
            tool_x: step as f64,
            tool_y: -1.0,
            tool_rotation: 0.0,
        }
    }

    fn summary(peaks: &[usize], history: &[StepRecord]) -> Summary {
        Summary {
            initial_force_norm: history[0].force_norm,
            max_force_norm: 0.0,
            u_over_d_at_max: 0.0,
            final_force_norm: 0.0,
            peaks: peaks
                .iter()
                .map(|&index| soilcut_model::Peak {
                    u_over_d: index as f64,
                    force_norm: history[index].force_norm,
                    index,
                })
                .collect(),
            mass_drift_rel: 0.0,
            steps: history.len(),
            band_jumps: vec![],
            dilation_area: 0.0,
        }
    }

    /// Two peaks; after each the emergence point flips far for one
    /// increment, then the new band settles at its trough: bands at 3
    /// and 7 (d = 2), 2 d apart, whatever the flips.
    #[test]
    fn bands_are_read_at_the_trough_after_each_peak() {
        let forces_and_x = [
            (1.0, 1.0),
            (4.0, 1.5), // peak 1
            (3.0, 30.0),
            (2.0, 3.0), // trough: the band at 3
            (2.5, 3.1),
            (5.0, 3.2), // peak 2
            (4.0, 40.0),
            (3.0, 7.0), // trough: the band at 7
            (3.5, 7.1),
        ];
        let h: Vec<StepRecord> = forces_and_x
            .iter()
            .enumerate()
            .map(|(i, &(f, x))| record(i + 1, f, x))
            .collect();
        assert_eq!(band_spacing(&h, &summary(&[1, 5], &h), 2.0), 2.0);
        assert!(band_spacing(&h, &summary(&[1], &h), 2.0).is_nan());
    }
}
