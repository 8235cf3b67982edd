//! The side crescents of a blade of finite width (McKyes & Ali 1977;
//! McKyes 1985; docs/model.md §16).
//!
//! A blade of width w pushes the band's block across its width and, at
//! each edge, a crescent: in plan a fan of radius r (the rupture distance)
//! about the face's top edge O, spanning the angle ρ from the direction of
//! travel, whose failure surface is the cone from the tip corner T to the
//! fan's arc on the ground. McKyes & Ali put each slice of the fan in
//! equilibrium with the centre block's factors and sum the forward
//! components. With the band's Eq. (1) factor f = P/W (M7), its cohesion
//! term k (M8) and its slip line of horizontal length L, the crescents add
//!
//! ```text
//! P_cr = f (W_cr + q r² sin ρ) + c L k r sin ρ                        (M42)
//! W_cr = γ0 d r² sin ρ / 3 + W_ridge
//! cos ρ = min(1, d cot α / r)                                        (F8)
//! ```
//!
//! to the blade's total force P = w P_band + P_cr, with r the emergence
//! node's distance from the face on the sheared grid (M33), which on flat
//! ground is McKyes' d (cot α + cot β) (F7). On flat ground this is the
//! crescent part of McKyes & Ali's factors, Nγ (2/3) x, Nc x and Nq x with
//! x = (r / w) sin ρ (docs/model.md §16.1); adhesion acts on the face only.
//! W_ridge is the weight of the side heaps (`side_heaps`) lying on the fans:
//!
//! ```text
//! W_ridge = 2 ∫₀^ρ cos θ ∫₀^r γs g(x_O + s cos θ, s sin θ) s ds dθ      (M43)
//! g(x, e) = max(h_s(x) − e tan θr, 0)
//! ```
//!
//! a heap of crest height h_s at the blade's edge falling away at the angle
//! of repose, integrated by Gauss-Legendre rules in θ and s (zero, and not
//! evaluated, before any soil has spilled). The search compares P / w, so
//! its bounds on the band's force (every crescent term is ≥ 0) stay bounds.

use crate::case::Case;
use crate::mechanism::{ForceFactor, Loads};
use crate::side_heaps::SideHeaps;

/// The narrowest blade, as a fraction of the tip depth, for which the
/// crescents describe the failure: below a critical depth of about 6 w a
/// narrow tine fails the soil sideways (Godwin & Spoor 1977; Grisso &
/// Perumpral 1985), docs/model.md §16.4.
pub const NARROWEST: f64 = 1.0 / 6.0;

/// Gauss-Legendre nodes and weights on [−1, 1], 8 points.
const GAUSS: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_48),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_48),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

/// The crescents of one increment: the blade's width, the fresh soil
/// beside it and the side heaps on the nodes ahead.
#[derive(Clone, Copy, Debug)]
pub struct Crescents<'a> {
    /// w: the blade's width.
    pub width: f64,
    /// γ0: unit weight of the soil beside the blade.
    pub unit_weight: f64,
    /// tan θr: the side heaps' flanks.
    pub tan_repose: f64,
    /// x' of the face (on the grid), where the fans are centred.
    pub face_x: f64,
    /// Δx: node spacing of the grid.
    pub spacing: f64,
    /// Whether any side heap lies ahead of the face (else W_ridge = 0).
    pub ridges: bool,
    /// h_s,i: crest height of the side heaps at node i.
    pub ridge_height: &'a [f64],
    /// γs,i: their unit weight.
    pub ridge_unit_weight: &'a [f64],
    /// The highest h_s,i: along a ray at θ no heap stands above the fan
    /// beyond s = h_s,max / (sin θ tan θr), so the quadrature stops there.
    pub highest_ridge: f64,
}

/// The parts of the band's force the crescents scale (M8): Eq. (1)'s
/// factor f = P/W, the cohesion term c L k, and the surcharge q.
#[derive(Clone, Copy, Debug)]
pub struct BandTerms {
    /// f = P/W at the band's angles (M7).
    pub factor: f64,
    /// c L k: the band's cohesion term (0 without cohesion).
    pub cohesion: f64,
    /// q: surcharge pressure.
    pub surcharge: f64,
}

/// (cos ρ, sin ρ) of the fans of radius r for a tip at depth d behind a
/// face at cot α: cos ρ = min(1, d cot α / r) (F8).
fn fan(r: f64, depth: f64, cot_rake: f64) -> (f64, f64) {
    let cos_rho = (depth * cot_rake / r).min(1.0);
    (cos_rho, (1.0 - cos_rho * cos_rho).sqrt())
}

/// Where the fans of a band stand: r, its emergence point's distance ahead
/// of the face on the grid (M33), the tip depth d and the face's cot α.
#[derive(Clone, Copy, Debug)]
pub struct Fan {
    /// r (length).
    pub rupture: f64,
    /// d (length).
    pub depth: f64,
    /// cot α.
    pub cot_rake: f64,
}

