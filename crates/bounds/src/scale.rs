//! The programs are solved in units where the face's height h is 1 and the
//! problem's largest stress scale S = max(γ h, c, a, q) is 1, so that the
//! solver's tolerances mean the same for millimetres and metres. Forces
//! scale back by S h, stresses by S, lengths by h.

use crate::problem::{Ground, Problem, Soil};

/// The scales of a problem: its face height h, stress S and tip (x_A, y_A).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// h, length scale.
    pub length: f64,
    /// S, stress scale.
    pub stress: f64,
    /// The tip, the origin of the scaled coordinates.
    pub origin: [f64; 2],
}

impl Scale {
    /// The scales of a validated problem.
    pub fn of(p: &Problem) -> Scale {
        let h = p.face_height();
        let soils = p.ground.soil.iter().chain(std::iter::once(&p.below));
        let mut s = p.surcharge.max(p.face.adhesion);
        for soil in soils {
            s = s.max(soil.unit_weight * h).max(soil.cohesion);
        }
        Scale {
            length: h,
            stress: if s > 0.0 { s } else { 1.0 },
            origin: [p.face.tip_x, p.face.tip_y],
        }
    }

    fn soil(&self, s: &Soil) -> Soil {
        Soil {
            friction_deg: s.friction_deg,
            cohesion: s.cohesion / self.stress,
            unit_weight: s.unit_weight * self.length / self.stress,
        }
    }

    /// The problem in scaled units: tip at the origin, h = 1, S = 1.
    pub fn problem(&self, p: &Problem) -> Problem {
        let h = self.length;
        let mut q = p.clone();
        q.face.tip_x = 0.0;
        q.face.tip_y = 0.0;
        q.face.adhesion /= self.stress;
        q.surcharge /= self.stress;
        q.below = self.soil(&p.below);
        q.ground = Ground {
            x: p.ground
                .x
                .iter()
                .map(|x| (x - self.origin[0]) / h)
                .collect(),
            y: p.ground
                .y
                .iter()
                .map(|y| (y - self.origin[1]) / h)
                .collect(),
            soil: p.ground.soil.iter().map(|s| self.soil(s)).collect(),
        };
        q
    }

    /// A scaled point back in the problem's coordinates.
    pub fn point(&self, p: [f64; 2]) -> [f64; 2] {
        [
            self.origin[0] + p[0] * self.length,
            self.origin[1] + p[1] * self.length,
        ]
    }
}
