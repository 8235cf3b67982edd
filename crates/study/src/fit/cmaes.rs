//! The global search by CMA-ES: the (μ/μ_w, λ) evolution strategy with
//! covariance matrix adaptation, in the default settings of Hansen's
//! tutorial (N. Hansen, "The CMA Evolution Strategy: A Tutorial", 2016,
//! Table 1 and Fig. 7), on the unit box, restarted with twice the
//! population when it has converged (IPOP: Auger & Hansen 2005).
//!
//! Each generation draws λ points xₖ = m + σ yₖ, yₖ = B D zₖ with
//! zₖ ~ N(0, I) and C = B D² Bᵀ, ranks them, and with the weights
//! wᵢ ∝ ln((λ + 1)/2) − ln i of the best μ = ⌊λ/2⌋ (y_w = Σ wᵢ y_i:λ):
//!
//!   m ← m + σ y_w,
//!   p_σ ← (1 − c_σ) p_σ + √(c_σ (2 − c_σ) μ_eff) C^−½ y_w,
//!   σ ← σ exp(c_σ/d_σ (‖p_σ‖ / E‖N(0, I)‖ − 1)),
//!   p_c ← (1 − c_c) p_c + h_σ √(c_c (2 − c_c) μ_eff) y_w,
//!   C ← (1 − c₁ − c_μ) C + c₁ (p_c p_cᵀ + δ(h_σ) C) + c_μ Σ wᵢ y_i:λ y_i:λᵀ.
//!
//! The first run starts at the case's values with σ = 0.3 (a third of the
//! box) and λ = 4 + ⌊3 ln n⌋ for n free keys (or the population asked
//! for); when every coordinate's standard deviation σ √Cᵢᵢ is below the
//! stop width of differential evolution, or C is ill-conditioned, it
//! restarts from a random point of the box with twice the population,
//! while the budget allows a whole generation.
//!
//! Bounds: a point drawn outside the box is drawn again (up to
//! `RESAMPLES` times, then projected onto the box), so that no run is
//! spent outside the bounds and the mean, a weighted mean of points in the
//! box, stays in it. (Running the projection of an outside point instead
//! makes the objective flat outside the box, and the mean drifts out and
//! stalls at a corner.) Infeasible points (a run fails) have RMS +∞ and
//! rank last, as in differential evolution.
//!
//! Determinism: every random number is drawn from one seeded generator on
//! the calling thread, in a fixed order; only a generation's runs are
//! spread over the threads (rayon keeps their order). The same seed gives
//! the same search, bit for bit, on any number of threads.

use super::problem::{Point, Problem};
use super::search::{best_of, generation, Budget, Search, SPREAD_STOP};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

/// Draws of a point before it is projected onto the box.
const RESAMPLES: usize = 100;
/// Initial step size (scaled coordinates).
const SIGMA0: f64 = 0.3;
/// A run whose covariance has a larger condition number restarts.
const CONDITION_STOP: f64 = 1e14;
/// Cyclic Jacobi sweeps of the eigendecomposition (converges long before
/// for the few keys of a fit).
const JACOBI_SWEEPS: usize = 50;

/// Runs `first` (scaled coordinates), then CMA-ES with restarts from it
/// while `budget.evaluations` runs allow a whole generation; `budget.population` is the first
/// run's λ (0 or less than 4: the default). `progress` is called with the
/// number of evaluations made.
pub fn cma_es(
    problem: &Problem,
    budget: Budget,
    first: &[f64],
    progress: &(dyn Fn(usize) + Sync),
) -> Search {
    minimise(&|z| problem.evaluate_scaled(z), budget, first, progress)
}

/// [`cma_es`] of any objective on the unit box.
fn minimise(
    evaluate: &(dyn Fn(&[f64]) -> Point + Sync),
    budget: Budget,
    first: &[f64],
    progress: &(dyn Fn(usize) + Sync),
) -> Search {
    let n = first.len();
    let mut rng = ChaCha8Rng::seed_from_u64(budget.seed);
    let mut lambda = if budget.population >= 4 {
        budget.population
    } else {
        default_lambda(n)
    };
    let mut mean = first.to_vec();
    // The start is the first point run, as in differential evolution.
    let mut all: Vec<Point> = vec![evaluate(first)];
    let mut generations = Vec::new();
    loop {
        let mut es = Strategy::new(mean, lambda);
        loop {
            let samples: Vec<Vec<f64>> = (0..lambda).map(|_| es.sample(&mut rng)).collect();
            let points: Vec<Point> = samples.par_iter().map(|x| evaluate(x)).collect();
            es.update(&samples, &points);
            all.extend(points.iter().cloned());
            let mut g = generation(&points, all.len());
            g.best_rms = best_of(&all).rms;
            generations.push(g);
            progress(all.len());
            if all.len() + lambda > budget.evaluations || es.converged() {
                break;
            }
        }
        lambda *= 2;
        if all.len() + lambda > budget.evaluations {
            break;
        }
        mean = (0..n).map(|_| rng.random::<f64>()).collect();
    }
    Search {
        best: best_of(&all).clone(),
        generations,
        points: all,
    }
}

