//! Calibration: the free case keys that best match one or more measured
//! force-displacement curves, and how far the curves determine them.
//!
//! * [`objective`]: how simulated and measured curves are compared
//!   (raw, smoothed, window means; weights; several tests);
//! * [`bounds`]: the free keys and their bounds;
//! * [`search`]: differential evolution over the bounds, in parallel and
//!   seeded, then a Nelder-Mead polish;
//! * [`cmaes`]: CMA-ES with restarts, the other global search
//!   ([`Method`]);
//! * [`profile`]: profile likelihood of each key (intervals, determined or
//!   not) and the keys' correlation near the optimum;
//! * [`calibrate`]: the intervals' threshold, calibrated for the rough
//!   objective by a wild bootstrap of the best fit's residuals;
//! * [`report`]: `fit.md`, the CSV files and the pictures.

pub mod bounds;
pub mod calibrate;
pub mod chaos;
pub mod cmaes;
pub mod objective;
pub mod problem;
pub mod profile;
pub mod report;
pub mod search;

pub use bounds::{default_bounds, free_keys, is_angle, parse_bounds, Free};
pub use objective::{interpolate, measured_width, Compare, Test};

use crate::error::StudyError;
use crate::run::RunResult;
use crate::Progress;
use chaos::Chaos;
use problem::{Point, Problem};
use profile::{Noise, Profile, Residuals};
use search::{best_of, evolve, polish, Budget, Generation, Search};
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Default runs of the global search (per test).
pub const EVALUATIONS: usize = 1200;
/// Default grid of a profile across a key's bounds.
pub const PROFILE_GRID: usize = 9;
/// Default Nelder-Mead iterations of the polish.
pub const POLISH_ITERATIONS: u64 = 60;
/// A profile that finds a point this much lower in χ² than the best is
/// computed again about it, at most [`PROFILE_ROUNDS`] times in all.
const REPROFILE_GAIN: f64 = 0.4;
const PROFILE_ROUNDS: usize = 2;
/// Simplex steps of the polish (scaled coordinates).
const POLISH_STEP: f64 = 0.02;

/// The global search of a fit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// Differential evolution ([`search::evolve`]).
    #[default]
    DifferentialEvolution,
    /// CMA-ES with restarts ([`cmaes::cma_es`]).
    CmaEs,
}

impl FromStr for Method {
    type Err = StudyError;

    /// `de` or `cmaes`.
    fn from_str(text: &str) -> Result<Self, StudyError> {
        match text {
            "de" => Ok(Method::DifferentialEvolution),
            "cmaes" => Ok(Method::CmaEs),
            _ => Err(StudyError::Spec(format!(
                "--method {text}: expected de (differential evolution) or cmaes (CMA-ES)"
            ))),
        }
    }
}

impl Method {
    /// Its name, for the picture of the search.
    pub fn name(&self) -> &'static str {
        match self {
            Method::DifferentialEvolution => "differential evolution",
            Method::CmaEs => "CMA-ES",
        }
    }

    /// In words, for the report.
    pub fn describe(&self) -> &'static str {
        match self {
            Method::DifferentialEvolution => "Differential evolution (current-to-pbest/1/bin)",
            Method::CmaEs => "CMA-ES (restarted with twice the population when converged)",
        }
    }
}

/// A calibration to run.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The measured curves, each with its case. The free keys are shared:
    /// they start at the first case's values.
    pub tests: Vec<Test>,
    /// The free keys, in order.
    pub free: Vec<String>,
    /// Bounds that replace the defaults: (key, lo, hi).
    pub bounds: Vec<(String, f64, f64)>,
    /// How the simulated and measured curves are compared (the objective).
    pub compare: Compare,
    /// The global search.
    pub method: Method,
    /// Runs of the global search (each runs every test).
    pub evaluations: usize,
    /// Population of the search; 0: the method's default, max(16, 8 p)
    /// for differential evolution and 4 + ⌊3 ln p⌋ for CMA-ES's first
    /// run, for p free keys.
    pub population: usize,
    /// Seed of the search: the same seed gives the same result.
    pub seed: u64,
    /// Nelder-Mead iterations of the polish.
    pub polish_iterations: u64,
    /// Grid of each profile across the bounds; 0: no profiles (and no
    /// intervals).
    pub profile_grid: usize,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
}

