//! Calibration: the free case keys that best match a measured
//! force-displacement curve.
//!
//! Objective: the RMS difference between the measured force and the
//! simulated force at the measured displacements,
//!
//!   E = sqrt( (1/m) Σᵢ (P_sim(uᵢ) − Pᵢ)² ),
//!
//! with P_sim the run's `force` (P*, per unit width, in γ·length²) linearly
//! interpolated in u between the increments of the run (held at its first
//! and last value outside them). A run that fails (an invalid combination,
//! no admissible mechanism) costs [`FAILED_COST`].
//!
//! Method: Nelder-Mead (argmin) in coordinates scaled to the bounds
//! (z = (x − lo)/(hi − lo) ∈ [0, 1]; a point outside costs more than any
//! failure, growing with the distance), from several starts run in
//! parallel: the case's own values and `starts − 1` seeded Latin-hypercube
//! points of the box (a start where the case fails is moved halfway
//! towards the case's values until it runs). The best of the starts is
//! polished by one more Nelder-Mead run from a fresh, smaller simplex
//! around it.

use crate::csv;
use crate::error::StudyError;
use crate::run::{override_of, BaseCase, RunResult};
use crate::Progress;
use argmin::core::{CostFunction, Error as ArgminError, Executor, State};
use argmin::solver::neldermead::NelderMead;
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use std::cell::Cell;
use std::fmt::Write as _;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Cost of a run that fails.
pub const FAILED_COST: f64 = 1e12;

/// Initial simplex: the start and one step of this size (in scaled
/// coordinates, a fraction of each parameter's range) along each axis.
pub const SIMPLEX_STEP: f64 = 0.1;

/// The polish of the best start uses steps of this size.
pub const POLISH_STEP: f64 = 0.03;

/// Nelder-Mead stops when the standard deviation of the simplex's costs
/// falls below this fraction of the RMS measured force.
pub const COST_TOLERANCE: f64 = 1e-6;

/// Times a failing start is moved halfway to the case's own values.
pub const FEASIBLE_TRIES: usize = 6;

/// A free parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Free {
    /// The case-file key (`soil.friction.peak`).
    pub key: String,
    /// The case's own value.
    pub start: f64,
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

/// Default bounds of a free key around its start value `x`, and the rule
/// in words:
/// * friction angles (`soil.friction.*`), `soil.repose`: x ± 10° within
///   [0°, 90°];
/// * `blade.wall_friction`: x ± 10° within [0°, 90°];
/// * dilation angles (`soil.dilation.*`): x ± 10° within [−45°, 45°];
/// * lengths and other positive sizes (`soil.peak_shear`,
///   `soil.residual_shear`, `soil.d50`, `soil.band_width`,
///   `soil.band_width_d50`, `soil.unit_weight`, `blade.depth`):
///   0.5 x to 2 x (x must be > 0).
///
/// The ends of a range may themselves be invalid (0°, 90°): runs there
/// fail and cost [`FAILED_COST`]. Any other key needs `--bounds`.
pub fn default_bounds(key: &str, x: f64) -> Result<(f64, f64), String> {
    let angle = |lo: f64, hi: f64| Ok(((x - 10.0).max(lo), (x + 10.0).min(hi)));
    match key {
        "soil.friction.initial"
        | "soil.friction.peak"
        | "soil.friction.residual"
        | "soil.repose"
        | "blade.wall_friction" => angle(0.0, 90.0),
        "soil.dilation.initial" | "soil.dilation.peak" | "soil.dilation.residual" => {
            angle(-45.0, 45.0)
        }
        "soil.peak_shear"
        | "soil.residual_shear"
        | "soil.d50"
        | "soil.band_width"
        | "soil.band_width_d50"
        | "soil.unit_weight"
        | "blade.depth" => {
            if x > 0.0 {
                Ok((0.5 * x, 2.0 * x))
            } else {
                Err(format!(
                    "{key}: no default bounds for a start of {x} (give --bounds {key}=lo:hi)"
                ))
            }
        }
        _ => Err(format!(
            "{key}: no default bounds for this key (give --bounds {key}=lo:hi)"
        )),
    }
}

