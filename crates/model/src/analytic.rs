//! Analytical baselines for the initial flat ground: the forces that users
//! of earthmoving models already know, to set beside the simulation.
//!
//! **Trial wedge** (Coulomb; Reece's Fundamental Earthmoving Equation with
//! McKyes' factors). A blade of rake α (the face's angle from the horizontal
//! on the soil side, 90° vertical) with its tip at depth d below flat ground
//! pushes a wedge bounded by the face and a plane failure surface at β. With
//! the wedge's weight W = ½ γ d² (cot α + cot β), its top d (cot α + cot β)
//! carrying a surcharge q, the failure surface of length Ls = d / sin β with
//! cohesion c, the face contact of length Lb = d / sin α with adhesion a, the
//! face reaction inclined at φw to its normal (the wedge slides up the face)
//! and the failure-surface reaction at φ to its normal, equilibrium gives
//!
//! ```text
//! P = [(W + Q) sin(β + φ) + c Ls cos φ − a Lb cos(α + β + φ)] / sin(α + β + φ + φw)
//!   = γ d² Nγ + c d Nc + a d Na + q d Nq
//! Nγ = (cot α + cot β) sin(β + φ) / (2 sin(α + β + φ + φw))
//! Nq = (cot α + cot β) sin(β + φ) / sin(α + β + φ + φw)
//! Nc = cos φ / (sin β sin(α + β + φ + φw))
//! Na = −cos(α + β + φ) / (sin α sin(α + β + φ + φw))
//! ```
//!
//! (derivation: resolve the forces on the wedge along the failure surface's
//! normal-and-friction direction, which eliminates its reaction). For α = 90°,
//! c = a = q = 0 this is the paper's Eq. (1) with the wedge's weight, and its
//! minimum over β is Coulomb's passive force ½ γ d² Kp. The failure angle is
//! the β of least force.
//!
//! **Rankine** passive pressure on a smooth vertical wall:
//! P = ½ γ d² Kp + 2 c d √Kp + q d Kp, Kp = tan²(45° + φ/2), failure planes
//! at 45° − φ/2.
//!
//! Forces are per unit width. The face reaction on the soil is inclined at
//! φw from the face normal, so its horizontal (draft) component is
//! P sin(α + φw) and the vertical component of the soil's force on the blade
//! (positive upward) is −P cos(α + φw).

mod mckyes_ali;
pub use mckyes_ali::Narrow;

/// A wedge problem on flat ground; angles in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wedge {
    /// γ: unit weight (force per length³).
    pub unit_weight: f64,
    /// d: depth of the blade tip below the flat ground.
    pub depth: f64,
    /// φ: soil friction angle, radians.
    pub friction: f64,
    /// φw: blade-soil friction angle, radians.
    pub wall_friction: f64,
    /// α: rake, the face's angle from the horizontal on the soil side, radians
    /// (π/2: vertical).
    pub rake: f64,
    /// c: cohesion on the failure surface (stress).
    pub cohesion: f64,
    /// a: adhesion on the face contact (stress).
    pub adhesion: f64,
    /// q: surcharge pressure on the ground surface (stress).
    pub surcharge: f64,
}

/// McKyes' dimensionless factors at one failure angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Factors {
    /// Nγ = (cot α + cot β) sin(β + φ) / (2 sin(α + β + φ + φw)).
    pub n_gamma: f64,
    /// Nc = cos φ / (sin β sin(α + β + φ + φw)).
    pub n_c: f64,
    /// Na = −cos(α + β + φ) / (sin α sin(α + β + φ + φw)).
    pub n_a: f64,
    /// Nq = (cot α + cot β) sin(β + φ) / sin(α + β + φ + φw) = 2 Nγ.
    pub n_q: f64,
}

/// One baseline: the least force over the failure angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Baseline {
    /// P, resultant blade force per unit width.
    pub force: f64,
    /// Horizontal (draft) component.
    pub force_h: f64,
    /// Vertical component of the soil's force on the blade, positive upward.
    pub force_v: f64,
    /// β* (radians) of the failure surface.
    pub failure_angle: f64,
    /// The FEE factors at β* (trial wedge only).
    pub factors: Option<Factors>,
}

