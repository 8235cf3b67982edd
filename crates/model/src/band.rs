//! The shear band of the refined model (paper Fig. 3a; docs/model.md
//! §3.2-§3.3), whatever the ground: its lower boundary is the line from
//! the blade tip to the emergence point, its upper boundary parallel, dB
//! above it (normal distance), i.e. e = dB / cos β above it vertically. A
//! point whose height above the lower boundary is z lies at relative
//! position g = z / e in the band: g ≥ 1 is the rigid block, 0 < g < 1 the
//! band, g = 0 the lower boundary. The original model is the limit dB = 0
//! (a slip line). Here: how the band moves the block (M18, M35, M36), the
//! raked blade's stretch of its thickness (M16), and the dilation under
//! the block (M26). The node grid's band of nodes is `grid::Band`, the
//! vertex ground's motion `vertices::motion`.

use crate::rake::Rake;

/// grid slope / tan β, the grid's horizontal stretch of a raked blade, by
/// which the band's vertical thickness on the grid grows (M16); 1 for a
/// vertical blade, taken without a division (x / x = 1 exactly).
#[inline]
pub(crate) fn stretch(grid_slope: f64, tan_beta: f64) -> f64 {
    if grid_slope == tan_beta && tan_beta > 0.0 {
        1.0
    } else {
        grid_slope / tan_beta
    }
}

/// The motion of the band's block: rise v0 tan(β + ψ) on the grid, slip
/// Δut = λ cos ψ with λ = v0 sin α / sin(α + β + ψ) (`Rake`); `None` where
/// β + ψ ≥ 90°.
/// The node grid's update and the vertex ground's (`vertices::motion`) both
/// move the soil by it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BandMotion {
    pub(crate) rise: f64,
    pub(crate) slip: f64,
    pub(crate) tan_psi: f64,
}

impl BandMotion {
    /// The band's motion (M35): the block moves by λ (cos θ, sin θ), θ = β + ψ,
    /// which on the grid is (v0, v0 tan θ'), a rise of v0 tan θ'; its slip
    /// Δut = v0 cos ψ √(1 + tan² θ) / (1 + cot α tan θ) (M36), for a vertical
    /// blade Δut = v0 cos ψ / cos(β + ψ) with Δuv = Δut tan ψ (M18).
    pub(crate) fn new((t, psi): (f64, f64), rake: &Rake, dx: f64) -> Option<Self> {
        let tan_psi = psi.tan();
        let run = 1.0 - t * tan_psi;
        if run <= 0.0 {
            return None;
        }
        let rho = (t + tan_psi) / run;
        Some(BandMotion {
            rise: dx * rake.grid(rho),
            slip: dx * psi.cos() * (1.0 + rho * rho).sqrt() / (1.0 + rake.cot * rho),
            tan_psi,
        })
    }

    /// The motion of a band of width dB > 0 (`banded`) at (tan β', tan β)
    /// with dilation ψ (M35), or, where dB = 0 or β + ψ ≥ 90°, its slip
    /// line's (M15); with whether it is the band's. The increment moves the
    /// soil by it, and the midpoint force takes half its slip.
    pub(crate) fn of(
        banded: bool,
        (grid_slope, t, psi): (f64, f64, f64),
        rake: &Rake,
        dx: f64,
    ) -> (Self, bool) {
        match Self::new((t, psi), rake, dx) {
            Some(motion) if banded => (motion, true),
            _ => (Self::slip_line((grid_slope, t), rake, dx), false),
        }
    }

    /// The slip line's motion: the block slides along it, rise v0 tan β
    /// on the grid, Δut = v0 / cos β (M15; `Rake` for a raked blade, M36).
    pub(crate) fn slip_line((grid_slope, t): (f64, f64), rake: &Rake, v0: f64) -> Self {
        BandMotion {
            rise: v0 * grid_slope,
            slip: v0 * (1.0 + t * t).sqrt() / (1.0 + rake.cot * t),
            tan_psi: 0.0,
        }
    }
}

/// The band's dilation under the block in one increment, as a height: its
/// normal opening Δut tan ψ over cos β (M26), on a raked blade's sheared
/// coordinates times M16's stretch tan β' / tan β (the line of slope
/// (`grid_slope`, `tan_beta`); for a vertical blade rise − v0 tan β,
/// (M18), and on the grid rise' − v0 tan β'). A column of the block holds
/// the band's full thickness, so this much of it is volume the band
/// gained, not soil the block brought; weighed at the block's γ, the
/// band's pieces at the emergence point (M27) paid for it and a band that
/// stays for many increments fell below zero weight (issue 38).
pub(crate) fn dilation_gap(slip: f64, tan_psi: f64, (grid_slope, tan_beta): (f64, f64)) -> f64 {
    slip * tan_psi * (1.0 + tan_beta * tan_beta).sqrt() * stretch(grid_slope, tan_beta)
}
