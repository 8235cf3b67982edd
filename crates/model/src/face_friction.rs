//! The friction on the blade's face (docs/model.md §2.6): its direction
//! follows the block's motion relative to the face (M9), and under
//! `choices.face_friction = "mobilised"` its size follows the block's slip
//! along the face (M41), ω = m φw + (α − 90°) in Eq. (1).

use crate::case::{Case, FaceFrictionRule};
use crate::rake::Rake;
use crate::trig;

/// The slip along the face, per unit of blade travel, at which the face
/// friction is fully mobilised (M41): Coulomb friction is set-valued at
/// zero slip, and a least-force search over it takes the extreme (a
/// block that does not slip gets the full −φw of a sinking one); over this
/// small range it follows the slip continuously, so that the force is
/// continuous in β. 5 % of the blade's travel is a slip direction about
/// 3° from the face's (docs/model.md §2.6).
pub const SLIP_MOBILISATION: f64 = 0.05;

/// How the face moves in one increment, for the direction of its friction.
#[derive(Clone, Copy, Debug)]
pub struct Face {
    /// Rise of the tip per unit of travel: −Δd / v0 (0 at constant depth).
    pub climb: f64,
    /// tan β at and below which some band may have less than the full
    /// +φw of a block rising along the face.
    pub sinking_below: f64,
    /// The rule (`choices.face_friction`).
    pub rule: FaceFrictionRule,
    /// sin α of the face.
    pub rake_sin: f64,
    /// cot α of the face.
    pub rake_cot: f64,
}

impl Face {
    /// The share m ∈ [−1, 1] of the wall friction that a block on a band
    /// at tan β with dilation ψ mobilises, ω = m φw + (α − 90°) in Eq. (1):
    /// its sign is (M9), the block rising along the face where its
    /// direction β + ψ climbs faster than the tip, tan(β + ψ) > κ; under
    /// `Mobilised` it follows the block's slip along the face per unit of
    /// travel,
    /// s = (tan(β + ψ) − κ) / (sin α + tan(β + ψ) cos α),
    /// as m = clamp(s / s_m, −1, 1) (M41). Exactly ±1 outside the ramp,
    /// so that Eq. (1) takes the precomputed factors there.
    #[inline]
    pub fn mobilisation(&self, tan_beta: f64, dilation: f64) -> f64 {
        if tan_beta > self.sinking_below {
            return 1.0;
        }
        // tan(β + ψ) = rise / run; run ≤ 0 is β + ψ ≥ 90°, a block that
        // rises.
        let (sin_psi, cos_psi) = trig::sin_cos(dilation);
        let run = cos_psi - tan_beta * sin_psi;
        if run <= 0.0 {
            return 1.0;
        }
        let rise = tan_beta * cos_psi + sin_psi;
        match self.rule {
            // tan(β + ψ) > κ (M9), times run > 0.
            FaceFrictionRule::Sign => {
                if rise > self.climb * run {
                    1.0
                } else {
                    -1.0
                }
            }
            FaceFrictionRule::Mobilised => {
                // (M41) times run / sin α. across ≤ 0 is β + ψ ≤ −α (a
                // block going down more steeply than the face), which (M9)
                // takes as sinking (tan(β + ψ) < 0 = κ on a raked face).
                let across = run + rise * self.rake_cot;
                if across <= 0.0 {
                    return -1.0;
                }
                let slip = (rise - self.climb * run) / (self.rake_sin * across);
                (slip / SLIP_MOBILISATION).clamp(-1.0, 1.0)
            }
        }
    }
}

/// The face friction of a case: the wall friction, the rake and the rule,
/// from which each increment's `Face` and the ω of a mobilisation follow.
#[derive(Clone, Debug)]
pub(crate) struct FaceFriction {
    /// The wall friction of Eq. (1) for a block rising along the face and
    /// for one sinking: ±φw + (α − 90°) (`Rake`), radians.
    pub(crate) walls: (f64, f64),
    /// φw and α − 90° (radians), for a partially mobilised face friction.
    wall_friction: f64,
    rake_offset: f64,
    /// sin α, cot α.
    pub(crate) rake_sin: f64,
    pub(crate) rake_cot: f64,
    /// The face friction rule (`choices.face_friction`).
    pub(crate) rule: FaceFrictionRule,
    /// The least dilation angle of the law (radians): how far a band may
    /// sink.
    least_dilation: f64,
}

impl FaceFriction {
    pub(crate) fn new(case: &Case) -> Self {
        let wall_friction = case.blade.wall_friction.to_radians();
        let rake = Rake::new(case.blade.rake);
        let offset = rake.offset;
        FaceFriction {
            walls: (wall_friction + offset, -wall_friction + offset),
            wall_friction,
            rake_offset: offset,
            rake_sin: case.blade.rake.to_radians().sin(),
            rake_cot: rake.cot,
            rule: case.choices.face_friction,
            least_dilation: case.soil.dilation.min().to_radians(),
        }
    }

    /// ω for the least mobilisation any block of the run may have: at
    /// β → 0 with the least ψ and the fastest climb of the depth path,
    /// `climb_max` (`Case::steepest_climb`; s grows with β + ψ and falls
    /// with κ, (M41)), less a margin for the rounding of an increment's
    /// climb; `None` where every block mobilises the full +φw.
    pub(crate) fn least_angle(&self, climb_max: f64) -> Option<f64> {
        let tan_psi = self.least_dilation.tan();
        let across = 1.0 + tan_psi * self.rake_cot;
        let least = if across <= 0.0 {
            -1.0
        } else {
            let slip = (tan_psi - climb_max) / (self.rake_sin * across);
            (slip / SLIP_MOBILISATION - 1e-9).clamp(-1.0, 1.0)
        };
        (least < 1.0).then_some(least * self.wall_friction + self.rake_offset)
    }

    /// The face of an increment in which the tip climbs by `climb` per
    /// unit of travel (negative while the blade deepens).
    pub(crate) fn for_climb(&self, climb: f64) -> Face {
        // Some band has less than the full +φw where tan(β + ψ) is below
        // the edge for some ψ of the law: β ≤ atan(edge) − ψ_min. The edge
        // is κ under (M9); under (M41) s < s_m, i.e.
        // tan(β + ψ) < (κ + s_m sin α) / (1 − s_m cos α).
        let edge = match self.rule {
            FaceFrictionRule::Sign => climb.atan(),
            FaceFrictionRule::Mobilised => {
                let s = SLIP_MOBILISATION * self.rake_sin;
                ((climb + s) / (1.0 - s * self.rake_cot)).atan()
            }
        };
        let angle = edge - self.least_dilation;
        let sinking_below = if angle <= 0.0 {
            0.0
        } else if angle >= std::f64::consts::FRAC_PI_2 {
            f64::INFINITY
        } else {
            angle.tan()
        };
        Face {
            climb,
            sinking_below,
            rule: self.rule,
            rake_sin: self.rake_sin,
            rake_cot: self.rake_cot,
        }
    }

    /// ω, the face friction of Eq. (1) and of the force's direction (M12),
    /// for a mobilisation m: ±φw + (α − 90°) at m = ±1, m φw + (α − 90°)
    /// in between (M41).
    pub(crate) fn angle(&self, mobilisation: f64) -> f64 {
        if mobilisation == 1.0 {
            self.walls.0
        } else if mobilisation == -1.0 {
            self.walls.1
        } else {
            mobilisation * self.wall_friction + self.rake_offset
        }
    }
}
