//! Parameter sweeps: many runs of one case with varied keys, in parallel.
//!
//! Output: `sweep.csv` (one row per run, in the order of the sample, the
//! same on any number of threads), `timing.csv` (wall time per run: the
//! only figure that changes between identical runs) and, on request, each
//! run's usual output folder.

use crate::error::StudyError;
use crate::field;
use crate::figures::{key_label, Figures, LABELS, NAMES};
use crate::run::{override_of, BaseCase};
use crate::sample::{points, Sample, Values, Vary};
use crate::Progress;
use rayon::prelude::*;
use soilcut_io::Columns;
use soilcut_io::CsvText;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

mod check;
pub use check::check_keys;

/// A sweep to run.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// The case and its `--set` overrides.
    pub base: BaseCase,
    /// The varied keys, in the order given (the last changes fastest on a
    /// grid).
    pub varies: Vec<Vary>,
    /// Grid or Latin hypercube.
    pub sample: Sample,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
    /// Write each finished run's output folder `run-NNNN` under this one.
    pub keep_runs: Option<PathBuf>,
}

/// One run of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepRow {
    /// Run number, from 1, in the order of the sample.
    pub run: usize,
    /// The varied keys' values, in the order of the `--vary` arguments.
    pub values: Vec<toml::Value>,
    /// The figures, or why the run failed (one line).
    pub outcome: Result<Figures, String>,
    /// Wall time of the simulation, s (0 for a run that failed to start).
    pub wall_time_s: f64,
}

/// A finished sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepResult {
    /// The varied keys.
    pub keys: Vec<String>,
    /// One row per run, in the order of the sample.
    pub rows: Vec<SweepRow>,
}

/// The name of run `run`'s folder: `run-0001` (at least four digits).
pub fn run_folder(run: usize, total: usize) -> String {
    let width = total.to_string().len().max(4);
    format!("run-{run:0width$}")
}

impl Sweep {
    /// The runs this sweep will make (varied values per run). A varied
    /// key that no run could set (unknown to the case file, naming the
    /// nearest keys) or a listed value of a type the key does not take
    /// (`abc` for a number) is an error before any run: every run would
    /// fail alike.
    pub fn points(&self) -> Result<Vec<Vec<toml::Value>>, StudyError> {
        for vary in &self.varies {
            if let Values::List(values) = &vary.values {
                for value in values {
                    check_keys(
                        &self.base,
                        std::slice::from_ref(&vary.key),
                        std::slice::from_ref(value),
                    )?;
                }
            }
        }
        let points = points(&self.varies, self.sample)?;
        if let Some(first) = points.first() {
            let keys: Vec<String> = self.varies.iter().map(|v| v.key.clone()).collect();
            check_keys(&self.base, &keys, first)?;
        }
        Ok(points)
    }

    /// Runs every point on a pool of `jobs` threads. A run that fails is a
    /// row with its error; only a kept run folder that cannot be written
    /// fails the sweep (after every run has finished).
    pub fn run(&self, progress: Progress) -> Result<SweepResult, StudyError> {
        self.run_each(progress, &|_| {})
    }

    /// [`Sweep::run`], handing each row to `each` as its run finishes
    /// (from the worker threads, in the order they finish): a front end
    /// writes the finished runs as they come, so that a sweep stopped
    /// partway keeps them.
    pub fn run_each(
        &self,
        progress: Progress,
        each: &(dyn Fn(&SweepRow) + Sync),
    ) -> Result<SweepResult, StudyError> {
        let points = self.points()?;
        let keys: Vec<String> = self.varies.iter().map(|v| v.key.clone()).collect();
        let total = points.len();
        let finished = AtomicUsize::new(0);
        progress(0, total);
        let one = |(index, values): (usize, Vec<toml::Value>)| {
            let row = self.run_point(&keys, index + 1, total, values);
            if let Ok(row) = &row {
                each(row);
            }
            progress(finished.fetch_add(1, Ordering::Relaxed) + 1, total);
            row
        };
        let rows: Vec<Result<SweepRow, StudyError>> = crate::pool(self.jobs)?
            .install(|| points.into_par_iter().enumerate().map(one).collect());
        let rows = rows.into_iter().collect::<Result<Vec<_>, _>>()?;
        Ok(SweepResult { keys, rows })
    }

    /// Runs one point of the sweep: run number `run` (from 1) of `total`,
    /// `values` for `keys`. A sweep spread over other processes (an
    /// executor of the Python package) runs its points through here.
    pub fn run_point(
        &self,
        keys: &[String],
        run: usize,
        total: usize,
        values: Vec<toml::Value>,
    ) -> Result<SweepRow, StudyError> {
        let overrides: Result<Vec<_>, String> = keys
            .iter()
            .zip(&values)
            .map(|(k, v)| override_of(k, v))
            .collect();
        let result = overrides.and_then(|o| self.base.run(&o));
        let wall_time_s = result.as_ref().map_or(0.0, |r| r.wall_time_s);
        if let (Some(dir), Ok(result)) = (&self.keep_runs, &result) {
            let folder = dir.join(run_folder(run, total));
            soilcut_io::write_output_dir(&folder, &result.files(), false)?;
        }
        Ok(SweepRow {
            run,
            values,
            outcome: result.as_ref().map(Figures::of).map_err(Clone::clone),
            wall_time_s,
        })
    }
}

