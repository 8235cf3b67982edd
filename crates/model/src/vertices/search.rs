//! The search for the least force on the vertex ground (M49;
//! docs/model.md §2.1, §2.8, §2.11, and §9.1 for the node grid): the band may emerge
//! anywhere on the ground, not only at vertices.
//!
//! For an emergence point x on piece k (x_k ≤ x < x_{k+1}), with the tip at
//! (x_0, −d) and tan β = (y(x) + d) / (x − x_0):
//!
//! * the line stays inside the soil iff every vertex before x lies on or
//!   above it, tan β ≤ min_i (y_i + d) / (x_i − x_0) (M3);
//! * the block's weight is the exact integral over its pieces,
//!   W = Σ γ_i ∫ (y − y_line) dx = S_A(x) − tan β S_B(x), with
//!   S_A = Σ γ_i ½ Δx_i (y_i + y_{i+1} + 2d) and
//!   S_B = Σ γ_i ½ Δx_i (x_i + x_{i+1} − 2 x_0) up to x (M5);
//! * the band's angles are the means of φ(ut), ψ(ut) and ut over its
//!   footprint [x − L, x], L = e / (tan β − s) with s the surface's secant
//!   slope over the flat-ground footprint e / tan β (M10, M17), integrals
//!   of piecewise constant state;
//! * P = W (P/W)(β, φ) with the loads, Eq. (1) (M6, M8).
//!
//! Every one is O(1) from prefix sums at the vertices (O(log n) for the
//! footprint's rear end). The search samples every piece at spacing
//! dB / K (the sampled search of (M47), here along the ground; coarser
//! for flat bands, M52, and once for vertices crowded closer than h/4,
//! M54), stops
//! where the block's weight times the least factor passes the best force
//! (M31), then narrows every local minimum of the samples within 0.5 % of
//! the least by golden-section search down to the resolution.

use super::midpoint::{half_slip, midpoint_force};
use super::scan::{Pick, Scan};
use super::Vertices;
use crate::band::stretch;
use crate::force_bounds::{may_win, Lower};
use crate::laws::BandAngles;

/// Local minima of the samples within this fraction of the least are
/// narrowed, and the first stage prunes against it (the sampled search's
/// slack, (M47); measured against the former 2 % in docs/performance.md,
/// "Issue 28, fourth step: the midpoint force and d/350", with the
/// ensembles of `docs/studies/vertex-ground/`; docs/model.md §2.8).
const SLACK: f64 = 0.005;
/// A vertex near the least's emergence point takes the band if its force
/// is within this fraction of the least.
const SNAP_SLACK: f64 = 1e-3;
/// Every LEAD-th sample is evaluated first: a bar near the least before
/// the rest (`fill_samples`).
const LEAD: usize = 8;
/// tan 10°: a band emerging on a piece seen from the tip at a flatter
/// angle has a footprint of at least dB / tan β along the ground, and the
/// search samples it coarser in proportion (M52, `far_spacing`); 10°
/// against 15° and 20° is measured in docs/performance.md, "Issue 39,
/// second step: flat bands sampled by their footprint (M52)" (docs/model.md
/// §2.11).
const FLAT_BAND: f64 = 0.176_326_980_708_464_97;
/// A vertex closer than this many h (`run.vertex_spacing`) to the last
/// vertex sampled takes no sample of its own (M54, `VertexSearch::crowded`):
/// crowded vertices lie a few v0 apart, far closer than h / 4; h / 4
/// against h / 2 and h is measured in docs/performance.md, "Issue 39,
/// fourth step: crowded vertices sampled once (M54)" (docs/model.md §2.11).
const CROWDED: f64 = 0.25;
/// 1 / golden ratio.
const INVERSE_PHI: f64 = 0.618_033_988_749_894_8;

/// A first-stage candidate: its emergence point, piece and force (NaN
/// until evaluated, infinite if inadmissible or pruned).
#[derive(Clone, Copy, Debug)]
struct Sample {
    x: f64,
    piece: usize,
    force: f64,
}

