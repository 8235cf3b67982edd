//! One increment's motion of the soil on the vertex ground (M48;
//! docs/model.md §3, and §9.1 for the node grid).
//!
//! The lower boundary of the band is the line from the tip (x_0, −d) to the
//! emergence point x_e, of slope tan β = (y(x_e) + d) / (x_e − x_0); the
//! upper boundary lies e above it. A point at height z above the lower
//! boundary has relative position g = z / e. The block (g ≥ 1) translates
//! by (v0, rise), band soil (0 < g < 1) by g (v0, rise), soil below stays
//! (M14, M18, M35). That map is affine on each side of the upper boundary,
//! so the image of a straight piece that does not cross it is straight:
//! moving the vertices, with one made where a piece crosses the upper
//! boundary and one at x_e, moves the surface exactly, and each piece's
//! state moves with it. Nothing is resampled.
//!
//! A slip line (e = 0) moves every vertex up to x_e with the block: the
//! emergence point is the block's corner. Vertices vertices the corner passes
//! over are buried under it, and the piece from the corner to the ground
//! ahead is the slip surface, which accumulates Δut (M15).
//!
//! What the face sweeps (the band soil that moved less than v0 and the soil
//! below the band, ½ v0 (e + rise), M20) is put back at the face by raising
//! the face vertex, the soil below the tip's path stays behind in the trench
//! (M38), the band accumulates Δut (M22, the full rule), a block piece's
//! unit weight mixes the soil it arrived with and the soil below the band
//! it now stands on (M26), and the band takes the one unit weight that
//! keeps the weight of soil unchanged (M27).

use super::Vertices;
use crate::band::dilation_gap;
use crate::case::{BandShearRule, UnitWeightRule};
use crate::mass::{compensated_sum, CompensatedSum};
use std::ops::Range;

/// The mechanism an increment moves the soil by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cut {
    /// d: depth of the blade tip below y = 0, the tip at (x_0, −d) (length).
    pub depth: f64,
    /// Δd: how much deeper the tip is after the increment (a depth path;
    /// negative where it rises) (length).
    pub deepening: f64,
    /// x_e: where the band's lower boundary meets the surface (length).
    pub emergence: f64,
    /// e: the band's vertical thickness, dB / cos β (0: a slip line) (length).
    pub thickness: f64,
    /// dB: the band's width, normal to it (length; unused for a slip line).
    pub width: f64,
    /// Pieces shorter than this are joined after the motion (length).
    pub min_spacing: f64,
    /// A crossing of the band's upper boundary closer than this to a
    /// vertex takes that vertex instead of making one (length).
    pub snap: f64,
    /// v0: the block's horizontal advance, the blade's increment (length).
    pub advance: f64,
    /// The block's rise: v0 tan(β + ψ), v0 tan β for a slip line (length).
    pub rise: f64,
    /// Δut: the band's shearing displacement (length).
    pub slip: f64,
    /// tan ψ of the band (0 for a slip line).
    pub tan_psi: f64,
    /// The shear of a raked blade's coordinates, in which the ground is
    /// held (`Rake`; the identity for a vertical blade).
    pub rake: crate::rake::Rake,
    /// How much of Δut the band's pieces accumulate (M22).
    pub band_shear: BandShearRule,
    /// How the band's unit weight is updated (M25, M27).
    pub unit_weight: UnitWeightRule,
}

impl Cut {
    /// ½ v0 Δd: the tip path's strip of area, taken from the ground at the
    /// face (negative where the tip rises, M38).
    fn path_strip(&self) -> f64 {
        0.5 * self.advance * self.deepening
    }
}

/// What an increment did to the ground.
#[derive(Clone, Debug, PartialEq)]
pub struct Moved {
    /// Area the band's dilation added, A0 Δut tan ψ / dB (M19).
    pub dilation_area: f64,
    /// Weight of the soil the tip passed over, left in the trench (M38).
    pub trench_mass: f64,
    /// The pieces of the band after the motion (for a slip line, the slip
    /// surface's piece ahead of the block's corner).
    pub band: std::ops::Range<usize>,
}

