//! The runs of a sensitivity study and the indices of their outputs.

use super::analysis::{output_indices, OutputIndices};
use super::tornado::{self, TornadoPoint};
use super::{design, outputs, Method, Model, Sensitivity};
use super::{DEFAULT_LEVELS, MIN_SOBOL_SAMPLES, MIN_TRAJECTORIES};
use crate::ensemble::{member_offsets, Perturbation};
use crate::error::StudyError;
use crate::run::{override_of, BaseCase};
use crate::sample::MAX_RUNS;
use crate::Progress;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One run: member k of design point `point`.
#[derive(Clone, Debug, PartialEq)]
pub struct RunRow {
    /// Design point, from 0, in the design's order.
    pub point: usize,
    /// Member k (0 without members).
    pub k: i32,
    /// The outputs ([`OUTPUTS`](super::OUTPUTS), then the unit windows', or `f`), or why the run failed.
    pub outcome: Result<Vec<f64>, String>,
    /// Wall time of the simulation, s.
    pub wall_time_s: f64,
}

/// A finished sensitivity study.
#[derive(Clone, Debug)]
pub struct SensitivityResult {
    /// The study as given.
    pub study: Sensitivity,
    /// The inputs (the keys, then `dummy`).
    pub keys: Vec<String>,
    /// The outputs' names.
    pub outputs: Vec<String>,
    /// The design in the unit cube, one row per point.
    pub design: Vec<Vec<f64>>,
    /// The inputs' values of each point.
    pub values: Vec<Vec<f64>>,
    /// Every run, point by point, members in the order of k.
    pub runs: Vec<RunRow>,
    /// The tornado's points (none for a test function).
    pub tornado: Vec<TornadoPoint>,
    /// Their runs, point by point, members in the order of k.
    pub tornado_runs: Vec<RunRow>,
    /// The ensembles' rule, if K > 1.
    pub perturbation: Option<String>,
    /// The indices per output, or the first failed run.
    pub analysis: Result<Vec<OutputIndices>, String>,
}

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
        Method::Sobol if n < MIN_SOBOL_SAMPLES || !n.is_power_of_two() => Err(spec(format!(
            "--samples {n}: Sobol indices need N a power of 2 and at least {MIN_SOBOL_SAMPLES} \
             (SALib's guidance: 500 or more per input)"
        ))),
        Method::Sobol if 2 * keys.len() > super::sequence::MAX_DIMENSIONS => Err(spec(format!(
            "--vary: {} inputs; Sobol indices take at most {} (the sequence's dimensions / 2): \
             screen them first with --method morris",
            keys.len(),
            super::sequence::MAX_DIMENSIONS / 2
        ))),
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

impl Sensitivity {
    /// The design: in the unit cube, and scaled to the keys' ranges
    /// (`dummy` over [0, 1]).
    fn design(&self) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let d = self.keys().len();
        let unit = match self.method {
            Method::Morris { levels } => design::morris(d, self.samples, levels, self.seed),
            Method::Sobol => design::saltelli(d, self.samples, self.seed),
        };
        let scale = |row: &Vec<f64>| {
            row.iter()
                .enumerate()
                .map(|(j, u)| match self.ranges.get(j) {
                    Some(r) => r.lo + (r.hi - r.lo) * u,
                    None => *u,
                })
                .collect()
        };
        let values = unit.iter().map(scale).collect();
        (unit, values)
    }

    /// Runs every design point's members, and the tornado's of a case, on
    /// `jobs` threads, and computes the indices of every output.
    pub fn run(&self, progress: Progress) -> Result<SensitivityResult, StudyError> {
        self.check()?;
        let (unit, values) = self.design();
        let perturbation = self.perturbation()?;
        let ks = if self.members > 1 {
            member_offsets(self.members)
        } else {
            vec![0]
        };
        let tornado = self.tornado_points();
        let points = (0..values.len()).map(Job::Design);
        let points = points.chain((0..tornado.len()).map(Job::Tornado));
        let jobs: Vec<(Job, i32)> = points
            .flat_map(|p| ks.iter().map(move |&k| (p, k)))
            .collect();
        let finished = AtomicUsize::new(0);
        progress(0, jobs.len());
        let one = |&(job, k): &(Job, i32)| {
            let (point, (outcome, wall_time_s)) = match job {
                Job::Design(p) => (p, self.run_point(&values[p], k)),
                Job::Tornado(t) => (t, self.run_tornado(&tornado[t], k)),
            };
            progress(finished.fetch_add(1, Ordering::Relaxed) + 1, jobs.len());
            RunRow {
                point,
                k,
                outcome,
                wall_time_s,
            }
        };
        let mut runs: Vec<RunRow> =
            crate::pool(self.jobs)?.install(|| jobs.par_iter().map(one).collect());
        let mut tornado_runs = runs.split_off(values.len() * ks.len());
        let outputs = match self.model {
            Model::Case(_) => {
                let windows = common_windows(&runs);
                fit_windows(&mut runs, windows);
                fit_windows(&mut tornado_runs, windows);
                outputs::names(windows)
            }
            Model::Function(_) => vec!["f".to_string()],
        };
        let analysis = analyse(self, &unit, &runs, &outputs).and_then(|a| {
            failure(&tornado_runs, |row| {
                self.tornado_run_named(&tornado[row.point], row.k)
            })?;
            Ok(a)
        });
        Ok(SensitivityResult {
            study: self.clone(),
            keys: self.keys(),
            outputs,
            design: unit,
            values,
            runs,
            tornado,
            tornado_runs,
            perturbation: perturbation.map(|p| p.rule()),
            analysis,
        })
    }

    /// The tornado's points: a case's (none for a test function, which
    /// has no values of its own).
    fn tornado_points(&self) -> Vec<TornadoPoint> {
        match self.model {
            Model::Case(_) => tornado::points(self.ranges.len()),
            Model::Function(_) => Vec::new(),
        }
    }

    fn tornado_run_named(&self, point: &TornadoPoint, k: i32) -> String {
        match point.setting(&self.ranges) {
            Some((key, value)) => format!("tornado run {key} = {value} (member k = {k})"),
            None => format!("tornado run of the case (member k = {k})"),
        }
    }

    /// The ensembles' rule at the case's own values (for summary.json);
    /// each point takes it at its own values.
    fn perturbation(&self) -> Result<Option<Perturbation>, StudyError> {
        match &self.model {
            Model::Case(base) if self.members > 1 => Ok(Some(Perturbation::of(&base.load(&[])?)?)),
            _ => Ok(None),
        }
    }

    /// Member k of the design point `values`: its outputs and wall time.
    fn run_point(&self, values: &[f64], k: i32) -> (Result<Vec<f64>, String>, f64) {
        match &self.model {
            Model::Function(f) => (Ok(vec![f.value(values)]), 0.0),
            Model::Case(base) => {
                let keys = self.ranges.iter().map(|r| r.key.as_str());
                let set: Vec<(&str, f64)> = keys.zip(values.iter().copied()).collect();
                run_member(base, &set, k)
            }
        }
    }

    /// Member k of a tornado point (a case's only).
    fn run_tornado(&self, point: &TornadoPoint, k: i32) -> (Result<Vec<f64>, String>, f64) {
        match &self.model {
            Model::Case(base) => run_member(
                base,
                &point.setting(&self.ranges).into_iter().collect::<Vec<_>>(),
                k,
            ),
            Model::Function(_) => (Err("a test function has no tornado".into()), 0.0),
        }
    }
}

