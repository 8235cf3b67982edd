//! The force on the blade for one trial mechanism: paper Eq. (1).
//!
//! Equilibrium of the rigid block (weight W) pushed by the blade (reaction
//! inclined at φw below the face normal, the block sliding up the face) and
//! resisted by the slip surface (reaction inclined at φ to its normal) gives
//!
//! ```text
//! P = W tan(β + φ) / (cos φw − sin φw tan(β + φ)) = W sin(β + φ) / cos(β + φ + φw)   (1)
//! ```
//!
//! Dividing numerator and denominator by cos β gives the form used in the
//! search loop, trigonometry-free in t = tan β:
//!
//! ```text
//! P / W = (t cos φ + sin φ) / (cos(φ + φw) − t sin(φ + φw))
//! ```
//!
//! A mechanism is admissible only for β > 0 and β + φ + φw < 90°, i.e. for
//! t > 0 and a positive denominator.

use crate::case::Case;
use crate::rake::Rake;

/// Eq. (1) for one friction angle φ and wall friction φw, precomputed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceFactor {
    cos_phi: f64,
    sin_phi: f64,
    cos_phi_w: f64,
    sin_phi_w: f64,
}

impl ForceFactor {
    /// The coefficients of (M7), cos φ, sin φ, cos(φ + ω), sin(φ + ω), for
    /// ω = `wall_friction`; `phi`, `wall_friction` in radians.
    pub fn new(phi: f64, wall_friction: f64) -> Self {
        ForceFactor {
            cos_phi: phi.cos(),
            sin_phi: phi.sin(),
            cos_phi_w: (phi + wall_friction).cos(),
            sin_phi_w: (phi + wall_friction).sin(),
        }
    }

    /// The same coefficients of (M7) from sin φ, cos φ and sin ω, cos ω: no
    /// trigonometry.
    #[inline]
    pub fn from_sin_cos(phi: (f64, f64), wall: (f64, f64)) -> Self {
        let ((sin_phi, cos_phi), (sin_w, cos_w)) = (phi, wall);
        ForceFactor {
            cos_phi,
            sin_phi,
            cos_phi_w: cos_phi * cos_w - sin_phi * sin_w,
            sin_phi_w: sin_phi * cos_w + cos_phi * sin_w,
        }
    }

    /// P / W at t = tan β by Eq. (1) (M6) in its tangent form
    /// (t cos φ + sin φ) / (cos(φ + ω) − t sin(φ + ω)) (M7), or `None` if
    /// the mechanism is not admissible: t > 0 and a positive denominator,
    /// β > 0 and β + φ + ω < 90° (M4).
    #[inline]
    pub fn at(&self, t: f64) -> Option<f64> {
        let denominator = self.cos_phi_w - t * self.sin_phi_w;
        if t > 0.0 && denominator > 0.0 {
            Some((t * self.cos_phi + self.sin_phi) / denominator)
        } else {
            None
        }
    }

    /// (sin φ, cos φ).
    #[inline]
    pub fn friction_sin_cos(&self) -> (f64, f64) {
        (self.sin_phi, self.cos_phi)
    }

    /// The denominator of Eq. (1) divided by cos β (positive iff admissible).
    #[inline]
    pub fn denominator(&self, t: f64) -> f64 {
        self.cos_phi_w - t * self.sin_phi_w
    }

    /// The cohesion term of the vertical-blade equation per unit c L
    /// (L the horizontal length of the block): c Ls cos φ / cos(β + φ + φw)
    /// with Ls = L / cos β, i.e. (1 + t²) cos φ / (cos(φ + φw) − t sin(φ + φw)),
    /// the c Ls cos φ term of (M8).
    #[inline]
    pub fn cohesion_at(&self, t: f64) -> f64 {
        (1.0 + t * t) * self.cos_phi / (self.cos_phi_w - t * self.sin_phi_w)
    }

    /// Whether W (P/W)(t) ≤ `bar` for an admissible t, division-free: false
    /// also where the mechanism is not admissible.
    #[inline]
    pub fn can_beat(&self, weight: f64, t: f64, bar: f64) -> bool {
        let denominator = self.cos_phi_w - t * self.sin_phi_w;
        denominator > 0.0 && weight * (t * self.cos_phi + self.sin_phi) <= bar * denominator
    }

    /// Whether the face friction that makes Eq. (1)'s denominator largest
    /// at tan β lies strictly between this factor's and `upper`'s (same φ,
    /// this one's ω the lesser): β + φ + ω = 0, where
    /// sin(β + φ + ω) / cos β = sin(φ + ω) + t cos(φ + ω) changes sign. Only
    /// a raked face's interval can hold it (ω ≥ −φw > −φ for a vertical one).
    #[inline]
    pub fn peak_between(&self, upper: &ForceFactor, t: f64) -> bool {
        self.sin_phi_w + t * self.cos_phi_w < 0.0 && upper.sin_phi_w + t * upper.cos_phi_w > 0.0
    }