/// Prefix sums at vertex k: the integrals from the face to x_k.
#[derive(Clone, Copy, Debug, Default)]
struct Row {
    sum_a: f64,
    sum_b: f64,
    /// ∫ φ, ∫ ψ, ∫ ut.
    state: [f64; 3],
    /// min over vertices 1..k (before k) of (y_i + d) / (x_i − x_0).
    least_slope: f64,
    /// (y_k + d) / (x_k − x_0), vertex k's (infinite at the face): the
    /// admissibility slope, the stopping rule's and (M52)'s, computed once.
    slope: f64,
    /// Whether a piece before k stands steeper than its φ(ut) (M53: its
    /// φ̂ is then the floor, and a band crossing it is not fresh soil).
    lifted: bool,
}

/// The search's reusable scratch.
/// The line of a candidate band from the tip to its emergence point.
#[derive(Clone, Copy, Debug)]
struct Emergence {
    /// y of the emergence point.
    y: f64,
    /// x − x_0: the emergence point's distance from the face.
    run: f64,
    /// tan β in the ground's coordinates (sheared on a raked blade).
    grid: f64,
    /// tan β physical.
    t: f64,
    /// The slip line's length.
    length: f64,
    /// The block's weight per unit width (≥ 0).
    weight: f64,
}

#[derive(Clone, Debug, Default)]
pub(crate) struct VertexSearch {
    rows: Vec<Row>,
    /// φ, ψ of each piece scanned (radians).
    angles: Vec<(f64, f64)>,
    samples: Vec<Sample>,
    /// The least φ of the pieces scanned and Eq. (1) at it: a band's mean
    /// φ is no less, so W (P/W)(β, φ_least) bounds its force (as on the
    /// node grid, `Lower::can_beat`).
    least: Option<(f64, Lower)>,
    /// The pieces of the last footprint's two ends (`Vertices::piece_near`).
    hints: [usize; 2],
    /// Eq. (1) evaluations so far.
    pub(crate) evaluations: u64,
    /// Where the next sample on a flat band's piece lies (M52).
    next_sample: f64,
    /// The last vertex that took a sample (M54).
    last_vertex_sample: f64,
}

/// What the prefix sums count below the line at the face where the face
/// vertex lies below the tip (a tip pulled up faster than the ground
/// follows): there the line runs through air, which weighs nothing, so
/// the block's weight is ∫ max(y − y_line, 0), and this adds back the
/// negative part over piece 0, γ_0 ½ Δx g_0² / (g_end − g_0) with g the
/// height above the line (g_0 < 0 at the face, g_end ≥ 0 at the piece's
/// end by (M3), or 0 at the emergence point on piece 0). 0 where the face
/// vertex is at or above the tip, as every cut that does not steer keeps it.
fn air_at_face(ground: &Vertices, (k, x, y): (usize, f64, f64), (d, grid): (f64, f64)) -> f64 {
    let g0 = ground.y[0] + d;
    if g0 >= 0.0 {
        return 0.0;
    }
    let x0 = ground.x[0];
    let (end, y_end) = if k == 0 {
        (x, y)
    } else {
        (ground.x[1], ground.y[1])
    };
    let g_end = (y_end + d - grid * (end - x0)).max(0.0);
    ground.unit_weight[0] * 0.5 * (end - x0) * g0 * g0 / (g_end - g0)
}

/// The first stage's spacing on piece k if a band there is flatter than
/// `FLAT_BAND` (M52): dB / K times tan 10° / tan β, tan β the slope from
/// the tip to the piece's start in the ground's coordinates, so that a
/// band's footprint, dB / tan β along flat ground, holds K / tan 10°
/// samples however flat the band; `None` (the spacing `scan.sample`, a
/// sample at the vertex) on steeper pieces, for a slip line (whose
/// strength jumps at every vertex, no footprint averaging it) and for the
/// exhaustive search.
fn far_spacing(scan: &Scan, (k, t): (usize, f64)) -> Option<f64> {
    if k == 0 || !scan.thins_samples {
        return None;
    }
    (t > 0.0 && t < FLAT_BAND).then(|| scan.sample * FLAT_BAND / t)
}

