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

use crate::problem::{Ground, Soil};

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
    /// The option's word (`--strength`).
    pub fn name(self) -> &'static str {
        match self {
            Strength::Associated => "associated",
            Strength::Davis => "davis",
        }
    }

    /// The soil the bounds use for a soil of dilation `dilation_deg`.
    pub fn apply(self, soil: Soil, dilation_deg: f64) -> Soil {
        match self {
            Strength::Associated => soil,
            Strength::Davis => davis(soil, dilation_deg),
        }
    }
}

/// Which friction angle each column of the ground is given: the strength
/// field of the bounds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Field {
    /// Each column its own node's φ(ut) (docs/model.md §18.1).
    #[default]
    Columns,
    /// Each column at least as strong as the steepest piece of the surface
    /// at its node: φ = max(φ(ut), θ + [`SLOPE_MARGIN`]) with θ the larger
    /// of the two pieces' slopes, so that no surface is steeper than its
    /// soil's friction angle (beyond the paper; docs/model.md §18.5).
    Slope,
}

impl Field {
    /// The option's word (`--field`).
    pub fn name(self) -> &'static str {
        match self {
            Field::Columns => "columns",
            Field::Slope => "slope",
        }
    }
}

/// How much stronger than the slope it stands at [`Field::Slope`] makes a
/// column, degrees. A cohesionless slope at exactly its friction angle is
/// at limiting equilibrium: near the surface its stress field is unique
/// and at yield, and the interior-point solver does not find it (Fig. 5 at
/// u/d = 0.5 and 2, N = 8: NumericalError and AlmostPrimalInfeasible).
/// 0.01° suffices there; 0.1° keeps a margin and moves the bounds by 0.2 %.
pub const SLOPE_MARGIN: f64 = 0.1;

impl Field {
    /// Gives the columns of `ground` this field's friction angles (their
    /// own for [`Field::Columns`]).
    pub fn apply(self, ground: &mut Ground) {
        if self == Field::Slope {
            let slopes = node_slopes(&ground.x, &ground.y);
            for (s, theta) in ground.soil.iter_mut().zip(slopes) {
                s.friction_deg = s.friction_deg.max(theta + SLOPE_MARGIN);
            }
        }
    }
}

/// The steepest slope of the surface pieces meeting at each node of the
/// polyline (x, y), degrees (0 for a lone node).
pub fn node_slopes(x: &[f64], y: &[f64]) -> Vec<f64> {
    let piece = |i: usize| {
        ((y[i + 1] - y[i]) / (x[i + 1] - x[i]))
            .atan()
            .abs()
            .to_degrees()
    };
    (0..x.len())
        .map(|i| {
            let before = if i > 0 { piece(i - 1) } else { 0.0 };
            let after = if i + 1 < x.len() { piece(i) } else { 0.0 };
            before.max(after)
        })
        .collect()
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
