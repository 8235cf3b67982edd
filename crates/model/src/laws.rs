//! The material laws as the search and the step use them: the band's
//! angles from its footprint (docs/model.md §2.7, (M10)), Eq. (1) for
//! them (paper Eq. (1), (M6), (M7)) with the face friction's direction
//! and mobilisation (§2.6, (M9), (M41)), and the stopping bound's f_min
//! (M31).

use crate::case::{BandAngleRule, Case, FaceFrictionRule};
use crate::material::Material;
use crate::mechanism::{Face, FactorTable, ForceFactor, SLIP_MOBILISATION};
use crate::rake::Rake;
use crate::surface::Surface;
use crate::trig;

/// The band angles a candidate takes from its footprint (radians).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BandAngles {
    /// Mean of φ(ut_i) over the footprint.
    pub friction: f64,
    /// Mean of ψ(ut_i) over the footprint.
    pub dilation: f64,
    /// Mean of ut_i over the footprint.
    pub shear: f64,
    /// Every node of the footprint is unsheared (ut = 0).
    pub fresh: bool,
}

/// The material law with Eq. (1) coefficients cached for fresh soil.
#[derive(Clone, Debug)]
pub struct Laws {
    pub(crate) material: Material,
    /// The band-angle rule (`choices.band_angles`).
    rule: BandAngleRule,
    /// The wall friction of Eq. (1) for a block rising along the face and
    /// for one sinking: ±φw + (α − 90°) (`Rake`), radians.
    pub(crate) walls: (f64, f64),
    /// φw and α − 90° (radians), for a partially mobilised face friction.
    wall_friction: f64,
    rake_offset: f64,
    /// sin α, cot α.
    rake_sin: f64,
    rake_cot: f64,
    /// The face friction rule (`choices.face_friction`).
    face_rule: FaceFrictionRule,
    /// Fresh soil with the block rising along the face (+φw) and not (−φw).
    fresh_rising: ForceFactor,
    fresh_sinking: ForceFactor,
    /// Lower bound of P/W over every admissible mechanism.
    pub(crate) min_factor: f64,
    /// The least dilation angle of the law (radians): how far a band may
    /// sink.
    least_dilation: f64,
    /// (sin, cos) of the two walls.
    wall_sin_cos: ((f64, f64), (f64, f64)),
    /// Eq. (1) on a grid of friction angles, for the search's bounds.
    pub(crate) table: FactorTable,
    /// Band angles of undisturbed soil.
    pub(crate) fresh: BandAngles,
}

impl Laws {
    /// The laws of the case's soil and blade.
    pub(crate) fn new(case: &Case) -> Self {
        let material = Material::new(&case.soil);
        let wall_friction = case.blade.wall_friction.to_radians();
        let rake = Rake::new(case.blade.rake);
        let offset = rake.offset;
        let rake_sin = case.blade.rake.to_radians().sin();
        let walls = (wall_friction + offset, -wall_friction + offset);
        let phi0 = material.friction.at(0.0);
        let face_rule = case.choices.face_friction;
        // The infimum of P/W (β → 0, least φ) over the face frictions the
        // block may have: f_min of the stopping bound (M31). P/W grows with
        // β and φ at any ω, so it is sin φ / cos(φ + ω) at β → 0 for the
        // ω of largest cos(φ + ω).
        let phi_min = material.friction.min();
        let at_zero = |wall: f64| ForceFactor::new(phi_min, wall).at_zero_angle();
        let climbs = case.blade.depth_path.windows(2).any(|w| w[1][1] < w[0][1]);
        let psi_min = case.soil.dilation.min().to_radians();
        let min_factor = match face_rule {
            // Where the block does not rise along the face (β + ψ ≤ 0 in
            // compaction, or a blade climbing faster than the block) the
            // friction acts upward on it (M9): ω is one of the two walls.
            FaceFrictionRule::Sign => {
                if psi_min < 0.0 || climbs {
                    at_zero(walls.0).min(at_zero(walls.1))
                } else {
                    at_zero(walls.0)
                }
            }
            // The least mobilisation is at β → 0 with the least ψ and the
            // fastest climb (s grows with β + ψ and falls with κ, (M41)),
            // less a margin for the rounding of an increment's climb.
            FaceFrictionRule::Mobilised => {
                let climb_max = case
                    .blade
                    .depth_path
                    .windows(2)
                    .map(|w| (w[0][1] - w[1][1]) / (w[1][0] - w[0][0]))
                    .fold(0.0, f64::max);
                let tan_psi = psi_min.tan();
                let across = 1.0 + tan_psi * rake.cot;
                let least = if across <= 0.0 {
                    -1.0
                } else {
                    let slip = (tan_psi - climb_max) / (rake_sin * across);
                    (slip / SLIP_MOBILISATION - 1e-9).clamp(-1.0, 1.0)
                };
                if least >= 1.0 {
                    at_zero(walls.0)
                } else {
                    let lowest = least * wall_friction + offset;
                    let ends = at_zero(walls.0).min(at_zero(lowest));
                    // cos(φ + ω) = 1 inside the interval.
                    if phi_min + lowest < 0.0 && phi_min + walls.0 > 0.0 {
                        ends.min(phi_min.sin())
                    } else {
                        ends
                    }
                }
            }
        };
        Laws {
            fresh_rising: ForceFactor::new(phi0, walls.0),
            fresh_sinking: ForceFactor::new(phi0, walls.1),
            min_factor,
            least_dilation: case.soil.dilation.min().to_radians(),
            wall_sin_cos: (walls.0.sin_cos(), walls.1.sin_cos()),
            table: FactorTable::new(walls, (material.friction.min(), material.friction.max())),
            fresh: BandAngles {
                friction: phi0,
                dilation: material.dilation.at(0.0),
                shear: 0.0,
                fresh: true,
            },
            material,
            rule: case.choices.band_angles,
            walls,
            wall_friction,
            rake_offset: offset,
            rake_sin,
            rake_cot: rake.cot,
            face_rule,
        }
    }

