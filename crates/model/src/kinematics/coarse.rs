//! The update on a coarse node grid, h = k v0 with k > 1 (docs/model.md,
//! "Discretisation").
//!
//! The motion is that of the reference scheme: the block above the band
//! translates by v0 (1, tan(β* + ψ)), band soil by the fraction f of it at
//! relative position f, soil below stays. The face moves by v0, a fraction
//! 1/k of a node spacing, so the soil no longer lands on nodes. The image
//! of the old surface (`trace_image`) tells where the block ends and
//! whether the band folds; the nodes' new heights, and the block's
//! accumulated shear and unit weight, are the old surface's at x − f v0, by
//! a second-order upwind remap (`remap`): linear interpolation instead
//! smears the pile by about √(h u) after a travel u, which moved the band
//! jumps by several per cent of the force. The face node carries the face's
//! own soil; the soil the face sweeps over (below the block,
//! ½ v0 (e + v0 tan(β* + ψ) + Δd)) is put on the face node's half segment.
//! What the remap gains or loses in area is spread over the band's nodes so
//! that the area is exactly the old area plus the dilation, and the band's
//! unit weight keeps the weight of soil exact, as on the reference grid.

use super::{
    band_unit_weight, dilation_gap, mix_column, region_area, spread_residual, Advance, BandMotion,
    Kinematics, Update,
};
use crate::case::Choices;
use crate::grid::Band;
use crate::rake::Rake;
use crate::search::Choice;
use crate::surface::Surface;

impl Kinematics {
    pub(super) fn coarse(
        &mut self,
        surface: &mut Surface,
        band: &Band,
        choice: &Choice,
        choices: Choices,
        rake: &Rake,
        advance: Advance,
    ) -> Update {
        let (b, j, v0) = (band.face.node, band.emergence, surface.scheme.increment);
        let deepening = advance.deepening;
        let (trench_mass, mass_before) = self.start(surface, band, advance);
        let area_before = region_area(surface, b, j + 1);
        self.save(surface, b, j);
        let old_face = (surface.x(b), surface.segment(b));
        let band_motion = BandMotion::new((choice.tan_beta, choice.dilation), rake, v0)
            .filter(|_| band.thickness > 0.0);
        let traced =
            band_motion.and_then(|m| self.trace_image(surface, band, m.rise, v0).map(|x| (m, x)));
        let (motion, last_block_x, thickness) = match traced {
            Some((m, x)) => (m, x, band.thickness),
            None => {
                let slip_line = Band {
                    thickness: 0.0,
                    ..*band
                };
                let m = BandMotion::slip_line((choice.grid_slope, choice.tan_beta), rake, v0);
                let x = self
                    .trace_image(surface, &slip_line, m.rise, v0)
                    .expect("a slip line's image");
                (m, x, 0.0)
            }
        };
        let dilation_area = if thickness > 0.0 {
            band.area_below(&surface.height) * motion.slip * motion.tan_psi / band.width
        } else {
            0.0
        };
        surface.face = advance.face;
        let face = advance.face.node;
        let first_band = (face + 1..=j)
            .find(|&i| surface.x(i) > last_block_x)
            .unwrap_or(j);
        let gap = if thickness > 0.0 {
            dilation_gap(
                motion.slip,
                motion.tan_psi,
                (choice.grid_slope, choice.tan_beta),
            )
        } else {
            0.0
        };
        self.carry_block(
            surface,
            band,
            (face, first_band),
            old_face,
            (v0, motion.rise, gap),
        );
        self.carry_band(
            surface,
            band,
            first_band,
            surface.scheme.courant(),
            motion.rise,
        );
        // The face node: the face's own soil, risen with the block, and the
        // soil the face swept over on its half segment.
        let swept = 0.5 * v0 * (thickness + motion.rise + deepening);
        let half_segment = surface.face.node_weight(face) * surface.scheme.spacing;
        surface.height[face] = self.old_height[0] + motion.rise + swept / half_segment;
        surface.accumulated_shear[face] = self.old_shear[0];
        surface.unit_weight[face] = self.old_unit_weight[0];
        let left_behind = v0 * (-surface.floor - band.depth);
        let residual =
            area_before - left_behind + dilation_area - region_area(surface, face, j + 1);
        let spread = if first_band < j {
            first_band..j
        } else {
            j..j + 1
        };
        spread_residual(surface, spread, residual);
        self.accumulate_shear(surface, band, first_band, motion.slip, choices.band_shear);
        let update = Update {
            slip: motion.slip,
            dilation_area,
            first_band_node: first_band,
            trench_mass,
            state_from: face,
        };
        band_unit_weight(surface, band, choice, choices, &update, mass_before);
        update
    }

