//! Identifiability and uncertainty: profile likelihood of each free key.
//!
//! The noise of test t is estimated from the residuals at the best point,
//!
//!   σ_t² = S_t / W_t · N / (N − p),
//!
//! the noise of a residual of the test's mean weight w̄_t = W_t / n_t (a
//! residual of weight w has σ_t² w̄_t / w), with S_t = Σ wᵢ rᵢ² its
//! weighted sum of squares, W_t = Σ wᵢ, n_t its residuals, N = Σ n_t and
//! p the free keys; with k_t the mean number of measured points a
//! residual averages over (1 for raw residuals and window means, whose
//! weights already count their points; the window's points for a
//! smoothed curve, whose residuals overlap),
//!
//!   χ²(θ) = Σ_t S_t(θ) / (k_t w̄_t σ_t²),
//!
//! N − p at the best point when k_t = 1. For key j, the profile
//!
//!   χ²_j(v) = min over the other keys of χ²(θ with θ_j = v)
//!
//! on a grid across its bounds, each minimum a Nelder-Mead run of the
//! other keys continued from the neighbouring grid value towards the best
//! point, the first crossing of the threshold refined by bisection.
//!
//! The 95 % interval of key j spans its values over every evaluated point
//! (search, polish, profiles) with χ² − χ²_min within the threshold, and
//! the profile's crossings of the threshold (linear in √Δχ² between its
//! points):
//! the projection of the joint region onto the key. The threshold is
//! calibrated for the roughness of the objective by [`super::calibrate`].
//! The profiles put points at the interval's ends and at the bounds.
//!
//! A key is **determined** when its interval ends inside its bounds and
//! lies within ± 1° (angles) or ± 10 % of the best value; **weakly
//! determined** when it ends inside its bounds but is wider;
//! **undetermined** when it reaches a bound: the curves do not fix it.

use super::bounds::Free;
use super::problem::{Point, Problem};
use super::search::{best_of, polish};
use rayon::prelude::*;

/// Nelder-Mead iterations per profile value, per other free key.
const ITERATIONS_PER_KEY: u64 = 6;
/// Simplex steps of the re-optimisation (scaled coordinates).
const STEP: f64 = 0.05;
/// Bisections of an interval's end: at most this many, until the bracket
/// is narrower than a quarter of the key's accuracy.
const BISECTIONS: usize = 6;

/// χ² at a point from the noise of each test.
#[derive(Clone, Debug, PartialEq)]
pub struct Noise {
    /// k_t w̄_t σ_t² of each test: what its sum of squares is divided by.
    pub variance: Vec<f64>,
    /// σ_t: the noise level of the measured force at the test's mean
    /// weight (force per unit width), the σ of `variance`.
    pub sigma: Vec<f64>,
}

/// What [`Noise::estimate`] reads of each test: its residuals n_t, the sum
/// of their weights W_t and the overlap factor k_t.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Residuals {
    /// n_t.
    pub count: usize,
    /// W_t.
    pub weight: f64,
    /// k_t.
    pub overlap: f64,
}

impl Noise {
    /// From the sums of squares at the best point (see the module
    /// documentation); None if there are no more residuals than keys or
    /// the fit is exact.
    pub fn estimate(best: &Point, tests: &[Residuals], keys: usize) -> Option<Noise> {
        let sums = best.sums.as_ref()?;
        let n: usize = tests.iter().map(|t| t.count).sum();
        if n <= keys {
            return None;
        }
        let dof = n as f64 / (n - keys) as f64;
        // w̄_t σ_t² = S_t / n_t · N / (N − p).
        let per_mean_weight: Vec<f64> = sums
            .iter()
            .zip(tests)
            .map(|(s, t)| s / t.count as f64 * dof)
            .collect();
        if per_mean_weight.iter().any(|s| !s.is_finite() || *s <= 0.0) {
            return None;
        }
        let each = per_mean_weight.iter().zip(tests);
        Some(Noise {
            variance: each.clone().map(|(s, t)| s * t.overlap).collect(),
            sigma: each
                .map(|(s, t)| (s * t.count as f64 / t.weight).sqrt())
                .collect(),
        })
    }