impl Vertices {
    /// Moves the soil by `cut` (M48) and keeps its weight exact; `None` (nothing
    /// changed) where the face lies in the band or the band's image folds
    /// over, which a band narrower than the vertices resolve does.
    pub fn apply(&mut self, cut: &Cut) -> Option<Moved> {
        let emergence = self.split_at(cut.emergence);
        let line = LowerBoundary::through(self, cut.depth, emergence);
        let banded = cut.thickness > 0.0;
        let (corner, emergence) = if banded {
            if line.position(self, 0, cut.thickness) < 1.0 {
                return None;
            }
            self.split_at_upper_boundary(&line, (cut.thickness, cut.snap), emergence)
        } else {
            (emergence, emergence)
        };
        let dilation_area = if banded {
            line.band_area(self, cut.thickness, emergence) * cut.slip * cut.tan_psi / cut.width
        } else {
            0.0
        };
        let before = PiecesBefore::of(self, (emergence + 1).min(self.pieces()));
        let last = self.sums_end(cut, emergence);
        let end = self.x[last];
        let (mass_before, area_before) = self.region(end);
        // The soil below the tip's path, from depth d to d + Δd, stays
        // behind in the trench (M38); what lies above it goes up the face.
        let below_path = -self.floor - cut.depth - 0.5 * cut.deepening;
        let target_area = area_before - cut.advance * below_path + dilation_area;
        let trench_mass = self.unit_weight[0] * cut.advance * below_path;
        let (band, shares) = if banded {
            self.shear_band(&line, cut, corner, emergence)?
        } else {
            (self.slide_over(cut, emergence), Vec::new())
        };
        self.lift(cut, corner..band.end, end, target_area);
        // The band's dilation under the block (0 for a slip line), in the
        // ground's coordinates (M16's stretch on a raked blade's).
        let t = cut.rake.physical(line.tan_beta).unwrap_or(line.tan_beta);
        let gap = dilation_gap(cut.slip, cut.tan_psi, (line.tan_beta, t));
        self.mix_block_pieces(&before, &line, band.start, gap);
        if banded {
            self.keep_band_state(&before, band.clone());
        }
        self.accumulate_shear(band.clone(), &shares, cut);
        self.trench_mass += trench_mass;
        self.weigh_moved(
            cut,
            band.clone(),
            dilation_area,
            mass_before - trench_mass,
            end,
        );
        let merged = self.merge_close(1, band.end + 2, cut.min_spacing);
        let band = band.start..band.end.saturating_sub(merged).max(band.start + 1);
        Some(Moved {
            dilation_area,
            trench_mass,
            band,
        })
    }

    /// The last vertex the sums that keep area and mass exact take.
    fn sums_end(&self, cut: &Cut, emergence: usize) -> usize {
        // Nothing beyond the second vertex after the emergence point moves,
        // unless the tip rises faster than the ground near the face can
        // give (`path_reach`): then the sums that keep area and mass exact
        // take the whole ground (an increment 15 vertices long rising 80,
        // from fuzzing `--set`: the mass drifted 1.4e-3 with the sums
        // stopping at the emergence point).
        // The block moves v0 along x, so its far end lands up to v0 past
        // the emergence vertex: where that is beyond the second vertex on,
        // the sums reach the first vertex past it (a slip line pushed 5 in
        // one increment over vertices 0.4 apart, from fuzzing `--set`: the
        // mass drifted 6e-5 with the sums stopping two vertices on).
        if self.rises_fast(cut) {
            self.pieces()
        } else {
            let landing = self.x[emergence] + cut.advance;
            let past = self.x.partition_point(|&x| x <= landing);
            (emergence + 2).max(past).min(self.pieces())
        }
    }

    /// Lifts the face's piece by the swept soil and the band's pieces
    /// `band` to the area `target_area` of the ground up to `end`.
    fn lift(&mut self, cut: &Cut, band: Range<usize>, end: f64, target_area: f64) {
        // The swept soil, ½ v0 (e + rise), on the face's piece (M20), and
        // the tip's path's share, ½ v0 Δd (M38), over the ground within v0
        // of the face (the node grid's face node): on the face's piece
        // alone, shorter than v0, a tip rising fast sank the face vertex
        // below the tip (a negative weight and force; the fuzz corpus's
        // scoop rising 82 mm an increment).
        let first = self.x[1] - self.x[0];
        self.y[0] += cut.advance * (cut.thickness + cut.rise) / first;
        if cut.deepening != 0.0 {
            let reach = self.path_reach(cut, end);
            self.lift_band(0..reach, cut.path_strip());
        }
        if cut.thickness > 0.0 {
            self.lift_band(band, target_area - self.region(end).1);
        }
    }

