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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::case::{AngleLaw, FaceFrictionRule};

    /// The least P/W of Eq. (1) over a grid of the band angles the law can
    /// give (φ and ψ each anywhere in its range, as a footprint's means
    /// are), tan β from 1e-8 to 10 and every climb of the path, each
    /// block with the face friction it mobilises (M9, M41).
    fn least_on_grid(laws: &Laws, climbs: &[f64]) -> f64 {
        let (friction, dilation) = (&laws.material.friction, &laws.material.dilation);
        let within =
            |(lo, hi): (f64, f64), k: usize, n: usize| lo + (hi - lo) * k as f64 / n as f64;
        let mut least = f64::INFINITY;
        for &climb in climbs {
            let face = laws.face.for_climb(climb);
            for i in 0..=5 {
                for j in 0..=10 {
                    let angles = BandAngles {
                        friction: within((friction.min(), friction.max()), i, 5),
                        dilation: within((dilation.min(), dilation.max()), j, 10),
                        shear: 0.0,
                        fresh: false,
                    };
                    for k in 0..=60 {
                        let t = 10f64.powf(-8.0 + 9.0 * k as f64 / 60.0);
                        if let Some(p) = laws.factor(angles, t, face).at(t) {
                            least = least.min(p);
                        }
                    }
                }
            }
        }
        least
    }

    /// The stopping bound's f_min (M31) is the infimum of P/W over every
    /// mechanism a run may try: no band on the grid lies below it, and the
    /// flattest band of the least φ comes within 0.1 % of it. A bound 1 %
    /// higher would end the scan before bands that can win; 1 % lower, it
    /// would scan ground no band can win on. Compacting and dilating soils,
    /// vertical and raked blades, both face-friction rules, a constant
    /// depth and a path that climbs.
    #[test]
    fn the_stopping_bound_is_the_infimum_of_eq_1() {
        let law = |initial, peak, residual| AngleLaw {
            initial,
            peak,
            residual,
        };
        let soils = [
            (law(20.0, 40.0, 30.0), law(-5.0, 10.0, 0.0)),
            (law(35.0, 35.0, 30.0), law(0.0, 5.0, 0.0)),
        ];
        let climbing = [[0.0, 20.0], [10.0, 16.0], [20.0, 16.0], [25.0, 20.0]];
        let paths: [&[[f64; 2]]; 2] = [&[], &climbing];
        for (friction, dilation) in soils {
            for rake in [90.0, 60.0, 45.0] {
                for path in paths {
                    for rule in [FaceFrictionRule::Mobilised, FaceFrictionRule::Sign] {
                        let mut case = crate::common::refined("fig5", 2.0, 50.0);
                        case.soil.friction = friction;
                        case.soil.dilation = dilation;
                        case.blade.rake = rake;
                        case.blade.depth_path = path.to_vec();
                        case.choices.face_friction = rule;
                        let laws = Laws::new(&case);
                        let climbs: Vec<f64> = match path {
                            [] => vec![0.0],
                            _ => path
                                .windows(2)
                                .map(|w| crate::case::climb(w[0], w[1]))
                                .collect(),
                        };
                        let ratio = least_on_grid(&laws, &climbs) / laws.min_factor;
                        let what = format!(
                            "φ {friction:?}, ψ {dilation:?}, α {rake}, {rule:?}, path {path:?}"
                        );
                        assert!(ratio >= 1.0 - 1e-12, "{what}: a band {ratio} of f_min");
                        assert!(
                            ratio <= 1.0 + 1e-3,
                            "{what}: the least band {ratio} of f_min"
                        );
                    }
                }
            }
        }
    }
}