/// Parses `--bounds key=lo:hi`.
pub fn parse_bounds(text: &str) -> Result<(String, f64, f64), StudyError> {
    let bad = || {
        StudyError::Spec(format!(
            "--bounds {text}: expected key.path=lo:hi with lo < hi"
        ))
    };
    let (key, range) = text.split_once('=').ok_or_else(bad)?;
    let (lo, hi) = range.split_once(':').ok_or_else(bad)?;
    let lo: f64 = lo.trim().parse().map_err(|_| bad())?;
    let hi: f64 = hi.trim().parse().map_err(|_| bad())?;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) || key.trim().is_empty() {
        return Err(bad());
    }
    Ok((key.trim().to_string(), lo, hi))
}

/// A calibration to run.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The case and its `--set` overrides.
    pub base: BaseCase,
    /// The free keys, in order.
    pub free: Vec<String>,
    /// Bounds that replace the defaults: (key, lo, hi).
    pub bounds: Vec<(String, f64, f64)>,
    /// The measured curve: (u, force per unit width), case units.
    pub measured: Vec<(f64, f64)>,
    /// Nelder-Mead starts (the first is the case's own values).
    pub starts: usize,
    /// Seed of the Latin-hypercube starts.
    pub seed: u64,
    /// Nelder-Mead iterations per start (and for the polish).
    pub max_iters: u64,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
}

/// One Nelder-Mead run.
#[derive(Clone, Debug, PartialEq)]
pub struct StartResult {
    /// Where it started (parameter values).
    pub from: Vec<f64>,
    /// Where it ended.
    pub best: Vec<f64>,
    /// RMS force difference at `best` (γ·length²).
    pub rms: f64,
    /// Objective evaluations (case runs).
    pub evaluations: u64,
    /// Nelder-Mead iterations.
    pub iterations: u64,
}

/// A finished calibration.
#[derive(Clone, Debug)]
pub struct FitResult {
    /// The free keys with their starts and bounds.
    pub params: Vec<Free>,
    /// Best values, in the order of `params`.
    pub best: Vec<f64>,
    /// RMS force difference at the best values (γ·length²).
    pub best_rms: f64,
    /// RMS force difference at the case's own values.
    pub start_rms: f64,
    /// The starts, in order, then the polish as the last entry.
    pub starts: Vec<StartResult>,
    /// The measured curve: (u, force per unit width).
    pub measured: Vec<(f64, f64)>,
    /// Runs of the case at the start and at the best values.
    pub start_run: RunResult,
    /// Run of the case at the best values.
    pub best_run: RunResult,
}

/// RMS difference between `measured` and the run's force interpolated at
/// the measured u (see the module documentation).
pub fn rms_error(run: &RunResult, measured: &[(f64, f64)]) -> f64 {
    let curve: Vec<(f64, f64)> = run.history.iter().map(|r| (r.u, r.force)).collect();
    let sum: f64 = measured
        .iter()
        .map(|&(u, p)| (interpolate(&curve, u) - p).powi(2))
        .sum();
    (sum / measured.len() as f64).sqrt()
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

/// The objective in scaled coordinates, counting its evaluations.
#[derive(Clone, Copy)]
struct Objective<'a> {
    fit: &'a Fit,
    params: &'a [Free],
    evaluations: &'a Cell<u64>,
}

impl Objective<'_> {
    fn values(&self, z: &[f64]) -> Vec<f64> {
        self.params
            .iter()
            .zip(z)
            .map(|(p, &z)| p.lo + (p.hi - p.lo) * z)
            .collect()
    }

    fn evaluate(&self, z: &[f64]) -> f64 {
        self.evaluations.set(self.evaluations.get() + 1);
        let outside: f64 = z.iter().map(|&z| (-z).max(z - 1.0).max(0.0)).sum();
        if outside > 0.0 {
            return FAILED_COST * (2.0 + outside);
        }
        match run_at(&self.fit.base, self.params, &self.values(z)) {
            Ok(run) => rms_error(&run, &self.fit.measured),
            Err(_) => FAILED_COST,
        }
    }
}

impl CostFunction for Objective<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, z: &Vec<f64>) -> Result<f64, ArgminError> {
        Ok(self.evaluate(z))
    }
}

/// Runs the case with the free keys at `values`.
fn run_at(base: &BaseCase, params: &[Free], values: &[f64]) -> Result<RunResult, String> {
    let overrides = params
        .iter()
        .zip(values)
        .map(|(p, &x)| override_of(&p.key, &toml::Value::Float(x)))
        .collect::<Result<Vec<_>, _>>()?;
    base.run(&overrides)
}