/// λ = 4 + ⌊3 ln n⌋ (Hansen's default).
pub fn default_lambda(n: usize) -> usize {
    4 + (3.0 * (n.max(1) as f64).ln()).floor() as usize
}

/// The state of one run and its constants (Hansen's Table 1).
struct Strategy {
    mean: Vec<f64>,
    sigma: f64,
    c: Vec<Vec<f64>>,
    /// Eigenvectors of C (columns) and the square roots of its eigenvalues.
    b: Vec<Vec<f64>>,
    d: Vec<f64>,
    p_sigma: Vec<f64>,
    p_c: Vec<f64>,
    generation: i32,
    weights: Vec<f64>,
    mu_eff: f64,
    c_sigma: f64,
    d_sigma: f64,
    c_c: f64,
    c_1: f64,
    c_mu: f64,
    chi_n: f64,
}

impl Strategy {
    fn new(mean: Vec<f64>, lambda: usize) -> Self {
        let n = mean.len();
        let nf = n as f64;
        let mu = lambda / 2;
        let raw: Vec<f64> = (1..=mu)
            .map(|i| ((lambda as f64 + 1.0) / 2.0).ln() - (i as f64).ln())
            .collect();
        let total: f64 = raw.iter().sum();
        let weights: Vec<f64> = raw.iter().map(|w| w / total).collect();
        let mu_eff = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
        let c_sigma = (mu_eff + 2.0) / (nf + mu_eff + 5.0);
        let c_1 = 2.0 / ((nf + 1.3).powi(2) + mu_eff);
        let identity: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| f64::from(i == j)).collect())
            .collect();
        Strategy {
            mean,
            sigma: SIGMA0,
            c: identity.clone(),
            b: identity,
            d: vec![1.0; n],
            p_sigma: vec![0.0; n],
            p_c: vec![0.0; n],
            generation: 0,
            weights,
            mu_eff,
            c_sigma,
            d_sigma: 1.0 + 2.0 * (((mu_eff - 1.0) / (nf + 1.0)).sqrt() - 1.0).max(0.0) + c_sigma,
            c_c: (4.0 + mu_eff / nf) / (nf + 4.0 + 2.0 * mu_eff / nf),
            c_1,
            c_mu: (1.0 - c_1)
                .min(2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((nf + 2.0).powi(2) + mu_eff)),
            chi_n: nf.sqrt() * (1.0 - 1.0 / (4.0 * nf) + 1.0 / (21.0 * nf * nf)),
        }
    }

    /// x = m + σ B D z, z standard normal, drawn until x is in the box
    /// (projected onto it after [`RESAMPLES`] draws).
    fn sample(&self, rng: &mut ChaCha8Rng) -> Vec<f64> {
        let mut x = Vec::new();
        for _ in 0..RESAMPLES {
            let dz: Vec<f64> = self.d.iter().map(|d| d * normal(rng)).collect();
            let y = mat_vec(&self.b, &dz);
            x = self
                .mean
                .iter()
                .zip(y)
                .map(|(m, y)| m + self.sigma * y)
                .collect();
            if x.iter().all(|v| (0.0..=1.0).contains(v)) {
                return x;
            }
        }
        x.iter().map(|v| v.clamp(0.0, 1.0)).collect()
    }

    /// One generation's update from the points drawn and their runs.
    fn update(&mut self, samples: &[Vec<f64>], points: &[Point]) {
        let steps = self.selected_steps(samples, points);
        let n = self.mean.len();
        let y_w: Vec<f64> = (0..n)
            .map(|i| self.weights.iter().zip(&steps).map(|(w, y)| w * y[i]).sum())
            .collect();
        for (m, y) in self.mean.iter_mut().zip(&y_w) {
            *m += self.sigma * y;
        }
        let (norm, h_sigma) = self.adapt_paths(&y_w);
        self.adapt_covariance(&steps, h_sigma);
        self.sigma *= ((self.c_sigma / self.d_sigma) * (norm / self.chi_n - 1.0)).exp();
        let (values, vectors) = eigen(&self.c);
        self.d = values
            .iter()
            .map(|v| v.max(f64::MIN_POSITIVE).sqrt())
            .collect();
        self.b = vectors;
    }

    /// The steps yₖ = (xₖ − m)/σ of the μ best samples, best first (ties
    /// by the order drawn).
    fn selected_steps(&self, samples: &[Vec<f64>], points: &[Point]) -> Vec<Vec<f64>> {
        let mut order: Vec<usize> = (0..samples.len()).collect();
        order.sort_by(|&a, &b| points[a].rms.total_cmp(&points[b].rms).then(a.cmp(&b)));
        order[..self.weights.len()]
            .iter()
            .map(|&k| {
                samples[k]
                    .iter()
                    .zip(&self.mean)
                    .map(|(x, m)| (x - m) / self.sigma)
                    .collect()
            })
            .collect()
    }

    /// Updates the evolution paths p_σ and p_c by the weighted step y_w
    /// and counts the generation; returns ‖p_σ‖ and h_σ (whether p_σ is
    /// short enough for p_c to take the step).
    fn adapt_paths(&mut self, y_w: &[f64]) -> (f64, bool) {
        let n = self.mean.len();
        // C^−½ y_w = B D⁻¹ Bᵀ y_w.
        let bt_y: Vec<f64> = (0..n)
            .map(|j| (0..n).map(|i| self.b[i][j] * y_w[i]).sum::<f64>() / self.d[j])
            .collect();
        let whitened = mat_vec(&self.b, &bt_y);
        let cs = self.c_sigma;
        let ks = (cs * (2.0 - cs) * self.mu_eff).sqrt();
        for (p, w) in self.p_sigma.iter_mut().zip(&whitened) {
            *p = (1.0 - cs) * *p + ks * w;
        }
        self.generation += 1;
        let norm = self.p_sigma.iter().map(|p| p * p).sum::<f64>().sqrt();
        let h_sigma = norm / (1.0 - (1.0 - cs).powi(2 * self.generation)).sqrt()
            < (1.4 + 2.0 / (n as f64 + 1.0)) * self.chi_n;
        let cc = self.c_c;
        let kc = f64::from(u8::from(h_sigma)) * (cc * (2.0 - cc) * self.mu_eff).sqrt();
        for (p, y) in self.p_c.iter_mut().zip(y_w) {
            *p = (1.0 - cc) * *p + kc * y;
        }
        (norm, h_sigma)
    }

    /// C ← (1 − c₁ − c_μ + c₁ δ) C + c₁ p_c p_cᵀ + c_μ Σ wₖ yₖ yₖᵀ, with
    /// δ = c_c (2 − c_c) when h_σ is false.
    fn adapt_covariance(&mut self, steps: &[Vec<f64>], h_sigma: bool) {
        let n = self.mean.len();
        let cc = self.c_c;
        let delta = if h_sigma { 0.0 } else { cc * (2.0 - cc) };
        let keep = 1.0 - self.c_1 - self.c_mu + self.c_1 * delta;
        for i in 0..n {
            for j in 0..n {
                let rank_mu: f64 = self
                    .weights
                    .iter()
                    .zip(steps)
                    .map(|(w, y)| w * y[i] * y[j])
                    .sum();
                self.c[i][j] = keep * self.c[i][j]
                    + self.c_1 * self.p_c[i] * self.p_c[j]
                    + self.c_mu * rank_mu;
            }
        }
    }

    /// Every coordinate's deviation below the stop width, or C
    /// ill-conditioned.
    fn converged(&self) -> bool {
        let widest = (0..self.c.len())
            .map(|i| self.sigma * self.c[i][i].sqrt())
            .fold(0.0, f64::max);
        let (lo, hi) = self.d.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), d| {
            (lo.min(*d), hi.max(*d))
        });
        widest < SPREAD_STOP || (hi / lo).powi(2) > CONDITION_STOP
    }
}