    /// The band's unit weight after the motion (M25, M27): the band as a
    /// whole holds `mass` of the ground up to `end`, or the paper's formula
    /// piece by piece.
    fn weigh_moved(
        &mut self,
        cut: &Cut,
        band: Range<usize>,
        dilation_area: f64,
        mass: f64,
        end: f64,
    ) {
        match cut.unit_weight {
            UnitWeightRule::BandUniform => self.weigh_band(band, mass, end),
            UnitWeightRule::PerNodeFormula if cut.thickness > 0.0 && dilation_area != 0.0 => {
                // The paper's A_new = A0 (1 + Δut tan ψ / dB) on each piece.
                let strain = cut.slip * cut.tan_psi / cut.width;
                for g in &mut self.unit_weight[band] {
                    *g /= 1.0 + strain;
                }
            }
            UnitWeightRule::PerNodeFormula => {}
        }
    }

    /// Makes a vertex wherever a piece between the face and the emergence
    /// vertex crosses the band's upper boundary; returns the last vertex
    /// of the block (g ≥ 1) and the emergence vertex after them.
    fn split_at_upper_boundary(
        &mut self,
        line: &LowerBoundary,
        (e, snap): (f64, f64),
        emergence: usize,
    ) -> (usize, usize) {
        let crossings: Vec<f64> = (0..emergence)
            .filter_map(|k| {
                let (g0, g1) = (line.position(self, k, e), line.position(self, k + 1, e));
                ((g0 - 1.0) * (g1 - 1.0) < 0.0).then(|| {
                    let lambda = (g0 - 1.0) / (g0 - g1);
                    self.x[k] + lambda * (self.x[k + 1] - self.x[k])
                })
            })
            .collect();
        let before = self.x.len();
        // The last crossing never snaps to the emergence vertex or halfway
        // to it: a band thinner than the snap would have no pieces, and
        // M27 none to weigh (issue 38: dB = d/200 drifted 1e-3 of the mass).
        let xe = self.x[emergence];
        let last = crossings
            .last()
            .map(|&x| self.split_near(x, snap.min(0.5 * (xe - x))));
        for &x in crossings.iter().rev().skip(1) {
            self.split_near(x, snap);
        }
        let emergence = emergence + self.x.len() - before;
        let corner = match last {
            Some(x) => self.x.partition_point(|&v| v < x),
            None => (0..emergence)
                .rev()
                .find(|&k| line.position(self, k, e) >= 1.0)
                .unwrap_or(0),
        };
        (corner, emergence)
    }

    /// The band's motion: vertex k moves by f_k (v0, rise), f_k = g_k
    /// clamped to [0, 1]; returns the band's pieces and every vertex's
    /// f_k up to the emergence vertex, or `None` if the images fold over.
    fn shear_band(
        &mut self,
        line: &LowerBoundary,
        cut: &Cut,
        corner: usize,
        emergence: usize,
    ) -> Option<(std::ops::Range<usize>, Vec<f64>)> {
        // The corner's g is 1 to round-off: it moves with the block.
        let share = |k: usize| match k <= corner {
            true => 1.0,
            false => line.position(self, k, cut.thickness).clamp(0.0, 1.0),
        };
        let shares: Vec<f64> = (0..=emergence).map(share).collect();
        let moved: Vec<f64> = (0..=emergence)
            .map(|k| self.x[k] + shares[k] * cut.advance)
            .collect();
        if moved.windows(2).any(|w| w[1] <= w[0]) {
            return None;
        }
        self.x[..=emergence].copy_from_slice(&moved);
        for (y, f) in self.y.iter_mut().zip(&shares) {
            *y += f * cut.rise;
        }
        Some((corner..emergence, shares))
    }