/// The initial simplex: `z0` and one step along each axis (backwards where
/// forwards would leave [0, 1]).
fn simplex(z0: &[f64], step: f64) -> Vec<Vec<f64>> {
    let mut vertices = vec![z0.to_vec()];
    for i in 0..z0.len() {
        let mut v = z0.to_vec();
        v[i] = if v[i] + step <= 1.0 {
            v[i] + step
        } else {
            v[i] - step
        };
        vertices.push(v);
    }
    vertices
}

impl Fit {
    /// The free parameters with their starts and bounds.
    pub fn params(&self) -> Result<Vec<Free>, StudyError> {
        if self.free.is_empty() {
            return Err(StudyError::Spec("give at least one --free key".to_string()));
        }
        for (key, ..) in &self.bounds {
            if !self.free.contains(key) {
                return Err(StudyError::Spec(format!(
                    "--bounds {key}: not one of the --free keys"
                )));
            }
        }
        let mut params = Vec::new();
        for (i, key) in self.free.iter().enumerate() {
            if self.free[..i].contains(key) {
                return Err(StudyError::Spec(format!("--free {key}: given twice")));
            }
            let start = self.base.number(key).map_err(StudyError::Spec)?;
            let (lo, hi) = match self.bounds.iter().rev().find(|b| &b.0 == key) {
                Some(&(_, lo, hi)) => (lo, hi),
                None => default_bounds(key, start).map_err(StudyError::Spec)?,
            };
            if !(lo..=hi).contains(&start) {
                return Err(StudyError::Spec(format!(
                    "--bounds {key}={lo}:{hi}: the start value {start} lies outside"
                )));
            }
            params.push(Free {
                key: key.clone(),
                start,
                lo,
                hi,
            });
        }
        Ok(params)
    }

    fn check_measured(&self) -> Result<(), StudyError> {
        if self.measured.len() < 2 {
            return Err(StudyError::Spec(
                "the measured curve needs at least 2 points".to_string(),
            ));
        }
        let travel = self.base.load(&[])?.case.run.travel;
        let u_max = self.measured.iter().map(|p| p.0).fold(f64::MIN, f64::max);
        let u_min = self.measured.iter().map(|p| p.0).fold(f64::MAX, f64::min);
        if u_min < 0.0 || u_max > travel {
            return Err(StudyError::Spec(format!(
                "the measured u ({u_min} to {u_max}) must lie within 0 and the case's run.travel = {travel} (set run.travel to cover it)"
            )));
        }
        Ok(())
    }

    /// Starting points in scaled coordinates: the case's values, then a
    /// seeded Latin-hypercube sample of the box.
    fn start_points(&self, params: &[Free]) -> Vec<Vec<f64>> {
        let z0: Vec<f64> = params
            .iter()
            .map(|p| (p.start - p.lo) / (p.hi - p.lo))
            .collect();
        let others = self.starts.saturating_sub(1);
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let mut points = vec![Vec::with_capacity(params.len()); others];
        for _ in params {
            let mut strata: Vec<usize> = (0..others).collect();
            strata.shuffle(&mut rng);
            for (point, stratum) in points.iter_mut().zip(strata) {
                point.push((stratum as f64 + rng.random::<f64>()) / others as f64);
            }
        }
        std::iter::once(z0).chain(points).collect()
    }

    fn nelder_mead(&self, params: &[Free], z0: &[f64], step: f64, tolerance: f64) -> StartResult {
        let evaluations = Cell::new(0);
        let objective = Objective {
            fit: self,
            params,
            evaluations: &evaluations,
        };
        // A start where the case fails (e.g. up > ur) gives a flat simplex
        // that stops at once: move it halfway to the case's own values
        // until it runs (a few times at most).
        let home: Vec<f64> = params
            .iter()
            .map(|p| (p.start - p.lo) / (p.hi - p.lo))
            .collect();
        let mut z0 = z0.to_vec();
        for _ in 0..FEASIBLE_TRIES {
            if objective.evaluate(&z0) < FAILED_COST {
                break;
            }
            z0 = z0.iter().zip(&home).map(|(z, h)| 0.5 * (z + h)).collect();
        }
        let z0 = &z0[..];
        let solver = NelderMead::new(simplex(z0, step))
            .with_sd_tolerance(tolerance)
            .expect("a non-negative tolerance");
        let result = Executor::new(objective, solver)
            .configure(|state| state.max_iters(self.max_iters))
            .run();
        let (z_best, iterations) = match result {
            Ok(r) => (
                r.state()
                    .get_best_param()
                    .cloned()
                    .unwrap_or_else(|| z0.to_vec()),
                r.state().get_iter(),
            ),
            // The objective never fails; keep the start if argmin does.
            Err(_) => (z0.to_vec(), 0),
        };
        let rms = objective.evaluate(&z_best);
        StartResult {
            from: objective.values(z0),
            best: objective.values(&z_best),
            rms,
            evaluations: evaluations.get(),
            iterations,
        }
    }

