//! Ensembles: one case run N times with imperceptible perturbations, and
//! the spread its own chaos puts on every result (docs/model.md §12).
//!
//! Member k (k = −⌊N/2⌋ … N − 1 − ⌊N/2⌋, so k = −3 … 3 for N = 7 and
//! k = 0 is the case itself) changes one key:
//! * refined model: `soil.d50` × (1 + 0.001 k), or `soil.band_width` ×
//!   (1 + 0.001 k) where the case gives the band's width as a length
//!   (d50 enters the model only through dB = N d50, so both are the same
//!   perturbation);
//! * original model: `blade.wall_friction` + 0.01° × k (in the refined
//!   model a change of the friction alone scales every candidate alike and
//!   does not set the chaos off; in the original model it does).
//!
//! Members run in parallel; their results are collected in the order of k,
//! so the output is the same on any number of threads.

use crate::accuracy::{agreement, Agreement, Spread};
use crate::error::StudyError;
use crate::figures::{mean, unit_windows, window_means};
use crate::run::{override_of, resolved_number, run_recorded, BaseCase};
use crate::Progress;
use rayon::prelude::*;
use soilcut_io::{LoadedCase, RecordedRun};
use soilcut_model::Model;
use std::sync::atomic::{AtomicUsize, Ordering};

mod files;
pub use files::{accuracy_rule, RecordedSpread, ENVELOPE};

/// Members of an ensemble by default (k = −3 … 3).
pub const DEFAULT_MEMBERS: usize = 7;
/// Relative change of d50 (or dB) per unit of k.
pub const RELATIVE_STEP: f64 = 1e-3;
/// Change of the wall friction per unit of k, degrees.
pub const FRICTION_STEP_DEG: f64 = 0.01;

/// An ensemble to run.
#[derive(Clone, Debug)]
pub struct Ensemble {
    /// The case and its `--set` overrides.
    pub base: BaseCase,
    /// Number of members N (≥ 2).
    pub members: usize,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
}

/// The key an ensemble perturbs and how.
#[derive(Clone, Debug, PartialEq)]
pub struct Perturbation {
    /// The case key, e.g. `soil.d50`.
    pub key: String,
    /// Its value in the case.
    pub base: f64,
    /// Relative (× (1 + step k)) or absolute (+ step k).
    pub relative: bool,
    /// The step per unit of k.
    pub step: f64,
}

impl Perturbation {
    /// The perturbation of the case `loaded` (M39): the original model's
    /// wall friction, the refined model's d50 where the band width is
    /// given in d50, else its band width.
    pub fn of(loaded: &LoadedCase) -> Result<Perturbation, StudyError> {
        let (key, relative, step) = match loaded.case.model {
            Model::Original => ("blade.wall_friction", false, FRICTION_STEP_DEG),
            Model::Refined if resolved_number(loaded, "soil.band_width_d50").is_ok() => {
                ("soil.d50", true, RELATIVE_STEP)
            }
            Model::Refined => ("soil.band_width", true, RELATIVE_STEP),
        };
        let value = resolved_number(loaded, key).map_err(StudyError::Spec)?;
        Ok(Perturbation {
            key: key.to_string(),
            base: value,
            relative,
            step,
        })
    }

    /// The key's value in member k (M39).
    pub fn value(&self, k: i32) -> f64 {
        self.value_at(f64::from(k))
    }

    /// The key's value at a real k (the gym draws k from [−3, 3]).
    pub fn value_at(&self, k: f64) -> f64 {
        if self.relative {
            self.base * (1.0 + self.step * k)
        } else {
            self.base + self.step * k
        }
    }

    /// The rule in words, for `summary.json`.
    pub fn rule(&self) -> String {
        if self.relative {
            format!("{} × (1 + {} k)", self.key, self.step)
        } else {
            format!("{} + {}° × k", self.key, self.step)
        }
    }
}

/// The k of each of `n` members, in order: −⌊n/2⌋ … n − 1 − ⌊n/2⌋.
pub fn member_offsets(n: usize) -> Vec<i32> {
    let first = -((n / 2) as i32);
    (0..n as i32).map(|i| first + i).collect()
}

/// The folder name of member k: `k-3`, `k+0`, `k+3`.
pub fn member_folder(k: i32) -> String {
    format!("k{k:+}")
}

/// One finished member.
#[derive(Clone, Debug)]
pub struct Member {
    /// Its k.
    pub k: i32,
    /// The perturbed key's value.
    pub value: f64,
    /// The case as run (`case.resolved.toml` shows the perturbed key).
    pub loaded: LoadedCase,
    /// The files `soilcut run` writes, and the history and summary.
    pub run: RecordedRun,
    /// (u/d, P/(γ0 d²)) of every increment.
    pub force: Vec<(f64, f64)>,
    /// Mean P/(γ0 d²) over each unit window.
    pub window_means: Vec<f64>,
    /// Mean P/(γ0 d²) over the whole run.
    pub mean_force_norm: f64,
}