    /// Δut on the band's pieces (M22): all of it, or by position, a piece
    /// the mean of its vertices' f, its soil's mean displacement relative
    /// to the ground below the band (f is affine along a piece, which no
    /// upper boundary crosses). A slip line's piece lies on the line
    /// (f = 0), as the node grid's emergence node does.
    fn accumulate_shear(&mut self, band: std::ops::Range<usize>, shares: &[f64], cut: &Cut) {
        for k in band {
            let share = match cut.band_shear {
                BandShearRule::Full => 1.0,
                BandShearRule::ByPosition if shares.is_empty() => 0.0,
                BandShearRule::ByPosition => 0.5 * (shares[k] + shares[k + 1]),
            };
            self.accumulated_shear[k] += share * cut.slip;
        }
    }

    /// The slip line's motion (M14): the block's vertices move by
    /// (v0, rise); the emergence vertex stays, the ground's sheared point,
    /// and takes the height of the block's surface above it, so that the
    /// block's toe beyond it is cut off (as on the node grid, whose block
    /// lands on the emergence node; M27 keeps the mass); block vertices
    /// that reach it go. Returns the slip surface's piece, ahead of it, v0
    /// long (M15, M22).
    fn slide_over(&mut self, cut: &Cut, emergence: usize) -> std::ops::Range<usize> {
        let xe = self.x[emergence];
        let corner = (xe + cut.advance, self.y[emergence] + cut.rise);
        for k in 0..emergence {
            self.x[k] += cut.advance;
            self.y[k] += cut.rise;
        }
        let kept = (1..emergence)
            .find(|&k| self.x[k] >= xe)
            .unwrap_or(emergence);
        let (xa, ya) = (self.x[kept - 1], self.y[kept - 1]);
        self.y[emergence] = ya + (corner.1 - ya) * (xe - xa) / (corner.0 - xa);
        self.x.drain(kept..emergence);
        self.y.drain(kept..emergence);
        self.accumulated_shear.drain(kept..emergence);
        self.unit_weight.drain(kept..emergence);
        // The slip line shears a point of the ground: its piece is v0 long,
        // as the node grid's emergence node is.
        if self.x.get(kept + 1).is_some_and(|&x| x > xe + cut.advance) {
            self.split_at(xe + cut.advance);
        }
        kept..kept + 1
    }

    /// Weight and area of the pieces from the face to the vertex at `end`.
    fn region(&self, end: f64) -> (f64, f64) {
        let pieces = self.x.partition_point(|&x| x < end);
        let (mut mass, mut area) = (CompensatedSum::default(), CompensatedSum::default());
        for k in 0..pieces {
            let a = self.piece_area(k);
            mass.add(self.unit_weight[k] * a);
            area.add(a);
        }
        (mass.total(), area.total())
    }

    /// The band's state stays where it was (M48; docs/model.md §3.6, as on the
    /// node grid, whose band nodes keep theirs): each band piece, moved by
    /// the band's shear, takes the mean ut of the ground that lay under its
    /// new extent before the increment (a conservative remap within the
    /// band; the block's pieces carry theirs).
    fn keep_band_state(&mut self, before: &PiecesBefore, band: std::ops::Range<usize>) {
        let mut first = 0;
        for k in band {
            let (xa, xb) = (self.x[k], self.x[k + 1]);
            first = before.walk_to(first, xa);
            self.accumulated_shear[k] = before.mean_shear(first, xa, xb);
        }
    }

    /// The vertices that take the tip path's strip ½ v0 Δd (M38): those
    /// within v0 of the face, as the node grid's face node does, and, where
    /// a tip rising that fast would leave the face below it (the model's
    /// face holds soil from the tip up), as many more as keep the face
    /// vertex at the tip's new depth or above (a controller pulling the tip
    /// up by 19.7 d in one increment of d/500, from the fuzz corpus of the
    /// C ABI: the face sank 0.34 below the tip and the force went negative).
    /// Never the vertex at `end` or beyond, where the sums that keep the
    /// mass exact stop (a tip rising 224 in one increment of 2 reached
    /// past them, from the fuzz corpus of `--set`: the mass drifted 2e-3).
    fn path_reach(&self, cut: &Cut, end: f64) -> usize {
        let (near, mut weight) = self.near_face(cut.advance);
        let strip = cut.path_strip();
        if strip >= 0.0 {
            return near;
        }
        let last = self.x.partition_point(|&x| x < end);
        let room = self.face_above_new_tip(cut);
        let mut reach = near;
        while reach < last && -strip > room * weight {
            weight += self.vertex_share(reach);
            reach += 1;
        }
        reach
    }

