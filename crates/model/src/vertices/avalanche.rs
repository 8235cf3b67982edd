//! Avalanching on the vertex ground (M50; docs/model.md §6, and §9.1 for
//! the node grid):
//! no piece may be steeper than the angle of repose θr.
//!
//! With s = tan θr, the downslope constraint y_{k+1} ≥ y_k − s (x_{k+1} − x_k)
//! says g_k = y_k + s x_k is non-decreasing, the upslope one that
//! −y_k + s x_k is. Each is restored by one pass of the pool-adjacent-
//! violators algorithm weighted by the vertices' trapezoid weights
//! w_k = ½ (x_{k+1} − x_{k−1}) (half a piece at the ends), under which the
//! area is Σ w_k y_k: a pooled run becomes a line at exactly the angle of
//! repose holding the same area. The two passes alternate until neither
//! pools anything.
//!
//! The vertices stay where they are (only their heights change), so each
//! piece keeps its place; the soil a piece loses from its top is mixed
//! (mass-weighted) and deposited on the pieces that gain, whose γ and ut
//! become the mass-weighted mean of their soil and the deposit: mass is
//! conserved exactly.

use super::Vertices;
use crate::repose::{Pool, MAX_PASSES, SLOPE_TOLERANCE};

/// The ground as the last relax left it, every vertex pair unpooled by
/// both passes (empty until a relax ends so, and after one that gave up
/// at `MAX_PASSES`). Between relaxes the motion, the spill and the
/// merging change the ground near the blade and where heaps spill; the
/// rest is still this ground, vertex for vertex, and pools nothing: a
/// relax need not visit it. A cache: a relax without it (after a
/// snapshot) gives the same ground bit for bit.
#[derive(Clone, Debug, Default)]
pub(crate) struct Settled {
    x: Vec<f64>,
    y: Vec<f64>,
    slopes: (f64, f64),
}

impl Settled {
    /// The first vertex of `ground` from which on its vertices are the
    /// settled ground's last ones, bit for bit, under the same `slopes`
    /// (the number of vertices if none is).
    fn common_suffix(&self, ground: &Vertices, slopes: (f64, f64)) -> usize {
        let n = ground.x.len();
        let same_slopes = self.slopes.0.to_bits() == slopes.0.to_bits()
            && self.slopes.1.to_bits() == slopes.1.to_bits();
        if !same_slopes {
            return n;
        }
        let pairs = ground.x.iter().zip(&ground.y).rev();
        let kept = self.x.iter().zip(&self.y).rev();
        let equal = pairs
            .zip(kept)
            .take_while(|((x, y), (kx, ky))| {
                x.to_bits() == kx.to_bits() && y.to_bits() == ky.to_bits()
            })
            .count();
        n - equal
    }

    fn keep(&mut self, ground: &Vertices, slopes: (f64, f64)) {
        self.x.clone_from(&ground.x);
        self.y.clone_from(&ground.y);
        self.slopes = slopes;
    }

    fn forget(&mut self) {
        self.x.clear();
        self.y.clear();
    }
}

/// A run of changed pieces balances when its net area change is within
/// this fraction of its gross change (the pooling keeps the area to
/// round-off).
const BALANCE: f64 = 1e-9;

impl Vertices {
    /// Relaxes every piece steeper than the angle of repose (M28, M50):
    /// `slopes` are the steepest slopes downhill and uphill in +x, both
    /// s = tan θr for a vertical blade, on a raked blade's sheared
    /// coordinates those of `Rake::repose_slopes` (M29; downhill infinite
    /// where the face is flatter than the repose); returns whether any
    /// soil moved. The pieces next to a steep one are first cut to at most
    /// `spacing`, so that the soil that runs down heaps where it stops,
    /// not over a long piece.
    pub fn relax(&mut self, slopes: (f64, f64), spacing: f64) -> bool {
        self.relax_after(slopes, spacing, &mut Settled::default())
    }

