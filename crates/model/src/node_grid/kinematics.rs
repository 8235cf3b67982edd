//! The update of the free surface after an increment (docs/model.md §3, §9.1).
//!
//! **Slip line** (original model, Fig. 1b; and any band narrower than a
//! node): the block above the slip line A→j translates by v0 (1, tan β*).
//! On the grid Δx = v0 that is an exact shift of nodes b..j−1 to b+1..j with
//! a rise of v0 tan β*; nodes beyond j are unchanged. Block nodes carry their
//! state; node j, where the slip line emerges, keeps the state of the slip
//! surface and accumulates Δut = v0 / cos β*. The face sweeps the triangle
//! (x_b, −d), (x_b + v0, −d), (x_b + v0, −d + v0 tan β*) of area ½ v0² tan β*:
//! that soil is pushed up the face rather than dropped, by raising the new
//! face node a further v0 tan β* (half trapezoid weight: exactly that area).
//!
//! **Shear band** (refined model, Fig. 3b-c): soil above the band moves by
//! v0 (1, tan(β* + ψ)); inside the band the displacement falls linearly to 0
//! at the lower boundary. This map is piecewise affine, so the image of the
//! old surface polyline is the polyline through the images of its nodes and
//! of the points where it crosses the upper boundary. Its area exceeds the
//! old one by the band's dilation, A0 Δuv / dB (Jacobian 1 + Δuv / dB on the
//! band, Δuv = Δut tan ψ, Δut = v0 cos ψ / cos(β* + ψ)). The image is
//! resampled on the grid; the face sweeps the band soil that moved less than
//! v0 and the soil below the band, ½ v0 e + ½ v0² tan(β* + ψ) in all (e =
//! dB / cos β*), which is pushed up the face as above; the small resampling
//! error is spread evenly over the band's nodes so that the area is exactly
//! the old area plus the dilation. Block nodes carry their state, band nodes
//! keep theirs (the band is part of the ground) and all accumulate Δut.
//!
//! **Mass** (all): the band's nodes, from the first one the band reaches to
//! the emergence node, take one uniform unit weight chosen so that the weight
//! of the soil in front of the blade is unchanged (paper: γ = Wb / Anew for
//! the band as a whole).

use crate::band::{dilation_gap, BandMotion};
use crate::case::{BandShearRule, Choices, UnitWeightRule};
use crate::node_grid::face_node::FaceNode;
use crate::node_grid::node_band::Band;
use crate::node_grid::node_search::Choice;
use crate::node_grid::surface::Surface;
use crate::rake::Rake;
use std::ops::Range;

/// How the face moves in an increment (by v0 = h): how much deeper the tip
/// goes (Δd, negative while it rises), and the face node afterwards
/// (node b + 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Advance {
    /// Δd, how much deeper the tip goes (length).
    pub deepening: f64,
    /// The face after the increment.
    pub face: FaceNode,
}

/// What an update did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Update {
    /// Δut of the band (or slip line).
    pub slip: f64,
    /// Area added by the band's dilation (negative for compaction).
    pub dilation_area: f64,
    /// First node of the band after the update (the emergence node for a
    /// slip line).
    pub first_band_node: usize,
    /// Weight of the soil the tip passed over, left behind in the trench.
    pub trench_mass: f64,
    /// First node whose accumulated shear changed (the band's first node,
    /// or the face on a coarse grid, where the block's state is remapped).
    pub state_from: usize,
}

/// Reusable scratch for the band update.
#[derive(Clone, Debug, Default)]
pub struct Kinematics {
    /// Image points (x, y) of the old surface from the face to j.
    image: Vec<(f64, f64)>,
    /// Relative positions f_i = clamp(g_i, 0, 1) of nodes b..=j before the
    /// update.
    position: Vec<f64>,
    /// γ of nodes b..=j before the update.
    old_unit_weight: Vec<f64>,
}