/// Is handed every candidate the first stage evaluates, which then prunes
/// none (a landscape, as the node grid's `node_search::Observer`).
pub(crate) type PickObserver<'o> = &'o mut dyn FnMut(&Pick);

impl VertexSearch {
    /// The least-force mechanism, if any is admissible before `scan.reach`;
    /// with `observer`, the first stage prunes nothing and hands it every
    /// candidate it evaluates.
    pub(crate) fn run(
        &mut self,
        ground: &mut Vertices,
        scan: &Scan,
        mut observer: Option<PickObserver>,
    ) -> Option<Pick> {
        self.start();
        let stride = if observer.is_some() { 1 } else { LEAD };
        let mut best: Option<Pick> = None;
        let mut k = 0;
        // Every piece is scanned, the last one's too where the ground ends
        // at `scan.reach` (the end wall): a band emerges before it. The
        // ground grows by `scan.grow` up to `scan.reach`, so the pieces
        // scanned are bounded: the ground's and (reach − end) / grow more.
        while k < ground.pieces() {
            let end = ground.x[ground.pieces()];
            // A piece of no length to round-off (reach within an ulp of
            // the end) is not appended: its band gave 0 / 0.
            let grow = scan.grow.min(scan.reach - end);
            if k + 1 == ground.pieces() && end + grow > end {
                ground.extend_flat(grow);
            }
            self.push_row(ground, scan, k);
            if self.beyond_reach(ground, scan, k, best.as_ref()) {
                break;
            }
            self.sample_piece(ground, scan, (k, stride), &mut best, &mut observer);
            k += 1;
        }
        self.fill_samples(ground, scan, &mut best);
        let best = self.narrow(ground, scan, best?);
        Some(self.snap(ground, scan, best))
    }

    /// The least candidate at a vertex within `scan.snap` of the least's
    /// emergence point, if one is within `SNAP_SLACK` of its force (a
    /// vertex's piece may hold other soil, which a band there would shear
    /// instead); else the least itself, whose point becomes a vertex.
    fn snap(&mut self, ground: &Vertices, scan: &Scan, best: Pick) -> Pick {
        let k = ground.piece_at(best.x);
        let mut snapped: Option<Pick> = None;
        for v in [k, k + 1] {
            let near = (ground.x[v] - best.x).abs() <= scan.snap;
            if v == 0 || v + 1 >= self.rows.len() || !near {
                continue;
            }
            if let Some(pick) = self.evaluate(ground, scan, (v, ground.x[v]), f64::INFINITY) {
                if snapped.is_none_or(|s| pick.force < s.force) {
                    snapped = Some(pick);
                }
            }
        }
        snapped
            .filter(|s| s.force <= best.force * (1.0 + SNAP_SLACK))
            .unwrap_or(best)
    }

    fn start(&mut self) {
        self.rows.clear();
        self.angles.clear();
        self.samples.clear();
        self.least = None;
        self.hints = [0, 0];
        self.last_vertex_sample = f64::NEG_INFINITY;
        self.rows.push(Row {
            least_slope: f64::INFINITY,
            slope: f64::INFINITY,
            ..Row::default()
        });
    }