    /// `relax` of a ground that `settled` holds as the last relax left it:
    /// the pools stop where the ground is still that ground (`Settled`), so
    /// an increment pools what it changed, not the ground ahead; the
    /// result is the same bit for bit as pooling every vertex.
    pub(crate) fn relax_after(
        &mut self,
        slopes: (f64, f64),
        spacing: f64,
        settled: &mut Settled,
    ) -> bool {
        self.refine_around_steep(slopes, spacing);
        // Vertices from `unchanged` on are the settled ground's.
        let mut unchanged = settled.common_suffix(self, slopes);
        let mut moved = false;
        let mut before = Vec::new();
        for _ in 0..MAX_PASSES {
            before.clone_from(&self.y);
            let down = if slopes.0.is_finite() {
                self.pool(slopes.0, 1.0, unchanged)
            } else {
                None
            };
            let up = self.pool(slopes.1, -1.0, unchanged.max(down.unwrap_or(0)));
            let Some(end) = down.max(up) else {
                settled.keep(self, slopes);
                return moved;
            };
            unchanged = unchanged.max(end);
            self.deposit(&before, end);
            moved = true;
        }
        settled.forget();
        moved
    }

    /// Cuts the two pieces on either side of every piece steeper than
    /// `slopes` (downhill, uphill) into equal pieces no longer than
    /// `spacing` (the avalanche cuts the ground where its soil lands; each
    /// part keeps the piece's state).
    fn refine_around_steep(&mut self, (down, up): (f64, f64), spacing: f64) {
        let (down, up) = (down * (1.0 + SLOPE_TOLERANCE), up * (1.0 + SLOPE_TOLERANCE));
        let steep: Vec<usize> = (0..self.pieces())
            .filter(|&k| {
                let (rise, run) = (self.y[k + 1] - self.y[k], self.x[k + 1] - self.x[k]);
                rise > up * run || -rise > down * run
            })
            .collect();
        let mut near: Vec<usize> = steep
            .iter()
            .flat_map(|&k| k.saturating_sub(2)..(k + 3).min(self.pieces()))
            .filter(|&k| self.x[k + 1] - self.x[k] > spacing)
            .collect();
        near.sort_unstable();
        near.dedup();
        if !near.is_empty() {
            self.cut_pieces(&near, spacing);
        }
    }

    /// Cuts each piece in `near` (in order) into equal pieces no longer
    /// than `spacing`, each part keeping the piece's state, in one pass
    /// over the ground: inserting the vertices one by one shifted the
    /// ground behind each, quadratic where thousands of pieces were cut
    /// (vertices 0.0006 apart under an increment of 0.2, from fuzzing
    /// `--set`: minutes an increment). Each new vertex's height is the
    /// one `split_at` gave when the cuts were made from the far end: on
    /// the part between the piece's start and the cut after it.
    fn cut_pieces(&mut self, near: &[usize], spacing: f64) {
        let pieces = self.pieces();
        let mut x = Vec::with_capacity(self.x.len());
        let mut y = Vec::with_capacity(self.x.len());
        let mut shear = Vec::with_capacity(pieces);
        let mut gamma = Vec::with_capacity(pieces);
        let mut cut = near.iter().peekable();
        let mut parts: Vec<(f64, f64)> = Vec::new();
        for k in 0..pieces {
            parts.clear();
            parts.push((self.x[k], self.y[k]));
            if cut.next_if_eq(&&k).is_some() {
                let (xa, xb, ya) = (self.x[k], self.x[k + 1], self.y[k]);
                let n = ((xb - xa) / spacing).ceil() as usize;
                let (mut x_hi, mut y_hi) = (xb, self.y[k + 1]);
                for i in (1..n).rev() {
                    let at = xa + (xb - xa) * i as f64 / n as f64;
                    // Where `split_at` found a vertex there already.
                    if at == xa || at == x_hi {
                        continue;
                    }
                    let height = ya + (at - xa) / (x_hi - xa) * (y_hi - ya);
                    parts.push((at, height));
                    (x_hi, y_hi) = (at, height);
                }
                parts[1..].reverse();
            }
            for &(px, py) in &parts {
                x.push(px);
                y.push(py);
                shear.push(self.accumulated_shear[k]);
                gamma.push(self.unit_weight[k]);
            }
        }
        x.push(self.x[pieces]);
        y.push(self.y[pieces]);
        (self.x, self.y) = (x, y);
        (self.accumulated_shear, self.unit_weight) = (shear, gamma);
    }