    /// χ² of a point; +∞ if infeasible.
    pub fn chi2(&self, point: &Point) -> f64 {
        match &point.sums {
            Some(sums) => sums.iter().zip(&self.variance).map(|(s, v)| s / v).sum(),
            None => f64::INFINITY,
        }
    }
}

/// The profile of one key.
#[derive(Clone, Debug)]
pub struct Profile {
    /// (value of the key, the re-optimised point), by increasing value.
    pub points: Vec<(f64, Point)>,
    /// The 95 % interval; an end at None reached the bound.
    pub lower: Option<f64>,
    /// The interval's upper end (None: it reached the bound).
    pub upper: Option<f64>,
    /// Both ends inside the bounds.
    pub bounded: bool,
    /// Bounded, and the interval within the accuracy of the key about
    /// the best value ([`ACCURACY_DEG`], [`ACCURACY_REL`]).
    pub determined: bool,
}

/// Accuracy of an angle that counts as determined: ± 1°.
pub const ACCURACY_DEG: f64 = 1.0;
/// Accuracy of another key that counts as determined: ± 10 %.
pub const ACCURACY_REL: f64 = 0.1;

/// The profiles of every key about `best`, computed in parallel (one
/// chain per key and direction), bisecting where Δχ² first exceeds
/// `threshold`. `progress` is called as chains finish. Their intervals
/// are left open; [`Profile::bound`] sets them.
pub fn profiles(
    problem: &Problem,
    best: &Point,
    noise: &Noise,
    grid: usize,
    threshold: f64,
    progress: &(dyn Fn() + Sync),
) -> Vec<Profile> {
    let p = problem.params.len();
    let chains: Vec<Vec<(f64, Point)>> = (0..2 * p)
        .into_par_iter()
        .map(|c| {
            let chain = walk(problem, best, noise, (c / 2, c % 2 == 1), grid, threshold);
            progress();
            chain
        })
        .collect();
    (0..p)
        .map(|j| {
            let mut points: Vec<(f64, Point)> = chains[2 * j].iter().rev().cloned().collect();
            points.push((best.x[j], best.clone()));
            points.extend(chains[2 * j + 1].iter().cloned());
            Profile {
                points,
                lower: None,
                upper: None,
                bounded: false,
                determined: false,
            }
        })
        .collect()
}

impl Profile {
    /// Sets the interval of key `j` (bounds `lo`, `hi`) from every
    /// evaluated point: the range of its values over the points with
    /// Δχ² ≤ `threshold`; an end at a bound is None.
    pub fn bound(
        &mut self,
        j: usize,
        free: &Free,
        points: &[Point],
        noise: &Noise,
        threshold: f64,
    ) {
        let (lo, hi) = (free.lo, free.hi);
        let chi2_min = points
            .iter()
            .map(|p| noise.chi2(p))
            .fold(f64::INFINITY, f64::min);
        let inside: Vec<f64> = points
            .iter()
            .filter(|p| noise.chi2(p) - chi2_min <= threshold)
            .map(|p| p.x[j])
            .collect();
        // The profile's crossings of the threshold, interpolated linearly
        // in √Δχ² between its points (linear for a quadratic profile),
        // widen the range to where the threshold is met.
        let delta: Vec<f64> = self
            .points
            .iter()
            .map(|(_, p)| noise.chi2(p) - chi2_min)
            .collect();
        let crossings = self
            .points
            .windows(2)
            .zip(delta.windows(2))
            .filter_map(|(v, d)| {
                let (v0, v1, d0, d1) = (v[0].0, v[1].0, d[0], d[1]);
                let crosses =
                    (d0 <= threshold) != (d1 <= threshold) && d0.is_finite() && d1.is_finite();
                let (s0, s1, st) = (d0.max(0.0).sqrt(), d1.max(0.0).sqrt(), threshold.sqrt());
                crosses.then(|| v0 + (v1 - v0) * (st - s0) / (s1 - s0))
            });
        let ends: Vec<f64> = inside.iter().copied().chain(crossings).collect();
        let a = ends.iter().copied().fold(f64::INFINITY, f64::min);
        let b = ends.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        self.lower = (a > lo).then_some(a);
        self.upper = (b < hi).then_some(b);
        self.bounded = self.lower.is_some() && self.upper.is_some();
        let best = points
            .iter()
            .reduce(|x, y| if noise.chi2(y) < noise.chi2(x) { y } else { x })
            .map_or(f64::NAN, |p| p.x[j]);
        let accuracy = if free.is_angle() {
            ACCURACY_DEG
        } else {
            ACCURACY_REL * best.abs()
        };
        self.determined = self.bounded && b - best <= accuracy && best - a <= accuracy;
    }
}

