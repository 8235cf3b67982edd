//! When a scheme is accurate: the ensemble rule (docs/model.md §12.1,
//! (M40)).
//!
//! The model is chaotic: an imperceptible change of the input moves a late
//! unit-window mean force by 1-2 %, so one run against one reference run
//! asks more than the model decides. A scheme is judged by ensembles
//! of perturbed runs: it is **accurate** on a case when every unit-window
//! ensemble mean of P/(γ0 d²) lies within
//!
//! ```text
//! tol = clamp(2 √(s_a²/n_a + s_r²/n_r) / |m_r|, 1 %, 2.5 %)
//! ```
//!
//! of the reference ensemble's mean m_r (two standard errors of the
//! difference of the two means, relative, but never below 1 % nor above
//! 2.5 %), and the whole-run ensemble mean within 1 % of the reference's.

/// Least window tolerance, relative.
pub const WINDOW_FLOOR: f64 = 0.01;
/// Largest window tolerance, relative.
pub const WINDOW_CEILING: f64 = 0.025;
/// Tolerance of the whole-run mean, relative.
pub const WHOLE_RUN: f64 = 0.01;

/// The spread of one figure over the members of an ensemble.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    /// Members.
    pub n: usize,
    /// Mean over the members.
    pub mean: f64,
    /// Sample standard deviation (n − 1 in the denominator; 0 for n = 1).
    pub std: f64,
    /// Least value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
}

impl Spread {
    /// The spread of `values` (NaN figures for none).
    pub fn of(values: &[f64]) -> Spread {
        let n = values.len();
        let mean = values.iter().sum::<f64>() / n as f64;
        let squares: f64 = values.iter().map(|v| (v - mean).powi(2)).sum();
        let std = if n > 1 {
            (squares / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        Spread {
            n,
            mean,
            std,
            min: values.iter().copied().fold(f64::NAN, f64::min),
            max: values.iter().copied().fold(f64::NAN, f64::max),
        }
    }

    /// The standard error of the mean, s / √n.
    pub fn standard_error(&self) -> f64 {
        self.std / (self.n as f64).sqrt()
    }
}

/// One figure of a scheme's ensemble against the reference's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Verdict {
    /// (m_a − m_r) / |m_r|.
    pub deviation: f64,
    /// The tolerance it is held to, relative.
    pub tolerance: f64,
}

impl Verdict {
    /// |deviation| within the tolerance.
    pub fn ok(&self) -> bool {
        self.deviation.abs() <= self.tolerance
    }
}

/// A scheme's ensemble judged against the reference ensemble.
#[derive(Clone, Debug, PartialEq)]
pub struct Agreement {
    /// One per unit window both ensembles have.
    pub windows: Vec<Verdict>,
    /// The whole-run mean, held to [`WHOLE_RUN`].
    pub whole_run: Verdict,
}

impl Agreement {
    /// Every window and the whole-run mean within their tolerances.
    pub fn accurate(&self) -> bool {
        self.whole_run.ok() && self.windows.iter().all(Verdict::ok)
    }

    /// The largest |deviation| / tolerance over the windows and the whole
    /// run: ≤ 1 when accurate.
    pub fn worst_ratio(&self) -> f64 {
        self.windows
            .iter()
            .chain([&self.whole_run])
            .map(|v| v.deviation.abs() / v.tolerance)
            .fold(0.0, f64::max)
    }
}

/// The window tolerance of a scheme's spread `a` against the reference's
/// `r` (M40): two standard errors of the difference of the means, relative,
/// clamped to [[`WINDOW_FLOOR`], [`WINDOW_CEILING`]].
pub fn window_tolerance(a: &Spread, r: &Spread) -> f64 {
    let se = (a.standard_error().powi(2) + r.standard_error().powi(2)).sqrt();
    (2.0 * se / r.mean.abs()).clamp(WINDOW_FLOOR, WINDOW_CEILING)
}

fn deviation(a: &Spread, r: &Spread) -> f64 {
    (a.mean - r.mean) / r.mean.abs()
}

/// Judges the scheme's window spreads and whole-run spread against the
/// reference's by (M40) (windows beyond the shorter list are not judged).
pub fn agreement(
    windows: &[Spread],
    whole_run: &Spread,
    reference_windows: &[Spread],
    reference_whole_run: &Spread,
) -> Agreement {
    Agreement {
        windows: windows
            .iter()
            .zip(reference_windows)
            .map(|(a, r)| Verdict {
                deviation: deviation(a, r),
                tolerance: window_tolerance(a, r),
            })
            .collect(),
        whole_run: Verdict {
            deviation: deviation(whole_run, reference_whole_run),
            tolerance: WHOLE_RUN,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_of_known_values() {
        let s = Spread::of(&[1.0, 2.0, 3.0, 4.0]);
        assert_eq!((s.n, s.mean, s.min, s.max), (4, 2.5, 1.0, 4.0));
        assert!((s.std - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert!((s.standard_error() - s.std / 2.0).abs() < 1e-15);
        assert_eq!(Spread::of(&[7.0]).std, 0.0);
    }

    #[test]
    fn tolerance_is_two_standard_errors_clamped() {
        let r = Spread::of(&[10.0, 10.0]);
        // No spread: the floor.
        assert_eq!(window_tolerance(&r, &r), WINDOW_FLOOR);
        // Between the bounds: two standard errors of the difference.
        let a = Spread::of(&[9.9, 10.1]);
        let expected = 2.0 * a.standard_error() / 10.0;
        assert!(
            (window_tolerance(&a, &r) - expected).abs() < 1e-15,
            "{expected}"
        );
        assert!(expected > WINDOW_FLOOR && expected < WINDOW_CEILING);
        // A wide spread: the ceiling.
        let wide = Spread::of(&[5.0, 15.0]);
        assert_eq!(window_tolerance(&wide, &r), WINDOW_CEILING);
    }

    #[test]
    fn a_biased_scheme_fails_and_a_close_one_passes() {
        let r = [Spread::of(&[9.9, 10.0, 10.1])];
        let whole = Spread::of(&[5.0, 5.0, 5.0]);
        let close = [Spread::of(&[9.95, 10.05, 10.15])];
        assert!(agreement(&close, &whole, &r, &whole).accurate());
        let biased = [Spread::of(&[9.6, 9.7, 9.8])];
        let a = agreement(&biased, &whole, &r, &whole);
        assert!(!a.accurate());
        assert!((a.windows[0].deviation + 0.03).abs() < 1e-12);
        assert!(a.worst_ratio() > 1.0);
        // The whole run alone, off by 1.2 %.
        let off = Spread::of(&[5.06, 5.06, 5.06]);
        assert!(!agreement(&r, &off, &r, &whole).accurate());
    }
}
