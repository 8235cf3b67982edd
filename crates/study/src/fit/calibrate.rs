//! The threshold of the intervals, calibrated by a wild bootstrap of the
//! best fit's residuals: the likelihood-ratio statistic over the
//! evaluated points and a few local refits.
//!
//! The objective is rough: a small change of a key moves a band jump by
//! an increment and the curve with it, so among the many points a search
//! evaluates, the least χ² undercuts the truth's χ² by much more than the
//! 3.84 of the χ²₁ quantile that holds for smooth models, and more so
//! where the noise is not of one level (2 % of the force is larger where
//! the force is). For replicates b = 1 … B, a synthetic measured curve is
//! the best fit plus a wild bootstrap of its residuals at the measured
//! points, y_b,i = f(θ̂, uᵢ) + vᵢ eᵢ with eᵢ = Pᵢ − f(θ̂, uᵢ) and vᵢ = ±1
//! at random (which keeps the noise's level where it is); every evaluated
//! point's residuals against it follow from its stored ones without
//! running the model (rₖ − r̂ − A(v e), with A the comparison's
//! averaging), and
//!
//!   Λ_b = χ²_b(θ̂) − minₖ χ²_b(θₖ)
//!
//! is how far the best of the evaluated points undercuts the truth of the
//! replicate. A search follows the noise it is given, which a fixed set of
//! points cannot: the first [`REFITS`] replicates are also refitted by a
//! short Nelder-Mead run from θ̂. The threshold is the largest of: the
//! 95 % quantile of Λ_b over the evaluated points, the largest Λ_b of the
//! refits, and the 95 % quantile of χ²ₚ for p free keys (the value of a
//! smooth model). The intervals ([`super::profile`]) are the projections
//! onto each key of the joint region Δχ² ≤ threshold.

use super::objective::{force_curve, interpolate, residuals, Compare, Test};
use super::problem::{Point, Problem};
use super::profile::Noise;
use super::search::polish;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

/// Replicates of the bootstrap.
pub const REPLICATES: usize = 200;
/// Replicates that are also refitted locally (each a Nelder-Mead run).
pub const REFITS: usize = 8;
/// Nelder-Mead iterations of a refit, per free key, and its steps.
const REFIT_ITERATIONS: u64 = 8;
const REFIT_STEP: f64 = 0.02;

/// The calibrated threshold of Δχ² (see the module documentation).
pub fn threshold(
    problem: &Problem,
    points: &[Point],
    best: &Point,
    noise: &Noise,
    seed: u64,
) -> f64 {
    let smooth = chi2_quantile_95(problem.params.len());
    let Some(best_r) = &best.residuals else {
        return smooth;
    };
    let raw = best_fit_residuals(problem, best);
    let replicates = sign_flipped(&raw, seed);
    let replica = Replicas {
        weights: problem.weights(),
        best: best_r,
        variance: &noise.variance,
        seen: replicates
            .iter()
            .map(|r| {
                let tests = problem.tests.iter().zip(r);
                tests
                    .map(|(t, noisy)| seen_noise(problem.compare, t, noisy))
                    .collect()
            })
            .collect(),
    };
    let feasible: Vec<&Vec<Vec<f64>>> =
        points.iter().filter_map(|p| p.residuals.as_ref()).collect();
    let undercut = |b: usize, refitted: bool| {
        let mut least = feasible
            .iter()
            .map(|r| replica.chi2(b, r))
            .fold(f64::INFINITY, f64::min);
        if refitted {
            least = least.min(refit(problem, best, &raw, &replicates[b], noise));
        }
        replica.chi2(b, best_r) - least
    };
    let mut lambda: Vec<f64> = (0..REPLICATES)
        .into_par_iter()
        .map(|b| undercut(b, false))
        .collect();
    lambda.sort_by(f64::total_cmp);
    let k = ((0.95 * REPLICATES as f64).ceil() as usize).clamp(1, REPLICATES) - 1;
    let refitted = (0..REFITS.min(REPLICATES))
        .into_par_iter()
        .map(|b| undercut(b, true))
        .reduce(|| f64::NEG_INFINITY, f64::max);
    lambda[k].max(refitted).max(smooth)
}

/// The best fit's raw residuals (uᵢ, eᵢ = Pᵢ − f(θ̂, uᵢ)) at each test's
/// measured points; 0 for a test whose run fails.
fn best_fit_residuals(problem: &Problem, best: &Point) -> Vec<Vec<(f64, f64)>> {
    let keys: Vec<String> = problem.params.iter().map(|p| p.key.clone()).collect();
    problem
        .tests
        .iter()
        .map(|t| match t.run_at(&keys, &best.x) {
            Ok(run) => t
                .measured
                .iter()
                .map(|&(u, p)| (u, p - interpolate(&force_curve(&run), u)))
                .collect(),
            Err(_) => t.measured.iter().map(|&(u, _)| (u, 0.0)).collect(),
        })
        .collect()
}

