//! Morris's elementary effects from the outputs of its design
//! ([`super::design::morris`]), and their statistics μ, μ*, σ (Morris
//! 1991; Campolongo et al. 2007), as SALib's `morris.analyze` computes
//! them.

use super::bootstrap::{self, Interval};
use super::design::morris_delta;

/// The screening statistics of one input, in the output's unit per unit
/// of the input's range taken as 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MorrisIndex {
    /// μ* = mean |EE|, with its bootstrap interval.
    pub mu_star: Interval,
    /// μ = mean EE.
    pub mu: f64,
    /// σ = standard deviation of EE (n − 1).
    pub sigma: f64,
}

/// The elementary effects of every input, `[input][trajectory]`: along
/// each step of a trajectory (rows `x` in the unit cube, `d` inputs) one
/// input moves by ±Δ; its effect is (y at the higher value − y at the
/// lower) / Δ.
pub fn elementary_effects(x: &[Vec<f64>], y: &[f64], d: usize, levels: usize) -> Vec<Vec<f64>> {
    let delta = morris_delta(levels);
    let r = y.len() / (d + 1);
    let mut ee = vec![vec![0.0; r]; d];
    for s in 0..y.len() - 1 {
        // The last row of a trajectory is not followed by its next step.
        if (s + 1) % (d + 1) == 0 {
            continue;
        }
        let Some(k) = (0..d).find(|&k| x[s][k] != x[s + 1][k]) else {
            continue;
        };
        let up = x[s + 1][k] > x[s][k];
        ee[k][s / (d + 1)] = if up {
            (y[s + 1] - y[s]) / delta
        } else {
            (y[s] - y[s + 1]) / delta
        };
    }
    ee
}

/// The statistics of every input from the design `x` (unit cube) and
/// its outputs `y`, μ*'s interval by `resamples` bootstrap resamples of
/// the trajectories seeded by `seed`.
pub fn morris_indices(
    x: &[Vec<f64>],
    y: &[f64],
    d: usize,
    levels: usize,
    resamples: usize,
    seed: u64,
) -> Vec<MorrisIndex> {
    let ee = elementary_effects(x, y, d, levels);
    let r = y.len() / (d + 1);
    let draws = bootstrap::resamples(r, resamples, seed);
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    ee.iter()
        .map(|e| {
            let abs: Vec<f64> = e.iter().map(|v| v.abs()).collect();
            let replicates: Vec<f64> = draws
                .iter()
                .map(|t| t.iter().map(|&i| abs[i]).sum::<f64>() / t.len() as f64)
                .collect();
            MorrisIndex {
                mu_star: Interval::of(mean(&abs), &replicates),
                mu: mean(e),
                sigma: bootstrap::sd(e),
            }
        })
        .collect()
}