/// A finished ensemble.
#[derive(Clone, Debug)]
pub struct EnsembleResult {
    /// The case's name (of the unperturbed case).
    pub name: String,
    /// The case's title.
    pub title: String,
    /// d, the depth that normalises u.
    pub depth: f64,
    /// What the members change.
    pub perturbation: Perturbation,
    /// Members in the order of k.
    pub members: Vec<Member>,
    /// The spread of each unit window's mean P/(γ0 d²).
    pub windows: Vec<Spread>,
    /// The spread of the whole-run mean P/(γ0 d²).
    pub whole_run: Spread,
    /// The spread of the largest P/(γ0 d²).
    pub max_force: Spread,
    /// The spread of the first increment's P/(γ0 d²).
    pub initial_force: Spread,
}

/// The number of members `given` (`name`: how the caller's user gave it,
/// `--ensemble` or `ensemble`), checked: at least 2, the fewest that have a
/// spread.
pub fn members_of(given: i64, name: &str) -> Result<usize, StudyError> {
    match usize::try_from(given) {
        Ok(n) if n >= 2 => Ok(n),
        _ => Err(StudyError::Spec(format!(
            "{name} {given}: an ensemble needs at least 2 members (7 is the rule's)"
        ))),
    }
}

impl Ensemble {
    /// Runs every member on a pool of `jobs` threads. Fails with the first
    /// member's error (in the order of k) if any fails.
    pub fn run(&self, progress: Progress) -> Result<EnsembleResult, StudyError> {
        let given = i64::try_from(self.members).unwrap_or(i64::MAX);
        members_of(given, "--ensemble")?;
        let loaded = self.base.load(&[])?;
        let perturbation = Perturbation::of(&loaded)?;
        let depth = loaded.case.blade.depth;
        let windows = unit_windows(loaded.case.run.travel, depth);
        let ks = member_offsets(self.members);
        let finished = AtomicUsize::new(0);
        progress(0, ks.len());
        let one = |k: i32| {
            let member = self.member(&perturbation, k, depth, windows);
            progress(finished.fetch_add(1, Ordering::Relaxed) + 1, ks.len());
            member
        };
        let members: Vec<Result<Member, StudyError>> =
            crate::pool(self.jobs)?.install(|| ks.par_iter().map(|&k| one(k)).collect());
        let members = members.into_iter().collect::<Result<Vec<_>, _>>()?;
        Ok(EnsembleResult::of(
            loaded.case.name.clone(),
            loaded.case.title.clone(),
            depth,
            perturbation,
            members,
        ))
    }

    fn member(
        &self,
        perturbation: &Perturbation,
        k: i32,
        depth: f64,
        windows: usize,
    ) -> Result<Member, StudyError> {
        let value = perturbation.value(k);
        let fail = |e: String| {
            StudyError::Case(format!(
                "member k = {k} ({} = {value}): {e}",
                perturbation.key
            ))
        };
        let extra = if k == 0 {
            vec![]
        } else {
            vec![override_of(&perturbation.key, &toml::Value::Float(value)).map_err(fail)?]
        };
        let loaded = self.base.load(&extra).map_err(|e| fail(e.to_string()))?;
        let run = run_recorded(&loaded).map_err(fail)?;
        let force: Vec<(f64, f64)> = run
            .history
            .iter()
            .map(|r| (r.u / depth, r.force_norm))
            .collect();
        let forces: Vec<f64> = force.iter().map(|p| p.1).collect();
        Ok(Member {
            k,
            value,
            window_means: window_means(&force, windows),
            mean_force_norm: mean(&forces),
            force,
            loaded,
            run,
        })
    }
}

impl EnsembleResult {
    /// The spreads of finished `members`.
    pub fn of(
        name: String,
        title: String,
        depth: f64,
        perturbation: Perturbation,
        members: Vec<Member>,
    ) -> EnsembleResult {
        let over =
            |f: &dyn Fn(&Member) -> f64| Spread::of(&members.iter().map(f).collect::<Vec<_>>());
        let windows = members.first().map_or(0, |m| m.window_means.len());
        EnsembleResult {
            windows: (0..windows).map(|w| over(&|m| m.window_means[w])).collect(),
            whole_run: over(&|m| m.mean_force_norm),
            max_force: over(&|m| m.run.summary.max_force_norm),
            initial_force: over(&|m| m.run.summary.initial_force_norm),
            name,
            title,
            depth,
            perturbation,
            members,
        }
    }

    /// This ensemble judged against `reference` by the rule of
    /// [`crate::accuracy`].
    pub fn agreement(&self, reference: &EnsembleResult) -> Agreement {
        agreement(
            &self.windows,
            &self.whole_run,
            &reference.windows,
            &reference.whole_run,
        )
    }
}