impl Kinematics {
    /// Moves the soil for the chosen mechanism and keeps mass exact.
    pub fn apply(
        &mut self,
        surface: &mut Surface,
        band: &Band,
        choice: &Choice,
        choices: Choices,
        rake: &Rake,
        advance: Advance,
    ) -> Update {
        let (trench_mass, mass_before) = self.start(surface, band, advance);
        surface.face = advance.face;
        let deepening = advance.deepening;
        let motion = BandMotion::new((choice.tan_beta, choice.dilation), rake, surface.spacing);
        let update =
            match motion.and_then(|m| self.shear_band(surface, band, m, choices.band_shear)) {
                Some(update) => update,
                None => slide_block(surface, band.face.node, choice, rake),
            };
        surface.height[band.face.node + 1] += deepening;
        let update = Update {
            trench_mass,
            ..update
        };
        let gap = if update.dilation_area == 0.0 {
            0.0
        } else {
            dilation_gap(
                update.slip,
                choice.dilation.tan(),
                (choice.grid_slope, choice.tan_beta),
            )
        };
        self.mix_block_columns(surface, band, update.first_band_node, gap);
        band_unit_weight(surface, band, choice, choices, &update, mass_before);
        update
    }

    /// Before the update: the weight of the soil the tip passes over (left
    /// in the trench, γ_b Δx (d_max − d − ½ Δd), (M38)) and the weight from
    /// the face to j less it, which the update keeps; the unit weights of
    /// the face to j are saved.
    fn start(&mut self, surface: &Surface, band: &Band, advance: Advance) -> (f64, f64) {
        let (b, j) = (band.face.node, band.emergence);
        // The strip the blade moves through: soil below the tip's path
        // (from depth d to d + Δd) stays behind; what lies between that path
        // and the slip line is pushed up the face (`deepening` adds to the
        // face's lift; a rising tip, Δd < 0, leaves more behind and lifts
        // the face less).
        let depth_below = -surface.floor - band.depth - 0.5 * advance.deepening;
        let trench_mass = surface.unit_weight[b] * (surface.spacing * depth_below);
        let mass_before = region_mass(surface, b, b..j + 1) - trench_mass;
        self.old_unit_weight.clear();
        self.old_unit_weight
            .extend_from_slice(&surface.unit_weight[b..=j]);
        (trench_mass, mass_before)
    }

    /// The shear band update; `None` (nothing changed) where the band is too
    /// thin for the grid to resolve it, which is then a slip line.
    fn shear_band(
        &mut self,
        surface: &mut Surface,
        band: &Band,
        motion: BandMotion,
        rule: BandShearRule,
    ) -> Option<Update> {
        let (b, j, dx, t) = (
            band.face.node,
            band.emergence,
            surface.spacing,
            band.tan_beta,
        );
        let (e, rise, slip) = (band.thickness, motion.rise, motion.slip);
        if e == 0.0 || e + rise - dx * t < 0.0 {
            return None;
        }
        let last_block_x = self.trace_image(surface, band, rise, dx)?;
        let first_band_node = (b + 2..j).find(|&i| surface.x(i) > last_block_x)?;
        let area_before = region_area(surface, b, j);
        // ΔA = A0 Δut tan ψ / dB (M19).
        let dilation_area = band.area_below(&surface.height) * slip * motion.tan_psi / band.width;
        self.resample(surface, b, j);
        // Swept area ½ Δx (e + rise) on a half-weight node: a rise of e + rise
        // (M20).
        surface.height[b + 1] += e + rise;
        // The strip's soil below the tip (deeper than d, above the floor)
        // stays behind the blade.
        let left_behind = dx * (-surface.floor - band.depth);
        // Area after = area before + ΔA, exactly (M21).
        let residual = area_before - left_behind + dilation_area - region_area(surface, b + 1, j);
        spread_residual(surface, first_band_node..j, residual);
        shift_block_state(surface, b, first_band_node);
        // ut_i += Δut, or f_i Δut (M22).
        self.accumulate_shear(surface, band, first_band_node, slip, rule);
        Some(Update {
            slip,
            dilation_area,
            first_band_node,
            trench_mass: 0.0,
            state_from: first_band_node,
        })
    }

