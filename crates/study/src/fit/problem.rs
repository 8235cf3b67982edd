//! The fit as a problem on the unit box: free values in scaled
//! coordinates z ∈ [0, 1]ᵖ (z = (x − lo)/(hi − lo)), evaluated by running
//! every test.

use super::bounds::Free;
use super::objective::{residuals, sum_of_squares, Compare, Test};
use std::sync::atomic::{AtomicUsize, Ordering};

/// One evaluated set of values.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// The free keys' values, in the order of the fit's keys.
    pub x: Vec<f64>,
    /// Each test's sum of squares S_t; None if a run failed (an
    /// infeasible point).
    pub sums: Option<Vec<f64>>,
    /// Each test's residuals rₖ (their weights are the problem's
    /// [`Problem::weights`]); None at an infeasible point.
    pub residuals: Option<Vec<Vec<f64>>>,
    /// Pooled weighted RMS E; +∞ at an infeasible point.
    pub rms: f64,
}

/// The tests, the comparison and the free keys.
pub struct Problem<'a> {
    /// The measured curves and their cases.
    pub tests: &'a [Test],
    /// The objective.
    pub compare: Compare,
    /// The free keys.
    pub params: &'a [Free],
    keys: Vec<String>,
    /// Σ of every residual's weight, over all tests.
    total_weight: f64,
    evaluations: AtomicUsize,
}

impl<'a> Problem<'a> {
    /// The problem of fitting `params` to `tests` under `compare`.
    pub fn new(tests: &'a [Test], compare: Compare, params: &'a [Free]) -> Self {
        Problem {
            tests,
            compare,
            params,
            keys: params.iter().map(|p| p.key.clone()).collect(),
            total_weight: tests.iter().map(|t| t.weight(compare)).sum(),
            evaluations: AtomicUsize::new(0),
        }
    }

    /// The values at scaled coordinates `z`.
    pub fn values(&self, z: &[f64]) -> Vec<f64> {
        self.params
            .iter()
            .zip(z)
            .map(|(p, &z)| p.value(z))
            .collect()
    }

    /// The scaled coordinates of `x`.
    pub fn scaled(&self, x: &[f64]) -> Vec<f64> {
        self.params
            .iter()
            .zip(x)
            .map(|(p, &x)| p.scaled(x))
            .collect()
    }

    /// Evaluations made so far.
    pub fn evaluations(&self) -> usize {
        self.evaluations.load(Ordering::Relaxed)
    }

    /// The weight of each residual of each test (they do not depend on
    /// the values).
    pub fn weights(&self) -> Vec<Vec<f64>> {
        self.tests
            .iter()
            .map(|t| {
                residuals(self.compare, &t.measured, &t.measured, &t.weights)
                    .iter()
                    .map(|r| r.0)
                    .collect()
            })
            .collect()
    }

    /// Runs every test at the values `x`.
    pub fn evaluate(&self, x: &[f64]) -> Point {
        self.evaluations.fetch_add(1, Ordering::Relaxed);
        let all = self
            .tests
            .iter()
            .map(|t| {
                t.run_at(&self.keys, x)
                    .map(|run| t.residuals(self.compare, &run))
            })
            .collect::<Result<Vec<Vec<(f64, f64)>>, String>>();
        match all {
            Ok(all) => self.point_of(x, all),
            Err(_) => Point {
                x: x.to_vec(),
                sums: None,
                residuals: None,
                rms: f64::INFINITY,
            },
        }
    }

    /// The free keys, in the order of a point's values.
    pub fn keys(&self) -> &[String] {
        &self.keys
    }

    /// The point at `x` whose tests gave the (weight, residual) pairs
    /// `all`.
    pub fn point_of(&self, x: &[f64], all: Vec<Vec<(f64, f64)>>) -> Point {
        let sums: Vec<f64> = all.iter().map(|r| sum_of_squares(r)).collect();
        let rms = (sums.iter().sum::<f64>() / self.total_weight).sqrt();
        Point {
            x: x.to_vec(),
            sums: Some(sums),
            residuals: Some(
                all.iter()
                    .map(|r| r.iter().map(|&(_, r)| r).collect())
                    .collect(),
            ),
            rms,
        }
    }

    /// [`Problem::evaluate`] at scaled coordinates.
    pub fn evaluate_scaled(&self, z: &[f64]) -> Point {
        self.evaluate(&self.values(z))
    }
}
