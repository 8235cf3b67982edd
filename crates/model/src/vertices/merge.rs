//! Joining pieces (docs/model.md §3.4, §3.8): a vertex goes where a piece it ends
//! is too short to matter (`merge_close`, every increment, below v0/4) or
//! where it carries no information (`merge_quiet`, with
//! `run.merge_tolerance` > 0): the pieces either side of it hold nearly
//! the same state and it lies nearly on their chord. Either way the joined
//! piece keeps the two pieces' weight (its γ the weight over its area) and
//! their mass-weighted ut, so the mass is exact and the state is averaged,
//! never interpolated.

use super::Vertices;

/// When a vertex carries no information (`Vertices::merge_quiet`): the
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

impl Vertices {
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
    /// (`join_at`), so that a joined piece is judged again with its next
    /// neighbour; returns how many went.
    ///
    /// In one pass, moving each kept vertex down once: removing them one by
    /// one shifted the whole ground behind each, and a block of vertices
    /// far closer than v0/4 (`run.vertex_spacing` 0.006 under a tine's
    /// increment of 0.6, from fuzzing `--set`) took seconds an increment.
    /// Positions up to `w` hold the vertices kept so far and the one being
    /// judged; the next vertex, the original `r + 1`, is copied to
    /// `w + 1` before `goes` reads it, so `goes` sees the ground as the
    /// removals so far left it.
    fn remove_vertices_where(
        &mut self,
        from: usize,
        to: usize,
        goes: impl Fn(&Vertices, usize) -> bool,
    ) -> usize {
        let len = self.x.len();
        let (mut w, mut removed) = (from.max(1), 0);
        // r = w + removed, the original index of the vertex judged: before
        // `to`, and `removed + 1` vertices short of the ground's end.
        let mut r = w;
        while r < to.min(len - removed - 1) {
            self.place(r + 1, w + 1);
            if goes(self, w) {
                self.join_at(w);
                removed += 1;
            } else {
                w += 1;
            }
            r += 1;
        }
        if removed > 0 {
            // The rest, from the original r + 1 on, follows vertex w.
            self.x.copy_within(r + 1.., w + 1);
            self.y.copy_within(r + 1.., w + 1);
            let pieces = (r + 1).min(len - 1);
            self.accumulated_shear.copy_within(pieces.., w + 1);
            self.unit_weight.copy_within(pieces.., w + 1);
            for v in [&mut self.x, &mut self.y] {
                v.truncate(len - removed);
            }
            self.accumulated_shear.truncate(len - removed - 1);
            self.unit_weight.truncate(len - removed - 1);
        }
        removed
    }

    /// Copies the original vertex `from` to position `to` (≤ `from`), with
    /// the piece that starts at it but for the last vertex's.
    fn place(&mut self, from: usize, to: usize) {
        if from == to {
            return;
        }
        self.x[to] = self.x[from];
        self.y[to] = self.y[from];
        if from < self.accumulated_shear.len() {
            self.accumulated_shear[to] = self.accumulated_shear[from];
            self.unit_weight[to] = self.unit_weight[from];
        }
    }

    /// Joins pieces k − 1 and k, vertex k going (0 < k < last): the piece
    /// k − 1 takes both pieces' weight and their mass-weighted ut over
    /// vertices k − 1 and k + 1, which then stands at position k with the
    /// piece after it.
    fn join_at(&mut self, k: usize) {
        let (a, b) = (self.piece_area(k - 1), self.piece_area(k));
        let (ga, gb) = (self.unit_weight[k - 1], self.unit_weight[k]);
        let weight = ga * a + gb * b;
        let ut =
            (ga * a * self.accumulated_shear[k - 1] + gb * b * self.accumulated_shear[k]) / weight;
        self.place(k + 1, k);
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

#[cfg(test)]
mod tests {
    use super::Vertices;

    /// Vertex k removed by shifting everything behind it, as the pass did
    /// before it moved each vertex once: the yardstick of the pass.
    fn remove_one(g: &mut Vertices, k: usize) {
        let (a, b) = (g.piece_area(k - 1), g.piece_area(k));
        let (ga, gb) = (g.unit_weight[k - 1], g.unit_weight[k]);
        let weight = ga * a + gb * b;
        let ut = (ga * a * g.accumulated_shear[k - 1] + gb * b * g.accumulated_shear[k]) / weight;
        g.x.remove(k);
        g.y.remove(k);
        g.accumulated_shear.remove(k);
        g.unit_weight.remove(k);
        g.accumulated_shear[k - 1] = ut;
        g.unit_weight[k - 1] = weight / g.piece_area(k - 1);
    }

    #[test]
    fn one_pass_removes_what_one_at_a_time_removed_bit_for_bit() {
        let mut draw = super::super::test_draws(11);
        for case in 0..200 {
            let mut g = Vertices::flat(10.0, 0.05 + 0.3 * draw(), 1.0, 1.0);
            for k in 1..g.x.len() - 1 {
                g.x[k] += 0.4 * (draw() - 0.5) * (g.x[k + 1] - g.x[k]).min(g.x[k] - g.x[k - 1]);
                g.y[k] = 0.3 * draw();
            }
            for k in 0..g.pieces() {
                g.accumulated_shear[k] = draw();
                g.unit_weight[k] = 1.0 + 0.2 * draw();
            }
            let n = g.x.len();
            let from = (draw() * 5.0) as usize;
            let to = if case % 3 == 0 {
                n + 3
            } else {
                (draw() * n as f64) as usize
            };
            let min = 0.3 * draw();
            let mut expected = g.clone();
            let mut removed = 0;
            let mut k = from.max(1);
            while k < to.min(expected.x.len() - 1) - removed {
                let x = &expected.x;
                if x[k] - x[k - 1] < min || x[k + 1] - x[k] < min {
                    remove_one(&mut expected, k);
                    removed += 1;
                } else {
                    k += 1;
                }
            }
            assert_eq!(g.merge_close(from, to, min), removed, "case {case}");
            assert_eq!(g, expected, "case {case}");
        }
    }
}
