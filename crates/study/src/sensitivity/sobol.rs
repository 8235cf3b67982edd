//! Sobol first-order and total indices from the outputs of Saltelli's
//! design ([`super::design::saltelli`]): S1 by Saltelli et al. (2010),
//! ST by Jansen (1999), as SALib's `sobol.analyze` computes them.

use super::bootstrap::{self, Interval};

/// The indices of one input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SobolIndex {
    /// First-order index S1 = V[E(Y | X_i)] / V(Y).
    pub s1: Interval,
    /// Total index ST = E[V(Y | X_~i)] / V(Y).
    pub st: Interval,
}

/// The blocks of `y` (n (d + 2) outputs in the design's order): A, the
/// d columns of A_B, B, each of n values.
struct Blocks {
    a: Vec<f64>,
    ab: Vec<Vec<f64>>,
    b: Vec<f64>,
}

impl Blocks {
    fn of(y: &[f64], d: usize) -> Blocks {
        let rows: Vec<&[f64]> = y.chunks(d + 2).collect();
        Blocks {
            a: rows.iter().map(|r| r[0]).collect(),
            ab: (0..d)
                .map(|j| rows.iter().map(|r| r[1 + j]).collect())
                .collect(),
            b: rows.iter().map(|r| r[d + 1]).collect(),
        }
    }
}

/// The population variance of A and B together (numpy's `var` of
/// `r_[A, B]`).
fn variance(a: &[f64], b: &[f64]) -> f64 {
    let n = (a.len() + b.len()) as f64;
    let mean = a.iter().chain(b).sum::<f64>() / n;
    a.iter()
        .chain(b)
        .map(|x| (x - mean) * (x - mean))
        .sum::<f64>()
        / n
}

/// S1_i = mean(B (A_B^i − A)) / V (Saltelli 2010, table 2 b) and
/// ST_i = mean((A − A_B^i)²) / (2 V) (Jansen 1999, table 2 f) over the
/// base points `take`; 0 where the outputs of `take` do not vary (as
/// SALib does).
fn indices(blocks: &Blocks, j: usize, take: &[usize]) -> (f64, f64) {
    let pick = |v: &[f64]| take.iter().map(|&i| v[i]).collect::<Vec<f64>>();
    let (a, ab, b) = (pick(&blocks.a), pick(&blocks.ab[j]), pick(&blocks.b));
    let v = variance(&a, &b);
    if v == 0.0 {
        return (0.0, 0.0);
    }
    let n = take.len() as f64;
    let first: f64 = b
        .iter()
        .zip(&ab)
        .zip(&a)
        .map(|((b, ab), a)| b * (ab - a))
        .sum();
    let total: f64 = a.iter().zip(&ab).map(|(a, ab)| (a - ab) * (a - ab)).sum();
    (first / n / v, 0.5 * total / n / v)
}

/// The indices of every one of `d` inputs from the outputs `y` of
/// Saltelli's design, with bootstrap intervals (`resamples` resamples of
/// the base points, seeded by `seed`). The outputs are first centred and
/// scaled by their mean and standard deviation, as SALib does (the S1
/// estimator is not invariant to a shift of Y). `None` if `y` does not
/// vary at all: there is no variance to apportion.
pub fn sobol_indices(y: &[f64], d: usize, resamples: usize, seed: u64) -> Option<Vec<SobolIndex>> {
    let n = y.len() / (d + 2);
    let mean = y.iter().sum::<f64>() / y.len() as f64;
    let sd = (y.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / y.len() as f64).sqrt();
    if sd == 0.0 || !sd.is_finite() {
        return None;
    }
    let scaled: Vec<f64> = y.iter().map(|x| (x - mean) / sd).collect();
    let blocks = Blocks::of(&scaled, d);
    let all: Vec<usize> = (0..n).collect();
    let draws = bootstrap::resamples(n, resamples, seed);
    let index = |j: usize| {
        let (s1, st) = indices(&blocks, j, &all);
        let (r1, rt): (Vec<f64>, Vec<f64>) = draws.iter().map(|t| indices(&blocks, j, t)).unzip();
        SobolIndex {
            s1: Interval::of(s1, &r1),
            st: Interval::of(st, &rt),
        }
    };
    Some((0..d).map(index).collect())
}
