//! The band's strength from the columns it crosses (M53;
//! `choices.band_strength = "crossed-columns"`, docs/model.md §20): beyond
//! the paper, whose rule (M10, M17) takes the band's φ, ψ from its
//! footprint near the emergence point.
//!
//! The vertex ground's pieces are columns of soil that move with it, each
//! with its own ut. A straight band from the tip to its emergence point x
//! crosses every column between the face x_0 and x, for a length of band
//! Δx / cos β' in each: its angles are the means over those columns
//! weighted by that length,
//!
//!   φ_band = (1 / (x − x_0)) ∫ φ̂ dx,  ψ_band = (1 / (x − x_0)) ∫ ψ(ut) dx,
//!   φ̂_k = max(φ(ut_k), min(θ_k, θr))                                 (M53)
//!
//! with θ_k the angle piece k's surface stands at, physically: its slope
//! s'_k in the ground's coordinates is s'_k / (1 − s'_k cot α) in the
//! blade's plane (the shear `Rake`; 90° where that is not positive), and
//! |atan| of it. A column standing steeper than φ(ut) is statically
//! admissible only if its soil is at least that strong (an infinite slope
//! at θ needs tan φ ≥ tan θ), so its strength is taken no lower; never
//! above the repose θr, the steepest slope the avalanche (M29) leaves.
//! ψ is not floored: the floor is a statement of strength, not of the
//! soil's volume change. Where the soil's law does not reach θ on a
//! slope, e.g. the pile at the repose, the column's strength is the
//! slope's. These are the prefix integrals of the search (M49) with φ̂
//! for φ: no cost beyond the footprint's.

use super::Vertices;
use crate::rake::Rake;

/// The floor of a column's friction angle (M53).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Columns {
    /// θr (radians): no column's floor above it.
    repose: f64,
    /// The shear of a raked blade's coordinates.
    rake: Rake,
}

impl Columns {
    /// `repose` θr in degrees: the floor's cap (0: no floor,
    /// `"crossed-columns-unfloored"`).
    pub(crate) fn new(repose: f64, rake: Rake) -> Self {
        Columns {
            repose: repose.to_radians(),
            rake,
        }
    }

    /// θ_k: the angle piece k's surface stands at in the blade's plane
    /// (radians), at most θr (M53).
    pub(crate) fn standing(&self, ground: &Vertices, k: usize) -> f64 {
        let grid = (ground.y[k + 1] - ground.y[k]) / (ground.x[k + 1] - ground.x[k]);
        let run = 1.0 - grid * self.rake.cot;
        if run <= 0.0 {
            return self.repose;
        }
        (grid / run).abs().atan().min(self.repose)
    }

    /// φ̂_k = max(φ(ut_k), min(θ_k, θr)) (M53), `phi` = φ(ut_k) of piece k.
    pub(crate) fn friction(&self, ground: &Vertices, k: usize, phi: f64) -> f64 {
        phi.max(self.standing(ground, k))
    }
}