/// The re-optimised points of key `j` walking from the best point down
/// (`up` false) or up to its bound: the grid values beyond the best value,
/// and bisections of the first crossing of the threshold.
fn walk(
    problem: &Problem,
    best: &Point,
    noise: &Noise,
    (j, up): (usize, bool),
    grid: usize,
    threshold: f64,
) -> Vec<(f64, Point)> {
    let others: Vec<usize> = (0..problem.params.len()).filter(|&k| k != j).collect();
    let walk = Walk {
        problem,
        j,
        iterations: ITERATIONS_PER_KEY * others.len() as u64,
        others,
        noise,
        chi2_best: noise.chi2(best),
        threshold,
    };
    let mut chain: Vec<(f64, Point)> = Vec::new();
    let mut last = (best.x[j], best.clone());
    let mut crossed = false;
    for v in grid_beyond(&problem.params[j], best.x[j], up, grid) {
        let point = walk.at(v, &last.1);
        if !crossed && walk.outside(&point) {
            crossed = true;
            let accuracy = if problem.params[j].is_angle() {
                ACCURACY_DEG
            } else {
                ACCURACY_REL * best.x[j].abs()
            };
            walk.bisect(last.clone(), (v, point.clone()), accuracy, &mut chain);
        }
        chain.push((v, point.clone()));
        last = (v, point);
    }
    if up {
        chain.sort_by(|a, b| a.0.total_cmp(&b.0));
    } else {
        chain.sort_by(|a, b| b.0.total_cmp(&a.0));
    }
    chain
}

/// The values of a `grid`-point grid over the key's bounds beyond `from`,
/// in the walk's order: up, or down from it.
fn grid_beyond(free: &Free, from: f64, up: bool, grid: usize) -> Vec<f64> {
    let n = grid.max(2);
    let values: Vec<f64> = (0..n)
        .map(|k| free.value(k as f64 / (n - 1) as f64))
        .collect();
    if up {
        values.into_iter().filter(|&v| v > from).collect()
    } else {
        values.into_iter().rev().filter(|&v| v < from).collect()
    }
}

/// One key's profile walk: key `j` held at a value, the others
/// re-optimised.
struct Walk<'a> {
    problem: &'a Problem<'a>,
    j: usize,
    others: Vec<usize>,
    iterations: u64,
    noise: &'a Noise,
    chi2_best: f64,
    threshold: f64,
}

impl Walk<'_> {
    /// The best point with key `j` at `v`, polished from `from`.
    fn at(&self, v: f64, from: &Point) -> Point {
        let mut z = self.problem.scaled(&from.x);
        z[self.j] = self.problem.params[self.j].scaled(v);
        let tried = polish(self.problem, &z, &self.others, STEP, self.iterations);
        best_of(&tried).clone()
    }

    /// Whether a point's Δχ² from the best is beyond the threshold.
    fn outside(&self, point: &Point) -> bool {
        self.noise.chi2(point) - self.chi2_best > self.threshold
    }

    /// Bisects the crossing between a point `inside` the threshold and one
    /// `outside` until they are a quarter of `accuracy` apart (at most
    /// [`BISECTIONS`] times), adding each midpoint to `chain`.
    fn bisect(
        &self,
        mut inside: (f64, Point),
        mut outside: (f64, Point),
        accuracy: f64,
        chain: &mut Vec<(f64, Point)>,
    ) {
        for _ in 0..BISECTIONS {
            if (outside.0 - inside.0).abs() < 0.25 * accuracy {
                break;
            }
            let m = 0.5 * (inside.0 + outside.0);
            let mid = (m, self.at(m, &inside.1));
            chain.push(mid.clone());
            if self.outside(&mid.1) {
                outside = mid;
            } else {
                inside = mid;
            }
        }
    }
}

