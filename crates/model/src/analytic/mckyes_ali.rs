//! McKyes & Ali (1977): the trial wedge of a blade of finite width w, the
//! centre wedge across the width plus a side crescent at each edge
//! (docs/model.md §16.1). With the plane-strain factors of the module
//! above, the rupture distance r, the crescent's half-angle ρ and
//! x = (r / w) sin ρ,
//!
//! ```text
//! r = d (cot α + cot β)                                              (F7)
//! cos ρ = cot α / (cot α + cot β)                                    (F8)
//! Nγ3 = Nγ (1 + 2x/3)    Nc3 = Nc (1 + x)    Nq3 = Nq (1 + x)    Na3 = Na   (F9)-(F12)
//! P = w (γ d² Nγ3 + c d Nc3 + a d Na3 + q d Nq3)                (F13), (M46)
//! ```
//!
//! least over β (the total force, as soilcut's minimum effort selects). As
//! w → ∞ these are the plane-strain factors times w.

use super::{Baseline, Factors, Wedge};

/// The least force of a blade of finite width and its geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Narrow {
    /// P per blade, its components and β*; the factors are Nγ3 … Nq3.
    pub baseline: Baseline,
    /// r: the rupture distance, from the face's top edge to where the
    /// failure surface meets the ground (F7).
    pub rupture: f64,
    /// ρ: the crescent's half-angle in plan, radians (F8).
    pub crescent_angle: f64,
}

impl Wedge {
    /// The factors of (F9)-(F12) of (M46) at failure angle β for width w,
    /// with r and ρ, or `None` where the wedge is not admissible.
    pub fn narrow_factors(&self, beta: f64, width: f64) -> Option<(Factors, f64, f64)> {
        let f = self.factors(beta)?;
        let cot_alpha = 1.0 / self.rake.tan();
        let cots = cot_alpha + 1.0 / beta.tan();
        let rupture = self.depth * cots;
        let rho = (cot_alpha / cots).clamp(-1.0, 1.0).acos();
        let x = rupture / width * rho.sin();
        let factors = Factors {
            n_gamma: f.n_gamma * (1.0 + 2.0 * x / 3.0),
            n_c: f.n_c * (1.0 + x),
            n_a: f.n_a,
            n_q: f.n_q * (1.0 + x),
        };
        Some((factors, rupture, rho))
    }

    /// (F13), (M46), minimised over β as `fee` does.
    pub fn mckyes_ali(&self, width: f64) -> Option<Narrow> {
        let beta = self.least_over_beta(|beta| {
            self.narrow_factors(beta, width)
                .map(|(f, _, _)| width * self.force_with(&f))
        })?;
        let (factors, rupture, rho) = self.narrow_factors(beta, width)?;
        let total = width * self.force_with(&factors);
        Some(Narrow {
            baseline: self.baseline(total, beta, Some(factors)),
            rupture,
            crescent_angle: rho,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tine(rake_deg: f64, cohesion: f64) -> Wedge {
        Wedge {
            unit_weight: 1.0,
            depth: 1.0,
            friction: 35f64.to_radians(),
            wall_friction: 20f64.to_radians(),
            rake: rake_deg.to_radians(),
            cohesion,
            adhesion: 0.0,
            surcharge: 0.0,
        }
    }

    /// The table of docs/studies/finite-width/README.md §5, computed there
    /// by an independent implementation (standard-library Python, its
    /// plane-strain part checked against a published example and its
    /// vertical crescents against a cone integral).
    #[test]
    fn matches_the_studys_independent_implementation() {
        for (rake, c, w, p_per_width, beta, rupture) in [
            (90.0, 0.0, 1.0, 12.207, 21.40, 2.552),
            (90.0, 0.0, 0.25, 34.976, 22.73, 2.387),
            (90.0, 0.2, 5.0, 8.7941, 19.36, 2.846),
            (45.0, 0.0, 1.0, 3.6935, 46.69, 1.943),
            (45.0, 0.2, 5.0, 2.6259, 40.44, 2.174),
        ] {
            let n = tine(rake, c).mckyes_ali(w).unwrap();
            let p = n.baseline.force / w;
            assert!((p / p_per_width - 1.0).abs() < 2e-4, "{rake} {c} {w}: {p}");
            let b = n.baseline.failure_angle.to_degrees();
            assert!((b - beta).abs() < 0.01, "{rake} {c} {w}: β {b}");
            assert!(
                (n.rupture - rupture).abs() < 1e-3,
                "{rake} {c} {w}: r {}",
                n.rupture
            );
        }
    }

    #[test]
    fn tends_to_plane_strain_and_falls_with_width() {
        for (rake, c) in [(90.0, 0.0), (90.0, 0.2), (45.0, 0.0), (45.0, 0.2)] {
            let wedge = tine(rake, c);
            let plane = wedge.fee().unwrap().force;
            let mut last = f64::INFINITY;
            for w in [0.25, 0.5, 1.0, 2.0, 5.0, 20.0, 1000.0, 1e7] {
                let per_width = wedge.mckyes_ali(w).unwrap().baseline.force / w;
                assert!(per_width < last && per_width > plane, "{rake} {c} {w}");
                last = per_width;
            }
            assert!((last / plane - 1.0) < 1e-6, "{rake} {c}: {last} {plane}");
        }
    }
}
