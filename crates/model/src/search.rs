//! The principle of minimum effort: the grid search over candidate emergence
//! nodes for the admissible mechanism of least force (paper, "Numerical
//! formulation"; docs/model.md §2).
//!
//! Candidate j is the straight line from the blade tip A = (x_b, −d) to
//! surface node j. With r_j = (y_j + d) / (j − b) (rise per node, so that
//! tan β_j = r_j / Δx on the grid; for a raked blade the grid is sheared and
//! `Rake` converts the slope):
//!
//! * the line stays inside the soil iff no node between lies below it, i.e.
//!   r_j ≤ min over b < i < j of r_i (a running minimum);
//! * the block weight by the trapezoid rule is
//!   W_j = Δx [ ½ γ_b (y_b + d) + Σ_{b<i<j} γ_i (y_i + d) − r_j Σ_{b<i<j} γ_i (i − b) ],
//!   two running sums, so each candidate costs O(1);
//! * P_j = W_j · (P/W)(β_j, φ_j) by Eq. (1), with φ_j and ψ_j the mean of
//!   the node angles over the band's footprint at the surface (the nodes the
//!   band touches, `Band::footprint`; the emergence node alone for a slip
//!   line), from running prefix sums.
//!
//! Stopping rule (why the domain may be finite): along admissible candidates
//! the lines only get lower, so W_j never decreases, and P/W ≥ f_min, its
//! value at β → 0 for the least friction angle and the lesser of the face
//! frictions the block may have (P/W grows with β and φ while the rake
//! exceeds the wall friction, which the case validation ensures). Once W_j f_min exceeds
//! the best force found, no later candidate can win. The scan stops there and
//! grows the domain only if it reaches the end first: growing never changes
//! the result.
//!
//! Pruning (speed without changing the result): a candidate is evaluated in
//! full (footprint, band angles, Eq. (1)) only if its lower bound
//! W_j (P/W)(β_j, φ_lo) can beat the best force so far, φ_lo being the least
//! friction angle of the nodes scanned so far (P/W grows with φ); the test is
//! division-free. The best force starts from the previous increment's
//! emergence node, evaluated first. Beyond the last disturbed node the ground
//! is undisturbed and flat, so W_j has a closed form in n = j − b and every
//! band there has the fresh soil's angles: those candidates are handled in
//! blocks (`far_field`), each skipped whole when W(n₁) (P/W)(β(n₂)) cannot
//! beat the best.
//!
//! Blocks (speed without changing the result): the scan takes `BLOCK`
//! nodes at a time in three passes: the running sums and each line's
//! weight and first bound; the footprints and the second bound of the
//! lines that passed; Eq. (1) for those left, in order, up to the stopping
//! rule. The first two passes use the best force at the block's start,
//! which the third only lowers, so they reject no line that the scan node
//! by node would have kept; they hold no branch on their bounds (which
//! lines pass is data), so the processor overlaps candidates.
//!
//! Ties: candidates whose force is within `TIE_TOLERANCE` (relative) of the
//! minimum count as equal, and the one nearest the blade wins, so round-off
//! cannot flip the choice between near-equal mechanisms.

use crate::band::{stretch, Band};
use crate::far_field::{far_field_from, FarField};
use crate::mechanism::{Face, FactorTable, ForceFactor, Loads};
use crate::rake::Rake;
use crate::surface::Surface;

/// Relative force difference below which two candidates are equal.
pub const TIE_TOLERANCE: f64 = 1e-10;

/// Nodes appended at a time when the scan reaches the end of the domain.
const GROW_NODES_MIN: usize = 256;

/// The chosen mechanism of one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// Emergence node j.
    pub node: usize,
    /// tan β* (physical).
    pub tan_beta: f64,
    /// Slope of the slip line on the grid (= tan β* for a vertical blade;
    /// see `Rake`).
    pub grid_slope: f64,
    /// P*: force per unit width.
    pub force: f64,
    /// W: weight of the block.
    pub weight: f64,
    /// The band's friction and dilation angles (radians).
    pub friction: f64,
    /// Mean of ψ(ut_i) over the footprint, radians.
    pub dilation: f64,
}

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