/// A standard normal number (Box-Muller; one of the pair).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let (a, b): (f64, f64) = (rng.random(), rng.random());
    (-2.0 * (1.0 - a).ln()).sqrt() * (std::f64::consts::TAU * b).cos()
}

fn mat_vec(m: &[Vec<f64>], v: &[f64]) -> Vec<f64> {
    m.iter()
        .map(|row| row.iter().zip(v).map(|(a, b)| a * b).sum())
        .collect()
}

/// Eigenvalues and eigenvectors (the columns of the second) of the
/// symmetric matrix `c`, by cyclic Jacobi rotations.
fn eigen(c: &[Vec<f64>]) -> (Vec<f64>, Vec<Vec<f64>>) {
    let n = c.len();
    // Symmetrised: the update's rounding may leave it slightly off.
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| 0.5 * (c[i][j] + c[j][i])).collect())
        .collect();
    let mut v: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| f64::from(i == j)).collect())
        .collect();
    for _ in 0..JACOBI_SWEEPS {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        let diagonal: f64 = (0..n).map(|i| a[i][i] * a[i][i]).sum();
        if off <= 1e-30 * diagonal {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                // The rotation that zeroes a[p][q] (Numerical Recipes §11.1).
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let cos = 1.0 / (t * t + 1.0).sqrt();
                let sin = t * cos;
                for row in a.iter_mut().chain(v.iter_mut()) {
                    let (kp, kq) = (row[p], row[q]);
                    row[p] = cos * kp - sin * kq;
                    row[q] = sin * kp + cos * kq;
                }
                let (upper, lower) = a.split_at_mut(q);
                for (pk, qk) in upper[p].iter_mut().zip(lower[0].iter_mut()) {
                    let (x, y) = (*pk, *qk);
                    *pk = cos * x - sin * y;
                    *qk = sin * x + cos * y;
                }
            }
        }
    }
    ((0..n).map(|i| a[i][i]).collect(), v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_reconstructs_a_symmetric_matrix() {
        let c = vec![
            vec![4.0, 1.0, -2.0],
            vec![1.0, 3.0, 0.5],
            vec![-2.0, 0.5, 5.0],
        ];
        let (values, b) = eigen(&c);
        for i in 0..3 {
            for j in 0..3 {
                let back: f64 = (0..3).map(|k| b[i][k] * values[k] * b[j][k]).sum();
                let unit: f64 = (0..3).map(|k| b[k][i] * b[k][j]).sum();
                assert!((back - c[i][j]).abs() < 1e-12, "{i},{j}: {back}");
                assert!((unit - f64::from(i == j)).abs() < 1e-12, "{i},{j}: {unit}");
            }
        }
        // The trace is the sum of the eigenvalues.
        assert!((values.iter().sum::<f64>() - 12.0).abs() < 1e-12);
    }

    /// A rotated, ill-scaled ellipsoid with its minimum at `at`.
    fn ellipsoid(at: [f64; 3]) -> impl Fn(&[f64]) -> Point + Sync {
        move |z: &[f64]| {
            let d: Vec<f64> = z.iter().zip(at).map(|(z, a)| z - a).collect();
            let (u, v, w) = (d[0] + d[1], d[1] - d[0], d[2] + 0.5 * d[0]);
            let f = u * u + 100.0 * v * v + 1e4 * w * w;
            Point {
                x: z.to_vec(),
                sums: Some(vec![f]),
                residuals: None,
                rms: f.sqrt(),
            }
        }
    }

    fn budget(evaluations: usize, seed: u64) -> Budget {
        Budget {
            population: 0,
            evaluations,
            seed,
        }
    }

    #[test]
    fn finds_the_minimum_of_an_ill_scaled_ellipsoid() {
        let at = [0.3, 0.6, 0.45];
        let s = minimise(&ellipsoid(at), budget(3000, 1), &[0.9, 0.1, 0.9], &|_| {});
        for (x, a) in s.best.x.iter().zip(at) {
            assert!((x - a).abs() < 1e-4, "{:?}", s.best.x);
        }
        assert!(s.points.len() <= 3000);
        // The best RMS of the generations never rises.
        assert!(s
            .generations
            .windows(2)
            .all(|g| g[1].best_rms <= g[0].best_rms));
    }

    #[test]
    fn a_minimum_outside_the_box_is_found_on_its_bound() {
        // The minimum at z₀ = 1.2 lies outside: the best point is on z₀ = 1,
        // and every run is inside the box.
        let s = minimise(
            &ellipsoid([1.2, 0.5, 0.5]),
            budget(2000, 2),
            &[0.5; 3],
            &|_| {},
        );
        assert!(s
            .points
            .iter()
            .flat_map(|p| &p.x)
            .all(|z| (0.0..=1.0).contains(z)));
        assert!((s.best.x[0] - 1.0).abs() < 1e-5, "{:?}", s.best.x);
    }

    #[test]
    fn infeasible_points_rank_last() {
        // Half the box fails to run: the search stays in the other half.
        let f = ellipsoid([0.7, 0.7, 0.7]);
        let feasible_half = |z: &[f64]| {
            let mut p = f(z);
            if z[0] < 0.5 {
                p.sums = None;
                p.rms = f64::INFINITY;
            }
            p
        };
        let s = minimise(&feasible_half, budget(1500, 3), &[0.6; 3], &|_| {});
        assert!(
            s.best.x.iter().all(|x| (x - 0.7).abs() < 1e-3),
            "{:?}",
            s.best
        );
    }
}
