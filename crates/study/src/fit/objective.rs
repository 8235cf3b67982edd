//! The objective of a fit: how far the simulated force curves lie from
//! the measured ones.
//!
//! Each test t (a case and its measured curve of points (uᵢ, Pᵢ) with
//! weights wᵢ) gives residuals rₖ with weights Wₖ, compared as the user
//! chose ([`Compare`]); P_sim is the run's `force` (P*, per unit width, in
//! γ·length²) linearly interpolated in u between the increments (held at
//! its first and last value outside them). The test's sum of squares is
//!
//!   S_t = Σₖ Wₖ rₖ²,
//!
//! and the objective of the search is the pooled weighted RMS
//!
//!   E = sqrt( Σ_t S_t / Σ_t Σₖ Wₖ ).
//!
//! A set of values at which any test's run fails (a rule of the case
//! broken, no admissible mechanism) is an infeasible point.

use crate::error::StudyError;
use crate::run::{override_of, BaseCase, RunResult};
use soilcut_io::Override;
use soilcut_model::Case;
use std::str::FromStr;

/// How a simulated curve is compared with a measured one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Compare {
    /// rᵢ = P_sim(uᵢ) − Pᵢ at every measured point, Wᵢ = wᵢ.
    Raw,
    /// Both curves smoothed over a window of this width (case length
    /// unit) centred on each measured point: rᵢ is the weighted mean of
    /// P_sim(uⱼ) − Pⱼ over the points j with |uⱼ − uᵢ| ≤ W/2; Wᵢ = wᵢ. The
    /// model's band jumps are sharp, measured curves are not.
    Smoothed(f64),
    /// Windows [u₀ + kW, u₀ + (k+1)W) from the first measured u₀: r is the
    /// weighted mean of P_sim(uⱼ) − Pⱼ over the window's points, its weight
    /// the window's Σ wⱼ.
    WindowMeans(f64),
}

impl FromStr for Compare {
    type Err = StudyError;

    /// `raw`, `smooth:W` or `means:W` with W > 0.
    fn from_str(text: &str) -> Result<Self, StudyError> {
        let bad = || {
            StudyError::Spec(format!(
                "--objective {text}: expected raw, smooth:W or means:W with a window W > 0 (case length unit)"
            ))
        };
        if text == "raw" {
            return Ok(Compare::Raw);
        }
        let (kind, w) = text.split_once(':').ok_or_else(bad)?;
        let w: f64 = w.trim().parse().map_err(|_| bad())?;
        if !(w.is_finite() && w > 0.0) {
            return Err(bad());
        }
        match kind {
            "smooth" => Ok(Compare::Smoothed(w)),
            "means" => Ok(Compare::WindowMeans(w)),
            _ => Err(bad()),
        }
    }
}

impl Compare {
    /// In words, for the report.
    pub fn describe(&self) -> String {
        match self {
            Compare::Raw => "the measured force minus the simulated force at each measured u".into(),
            Compare::Smoothed(w) => format!(
                "both curves smoothed over a window of {w} (case length unit) centred on each measured u"
            ),
            Compare::WindowMeans(w) => format!(
                "the mean force of both curves in consecutive windows of {w} (case length unit)"
            ),
        }
    }
}

/// The divisor of measured forces that are totals over a blade `width`
/// (`name`: how the caller's user gave it, `--width` or `width`): the
/// width, or 1 without one. Refused when not a finite number > 0, and when
/// the case has `blade.width`: its simulated force is the blade's total
/// already, and dividing the measured one would compare a total with a
/// force per unit width.
pub fn measured_width(width: Option<f64>, case: &Case, name: &str) -> Result<f64, StudyError> {
    let Some(w) = width else {
        return Ok(1.0);
    };
    if !(w.is_finite() && w > 0.0) {
        return Err(StudyError::Spec(format!(
            "{name} {w}: must be a finite number > 0"
        )));
    }
    if case.blade.width.is_some() {
        return Err(StudyError::Spec(format!(
            "{name} {w}: the case's blade.width makes the simulated force the blade's total \
             already; give the measured total force without {name}"
        )));
    }
    Ok(w)
}