/// Pearson correlation of the free keys over the evaluated points within
/// `threshold` of the least χ²; None with fewer than p + 2 such points.
pub fn correlation(
    points: &[Point],
    noise: &Noise,
    threshold: f64,
    p: usize,
) -> Option<Vec<Vec<f64>>> {
    let chi2_min = points
        .iter()
        .map(|p| noise.chi2(p))
        .fold(f64::INFINITY, f64::min);
    let limit = threshold;
    let near: Vec<&Point> = points
        .iter()
        .filter(|pt| noise.chi2(pt) - chi2_min <= limit)
        .collect();
    if near.len() < p + 2 {
        return None;
    }
    let n = near.len() as f64;
    let mean: Vec<f64> = (0..p)
        .map(|k| near.iter().map(|pt| pt.x[k]).sum::<f64>() / n)
        .collect();
    let cov = |a: usize, b: usize| {
        near.iter()
            .map(|pt| (pt.x[a] - mean[a]) * (pt.x[b] - mean[b]))
            .sum::<f64>()
            / n
    };
    Some(
        (0..p)
            .map(|a| {
                (0..p)
                    .map(|b| cov(a, b) / (cov(a, a) * cov(b, b)).sqrt())
                    .collect()
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(x: f64, chi2: f64) -> Point {
        Point {
            x: vec![x],
            sums: Some(vec![chi2]),
            residuals: None,
            rms: chi2.sqrt(),
        }
    }

    fn interval(chi2: impl Fn(f64) -> f64) -> Profile {
        let free = Free {
            key: "soil.friction.peak".into(),
            start: 5.0,
            lo: 0.0,
            hi: 10.0,
            rule: String::new(),
        };
        let noise = Noise {
            variance: vec![1.0],
            sigma: vec![1.0],
        };
        let points: Vec<Point> = (0..=10).map(|k| point(k as f64, chi2(k as f64))).collect();
        let mut profile = Profile {
            points: points.iter().map(|p| (p.x[0], p.clone())).collect(),
            lower: None,
            upper: None,
            bounded: false,
            determined: false,
        };
        profile.bound(0, &free, &points, &noise, 4.0);
        profile
    }

    #[test]
    fn intervals_end_where_a_quadratic_profile_crosses_the_threshold() {
        // Δχ² = (x − 5)² / 0.5625: crossings of 4 at 3.5 and 6.5, between
        // grid points (√Δχ² is linear in x).
        let p = interval(|x| (x - 5.0).powi(2) / 0.5625 + 1.0);
        assert!((p.lower.unwrap() - 3.5).abs() < 1e-12, "{:?}", p.lower);
        assert!((p.upper.unwrap() - 6.5).abs() < 1e-12, "{:?}", p.upper);
        assert!(p.bounded && !p.determined, "wider than ± 1°");
        let p = interval(|x| 16.0 * (x - 5.0).powi(2));
        assert!(p.determined, "{:?}..{:?}", p.lower, p.upper);
    }

    #[test]
    fn a_flat_profile_is_undetermined() {
        let p = interval(|x| 0.01 * x);
        assert_eq!((p.lower, p.upper), (None, None));
        assert!(!p.bounded && !p.determined);
        let p = interval(|x| if x < 5.0 { 0.0 } else { 100.0 });
        assert_eq!(p.lower, None, "reaches the lower bound");
        assert!(p.upper.is_some() && !p.bounded);
    }
}