    /// Whether the tip path's strip ½ v0 Δd is more than the ground within
    /// v0 of the face holds above the tip's new depth (`path_reach` then
    /// takes it from farther).
    fn rises_fast(&self, cut: &Cut) -> bool {
        let strip = cut.path_strip();
        // Every increment asks: at constant depth, nothing to sum.
        strip < 0.0 && -strip > self.face_above_new_tip(cut) * self.near_face(cut.advance).1
    }

    /// The vertices within v0 of the face (the face's at least) and the
    /// length of ground they stand for.
    fn near_face(&self, advance: f64) -> (usize, f64) {
        let near = self.x.partition_point(|&x| x <= self.x[0] + advance).max(1);
        (near, (0..near).map(|k| self.vertex_share(k)).sum())
    }

    /// Height of the face vertex above the tip's depth after the increment.
    fn face_above_new_tip(&self, cut: &Cut) -> f64 {
        self.y[0] + cut.depth + cut.deepening
    }

    /// Half of each piece beside vertex k: the length its height stands for.
    fn vertex_share(&self, k: usize) -> f64 {
        let left = if k == 0 {
            0.0
        } else {
            self.x[k] - self.x[k - 1]
        };
        0.5 * (left + self.x[k + 1] - self.x[k])
    }

    /// Raises `vertices` (the band's, from the block's corner to before the
    /// emergence vertex, or those near the face) by one height, so that
    /// the area changes by `residual` (M21: exactly the old area less the
    /// trench plus the dilation).
    fn lift_band(&mut self, vertices: std::ops::Range<usize>, residual: f64) {
        let total: f64 = vertices.clone().map(|k| self.vertex_share(k)).sum();
        let lift = residual / total;
        for y in &mut self.y[vertices] {
            *y += lift;
        }
    }

    /// Unit weight of the block's pieces after the motion (M26): the soil
    /// below the band's lower boundary stayed (γ of the ground that was
    /// there), the soil above it arrived with the piece, mixed by area over
    /// the piece (exact: the staying γ is integrated over the old pieces
    /// beneath it), less `gap` (height), the band's dilation under the
    /// block, which holds no soil (M26'). Without it the block's columns
    /// weighed the band's whole dilation at their own γ and M27 took that
    /// weight from the band's pieces at the emergence point alone, which a
    /// band that stays for many increments drove below zero (issue 38).
    fn mix_block_pieces(
        &mut self,
        before: &PiecesBefore,
        line: &LowerBoundary,
        block_end: usize,
        gap: f64,
    ) {
        let floor = self.floor;
        let at_rest = |x: f64| line.lower(x) - floor;
        // The block's pieces and the old pieces are both in order of x: the
        // old pieces under piece k start from the first under piece k − 1.
        let mut first_old = 0;
        for k in 0..block_end {
            let (xa, xb) = (self.x[k], self.x[k + 1]);
            let total = self.piece_area(k);
            // A linear walk, not a binary search: old and new pieces are
            // about one to one, so the walk takes a step or two a piece.
            first_old = before.walk_to(first_old, xa);
            let staying = before.weight_below(first_old, xa, xb, at_rest);
            let resting = 0.5 * (xb - xa) * (at_rest(xa) + at_rest(xb));
            let arriving = self.unit_weight[k] * (total - resting - gap * (xb - xa));
            self.unit_weight[k] = (staying + arriving) / total;
        }
    }

    /// Gives the band's pieces the one unit weight that makes the weight of
    /// the soil from the face to `end` equal `mass_before` (what it was less
    /// the trench's share): γ_band = (M_before − M_outside) / A_band (M27).
    fn weigh_band(&mut self, band: std::ops::Range<usize>, mass_before: f64, end: f64) {
        let pieces = self.x.partition_point(|&x| x < end);
        let outside = (0..pieces)
            .filter(|k| !band.contains(k))
            .map(|k| self.unit_weight[k] * self.piece_area(k));
        let outside = compensated_sum(outside);
        let area: f64 = band.clone().map(|k| self.piece_area(k)).sum();
        let gamma = (mass_before - outside) / area;
        for g in &mut self.unit_weight[band] {
            *g = gamma;
        }
    }
}