/// Reusable search state (no allocation per step once warmed up).
#[derive(Clone, Debug, Default)]
pub struct Search {
    /// Admissible candidates of the current step, kept for the tie-break.
    admissible: Vec<Choice>,
    /// Prefix sums from the blade node of φ, ψ and ut.
    prefix: Vec<[f64; 3]>,
    /// Emergence node of the previous increment (seeds the best force).
    previous: Option<usize>,
    /// The block of nodes being scanned.
    block: Block,
    /// Candidates evaluated in full since creation (for benchmarks).
    pub evaluations: u64,
    /// Set while a landscape is being taken.
    landscape: Option<Landscape>,
}

/// Every candidate of one search, and the state to restore after it.
#[derive(Clone, Debug)]
struct Landscape {
    candidates: Vec<Choice>,
    previous: Option<usize>,
    evaluations: u64,
}

/// What the search needs to know about the soil besides the surface.
pub struct SearchInput<'a, A, F>
where
    A: Fn(BandAngles) -> BandAngles,
    F: Fn(BandAngles, f64) -> ForceFactor,
{
    /// Node b of the blade face.
    pub blade: usize,
    /// d: depth of the blade tip during the increment.
    pub depth: f64,
    /// dB (0 for the original model's slip line).
    pub band_width: f64,
    /// Lower bound of P/W over every candidate (see the stopping rule).
    pub min_factor: f64,
    /// The wall friction in Eq. (1) for a rising and a sinking block (±φw,
    /// plus α − 90° for a raked blade), radians: for the bounds.
    pub walls: (f64, f64),
    /// How the face moves (§2.6 of docs/model.md): below
    /// `face.sinking_below` a block may sink relative to it, and the
    /// sinking face friction must be bounded too.
    pub face: Face,
    /// The shear of coordinates of a raked blade.
    pub rake: Rake,
    /// Band angles of undisturbed ground.
    pub fresh: BandAngles,
    /// Eq. (1) on a grid of friction angles (a lower bound before the
    /// exact factor).
    pub table: &'a FactorTable,
    /// The band's angles from the footprint means (the band-angle rule).
    pub angles: &'a A,
    /// Eq. (1) for a candidate's band angles at tan β.
    pub factor: &'a F,
    /// Nodes appended when the scan needs more domain.
    pub grow_nodes: usize,
    /// Loads beside the block's weight (all ≥ 0, so every bound on the
    /// weight alone stays a bound).
    pub loads: Loads,
}

/// The state of the outward scan over candidates.
pub(crate) struct Scan {
    pub(crate) b: usize,
    pub(crate) d: f64,
    pub(crate) dx: f64,
    /// δ / Δx: the face's offset from node b's grid point (0 on the grid).
    pub(crate) offset: f64,
    /// ½ γ_b (y_b + d) (1 − δ/Δx): the face node's trapezoid share.
    pub(crate) base: f64,
    /// Σ γ_i (y_i + d) and Σ γ_i (i − b) over the nodes between b and j.
    pub(crate) sum_gh: f64,
    pub(crate) sum_gk: f64,
    /// Running minimum of r_i.
    pub(crate) r_min: f64,
    /// Best force so far, widened by the tie tolerance.
    pub(crate) bar: f64,
    /// Whether bounds may reject candidates unevaluated.
    pub(crate) prune: bool,
}

impl Scan {
    /// (x_j − x_b) / Δx for a node j ahead of the face.
    pub(crate) fn spacings(&self, j: usize) -> f64 {
        (j - self.b) as f64 - self.offset
    }

    /// Trapezoid weight of node i between the face and a candidate beyond
    /// it: the face's segment is 1 − δ/Δx long.
    pub(crate) fn node_weight(&self, i: usize) -> f64 {
        if i == self.b + 1 {
            1.0 - 0.5 * self.offset
        } else {
            1.0
        }
    }

