//! Avalanching (docs/model.md §6, §9.1): sand cannot stand steeper than its
//! angle of repose θr.
//!
//! With s = Δx tan θr, the surface must satisfy |y_{i+1} − y_i| ≤ s. The
//! downslope constraint y_{i+1} ≥ y_i − s says g_i = y_i + s i is
//! non-decreasing; the upslope one says y_i − s i is non-increasing. Each is
//! restored by one pass of the pool-adjacent-violators algorithm with the
//! trapezoid node weights: every pooled run of nodes is replaced by a line at
//! exactly the angle of repose holding the same weighted area, so soil moves
//! from above that line to below it (downslope) and area is conserved
//! exactly. The two passes alternate until neither pools anything.
//!
//! State travels with the soil: the soil removed from the nodes above the
//! line is mixed (mass-weighted) and deposited on the nodes below it, whose
//! unit weight and accumulated shear become the mass-weighted mean of their
//! column and the deposit. Mass is therefore conserved exactly as well.

use crate::node_grid::surface::Surface;
use crate::repose::{Pool, MAX_PASSES, SLOPE_TOLERANCE};
use std::ops::Range;

/// Reusable scratch for avalanching (no allocation per step).
#[derive(Clone, Debug, Default)]
pub struct Avalanche {
    pools: Vec<Pool>,
    old_height: Vec<f64>,
    windows: Vec<Range<usize>>,
}

impl Avalanche {
    /// Relaxes every slope steeper than the angle of repose among the nodes
    /// from `first` (the face) to the end of the domain, given as the
    /// steepest grid slopes downhill and uphill (`slopes`; an infinite one
    /// is no limit), where slopes elsewhere
    /// are known to be at most the angle of repose: only the nodes in
    /// `changed` (and as far as pooling spreads from them) are visited;
    /// the result is that of passes over the whole domain. Returns the range
    /// of nodes whose soil moved (empty if none).
    pub fn relax(
        &mut self,
        surface: &mut Surface,
        first: usize,
        slopes: (f64, f64),
        changed: &[Range<usize>],
    ) -> Range<usize> {
        // s_down, s_up = Δx times the grid's repose slopes (M29); the passes
        // restore −s_down ≤ y_{i+1} − y_i ≤ s_up (M28).
        let (down, up) = (surface.spacing * slopes.0, surface.spacing * slopes.1);
        self.set_windows(changed, first, surface.len());
        let mut touched = first..first;
        for _ in 0..MAX_PASSES {
            // No downhill limit (a face flatter than the repose, `Rake`).
            let down = down.is_finite() && self.pass(surface, first, down, 1.0, &mut touched);
            let up = self.pass(surface, first, up, -1.0, &mut touched);
            if !down && !up {
                break;
            }
        }
        touched
    }

    /// Sorted, disjoint windows of node pairs to examine, within the domain.
    fn set_windows(&mut self, changed: &[Range<usize>], first: usize, len: usize) {
        self.windows.clear();
        for r in changed {
            let (lo, hi) = (r.start.max(first), r.end.min(len));
            if lo < hi {
                self.windows.push(lo..hi);
            }
        }
        self.windows.sort_by_key(|w| w.start);
        self.merge_windows();
    }

    fn merge_windows(&mut self) {
        let mut k = 0;
        while k + 1 < self.windows.len() {
            if self.windows[k].end >= self.windows[k + 1].start {
                let next = self.windows.remove(k + 1);
                self.windows[k].end = self.windows[k].end.max(next.end);
            } else {
                k += 1;
            }
        }
    }

    /// One pool-adjacent-violators pass on g_i = σ y_i + s (i − first) over
    /// every window; returns whether anything moved.
    fn pass(
        &mut self,
        surface: &mut Surface,
        first: usize,
        s: f64,
        sign: f64,
        touched: &mut Range<usize>,
    ) -> bool {
        while self.widen(surface, first, s, sign) {}
        self.apply(surface, first, s, sign, touched)
    }

