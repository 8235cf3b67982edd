//! Lower bounds of Eq. (1)'s force for pruning (speed without changing the
//! result, docs/model.md §2.8, §7.2): a candidate is evaluated in full
//! (footprint, band angles, Eq. (1)) only if a lower bound of its force
//! can beat the best so far. P/W grows with φ (as sin(α ± φw) > 0), so
//! before the footprint is known the bound is W (P/W)(β, φ_lo), φ_lo a
//! friction angle no greater than the band's; after it, Eq. (1) at the
//! band's friction angle rounded down on a grid (`FactorTable`). Both
//! tests are division-free. Both grounds' searches prune by them.

use crate::case::FaceFrictionRule;
use crate::face_friction::Face;
use crate::laws::{BandAngles, Laws};
use crate::mechanism::{ForceFactor, Loads};

/// Eq. (1) at a friction angle no greater than the band's: a lower bound
/// of P/W, with the face friction of a rising block above `sinking_below`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Lower {
    pub(crate) rising: ForceFactor,
    pub(crate) sinking: ForceFactor,
}

impl Lower {
    pub(crate) fn new(phi: f64, laws: &Laws) -> Self {
        Lower {
            rising: ForceFactor::new(phi, laws.face.walls.0),
            sinking: ForceFactor::new(phi, laws.face.walls.1),
        }
    }

    /// Whether W (P/W) ≤ `bar` at tan β for any face friction the block
    /// may have there. Eq. (1) grows with φ (as sin(α ± φw) > 0), but with
    /// the face friction only where α + β + φ + ω > 90°: for a vertical
    /// blade the sinking block's −φw is always the lesser, for a raked one
    /// either may be, so both are tried; a partly mobilised block's ω lies
    /// anywhere between them (M41), where the raked blade's denominator
    /// may peak (`ForceFactor::can_beat_between`).
    pub(crate) fn can_beat(&self, weight: f64, tan_beta: f64, bar: f64, face: &Face) -> bool {
        self.rising.can_beat(weight, tan_beta, bar)
            | (tan_beta <= face.sinking_below && self.sinking_can_beat(weight, tan_beta, bar, face))
    }

    /// The same below `sinking_below`, where the block need not rise.
    #[inline]
    fn sinking_can_beat(&self, weight: f64, tan_beta: f64, bar: f64, face: &Face) -> bool {
        match face.rule {
            FaceFrictionRule::Sign => self.sinking.can_beat(weight, tan_beta, bar),
            FaceFrictionRule::Mobilised => {
                self.sinking
                    .can_beat_between(&self.rising, weight, tan_beta, bar)
            }
        }
    }

    /// A lower bound of the force with the loads at tan β for any face
    /// friction the block may have below `sinking_below` (M8, M41).
    pub(crate) fn least_sinking(
        &self,
        (face, loads): (&Face, &Loads),
        weight: f64,
        length: f64,
        tan_beta: f64,
    ) -> Option<f64> {
        match face.rule {
            FaceFrictionRule::Sign => loads.force(&self.sinking, weight, length, tan_beta),
            FaceFrictionRule::Mobilised => {
                loads.least_between((&self.sinking, &self.rising), weight, length, tan_beta)
            }
        }
    }
}

/// The bound after the footprint: whether a line of weight W (as the
/// bounds take it) at tan β, with its band's angles known, may beat `bar`. Which face friction is the lesser depends on the
/// rake (see `Lower`). With the band's dilation known, a block that rises
/// fully (`Face::mobilisation`, taken only where it decides) has the rising
/// one in Eq. (1); one that does not, −φw (M9) or anything up to +φw (M41).
pub(crate) fn may_win(
    (laws, face): (&Laws, &Face),
    (weight, t): (f64, f64),
    angles: &BandAngles,
    bar: f64,
) -> bool {
    let (rising, sinking) = laws.table.below(angles.friction);
    rising.can_beat(weight, t, bar)
        || (t <= face.sinking_below
            && match face.rule {
                FaceFrictionRule::Sign => sinking.can_beat(weight, t, bar),
                FaceFrictionRule::Mobilised => sinking.can_beat_between(rising, weight, t, bar),
            }
            && face.mobilisation(t, angles.dilation) < 1.0)
}