/// A finished calibration.
#[derive(Clone, Debug)]
pub struct FitResult {
    /// The free keys with their starts and bounds.
    pub params: Vec<Free>,
    /// The measured curves and their cases.
    pub tests: Vec<Test>,
    /// The objective used.
    pub compare: Compare,
    /// The global search used.
    pub method: Method,
    /// At the first case's own values.
    pub start: Point,
    /// The best point found (after the polish).
    pub best: Point,
    /// RMS at the end of the global search (before the polish).
    pub search_rms: f64,
    /// The search's progress, generation by generation.
    pub generations: Vec<Generation>,
    /// Runs of the search, the polish and the profiles (each runs every test).
    pub evaluations: usize,
    /// The noise level of each test estimated from the residuals.
    pub noise: Option<Noise>,
    /// One per free key (empty without profiles).
    pub profiles: Vec<Profile>,
    /// The calibrated Δχ² of the intervals ([`calibrate`]), at least the
    /// chaos's ([`chaos`]).
    pub threshold: Option<f64>,
    /// The best values' ensemble members and the Δχ² they span (None
    /// without profiles, or where a member cannot run).
    pub chaos: Option<Chaos>,
    /// Correlation of the keys near the optimum.
    pub correlation: Option<Vec<Vec<f64>>>,
    /// Each test's run at the start (None if it fails) and at the best values.
    pub start_runs: Vec<Option<RunResult>>,
    /// Each test's run at the best values.
    pub best_runs: Vec<RunResult>,
}

impl Fit {
    /// The free parameters with their starts and bounds.
    pub fn params(&self) -> Result<Vec<Free>, StudyError> {
        let first = self
            .tests
            .first()
            .ok_or_else(|| StudyError::Spec("give at least one measured curve".to_string()))?;
        let params = free_keys(&first.base, &self.free, &self.bounds)?;
        for t in &self.tests[1..] {
            for key in &self.free {
                t.base
                    .number(key)
                    .map_err(|e| StudyError::Spec(format!("{}: {e}", t.name)))?;
            }
        }
        Ok(params)
    }

    /// The population of the search for `keys` free keys (its first
    /// run's for CMA-ES).
    pub fn population(&self, keys: usize) -> usize {
        match (self.population, self.method) {
            (0, Method::DifferentialEvolution) => (8 * keys).max(16),
            (0, Method::CmaEs) => cmaes::default_lambda(keys),
            (n, _) => n,
        }
    }

    /// The global search of [`Fit::method`] over `problem` from the free
    /// keys' starts (the first point run), on the current rayon pool.
    /// `progress` is called with the number of runs made.
    pub fn search(&self, problem: &Problem, progress: &(dyn Fn(usize) + Sync)) -> Search {
        let start: Vec<f64> = problem.params.iter().map(|p| p.start).collect();
        let first = problem.scaled(&start);
        let budget = Budget {
            population: self.population(problem.params.len()),
            evaluations: self.evaluations,
            seed: self.seed,
        };
        match self.method {
            Method::DifferentialEvolution => evolve(problem, budget, &first, progress),
            Method::CmaEs => cmaes::cma_es(problem, budget, &first, progress),
        }
    }

    /// Runs the calibration. `progress` counts runs of the search and
    /// the polish, then profile chains.
    pub fn run(&self, progress: Progress) -> Result<FitResult, StudyError> {
        let params = self.params()?;
        for t in &self.tests {
            t.check()?;
        }
        let problem = Problem::new(&self.tests, self.compare, &params);
        let chains = if self.profile_grid > 0 {
            2 * params.len()
        } else {
            0
        };
        let total = self.evaluations + self.polish_iterations as usize + chains;
        progress(0, total);
        let pool = crate::pool(self.jobs)?;
        pool.install(|| {
            let search = self.search(&problem, &|n| progress(n.min(self.evaluations), total));
            let start = search.points[0].clone();
            let mut points = search.points;
            let mut best = self.polished_best(&problem, &search.best, &mut points)?;
            let done = self.evaluations + self.polish_iterations as usize;
            progress(done, total);
            let noise = Noise::estimate(&best, &self.residuals(), params.len());
            let profiled = match &noise {
                Some(noise) if self.profile_grid > 0 => {
                    let finished = AtomicUsize::new(done);
                    let tick = || {
                        let n = finished.fetch_add(1, Ordering::Relaxed) + 1;
                        progress(n.min(total - 1), total)
                    };
                    self.profile(&problem, &params, noise, (&mut points, &mut best), &tick)
                }
                _ => Profiled::default(),
            };
            progress(total, total);
            self.finish(
                params.clone(),
                start,
                best,
                search.best.rms,
                search.generations,
                problem.evaluations(),
                noise,
                profiled,
            )
        })
    }