    /// Pools every window; where pooling runs into a window's edge (it may
    /// continue beyond it) widens that window and returns true; false once
    /// no window does. Nothing is levelled before every window is settled,
    /// so the pools are those of a pass over the whole domain.
    fn widen(&mut self, surface: &Surface, first: usize, s: f64, sign: f64) -> bool {
        self.pools.clear();
        for k in 0..self.windows.len() {
            let window = self.windows[k].clone();
            let start = self.pools.len();
            self.pool(surface, first, s, sign, window.clone());
            let open_lo = window.start > first && self.pools[start].len > 1;
            let open_hi =
                window.end < surface.len() && self.pools.last().is_some_and(|p| p.len > 1);
            if open_lo || open_hi {
                let width = window.end - window.start;
                let lo = if open_lo {
                    window.start.saturating_sub(width).max(first)
                } else {
                    window.start
                };
                let hi = if open_hi {
                    (window.end + width).min(surface.len())
                } else {
                    window.end
                };
                self.windows[k] = lo..hi;
                self.merge_windows();
                return true;
            }
        }
        false
    }

    /// The pools of the nodes in `window` (PAVA with a stack).
    fn pool(&mut self, surface: &Surface, first: usize, s: f64, sign: f64, window: Range<usize>) {
        let bottom = self.pools.len();
        let tolerance = SLOPE_TOLERANCE * s;
        for i in window {
            let w = surface.node_weight(i, first);
            let g = sign * surface.height[i] + s * (i - first) as f64;
            let mut top = Pool::new(i, w, g);
            while self.pools.len() > bottom {
                let below = self.pools.last_mut().expect("a pool below");
                if below.mean <= top.mean + tolerance {
                    break;
                }
                below.merge(&top);
                top = self.pools.pop().expect("the merged pool");
            }
            self.pools.push(top);
        }
    }

    /// Levels every pooled run; returns whether anything moved.
    fn apply(
        &mut self,
        surface: &mut Surface,
        first: usize,
        s: f64,
        sign: f64,
        touched: &mut Range<usize>,
    ) -> bool {
        let mut moved = false;
        for k in 0..self.pools.len() {
            let pool = self.pools[k];
            if pool.len > 1 {
                moved = true;
                let end = pool.start + pool.len;
                *touched = if touched.start >= touched.end {
                    pool.start..end
                } else {
                    touched.start.min(pool.start)..touched.end.max(end)
                };
                self.level(surface, first, pool, s, sign);
            }
        }
        moved
    }

    /// Replaces the pooled run by the repose line and moves state with soil.
    fn level(&mut self, surface: &mut Surface, first: usize, pool: Pool, s: f64, sign: f64) {
        let range = pool.start..pool.start + pool.len;
        let mean = pool.mean;
        self.old_height.clear();
        self.old_height
            .extend_from_slice(&surface.height[range.clone()]);
        let (mut lost_area, mut lost_mass, mut lost_shear, mut gained_area) = (0.0, 0.0, 0.0, 0.0);
        for i in range.clone() {
            let new = sign * (mean - s * (i - first) as f64);
            let w = surface.node_weight(i, first) * surface.spacing;
            let delta = (new - surface.height[i]) * w;
            if delta < 0.0 {
                let m = -delta * surface.unit_weight[i];
                lost_area -= delta;
                lost_mass += m;
                lost_shear += m * surface.accumulated_shear[i];
            } else {
                gained_area += delta;
            }
            surface.height[i] = new;
        }
        if gained_area <= 0.0 || lost_area <= 0.0 {
            return;
        }
        // Deposit exactly the removed mass, spread over the gained area.
        let deposit_weight = lost_mass / gained_area;
        let deposit_shear = lost_shear / lost_mass;
        for (k, i) in range.enumerate() {
            let w = surface.node_weight(i, first) * surface.spacing;
            let old_area = (self.old_height[k] - surface.floor) * w;
            let gain = (surface.height[i] - self.old_height[k]) * w;
            if gain <= 0.0 {
                continue;
            }
            let old_mass = surface.unit_weight[i] * old_area;
            let new_mass = old_mass + deposit_weight * gain;
            surface.accumulated_shear[i] = (old_mass * surface.accumulated_shear[i]
                + deposit_weight * gain * deposit_shear)
                / new_mass;
            surface.unit_weight[i] = new_mass / (old_area + gain);
        }
    }
}