/// The band's lower boundary: from the tip (x_0, −d) to the emergence
/// vertex, frozen at the increment's start.
#[derive(Clone, Copy, Debug)]
struct LowerBoundary {
    x0: f64,
    depth: f64,
    tan_beta: f64,
}

impl LowerBoundary {
    fn through(ground: &Vertices, depth: f64, emergence: usize) -> Self {
        let x0 = ground.x[0];
        LowerBoundary {
            x0,
            depth,
            tan_beta: (ground.y[emergence] + depth) / (ground.x[emergence] - x0),
        }
    }

    /// Height of the lower boundary at x.
    fn lower(&self, x: f64) -> f64 {
        -self.depth + self.tan_beta * (x - self.x0)
    }

    /// g of vertex k: its height above the lower boundary in thicknesses e.
    fn position(&self, ground: &Vertices, k: usize, e: f64) -> f64 {
        (ground.y[k] - self.lower(ground.x[k])) / e
    }

    /// A0: the band's area below the surface from the face to the emergence
    /// vertex, ∫ min(g, 1) e dx, exact once no piece crosses g = 1.
    fn band_area(&self, ground: &Vertices, e: f64, emergence: usize) -> f64 {
        let g = |k: usize| self.position(ground, k, e).clamp(0.0, 1.0);
        (0..emergence)
            .map(|k| 0.5 * (ground.x[k + 1] - ground.x[k]) * e * (g(k) + g(k + 1)))
            .sum()
    }
}

/// The ground from the face to the emergence vertex before the motion:
/// where each old piece lay and its unit weight.
struct PiecesBefore {
    x: Vec<f64>,
    unit_weight: Vec<f64>,
    shear: Vec<f64>,
}

impl PiecesBefore {
    /// The pieces before vertex `end`.
    fn of(ground: &Vertices, end: usize) -> Self {
        PiecesBefore {
            x: ground.x[..=end].to_vec(),
            unit_weight: ground.unit_weight[..end].to_vec(),
            shear: ground.accumulated_shear[..end].to_vec(),
        }
    }

    /// Mean ut of the old pieces over [xa, xb] (the last old piece reaches
    /// beyond its end); the old pieces before `first` lie before xa.
    fn mean_shear(&self, first: usize, xa: f64, xb: f64) -> f64 {
        let mut sum = 0.0;
        self.each_overlap(first, (xa, xb), true, |k, lo, hi| {
            sum += self.shear[k] * (hi - lo);
        });
        sum / (xb - xa)
    }

    /// The old piece holding x, walking on from `from` (one at or before
    /// it): the last k with x_k ≤ x, at most the last old piece.
    fn walk_to(&self, mut from: usize, x: f64) -> usize {
        let last = self.unit_weight.len() - 1;
        while from < last && self.x[from + 1] <= x {
            from += 1;
        }
        from
    }

    /// ∫ γ_old(x) h(x) dx over [xa, xb], h the height of the soil that
    /// stayed (linear): the weight of the soil that stayed below a piece
    /// now over [xa, xb]; the old pieces before `first` lie before xa.
    fn weight_below(&self, first: usize, xa: f64, xb: f64, height: impl Fn(f64) -> f64) -> f64 {
        let mut weight = 0.0;
        self.each_overlap(first, (xa, xb), false, |k, s0, s1| {
            weight += self.unit_weight[k] * 0.5 * (s1 - s0) * (height(s0) + height(s1));
        });
        weight
    }

    /// `visit(k, lo, hi)` for each old piece k from `first` on that overlaps
    /// [xa, xb], lo < hi the overlap, in order of x; with `open_end` the
    /// last old piece reaches to xb, beyond its end. A plain loop: as an
    /// iterator's adaptors it cost a tenth of the motion.
    #[inline]
    fn each_overlap(
        &self,
        first: usize,
        (xa, xb): (f64, f64),
        open_end: bool,
        mut visit: impl FnMut(usize, f64, f64),
    ) {
        let last = self.unit_weight.len() - 1;
        let mut k = first;
        while k <= last && self.x[k] < xb {
            let hi = if open_end && k == last {
                xb
            } else {
                self.x[k + 1].min(xb)
            };
            let lo = self.x[k].max(xa);
            if hi > lo {
                visit(k, lo, hi);
            }
            k += 1;
        }
    }
}