    /// Whether W (P/W)(t) ≤ `bar` for some face friction ω between this
    /// factor's and `upper`'s, as a partially mobilised block may have
    /// (M41): P/W = N / D(ω), and the largest denominator
    /// D = cos(β + φ + ω) / cos β over the interval is at one of its ends,
    /// or 1 / cos β = √(1 + t²) where β + φ + ω = 0 lies inside.
    #[inline]
    pub fn can_beat_between(&self, upper: &ForceFactor, weight: f64, t: f64, bar: f64) -> bool {
        if self.peak_between(upper, t) {
            let n = weight * (t * self.cos_phi + self.sin_phi);
            n * n <= bar * bar * (1.0 + t * t)
        } else {
            self.can_beat(weight, t, bar) || upper.can_beat(weight, t, bar)
        }
    }

    /// The infimum of P / W over admissible β (β → 0): sin φ / cos(φ + φw).
    /// P / W grows with β and with φ, so this bounds every candidate: f_min
    /// of the stopping bound (M31) at the least φ.
    pub fn at_zero_angle(&self) -> f64 {
        self.sin_phi / self.cos_phi_w
    }
}

/// Eq. (1) coefficients on a grid of friction angles, for a cheap lower
/// bound: P/W grows with φ, so the entry at or below φ bounds it from below.
/// The grid is fine (0.01°, so that the bound is within about 0.05 % of
/// Eq. (1) and few candidates need the exact factor) and covers only the
/// friction angles the soil's law can take.
#[derive(Clone, Debug)]
pub struct FactorTable {
    /// Index of the first entry on the grid φ = k STEP.
    first: usize,
    /// (rising, sinking) at φ = (first + k) STEP.
    entries: Vec<(ForceFactor, ForceFactor)>,
}

impl FactorTable {
    const STEP: f64 = 0.01 * std::f64::consts::PI / 180.0;

    /// `walls`: the wall friction of Eq. (1) for a rising and a sinking
    /// block; `friction`: the least and largest friction angle of the law
    /// (radians).
    pub fn new(walls: (f64, f64), friction: (f64, f64)) -> Self {
        // One entry of margin below the least angle, for a mean of node
        // angles a rounding below it.
        let first = ((friction.0 / Self::STEP) as usize).saturating_sub(1);
        let last = (friction.1 / Self::STEP).ceil() as usize;
        let entries = (first..=last)
            .map(|k| {
                let phi = k as f64 * Self::STEP;
                (
                    ForceFactor::new(phi, walls.0),
                    ForceFactor::new(phi, walls.1),
                )
            })
            .collect();
        FactorTable { first, entries }
    }

    /// Factors no larger than Eq. (1) at any φ' ≥ `phi` (radians, at
    /// least the law's least angle less 0.01°): (with +φw, with −φw).
    #[inline]
    pub fn below(&self, phi: f64) -> &(ForceFactor, ForceFactor) {
        // A multiplication, not a division; shrunk by 1e-12 so that
        // rounding never takes the entry above φ.
        const BELOW: f64 = (1.0 - 1e-12) / FactorTable::STEP;
        let k = ((phi * BELOW) as usize)
            .saturating_sub(self.first)
            .min(self.entries.len() - 1);
        &self.entries[k]
    }
}

/// What the extended equation adds to the block's weight (`analytic` gives
/// it on flat ground), divided through by cos β:
/// P = [(W + q Lt) sin(β + φ) + c Ls cos φ − a Lb cos(α + β + φ)] / sin(α + β + φ + φw),
/// with Lt the block's top and Ls the slip line (horizontal lengths L of
/// the slip line, L + (y_b + d) cot α of the top) and Lb the face contact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Loads {
    /// q: surcharge pressure on the free surface.
    pub surcharge: f64,
    /// a Lb: adhesion times the face contact length.
    pub adhesion: f64,
    /// c: cohesion on the slip surface.
    pub cohesion: f64,
    /// (y_b + d) cot α: how far the block's top reaches behind the tip.
    pub face_run: f64,
    /// (sin, cos) of α − 90°.
    pub rake_offset: (f64, f64),
}

impl Loads {
    /// The loads of `case`'s blade whose face holds soil to `rise` above
    /// the tip (a face Lb = rise / sin α long, reaching rise cot α behind
    /// the tip; M8).
    pub fn at_face(case: &Case, rake: &Rake, rise: f64) -> Self {
        let sin_alpha = if case.blade.rake == 90.0 {
            1.0
        } else {
            case.blade.rake.to_radians().sin()
        };
        let offset = rake.offset;
        Loads {
            surcharge: case.soil.surcharge,
            adhesion: case.blade.adhesion * rise / sin_alpha,
            cohesion: case.soil.cohesion,
            face_run: rise * rake.cot,
            rake_offset: if offset == 0.0 {
                (0.0, 1.0)
            } else {
                offset.sin_cos()
            },
        }
    }

