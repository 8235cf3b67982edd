//! The free surface of the node grid: nodes on a fixed grid x_i = i h,
//! h = v0 (docs/model.md §9.1), each carrying the height of the surface, the
//! accumulated shearing displacement ut of the soil there (with the
//! friction and dilation angles it implies) and the unit weight γ of its
//! column. The blade sits on node b = (increments done), and a block
//! translating by v0 moves exactly one node.
//!
//! The soil of node i is its column from the fixed floor y = −d up to the
//! surface, integrated with the trapezoid rule over the nodes in front of the
//! blade: the weight of soil is M = h Σ w_i γ_i (y_i + d), w_i = 1 inside,
//! ½ at the face and at the far end (`FaceNode`).

use crate::mass::compensated_sum;
use crate::material::Material;
use crate::node_grid::face_node::FaceNode;
use std::ops::Range;

/// Nodes of the free surface.
#[derive(Clone, Debug)]
pub struct Surface {
    /// h = Δx = v0, the node spacing (length).
    pub spacing: f64,
    /// y of the floor below which soil never moves (−d).
    pub floor: f64,
    /// The blade face: the node of the soil column at it.
    pub face: FaceNode,
    /// Unit weight of the ground appended when the domain grows.
    pub ground_unit_weight: f64,
    /// y_i: surface height at x_i = i Δx.
    pub height: Vec<f64>,
    /// ut_i: accumulated shearing displacement of the soil at node i.
    pub accumulated_shear: Vec<f64>,
    /// γ_i: unit weight of the column at node i.
    pub unit_weight: Vec<f64>,
    /// φ(ut_i), radians: kept in step with `accumulated_shear` by the caller.
    pub friction: Vec<f64>,
    /// ψ(ut_i), radians: kept in step with `accumulated_shear` by the caller.
    pub dilation: Vec<f64>,
    /// φ and ψ of fresh soil (ut = 0), for appended ground.
    fresh_angles: (f64, f64),
    /// Nodes from here on are undisturbed flat ground (y = 0, ut = 0, γ0).
    pub pristine_from: usize,
    /// Weight of the soil left below the tip's path behind the blade (a
    /// blade on a depth path passes over it).
    pub trench_mass: f64,
    /// Weight of the flat ground appended by `grow`, so that `mass` counts
    /// only the ground that existed at the start.
    pub(crate) appended_mass: f64,
    /// Area of the same (differs from its weight / γ0 where the old last
    /// node had a γ of its own).
    pub(crate) appended_area: f64,
}

impl Surface {
    /// Flat ground y = 0 of `nodes` nodes from x = 0, `spacing` apart (the
    /// node grid (M1): x_i = i Δx, Δx = v0), of fresh soil with friction
    /// and dilation angles `fresh_angles` (radians).
    pub fn flat(
        spacing: f64,
        depth: f64,
        unit_weight: f64,
        fresh_angles: (f64, f64),
        nodes: usize,
    ) -> Self {
        Surface {
            spacing,
            face: FaceNode::default(),
            floor: -depth,
            ground_unit_weight: unit_weight,
            height: vec![0.0; nodes],
            accumulated_shear: vec![0.0; nodes],
            unit_weight: vec![unit_weight; nodes],
            friction: vec![fresh_angles.0; nodes],
            dilation: vec![fresh_angles.1; nodes],
            fresh_angles,
            pristine_from: 0,
            trench_mass: 0.0,
            appended_mass: 0.0,
            appended_area: 0.0,
        }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.height.len()
    }

    /// Whether the surface has no nodes.
    pub fn is_empty(&self) -> bool {
        self.height.is_empty()
    }

    /// x of node i: i Δx on the grid (M1) (physical for a vertical blade).
    pub fn x(&self, i: usize) -> f64 {
        i as f64 * self.spacing
    }