    fn improve(&mut self, force: f64) {
        self.bar = self.bar.min(force * (1.0 + TIE_TOLERANCE));
    }

    /// No candidate from weight W on can beat the best (stopping rule).
    fn beyond_reach(&self, weight: f64, min_factor: f64) -> bool {
        weight * min_factor > self.bar
    }
}

/// Nodes scanned per block (see `Search::scan`).
const BLOCK: usize = 128;

/// A candidate's slip line: emergence node, slope and block weight.
#[derive(Clone, Copy, Debug, Default)]
struct Line {
    node: usize,
    slope: Slope,
    weight: f64,
}

/// Where a block of the scan ended.
enum BlockEnd {
    /// After `BLOCK` nodes: the next block starts at this node.
    Next(usize),
    /// At a node with no neighbour ahead: grow the domain, then go on from it.
    Grow(usize),
    /// At the first node of the far field (`far_field`).
    FarField(usize),
    /// At the end of the domain, which may not grow.
    Domain,
}

/// One block of the scan (see `Search::scan`), reused from step to step.
#[derive(Clone, Debug, Default)]
struct Block {
    /// Its first node.
    start: usize,
    /// W_j of each node from `start`, −∞ where the line is not admissible.
    weight: Vec<f64>,
    /// The lines of the first pass; the first `near` passed its bound.
    lines: Vec<Line>,
    near: usize,
    /// The lines that passed the second pass's bound, with their band angles.
    kept: Vec<(Line, BandAngles)>,
}

impl Block {
    /// The first node from block index `from` at which the stopping rule
    /// ends the scan (as an index; the block's length if none).
    fn first_stop(&self, from: usize, scan: &Scan, min_factor: f64) -> usize {
        self.weight[from..]
            .iter()
            .position(|&w| scan.beyond_reach(w, min_factor))
            .map_or(self.weight.len(), |k| from + k)
    }
}

