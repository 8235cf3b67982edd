//! The material laws as the search and the step use them: the band's
//! angles from its footprint (docs/model.md §2.7, (M10)), Eq. (1) for
//! them (paper Eq. (1), (M6), (M7)) with the face friction's sign (§2.6,
//! (M9)), and the stopping bound's f_min (M31).

use crate::case::{BandAngleRule, Case};
use crate::material::Material;
use crate::mechanism::{Face, FactorTable, ForceFactor};
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
        let offset = Rake::new(case.blade.rake).offset;
        let walls = (wall_friction + offset, -wall_friction + offset);
        let phi0 = material.friction.at(0.0);
        // Friction on the face opposes the block's motion relative to it:
        // where the block does not rise along the face (β + ψ ≤ 0 in
        // compaction, or a blade climbing faster than the block) it acts
        // upward on the block, the least-force choice at the threshold.
        let climbs = case.blade.depth_path.windows(2).any(|w| w[1][1] < w[0][1]);
        let can_sink = case.soil.dilation.min() < 0.0 || climbs;
        // The infimum of P/W (β → 0, least φ) over the face frictions the
        // block may have: which one is least depends on the rake. f_min of
        // the stopping bound (M31).
        let at_zero = |wall: f64| ForceFactor::new(material.friction.min(), wall).at_zero_angle();
        let min_factor = if can_sink {
            at_zero(walls.0).min(at_zero(walls.1))
        } else {
            at_zero(walls.0)
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
        }
    }

    /// The face of an increment in which the tip climbs by `climb` per
    /// unit of travel (negative while the blade deepens).
    pub(crate) fn face(&self, climb: f64) -> Face {
        // Some band sinks relative to the face where tan(β + ψ) ≤ climb for
        // some ψ of the law: β ≤ atan(climb) − ψ_min.
        let angle = climb.atan() - self.least_dilation;
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
        }
    }

    /// Eq. (1) coefficients for a candidate band at tan β.
    pub(crate) fn factor(&self, angles: BandAngles, tan_beta: f64, face: Face) -> ForceFactor {
        let rising = face.rises(tan_beta, angles.dilation);
        match (angles.fresh, rising) {
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
