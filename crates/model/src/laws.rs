//! The material laws as the search and the step use them: the band's
//! angles from its footprint (docs/model.md §2.7, (M10)) and Eq. (1) for
//! them (paper Eq. (1), (M6), (M7)), with the face friction of
//! `face_friction` (§2.6, (M9), (M41)) and the stopping bound's f_min of
//! `stopping` (M31).

use crate::case::{BandAngleRule, Case};
use crate::face_friction::{Face, FaceFriction};
use crate::material::Material;
use crate::mechanism::{FactorTable, ForceFactor};
use crate::stopping::least_force_factor;
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
    /// The face friction (M9, M41): each increment's `Face`, ω.
    pub(crate) face: FaceFriction,
    /// Fresh soil with the block rising along the face (+φw) and not (−φw).
    fresh_rising: ForceFactor,
    fresh_sinking: ForceFactor,
    /// Lower bound of P/W over every admissible mechanism.
    pub(crate) min_factor: f64,
    /// `Case::steepest_climb` of the case they were made for: the bounds
    /// (`min_factor`, the face's least mobilisation) hold for climbs up to
    /// it, and a tip steered to climb faster needs new laws.
    pub(crate) steepest_climb: f64,
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
        let face = FaceFriction::new(case);
        let walls = face.walls;
        let phi0 = material.friction.at(0.0);
        let steepest_climb = case.steepest_climb();
        Laws {
            fresh_rising: ForceFactor::new(phi0, walls.0),
            fresh_sinking: ForceFactor::new(phi0, walls.1),
            min_factor: least_force_factor(case, &material, &face, steepest_climb),
            steepest_climb,
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
            face,
        }
    }

    /// The laws of `case` for a tip that climbs up to `climb` per unit of
    /// travel, faster than any climb they were made for (a steered tip):
    /// the stopping bound made for it.
    pub(crate) fn climbing(&mut self, case: &Case, climb: f64) {
        self.steepest_climb = climb;
        self.min_factor = least_force_factor(case, &self.material, &self.face, climb);
    }

    /// Eq. (1) coefficients for a candidate band at tan β, with the face
    /// friction its block mobilises (M9, M41).
    pub(crate) fn factor(&self, angles: BandAngles, tan_beta: f64, face: Face) -> ForceFactor {
        let m = face.mobilisation(tan_beta, angles.dilation);
        if m != 1.0 && m != -1.0 {
            // Partly mobilised: rare, so computed here.
            return ForceFactor::new(angles.friction, self.face.angle(m));
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
