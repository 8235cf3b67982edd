//! The strength a column is given in the bounds: its own (associated flow,
//! ψ = φ) or Davis's reduced strength for a non-associated soil.
//!
//! Davis (1968; Drescher & Detournay 1993, Sloan 2013): a soil with
//! friction φ, cohesion c and dilation ψ < φ is given, for a bound analysis
//! with associated flow, the reduced strength
//!
//! ```text
//! tan φ* = sin φ cos ψ / (1 − sin φ sin ψ),   c* = c cos φ cos ψ / (1 − sin φ sin ψ)   (D1)
//! ```
//!
//! (φ* = φ, c* = c where ψ = φ).

use crate::problem::Soil;

/// Which strength the bounds give the soil.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Strength {
    /// φ and c as they are, with associated flow: the bounds of the
    /// associated soil of the same strength.
    #[default]
    Associated,
    /// Davis's reduced φ*, c* (D1) from the column's dilation ψ.
    Davis,
}

impl Strength {
    /// The soil the bounds use for a soil of dilation `dilation_deg`.
    pub fn apply(self, soil: Soil, dilation_deg: f64) -> Soil {
        match self {
            Strength::Associated => soil,
            Strength::Davis => davis(soil, dilation_deg),
        }
    }
}

/// (D1), angles in degrees.
pub fn davis(soil: Soil, dilation_deg: f64) -> Soil {
    let (sin_phi, cos_phi) = soil.friction_deg.to_radians().sin_cos();
    let (sin_psi, cos_psi) = dilation_deg.to_radians().sin_cos();
    let eta = 1.0 - sin_phi * sin_psi;
    Soil {
        friction_deg: (sin_phi * cos_psi / eta).atan().to_degrees(),
        cohesion: soil.cohesion * cos_phi * cos_psi / eta,
        unit_weight: soil.unit_weight,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn davis_is_the_identity_for_associated_flow_and_weakens_otherwise() {
        let soil = Soil {
            friction_deg: 35.0,
            cohesion: 2.0,
            unit_weight: 1.0,
        };
        let same = davis(soil, 35.0);
        assert!((same.friction_deg - 35.0).abs() < 1e-12);
        assert!((same.cohesion - 2.0).abs() < 1e-12);
        // ψ = 0: tan φ* = sin φ.
        let zero = davis(soil, 0.0);
        let expected = 35f64.to_radians().sin().atan().to_degrees();
        assert!((zero.friction_deg - expected).abs() < 1e-12);
        assert!((zero.cohesion - 2.0 * 35f64.to_radians().cos()).abs() < 1e-12);
    }
}