impl Wedge {
    /// The wedge of a case's initial flat ground (soil at zero shear).
    pub fn of_case(case: &crate::Case) -> Self {
        Wedge {
            unit_weight: case.soil.unit_weight,
            depth: case.blade.depth,
            friction: case.soil.friction.initial.to_radians(),
            wall_friction: case.blade.wall_friction.to_radians(),
            rake: case.blade.rake.to_radians(),
            cohesion: case.soil.cohesion,
            adhesion: case.blade.adhesion,
            surcharge: case.soil.surcharge,
        }
    }

    /// The FEE factors Nγ, Nc, Na, Nq of (M37) at failure angle β, if the
    /// wedge is admissible there (β > 0 and α + β + φ + φw < 180°).
    pub fn factors(&self, beta: f64) -> Option<Factors> {
        let (alpha, phi) = (self.rake, self.friction);
        let denominator = (alpha + beta + phi + self.wall_friction).sin();
        if beta <= 0.0 || denominator <= 0.0 || alpha + beta + phi + self.wall_friction >= PI {
            return None;
        }
        let cots = 1.0 / alpha.tan() + 1.0 / beta.tan();
        let n_q = cots * (beta + phi).sin() / denominator;
        Some(Factors {
            n_gamma: 0.5 * n_q,
            n_c: phi.cos() / (beta.sin() * denominator),
            n_a: -(alpha + beta + phi).cos() / (alpha.sin() * denominator),
            n_q,
        })
    }

    /// F = γ d² Nγ + c d Nc + a d Na + q d Nq (M37).
    pub fn force_with(&self, f: &Factors) -> f64 {
        let d = self.depth;
        self.unit_weight * d * d * f.n_gamma
            + d * (self.cohesion * f.n_c + self.adhesion * f.n_a + self.surcharge * f.n_q)
    }

    fn baseline(&self, force: f64, beta: f64, factors: Option<Factors>) -> Baseline {
        let lean = self.rake + self.wall_friction;
        Baseline {
            force,
            force_h: force * lean.sin(),
            force_v: -force * lean.cos(),
            failure_angle: beta,
            factors,
        }
    }

    /// The trial wedge of least force (FEE, (M37)).
    pub fn fee(&self) -> Option<Baseline> {
        let beta = self.least_over_beta(|beta| self.factors(beta).map(|f| self.force_with(&f)))?;
        let factors = self.factors(beta)?;
        Some(self.baseline(self.force_with(&factors), beta, Some(factors)))
    }

    /// The failure angle of least `force` over admissible β: a scan of
    /// 4000 angles refined by golden sections around the best.
    fn least_over_beta(&self, force: impl Fn(f64) -> Option<f64>) -> Option<f64> {
        let upper = PI - self.rake - self.friction - self.wall_friction;
        let n = 4000;
        let best = (1..n)
            .map(|k| upper * k as f64 / n as f64)
            .filter_map(|b| force(b).map(|f| (b, f)))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        let step = upper / n as f64;
        Some(golden_minimum(
            |b| force(b).unwrap_or(f64::INFINITY),
            best.0 - step,
            best.0 + step,
        ))
    }

    /// Coulomb's passive wedge: the trial wedge without cohesion, adhesion
    /// or surcharge; for a vertical blade ½ γ d² Kp (M13).
    pub fn coulomb(&self) -> Option<Baseline> {
        let frictional = Wedge {
            cohesion: 0.0,
            adhesion: 0.0,
            surcharge: 0.0,
            ..*self
        };
        frictional.fee().map(|b| Baseline { factors: None, ..b })
    }

    /// Rankine's passive force on a smooth vertical wall.
    pub fn rankine(&self) -> Baseline {
        let kp = (FRAC_PI_4 + 0.5 * self.friction).tan().powi(2);
        let d = self.depth;
        let force = 0.5 * self.unit_weight * d * d * kp
            + 2.0 * self.cohesion * d * kp.sqrt()
            + self.surcharge * d * kp;
        Baseline {
            force,
            force_h: force,
            force_v: 0.0,
            failure_angle: FRAC_PI_4 - 0.5 * self.friction,
            factors: None,
        }
    }
}

