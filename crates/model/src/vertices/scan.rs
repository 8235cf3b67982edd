//! What the vertex ground's search reads besides the ground (`Scan`) and
//! what it chooses (`Pick`): the loads, the face, the band's width, the
//! search's spacings and reach, and Eq. (1) with the crescents of a blade
//! of finite width.

use super::strength::Columns;
use crate::crescent::{blade_force, bound_weight, Crescents, Fan};
use crate::face_friction::Face;
use crate::laws::{BandAngles, Laws};
use crate::mechanism::{ForceFactor, Loads};
use crate::rake::Rake;

/// What the search needs besides the ground.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scan<'a> {
    pub(crate) laws: &'a Laws,
    pub(crate) loads: Loads,
    pub(crate) face: Face,
    /// d, the tip's depth (length).
    pub(crate) depth: f64,
    /// dB (0: a slip line) (length).
    pub(crate) band_width: f64,
    /// Spacing of the first stage's samples along the ground (length).
    pub(crate) sample: f64,
    /// Whether the first stage samples flat bands coarser (M52,
    /// `search::far_spacing`) and crowded vertices not each (M54,
    /// `VertexSearch::crowded`): the sampled search (K > 0) of a band with
    /// a width.
    pub(crate) thins_samples: bool,
    /// h, `run.vertex_spacing` (length).
    pub(crate) vertex_spacing: f64,
    /// Width at which a local minimum's bracket stops narrowing (length).
    pub(crate) resolution: f64,
    /// v0: the block's advance in the increment (length).
    pub(crate) advance: f64,
    /// An emergence point this close to a vertex moves to it (length).
    pub(crate) snap: f64,
    /// Flat fresh ground appended when the scan reaches the end, up to
    /// `reach` (length).
    pub(crate) grow: f64,
    /// No emergence point at or beyond this x, where the ground stops
    /// growing (the end wall, else far ahead).
    pub(crate) reach: f64,
    /// The shear of a raked blade's coordinates (the ground is held in
    /// x' = x + (y + d) cot α, where the face is vertical; `Rake`).
    pub(crate) rake: Rake,
    /// The side crescents of a blade of finite width (`None`: plane
    /// strain); forces compared are then the blade's per unit width.
    pub(crate) crescents: Option<Crescents<'a>>,
    /// Whether the search compares the bands by their midpoint force
    /// (M51, `vertices::midpoint`) rather than the start's: the midpoint
    /// force where the soil never softens.
    pub(crate) choose_at_midpoint: bool,
    /// The band's strength from the columns it crosses (M53,
    /// `strength`); `None`: from its footprint, the paper's (M10, M17).
    pub(crate) columns: Option<Columns>,
}

impl Scan<'_> {
    /// The fans of a band emerging `rupture` ahead of the face.
    fn fan(&self, rupture: f64) -> Fan {
        Fan {
            rupture,
            depth: self.depth,
            cot_rake: self.rake.cot,
        }
    }

    /// P for a band of weight W and slip line of horizontal length L at
    /// tan β = `t`, emerging `rupture` ahead of the face in the ground's
    /// coordinates (`blade_force`: Eq. (1), and the crescents of a blade of
    /// finite width).
    pub(crate) fn force(
        &self,
        factor: &ForceFactor,
        geometry: (f64, f64, f64),
        rupture: f64,
    ) -> Option<f64> {
        let crescents = self.crescents.as_ref();
        blade_force(
            crescents,
            (&self.loads, factor),
            geometry,
            self.fan(rupture),
        )
    }

    /// The weight the bounds use for a band of weight W emerging `rupture`
    /// ahead of the face (`crescent::bound_weight`).
    pub(crate) fn bound_weight(&self, weight: f64, rupture: f64) -> f64 {
        bound_weight(self.crescents.as_ref(), weight, self.fan(rupture))
    }
}

/// The chosen mechanism.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pick {
    /// x_e, the emergence point.
    pub(crate) x: f64,
    /// y(x_e).
    pub(crate) y: f64,
    /// tan β, physical (Eq. (1), the motion).
    pub(crate) tan_beta: f64,
    /// tan β' = (y + d) / (x_e − x_0), the line's slope in the ground's
    /// coordinates (M34; tan β for a vertical blade).
    pub(crate) grid_slope: f64,
    /// The slip line's horizontal length, x_e − x_0 physically (length).
    pub(crate) length: f64,
    /// P (force per unit width).
    pub(crate) force: f64,
    /// The band's angles (radians).
    pub(crate) angles: BandAngles,
    /// W, the block's weight (force per unit width).
    pub(crate) weight: f64,
    /// x − L, the rear end of the band's footprint (x for a slip line).
    pub(crate) rear: f64,
}
