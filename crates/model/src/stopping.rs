//! The stopping bound's f_min (docs/model.md §7.2, (M31)): the infimum of
//! P/W over every mechanism a run may try. Along admissible candidates W
//! never decreases, so once W f_min exceeds the best force no later
//! candidate can win. P/W grows with β and φ at any face friction ω, so
//! f_min is sin φ / cos(φ + ω) at β → 0 for the least φ of the law and the
//! ω of largest cos(φ + ω) among those a block may have.

use crate::case::{Case, FaceFrictionRule};
use crate::face_friction::FaceFriction;
use crate::material::Material;
use crate::mechanism::ForceFactor;

/// f_min of (M31) for the case's soil and face.
/// The tip climbs at most `steepest_climb` per unit of travel
/// (`Case::steepest_climb`).
pub(crate) fn least_force_factor(
    case: &Case,
    material: &Material,
    face: &FaceFriction,
    steepest_climb: f64,
) -> f64 {
    let phi_min = material.friction.min();
    let at_zero = |wall: f64| ForceFactor::new(phi_min, wall).at_zero_angle();
    let walls = face.walls;
    match face.rule {
        // Where the block does not rise along the face (β + ψ ≤ 0 in
        // compaction, or a blade climbing faster than the block) the
        // friction acts upward on it (M9): ω is one of the two walls.
        FaceFrictionRule::Sign => {
            let climbs = steepest_climb > 0.0;
            if case.soil.dilation.min().to_radians() < 0.0 || climbs {
                at_zero(walls.0).min(at_zero(walls.1))
            } else {
                at_zero(walls.0)
            }
        }
        // ω anywhere between the least mobilisation's and +φw (M41).
        FaceFrictionRule::Mobilised => match face.least_angle(steepest_climb) {
            None => at_zero(walls.0),
            Some(lowest) => {
                let ends = at_zero(walls.0).min(at_zero(lowest));
                // cos(φ + ω) = 1 inside the interval.
                if phi_min + lowest < 0.0 && phi_min + walls.0 > 0.0 {
                    ends.min(phi_min.sin())
                } else {
                    ends
                }
            }
        },
    }
}
