//! The chaos's share of the intervals. The model is chaotic (the
//! ensembles, docs/guide/ensembles.md): perturbing a key far below any
//! measurement's resolution moves its band jumps, and with them the force
//! curve, so the best values' own ensemble members (the ensembles' rule,
//! (M39), k = ±1, ±2) fit the measured curve differently by chance alone.
//! How far apart their χ² and the best point's lie,
//!
//!   Λ_chaos = max χ² − min χ² over θ̂ and its members,
//!
//! is a Δχ² the curves cannot tell from no change of the keys at all: the
//! intervals' threshold is at least that ([`super::Fit`]). The spread, not
//! a typical member's distance: the residuals of a chaotic curve are
//! correlated over a band's spacing, so χ² (which counts them as
//! independent) overstates every difference, and the guide's one-key fit
//! (φp = 39.84 where the truth is 38) still reports [39.7596, 39.9000]
//! with the members' median distance from the best (703.8) as the floor,
//! and φp ≤ 42.56, undetermined, with their spread (8 990.65). Without it, a
//! search that lands in a valley of the chaotic objective away from the
//! truth reports a narrow interval about the valley (issue 50: a one-key fit
//! at 80 runs, φp = 39.84 in [39.8346, 39.8449] where the truth was 38).

use super::objective::{overrides_of, Test};
use super::problem::{Point, Problem};
use super::profile::Noise;
use crate::ensemble::Perturbation;
use crate::run::override_of;
use rayon::prelude::*;

/// The members run at the best values (k of the ensembles' rule).
pub const MEMBERS: [i32; 4] = [-2, -1, 1, 2];

/// The best values' members and the Δχ² they span.
#[derive(Clone, Debug)]
pub struct Chaos {
    /// χ² of each member at the best values (∞ where one fails).
    pub chi2: Vec<f64>,
    /// Λ_chaos: the spread of χ² over the best point and its members.
    pub threshold: f64,
}

impl Chaos {
    /// The members of `best` under `noise`'s χ²; None if a member cannot
    /// be made (a test's case has no key to perturb) or fails to run.
    pub fn of(problem: &Problem, best: &Point, noise: &Noise) -> Option<Chaos> {
        let points: Vec<Option<Point>> = MEMBERS
            .par_iter()
            .map(|&k| member(problem, &best.x, k))
            .collect();
        let chi2: Vec<f64> = points
            .iter()
            .map(|p| p.as_ref().map_or(f64::INFINITY, |p| noise.chi2(p)))
            .collect();
        let at_best = noise.chi2(best);
        let worst = chi2.iter().copied().fold(at_best, f64::max);
        let least = chi2.iter().copied().fold(at_best, f64::min);
        worst.is_finite().then_some(Chaos {
            threshold: worst - least,
            chi2,
        })
    }
}

/// The point `x` with every test's case perturbed as member `k`.
fn member(problem: &Problem, x: &[f64], k: i32) -> Option<Point> {
    let runs: Option<Vec<Vec<(f64, f64)>>> = problem
        .tests
        .iter()
        .map(|t| {
            let run = member_run(t, problem, x, k)?;
            Some(t.residuals(problem.compare, &run))
        })
        .collect();
    Some(problem.point_of(x, runs?))
}

fn member_run(test: &Test, problem: &Problem, x: &[f64], k: i32) -> Option<crate::run::RunResult> {
    let mut overrides = overrides_of(problem.keys(), x).ok()?;
    let loaded = test.base.load(&overrides).ok()?;
    let rule = Perturbation::of(&loaded).ok()?;
    overrides.push(override_of(&rule.key, &toml::Value::Float(rule.value(k))).ok()?);
    test.base.run(&overrides).ok()
}
