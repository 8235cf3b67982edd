//! The midpoint force (M51; `run.time_scheme = "midpoint-force"`,
//! docs/model.md §2.12): the band the search chose at the start of the increment keeps its
//! geometry and weight, and takes its strength from the state half an
//! increment on.
//!
//! Over an increment the band's soil shears by Δut (M18), and in
//! softening soil its strength falls as it does; the explicit rule takes
//! φ(ut), ψ(ut) at the start, an error of first order in v0. Here the
//! band's angles are the means over its footprint [x − L, x] of
//! φ(ut_i + ½ Δut) and ψ(ut_i + ½ Δut) (M10 at the midpoint state), and
//! P is Eq. (1) with them at the band's β and W. The search's choice is
//! not redone: the band is the one that was least at the start.
//!
//! A band whose footprint holds only fresh soil keeps the explicit force,
//! so that the first increment is Coulomb's wedge at φ0 (M13), as every
//! scheme's must be (§9): a band emerging in fresh soil has not yet
//! softened it.
//!
//! Where the soil never softens (φ never falls with ut), the band's
//! strength rises over the increment, and the band least at the start can
//! pass another before the increment ends: the search then compares every
//! band by its midpoint force (`Scan::choose_at_midpoint`, M51a). Its
//! bounds stay valid, since P rises with φ (Eq. (1)) and each band's
//! midpoint force is then at least its start force, which they bound.
//! Where the soil softens the search chooses at the start, as the paper's
//! explicit rule does.

use super::scan::{Pick, Scan};
use super::strength::Columns;
use super::Vertices;
use crate::band::BandMotion;
use crate::laws::BandAngles;

/// ½ Δut, the half of the increment's slip that the midpoint state takes
/// (M18, M36; a slip line's M15 where dB = 0 or β + ψ ≥ 90°), as the
/// motion of `pick` will shear its band.
pub(crate) fn half_slip(scan: &Scan, pick: &Pick) -> f64 {
    let band = (pick.grid_slope, pick.tan_beta, pick.angles.dilation);
    let (motion, _) = BandMotion::of(scan.band_width > 0.0, band, &scan.rake, scan.advance);
    0.5 * motion.slip
}

/// `pick` with its force and angles on the midpoint state of its footprint
/// (M51),
/// every piece of which shears by `half_slip` = ½ Δut; `pick` itself if its
/// footprint is fresh, or if Eq. (1) has no solution there.
pub(crate) fn midpoint_force(ground: &Vertices, scan: &Scan, pick: Pick, half_slip: f64) -> Pick {
    if pick.angles.fresh {
        return pick;
    }
    let means = match scan.columns {
        None => footprint_means(ground, scan, &pick, half_slip),
        Some(columns) => crossed_means(ground, (scan, &columns), &pick, half_slip),
    };
    let angles = scan.laws.band_angles(means);
    let factor = scan.laws.factor(angles, pick.tan_beta, scan.face);
    let geometry = (pick.weight, pick.length, pick.tan_beta);
    match scan.force(&factor, geometry, pick.x - ground.x[0]) {
        Some(force) => Pick {
            force,
            angles,
            ..pick
        },
        None => pick,
    }
}

/// The crossed columns' means (M53) half an increment on: the start's,
/// `pick.angles`, over [x_0, x], with the columns of the footprint
/// [x − L, x], the band's soil that the motion shears (M22), at
/// ut + `half_slip` (φ̂ floored as at the start: the band keeps its
/// geometry); the columns the band crosses below its footprint are not
/// sheared by the increment and keep their state. A slip line's footprint
/// is a point: its means are the start's.
fn crossed_means(
    ground: &Vertices,
    (scan, columns): (&Scan, &Columns),
    pick: &Pick,
    half_slip: f64,
) -> BandAngles {
    let material = &scan.laws.material;
    let at = |k: usize, ut: f64| {
        let phi = columns.friction(ground, k, material.friction.at(ut));
        [phi, material.dilation.at(ut), ut]
    };
    let start = &pick.angles;
    let mut means = [start.friction, start.dilation, start.shear];
    let run = pick.x - ground.x[0];
    let last = ground.piece_at(pick.x);
    if pick.rear < pick.x {
        for k in ground.piece_at(pick.rear).min(last)..=last {
            let overlap = ground.x[k + 1].min(pick.x) - ground.x[k].max(pick.rear);
            if overlap > 0.0 {
                let ut = ground.accumulated_shear[k];
                let (now, mid) = (at(k, ut), at(k, ut + half_slip));
                for (i, mean) in means.iter_mut().enumerate() {
                    *mean += (mid[i] - now[i]) * overlap / run;
                }
            }
        }
    }
    BandAngles {
        friction: means[0],
        dilation: means[1],
        shear: means[2],
        fresh: false,
    }
}

/// Means of φ, ψ and ut over [x − L, x] at ut + `half_slip` (M10): the
/// integral of piecewise constant state, piece by piece, since φ(ut + s)
/// is not a shift of the prefix sums. A slip line's, whose footprint is a
/// point, are the emergence piece's.
fn footprint_means(ground: &Vertices, scan: &Scan, pick: &Pick, half_slip: f64) -> BandAngles {
    let material = &scan.laws.material;
    let at = |k: usize| {
        let ut = ground.accumulated_shear[k] + half_slip;
        [material.friction.at(ut), material.dilation.at(ut), ut]
    };
    let last = ground.piece_at(pick.x);
    let means = if pick.rear >= pick.x {
        at(last)
    } else {
        let mut sums = [0.0; 3];
        for k in ground.piece_at(pick.rear).min(last)..=last {
            let overlap = ground.x[k + 1].min(pick.x) - ground.x[k].max(pick.rear);
            if overlap > 0.0 {
                let state = at(k);
                for (sum, value) in sums.iter_mut().zip(state) {
                    *sum += value * overlap;
                }
            }
        }
        sums.map(|sum| sum / (pick.x - pick.rear))
    };
    BandAngles {
        friction: means[0],
        dilation: means[1],
        shear: means[2],
        fresh: false,
    }
}
