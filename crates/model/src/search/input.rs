//! What the search needs to know about the soil besides the surface.

use super::angles::BandAngles;
use crate::mechanism::{Face, FactorTable, ForceFactor, Loads};
use crate::rake::Rake;

/// The soil, blade and loads of one increment's search.
pub struct SearchInput<'a, A, F>
where
    A: Fn(BandAngles) -> BandAngles,
    F: Fn(BandAngles, f64) -> ForceFactor,
{
    /// Node b of the blade face.
    pub blade: usize,
    /// d: depth of the blade tip during the increment.
    pub depth: f64,
    /// dB (0 for the original model's slip line).
    pub band_width: f64,
    /// Lower bound of P/W over every candidate (the stopping rule, (M31)).
    pub min_factor: f64,
    /// The wall friction in Eq. (1) for a rising and a sinking block (±φw,
    /// plus α − 90° for a raked blade), radians: for the bounds.
    pub walls: (f64, f64),
    /// How the face moves (§2.6 of docs/model.md): below
    /// `face.sinking_below` a block may sink relative to it, and the
    /// sinking face friction must be bounded too.
    pub face: Face,
    /// The shear of coordinates of a raked blade.
    pub rake: Rake,
    /// Band angles of undisturbed ground.
    pub fresh: BandAngles,
    /// Eq. (1) on a grid of friction angles (a lower bound before the
    /// exact factor).
    pub table: &'a FactorTable,
    /// The band's angles from the footprint means (the band-angle rule).
    pub angles: &'a A,
    /// Eq. (1) for a candidate's band angles at tan β.
    pub factor: &'a F,
    /// Nodes appended when the scan needs more domain.
    pub grow_nodes: usize,
    /// Loads beside the block's weight (all ≥ 0, so every bound on the
    /// weight alone stays a bound).
    pub loads: Loads,
}