    /// Trapezoid weight of vertex k: half of each piece it bounds.
    fn vertex_weight(&self, k: usize) -> f64 {
        let left = if k == 0 {
            0.0
        } else {
            self.x[k] - self.x[k - 1]
        };
        let right = if k + 1 == self.x.len() {
            0.0
        } else {
            self.x[k + 1] - self.x[k]
        };
        0.5 * (left + right)
    }

    /// One pool-adjacent-violators pass on g_k = σ y_k + s x_k; returns
    /// one past the last vertex it levelled, if it levelled any. From
    /// vertex `unchanged` on the ground is one that a pass left unpooled:
    /// once a vertex there stands as a pool of its own, every vertex after
    /// it does too, and the pass stops.
    fn pool(&mut self, s: f64, sign: f64, unchanged: usize) -> Option<usize> {
        if !self.would_level(s, sign, unchanged) {
            return None;
        }
        let mut pools: Vec<Pool> = Vec::new();
        let mut end = None;
        for k in 0..self.x.len() {
            let w = self.vertex_weight(k);
            let g = sign * self.y[k] + s * self.x[k];
            let mut pool = Pool {
                start: k,
                len: 1,
                weight: w,
                weighted: w * g,
                mean: g,
            };
            while let Some(last) = pools.last() {
                let gap = s * (self.x[k] - self.x[last.start + last.len - 1]);
                if last.mean - pool.mean <= SLOPE_TOLERANCE * gap {
                    break;
                }
                let mut last = pools.pop().expect("a pool");
                last.merge(&pool);
                pool = last;
                end = Some(k + 1);
            }
            let alone = pool.len == 1;
            pools.push(pool);
            if alone && k >= unchanged {
                break;
            }
        }
        for p in pools.iter().filter(|p| p.len > 1) {
            for k in p.start..p.start + p.len {
                self.y[k] = sign * (p.mean - s * self.x[k]);
            }
        }
        end
    }

    /// Whether `pool` would level anything: two neighbouring vertices out
    /// of order before the first vertex from `unchanged` on. Where none
    /// is, every vertex is a pool of its own and `pool` compares exactly
    /// these pairs, so this scan stands for it without building pools
    /// (most passes find nothing: the last of every relax does).
    fn would_level(&self, s: f64, sign: f64, unchanged: usize) -> bool {
        let mut previous = f64::NAN;
        for k in 0..self.x.len() {
            let g = sign * self.y[k] + s * self.x[k];
            if k > 0 {
                let gap = s * (self.x[k] - self.x[k - 1]);
                // As `pool` compares: a NaN levels.
                let in_order = previous - g <= SLOPE_TOLERANCE * gap;
                if !in_order {
                    return true;
                }
            }
            if k >= unchanged {
                return false;
            }
            previous = g;
        }
        false
    }

    /// Moves the soil the pieces lost onto the pieces that gained, within
    /// each run of changed pieces (one avalanche), mixed: each gaining
    /// piece's γ and ut become the mass-weighted mean of its soil and the
    /// deposit. `before` are the heights before the pools, which changed
    /// no vertex from `end` on.
    fn deposit(&mut self, before: &[f64], end: usize) {
        let pieces = end.min(self.pieces());
        let before: Vec<f64> = (0..pieces).map(|k| self.piece_area_at(before, k)).collect();
        let change: Vec<f64> = (0..pieces)
            .map(|k| self.piece_area(k) - before[k])
            .collect();
        let mut k = 0;
        while k < change.len() {
            if change[k] == 0.0 {
                k += 1;
                continue;
            }
            let end = run_end(&change, k);
            self.deposit_run(k..end, &change, &before);
            k = end;
        }
    }

    /// `deposit` over one run of changed pieces.
    fn deposit_run(&mut self, run: std::ops::Range<usize>, change: &[f64], before: &[f64]) {
        let (mut mass, mut shear_mass, mut gained) = (0.0, 0.0, 0.0);
        for k in run.clone() {
            if change[k] < 0.0 {
                let lost = -change[k] * self.unit_weight[k];
                mass += lost;
                shear_mass += lost * self.accumulated_shear[k];
            } else {
                gained += change[k];
            }
        }
        if gained == 0.0 || mass == 0.0 {
            return;
        }
        let (gamma, ut) = (mass / gained, shear_mass / mass);
        for k in run.filter(|&k| change[k] > 0.0) {
            let own = self.unit_weight[k] * before[k];
            let total = own + gamma * change[k];
            self.accumulated_shear[k] =
                (own * self.accumulated_shear[k] + gamma * change[k] * ut) / total;
            self.unit_weight[k] = total / (before[k] + change[k]);
        }
    }
}