impl Search {
    /// The minimum-effort mechanism, or `None` if no admissible candidate
    /// exists within a domain of `max_nodes` nodes.
    pub fn run<A, F>(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput<A, F>,
        max_nodes: usize,
    ) -> Option<Choice>
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let prune = self.landscape.is_none();
        let found = self.scan(surface, input, max_nodes, prune);
        if found.is_some() || !prune {
            return found;
        }
        // None may be true (an end wall leaves no room); that a bound
        // rejected every admissible candidate is proven not to happen: if it
        // ever does, tests fail here and a user's run still gets the true
        // minimum.
        let exact = self.scan(surface, input, max_nodes, false);
        debug_assert!(
            exact.is_none(),
            "a bound rejected every admissible candidate"
        );
        exact
    }

    /// The outward scan; with `prune` false, no candidate is rejected
    /// unevaluated except beyond the stopping bound.
    fn scan<A, F>(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput<A, F>,
        max_nodes: usize,
        prune: bool,
    ) -> Option<Choice>
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        self.admissible.clear();
        self.prefix.clear();
        self.prefix.push([0.0; 3]);
        let (b, d, dx) = (input.blade, input.depth, surface.spacing);
        let offset = surface.offset_of(b);
        let mut scan = Scan {
            b,
            d,
            dx,
            offset,
            base: 0.5 * surface.unit_weight[b] * (surface.height[b] + d) * (1.0 - offset),
            sum_gh: 0.0,
            sum_gk: 0.0,
            r_min: f64::INFINITY,
            bar: f64::INFINITY,
            prune,
        };
        let seed = self.previous.filter(|_| prune);
        if let Some(force) = seed.and_then(|j| self.seed(surface, input, &scan, j)) {
            scan.improve(force);
        }
        // The least friction angle seen so far and Eq. (1) at it.
        let phi_lo = surface.friction[b];
        let mut bounds = (phi_lo, Lower::new(phi_lo, input));
        let mut j = b + 1;
        // A block ends before the domain grows or the far field starts, and
        // both happen only once the block is settled and the scan goes on:
        // where the scan node by node would have done them (the profile
        // holds every node the domain grew by).
        loop {
            let end = self.lines(surface, input, &mut scan, &mut bounds, j, max_nodes);
            self.footprints(surface, input, &scan);
            if self.settle(input, &mut scan) {
                break;
            }
            match end {
                BlockEnd::Next(next) => j = next,
                BlockEnd::Grow(next) => {
                    surface.grow(input.grow_nodes.max(GROW_NODES_MIN));
                    j = next;
                }
                BlockEnd::FarField(j0) => {
                    self.far_field(surface.ground_unit_weight, input, &mut scan, j0, max_nodes);
                    break;
                }
                BlockEnd::Domain => break,
            }
        }
        let choice = self.select(scan.bar);
        self.previous = choice.map(|c| c.node);
        choice
    }

    /// The candidate of least force, nearest the blade among near-ties.
    fn select(&self, bar: f64) -> Option<Choice> {
        self.admissible.iter().find(|c| c.force <= bar).copied()
    }

    /// First pass over a block of up to `BLOCK` nodes from j: the running
    /// sums, each node's line (admissible or not, and W_j) and the lines that
    /// pass the bound before the footprint (`Lower`, with the best force at
    /// the block's start). Stops before a node where the scan must first do
    /// something else (`BlockEnd`).
    fn lines<A, F>(
        &mut self,
        surface: &Surface,
        input: &SearchInput<A, F>,
        scan: &mut Scan,
        (phi_lo, lower): &mut (f64, Lower),
        mut j: usize,
        max_nodes: usize,
    ) -> BlockEnd
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let (d, dx) = (scan.d, scan.dx);
        self.block.start = j;
        self.block.weight.clear();
        self.block.lines.resize(BLOCK, Line::default());
        let mut near = 0;
        let limit = j + BLOCK;
        while j < limit {
            if far_field_from(surface, input, j) {
                self.block.near = near;
                return BlockEnd::FarField(j);
            }
            // The emergence node always has a neighbour ahead of it.
            if j + 1 >= surface.len() {
                self.block.near = near;
                return if surface.len() >= max_nodes {
                    BlockEnd::Domain
                } else {
                    BlockEnd::Grow(j)
                };
            }
            self.push_prefix(surface, j - 1);
            if surface.friction[j] < *phi_lo || surface.friction[j - 1] < *phi_lo {
                *phi_lo = phi_lo.min(surface.friction[j]).min(surface.friction[j - 1]);
                *lower = Lower::new(*phi_lo, input);
            }
            let k = scan.spacings(j);
            let rise = surface.height[j] + d;
            // Inadmissible lines never stop the scan.
            let mut stop_weight = f64::NEG_INFINITY;
            if rise <= scan.r_min * k {
                let r = rise / k;
                scan.r_min = r;
                let weight = dx * (scan.base + scan.sum_gh - r * scan.sum_gk);
                stop_weight = weight;
                let grid = r / dx;
                if let Some(tan_beta) = input.rake.physical(grid) {
                    let slope = Slope { grid, tan_beta };
                    self.block.lines[near] = Line {
                        node: j,
                        slope,
                        weight,
                    };
                    // Kept without a branch: which lines pass is data.
                    let pass = !scan.prune || lower.can_beat(weight, tan_beta, scan.bar, input);
                    near += usize::from(pass);
                }
            }
            self.block.weight.push(stop_weight);
            let g = surface.unit_weight[j] * scan.node_weight(j);
            scan.sum_gh += g * rise;
            scan.sum_gk += g * k;
            j += 1;
        }
        self.block.near = near;
        BlockEnd::Next(j)
    }

    /// Second pass: the footprint and band angles of each line kept by the
    /// first, and the bound after the footprint (`FactorTable`, with the best
    /// force at the block's start); keeps those that pass, in order.
    fn footprints<A, F>(&mut self, surface: &Surface, input: &SearchInput<A, F>, scan: &Scan)
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let near = self.block.near;
        self.block.kept.resize(near, (Line::default(), input.fresh));
        let mut kept = 0;
        for i in 0..near {
            let line = self.block.lines[i];
            let band = line.slope.band(scan, line.node, input.band_width);
            let angles = (input.angles)(self.band_angles(surface, &band, input.fresh));
            let t = line.slope.tan_beta;
            let can_beat = |rising| {
                input
                    .table
                    .below(angles.friction, rising)
                    .can_beat(line.weight, t, scan.bar)
            };
            // Which face friction is the lesser depends on the rake (see
            // `Lower`). With the band's dilation known, a block that rises
            // (`Face::rises`, taken only where it decides) has the rising
            // one in Eq. (1).
            let may_win = can_beat(true)
                || (t <= input.face.sinking_below
                    && can_beat(false)
                    && !input.face.rises(t, angles.dilation));
            self.block.kept[kept] = (line, angles);
            kept += usize::from(angles.fresh | !scan.prune | may_win);
        }
        self.evaluations += near as u64;
        self.block.kept.truncate(kept);
    }

    /// Third pass: Eq. (1) for the lines kept, in order, with the best force
    /// as it improves, up to the node where the stopping rule ends the scan
    /// (W_j f_min above the best force then); returns whether it did. The
    /// bounds of the first two passes used the best force at the block's
    /// start, no lower than the best force now: they rejected only lines
    /// that could not beat it.
    fn settle<A, F>(&mut self, input: &SearchInput<A, F>, scan: &mut Scan) -> bool
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let min_factor = input.min_factor;
        let mut stop = self.block.first_stop(0, scan, min_factor);
        for k in 0..self.block.kept.len() {
            let (line, angles) = self.block.kept[k];
            let i = line.node - self.block.start;
            if i > stop {
                return true;
            }
            let bar = scan.bar;
            self.consider(input, scan, line.node, line.slope, line.weight, angles);
            if scan.bar != bar {
                stop = self.block.first_stop(i, scan, min_factor);
            }
        }
        stop < self.block.weight.len()
    }

    fn consider<A, F>(
        &mut self,
        input: &SearchInput<A, F>,
        scan: &mut Scan,
        j: usize,
        slope: Slope,
        weight: f64,
        angles: BandAngles,
    ) where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let factor = (input.factor)(angles, slope.tan_beta);
        let length = slope.length(scan.spacings(j), scan.dx);
        if let Some(force) = input.loads.force(&factor, weight, length, slope.tan_beta) {
            let candidate = Choice {
                node: j,
                tan_beta: slope.tan_beta,
                grid_slope: slope.grid,
                force,
                weight,
                friction: angles.friction,
                dilation: angles.dilation,
            };
            if let Some(landscape) = &mut self.landscape {
                landscape.candidates.push(candidate);
            }
            if force > scan.bar {
                return;
            }
            scan.improve(force);
            self.admissible.push(candidate);
        }
    }

    /// Makes the next `run` a landscape: no pruning, and every admissible
    /// candidate up to the stopping bound recorded (`end_landscape`).
    pub fn begin_landscape(&mut self) {
        self.landscape = Some(Landscape {
            candidates: Vec::new(),
            previous: self.previous,
            evaluations: self.evaluations,
        });
    }

    /// The candidates recorded since `begin_landscape`, nearest the blade
    /// first; the search is left as it was before (the next increment is
    /// seeded from the same node, and `evaluations` counts increments only).
    pub fn end_landscape(&mut self) -> Vec<Choice> {
        let Some(landscape) = self.landscape.take() else {
            return Vec::new();
        };
        self.previous = landscape.previous;
        self.evaluations = landscape.evaluations;
        landscape.candidates
    }

    fn push_prefix(&mut self, surface: &Surface, i: usize) {
        let last = *self.prefix.last().expect("prefix starts with zero");
        self.prefix.push([
            last[0] + surface.friction[i],
            last[1] + surface.dilation[i],
            last[2] + surface.accumulated_shear[i],
        ]);
    }

    /// Mean angles over the band's footprint, nodes j − m ..= j (the prefix
    /// sums must cover the nodes before j).
    #[inline]
    fn band_angles(&self, surface: &Surface, band: &Band, fresh: BandAngles) -> BandAngles {
        let (b, j) = (band.blade, band.emergence);
        let m = band.footprint(&surface.height);
        if m == 0 {
            return node_angles(surface, j);
        }
        let before = self.prefix[j - b];
        let lo = self.prefix[j - m - b];
        if before[2] == lo[2] && surface.accumulated_shear[j] == 0.0 {
            return fresh;
        }
        let hi = [
            before[0] + surface.friction[j],
            before[1] + surface.dilation[j],
            before[2] + surface.accumulated_shear[j],
        ];
        window_angles(hi, lo, m)
    }

    /// Force of candidate j computed on its own (an upper bound for the
    /// scan), if it is admissible.
    fn seed<A, F>(
        &self,
        surface: &Surface,
        input: &SearchInput<A, F>,
        scan: &Scan,
        j: usize,
    ) -> Option<f64>
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let (b, d) = (scan.b, scan.d);
        if j <= b || j + 1 >= surface.len() {
            return None;
        }
        // The scan's own admissibility test, to the last bit: a seed the
        // scan would reject must not lower the bar.
        let (mut sum_gh, mut sum_gk, mut r_min) = (0.0, 0.0, f64::INFINITY);
        for i in b + 1..j {
            let k = scan.spacings(i);
            let rise = surface.height[i] + d;
            if rise <= r_min * k {
                r_min = rise / k;
            }
            let g = surface.unit_weight[i] * scan.node_weight(i);
            sum_gh += g * rise;
            sum_gk += g * k;
        }
        let (k, rise) = (scan.spacings(j), surface.height[j] + d);
        if rise > r_min * k {
            return None;
        }
        let r = rise / k;
        let weight = scan.dx * (scan.base + sum_gh - r * sum_gk);
        let grid = r / scan.dx;
        let slope = Slope {
            grid,
            tan_beta: input.rake.physical(grid)?,
        };
        let band = slope.band(scan, j, input.band_width);
        let m = band.footprint(&surface.height);
        let sum = |i: usize| {
            [
                surface.friction[i],
                surface.dilation[i],
                surface.accumulated_shear[i],
            ]
        };
        let total = (j - m..=j)
            .map(sum)
            .fold([0.0; 3], |a, v| [a[0] + v[0], a[1] + v[1], a[2] + v[2]]);
        let angles = (input.angles)(window_angles(total, [0.0; 3], m));
        let factor = (input.factor)(angles, slope.tan_beta);
        let length = slope.length(scan.spacings(j), scan.dx);
        let force = input.loads.force(&factor, weight, length, slope.tan_beta)?;
        Some(force)
    }

    /// Candidates on undisturbed flat ground from node j0 on, in blocks.
    fn far_field<A, F>(
        &mut self,
        ground_unit_weight: f64,
        input: &SearchInput<A, F>,
        scan: &mut Scan,
        j0: usize,
        max_nodes: usize,
    ) where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        let far = FarField::new(scan, ground_unit_weight, j0 - scan.b);
        let fresh = (input.angles)(input.fresh);
        let fresh_walls = Lower::new(fresh.friction, input);
        let mut n1 = far.first_admissible(scan.r_min);
        // A candidate needs a node ahead of it within `max_nodes` (an end
        // wall may set it).
        while scan.b + n1 + 1 < max_nodes {
            if scan.beyond_reach(far.weight(n1), input.min_factor) {
                return;
            }
            let n2 = (n1 + (n1 / 16).max(64) - 1).min(max_nodes - 2 - scan.b);
            // Weight and slip length grow with n, P/W and the cohesion term
            // with tan β: (n₁, β(n₂)) bounds the block from below.
            let slopes = (far.slope(n1, &input.rake), far.slope(n2, &input.rake));
            if let (Some(first), Some(last)) = slopes {
                let length = first.length(far.spacings(n1), scan.dx);
                let t2 = last.tan_beta;
                let bound =
                    |factor: &ForceFactor| input.loads.force(factor, far.weight(n1), length, t2);
                let below = |p: Option<f64>| p.is_some_and(|p| p <= scan.bar);
                let could_sink = t2 <= input.face.sinking_below;
                if !scan.prune
                    || below(bound(&fresh_walls.rising))
                    || (could_sink && below(bound(&fresh_walls.sinking)))
                {
                    for n in n1..=n2 {
                        let weight = far.weight(n);
                        if scan.beyond_reach(weight, input.min_factor) {
                            return;
                        }
                        if let Some(slope) = far.slope(n, &input.rake) {
                            self.evaluations += 1;
                            self.consider(input, scan, scan.b + n, slope, weight, fresh);
                        }
                    }
                }
            }
            n1 = n2 + 1;
        }
    }
}

