//! The strip's soil spilling around the edges of a blade of finite width
//! on the vertex ground (M45, docs/model.md §16.5): the side heaps are a
//! field at fixed x (`SideHeaps`), the vertices move with the soil.

use super::Vertices;
use crate::mass::compensated_sum;
use crate::side_heaps::{Column, Edges, SideHeaps};

impl Vertices {
    /// Spills the strip at every vertex above the original ground into
    /// `side`, a field of nodes `spacing` apart (M45); returns the weight
    /// spilled per unit width. Vertex k stands for half of each piece
    /// beside it: lowering it by δ takes δ Σ γ_p ½ Δx_p from the strip
    /// (the pieces' trapezoids, exactly what `mass` loses), the soil the
    /// heaps gain at its weight-averaged unit weight.
    pub(crate) fn spill(&mut self, side: &mut SideHeaps, edges: Edges, spacing: f64) -> f64 {
        let last = self.pieces();
        side.reach((self.x[last] / spacing) as usize + 2);
        let mut lost = Vec::new();
        for k in 0..=last {
            let height = self.y[k];
            if height <= 0.0 {
                continue;
            }
            let half = |p: usize| 0.5 * (self.x[p + 1] - self.x[p]);
            let (left, right) = (
                if k == 0 { 0.0 } else { half(k - 1) },
                if k == last { 0.0 } else { half(k) },
            );
            let weight = (if k == 0 {
                0.0
            } else {
                self.unit_weight[k - 1] * left
            }) + (if k == last {
                0.0
            } else {
                self.unit_weight[k] * right
            });
            let share = left + right;
            let column = Column {
                height,
                unit_weight: weight / share,
            };
            if let Some(kept) = side.spill_at((self.x[k], spacing), share, column, edges) {
                self.y[k] = kept;
                lost.push(weight * (height - kept));
            }
        }
        let spilled = compensated_sum(lost.into_iter());
        side.spilled += spilled;
        spilled
    }
}
