//! Joining pieces (docs/model.md §19): a vertex goes where a piece it ends
//! is too short to matter (`merge_close`, every increment, below v0/4) or
//! where it carries no information (`merge_quiet`, with
//! `run.merge_tolerance` > 0): the pieces either side of it hold nearly
//! the same state and it lies nearly on their chord. Either way the joined
//! piece keeps the two pieces' weight (its γ the weight over its area) and
//! their mass-weighted ut, so the mass is exact and the state is averaged,
//! never interpolated.

use super::Ground;

/// When a vertex carries no information (`Ground::merge_quiet`): the
/// pieces either side of it differ in ut by at most `tolerance` times
/// `shear_scale` and in γ by at most `tolerance` times `unit_weight`, it
/// lies within `tolerance` times `depth` of the chord of its neighbours
/// (vertically), and the joined piece is at most `longest` long.
#[derive(Clone, Copy, Debug)]
pub struct Quiet {
    /// The relative tolerance (`run.merge_tolerance`, –).
    pub tolerance: f64,
    /// ur, the scale of ut (length).
    pub shear_scale: f64,
    /// γ0 (force per volume).
    pub unit_weight: f64,
    /// d (length).
    pub depth: f64,
    /// h, the longest piece a join may make (length).
    pub longest: f64,
}

impl Ground {
    /// Removes the vertices that end a piece shorter than `min_spacing`
    /// among vertices `from..to` (never the face's), joining the two pieces
    /// it bounded: the joined piece holds their weight (its γ the weight
    /// over its area) and their mass-weighted ut. Returns how many went.
    pub fn merge_close(&mut self, from: usize, to: usize, min_spacing: f64) -> usize {
        self.remove_vertices_where(from, to, |g, k| {
            g.x[k] - g.x[k - 1] < min_spacing || g.x[k + 1] - g.x[k] < min_spacing
        })
    }

    /// Removes every vertex k among `from..to` (never the face's) for which
    /// `goes(self, k)` holds when it is reached, joining its two pieces
    /// (`remove_vertex`), so that a joined piece is judged again with its
    /// next neighbour; returns how many went.
    fn remove_vertices_where(
        &mut self,
        from: usize,
        to: usize,
        goes: impl Fn(&Ground, usize) -> bool,
    ) -> usize {
        let mut removed = 0;
        let mut k = from.max(1);
        while k < to.min(self.x.len() - 1) - removed {
            if goes(self, k) {
                self.remove_vertex(k);
                removed += 1;
            } else {
                k += 1;
            }
        }
        removed
    }

    /// Joins pieces k − 1 and k by removing vertex k (0 < k < last).
    fn remove_vertex(&mut self, k: usize) {
        let (a, b) = (self.piece_area(k - 1), self.piece_area(k));
        let (ga, gb) = (self.unit_weight[k - 1], self.unit_weight[k]);
        let weight = ga * a + gb * b;
        let ut =
            (ga * a * self.accumulated_shear[k - 1] + gb * b * self.accumulated_shear[k]) / weight;
        self.x.remove(k);
        self.y.remove(k);
        self.accumulated_shear.remove(k);
        self.unit_weight.remove(k);
        self.accumulated_shear[k - 1] = ut;
        self.unit_weight[k - 1] = weight / self.piece_area(k - 1);
    }

    /// Removes the vertices among `from..to` (never the face's) that carry
    /// no information by `quiet`; returns how many went.
    pub fn merge_quiet(&mut self, from: usize, to: usize, quiet: &Quiet) -> usize {
        self.remove_vertices_where(from, to, |g, k| g.is_quiet(k, quiet))
    }

    fn is_quiet(&self, k: usize, quiet: &Quiet) -> bool {
        let t = quiet.tolerance;
        let (x, y) = (&self.x, &self.y);
        if x[k + 1] - x[k - 1] > quiet.longest {
            return false;
        }
        let chord = y[k - 1] + (x[k] - x[k - 1]) * (y[k + 1] - y[k - 1]) / (x[k + 1] - x[k - 1]);
        let shear = (self.accumulated_shear[k] - self.accumulated_shear[k - 1]).abs();
        let weight = (self.unit_weight[k] - self.unit_weight[k - 1]).abs();
        shear <= t * quiet.shear_scale
            && weight <= t * quiet.unit_weight
            && (y[k] - chord).abs() <= t * quiet.depth
    }
}
