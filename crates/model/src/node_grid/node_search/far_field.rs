//! Candidates on undisturbed ground, in closed form (docs/model.md §9.1):
//! beyond the last disturbed node the surface is flat, fresh and of unit
//! weight γ0, so a candidate's weight is a function of its distance alone
//! (M32) and its band has the fresh soil's angles. Those candidates are
//! handled in blocks, each skipped whole when W(n₁) (P/W)(β(n₂)) cannot
//! beat the best.

use super::input::SearchInput;
use super::line::{Line, Lines, Slope};
use super::select::Best;
use crate::band::stretch;
use crate::force_bounds::Lower;
use crate::mechanism::ForceFactor;
use crate::node_grid::face_node::FaceNode;
use crate::node_grid::surface::Surface;
use crate::rake::Rake;

/// Candidates on undisturbed flat ground (y = 0, unit weight γ0) from
/// n_s = j0 − b on: with the running sums S over the nodes before j0,
/// W(n) = Δx [base + S_gh + γ0 d (n − n_s)
///            − (d/n) (S_gk + γ0 Σ_{k=n_s}^{n−1} k)]   (M32).
pub(super) struct FarField {
    face: FaceNode,
    d: f64,
    dx: f64,
    base: f64,
    sum_gh: f64,
    sum_gk: f64,
    gamma: f64,
    start: usize,
}

impl FarField {
    pub(super) fn new(lines: &Lines, gamma: f64, start: usize) -> Self {
        FarField {
            face: lines.face,
            d: lines.d,
            dx: lines.dx,
            base: lines.base,
            sum_gh: lines.sum_gh,
            sum_gk: lines.sum_gk,
            gamma,
            start,
        }
    }

    /// W(n), the block weight of the candidate n nodes from the face, in
    /// closed form (M32).
    pub(super) fn weight(&self, n: usize) -> f64 {
        let s = self.start;
        let ahead = (n - s) as f64;
        let triangle = ((n * (n - 1) - s * (s - 1)) / 2) as f64;
        let r = self.d / self.spacings(n);
        self.dx
            * (self.base + self.sum_gh + self.gamma * self.d * ahead
                - r * (self.sum_gk + self.gamma * triangle))
    }

    /// The weight the bounds use for candidate n (`SearchInput::bound_weight`).
    fn floor(&self, input: &SearchInput, n: usize) -> f64 {
        input.bound_weight(self.weight(n), self.spacings(n) * self.dx)
    }

    /// Spacings from the face to node b + n.
    fn spacings(&self, n: usize) -> f64 {
        self.face.spacings(self.face.node + n)
    }

    fn slope(&self, n: usize, rake: &Rake) -> Option<Slope> {
        Slope::on_grid((self.d / self.spacings(n)) / self.dx, rake)
    }

    /// First n ≥ n_s whose line passes below every node before it, or
    /// `limit` if none before it does.
    fn first_admissible(&self, r_min: f64, limit: usize) -> usize {
        // A node at or below the tip's level (r ≤ 0, a blade steered
        // shallower than a trench or dip ahead of it) lies above every
        // line from the tip: no candidate beyond it is admissible, and the
        // search below would never end (found by fuzzing the C ABI).
        if r_min.is_nan() || r_min <= 0.0 {
            return limit;
        }
        let admissible = |n: usize| self.d <= r_min * self.spacings(n);
        let mut n = if r_min.is_finite() {
            ((self.d / r_min).ceil() as usize)
                .max(self.start)
                .min(limit)
        } else {
            self.start
        };
        while n > self.start && admissible(n - 1) {
            n -= 1;
        }
        while n < limit && !admissible(n) {
            n += 1;
        }
        n
    }

    /// Considers the candidates from n_s on, in blocks, up to the stopping
    /// rule or `max_nodes`; returns the number evaluated in full.
    pub(super) fn scan(
        &self,
        input: &SearchInput,
        lines: &Lines,
        best: &mut Best,
        max_nodes: usize,
    ) -> u64 {
        let b = lines.face.node;
        let fresh = input.laws.band_angles(input.laws.fresh);
        let fresh_walls = Lower::new(fresh.friction, input.laws);
        let mut evaluations = 0;
        let mut n1 = self.first_admissible(lines.r_min, max_nodes.saturating_sub(b));
        // A candidate needs a node ahead of it within `max_nodes` (an end
        // wall may set it).
        while b + n1 + 1 < max_nodes {
            if best.beyond_reach(self.floor(input, n1), input.laws.min_factor) {
                break;
            }
            let n2 = (n1 + (n1 / 16).max(64) - 1).min(max_nodes - 2 - b);
            if self.may_win(input, &fresh_walls, best, (n1, n2)) {
                for n in n1..=n2 {
                    let (weight, floor) = (self.weight(n), self.floor(input, n));
                    if best.beyond_reach(floor, input.laws.min_factor) {
                        return evaluations;
                    }
                    if let Some(slope) = self.slope(n, &input.rake) {
                        evaluations += 1;
                        let line = Line {
                            node: b + n,
                            slope,
                            weight,
                            floor,
                        };
                        best.consider(input, lines, line, fresh);
                    }
                }
            }
            n1 = n2 + 1;
        }
        evaluations
    }

    /// Whether a candidate of n₁ ..= n₂ may beat the best: weight and slip
    /// length grow with n, P/W and the cohesion term with tan β, so
    /// (n₁, β(n₂)) bounds the block from below.
    fn may_win(
        &self,
        input: &SearchInput,
        fresh_walls: &Lower,
        best: &Best,
        (n1, n2): (usize, usize),
    ) -> bool {
        let slopes = (self.slope(n1, &input.rake), self.slope(n2, &input.rake));
        let (Some(first), Some(last)) = slopes else {
            return false;
        };
        let length = first.length(self.spacings(n1), self.dx);
        let t2 = last.tan_beta;
        let floor = self.floor(input, n1);
        let bound = |factor: &ForceFactor| input.loads.force(factor, floor, length, t2);
        let below = |p: Option<f64>| p.is_some_and(|p| p <= best.bar);
        let could_sink = t2 <= input.face.sinking_below;
        !best.prune
            || below(bound(&fresh_walls.rising))
            || (could_sink
                && below(fresh_walls.least_sinking((&input.face, &input.loads), floor, length, t2)))
    }
}

/// Whether candidate j and everything beyond lies on undisturbed flat ground
/// with a footprint (and its secant window) that does not reach disturbed
/// nodes.
pub(super) fn far_field_from(
    surface: &Surface,
    input: &SearchInput,
    lines: &Lines,
    j: usize,
) -> bool {
    let undisturbed = surface.pristine_from;
    if j < undisturbed {
        return false;
    }
    let dx = surface.spacing;
    let spacings = lines.face.spacings(j);
    // The footprint below is at least dB / (tan β Δx) + 2 with
    // 1 / tan β = Δx (x_j − x_b) / d − cot α (`Rake`): a test without
    // a square root for the many nodes that fail it.
    let (least, cut) = (
        input.band_width * spacings / input.depth,
        input.band_width * input.rake.cot / dx,
    );
    let ahead = (j - undisturbed) as f64;
    if ahead <= least - cut + 2.0 - 1e-9 * (least + cut + 2.0) {
        return false;
    }
    let grid = (input.depth / spacings) / dx;
    let Some(tan_beta) = input.rake.physical(grid) else {
        return false;
    };
    let thickness = input.band_width * (1.0 + tan_beta * tan_beta).sqrt() * stretch(grid, tan_beta);
    let footprint = thickness / grid / dx + 2.0;
    (j - undisturbed) as f64 > footprint
}