    /// Adds piece k to the prefix sums (row k + 1).
    fn push_row(&mut self, ground: &Vertices, scan: &Scan, k: usize) {
        let material = &scan.laws.material;
        let ut = ground.accumulated_shear[k];
        // Most of the ground ahead is fresh: its angles are known.
        let (law, psi) = if ut == 0.0 {
            (scan.laws.fresh.friction, scan.laws.fresh.dilation)
        } else {
            (material.friction.at(ut), material.dilation.at(ut))
        };
        // φ̂_k under the crossed columns (M53), else φ(ut_k).
        let phi = scan.columns.map_or(law, |c| c.friction(ground, k, law));
        self.angles.push((phi, psi));
        if self.least.is_none_or(|(least, _)| phi < least) {
            self.least = Some((phi, Lower::new(phi, scan.laws)));
        }
        let row = self.rows[k];
        let (x0, d) = (ground.x[0], scan.depth);
        let (xa, xb, ya, yb) = (ground.x[k], ground.x[k + 1], ground.y[k], ground.y[k + 1]);
        let g = ground.unit_weight[k];
        let dx = xb - xa;
        self.rows.push(Row {
            sum_a: row.sum_a + g * 0.5 * dx * (ya + yb + 2.0 * d),
            sum_b: row.sum_b + g * 0.5 * dx * (xa + xb - 2.0 * x0),
            state: [
                row.state[0] + phi * dx,
                row.state[1] + psi * dx,
                row.state[2] + ut * dx,
            ],
            least_slope: row.least_slope.min(row.slope),
            slope: (yb + d) / (xb - x0),
            lifted: row.lifted || phi > law,
        });
    }

    /// The stopping rule (M31): the weight of the block to x_k bounds that
    /// of every candidate beyond, times the least P/W.
    fn beyond_reach(&self, ground: &Vertices, scan: &Scan, k: usize, best: Option<&Pick>) -> bool {
        let Some(best) = best else { return false };
        if k == 0 {
            return false;
        }
        let row = &self.rows[k];
        let run = ground.x[k] - ground.x[0];
        scan.bound_weight(row.sum_a - row.slope * row.sum_b, run) * scan.laws.min_factor
            > best.force
    }

    /// The first stage on piece k: candidates from x_k (not the face, nor
    /// a crowded vertex, M54) at spacing `scan.sample`, or, on a piece
    /// seen from the tip flatter
    /// than `FLAT_BAND` where the search coarsens, from where the last
    /// piece's samples stopped at the spacing `far_spacing` (M52); of
    /// which every `stride`-th along the ground is evaluated now (the
    /// lead) and the rest by `fill_samples`; each handed to `observer` if
    /// there is one.
    fn sample_piece(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (k, stride): (usize, usize),
        best: &mut Option<Pick>,
        observer: &mut Option<PickObserver>,
    ) {
        let (xa, xb) = (ground.x[k], ground.x[k + 1]);
        if let Some(spacing) = far_spacing(scan, (k, self.rows[k].slope)) {
            let mut x = self.next_sample.max(xa);
            // Bounded by the samples the piece holds, two over for the
            // sums' round-off: a spacing below the round-off of x (which
            // validation refuses) would not advance it.
            let most = ((xb - x) / spacing).ceil() as usize + 2;
            for _ in 0..most {
                if x >= xb {
                    break;
                }
                self.push_sample(ground, scan, (k, x, stride), best, observer);
                x += spacing;
            }
            self.next_sample = x;
            return;
        }
        let n = ((xb - xa) / scan.sample).ceil().max(1.0) as usize;
        for i in usize::from(k == 0)..n {
            let x = xa + (xb - xa) * i as f64 / n as f64;
            if i == 0 {
                if self.crowded(scan, x) {
                    continue;
                }
                self.last_vertex_sample = x;
            }
            self.push_sample(ground, scan, (k, x, stride), best, observer);
        }
        self.next_sample = xb;
    }

    /// Whether the vertex at x lies closer than `CROWDED` h to the last
    /// vertex that took a sample, where the search thins its samples
    /// (M54): vertices crowd where the bands have sheared the ground (each
    /// increment cuts the ground at the band's upper boundary and its
    /// emergence point), pieces there a few v0 long, and a sample at each
    /// of them is denser than the ground's own h; a slip line (whose
    /// strength jumps at every vertex) and the exhaustive search keep every
    /// vertex.
    fn crowded(&self, scan: &Scan, x: f64) -> bool {
        scan.thins_samples && x - self.last_vertex_sample < CROWDED * scan.vertex_spacing
    }