    /// Runs the calibration. `progress` counts finished Nelder-Mead runs
    /// (the starts and the polish).
    pub fn run(&self, progress: Progress) -> Result<FitResult, StudyError> {
        let params = self.params()?;
        self.check_measured()?;
        let starts = self.starts.max(1);
        let start_values: Vec<f64> = params.iter().map(|p| p.start).collect();
        let start_run = run_at(&self.base, &params, &start_values)
            .map_err(|e| StudyError::Case(format!("the case at its own values cannot run: {e}")))?;
        let start_rms = rms_error(&start_run, &self.measured);
        let scale = (self.measured.iter().map(|p| p.1 * p.1).sum::<f64>()
            / self.measured.len() as f64)
            .sqrt();
        let tolerance = COST_TOLERANCE * scale.max(f64::MIN_POSITIVE);
        let total = starts + 1;
        let finished = AtomicUsize::new(0);
        progress(0, total);
        let points = self.start_points(&params);
        let pool = crate::pool(self.jobs)?;
        let mut results: Vec<StartResult> = pool.install(|| {
            points
                .par_iter()
                .map(|z0| {
                    let r = self.nelder_mead(&params, z0, SIMPLEX_STEP, tolerance);
                    progress(finished.fetch_add(1, Ordering::Relaxed) + 1, total);
                    r
                })
                .collect()
        });
        let best_start = best_of(&results);
        let z_best: Vec<f64> = params
            .iter()
            .zip(&best_start.best)
            .map(|(p, x)| (x - p.lo) / (p.hi - p.lo))
            .collect();
        let polish = self.nelder_mead(&params, &z_best, POLISH_STEP, tolerance);
        progress(total, total);
        results.push(polish);
        let best = best_of(&results).best.clone();
        let best_run = run_at(&self.base, &params, &best).map_err(|e| {
            StudyError::Case(format!(
                "no start found a set of values that runs (last error: {e})"
            ))
        })?;
        let best_rms = rms_error(&best_run, &self.measured);
        Ok(FitResult {
            params,
            best,
            best_rms,
            start_rms,
            starts: results,
            measured: self.measured.clone(),
            start_run,
            best_run,
        })
    }
}

/// The result of least RMS; the first of equals.
fn best_of(results: &[StartResult]) -> &StartResult {
    results
        .iter()
        .reduce(|best, r| if r.rms < best.rms { r } else { best })
        .expect("at least one start")
}

impl FitResult {
    /// `best.toml`: the case at the best values, resolved.
    pub fn best_toml(&self) -> String {
        self.best_run.loaded.resolved_toml()
    }

    /// `fit.csv`: `key,start,lo,hi,best`, one row per free key.
    pub fn csv(&self) -> String {
        let mut out = String::from("key,start,lo,hi,best\n");
        for (p, best) in self.params.iter().zip(&self.best) {
            out.push_str(&csv::line(&[
                csv::field(&p.key),
                p.start.to_string(),
                p.lo.to_string(),
                p.hi.to_string(),
                best.to_string(),
            ]));
        }
        out
    }

    /// `curves.csv`: at each measured u, the measured force and the
    /// simulated force at the start and at the best values.
    pub fn curves_csv(&self) -> String {
        let start: Vec<(f64, f64)> = self
            .start_run
            .history
            .iter()
            .map(|r| (r.u, r.force))
            .collect();
        let best: Vec<(f64, f64)> = self
            .best_run
            .history
            .iter()
            .map(|r| (r.u, r.force))
            .collect();
        let mut out = String::from("u,measured,start,fitted\n");
        for &(u, p) in &self.measured {
            out.push_str(&csv::line(&[
                u.to_string(),
                p.to_string(),
                interpolate(&start, u).to_string(),
                interpolate(&best, u).to_string(),
            ]));
        }
        out
    }

