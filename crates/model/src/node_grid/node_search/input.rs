//! What the search needs to know about the soil besides the surface.

use crate::crescent::{bound_weight, Crescents, Fan};
use crate::face_friction::Face;
use crate::laws::Laws;
use crate::mechanism::Loads;
use crate::rake::Rake;

/// The soil, blade and loads of one increment's search.
pub struct SearchInput<'a> {
    /// The material laws: the band-angle rule, Eq. (1), the stopping
    /// rule's f_min (M31) and the bounds' factor table.
    pub laws: &'a Laws,
    /// Node b of the blade face.
    pub blade: usize,
    /// d: depth of the blade tip during the increment.
    pub depth: f64,
    /// dB (0 for the original model's slip line).
    pub band_width: f64,
    /// How the face moves (§2.6 of docs/model.md): below
    /// `face.sinking_below` a block may sink relative to it, and the
    /// sinking face friction must be bounded too.
    pub face: Face,
    /// The shear of coordinates of a raked blade.
    pub rake: Rake,
    /// Nodes appended when the scan needs more domain.
    pub grow_nodes: usize,
    /// Loads beside the block's weight (all ≥ 0, so every bound on the
    /// weight alone stays a bound).
    pub loads: Loads,
    /// The side crescents of a blade of finite width (`None`: plane
    /// strain); forces compared are then the blade's per unit width.
    pub crescents: Option<Crescents<'a>>,
}

impl SearchInput<'_> {
    /// The weight the bounds use for a band of weight W emerging `rupture`
    /// ahead of the face: W, plus the crescents' least weight per unit
    /// width for a blade of finite width (`Crescents::weight_floor`).
    #[inline]
    pub fn bound_weight(&self, weight: f64, rupture: f64) -> f64 {
        let fan = Fan {
            rupture,
            depth: self.depth,
            cot_rake: self.rake.cot,
        };
        bound_weight(self.crescents.as_ref(), weight, fan)
    }
}