    /// A first-stage candidate at x on piece k: evaluated now if it is
    /// the lead's (every `stride`-th), else left for `fill_samples`.
    fn push_sample(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (k, x, stride): (usize, f64, usize),
        best: &mut Option<Pick>,
        observer: &mut Option<PickObserver>,
    ) {
        let force = if self.samples.len().is_multiple_of(stride) {
            self.sample(ground, scan, (k, x), best, observer)
        } else {
            f64::NAN
        };
        self.samples.push(Sample { x, piece: k, force });
    }

    /// The samples the lead left, in order along the ground, against the
    /// best force so far: with the lead's best as the bar from the start,
    /// the samples short of the least are mostly pruned, where scanning
    /// from the face made each of them the best so far in turn. Samples
    /// beyond the stopping rule (M31) under the best found are dropped.
    fn fill_samples(&mut self, ground: &Vertices, scan: &Scan, best: &mut Option<Pick>) {
        let mut samples = std::mem::take(&mut self.samples);
        let mut piece = usize::MAX;
        for i in 0..samples.len() {
            let k = samples[i].piece;
            if k != piece {
                piece = k;
                if self.beyond_reach(ground, scan, k, best.as_ref()) {
                    samples.truncate(i);
                    break;
                }
            }
            if samples[i].force.is_nan() {
                samples[i].force = self.sample(ground, scan, (k, samples[i].x), best, &mut None);
            }
        }
        self.samples = samples;
    }

    /// One first-stage candidate: its force (infinite if inadmissible or
    /// pruned), taken as the best if it is, and handed to `observer`.
    fn sample(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (k, x): (usize, f64),
        best: &mut Option<Pick>,
        observer: &mut Option<PickObserver>,
    ) -> f64 {
        let bar = match (observer.as_ref(), &*best) {
            (None, Some(b)) => b.force * (1.0 + SLACK),
            _ => f64::INFINITY,
        };
        let Some(pick) = self.evaluate(ground, scan, (k, x), bar) else {
            return f64::INFINITY;
        };
        if let Some(observe) = observer {
            observe(&pick);
        }
        if best.is_none_or(|b| pick.force < b.force) {
            *best = Some(pick);
        }
        pick.force
    }

    /// The band's line from the tip to x on piece k, if admissible (M3,
    /// M34): its geometry and the block's weight from the prefix sums.
    fn emergence(&self, ground: &Vertices, scan: &Scan, (k, x): (usize, f64)) -> Option<Emergence> {
        let (x0, d) = (ground.x[0], scan.depth);
        let row = self.rows[k];
        let (xa, ya) = (ground.x[k], ground.y[k]);
        let y = ya + (x - xa) * (ground.y[k + 1] - ya) / (ground.x[k + 1] - xa);
        let run = x - x0;
        let t = (y + d) / run;
        // Vertex k is before x unless x is vertex k (M3).
        let least = if x > xa && k > 0 {
            row.least_slope.min(row.slope)
        } else {
            row.least_slope
        };
        // The block's rear, the face, stays behind the emergence point: a
        // band within v0 of the face would carry the face over it (the
        // node grid's emergence node is at least one node, v0, ahead), and
        // one v0 ahead to round-off onto it (a piece of no length: the
        // face at 0.4 + 0.2 and the band at 0.6000000000000001, from the
        // C ABI's fuzzing), so by a margin far above round-off.
        if !(t > 0.0 && t <= least && run > scan.advance * (1.0 + 1e-6)) {
            return None;
        }
        // tan β physical (β < 90°, M34) and the slip line's length.
        let grid = t;
        let t = scan.rake.physical(grid)?;
        let length = run - (y + d) * scan.rake.cot;
        let g = ground.unit_weight[k];
        let part = x - xa;
        let sum_a = row.sum_a + g * 0.5 * part * (ya + y + 2.0 * d);
        let sum_b = row.sum_b + g * 0.5 * part * (xa + x - 2.0 * x0);
        // ≥ 0: a band through air at the face (`air_at_face`) weighs 0, not
        // its round-off.
        let weight = (sum_a - grid * sum_b + air_at_face(ground, (k, x, y), (d, grid))).max(0.0);
        Some(Emergence {
            y,
            run,
            grid,
            t,
            length,
            weight,
        })
    }

