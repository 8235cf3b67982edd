//! The tornado of a sensitivity study of a case: each varied key at each
//! end of its range, the others at the case's own values, and the case
//! itself; 2 k + 1 points for k keys (the dummy has no run to move), each
//! an ensemble of the study's members. One-at-a-time ranges say how far
//! each key alone moves an output from the case, which the indices,
//! averaged over the whole box of ranges, do not.

use super::Range;
use crate::figures::mean;

/// Where a tornado point puts its key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// No key moved: the case as it is.
    Case,
    /// The key at the lower end of its range.
    Lo,
    /// The key at the upper end.
    Hi,
}

impl End {
    /// `case`, `lo` or `hi`, as tornado.csv writes it.
    pub fn name(self) -> &'static str {
        match self {
            End::Case => "case",
            End::Lo => "lo",
            End::Hi => "hi",
        }
    }
}

/// One point of the tornado.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TornadoPoint {
    /// The moved key's index among the ranges (None for the case).
    pub key: Option<usize>,
    /// Which end.
    pub end: End,
}

impl TornadoPoint {
    /// The key and value this point sets (none for the case).
    pub fn setting<'a>(&self, ranges: &'a [Range]) -> Option<(&'a str, f64)> {
        let r = &ranges[self.key?];
        match self.end {
            End::Lo => Some((&r.key, r.lo)),
            End::Hi => Some((&r.key, r.hi)),
            End::Case => None,
        }
    }
}

/// The case, then each of `keys` keys at its lower and its upper end.
pub fn points(keys: usize) -> Vec<TornadoPoint> {
    let case = TornadoPoint {
        key: None,
        end: End::Case,
    };
    let ends =
        (0..keys).flat_map(|j| [End::Lo, End::Hi].map(|end| TornadoPoint { key: Some(j), end }));
    std::iter::once(case).chain(ends).collect()
}

/// The ensemble mean of each output at each point, `[point][output]`,
/// from every run's outputs (`values`, `members` a point, in the points'
/// order; NaN where a run lacks the output).
pub fn means(values: &[&[f64]], members: usize) -> Vec<Vec<f64>> {
    values
        .chunks(members)
        .map(|point| {
            let outputs = point.first().map_or(0, |v| v.len());
            (0..outputs)
                .map(|o| mean(&point.iter().map(|v| v[o]).collect::<Vec<f64>>()))
                .collect()
        })
        .collect()
}

/// One output's tornado: its value at the case, and each key's values at
/// its lower and upper end, the keys ordered by the width of their range
/// of the output, widest first (the tornado's shape); a key whose range
/// is not defined (a run lacks the output) last.
#[derive(Clone, Debug, PartialEq)]
pub struct Ranges {
    /// The output at the case.
    pub case: f64,
    /// (key index, output at lo, output at hi), widest first.
    pub keys: Vec<(usize, f64, f64)>,
}

/// Output `o`'s tornado from the points' means (`points`' order).
pub fn ranges_of(means: &[Vec<f64>], o: usize) -> Ranges {
    let keys = (means.len() - 1) / 2;
    let mut rows: Vec<(usize, f64, f64)> = (0..keys)
        .map(|j| (j, means[1 + 2 * j][o], means[2 + 2 * j][o]))
        .collect();
    let width = |r: &(usize, f64, f64)| {
        let w = (r.2 - r.1).abs();
        if w.is_finite() {
            w
        } else {
            -1.0
        }
    };
    rows.sort_by(|a, b| width(b).total_cmp(&width(a)));
    Ranges {
        case: means[0][o],
        keys: rows,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_case_then_each_key_at_both_ends() {
        let ranges = [
            Range {
                key: "a".into(),
                lo: 1.0,
                hi: 2.0,
            },
            Range {
                key: "b".into(),
                lo: 5.0,
                hi: 9.0,
            },
        ];
        let p = points(2);
        assert_eq!(p.len(), 5);
        assert_eq!(p[0].setting(&ranges), None);
        assert_eq!(p[3].setting(&ranges), Some(("b", 5.0)));
        assert_eq!(p[4].setting(&ranges), Some(("b", 9.0)));
    }

    /// Two members a point: the means; key 1 moves the output more than
    /// key 0 and comes first.
    #[test]
    fn keys_are_ordered_by_the_width_of_their_range() {
        let runs: [&[f64]; 10] = [
            &[1.0],
            &[3.0],
            &[2.0],
            &[2.0],
            &[2.5],
            &[2.5],
            &[0.0],
            &[0.0],
            &[10.0],
            &[12.0],
        ];
        let m = means(&runs, 2);
        assert_eq!(m[0], [2.0]);
        let r = ranges_of(&m, 0);
        assert_eq!(r.case, 2.0);
        assert_eq!(r.keys, [(1, 0.0, 11.0), (0, 2.0, 2.5)]);
    }
}