use std::f64::consts::{FRAC_PI_4, PI};

/// Minimum of a unimodal f on [a, b] by golden sections, to round-off.
fn golden_minimum(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let (mut c, mut d) = (b - ratio * (b - a), a + ratio * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if (b - a).abs() <= 1e-15 * b.abs().max(1.0) {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The literature's example: α = 60°, φw = 20°, φ = 35°, ρ = 1800 kg/m³
    /// (γ = 17.66 kN/m³), d = 0.5 m.
    fn example(rake_deg: f64) -> Wedge {
        Wedge {
            unit_weight: 17.66,
            depth: 0.5,
            friction: 35f64.to_radians(),
            wall_friction: 20f64.to_radians(),
            rake: rake_deg.to_radians(),
            cohesion: 0.0,
            adhesion: 0.0,
            surcharge: 0.0,
        }
    }

    #[test]
    fn fee_matches_the_literature_example() {
        let b = example(60.0).fee().unwrap();
        assert!((b.failure_angle.to_degrees() - 28.11).abs() < 0.01);
        assert!((b.factors.unwrap().n_gamma - 1.820).abs() < 5e-4);
        assert!((b.force - 8.03).abs() < 5e-3);
        assert!((b.force_h - 7.91).abs() < 5e-3);
        // The source rounds F to 8.03 before taking 8.03 cos 80° = 1.394.
        assert!((b.force_v.abs() - 1.39).abs() < 6e-3, "{b:?}");
    }

    #[test]
    fn fee_rake_sweep_matches_the_literature() {
        for (rake, beta, force) in [
            (30.0, 35.6, 7.57),
            (45.0, 32.8, 7.11),
            (75.0, 22.4, 10.81),
            (90.0, 16.2, 18.37),
        ] {
            let b = example(rake).fee().unwrap();
            assert!(
                (b.failure_angle.to_degrees() - beta).abs() < 0.05,
                "α={rake}"
            );
            assert!((b.force - force).abs() < 5e-3, "α={rake}: {}", b.force);
        }
    }

    #[test]
    fn cohesion_and_surcharge_match_the_literature() {
        let cohesive = Wedge {
            cohesion: 5.0,
            ..example(60.0)
        };
        assert!((cohesive.fee().unwrap().force - 15.19).abs() < 5e-3);
        let loaded = Wedge {
            surcharge: 2.0,
            ..example(60.0)
        };
        assert!((loaded.fee().unwrap().force - 11.67).abs() < 5e-3);
    }

    #[test]
    fn vertical_frictional_wedge_is_coulomb_closed_form() {
        let mut w = example(90.0);
        w.unit_weight = 1.0;
        w.depth = 1.0;
        w.friction = 20f64.to_radians();
        w.wall_friction = 10f64.to_radians();
        let (p, pw) = (w.friction, w.wall_friction);
        let root = ((p + pw).sin() * p.sin() / pw.cos()).sqrt();
        // Kp = cos² φ / (cos φw (1 − √(sin(φ + φw) sin φ / cos φw))²) (M13).
        let kp = p.cos().powi(2) / (pw.cos() * (1.0 - root).powi(2));
        let b = w.coulomb().unwrap();
        assert!(
            (b.force - 0.5 * kp).abs() < 1e-12 * kp,
            "{} {}",
            b.force,
            0.5 * kp
        );
    }

    #[test]
    fn rankine_for_a_smooth_wall() {
        let mut w = example(90.0);
        w.friction = 30f64.to_radians();
        w.wall_friction = 0.0;
        let r = w.rankine();
        assert!((r.force - 0.5 * 17.66 * 0.25 * 3.0).abs() < 1e-9);
        // Coulomb with φw = 0 on a vertical wall is Rankine.
        assert!((w.coulomb().unwrap().force - r.force).abs() < 1e-9 * r.force);
        assert!((r.failure_angle.to_degrees() - 30.0).abs() < 1e-12);
    }
}
