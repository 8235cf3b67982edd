//! sin and cos of the band angles without a libm call in the search loop.
//!
//! The band's mean friction and dilation angles change from candidate to
//! candidate, so Eq. (1) needs sin and cos of a fresh angle each time. A
//! table of sin, cos at multiples of h = 1/64 rad over (−π/2, π/2) and the
//! Taylor series of the remainder |δ| ≤ h/2 (terms beyond δ⁸ are below
//! 1e-21) give both to within a few units in the last place.

use std::sync::OnceLock;

/// Table step, radians.
const STEP: f64 = 1.0 / 64.0;
/// Table entries cover k STEP for |k| ≤ HALF.
const HALF: i64 = 101;
/// 1.5 · 2⁵²: adding and subtracting it rounds to the nearest integer
/// (ties to even) with plain arithmetic.
const ROUNDING: f64 = 6_755_399_441_055_744.0;

fn table() -> &'static [(f64, f64)] {
    static TABLE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
    TABLE.get_or_init(|| {
        (-HALF..=HALF)
            .map(|k| (k as f64 * STEP).sin_cos())
            .collect()
    })
}

/// (sin x, cos x): from the table for |x| < π/2, else (and for NaN) from
/// libm, so that no angle can index outside the table.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    let k = (x * (1.0 / STEP) + ROUNDING) - ROUNDING;
    // NaN fails the comparison and takes libm's path too.
    let within = k.abs() <= HALF as f64;
    if !within {
        return x.sin_cos();
    }
    let d = x - k * STEP;
    let d2 = d * d;
    let sin_d = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0)));
    let cos_d = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0 * (1.0 - d2 / 56.0)));
    let (sin_k, cos_k) = table()[(k as i64 + HALF) as usize];
    (sin_k * cos_d + cos_k * sin_d, cos_k * cos_d - sin_k * sin_d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_libm_to_a_few_ulp() {
        let mut worst: f64 = 0.0;
        for i in -15_000..=15_000 {
            let x = i as f64 * 1.0e-4;
            let (s, c) = sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
        }
        assert!(worst < 4.0 * f64::EPSILON, "worst error {worst:e}");
    }

    #[test]
    fn an_angle_beyond_the_table_is_libms() {
        for x in [-4.68, 1.7, 100.0, -1e300] {
            assert_eq!(sin_cos(x), x.sin_cos());
        }
        let (s, c) = sin_cos(f64::NAN);
        assert!(s.is_nan() && c.is_nan());
    }
}