    fn save(&mut self, surface: &Surface, b: usize, j: usize) {
        self.old_height.clear();
        self.old_height.extend_from_slice(&surface.height[b..=j]);
        self.old_shear.clear();
        self.old_shear
            .extend_from_slice(&surface.accumulated_shear[b..=j]);
    }

    /// The block's nodes after its translation by (v0, rise): height,
    /// accumulated shear and arriving unit weight are those of the old
    /// surface at x − v0, by a second-order upwind remap (cell averages of
    /// a linear reconstruction limited by the monotonized central slope:
    /// conservative, no new extrema, and little of the smearing that linear
    /// interpolation would add every increment); next to the face, linear
    /// interpolation. Each column's unit weight mixes the soil that stayed
    /// below the band's lower boundary with the soil that arrived above it.
    fn carry_block(
        &self,
        surface: &mut Surface,
        band: &Band,
        (face, first_band): (usize, usize),
        (old_face_x, old_segment): (f64, f64),
        (v0, rise, gap): (f64, f64, f64),
    ) {
        let b = band.face.node;
        let c = surface.scheme.courant();
        for i in face + 1..first_band {
            let q = i - b;
            // Next to the face the source x − v0 lies between the old face
            // and node b + 1.
            let t = ((surface.x(i) - v0 - old_face_x) / old_segment).clamp(0.0, 1.0);
            let carried = |v: &[f64]| {
                if q == 1 {
                    v[0] + t * (v[1] - v[0])
                } else {
                    remap(v, q, c)
                }
            };
            surface.height[i] = carried(&self.old_height) + rise;
            surface.accumulated_shear[i] = carried(&self.old_shear);
            let arriving = carried(&self.old_unit_weight);
            mix_column(surface, band, i, (self.old_unit_weight[q], arriving), gap);
        }
    }

    /// Heights of the band's nodes before j: the surface soil at relative
    /// position f moved by f (v0, rise), remapped as the block's with the
    /// fraction f of its Courant number. The band's nodes keep their state.
    fn carry_band(&self, surface: &mut Surface, band: &Band, first_band: usize, c: f64, rise: f64) {
        let b = band.face.node;
        for i in first_band.max(b + 2)..band.emergence {
            let q = i - b;
            let f = self.position[q];
            surface.height[i] = remap(&self.old_height, q, f * c) + f * rise;
        }
    }
}

/// Cell average over [x_q − h/2 − v0, x_q + h/2 − v0] (c = v0/h) of the
/// limited linear reconstruction of the values `v` on a uniform grid.
fn remap(v: &[f64], q: usize, c: f64) -> f64 {
    let p = q - 1;
    (1.0 - c) * (v[q] - 0.5 * c * slope(v, q)) + c * (v[p] + 0.5 * (1.0 - c) * slope(v, p))
}

/// Monotonized central difference at q (0 at the ends and at extrema).
fn slope(v: &[f64], q: usize) -> f64 {
    if q == 0 || q + 1 >= v.len() {
        return 0.0;
    }
    let (back, ahead) = (v[q] - v[q - 1], v[q + 1] - v[q]);
    if back * ahead <= 0.0 {
        return 0.0;
    }
    let central = 0.5 * (back + ahead);
    central.signum() * central.abs().min(2.0 * back.abs()).min(2.0 * ahead.abs())
}
