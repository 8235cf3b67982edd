//! The runs of a sensitivity study and the indices of their outputs.

use super::analysis::{output_indices, OutputIndices};
use super::plan::{Plan, Run, RunRow};
use super::tornado::{self, TornadoPoint};
use super::{outputs, Model, Sensitivity};
use crate::error::StudyError;
use crate::Progress;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

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

impl Sensitivity {
    /// Runs every design point's members, and the tornado's of a case, on
    /// `jobs` threads, and computes the indices of every output: the
    /// [`plan`](Sensitivity::plan), each run by [`Model::run`], then
    /// [`analyse`](Sensitivity::analyse), as any other executor would.
    pub fn run(&self, progress: Progress) -> Result<SensitivityResult, StudyError> {
        let plan = self.plan()?;
        let finished = AtomicUsize::new(0);
        let total = plan.runs.len();
        progress(0, total);
        let one = |run: &Run| {
            let row = self.model.run(run);
            progress(finished.fetch_add(1, Ordering::Relaxed) + 1, total);
            row
        };
        let rows = crate::pool(self.jobs)?.install(|| plan.runs.par_iter().map(one).collect());
        self.analyse(plan, rows)
    }

    /// The study from its `plan` and the rows of its runs, in the plan's
    /// order (from any executor): the outputs' names, the indices (or the
    /// first failed run) and everything the files say. Refuses rows that
    /// are not the plan's runs.
    pub fn analyse(&self, plan: Plan, rows: Vec<RunRow>) -> Result<SensitivityResult, StudyError> {
        check_rows(&plan, &rows)?;
        let mut runs = rows;
        let mut tornado_runs = runs.split_off(plan.design_runs());
        let outputs = match self.model {
            Model::Case(_) => {
                let windows = common_windows(&runs);
                fit_windows(&mut runs, windows);
                fit_windows(&mut tornado_runs, windows);
                outputs::names(windows)
            }
            Model::Function(_) => vec!["f".to_string()],
        };
        let tornado = plan.tornado;
        let analysis = analyse(self, &plan.unit, &runs, &outputs).and_then(|a| {
            failure(&tornado_runs, |row| {
                self.tornado_run_named(&tornado[row.point], row.k)
            })?;
            Ok(a)
        });
        Ok(SensitivityResult {
            study: self.clone(),
            keys: self.keys(),
            outputs,
            design: plan.unit,
            values: plan.values,
            runs,
            tornado,
            tornado_runs,
            perturbation: plan.perturbation,
            analysis,
        })
    }

    fn tornado_run_named(&self, point: &TornadoPoint, k: i32) -> String {
        match point.setting(&self.ranges) {
            Some((key, value)) => format!("tornado run {key} = {value} (member k = {k})"),
            None => format!("tornado run of the case (member k = {k})"),
        }
    }
}

/// Refuses `rows` that are not `plan`'s runs, one for one (a caller's
/// executor that lost or reordered some).
fn check_rows(plan: &Plan, rows: &[RunRow]) -> Result<(), StudyError> {
    if rows.len() != plan.runs.len() {
        return Err(StudyError::Spec(format!(
            "runs: {} rows for a plan of {} runs",
            rows.len(),
            plan.runs.len()
        )));
    }
    let stray = plan
        .runs
        .iter()
        .zip(rows)
        .position(|(run, row)| run.point.index() != row.point || run.k != row.k);
    match stray {
        Some(i) => Err(StudyError::Spec(format!(
            "runs: row {} is point {} member k = {}, the plan's run {:?} member k = {}",
            i + 1,
            rows[i].point + 1,
            rows[i].k,
            plan.runs[i].point,
            plan.runs[i].k
        ))),
        None => Ok(()),
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