    /// The face of an increment in which the tip climbs by `climb` per
    /// unit of travel (negative while the blade deepens).
    pub(crate) fn face(&self, climb: f64) -> Face {
        // Some band has less than the full +φw where tan(β + ψ) is below
        // the edge for some ψ of the law: β ≤ atan(edge) − ψ_min. The edge
        // is κ under (M9); under (M41) s < s_m, i.e.
        // tan(β + ψ) < (κ + s_m sin α) / (1 − s_m cos α).
        let edge = match self.face_rule {
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
            rule: self.face_rule,
            rake_sin: self.rake_sin,
            rake_cot: self.rake_cot,
        }
    }

    /// ω, the face friction of Eq. (1) and of the force's direction (M12),
    /// for a mobilisation m: ±φw + (α − 90°) at m = ±1, m φw + (α − 90°)
    /// in between (M41).
    pub(crate) fn face_angle(&self, mobilisation: f64) -> f64 {
        if mobilisation == 1.0 {
            self.walls.0
        } else if mobilisation == -1.0 {
            self.walls.1
        } else {
            mobilisation * self.wall_friction + self.rake_offset
        }
    }

    /// Eq. (1) coefficients for a candidate band at tan β, with the face
    /// friction its block mobilises (M9, M41).
    pub(crate) fn factor(&self, angles: BandAngles, tan_beta: f64, face: Face) -> ForceFactor {
        let m = face.mobilisation(tan_beta, angles.dilation);
        if m != 1.0 && m != -1.0 {
            // Partly mobilised: rare, so computed here.
            return ForceFactor::new(angles.friction, self.face_angle(m));
        }
        match (angles.fresh, m == 1.0) {
            (true, true) => self.fresh_rising,
            (true, false) => self.fresh_sinking,
            (false, rising) => {
                let wall = if rising {
                    self.wall_sin_cos.0
                } else {
                    self.wall_sin_cos.1
                };
                ForceFactor::from_sin_cos(trig::sin_cos(angles.friction), wall)
            }
        }
    }

    /// The band-angle rule: mean of the node angles (M10), or angles of the
    /// mean accumulated shear.
    pub(crate) fn band_angles(&self, means: BandAngles) -> BandAngles {
        match self.rule {
            BandAngleRule::MeanOfAngles => means,
            BandAngleRule::AngleOfMeanShear => BandAngles {
                friction: self.material.friction.at(means.shear),
                dilation: self.material.dilation.at(means.shear),
                ..means
            },
        }
    }

    /// Recomputes φ(ut) and ψ(ut) of the nodes in `range`.
    pub(crate) fn refresh_angles(&self, surface: &mut Surface, range: std::ops::Range<usize>) {
        for i in range {
            let ut = surface.accumulated_shear[i];
            surface.friction[i] = self.material.friction.at(ut);
            surface.dilation[i] = self.material.dilation.at(ut);
        }
    }
}