/// The end of the run of changed pieces from `start`: the first unchanged
/// piece where the run's area balances (what its pieces lost, the others
/// gained, to round-off). A piece through which soil runs can keep its
/// area exactly, losing at one end what it gains at the other; ending the
/// run there would deposit one side's soil on nothing and the other's
/// gain with no soil, so mass would not be kept.
fn run_end(change: &[f64], start: usize) -> usize {
    let (mut net, mut gross) = (0.0_f64, 0.0_f64);
    for (i, &c) in change.iter().enumerate().skip(start) {
        if c == 0.0 && net.abs() <= BALANCE * gross {
            return i;
        }
        net += c;
        gross += c.abs();
    }
    change.len()
}

#[cfg(test)]
mod tests {
    use super::{run_end, Settled, Vertices};

    #[test]
    fn cutting_pieces_in_one_pass_is_splitting_them_one_by_one() {
        // The pieces cut as `split_at` cut them, from the far end of the
        // ground and of each piece: the same vertices, heights and states.
        let mut draw = super::super::test_draws(3);
        for case in 0..100 {
            let mut g = Vertices::flat(10.0, 0.2 + draw(), 1.0, 1.0);
            for k in 0..g.x.len() {
                g.y[k] = draw();
            }
            for k in 0..g.pieces() {
                g.accumulated_shear[k] = draw();
            }
            let spacing = 0.01 + 0.3 * draw();
            let near: Vec<usize> = (0..g.pieces()).filter(|_| draw() < 0.4).collect();
            let mut expected = g.clone();
            for &k in near.iter().rev() {
                let (xa, xb) = (expected.x[k], expected.x[k + 1]);
                let parts = ((xb - xa) / spacing).ceil() as usize;
                for i in (1..parts).rev() {
                    expected.split_at(xa + (xb - xa) * i as f64 / parts as f64);
                }
            }
            g.cut_pieces(&near, spacing);
            assert_eq!(g, expected, "case {case}");
        }
    }

    #[test]
    fn a_relax_after_the_settled_ground_is_a_full_relax_bit_for_bit() {
        // Soil heaped near the face increment after increment, now and
        // then a dent far ahead (as a spill makes) and a steep piece cut
        // into vertices: the cached relax pools only what changed and
        // ends on the same ground, state and all, as pooling every vertex.
        let mut draw = super::super::test_draws(7);
        let mut cached = Vertices::flat(20.0, 0.1, 1.0, 1.0);
        let mut settled = Settled::default();
        let slopes = (0.7, 0.7);
        let mut pooled = 0;
        for i in 0..300 {
            let at = 1 + (draw() * 15.0) as usize;
            cached.y[at] += 0.5 * draw();
            cached.accumulated_shear[at] = draw();
            if i % 37 == 0 {
                let far = 100 + (draw() * 80.0) as usize;
                cached.y[far] -= 0.3 * draw();
            }
            let mut full = cached.clone();
            let moved = cached.relax_after(slopes, 0.1, &mut settled);
            assert_eq!(moved, full.relax(slopes, 0.1), "increment {i}");
            assert_eq!(cached, full, "increment {i}");
            pooled += usize::from(moved);
        }
        assert!(pooled > 100, "{pooled} increments pooled");
    }

    #[test]
    fn a_run_ends_where_its_area_balances_not_at_a_piece_soil_ran_through() {
        // Piece 1 loses at one end what it gains at the other: the soil
        // piece 0 lost lands on piece 2, one run.
        assert_eq!(run_end(&[-1.0, 0.0, 1.0, 0.0], 0), 3);
        // Two avalanches of their own, each balanced, apart.
        assert_eq!(run_end(&[-1.0, 1.0, 0.0, -2.0, 2.0], 0), 2);
        assert_eq!(run_end(&[-1.0, 1.0, 0.0, -2.0, 2.0], 3), 5);
    }
}