    /// P of a candidate of weight W whose slip line runs `length` ahead of
    /// the tip, at tan β: Eq. (1) with cohesion, adhesion and surcharge
    /// (M8), divided through by cos β. Each added term is ≥ 0 (adhesion: validated), so
    /// every bound on the weight alone stays a bound.
    #[inline]
    pub fn force(&self, factor: &ForceFactor, weight: f64, length: f64, t: f64) -> Option<f64> {
        let f = factor.at(t)?;
        let mut force = (weight + self.surcharge * (length + self.face_run)) * f;
        if self.cohesion > 0.0 {
            force += self.cohesion * length * factor.cohesion_at(t);
        }
        if self.adhesion > 0.0 {
            // −cos(α + β + φ) / cos β = t cos(φ + α − 90°) + sin(φ + α − 90°).
            let (sin_phi, cos_phi) = factor.friction_sin_cos();
            let (sin_d, cos_d) = self.rake_offset;
            let (sin_a, cos_a) = (
                sin_phi * cos_d + cos_phi * sin_d,
                cos_phi * cos_d - sin_phi * sin_d,
            );
            force += self.adhesion * (t * cos_a + sin_a) / factor.denominator(t);
        }
        Some(force)
    }

    /// A lower bound of `force` for every face friction between `lower`'s
    /// and `upper`'s (same φ): each term of (M8) is its own numerator over
    /// the same denominator D(ω), so the least is at the largest D, an
    /// end of the interval or √(1 + t²) (`ForceFactor::can_beat_between`).
    pub fn least_between(
        &self,
        (lower, upper): (&ForceFactor, &ForceFactor),
        weight: f64,
        length: f64,
        t: f64,
    ) -> Option<f64> {
        if !lower.peak_between(upper, t) {
            let ends = [
                self.force(lower, weight, length, t),
                self.force(upper, weight, length, t),
            ];
            return ends.into_iter().flatten().reduce(f64::min);
        }
        let (sin_phi, cos_phi) = lower.friction_sin_cos();
        let (sin_d, cos_d) = self.rake_offset;
        let (sin_a, cos_a) = (
            sin_phi * cos_d + cos_phi * sin_d,
            cos_phi * cos_d - sin_phi * sin_d,
        );
        let numerator = (weight + self.surcharge * (length + self.face_run))
            * (t * cos_phi + sin_phi)
            + self.cohesion * length * (1.0 + t * t) * cos_phi
            + self.adhesion * (t * cos_a + sin_a);
        Some(numerator / (1.0 + t * t).sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_form_equals_eq_1() {
        let (phi, phi_w) = (33f64.to_radians(), 12f64.to_radians());
        let f = ForceFactor::new(phi, phi_w);
        for beta_deg in [5.0, 20.0, 35.0, 44.0] {
            let beta = f64::to_radians(beta_deg);
            let tan_form = (beta + phi).tan() / (phi_w.cos() - phi_w.sin() * (beta + phi).tan());
            let sin_form = (beta + phi).sin() / (beta + phi + phi_w).cos();
            let ours = f.at(beta.tan()).unwrap();
            assert!((ours - tan_form).abs() < 1e-12 * tan_form);
            assert!((ours - sin_form).abs() < 1e-12 * sin_form);
        }
    }

    #[test]
    fn from_sin_cos_matches_new() {
        let (phi, w) = (31f64.to_radians(), -7f64.to_radians());
        let a = ForceFactor::new(phi, w);
        let b = ForceFactor::from_sin_cos(phi.sin_cos(), w.sin_cos());
        for t in [0.1, 0.5, 1.0] {
            let (x, y) = (a.at(t).unwrap(), b.at(t).unwrap());
            assert!((x - y).abs() < 1e-14 * x);
        }
    }

    #[test]
    fn table_bounds_from_below() {
        let w = 10f64.to_radians();
        let table = FactorTable::new((w, -w), (12f64.to_radians(), 45f64.to_radians()));
        // The law's extremes, a rounding below the least, beyond the largest.
        for deg in [12.0, 12.0 - 1e-12, 12.34, 20.0, 33.333, 44.99, 45.0, 47.0] {
            let phi = f64::to_radians(deg);
            for t in [0.05, 0.4, 0.7] {
                let Some(exact) = ForceFactor::new(phi, w).at(t) else {
                    continue; // β + φ + φw ≥ 90°: nothing to bound
                };
                let low = table.below(phi).0.at(t).unwrap();
                assert!(low <= exact, "{deg} {t}: {low} {exact}");
                // Tight away from β + φ + φw → 90°, where Eq. (1) blows up.
                if deg <= 45.0 && deg + t.atan().to_degrees() + 10.0 < 80.0 {
                    assert!(low > 0.999 * exact, "{deg} {t}: {low} {exact}");
                }
                let sinking = table.below(phi).1.at(t).unwrap();
                assert!(sinking <= low);
            }
        }
    }

    #[test]
    fn inadmissible_beyond_ninety_degrees() {
        let f = ForceFactor::new(30f64.to_radians(), 10f64.to_radians());
        assert!(f.at(49.9f64.to_radians().tan()).is_some());
        assert!(f.at(50.1f64.to_radians().tan()).is_none());
        assert!(f.at(0.0).is_none());
        assert!(f.at(-0.1).is_none());
    }
}