/// The slope of a candidate's slip line on the grid and physically.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Slope {
    pub(crate) grid: f64,
    pub(crate) tan_beta: f64,
}

impl Slope {
    /// Physical horizontal length of the slip line reaching `spacings`
    /// node spacings ahead of the tip on the grid.
    pub(crate) fn length(&self, spacings: f64, dx: f64) -> f64 {
        spacings * dx * stretch(self.grid, self.tan_beta)
    }

    fn band(&self, scan: &Scan, j: usize, band_width: f64) -> Band {
        Band::new(
            scan.b,
            j,
            (self.grid, self.tan_beta),
            band_width,
            scan.d,
            scan.dx,
            scan.offset,
        )
    }
}

/// Eq. (1) at the least friction angle seen so far: a lower bound of P/W,
/// with the face friction of a rising block above `sinking_below`.
#[derive(Clone, Copy)]
struct Lower {
    rising: ForceFactor,
    sinking: ForceFactor,
}

impl Lower {
    fn new<A, F>(phi: f64, input: &SearchInput<A, F>) -> Self
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        Lower {
            rising: ForceFactor::new(phi, input.walls.0),
            sinking: ForceFactor::new(phi, input.walls.1),
        }
    }

    /// Whether W (P/W) ≤ `bar` at tan β for either face friction the block
    /// may have there. Eq. (1) grows with φ (as sin(α ± φw) > 0), but with
    /// the face friction only where α + β + φ ± φw > 90°: for a vertical
    /// blade the sinking block's −φw is always the lesser, for a raked one
    /// either may be, so both are tried.
    fn can_beat<A, F>(
        &self,
        weight: f64,
        tan_beta: f64,
        bar: f64,
        input: &SearchInput<A, F>,
    ) -> bool
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        self.rising.can_beat(weight, tan_beta, bar)
            | (tan_beta <= input.face.sinking_below && self.sinking.can_beat(weight, tan_beta, bar))
    }
}

fn node_angles(surface: &Surface, j: usize) -> BandAngles {
    BandAngles {
        friction: surface.friction[j],
        dilation: surface.dilation[j],
        shear: surface.accumulated_shear[j],
        fresh: surface.accumulated_shear[j] == 0.0,
    }
}

/// Mean angles of the m + 1 nodes whose sums are `hi − lo`.
fn window_angles(hi: [f64; 3], lo: [f64; 3], m: usize) -> BandAngles {
    let n = (m + 1) as f64;
    BandAngles {
        friction: (hi[0] - lo[0]) / n,
        dilation: (hi[1] - lo[1]) / n,
        shear: (hi[2] - lo[2]) / n,
        fresh: hi[2] - lo[2] == 0.0,
    }
}