    /// Polishes the search's best point by Nelder-Mead over every key
    /// (the points it evaluates join `points`): the best point of all,
    /// which must run every test.
    fn polished_best(
        &self,
        problem: &Problem,
        searched: &Point,
        points: &mut Vec<Point>,
    ) -> Result<Point, StudyError> {
        let all_keys: Vec<usize> = (0..problem.params.len()).collect();
        let polished = polish(
            problem,
            &problem.scaled(&searched.x),
            &all_keys,
            POLISH_STEP,
            self.polish_iterations,
        );
        points.extend(polished);
        let best = best_of(points).clone();
        if !best.rms.is_finite() {
            return Err(StudyError::Case(
                "no set of values within the bounds runs every test".to_string(),
            ));
        }
        Ok(best)
    }

    /// The profile of each parameter about the best point, with the
    /// threshold of its confidence interval; profiled again about a clearly
    /// better point one finds (`REPROFILE_GAIN`, at most `PROFILE_ROUNDS`
    /// times). Every point it evaluates joins `points`; `best` follows.
    fn profile(
        &self,
        problem: &Problem,
        params: &[Free],
        noise: &Noise,
        (points, best): (&mut Vec<Point>, &mut Point),
        tick: &(dyn Fn() + Sync),
    ) -> Profiled {
        let chaos = Chaos::of(problem, best, noise);
        let floor = chaos.as_ref().map_or(0.0, |c| c.threshold);
        let threshold_at = |points: &[Point], best: &Point| {
            calibrate::threshold(problem, points, best, noise, self.seed).max(floor)
        };
        let mut threshold = threshold_at(points, best);
        let mut rounds = 0;
        let mut profiles = loop {
            let profiles =
                profile::profiles(problem, best, noise, self.profile_grid, threshold, tick);
            for pr in &profiles {
                points.extend(pr.points.iter().map(|(_, pt)| pt.clone()));
            }
            let better = best_of(points).clone();
            let gain = noise.chi2(best) - noise.chi2(&better);
            *best = better;
            rounds += 1;
            threshold = threshold_at(points, best);
            if gain <= REPROFILE_GAIN || rounds == PROFILE_ROUNDS {
                break profiles;
            }
        };
        for (j, (pr, p)) in profiles.iter_mut().zip(params).enumerate() {
            pr.bound(j, p, points, noise, threshold);
        }
        Profiled {
            correlation: profile::correlation(points, noise, threshold, params.len()),
            profiles,
            threshold: Some(threshold),
            chaos,
        }
    }

    /// Each test's residuals, their weight and overlap (none depends on
    /// the values).
    fn residuals(&self) -> Vec<Residuals> {
        self.tests
            .iter()
            .zip(self.overlaps())
            .map(|(t, overlap)| Residuals {
                count: objective::residuals(self.compare, &t.measured, &t.measured, &t.weights)
                    .len(),
                weight: t.weight(self.compare),
                overlap,
            })
            .collect()
    }

    /// The mean number of measured points a residual of each test averages
    /// over (1 unless smoothed).
    fn overlaps(&self) -> Vec<f64> {
        self.tests
            .iter()
            .map(|t| match self.compare {
                Compare::Smoothed(w) => {
                    let u: Vec<f64> = t.measured.iter().map(|p| p.0).collect();
                    let inside: usize = u
                        .iter()
                        .map(|&c| u.iter().filter(|&&x| (x - c).abs() <= 0.5 * w).count())
                        .sum();
                    inside as f64 / u.len() as f64
                }
                _ => 1.0,
            })
            .collect()
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        params: Vec<Free>,
        start: Point,
        best: Point,
        search_rms: f64,
        generations: Vec<Generation>,
        evaluations: usize,
        noise: Option<Noise>,
        profiled: Profiled,
    ) -> Result<FitResult, StudyError> {
        let keys: Vec<String> = params.iter().map(|p| p.key.clone()).collect();
        let best_runs = self
            .tests
            .iter()
            .map(|t| t.run_at(&keys, &best.x))
            .collect::<Result<Vec<_>, _>>()
            .map_err(StudyError::Case)?;
        let start_runs = self
            .tests
            .iter()
            .map(|t| t.run_at(&keys, &start.x).ok())
            .collect();
        Ok(FitResult {
            params,
            tests: self.tests.clone(),
            compare: self.compare,
            method: self.method,
            start,
            best,
            search_rms,
            generations,
            evaluations,
            noise,
            profiles: profiled.profiles,
            threshold: profiled.threshold,
            chaos: profiled.chaos,
            correlation: profiled.correlation,
            start_runs,
            best_runs,
        })
    }
}

/// What `Fit::profile` found (nothing when the fit is not profiled).
#[derive(Default)]
struct Profiled {
    profiles: Vec<Profile>,
    threshold: Option<f64>,
    chaos: Option<Chaos>,
    correlation: Option<Vec<Vec<f64>>>,
}