    /// The candidate emerging at x on piece k (M49; the prefix sums must
    /// reach row k + 1), if admissible and able to come under `bar`.
    fn evaluate(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (k, x): (usize, f64),
        bar: f64,
    ) -> Option<Pick> {
        let Emergence {
            y,
            run,
            grid,
            t,
            length,
            weight,
        } = self.emergence(ground, scan, (k, x))?;
        // No band here can come within the slack of the best: P ≥ W f_min.
        let (_, lower) = self.least.expect("a piece scanned");
        let bound = scan.bound_weight(weight, run);
        if !lower.can_beat(bound, t, bar, &scan.face) {
            return None;
        }
        let (mut angles, rear) = self.footprint_angles(ground, scan, (k, x, y), (grid, t));
        // Beyond the paper (M53): the columns crossed from the face to x;
        // the footprint's rear stays where the motion's Δut goes (M22).
        if scan.columns.is_some() {
            angles = self.crossed_means(ground, scan, (k, x));
        }
        let angles = scan.laws.band_angles(angles);
        // Eq. (1) at the band's φ rounded down on the table's grid.
        if !may_win((scan.laws, &scan.face), (bound, t), &angles, bar) {
            return None;
        }
        self.evaluations += 1;
        let factor = scan.laws.factor(angles, t, scan.face);
        let force = scan.force(&factor, (weight, length, t), run)?;
        let pick = Pick {
            x,
            y,
            tan_beta: t,
            grid_slope: grid,
            length,
            force,
            angles,
            weight,
            rear,
        };
        // A band already above the bar stays above it half an increment on.
        if !scan.choose_at_midpoint || force >= bar {
            return Some(pick);
        }
        Some(midpoint_force(ground, scan, pick, half_slip(scan, &pick)))
    }

    /// The means of φ̂, ψ and ut over the columns from the face to x on
    /// piece k, weighted by the band's length in each (M53): the prefix
    /// integrals over [x_0, x]. Fresh where every one of them is
    /// unsheared and stands no steeper than its φ(ut).
    fn crossed_means(&self, ground: &Vertices, scan: &Scan, (k, x): (usize, f64)) -> BandAngles {
        let run = x - ground.x[0];
        let hi = self.integral(ground, k, x);
        let law = scan.laws.material.friction.at(ground.accumulated_shear[k]);
        let lifted = self.rows[k].lifted || (x > ground.x[k] && self.angles[k].0 > law);
        BandAngles {
            friction: hi[0] / run,
            dilation: hi[1] / run,
            shear: hi[2] / run,
            fresh: hi[2] == 0.0 && !lifted,
        }
    }

    /// Means of φ, ψ and ut over the band's footprint [x − L, x] (M10,
    /// M17), and x − L; for a slip line, piece k's, and x. The band at
    /// x on piece k, height y, of slope `grid` in the ground's
    /// coordinates and tan β = `t`: its vertical thickness there is
    /// e = dB / cos β times M16's stretch tan β' / tan β, its footprint a
    /// length of the ground's x.
    fn footprint_angles(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (k, x, y): (usize, f64, f64),
        (grid, t): (f64, f64),
    ) -> (BandAngles, f64) {
        let ut = ground.accumulated_shear[k];
        let (phi, psi) = self.angles[k];
        if scan.band_width == 0.0 {
            let angles = BandAngles {
                friction: phi,
                dilation: psi,
                shear: ut,
                fresh: ut == 0.0,
            };
            return (angles, x);
        }
        let run = x - ground.x[0];
        let e = scan.band_width * (1.0 + t * t).sqrt() * stretch(grid, t);
        let flat = (e / grid).min(run);
        self.hints[0] = ground.piece_near(self.hints[0], x - flat);
        let back = self.hints[0].min(k);
        let s = (y - ground.height_on(back, x - flat)) / flat;
        let length = if grid > s {
            (e / (grid - s)).min(run)
        } else {
            run
        };
        let rear = x - length;
        let hi = self.integral(ground, k, x);
        self.hints[1] = ground.piece_near(self.hints[1], rear);
        let lo = self.integral(ground, self.hints[1].min(k), rear);
        let mean = |i: usize| (hi[i] - lo[i]) / length;
        let angles = BandAngles {
            friction: mean(0),
            dilation: mean(1),
            shear: mean(2),
            fresh: hi[2] == lo[2],
        };
        (angles, rear)
    }