impl SweepResult {
    /// `sweep.csv`: `run`, the varied keys, `status` (`ok` or `failed`),
    /// `error`, then the figures of [`NAMES`] (empty for a failed run).
    pub fn csv(&self) -> String {
        let mut header = vec!["run".to_string()];
        header.extend(self.keys.iter().cloned());
        header.extend(["status".to_string(), "error".to_string()]);
        header.extend(NAMES.iter().map(|n| n.to_string()));
        let mut out = CsvText::named(&header);
        for row in &self.rows {
            let mut fields = vec![row.run.to_string()];
            fields.extend(row.values.iter().map(field::value));
            match &row.outcome {
                Ok(figures) => {
                    fields.extend(["ok".to_string(), String::new()]);
                    fields.extend(figures.values().iter().map(|&x| field::number(x)));
                }
                Err(e) => {
                    fields.extend(["failed".to_string(), e.clone()]);
                    fields.extend(NAMES.iter().map(|_| String::new()));
                }
            }
            out.fields(&fields);
        }
        out.finish()
    }

    /// The figures of every run ([`NAMES`]), row by row; NaN for a run
    /// that failed: the numbers of `sweep.csv`, for front ends that hand
    /// out arrays.
    pub fn figure_columns(&self) -> Columns {
        let mut out = Columns::named(NAMES.iter().map(|n| n.to_string()).collect());
        for row in &self.rows {
            match &row.outcome {
                Ok(figures) => out.push(&figures.values()),
                Err(_) => out.push(&[f64::NAN; NAMES.len()]),
            }
        }
        out
    }

    /// `timing.csv`: `run,wall_time_s`.
    pub fn timing_csv(&self) -> String {
        let mut out = CsvText::new("run,wall_time_s");
        for row in &self.rows {
            out.fields(&[row.run.to_string(), row.wall_time_s.to_string()]);
        }
        out.finish()
    }

    /// Runs that failed.
    pub fn failed(&self) -> usize {
        self.rows.iter().filter(|r| r.outcome.is_err()).count()
    }

    /// Draws `sweep-<key>.png` into `dir` for every numeric varied key:
    /// each figure against that key, one panel per figure; nothing if every
    /// run failed. Returns the files written.
    pub fn draw(&self, dir: &Path) -> Result<Vec<PathBuf>, StudyError> {
        let mut written = Vec::new();
        if self.rows.iter().all(|r| r.outcome.is_err()) {
            // Panels without a point say nothing sweep.csv does not.
            return Ok(written);
        }
        for (k, key) in self.keys.iter().enumerate() {
            let xs: Vec<Option<f64>> = self.rows.iter().map(|r| number(&r.values[k])).collect();
            if xs.iter().any(Option::is_none) {
                continue;
            }
            let panels = self.panels_against(key, &xs);
            if panels.is_empty() {
                continue;
            }
            let path = dir.join(format!("sweep-{key}.png"));
            soilcut_plot::draw_panels(
                &format!("Sweep: summary figures against {key}"),
                &panels,
                3,
                &path,
            )?;
            written.push(path);
        }
        Ok(written)
    }
}

impl SweepResult {
    /// A panel per figure against `key` (`xs` its values), but none for a
    /// figure every run gave alike: a flat row of dots says only that
    /// (sweep.csv has it).
    fn panels_against(&self, key: &str, xs: &[Option<f64>]) -> Vec<soilcut_plot::Panel> {
        (0..NAMES.len())
            .filter_map(|f| {
                let points: Vec<(f64, f64)> = self
                    .rows
                    .iter()
                    .zip(xs)
                    .filter_map(|(r, x)| Some(((*x)?, r.outcome.as_ref().ok()?.values()[f])))
                    .collect();
                let first = points.first()?.1;
                let varies = points.iter().any(|p| p.1.to_bits() != first.to_bits());
                varies.then(|| soilcut_plot::Panel {
                    x_label: key_label(key),
                    y_label: LABELS[f].to_string(),
                    series: vec![soilcut_plot::Series::points("", points)],
                })
            })
            .collect()
    }
}

fn number(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(run: usize, peak: f64, max: f64) -> SweepRow {
        let figures = Figures {
            initial_force_norm: 1.32,
            max_force_norm: max,
            u_over_d_at_max: 0.5,
            final_force_norm: max,
            peaks: 1,
            mean_force_norm_last_half: max,
            mass_drift_rel: 1e-16 * run as f64,
            band_jumps: run,
            steps: 100,
        };
        SweepRow {
            run,
            values: vec![toml::Value::Float(peak)],
            outcome: Ok(figures),
            wall_time_s: 0.0,
        }
    }

    #[test]
    fn panels_name_units_and_leave_out_figures_alike_in_every_run() {
        let result = SweepResult {
            keys: vec!["soil.friction.peak".into()],
            rows: vec![row(1, 30.0, 2.0), row(2, 35.0, 2.5), row(3, 40.0, 3.0)],
        };
        let xs = [Some(30.0), Some(35.0), Some(40.0)];
        let panels = result.panels_against("soil.friction.peak", &xs);
        let labels: Vec<&str> = panels.iter().map(|p| p.y_label.as_str()).collect();
        assert_eq!(
            labels,
            [
                "largest P/(γ₀d²) (–)",
                "last P/(γ₀d²) (–)",
                "mean P/(γ₀d²), last half (–)",
                "mass drift Δm/m₀ (–)",
                "band jumps (count)"
            ]
        );
        assert!(panels.iter().all(|p| p.x_label == "soil.friction.peak (°)"));
    }
}