    /// Appends `nodes` nodes of undisturbed flat ground at the far end.
    /// Exact: the search only grows the domain when its proven bound says a
    /// candidate there could still win (see `search`).
    pub fn grow(&mut self, nodes: usize) {
        if nodes == 0 {
            return;
        }
        // The old last node's column goes from half weight (M24) to whole.
        // Its other half is no ground that existed at the start: flat
        // ground as much as an appended node's, and on ground that soil has
        // reached (y ≠ 0, γ ≠ γ0) the soil on it, which its half weight
        // already counts. Found by fuzzing (docs/fuzzing.md): a slip line
        // at 75° friction reached the end, and the growth gained that half.
        let last = self.len() - 1;
        let half = 0.5 * self.spacing * (self.height[last] - self.floor);
        self.appended_area += half - 0.5 * self.spacing * (0.0 - self.floor);
        self.appended_mass += half * self.unit_weight[last]
            - 0.5 * self.ground_unit_weight * (0.0 - self.floor) * self.spacing;
        let n = self.len() + nodes;
        self.height.resize(n, 0.0);
        self.accumulated_shear.resize(n, 0.0);
        self.unit_weight.resize(n, self.ground_unit_weight);
        self.friction.resize(n, self.fresh_angles.0);
        self.dilation.resize(n, self.fresh_angles.1);
        let appended = (0.0 - self.floor) * self.spacing * nodes as f64;
        self.appended_area += appended;
        self.appended_mass += self.ground_unit_weight * appended;
    }

    /// Records that nodes before `end` may have changed.
    pub fn disturb(&mut self, end: usize) {
        self.pristine_from = self.pristine_from.max(end);
    }

    /// Trapezoid weight of node i among the nodes from `first` to the end.
    pub fn node_weight(&self, i: usize, first: usize) -> f64 {
        if i + 1 == self.len() {
            0.5
        } else {
            FaceNode { node: first }.node_weight(i)
        }
    }

    /// Area of the column of node i (trapezoid share, above the floor).
    pub fn column_area(&self, i: usize, first: usize) -> f64 {
        self.node_weight(i, first) * (self.height[i] - self.floor) * self.spacing
    }

    /// Area of soil in front of the blade at node `first` (above the floor,
    /// less appended ground).
    pub fn area(&self, first: usize) -> f64 {
        compensated_sum((first..self.len()).map(|i| self.column_area(i, first)))
            - self.appended_area
    }

    /// Weight of soil in front of the blade at node `first` and of the soil
    /// left below the tip's path, counting only the ground that
    /// existed at the start: M = Δx Σ w_i γ_i (y_i − y_floor) + M_trench
    /// less the appended ground (M24).
    pub fn mass(&self, first: usize) -> f64 {
        let undisturbed = self.pristine_from.max(first).clamp(first, self.len());
        let disturbed =
            (first..undisturbed).map(|i| self.unit_weight[i] * self.column_area(i, first));
        // Undisturbed columns, γ0 d Δx each (half at the ends), in closed form.
        let whole = (self.len() - undisturbed) as f64;
        let halves = [first, self.len() - 1]
            .iter()
            .filter(|&&i| i >= undisturbed)
            .count() as f64;
        let column = self.ground_unit_weight * (0.0 - self.floor) * self.spacing;
        let pristine = column * (whole - 0.5 * halves.min(whole));
        compensated_sum(disturbed.chain([pristine, self.trench_mass, -self.appended_mass]))
    }

    /// Recomputes φ(ut) and ψ(ut) of the nodes in `range` from the soil's
    /// laws (Fig. 2).
    pub(crate) fn refresh_angles(&mut self, material: &Material, range: Range<usize>) {
        for i in range {
            let ut = self.accumulated_shear[i];
            self.friction[i] = material.friction.at(ut);
            self.dilation[i] = material.dilation.at(ut);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn growing_flat_ground_keeps_mass() {
        let mut s = Surface::flat(0.1, 2.0, 1.5, (0.5, 0.0), 101);
        let m0 = s.mass(0);
        assert!((m0 - 1.5 * 2.0 * 10.0).abs() < 1e-12);
        s.grow(37);
        assert!((s.mass(0) - m0).abs() < 1e-12 * m0);
        assert!((s.area(0) - 20.0).abs() < 1e-12);
    }

    #[test]
    fn growing_past_soil_at_the_end_keeps_mass() {
        let mut s = Surface::flat(0.1, 2.0, 1.5, (0.5, 0.0), 101);
        // Soil that has reached the last node, looser than the ground.
        s.height[99] = 0.02;
        s.height[100] = 0.01;
        s.unit_weight[99] = 1.2;
        s.unit_weight[100] = 1.3;
        s.disturb(101);
        let (m0, a0) = (s.mass(0), s.area(0));
        s.grow(37);
        assert!((s.mass(0) - m0).abs() < 1e-12 * m0, "{} {m0}", s.mass(0));
        assert!((s.area(0) - a0).abs() < 1e-12 * a0, "{} {a0}", s.area(0));
    }
}