    /// ∫ φ, ψ, ut from the face to x on piece k.
    fn integral(&self, ground: &Vertices, k: usize, x: f64) -> [f64; 3] {
        let row = self.rows[k];
        let part = x - ground.x[k];
        let (phi, psi) = self.angles[k];
        let ut = ground.accumulated_shear[k];
        [
            row.state[0] + phi * part,
            row.state[1] + psi * part,
            row.state[2] + ut * part,
        ]
    }

    /// The second stage (M49): every local minimum of the samples within
    /// `SLACK` of the least, narrowed by golden-section search to
    /// `scan.resolution`; returns the least found.
    fn narrow(&mut self, ground: &Vertices, scan: &Scan, mut best: Pick) -> Pick {
        let bar = best.force * (1.0 + SLACK);
        let samples = std::mem::take(&mut self.samples);
        for i in 0..samples.len() {
            let Sample { x, force: f, .. } = samples[i];
            let left = if i == 0 {
                f64::INFINITY
            } else {
                samples[i - 1].force
            };
            let right = samples.get(i + 1).map_or(f64::INFINITY, |s| s.force);
            if !(f <= bar && f <= left && f <= right) {
                continue;
            }
            let lo = if i == 0 { x } else { samples[i - 1].x };
            let hi = samples.get(i + 1).map_or(x, |s| s.x);
            if let Some(pick) = self.golden(ground, scan, (lo, hi), bar) {
                if pick.force < best.force {
                    best = pick;
                }
            }
        }
        self.samples = samples;
        best
    }

    /// Golden-section search for the least force on [lo, hi].
    fn golden(
        &mut self,
        ground: &Vertices,
        scan: &Scan,
        (mut lo, mut hi): (f64, f64),
        bar: f64,
    ) -> Option<Pick> {
        let mut at = |x: f64| {
            let k = ground.piece_at(x);
            self.evaluate(ground, scan, (k, x), bar)
        };
        let force = |p: &Option<Pick>| p.map_or(f64::INFINITY, |p| p.force);
        let mut a = hi - INVERSE_PHI * (hi - lo);
        let mut b = lo + INVERSE_PHI * (hi - lo);
        let (mut pa, mut pb) = (at(a), at(b));
        // The bracket shrinks by 1/φ a step: n = log_φ(width / resolution)
        // steps narrow it to the resolution, four over for round-off;
        // where the resolution is below the round-off of x the bracket
        // stops shrinking, and the search ends there (it hung, issue 50).
        let steps = ((hi - lo) / scan.resolution).ln() / INVERSE_PHI.recip().ln();
        let most = steps.ceil().max(0.0) as usize + 4;
        for _ in 0..most {
            if hi - lo <= scan.resolution {
                break;
            }
            if force(&pa) <= force(&pb) {
                (hi, b, pb) = (b, a, pa);
                a = hi - INVERSE_PHI * (hi - lo);
                pa = at(a);
            } else {
                (lo, a, pa) = (a, b, pb);
                b = lo + INVERSE_PHI * (hi - lo);
                pb = at(b);
            }
        }
        if force(&pa) <= force(&pb) {
            pa
        } else {
            pb
        }
    }
}
