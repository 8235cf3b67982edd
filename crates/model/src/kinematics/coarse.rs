//! The update on a coarse node grid, h = k v0 with k > 1 (docs/model.md,
//! "Discretisation").
//!
//! The motion is that of the reference scheme: the block above the band
//! translates by v0 (1, tan(β* + ψ)), band soil by the fraction f of it at
//! relative position f, soil below stays. The face moves by v0, a fraction
//! 1/k of a node spacing, so the block no longer lands on nodes: the image
//! of the old surface (the polyline through the images of its nodes and of
//! its crossings of the band's upper boundary, exact for this piecewise
//! affine map) is sampled at the grid nodes between the new face and the
//! emergence node, and the block's accumulated shear and unit weight are
//! taken from where its soil came from, x − v0 (linear between the old
//! nodes). The face node carries the face's own soil; the soil the face
//! sweeps over (below the block, ½ v0 (e + v0 tan(β* + ψ) + Δd)) is put on
//! the face node's half segment. What sampling gains or loses in area is
//! spread over the band's nodes (the nodes past the block's image) so that
//! the area is exactly the old area plus the dilation, and the band's unit
//! weight keeps the weight of soil exact, as on the reference grid.

use super::{band_unit_weight, region_area, region_mass, Advance, BandMotion, Kinematics, Update};
use crate::band::Band;
use crate::case::{BandShearRule, Choices};
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
        let (b, j, v0) = (band.blade, band.emergence, advance.increment);
        let deepening = advance.deepening;
        let trench_area = v0 * (-surface.floor - band.depth - 0.5 * deepening);
        let trench_mass = surface.unit_weight[b] * trench_area;
        let mass_before = region_mass(surface, b, b..j + 1) - trench_mass;
        let area_before = region_area(surface, b, j + 1);
        let old_x: Vec<f64> = (b..=j).map(|i| surface.x(i)).collect();
        self.save(surface, b, j);
        let band_motion = BandMotion::new(choice, rake, v0).filter(|_| band.thickness > 0.0);
        let traced =
            band_motion.and_then(|m| self.trace_image(surface, band, m.rise, v0).map(|x| (m, x)));
        let (motion, last_block_x, thickness) = match traced {
            Some((m, x)) => (m, x, band.thickness),
            None => {
                let slip_line = Band {
                    thickness: 0.0,
                    ..*band
                };
                let m = slip_motion(choice, rake, v0);
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
        surface.face_offset = advance.face_offset;
        let face = advance.face;
        self.resample(surface, face, j);
        let first_band = (face + 1..=j)
            .find(|&i| surface.x(i) > last_block_x)
            .unwrap_or(j);
        self.carry_block_state(surface, band, &old_x, face, first_band, v0);
        // The face node: the face's own soil, risen with the block, and the
        // soil the face swept over on its half segment.
        let swept = 0.5 * v0 * (thickness + motion.rise + deepening);
        let half_segment = 0.5 * (1.0 - advance.face_offset) * surface.spacing;
        surface.height[face] = self.old_height[0] + motion.rise + swept / half_segment;
        surface.accumulated_shear[face] = self.old_shear[0];
        surface.unit_weight[face] = self.old_unit_weight[0];
        let left_behind = v0 * (-surface.floor - band.depth);
        let residual =
            area_before - left_behind + dilation_area - region_area(surface, face, j + 1);
        let weights: f64 = (first_band..=j).map(|i| surface.node_weight(i, face)).sum();
        let correction = residual / (weights * surface.spacing);
        for y in &mut surface.height[first_band..=j] {
            *y += correction;
        }
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
        self.old_unit_weight.clear();
        self.old_unit_weight
            .extend_from_slice(&surface.unit_weight[b..=j]);
    }

    /// The block's nodes take the accumulated shear of the soil that
    /// arrived (from x − v0) and the unit weight of their column mixed by
    /// area: below the band's lower boundary the soil stayed, above it came
    /// from x − v0.
    fn carry_block_state(
        &self,
        surface: &mut Surface,
        band: &Band,
        old_x: &[f64],
        face: usize,
        first_band: usize,
        v0: f64,
    ) {
        let mut p = 0;
        for i in face + 1..first_band {
            let source = surface.x(i) - v0;
            while p + 2 < old_x.len() && old_x[p + 1] < source {
                p += 1;
            }
            let t = ((source - old_x[p]) / (old_x[p + 1] - old_x[p])).clamp(0.0, 1.0);
            let lerp = |v: &[f64]| v[p] + t * (v[p + 1] - v[p]);
            surface.accumulated_shear[i] = lerp(&self.old_shear);
            let arriving = lerp(&self.old_unit_weight);
            let staying = self.old_unit_weight[i - band.blade];
            let total = surface.height[i] - surface.floor;
            let at_rest = (band.lower(i) - surface.floor).clamp(0.0, total);
            surface.unit_weight[i] = (staying * at_rest + arriving * (total - at_rest)) / total;
        }
    }

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
                BandShearRule::ByPosition => {
                    self.position.get(i - band.blade).copied().unwrap_or(0.0)
                }
            };
            surface.accumulated_shear[i] += share * slip;
        }
    }
}

/// The slip line's motion: the block slides along it, rise v0 tan β on
/// the grid, Δut = v0 / cos β (`Rake` for a raked blade).
fn slip_motion(choice: &Choice, rake: &Rake, v0: f64) -> BandMotion {
    let t = choice.tan_beta;
    BandMotion {
        rise: v0 * choice.grid_slope,
        slip: v0 * (1.0 + t * t).sqrt() / (1.0 + rake.cot * t),
        tan_psi: 0.0,
    }
}