    /// `fit.md`: the objective, the result and every start, readable.
    pub fn markdown(&self, title: &str) -> String {
        let mut s = String::new();
        let w = &mut s;
        let _ = writeln!(w, "# Fit: {title}\n");
        let _ = writeln!(
            w,
            "Objective: RMS difference between the measured force and the simulated force P* (per unit width) linearly interpolated at the {} measured displacements.\n",
            self.measured.len()
        );
        let _ = writeln!(w, "| | RMS error |\n|---|---|");
        let _ = writeln!(w, "| start (the case's values) | {} |", self.start_rms);
        let _ = writeln!(w, "| best | {} |\n", self.best_rms);
        let _ = writeln!(
            w,
            "| key | start | lower bound | upper bound | best |\n|---|---|---|---|---|"
        );
        for (p, best) in self.params.iter().zip(&self.best) {
            let _ = writeln!(
                w,
                "| `{}` | {} | {} | {} | {} |",
                p.key, p.start, p.lo, p.hi, best
            );
        }
        let _ = writeln!(
            w,
            "\nNelder-Mead runs (the last is the polish of the best start):\n"
        );
        let _ = writeln!(
            w,
            "| run | from | to | RMS error | evaluations | iterations |\n|---|---|---|---|---|---|"
        );
        let list = |v: &[f64]| {
            v.iter()
                .map(|x| format!("{x:.4}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        for (i, r) in self.starts.iter().enumerate() {
            let name = if i + 1 == self.starts.len() {
                "polish".to_string()
            } else {
                (i + 1).to_string()
            };
            let _ = writeln!(
                w,
                "| {name} | {} | {} | {} | {} | {} |",
                list(&r.from),
                list(&r.best),
                r.rms,
                r.evaluations,
                r.iterations
            );
        }
        s
    }

    /// `fit.png`: the measured points and the simulated force curves at
    /// the start and at the best values.
    pub fn draw(&self, path: &Path) -> Result<(), StudyError> {
        use soilcut_plot::{draw_panels, Panel, Series};
        let curve = |run: &RunResult| run.history.iter().map(|r| (r.u, r.force)).collect();
        let u_max = self.measured.iter().map(|p| p.0).fold(0.0, f64::max);
        let clip = |points: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
            points.into_iter().filter(|p| p.0 <= u_max).collect()
        };
        let panel = Panel {
            x_label: "u (case length unit)".to_string(),
            y_label: "force per unit width".to_string(),
            series: vec![
                Series::points("measured", self.measured.clone()),
                Series::line(
                    &format!("start, RMS {:.4}", self.start_rms),
                    clip(curve(&self.start_run)),
                ),
                Series::line(
                    &format!("fitted, RMS {:.4}", self.best_rms),
                    clip(curve(&self.best_run)),
                ),
            ],
        };
        draw_panels("Fit: measured and simulated force", &[panel], 1, path)?;
        Ok(())
    }
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
    fn default_bounds_per_key() {
        assert_eq!(default_bounds("soil.friction.peak", 35.0), Ok((25.0, 45.0)));
        assert_eq!(
            default_bounds("soil.friction.initial", 5.0),
            Ok((0.0, 15.0))
        );
        assert_eq!(default_bounds("soil.dilation.peak", 40.0), Ok((30.0, 45.0)));
        assert_eq!(default_bounds("soil.peak_shear", 2.0), Ok((1.0, 4.0)));
        assert!(default_bounds("soil.peak_shear", 0.0).is_err());
        assert!(default_bounds("run.increment", 0.2).is_err());
        assert_eq!(
            parse_bounds("soil.peak_shear=0.5:3").unwrap(),
            ("soil.peak_shear".to_string(), 0.5, 3.0)
        );
        for bad in ["x", "a=1", "a=2:1", "a=x:1", "=1:2"] {
            assert!(parse_bounds(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn simplex_stays_in_the_box() {
        let s = simplex(&[0.5, 0.95], 0.1);
        assert_eq!(s.len(), 3);
        assert_eq!(s[1], vec![0.6, 0.95]);
        assert_eq!(s[2][0], 0.5);
        assert!((s[2][1] - 0.85).abs() < 1e-12, "backwards at the upper end");
    }
}
