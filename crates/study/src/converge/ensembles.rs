//! Convergence judged on ensembles (docs/model.md §12): every level is an
//! ensemble of perturbed runs ([`crate::ensemble`]), and each level is
//! judged against the finest by the rule of [`crate::accuracy`].

use super::{Refine, Resolution};
use crate::accuracy::{Agreement, Spread};
use crate::ensemble::{accuracy_rule, Ensemble, EnsembleResult};
use crate::error::StudyError;
use crate::field;
use crate::run::BaseCase;
use crate::Progress;
use soilcut_io::CsvText;
use soilcut_model::Ground;
use std::fmt::Write as _;

/// A convergence study of ensembles to run.
#[derive(Clone, Debug)]
pub struct EnsembleConverge {
    /// The case and its `--set` overrides.
    pub base: BaseCase,
    /// Number of levels; level k halves the resolution k times.
    pub levels: usize,
    /// What each level halves.
    pub refine: Refine,
    /// Members of each level's ensemble.
    pub members: usize,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
}

/// One level's ensemble.
#[derive(Clone, Debug)]
pub struct EnsembleLevel {
    /// Level k, from 0.
    pub level: usize,
    /// v0 of the level (length).
    pub increment: f64,
    /// The spacing of the level's ground points: the vertex spacing, or
    /// v0 on the node grid (length).
    pub spacing: f64,
    /// The level's ensemble.
    pub ensemble: EnsembleResult,
}

/// A finished convergence study of ensembles.
#[derive(Clone, Debug)]
pub struct EnsembleConvergeResult {
    /// The case's title.
    pub title: String,
    /// What each level halved.
    pub refine: Refine,
    /// The case's ground, on which every level runs.
    pub ground: Ground,
    /// Coarsest first.
    pub levels: Vec<EnsembleLevel>,
}

impl EnsembleConverge {
    /// Runs the levels one after the other, finest first, each ensemble
    /// on `jobs` threads; `progress` counts members over all levels.
    pub fn run(&self, progress: Progress) -> Result<EnsembleConvergeResult, StudyError> {
        if self.levels == 0 {
            return Err(StudyError::Spec("--levels must be >= 1".to_string()));
        }
        let loaded = self.base.load(&[])?;
        let own = Resolution::of(&loaded.case);
        let resolutions = (0..self.levels)
            .map(|level| self.refine.level(level, own))
            .collect::<Result<Vec<_>, _>>()?;
        let total = self.levels * self.members;
        let mut levels = Vec::with_capacity(self.levels);
        for (done, level) in (0..self.levels).rev().enumerate() {
            let resolution = resolutions[level];
            let base = self.base.with(&resolution.overrides()?);
            let offset = done * self.members;
            let inner = |d: usize, _: usize| progress(offset + d, total);
            let ensemble = Ensemble {
                base,
                members: self.members,
                jobs: self.jobs,
            }
            .run(&inner)
            .map_err(|e| {
                StudyError::Case(format!("level {level} ({}): {e}", resolution.describe()))
            })?;
            levels.push(EnsembleLevel {
                level,
                increment: resolution.increment,
                spacing: resolution.spacing(),
                ensemble,
            });
        }
        levels.reverse();
        Ok(EnsembleConvergeResult {
            title: loaded.case.title.clone(),
            refine: self.refine,
            ground: loaded.case.run.ground,
            levels,
        })
    }
}

impl EnsembleConvergeResult {
    fn finest(&self) -> &EnsembleResult {
        &self.levels.last().expect("one level at least").ensemble
    }

    /// Each level judged against the finest.
    pub fn agreements(&self) -> Vec<Agreement> {
        let finest = self.finest();
        self.levels
            .iter()
            .map(|l| l.ensemble.agreement(finest))
            .collect()
    }

    /// `converge.csv`: one row per level and window (window `all` is the
    /// whole run): the ensemble's spread, its deviation from the finest
    /// level's mean, the tolerance and whether it is within it.
    pub fn csv(&self) -> String {
        let mut out = CsvText::named(&[
            "level",
            "increment",
            "spacing",
            "window",
            "members",
            "mean",
            "std",
            "min",
            "max",
            "deviation",
            "tolerance",
            "within",
        ]);
        for (l, a) in self.levels.iter().zip(self.agreements()) {
            let e = &l.ensemble;
            let rows = e
                .windows
                .iter()
                .zip(&a.windows)
                .enumerate()
                .map(|(w, (s, v))| (format!("{w}-{}", w + 1), s, v))
                .chain([("all".to_string(), &e.whole_run, &a.whole_run)]);
            for (window, s, v) in rows {
                out.fields(&[
                    l.level.to_string(),
                    l.increment.to_string(),
                    l.spacing.to_string(),
                    window,
                    s.n.to_string(),
                    field::number(s.mean),
                    field::number(s.std),
                    field::number(s.min),
                    field::number(s.max),
                    field::number(v.deviation),
                    field::number(v.tolerance),
                    v.ok().to_string(),
                ]);
            }
        }
        out.finish()
    }

    /// `timing.csv`: every member's wall time, s, by level.
    pub fn timing_csv(&self) -> String {
        let mut out = CsvText::named(&["level", "k", "wall_time_s"]);
        for l in &self.levels {
            for m in &l.ensemble.members {
                out.fields(&[
                    l.level.to_string(),
                    m.k.to_string(),
                    m.run.wall_time_s.to_string(),
                ]);
            }
        }
        out.finish()
    }

    /// `converge.md`: per level, the ensemble mean ± sd of every window and
    /// of the whole run, its deviation from the finest level and the verdict.
    pub fn markdown(&self) -> String {
        let mut s = String::new();
        let w = &mut s;
        let members = self.finest().members.len();
        let _ = writeln!(w, "# Convergence of ensembles: {}\n", self.title);
        let _ = writeln!(
            w,
            "Level k runs at {}, each an ensemble of {members} perturbed runs ({}). Judged against the finest level by the rule: {}.\n",
            self.refine.describe(&self.ground),
            self.finest().perturbation.rule(),
            accuracy_rule()
        );
        let windows = self.finest().windows.len();
        let heads: Vec<String> = (0..windows).map(|k| format!("{k}–{}", k + 1)).collect();
        let _ = writeln!(
            w,
            "| level | increment | spacing | {} | whole run | accurate |\n|{}",
            heads.join(" | "),
            "---|".repeat(windows + 5)
        );
        for (l, a) in self.levels.iter().zip(self.agreements()) {
            let e = &l.ensemble;
            let cell = |s: &Spread, dev: f64, tol: f64| {
                format!(
                    "{:.4} ± {:.4} ({:+.2} % / {:.2} %)",
                    s.mean,
                    s.std,
                    dev * 100.0,
                    tol * 100.0
                )
            };
            let cells: Vec<String> = e
                .windows
                .iter()
                .zip(&a.windows)
                .map(|(s, v)| cell(s, v.deviation, v.tolerance))
                .collect();
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} |",
                l.level,
                l.increment,
                l.spacing,
                cells.join(" | "),
                cell(&e.whole_run, a.whole_run.deviation, a.whole_run.tolerance),
                if a.accurate() { "yes" } else { "no" }
            );
        }
        let _ = writeln!(
            w,
            "\nEach cell: ensemble mean of P/(γ0 d²) ± its standard deviation over the members (deviation from the finest level's mean / the tolerance)."
        );
        s
    }
}
