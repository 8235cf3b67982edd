//! The weight of soil (docs/model.md §5.1, (M24)): every ground sums its
//! columns' weights, and the mass record is checked to 1e-12 of the
//! initial weight, so the sums are compensated.

/// Neumaier's compensated sum: conservation checks at 1e-12 need better than
/// naive summation over 10⁵ nodes.
pub fn compensated_sum(values: impl Iterator<Item = f64>) -> f64 {
    let (mut sum, mut c) = (0.0f64, 0.0f64);
    for v in values {
        let t = sum + v;
        // The larger and the smaller of the two by magnitude: a select,
        // not a branch.
        let (large, small) = if sum.abs() >= v.abs() {
            (sum, v)
        } else {
            (v, sum)
        };
        c += (large - t) + small;
        sum = t;
    }
    sum + c
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