/// The raw noise (u, vᵢ eᵢ) of each replicate and test, vᵢ = ±1 drawn in
/// that order from a generator seeded by `seed`.
fn sign_flipped(raw: &[Vec<(f64, f64)>], seed: u64) -> Vec<Vec<Vec<(f64, f64)>>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed_ca1b);
    (0..REPLICATES)
        .map(|_| {
            raw.iter()
                .map(|e| {
                    e.iter()
                        .map(|&(u, e)| (u, if rng.random::<bool>() { e } else { -e }))
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// The replicates' curves as the χ² of a point sees them.
struct Replicas<'a> {
    /// The comparison's weights per test and point.
    weights: Vec<Vec<f64>>,
    /// The best fit's residuals r̂ per test and point.
    best: &'a [Vec<f64>],
    /// σ_t² per test.
    variance: &'a [f64],
    /// A(v e) per replicate, test and point.
    seen: Vec<Vec<Vec<f64>>>,
}

impl Replicas<'_> {
    /// χ²_b of a point with residuals `r` against replicate `b`:
    /// Σ_t Σ_i w (rᵢ − r̂ᵢ − A(v e)ᵢ)² / σ_t².
    fn chi2(&self, b: usize, r: &[Vec<f64>]) -> f64 {
        r.iter()
            .zip(self.best)
            .zip(&self.seen[b])
            .zip(self.weights.iter().zip(self.variance))
            .map(|(((r, r_best), e), (w, var))| {
                r.iter()
                    .zip(r_best)
                    .zip(e)
                    .zip(w)
                    .map(|(((r, rb), e), w)| w * (r - rb - e).powi(2))
                    .sum::<f64>()
                    / var
            })
            .sum()
    }
}

/// The 95 % quantile of χ² with `dof` degrees of freedom (Wilson-Hilferty
/// above the table).
pub fn chi2_quantile_95(dof: usize) -> f64 {
    const TABLE: [f64; 8] = [3.841, 5.991, 7.815, 9.488, 11.070, 12.592, 14.067, 15.507];
    match dof {
        0 => 0.0,
        1..=8 => TABLE[dof - 1],
        _ => {
            let k = dof as f64;
            let h = 2.0 / (9.0 * k);
            k * (1.0 - h + 1.644_853_6 * h.sqrt()).powi(3)
        }
    }
}

/// A(v e) of one replicate of a test: its raw noise `noisy` (u, ±e) as
/// the comparison sees it.
fn seen_noise(compare: Compare, test: &Test, noisy: &[(f64, f64)]) -> Vec<f64> {
    let (u_first, u_last) = (noisy[0].0, noisy[noisy.len() - 1].0);
    // The comparison of a zero curve with the noise gives −A(v e).
    let zero = [(u_first.min(u_last), 0.0), (u_first.max(u_last), 0.0)];
    residuals(compare, &zero, noisy, &test.weights)
        .iter()
        .map(|r| -r.1)
        .collect()
}

/// The least χ² of a local refit (Nelder-Mead from the best point) to the
/// replicate's curves f(θ̂, uᵢ) ± eᵢ: the overfit a search finds by
/// following the noise, which a fixed set of points misses.
fn refit(
    problem: &Problem,
    best: &Point,
    raw: &[Vec<(f64, f64)>],
    noisy: &[Vec<(f64, f64)>],
    noise: &Noise,
) -> f64 {
    let tests: Vec<Test> = problem
        .tests
        .iter()
        .zip(raw.iter().zip(noisy))
        .map(|(t, (e, n))| {
            let mut t = t.clone();
            for ((m, e), n) in t.measured.iter_mut().zip(e).zip(n) {
                m.1 = m.1 - e.1 + n.1;
            }
            t
        })
        .collect();
    let replica = Problem::new(&tests, problem.compare, problem.params);
    let all: Vec<usize> = (0..problem.params.len()).collect();
    let iterations = REFIT_ITERATIONS * all.len() as u64;
    polish(
        &replica,
        &problem.scaled(&best.x),
        &all,
        REFIT_STEP,
        iterations,
    )
    .iter()
    .map(|p| noise.chi2(p))
    .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chi2_quantiles_match_the_tables() {
        // Tables of the χ² distribution: 16.919 (9), 31.410 (20), 67.505 (50).
        assert_eq!(chi2_quantile_95(1), 3.841);
        for (dof, table) in [(9, 16.919), (20, 31.410), (50, 67.505)] {
            let q = chi2_quantile_95(dof);
            assert!((q - table).abs() < 0.02 * table, "{dof}: {q}");
        }
    }
}
