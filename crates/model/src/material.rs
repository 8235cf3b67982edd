//! The material law: friction and dilation angles as functions of the
//! accumulated shearing displacement ut (paper Fig. 2).
//!
//! Piecewise linear in ut: `initial` at ut = 0, `peak` at ut = up,
//! `residual` from ut = ur on. The original model (Fig. 2a) is the special
//! case up = 0 with `initial == peak` (softening only); up = 0 in general
//! means the law starts at its peak.

use crate::case::{AngleLaw, Soil};

/// Hardening-softening law of one angle, in radians inside.
#[derive(Clone, Copy, Debug)]
pub struct PiecewiseLaw {
    initial: f64,
    peak: f64,
    residual: f64,
    peak_shear: f64,
    residual_shear: f64,
}

impl PiecewiseLaw {
    /// The law through `angles_deg` (degrees) at ut = 0, `peak_shear` (up)
    /// and `residual_shear` (ur), lengths; up = ur softens at once.
    pub fn new(angles_deg: AngleLaw, peak_shear: f64, residual_shear: f64) -> Self {
        PiecewiseLaw {
            initial: angles_deg.initial.to_radians(),
            peak: angles_deg.peak.to_radians(),
            residual: angles_deg.residual.to_radians(),
            peak_shear,
            residual_shear,
        }
    }

    /// The angle (radians) at accumulated shear `ut` (Fig. 2b-c): linear
    /// from `initial` to `peak` over [0, up), from `peak` to `residual` over
    /// [up, ur), `residual` beyond (M23).
    pub fn at(&self, ut: f64) -> f64 {
        if ut < self.peak_shear {
            self.initial + (self.peak - self.initial) * ut / self.peak_shear
        } else if ut < self.residual_shear {
            let s = (ut - self.peak_shear) / (self.residual_shear - self.peak_shear);
            self.peak + (self.residual - self.peak) * s
        } else {
            self.residual
        }
    }

    /// The smallest angle the law can take (radians).
    pub fn min(&self) -> f64 {
        self.initial.min(self.peak).min(self.residual)
    }

    /// The largest angle the law can take (radians).
    pub fn max(&self) -> f64 {
        self.initial.max(self.peak).max(self.residual)
    }
}

/// Friction and dilation laws of one soil.
#[derive(Clone, Copy, Debug)]
pub struct Material {
    /// φ(ut) (paper Fig. 2a-b).
    pub friction: PiecewiseLaw,
    /// ψ(ut) (paper Fig. 2c).
    pub dilation: PiecewiseLaw,
}

impl Material {
    /// The laws of `soil`: φc → φp → φr and ψc → ψp → ψr over up, ur.
    pub fn new(soil: &Soil) -> Self {
        Material {
            friction: PiecewiseLaw::new(soil.friction, soil.peak_shear, soil.residual_shear),
            dilation: PiecewiseLaw::new(soil.dilation, soil.peak_shear, soil.residual_shear),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(up: f64, ur: f64) -> PiecewiseLaw {
        PiecewiseLaw::new(
            AngleLaw {
                initial: 20.0,
                peak: 40.0,
                residual: 30.0,
            },
            up,
            ur,
        )
    }

    #[test]
    fn hardening_then_softening_hits_its_corners() {
        let l = law(2.0, 4.0);
        assert!((l.at(0.0).to_degrees() - 20.0).abs() < 1e-12);
        assert!((l.at(1.0).to_degrees() - 30.0).abs() < 1e-12);
        assert!((l.at(2.0).to_degrees() - 40.0).abs() < 1e-12);
        assert!((l.at(3.0).to_degrees() - 35.0).abs() < 1e-12);
        assert!((l.at(4.0).to_degrees() - 30.0).abs() < 1e-12);
        assert!((l.at(40.0).to_degrees() - 30.0).abs() < 1e-12);
    }

    #[test]
    fn zero_peak_shear_starts_at_peak() {
        let l = law(0.0, 4.0);
        assert!((l.at(0.0).to_degrees() - 40.0).abs() < 1e-12);
        assert!((l.at(2.0).to_degrees() - 35.0).abs() < 1e-12);
    }

    #[test]
    fn instant_softening_when_residual_shear_equals_peak_shear() {
        let l = law(1.0, 1.0);
        assert!((l.at(0.5).to_degrees() - 30.0).abs() < 1e-12);
        assert!(l.at(1.0 - 1e-9).to_degrees() > 39.9);
        assert!((l.at(1.0).to_degrees() - 30.0).abs() < 1e-12);
        assert!((l.min().to_degrees() - 20.0).abs() < 1e-12);
    }
}
