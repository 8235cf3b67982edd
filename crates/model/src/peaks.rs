//! Distinct peaks of a force history, by topographic prominence.
//!
//! A peak is an interior local maximum whose prominence, the height above
//! the higher of the two lowest points separating it from any higher value
//! (or from the ends of the record), is at least `min_prominence`. Sawtooth
//! noise from the node grid has tiny prominence; a softening peak followed
//! by a band jump has a large one. Plateaus count once, at their first node.
//! The ends of the record are never peaks (a rise that is still going on at
//! the end of the run is not a peak).
//!
//! O(n log n): nearest higher values by monotonic stacks, the lowest point
//! between by a sparse table.

/// Indices of the peaks of `values` with prominence ≥ `min_prominence`.
pub fn find_peaks(values: &[f64], min_prominence: f64) -> Vec<usize> {
    let n = values.len();
    if n < 3 {
        return Vec::new();
    }
    let table = MinTable::new(values);
    let left_higher = nearest_higher(values, (0..n).collect());
    let right_higher = nearest_higher(values, (0..n).rev().collect());
    let mut peaks = Vec::new();
    let mut i = 1;
    while i + 1 < n {
        // The plateau [i, k] of equal values starting at i.
        let mut k = i;
        while k + 1 < n && values[k + 1] == values[i] {
            k += 1;
        }
        let is_max = values[i - 1] < values[i] && k + 1 < n && values[k + 1] < values[i];
        if is_max {
            let left_base = table.min(left_higher[i].unwrap_or(0), i);
            let right_base = table.min(k, right_higher[k].unwrap_or(n - 1));
            if values[i] - left_base.max(right_base) >= min_prominence {
                peaks.push(i);
            }
        }
        i = k + 1;
    }
    peaks
}

/// For each index in `order`, the nearest earlier index (in that order)
/// holding a strictly higher value.
fn nearest_higher(values: &[f64], order: Vec<usize>) -> Vec<Option<usize>> {
    let mut result = vec![None; values.len()];
    let mut stack: Vec<usize> = Vec::new();
    for i in order {
        while let Some(&top) = stack.last() {
            if values[top] > values[i] {
                break;
            }
            stack.pop();
        }
        result[i] = stack.last().copied();
        stack.push(i);
    }
    result
}

/// Range minimum queries in O(1) after O(n log n) set-up.
struct MinTable {
    levels: Vec<Vec<f64>>,
}

impl MinTable {
    fn new(values: &[f64]) -> Self {
        let mut levels = vec![values.to_vec()];
        let mut width = 1;
        while 2 * width <= values.len() {
            let prev = levels.last().expect("level 0");
            let next = (0..prev.len() - width)
                .map(|i| prev[i].min(prev[i + width]))
                .collect();
            levels.push(next);
            width *= 2;
        }
        MinTable { levels }
    }

    /// Minimum over the inclusive range [a, b] (in either order).
    fn min(&self, a: usize, b: usize) -> f64 {
        let (lo, hi) = (a.min(b), a.max(b));
        let level = (usize::BITS - 1 - (hi - lo + 1).leading_zeros()) as usize;
        let row = &self.levels[level];
        row[lo].min(row[hi + 1 - (1 << level)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_distinct_peaks_among_noise() {
        let mut v = Vec::new();
        for i in 0..400 {
            let x = i as f64 / 100.0;
            let smooth = (-(x - 1.0).powi(2) * 8.0).exp() + 0.8 * (-(x - 3.0).powi(2) * 8.0).exp();
            let noise = if i % 2 == 0 { 0.003 } else { -0.003 };
            v.push(smooth + noise);
        }
        let peaks = find_peaks(&v, 0.1);
        assert_eq!(peaks.len(), 2, "{peaks:?}");
        assert!((95..=105).contains(&peaks[0]) && (295..=305).contains(&peaks[1]));
        assert!(
            find_peaks(&v, 0.001).len() > 10,
            "noise has many small peaks"
        );
    }

    #[test]
    fn monotone_and_end_maxima_are_not_peaks() {
        let rising: Vec<f64> = (0..50).map(|i| i as f64).collect();
        assert!(find_peaks(&rising, 0.0).is_empty());
        assert_eq!(find_peaks(&[0.0, 2.0, 2.0, 2.0, 1.0, 5.0], 0.5), vec![1]);
    }

    #[test]
    fn prominence_is_measured_to_the_higher_saddle() {
        // Peak at 3 (value 4) is separated from the higher 10 by a dip to 3.
        let v = [0.0, 1.0, 2.0, 4.0, 3.0, 10.0, 0.0];
        assert_eq!(find_peaks(&v, 1.0), vec![3, 5]);
        assert_eq!(find_peaks(&v, 1.5), vec![5]);
    }
}