impl<'a> Crescents<'a> {
    /// The crescents of `case`'s blade beside `side`, a field of nodes
    /// `spacing` apart, for a face at grid x `face_x` on or after node
    /// `face_node` of the field; `None` in plane strain.
    pub fn of(
        case: &Case,
        side: &'a SideHeaps,
        (face_x, face_node, spacing): (f64, usize, f64),
    ) -> Option<Self> {
        let width = case.blade.width?;
        Some(Crescents {
            width,
            unit_weight: case.soil.unit_weight,
            tan_repose: case.soil.repose.to_radians().tan(),
            face_x,
            spacing,
            ridges: side.any_from(face_node),
            ridge_height: &side.height,
            ridge_unit_weight: &side.unit_weight,
            highest_ridge: side.highest(),
        })
    }
}

/// P: the band's Eq. (1) with the loads, W at tan β = `t` and a slip line
/// of horizontal length L (M4, M6, M8), plus, for a blade of finite width,
/// its side crescents per unit width (M42); `None` if not admissible. Both
/// grounds' searches compare it.
pub fn blade_force(
    crescents: Option<&Crescents>,
    (loads, factor): (&Loads, &ForceFactor),
    (weight, length, t): (f64, f64, f64),
    fan: Fan,
) -> Option<f64> {
    let band = loads.force(factor, weight, length, t)?;
    let Some(crescents) = crescents else {
        return Some(band);
    };
    let terms = BandTerms {
        factor: factor.at(t)?,
        cohesion: loads.cohesion * length * factor.cohesion_at(t),
        surcharge: loads.surcharge,
    };
    Some(band + crescents.force_per_width(terms, fan.rupture, fan.depth, fan.cot_rake))
}

/// The weight the bounds use for a band of weight W: W, plus the
/// crescents' least weight per unit width for a blade of finite width
/// (`Crescents::weight_floor`).
pub fn bound_weight(crescents: Option<&Crescents>, weight: f64, fan: Fan) -> f64 {
    match crescents {
        None => weight,
        Some(c) => weight + c.weight_floor(fan.rupture, fan.depth, fan.cot_rake),
    }
}

impl Crescents<'_> {
    /// P_cr / w for a band whose emergence lies `rupture` = r ahead of the
    /// face on the grid, the tip at depth d, the face at cot α (M42).
    pub fn force_per_width(&self, band: BandTerms, rupture: f64, depth: f64, cot_rake: f64) -> f64 {
        let r = rupture;
        let (cos_rho, sin_rho) = fan(r, depth, cot_rake);
        let weight =
            self.unit_weight * depth * r * r * sin_rho / 3.0 + self.ridge_weight(r, cos_rho);
        let total =
            band.factor * (weight + band.surcharge * r * r * sin_rho) + band.cohesion * r * sin_rho;
        total / self.width
    }

    /// A lower bound of P_cr / w per unit of f: the flat fans' weight
    /// γ0 d r² sin ρ / (3 w), which grows with r, so that the bounds and the
    /// stopping rule on the band's weight (M31) hold for W + this.
    pub fn weight_floor(&self, rupture: f64, depth: f64, cot_rake: f64) -> f64 {
        let r = rupture;
        let (_, sin_rho) = fan(r, depth, cot_rake);
        self.unit_weight * depth * r * r * sin_rho / (3.0 * self.width)
    }

    /// W_ridge (M43) over both fans of radius r, half-angle ρ = acos(cos ρ).
    fn ridge_weight(&self, r: f64, cos_rho: f64) -> f64 {
        if !self.ridges {
            return 0.0;
        }
        let rho = cos_rho.acos();
        let mut total = 0.0;
        for (xi, wi) in GAUSS {
            let theta = 0.5 * rho * (1.0 + xi);
            let (sin_t, cos_t) = theta.sin_cos();
            let mut ray = 0.0;
            // Beyond it g ≤ 0 at every node ahead: the terms skipped add
            // nothing (the nodes s rise along GAUSS).
            let beyond = self.highest_ridge / (sin_t * self.tan_repose);
            for (xj, wj) in GAUSS {
                let s = 0.5 * r * (1.0 + xj);
                if s >= beyond {
                    break;
                }
                let (h, gamma) = self.ridge_at(self.face_x + s * cos_t);
                let g = h - s * sin_t * self.tan_repose;
                if g > 0.0 {
                    ray += wj * gamma * g * s;
                }
            }
            total += wi * cos_t * ray * 0.5 * r;
        }
        2.0 * total * 0.5 * rho
    }

    /// h_s and γs at grid x, linear between nodes (0 beyond the heaps).
    fn ridge_at(&self, x: f64) -> (f64, f64) {
        let at = x / self.spacing;
        // x ≥ 0 ahead of the face: truncation is the floor.
        let i = at as usize;
        let (h, g) = (self.ridge_height, self.ridge_unit_weight);
        if i + 1 >= h.len() {
            return (
                h.get(i).copied().unwrap_or(0.0),
                g.get(i).copied().unwrap_or(0.0),
            );
        }
        let t = at - i as f64;
        let height = h[i] + t * (h[i + 1] - h[i]);
        // The heavier end's unit weight where one end has no heap.
        let gamma = if h[i] == 0.0 {
            g[i + 1]
        } else if h[i + 1] == 0.0 {
            g[i]
        } else {
            g[i] + t * (g[i + 1] - g[i])
        };
        (height, gamma)
    }
}
