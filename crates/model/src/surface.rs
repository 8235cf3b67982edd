//! The free surface: nodes on a fixed grid x_i = i Δx, each carrying the
//! height of the surface, the accumulated shearing displacement ut of the
//! soil there (with the friction and dilation angles it implies) and the unit
//! weight γ of its column.
//!
//! The grid spacing equals the blade increment v0, so the blade sits on node
//! `blade` = (steps done) and a block translating by v0 moves exactly one node.
//! The soil of node i is its column from the fixed floor y = −d up to the
//! surface, integrated with the trapezoid rule over the nodes in front of the
//! blade (half weight at both ends): the weight of soil is
//! M = Δx Σ w_i γ_i (h_i + d).

/// Nodes of the free surface.
#[derive(Clone, Debug)]
pub struct Surface {
    /// Δx: node spacing (= v0).
    pub spacing: f64,
    /// y of the floor below which soil never moves (−d).
    pub floor: f64,
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
    appended_mass: f64,
}

impl Surface {
    /// Flat ground y = 0 of `nodes` nodes from x = 0, of fresh soil with
    /// friction and dilation angles `fresh_angles` (radians).
    pub fn flat(
        spacing: f64,
        depth: f64,
        unit_weight: f64,
        fresh_angles: (f64, f64),
        nodes: usize,
    ) -> Self {
        Surface {
            spacing,
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

    /// x_i = i Δx of node i (on the grid; physical for a vertical blade).
    pub fn x(&self, i: usize) -> f64 {
        i as f64 * self.spacing
    }

    /// Appends `nodes` nodes of undisturbed flat ground at the far end.
    /// Exact: the search only grows the domain when its proven bound says a
    /// candidate there could still win (see `search`).
    pub fn grow(&mut self, nodes: usize) {
        let n = self.len() + nodes;
        self.height.resize(n, 0.0);
        self.accumulated_shear.resize(n, 0.0);
        self.unit_weight.resize(n, self.ground_unit_weight);
        self.friction.resize(n, self.fresh_angles.0);
        self.dilation.resize(n, self.fresh_angles.1);
        self.appended_mass +=
            self.ground_unit_weight * (0.0 - self.floor) * self.spacing * nodes as f64;
    }

    /// Records that nodes before `end` may have changed.
    pub fn disturb(&mut self, end: usize) {
        self.pristine_from = self.pristine_from.max(end);
    }

    /// Trapezoid weight of node i among the nodes from `first` to the end.
    pub fn node_weight(&self, i: usize, first: usize) -> f64 {
        if i == first || i + 1 == self.len() {
            0.5
        } else {
            1.0
        }
    }

    /// Area of the column of node i (trapezoid share, above the floor).
    pub fn column_area(&self, i: usize, first: usize) -> f64 {
        self.node_weight(i, first) * (self.height[i] - self.floor) * self.spacing
    }

    /// Area of soil in front of the blade at node `first` (above the floor,
    /// less appended ground).
    pub fn area(&self, first: usize) -> f64 {
        let appended = self.appended_mass / self.ground_unit_weight;
        compensated_sum((first..self.len()).map(|i| self.column_area(i, first))) - appended
    }

    /// Weight of soil in front of the blade at node `first` and of the soil
    /// left below the tip's path, counting only the ground that
    /// existed at the start.
    pub fn mass(&self, first: usize) -> f64 {
        let undisturbed = self.pristine_from.clamp(first, self.len());
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
}

/// Neumaier's compensated sum: conservation checks at 1e-12 need better than
/// naive summation over 10⁵ nodes.
pub fn compensated_sum(values: impl Iterator<Item = f64>) -> f64 {
    let (mut sum, mut c) = (0.0f64, 0.0f64);
    for v in values {
        let t = sum + v;
        c += if sum.abs() >= v.abs() {
            (sum - t) + v
        } else {
            (v - t) + sum
        };
        sum = t;
    }
    sum + c
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
    fn compensated_sum_beats_naive() {
        let v = [1e16, 1.0, -1e16, 1.0];
        assert_eq!(compensated_sum(v.into_iter()), 2.0);
    }
}
