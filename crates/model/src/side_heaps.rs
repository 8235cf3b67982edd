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
//! has met, to round-off (each ground sums the strip's loss by its own mass
//! rule: the node grid's trapezoid shares, the vertex ground's pieces). Spill is one way: a side heap does not flow back
//! when the strip later drops (the blade passes between its ridges, and a
//! heap at repose beside a lower strip is stable). It is local in x, the
//! pile's long axis being the direction of travel. As w → ∞, h' → h.

use serde::{Deserialize, Serialize};

/// The side heaps of a blade of finite width: a field at fixed x, node i
/// at x = i h for the field's spacing h (the node grid's nodes; on the
/// vertex ground, whose vertices move with the soil, its vertex spacing).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SideHeaps {
    /// S_i: cross-section area of both side heaps at node i.
    pub area: Vec<f64>,
    /// h_s,i = √(S_i tan θr): crest height of the heaps at the blade's edge.
    pub height: Vec<f64>,
    /// γs,i: unit weight of the heaps' soil (weight-averaged as it arrives).
    pub unit_weight: Vec<f64>,
    /// Weight spilled so far, per unit of the blade's width.
    pub spilled: f64,
}

/// A column of the strip that may spill (M45).
#[derive(Clone, Copy, Debug)]
pub struct Column {
    /// h: its height above the original ground (length).
    pub height: f64,
    /// γ of its soil (force per volume).
    pub unit_weight: f64,
}

/// The blade's width w and tan θr of the heaps' flanks.
#[derive(Clone, Copy, Debug)]
pub struct Edges {
    /// w (length).
    pub width: f64,
    /// tan θr.
    pub tan_repose: f64,
}

impl Edges {
    /// h': the height the strip keeps at a column of height h beside side
    /// heaps of section S (M45), if it spills: the positive root of
    /// cot h'² + w h' − (w h + S) = 0, in the form without cancellation.
    fn kept(&self, h: f64, s: f64) -> Option<f64> {
        let (w, cot) = (self.width, 1.0 / self.tan_repose);
        if h <= 0.0 || h * h * cot <= s {
            return None;
        }
        let section = w * h + s;
        let kept = 2.0 * section / (w + (w * w + 4.0 * cot * section).sqrt());
        (kept < h).then_some(kept)
    }
}

impl SideHeaps {
    /// Spills `column`, standing at node i of the field, into the heaps
    /// there (M45); returns the height the strip keeps, if it spilled.
    pub fn spill_at_node(&mut self, i: usize, column: Column, edges: Edges) -> Option<f64> {
        self.reach(i + 1);
        let kept = edges.kept(column.height, self.area[i])?;
        let moved = edges.width * (column.height - kept);
        self.deposit(i, moved, column.unit_weight, edges);
        Some(kept)
    }

    /// Spills `column`, standing at x between the field's nodes `spacing`
    /// apart and holding the strip over a length `share` of x, into the
    /// heaps (M45, S read linearly between the nodes); returns the height
    /// the strip keeps, if it spilled. The section w (h − h') it gives
    /// over `share` goes to the two nodes about x by the hat functions,
    /// so that the field's volume Σ S_i h grows by exactly w (h − h') share.
    pub fn spill_at(
        &mut self,
        (x, spacing): (f64, f64),
        share: f64,
        column: Column,
        edges: Edges,
    ) -> Option<f64> {
        let at = x / spacing;
        let i = at.floor() as usize;
        self.reach(i + 2);
        let t = at - i as f64;
        let s = self.area[i] + t * (self.area[i + 1] - self.area[i]);
        let kept = edges.kept(column.height, s)?;
        let moved = edges.width * (column.height - kept) * share / spacing;
        self.deposit(i, moved * (1.0 - t), column.unit_weight, edges);
        self.deposit(i + 1, moved * t, column.unit_weight, edges);
        Some(kept)
    }

    /// h_s at x for the field's `spacing`, linear between nodes (0 beyond).
    pub fn height_at(&self, x: f64, spacing: f64) -> f64 {
        let at = x / spacing;
        let i = at.floor() as usize;
        match (self.height.get(i), self.height.get(i + 1)) {
            (Some(a), Some(b)) => a + (at - i as f64) * (b - a),
            (Some(a), None) => *a,
            _ => 0.0,
        }
    }

    /// The highest crest h_s of the field (0 without heaps).
    pub fn highest(&self) -> f64 {
        self.height.iter().fold(0.0, |a, &h| a.max(h))
    }

    /// Whether any side heap lies at or after node `from`.
    pub fn any_from(&self, from: usize) -> bool {
        self.height
            .get(from..)
            .is_some_and(|h| h.iter().any(|&v| v > 0.0))
    }

    /// The field holds at least `nodes` nodes (0 beyond its heaps, which
    /// the crescents read linearly: a field that ended at its last heap
    /// would hold that heap's height beyond it).
    pub fn reach(&mut self, nodes: usize) {
        if self.area.len() < nodes {
            self.area.resize(nodes, 0.0);
            self.height.resize(nodes, 0.0);
            self.unit_weight.resize(nodes, 0.0);
        }
    }

    /// Adds the section `moved` of soil of unit weight γ to node i.
    fn deposit(&mut self, i: usize, moved: f64, gamma: f64, edges: Edges) {
        if moved <= 0.0 {
            return;
        }
        let s = self.area[i];
        let area = s + moved;
        self.unit_weight[i] = (self.unit_weight[i] * s + gamma * moved) / area;
        self.area[i] = area;
        self.height[i] = (area * edges.tan_repose).sqrt();
    }
}
