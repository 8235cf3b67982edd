//! Bootstrap confidence intervals: the estimator recomputed on resamples
//! (drawn with replacement, seeded) of the design's base points, the
//! interval the estimate ± z₀.₉₇₅ × the resamples' standard deviation
//! (the normal interval SALib reports as `_conf`).

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Resamples of every bootstrap.
pub const RESAMPLES: usize = 1000;

/// z of a two-sided 95 % normal interval, Φ⁻¹(0.975).
pub const Z95: f64 = 1.959_963_984_540_054;

/// `resamples` lists of `n` indices in 0 … n − 1, drawn with replacement
/// from a generator seeded with `seed` (its stream 1: the designs use
/// stream 0 of the same seed).
pub fn resamples(n: usize, resamples: usize, seed: u64) -> Vec<Vec<usize>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(1);
    (0..resamples)
        .map(|_| (0..n).map(|_| rng.random_range(0..n)).collect())
        .collect()
}

/// The sample standard deviation (n − 1) of `values`; NaN for fewer
/// than two.
pub fn sd(values: &[f64]) -> f64 {
    if values.len() < 2 {
        return f64::NAN;
    }
    let mean = values.iter().sum::<f64>() / values.len() as f64;
    let ss: f64 = values.iter().map(|x| (x - mean) * (x - mean)).sum();
    (ss / (values.len() - 1) as f64).sqrt()
}

/// An estimate and its 95 % interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The estimate on every base point.
    pub value: f64,
    /// Lower end, value − z sd.
    pub low: f64,
    /// Upper end, value + z sd.
    pub high: f64,
}

impl Interval {
    /// `value` ± z₀.₉₇₅ × sd(`replicates`).
    pub fn of(value: f64, replicates: &[f64]) -> Interval {
        let half = Z95 * sd(replicates);
        Interval {
            value,
            low: value - half,
            high: value + half,
        }
    }

    /// Whether `x` is inside [low, high].
    pub fn contains(&self, x: f64) -> bool {
        self.low <= x && x <= self.high
    }
}