/// One measured curve and the case that simulates it.
#[derive(Clone, Debug)]
pub struct Test {
    /// Shown in the report (e.g. the measured file's name).
    pub name: String,
    /// The test's case and its overrides.
    pub base: BaseCase,
    /// (u, force per unit width), case units.
    pub measured: Vec<(f64, f64)>,
    /// One per measured point, ≥ 0.
    pub weights: Vec<f64>,
}

impl Test {
    /// A measured curve of (u, force) as a test of `base`, the forces
    /// divided by `width` (from [`measured_width`]: 1 for forces per unit
    /// width) and the weights as given (one per point).
    pub fn per_width(
        name: impl Into<String>,
        base: BaseCase,
        points: &[(f64, f64)],
        weights: Vec<f64>,
        width: f64,
    ) -> Self {
        Test {
            name: name.into(),
            base,
            measured: points.iter().map(|&(u, p)| (u, p / width)).collect(),
            weights,
        }
    }

    /// Checks the curve against the case: weights, u within the travel.
    pub fn check(&self) -> Result<(), StudyError> {
        let spec = |m: String| Err(StudyError::Spec(format!("{}: {m}", self.name)));
        if self.measured.len() < 2 {
            return spec("the measured curve needs at least 2 points".into());
        }
        if self.weights.len() != self.measured.len()
            || self.weights.iter().any(|w| !(w.is_finite() && *w >= 0.0))
            || self.weights.iter().all(|&w| w == 0.0)
        {
            return spec("one weight ≥ 0 per measured point, not all 0".into());
        }
        let travel = self.base.load(&[])?.case.run.travel;
        let (u_min, u_max) = u_range(&self.measured);
        if u_min < 0.0 || u_max > travel {
            return spec(format!(
                "the measured u ({u_min} to {u_max}) must lie within 0 and the case's run.travel = {travel} (set run.travel to cover it)"
            ));
        }
        Ok(())
    }

    /// Runs the test's case with the free keys at `values`.
    pub fn run_at(&self, keys: &[String], values: &[f64]) -> Result<RunResult, String> {
        self.base.run(&overrides_of(keys, values)?)
    }

    /// (weight, residual) of the run against the measured curve.
    pub fn residuals(&self, compare: Compare, run: &RunResult) -> Vec<(f64, f64)> {
        residuals(compare, &force_curve(run), &self.measured, &self.weights)
    }

    /// Σ of the residuals' weights (the denominator of the RMS).
    pub fn weight(&self, compare: Compare) -> f64 {
        residuals(compare, &self.measured, &self.measured, &self.weights)
            .iter()
            .map(|r| r.0)
            .sum()
    }
}

/// The `--set` overrides that give the keys `keys` the values `values`.
pub fn overrides_of(keys: &[String], values: &[f64]) -> Result<Vec<Override>, String> {
    keys.iter()
        .zip(values)
        .map(|(k, &x)| override_of(k, &toml::Value::Float(x)))
        .collect()
}

/// The (u, force) curve of a run.
pub fn force_curve(run: &RunResult) -> Vec<(f64, f64)> {
    run.history.iter().map(|r| (r.u, r.force)).collect()
}

fn u_range(points: &[(f64, f64)]) -> (f64, f64) {
    let u_min = points.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let u_max = points.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    (u_min, u_max)
}

