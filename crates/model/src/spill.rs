//! Soil that spills around the edges of a blade of finite width into side
//! heaps (docs/model.md §16.5).
//!
//! The model moves soil per unit width across the blade (the strip). Ahead
//! of a blade of width w the pile, of height h above the original ground,
//! cannot stand vertically at the blade's edges: in the section across the
//! direction of travel it falls away at the angle of repose θr on both
//! sides. So a section of the soil above the ground holds the strip, w h,
//! and the two flanks, ½ h² cot θr each:
//!
//! ```text
//! A(h) = w h + h² cot θr                                              (M44)
//! ```
//!
//! After each increment (kinematics and avalanching conserve the strip's
//! soil per unit width) every node ahead of the face whose pile would stand
//! above its side heaps, h_i² cot θr > S_i, gives up soil sideways until the
//! section is (M44) again, with the side heaps S_i holding the flanks:
//!
//! ```text
//! w h'_i + h'_i² cot θr = w h_i + S_i,   S'_i = S_i + w (h_i − h'_i)   (M45)
//! ```
//!
//! Mass is exact: what the strip loses at node i, γ_i w (h_i − h'_i) times
//! the node's trapezoid share of Δx (M24), is what the side heaps gain, so
//! the soil ahead of the blade plus the soil spilled is the soil the blade
//! has met, to round-off. Spill is one way: a side heap does not flow back
//! when the strip later drops (the blade passes between its ridges, and a
//! heap at repose beside a lower strip is stable). It is local in x, the
//! pile's long axis being the direction of travel. As w → ∞, h' → h.

use crate::surface::{compensated_sum, Surface};
use std::ops::Range;

/// The side heaps of a blade of finite width, per node of the grid.
#[derive(Clone, Debug, Default)]
pub struct SideHeaps {
    /// S_i: cross-section area of both side heaps at node i.
    pub area: Vec<f64>,
    /// h_s,i = √(S_i tan θr): crest height of the heaps at the blade's edge.
    pub height: Vec<f64>,
    /// γs,i: unit weight of the heaps' soil (weight-averaged as it arrives).
    pub unit_weight: Vec<f64>,
    /// Weight spilled so far, per unit of the blade's width.
    pub spilled: f64,
    /// The strip's losses of one spill, summed compensated.
    lost: Vec<f64>,
}

impl SideHeaps {
    /// Spills the strip's soil at `nodes` (ahead of the face) into the side
    /// heaps of a blade of width `width` (M45); returns the weight spilled
    /// per unit width.
    pub fn spill(
        &mut self,
        surface: &mut Surface,
        width: f64,
        tan_repose: f64,
        nodes: Range<usize>,
    ) -> f64 {
        let n = surface.len();
        if self.area.len() < n {
            self.area.resize(n, 0.0);
            self.height.resize(n, 0.0);
            self.unit_weight.resize(n, 0.0);
        }
        let cot = 1.0 / tan_repose;
        let first = surface.face.node;
        self.lost.clear();
        for i in nodes {
            let (h, s) = (surface.height[i], self.area[i]);
            if h <= 0.0 || h * h * cot <= s {
                continue;
            }
            // The positive root of cot h'² + w h' − (w h + S) = 0, in the
            // form without cancellation.
            let section = width * h + s;
            let kept = 2.0 * section / (width + (width * width + 4.0 * cot * section).sqrt());
            if kept >= h {
                continue;
            }
            let gamma = surface.unit_weight[i];
            let moved = width * (h - kept);
            let area = s + moved;
            self.unit_weight[i] = (self.unit_weight[i] * s + gamma * moved) / area;
            self.area[i] = area;
            self.height[i] = (area * tan_repose).sqrt();
            // The strip's loss by its own mass rule (M24), so that the
            // balance is exact.
            let before = surface.unit_weight[i] * surface.column_area(i, first);
            surface.height[i] = kept;
            self.lost
                .push(before - gamma * surface.column_area(i, first));
        }
        let weight = compensated_sum(self.lost.iter().copied());
        self.spilled += weight;
        weight
    }

    /// Whether any side heap lies at or after node `from`.
    pub fn any_from(&self, from: usize) -> bool {
        self.height
            .get(from..)
            .is_some_and(|h| h.iter().any(|&v| v > 0.0))
    }
}