    /// Images of the surface nodes b..=j under the motion (block moved by
    /// (v0, rise), band soil by its fraction f of that) and of the
    /// crossings of the band's upper boundary; returns the x of the last
    /// image still in the rigid block, or `None` if the face lies in the
    /// band or the images fold over (a band narrower than the grid resolves).
    /// A slip line (no thickness) moves every node before j with the block.
    fn trace_image(&mut self, surface: &Surface, band: &Band, rise: f64, v0: f64) -> Option<f64> {
        let (b, j) = (band.face.node, band.emergence);
        let h = &surface.height;
        let banded = band.thickness > 0.0;
        self.image.clear();
        self.position.clear();
        let mut g_prev = band.position(h[b], b);
        self.position.push(g_prev.clamp(0.0, 1.0));
        if banded && g_prev < 1.0 {
            return None;
        }
        let mut last_block_x = surface.x(b) + v0;
        self.image.push((last_block_x, h[b] + rise));
        for i in b + 1..=j {
            let g = band.position(h[i], i);
            if banded && (g_prev - 1.0) * (g - 1.0) < 0.0 {
                let lambda = (g_prev - 1.0) / (g_prev - g);
                let x = surface.x(i - 1) + lambda * surface.spacing;
                let y = h[i - 1] + lambda * (h[i] - h[i - 1]);
                self.image.push((x + v0, y + rise));
                if g < 1.0 {
                    last_block_x = x + v0;
                }
            }
            let f = match (banded, i == j) {
                (true, _) => g.clamp(0.0, 1.0),
                (false, false) => 1.0,
                (false, true) => 0.0,
            };
            self.position.push(f);
            let point = (surface.x(i) + f * v0, h[i] + f * rise);
            if point.0 <= self.image.last().expect("face image").0 {
                if i == j && !banded {
                    // The slip line's block reaches the emergence node.
                    break;
                }
                return None;
            }
            if f == 1.0 {
                last_block_x = point.0;
            }
            self.image.push(point);
            g_prev = g;
        }
        Some(last_block_x)
    }

    /// Heights of nodes b+1..j from the image polyline (linear interpolation).
    fn resample(&self, surface: &mut Surface, b: usize, j: usize) {
        let mut k = 0;
        for i in b + 1..j {
            let x = surface.x(i);
            while self.image[k + 1].0 < x {
                k += 1;
            }
            let ((x0, y0), (x1, y1)) = (self.image[k], self.image[k + 1]);
            surface.height[i] = y0 + (y1 - y0) * (x - x0) / (x1 - x0);
        }
    }
}

/// The slip-line update (see the module doc): the block's nodes shift one
/// node and rise by v0 tan β* (M14), the face node takes the swept soil
/// (M20), and node j accumulates the slip Δut (M15, M36 on a raked blade;
/// M22).
pub fn slide_block(surface: &mut Surface, blade: usize, choice: &Choice, rake: &Rake) -> Update {
    let j = choice.node;
    let BandMotion { rise, slip, .. } =
        BandMotion::slip_line((choice.grid_slope, choice.tan_beta), rake, surface.spacing);
    let h = &mut surface.height;
    // y'_{i+1} = y_i + v0 tan β*, b ≤ i < j (M14).
    h.copy_within(blade..j, blade + 1);
    for y in &mut h[blade + 1..=j] {
        *y += rise;
    }
    // The swept soil: y'_{b+1} += v0 tan β* (M20).
    h[blade + 1] += rise;
    shift_block_state(surface, blade, j);
    // ut_j += Δut (M15; M22).
    surface.accumulated_shear[j] += slip;
    Update {
        slip,
        dilation_area: 0.0,
        first_band_node: j,
        trench_mass: 0.0,
        state_from: j,
    }
}

/// Block nodes b..end−1 carry their state to b+1..end.
fn shift_block_state(surface: &mut Surface, blade: usize, end: usize) {
    let range = blade..end - 1;
    surface
        .accumulated_shear
        .copy_within(range.clone(), blade + 1);
    surface.unit_weight.copy_within(range.clone(), blade + 1);
    surface.friction.copy_within(range.clone(), blade + 1);
    surface.dilation.copy_within(range, blade + 1);
}

/// Trapezoid area between the floor and the surface over nodes a..=z.
fn region_area(surface: &Surface, a: usize, z: usize) -> f64 {
    let (h, floor) = (&surface.height, surface.floor);
    let inner: f64 = h[a + 1..z].iter().map(|y| y - floor).sum();
    surface.spacing * (inner + 0.5 * (h[a] - floor) + 0.5 * (h[z] - floor))
}

/// Weight of the columns of `nodes` as counted by `Surface::mass` with the
/// face at node `face` (which counts half; none of them is the last node).
fn region_mass(surface: &Surface, face: usize, nodes: Range<usize>) -> f64 {
    nodes
        .map(|i| surface.unit_weight[i] * surface.column_area(i, face))
        .sum()
}