/// (weight, simulated − measured) of `curve` against the measured points
/// under `compare` (see [`Compare`]). Smoothing and window means average
/// the differences at the measured points, so the two curves are treated
/// alike and a curve compared with itself gives zero.
pub fn residuals(
    compare: Compare,
    curve: &[(f64, f64)],
    measured: &[(f64, f64)],
    weights: &[f64],
) -> Vec<(f64, f64)> {
    let differences: Vec<f64> = measured
        .iter()
        .map(|&(u, p)| interpolate(curve, u) - p)
        .collect();
    // Weighted mean difference of the points with u in `window`.
    let mean_in = |window: &dyn Fn(f64) -> bool| {
        let (mut sum, mut w_sum) = (0.0, 0.0);
        for ((&(u, _), &w), &d) in measured.iter().zip(weights).zip(&differences) {
            if window(u) {
                sum += w * d;
                w_sum += w;
            }
        }
        (w_sum > 0.0).then(|| (w_sum, sum / w_sum))
    };
    match compare {
        Compare::Raw => weights
            .iter()
            .copied()
            .zip(differences.iter().copied())
            .collect(),
        Compare::Smoothed(width) => measured
            .iter()
            .zip(weights)
            .filter_map(|(&(c, _), &w)| {
                let (_, d) = mean_in(&|u| (u - c).abs() <= 0.5 * width)?;
                Some((w, d))
            })
            .collect(),
        Compare::WindowMeans(width) => {
            let (u_min, u_max) = u_range(measured);
            let windows = ((u_max - u_min) / width).floor() as usize + 1;
            (0..windows)
                .filter_map(|k| {
                    let a = u_min + k as f64 * width;
                    mean_in(&|u| u >= a && u < a + width)
                })
                .collect()
        }
    }
}

/// Linear interpolation in a curve of increasing x, held constant outside.
pub fn interpolate(curve: &[(f64, f64)], x: f64) -> f64 {
    let Some(&(x_first, y_first)) = curve.first() else {
        return f64::NAN;
    };
    let (x_last, y_last) = curve[curve.len() - 1];
    if x <= x_first {
        return y_first;
    }
    if x >= x_last {
        return y_last;
    }
    let i = curve.partition_point(|&(cx, _)| cx <= x);
    let ((x0, y0), (x1, y1)) = (curve[i - 1], curve[i]);
    if x1 == x0 {
        y0
    } else {
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }
}

/// Σ W r² of residuals.
pub fn sum_of_squares(residuals: &[(f64, f64)]) -> f64 {
    residuals.iter().map(|&(w, r)| w * r * r).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_is_linear_and_held_outside() {
        let c = [(0.0, 1.0), (1.0, 3.0), (2.0, 2.0)];
        assert_eq!(interpolate(&c, 0.5), 2.0);
        assert_eq!(interpolate(&c, 1.0), 3.0);
        assert_eq!(interpolate(&c, 1.5), 2.5);
        assert_eq!(interpolate(&c, -1.0), 1.0);
        assert_eq!(interpolate(&c, 5.0), 2.0);
    }

    #[test]
    fn every_comparison_vanishes_on_the_curve_itself_and_sees_an_offset() {
        // A curve with a sharp jump, sampled at its own nodes.
        let curve: Vec<(f64, f64)> = (0..=40)
            .map(|i| (i as f64 * 0.25, if i < 20 { 1.0 } else { 3.0 }))
            .collect();
        let w = vec![1.0; curve.len()];
        let shifted: Vec<(f64, f64)> = curve.iter().map(|&(u, p)| (u, p + 0.5)).collect();
        for compare in [
            Compare::Raw,
            Compare::Smoothed(1.0),
            Compare::WindowMeans(2.0),
        ] {
            let same = residuals(compare, &curve, &shifted, &w);
            assert!(!same.is_empty());
            for (_, r) in same {
                assert!((r + 0.5).abs() < 1e-12, "{compare:?}: {r}");
            }
        }
        // Window means: 5 windows of 2 (the last holds u = 10 alone), each
        // weighted by its points.
        let means = residuals(Compare::WindowMeans(2.0), &curve, &curve, &w);
        assert_eq!(
            means.iter().map(|r| r.0).collect::<Vec<_>>(),
            [8.0, 8.0, 8.0, 8.0, 8.0, 1.0]
        );
    }

    #[test]
    fn objective_options_parse() {
        assert_eq!("raw".parse::<Compare>().unwrap(), Compare::Raw);
        assert_eq!(
            "smooth:2.5".parse::<Compare>().unwrap(),
            Compare::Smoothed(2.5)
        );
        assert_eq!(
            "means:4".parse::<Compare>().unwrap(),
            Compare::WindowMeans(4.0)
        );
        for bad in ["", "smooth", "smooth:0", "means:-1", "mean:2", "smooth:x"] {
            assert!(bad.parse::<Compare>().is_err(), "{bad}");
        }
    }
}