/// What a run is: a design point, or a tornado point (their indices).
#[derive(Clone, Copy, Debug)]
enum Job {
    Design(usize),
    Tornado(usize),
}

/// Member k of the case with the keys `set` to their values: its outputs
/// and wall time.
fn run_member(base: &BaseCase, set: &[(&str, f64)], k: i32) -> (Result<Vec<f64>, String>, f64) {
    let mut overrides = Vec::new();
    for (key, v) in set {
        match override_of(key, &toml::Value::Float(*v)) {
            Ok(o) => overrides.push(o),
            Err(e) => return (Err(e), 0.0),
        }
    }
    if k != 0 {
        let member = base
            .load(&overrides)
            .map_err(|e| e.to_string())
            .and_then(|l| Perturbation::of(&l).map_err(|e| e.to_string()))
            .and_then(|p| override_of(&p.key, &toml::Value::Float(p.value(k))));
        match member {
            Ok(o) => overrides.push(o),
            Err(e) => return (Err(e), 0.0),
        }
    }
    match base.run(&overrides) {
        Ok(run) => (Ok(outputs::outputs_of(&run)), run.wall_time_s),
        Err(e) => (Err(e), 0.0),
    }
}

/// The first failed run of `rows`, as "`named(row)` failed: why", or every
/// row's outputs.
fn failure(rows: &[RunRow], named: impl Fn(&RunRow) -> String) -> Result<Vec<&[f64]>, String> {
    rows.iter()
        .map(|row| match &row.outcome {
            Ok(v) => Ok(v.as_slice()),
            Err(e) => Err(format!("{} failed: {e}", named(row))),
        })
        .collect()
}

/// The indices of each output's ensemble mean, and its chaos share; the
/// first failed run's message if any failed (there is no estimator with
/// holes).
fn analyse(
    s: &Sensitivity,
    unit: &[Vec<f64>],
    runs: &[RunRow],
    names: &[String],
) -> Result<Vec<OutputIndices>, String> {
    let named = |row: &RunRow| format!("design point {} (member k = {})", row.point + 1, row.k);
    let values = failure(runs, named)?;
    let output = |(o, name): (usize, &String)| output_indices(s, unit, &values, o, name);
    Ok(names.iter().enumerate().map(output).collect())
}

/// The unit windows every design run covers: the fewest of any (a case
/// whose travel or depth is varied covers fewer windows in some runs).
fn common_windows(runs: &[RunRow]) -> usize {
    let fixed = outputs::OUTPUTS.len();
    runs.iter()
        .filter_map(|r| r.outcome.as_ref().ok())
        .map(|v| v.len().saturating_sub(fixed))
        .min()
        .unwrap_or(0)
}

/// Gives every run of `rows` `windows` unit windows: the further ones
/// dropped, those a tornado run does not cover NaN (the case's own travel
/// may be shorter than a varied travel's range).
fn fit_windows(rows: &mut [RunRow], windows: usize) {
    for row in rows {
        if let Ok(v) = &mut row.outcome {
            v.resize(outputs::OUTPUTS.len() + windows, f64::NAN);
        }
    }
}

impl SensitivityResult {
    /// Output `name`'s tornado (the case's value and each key's at its
    /// ends), or None: no tornado (a test function), no such output, or a
    /// run of it failed.
    pub fn tornado_ranges(&self, name: &str) -> Option<tornado::Ranges> {
        let o = self.outputs.iter().position(|n| n == name)?;
        if self.tornado.is_empty() {
            return None;
        }
        let values = failure(&self.tornado_runs, |_| String::new()).ok()?;
        let means = tornado::means(&values, values.len() / self.tornado.len());
        Some(tornado::ranges_of(&means, o))
    }
}
