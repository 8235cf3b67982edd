//! The global search: differential evolution on the unit box
//! (DE/current-to-pbest/1/bin, as in JADE, with fixed rates), then a
//! Nelder-Mead polish of the best point.
//!
//! Each generation, member i of the population (NP points zᵢ) proposes
//!
//!   vᵢ = zᵢ + F (z_pbest − zᵢ) + F (z_r1 − z_r2),
//!
//! with z_pbest drawn from the best ⌈NP/5⌉ members, r1 ≠ r2 ≠ i random
//! members and F uniform in [0.4, 0.9]; the trial takes vᵢ's coordinate
//! with probability CR = 0.9 (and at one random coordinate always), the
//! rest from zᵢ; a coordinate beyond the box is put halfway between zᵢ and
//! the bound it crossed. The trial replaces zᵢ if its RMS is no larger.
//! Infeasible points (a run fails) have RMS +∞: they are replaced by the
//! first feasible trial, and never replace a feasible member.
//!
//! Determinism: every random number is drawn from one seeded generator on
//! the calling thread, in a fixed order; only the runs of a generation's
//! trials are spread over the threads (rayon keeps their order). The same
//! seed gives the same search, bit for bit, on any number of threads.

use super::problem::{Point, Problem};
use argmin::core::{CostFunction, Error as ArgminError, Executor, State};
use argmin::solver::neldermead::NelderMead;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use std::cell::RefCell;

/// Share of the population the "pbest" member is drawn from.
const PBEST_SHARE: f64 = 0.2;
/// Crossover rate.
const CROSSOVER: f64 = 0.9;
/// The search stops early when every coordinate of the population lies
/// within this width (scaled coordinates).
pub(super) const SPREAD_STOP: f64 = 1e-4;
/// Range of the differential weight F.
const WEIGHT: (f64, f64) = (0.4, 0.9);

/// Settings of the global search.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// Population size NP (≥ 4).
    pub population: usize,
    /// Runs of the search: NP for the first generation, then NP per
    /// generation until this many have been made.
    pub evaluations: usize,
    /// Seed of the random numbers.
    pub seed: u64,
}

/// One generation of the search.
#[derive(Clone, Debug, PartialEq)]
pub struct Generation {
    /// Evaluations made so far.
    pub evaluations: usize,
    /// The least RMS of the population.
    pub best_rms: f64,
    /// The median RMS of the population.
    pub median_rms: f64,
    /// Members that are infeasible.
    pub infeasible: usize,
}

/// The result of the search.
#[derive(Clone, Debug)]
pub struct Search {
    /// The best point of the search.
    pub best: Point,
    /// Every generation's figures.
    pub generations: Vec<Generation>,
    /// Every point evaluated, in order.
    pub points: Vec<Point>,
}

/// Runs differential evolution from a seeded Latin-hypercube population
/// whose first member is `first` (scaled coordinates). `progress` is
/// called with the number of evaluations made.
pub fn evolve(
    problem: &Problem,
    budget: Budget,
    first: &[f64],
    progress: &(dyn Fn(usize) + Sync),
) -> Search {
    let dim = first.len();
    let np = budget.population.max(4);
    let mut rng = ChaCha8Rng::seed_from_u64(budget.seed);
    let mut members = latin_hypercube(np, dim, &mut rng);
    members[0] = first.to_vec();
    let evaluate = |zs: &[Vec<f64>]| -> Vec<Point> {
        zs.par_iter().map(|z| problem.evaluate_scaled(z)).collect()
    };
    let mut points = evaluate(&members);
    let mut all = points.clone();
    let mut generations = vec![generation(&points, all.len())];
    progress(all.len());
    while all.len() + np <= budget.evaluations.max(np) && spread(&members) > SPREAD_STOP {
        let trials: Vec<Vec<f64>> = (0..np)
            .map(|i| trial(i, &members, &points, &mut rng))
            .collect();
        let tried = evaluate(&trials);
        for (i, (z, p)) in trials.into_iter().zip(tried).enumerate() {
            all.push(p.clone());
            if p.rms <= points[i].rms {
                members[i] = z;
                points[i] = p;
            }
        }
        generations.push(generation(&points, all.len()));
        progress(all.len());
    }
    let best = best_of(&points).clone();
    Search {
        best,
        generations,
        points: all,
    }
}

/// The trial of member `i` (see the module documentation).
fn trial(i: usize, members: &[Vec<f64>], points: &[Point], rng: &mut ChaCha8Rng) -> Vec<f64> {
    let np = members.len();
    let mut order: Vec<usize> = (0..np).collect();
    order.sort_by(|&a, &b| points[a].rms.total_cmp(&points[b].rms).then(a.cmp(&b)));
    let top = ((PBEST_SHARE * np as f64).ceil() as usize).max(1);
    let pbest = order[rng.random_range(0..top)];
    let r1 = other(rng, np, &[i]);
    let r2 = other(rng, np, &[i, r1]);
    let f = WEIGHT.0 + (WEIGHT.1 - WEIGHT.0) * rng.random::<f64>();
    let z = &members[i];
    let forced = rng.random_range(0..z.len());
    (0..z.len())
        .map(|k| {
            let cross = rng.random::<f64>() < CROSSOVER || k == forced;
            if !cross {
                return z[k];
            }
            let v = z[k] + f * (members[pbest][k] - z[k]) + f * (members[r1][k] - members[r2][k]);
            if v < 0.0 {
                0.5 * z[k]
            } else if v > 1.0 {
                0.5 * (z[k] + 1.0)
            } else {
                v
            }
        })
        .collect()
}