impl Kinematics {
    /// Unit weight of the block's columns after the shift: the soil below
    /// the slip line stays (its column's γ), the soil above it came from the
    /// column behind (that column's γ), mixed by area. Without this the band
    /// would have to absorb every difference of γ along the block, which can
    /// drive its unit weight negative (M26, by `mix_column`); `gap` is the
    /// band's dilation under the block (`dilation_gap`).
    fn mix_block_columns(&self, surface: &mut Surface, band: &Band, first_band: usize, gap: f64) {
        let b = band.face.node;
        for i in b + 1..first_band {
            let (staying, arriving) =
                (self.old_unit_weight[i - b], self.old_unit_weight[i - 1 - b]);
            mix_column(surface, band, i, (staying, arriving), gap);
        }
    }

    /// Δut on the band's nodes first_band..=j: all of it, or the share f
    /// of a node's relative position (`BandShearRule`; M22).
    fn accumulate_shear(
        &self,
        surface: &mut Surface,
        band: &Band,
        first_band: usize,
        slip: f64,
        rule: BandShearRule,
    ) {
        for i in first_band..=band.emergence {
            let share = match rule {
                BandShearRule::Full => 1.0,
                BandShearRule::ByPosition => self
                    .position
                    .get(i - band.face.node)
                    .copied()
                    .unwrap_or(0.0),
            };
            surface.accumulated_shear[i] += share * slip;
        }
    }
}

/// Column i's unit weight after the block moved over it: the soil below the
/// band's lower boundary stayed (γ `staying`), the soil above it arrived
/// (γ `arriving`), mixed by height, less `gap`, the band's dilation under
/// the block, which holds no soil (M26).
fn mix_column(
    surface: &mut Surface,
    band: &Band,
    i: usize,
    (staying, arriving): (f64, f64),
    gap: f64,
) {
    let total = surface.height[i] - surface.floor;
    let at_rest = (band.lower(i) - surface.floor).clamp(0.0, total);
    let arrived = (total - at_rest - gap).max(0.0);
    surface.unit_weight[i] = (staying * at_rest + arriving * arrived) / total;
}

/// Spreads what the update gained or lost in area, `residual`, evenly in
/// height over `nodes` (by their trapezoid weights from the face), so that
/// the area is exactly the old area plus the dilation (M21).
fn spread_residual(surface: &mut Surface, nodes: Range<usize>, residual: f64) {
    let face = surface.face.node;
    let weights: f64 = nodes.clone().map(|i| surface.node_weight(i, face)).sum();
    let correction = residual / (weights * surface.spacing);
    for y in &mut surface.height[nodes] {
        *y += correction;
    }
}

/// The band's unit weight after the update (the `choices.unit_weight` rule):
/// the band as a whole (M27, `conserve_mass`), or node by node, each γ
/// divided by 1 + Δut tan ψ / dB, the paper's A_new / A0 (M25).
fn band_unit_weight(
    surface: &mut Surface,
    band: &Band,
    choice: &Choice,
    choices: Choices,
    update: &Update,
    mass_before: f64,
) {
    match choices.unit_weight {
        UnitWeightRule::BandUniform => {
            conserve_mass(surface, band, update.first_band_node, mass_before)
        }
        UnitWeightRule::PerNodeFormula => {
            let band_width = band.width;
            let strain = update.slip * choice.dilation.tan() / band_width;
            if band_width > 0.0 && update.dilation_area != 0.0 {
                for g in &mut surface.unit_weight[update.first_band_node..=band.emergence] {
                    *g /= 1.0 + strain;
                }
            }
        }
    }
}

/// Gives the band's nodes (first..=j) the one unit weight that makes the
/// weight of the nodes from the face (now `surface.face`) to j equal
/// `mass_before`: γ_band = (M_before − M_block) / Σ w_i (y'_i − y_floor) Δx
/// (M27).
fn conserve_mass(surface: &mut Surface, band: &Band, first: usize, mass_before: f64) {
    let (b, j) = (surface.face.node, band.emergence);
    let outside = region_mass(surface, b, b..first);
    let band_area: f64 = (first..=j).map(|i| surface.column_area(i, b)).sum();
    let gamma = (mass_before - outside) / band_area;
    for g in &mut surface.unit_weight[first..=j] {
        *g = gamma;
    }
}
