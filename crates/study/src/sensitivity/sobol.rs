//! Sobol first-order, total and second-order indices from the outputs of
//! Saltelli's design ([`super::design::saltelli`]): S1 by Saltelli et al.
//! (2010), ST by Jansen (1999), S2 by Saltelli (2002), as SALib's
//! `sobol.analyze` computes them.

use super::bootstrap::{self, Interval};
use super::design::rows_per_point;

/// The indices of one input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SobolIndex {
    /// First-order index S1 = V[E(Y | X_i)] / V(Y).
    pub s1: Interval,
    /// Total index ST = E[V(Y | X_~i)] / V(Y).
    pub st: Interval,
}

/// The second-order index of a pair of inputs j < k.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairIndex {
    /// The first input.
    pub j: usize,
    /// The second input, k > j.
    pub k: usize,
    /// S2_jk = V_jk / V(Y), the share of the pair's interaction alone.
    pub s2: Interval,
}

/// The indices of every input, and of every pair if asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct SobolIndices {
    /// S1 and ST of each input.
    pub inputs: Vec<SobolIndex>,
    /// S2 of each pair j < k, in the order (0, 1), (0, 2), … (empty
    /// without the second-order rows).
    pub pairs: Vec<PairIndex>,
}

/// The blocks of `y` (outputs in the design's order): A, the d columns of
/// A_B, those of B_A (none without the second-order rows), B, each of n
/// values.
struct Blocks {
    a: Vec<f64>,
    ab: Vec<Vec<f64>>,
    ba: Vec<Vec<f64>>,
    b: Vec<f64>,
}

impl Blocks {
    fn of(y: &[f64], d: usize, second_order: bool) -> Blocks {
        let rows: Vec<&[f64]> = y.chunks(rows_per_point(d, second_order)).collect();
        let column = |c: usize| rows.iter().map(|r| r[c]).collect::<Vec<f64>>();
        Blocks {
            a: column(0),
            ab: (0..d).map(|j| column(1 + j)).collect(),
            ba: if second_order {
                (0..d).map(|j| column(1 + d + j)).collect()
            } else {
                Vec::new()
            },
            b: rows.iter().map(|r| r[r.len() - 1]).collect(),
        }
    }
}

/// The pairs j < k of `d` inputs, in the order (0, 1), (0, 2), … of
/// [`SobolIndices::pairs`] and `indices2.csv`.
pub fn pairs(d: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..d).flat_map(move |j| (j + 1..d).map(move |k| (j, k)))
}

fn pick(v: &[f64], take: &[usize]) -> Vec<f64> {
    take.iter().map(|&i| v[i]).collect()
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
    let (a, ab, b) = (
        pick(&blocks.a, take),
        pick(&blocks.ab[j], take),
        pick(&blocks.b, take),
    );
    let v = variance(&a, &b);
    if v == 0.0 {
        return (0.0, 0.0);
    }
    let n = take.len() as f64;
    let total: f64 = a.iter().zip(&ab).map(|(a, ab)| (a - ab) * (a - ab)).sum();
    (first_order(&a, &ab, &b) / v, 0.5 * total / n / v)
}

/// mean(B (A_B^j − A)), V_j unscaled by V (Saltelli 2010, table 2 b).
fn first_order(a: &[f64], ab: &[f64], b: &[f64]) -> f64 {
    let sum: f64 = b
        .iter()
        .zip(ab)
        .zip(a)
        .map(|((b, ab), a)| b * (ab - a))
        .sum();
    sum / a.len() as f64
}

/// S2_jk = mean(B_A^j A_B^k − A B) / V − S1_j − S1_k (Saltelli 2002,
/// eq. 12 in SALib's form) over the base points `take`; 0 where the
/// outputs of `take` do not vary.
fn second_order_index(blocks: &Blocks, j: usize, k: usize, take: &[usize]) -> f64 {
    let (a, b) = (pick(&blocks.a, take), pick(&blocks.b, take));
    let v = variance(&a, &b);
    if v == 0.0 {
        return 0.0;
    }
    let (ba_j, ab_j, ab_k) = (
        pick(&blocks.ba[j], take),
        pick(&blocks.ab[j], take),
        pick(&blocks.ab[k], take),
    );
    let joint: f64 = ba_j
        .iter()
        .zip(&ab_k)
        .zip(a.iter().zip(&b))
        .map(|((ba, ab), (a, b))| ba * ab - a * b)
        .sum();
    let v_jk = joint / take.len() as f64;
    (v_jk - first_order(&a, &ab_j, &b) - first_order(&a, &ab_k, &b)) / v
}

/// The indices of every one of `d` inputs (and, with `second_order`, of
/// every pair) from the outputs `y` of Saltelli's design, with bootstrap
/// intervals (`resamples` resamples of the base points, seeded by `seed`,
/// the same resamples for every index). The outputs are first centred and
/// scaled by their mean and standard deviation, as SALib does (the S1
/// estimator is not invariant to a shift of Y). `None` if `y` does not
/// vary at all: there is no variance to apportion.
pub fn sobol_indices(
    y: &[f64],
    d: usize,
    second_order: bool,
    resamples: usize,
    seed: u64,
) -> Option<SobolIndices> {
    let n = y.len() / rows_per_point(d, second_order);
    let mean = y.iter().sum::<f64>() / y.len() as f64;
    let sd = (y.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / y.len() as f64).sqrt();
    if sd == 0.0 || !sd.is_finite() {
        return None;
    }
    let scaled: Vec<f64> = y.iter().map(|x| (x - mean) / sd).collect();
    let blocks = Blocks::of(&scaled, d, second_order);
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
    let pair = |(j, k): (usize, usize)| {
        let replicates: Vec<f64> = draws
            .iter()
            .map(|t| second_order_index(&blocks, j, k, t))
            .collect();
        PairIndex {
            j,
            k,
            s2: Interval::of(second_order_index(&blocks, j, k, &all), &replicates),
        }
    };
    Some(SobolIndices {
        inputs: (0..d).map(index).collect(),
        pairs: if second_order {
            pairs(d).map(pair).collect()
        } else {
            Vec::new()
        },
    })
}
