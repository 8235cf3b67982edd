//! The weight of soil (docs/model.md §5.1, (M24)): every ground sums its
//! columns' weights, and the mass record is checked to 1e-12 of the
//! initial weight, so the sums are compensated.

/// Neumaier's compensated sum: conservation checks at 1e-12 need better than
/// naive summation over 10⁵ nodes.
pub fn compensated_sum(values: impl Iterator<Item = f64>) -> f64 {
    let mut sum = CompensatedSum::default();
    for v in values {
        sum.add(v);
    }
    sum.total()
}

/// `compensated_sum` as a running sum, for loops that sum several
/// quantities in one pass.
#[derive(Clone, Copy, Debug, Default)]
pub struct CompensatedSum {
    sum: f64,
    c: f64,
}

impl CompensatedSum {
    /// Adds v.
    #[inline]
    pub fn add(&mut self, v: f64) {
        let t = self.sum + v;
        // The larger and the smaller of the two by magnitude: a select,
        // not a branch.
        let (large, small) = if self.sum.abs() >= v.abs() {
            (self.sum, v)
        } else {
            (v, self.sum)
        };
        self.c += (large - t) + small;
        self.sum = t;
    }

    /// The sum of everything added.
    pub fn total(&self) -> f64 {
        self.sum + self.c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compensated_sum_beats_naive() {
        let v = [1e16, 1.0, -1e16, 1.0];
        assert_eq!(compensated_sum(v.into_iter()), 2.0);
    }
}