/// A random index below `n` not in `not`.
fn other(rng: &mut ChaCha8Rng, n: usize, not: &[usize]) -> usize {
    loop {
        let k = rng.random_range(0..n);
        if !not.contains(&k) {
            return k;
        }
    }
}

/// `n` points of a Latin-hypercube sample of the unit box.
pub fn latin_hypercube(n: usize, dim: usize, rng: &mut ChaCha8Rng) -> Vec<Vec<f64>> {
    let mut points = vec![Vec::with_capacity(dim); n];
    for _ in 0..dim {
        let mut strata: Vec<usize> = (0..n).collect();
        for k in (1..n).rev() {
            strata.swap(k, rng.random_range(0..=k));
        }
        for (point, stratum) in points.iter_mut().zip(strata) {
            point.push((stratum as f64 + rng.random::<f64>()) / n as f64);
        }
    }
    points
}

/// The largest range of a coordinate over the members.
fn spread(members: &[Vec<f64>]) -> f64 {
    (0..members[0].len())
        .map(|k| {
            let (lo, hi) = members
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
                    (lo.min(z[k]), hi.max(z[k]))
                });
            hi - lo
        })
        .fold(0.0, f64::max)
}

/// The figures of a generation's points after `evaluations` runs.
pub(super) fn generation(points: &[Point], evaluations: usize) -> Generation {
    let mut rms: Vec<f64> = points.iter().map(|p| p.rms).collect();
    rms.sort_by(f64::total_cmp);
    Generation {
        evaluations,
        best_rms: rms[0],
        median_rms: rms[rms.len() / 2],
        infeasible: rms.iter().filter(|r| r.is_infinite()).count(),
    }
}

/// The point of least RMS; the first of equals.
pub fn best_of(points: &[Point]) -> &Point {
    points
        .iter()
        .reduce(|best, p| if p.rms < best.rms { p } else { best })
        .expect("at least one point")
}

/// Cost of a point outside the box or infeasible, for Nelder-Mead (which
/// needs finite costs): above any feasible RMS, growing with the distance
/// outside.
fn penalty(outside: f64) -> f64 {
    1e12 * (1.0 + outside)
}

/// Nelder-Mead over the coordinates `free` of the scaled point `z0` (the
/// others held), from a simplex of steps `step` (backwards where forwards
/// would leave the box), for at most `iterations` iterations. Returns
/// every point evaluated; the best of them is the result.
pub fn polish(
    problem: &Problem,
    z0: &[f64],
    free: &[usize],
    step: f64,
    iterations: u64,
) -> Vec<Point> {
    let evaluated = RefCell::new(Vec::new());
    let cost = |y: &[f64]| -> f64 {
        let outside: f64 = y.iter().map(|&y| (-y).max(y - 1.0).max(0.0)).sum();
        if outside > 0.0 {
            return penalty(outside);
        }
        let mut z = z0.to_vec();
        for (&k, &y) in free.iter().zip(y) {
            z[k] = y;
        }
        let p = problem.evaluate_scaled(&z);
        let c = if p.rms.is_finite() {
            p.rms
        } else {
            penalty(0.0)
        };
        evaluated.borrow_mut().push(p);
        c
    };
    let y0: Vec<f64> = free.iter().map(|&k| z0[k]).collect();
    if free.is_empty() {
        cost(&y0);
        return evaluated.into_inner();
    }
    let mut simplex = vec![y0.clone()];
    for k in 0..y0.len() {
        let mut v = y0.clone();
        v[k] = if v[k] + step <= 1.0 {
            v[k] + step
        } else {
            v[k] - step
        };
        simplex.push(v);
    }
    let solver = NelderMead::new(simplex)
        .with_sd_tolerance(1e-9)
        .expect("a non-negative tolerance");
    let outcome = Executor::new(Cost(&cost), solver)
        .configure(|state| state.max_iters(iterations))
        .run();
    // The cost never fails; whatever argmin returns, the points evaluated
    // are the result.
    let _ = outcome.map(|r| r.state().get_iter());
    evaluated.into_inner()
}

struct Cost<'a>(&'a dyn Fn(&[f64]) -> f64);

impl CostFunction for Cost<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, y: &Vec<f64>) -> Result<f64, ArgminError> {
        Ok((self.0)(y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin_hypercube_fills_each_stratum_once() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let points = latin_hypercube(10, 3, &mut rng);
        for k in 0..3 {
            let mut strata: Vec<usize> = points.iter().map(|p| (p[k] * 10.0) as usize).collect();
            strata.sort();
            assert_eq!(strata, (0..10).collect::<Vec<_>>());
        }
    }
}
