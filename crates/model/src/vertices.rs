//! A ground whose points move with the soil (issue 28; docs/model.md §1.2-§7,
//! measured in docs/performance.md, "Issue 28, second step: the vertex
//! ground"): the free surface
//! as a polyline of vertices (x_k, y_k), x strictly increasing, vertex 0
//! at the blade face, and the soil's state held per piece, piece k lying
//! between vertices k and k + 1.
//!
//! The vertices are material points: an increment moves them with the soil
//! (`motion`), so the state a piece carries travels with it and is never
//! interpolated; a vertex is made only where the face, a band boundary or
//! the emergence point cuts a piece, and the two halves keep its state.
//! With vertices every v0 and a band that emerges at a vertex, the block
//! translates by exactly one piece, as the reference grid's nodes do
//! (docs/model.md §9).
//!
//! The soil of piece k is its columns from the fixed floor y = −d up to
//! the surface, of unit weight γ_k: the weight of soil in front of the
//! blade is M = Σ_k γ_k ½ (x_{k+1} − x_k)(y_k + y_{k+1} − 2 y_floor) + M_trench,
//! exact for a polyline (the trapezoid rule integrates a linear surface
//! exactly).
//!
//! The default ground, `run.ground = "vertices"` (`cutting`, one
//! increment); the node grid (`node_grid`) is the yardstick it is judged
//! against.

use crate::mass::compensated_sum;
use serde::{Deserialize, Serialize};

pub(crate) mod avalanche;
pub(crate) mod cutting;
mod merge;
mod midpoint;
pub mod motion;
mod scan;
pub(crate) mod search;
mod spill;
mod strength;

pub use merge::Quiet;

/// The free surface as vertices that move with the soil, with the state
/// of the soil held per piece between them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Vertices {
    /// x_k: abscissae of the vertices, strictly increasing; x_0 is the
    /// blade face (length).
    pub x: Vec<f64>,
    /// y_k: heights of the vertices (length).
    pub y: Vec<f64>,
    /// ut of piece k, between vertices k and k + 1 (length).
    pub accumulated_shear: Vec<f64>,
    /// γ of the columns of piece k (force per volume).
    pub unit_weight: Vec<f64>,
    /// y of the floor below which soil never moves (−d).
    pub floor: f64,
    /// Weight of the soil left below the tip's path behind the blade.
    pub trench_mass: f64,
    /// γ0, the unit weight of the flat ground appended by `extend_flat`.
    pub ground_unit_weight: f64,
    /// Weight of the ground `extend_flat` appended, so that `mass` counts
    /// only the ground that existed at the start.
    pub appended_mass: f64,
}

impl Vertices {
    /// Flat ground y = 0 of fresh soil (ut = 0, γ `unit_weight`) from
    /// x = 0 to `length`, with vertices every `spacing` (the last piece
    /// ends at `length` exactly), above the floor at −`depth`. No piece
    /// has length 0: where `length` is a whole number of spacings to
    /// round-off, length / spacing rounds above it (10 d over d/50 is
    /// 500.00000000000006 at d = 5.549742791184853) and the last k h
    /// lands on `length`; a piece of length 0 there, once the search grew
    /// the ground past it, gave a band 0 / 0 for its unit weight (issue 50).
    pub fn flat(length: f64, spacing: f64, depth: f64, unit_weight: f64) -> Self {
        let pieces = (length / spacing).ceil().max(1.0) as usize;
        let mut x: Vec<f64> = (0..pieces)
            .map(|k| k as f64 * spacing)
            .take_while(|&x| x < length)
            .collect();
        x.push(length);
        let pieces = x.len() - 1;
        Vertices {
            y: vec![0.0; x.len()],
            x,
            accumulated_shear: vec![0.0; pieces],
            unit_weight: vec![unit_weight; pieces],
            floor: -depth,
            trench_mass: 0.0,
            ground_unit_weight: unit_weight,
            appended_mass: 0.0,
        }
    }

    /// Appends a piece of fresh ground (ut = 0, γ0) from the last vertex to
    /// `length` beyond it at y = 0. Exact where the search may need it:
    /// the weight it adds is not counted by `mass`.
    pub fn extend_flat(&mut self, length: f64) {
        let end = self.x[self.pieces()] + length;
        self.x.push(end);
        self.y.push(0.0);
        self.accumulated_shear.push(0.0);
        self.unit_weight.push(self.ground_unit_weight);
        let k = self.pieces() - 1;
        self.appended_mass += self.ground_unit_weight * self.piece_area(k);
    }

    /// What is wrong with a ground that no run makes (for a restored
    /// snapshot): columns of unequal length, x not increasing, a number not
    /// finite, ut < 0 or γ ≤ 0; `None` if nothing.
    pub fn defect(&self) -> Option<String> {
        let pieces = self.x.len().saturating_sub(1);
        let lengths = [
            self.y.len(),
            self.accumulated_shear.len() + 1,
            self.unit_weight.len() + 1,
        ];
        if pieces == 0 || lengths.iter().any(|&n| n != self.x.len()) {
            return Some(format!(
                "{} vertices and columns of lengths {lengths:?}",
                self.x.len()
            ));
        }
        let numbers = [
            self.floor,
            self.trench_mass,
            self.ground_unit_weight,
            self.appended_mass,
        ];
        let columns = [&self.x, &self.y, &self.accumulated_shear, &self.unit_weight];
        if numbers
            .iter()
            .chain(columns.into_iter().flatten())
            .any(|v| !v.is_finite())
        {
            return Some("a number that is not finite".into());
        }
        if self.x.windows(2).any(|w| w[1] <= w[0]) {
            return Some("vertices whose x does not increase".into());
        }
        if self.accumulated_shear.iter().any(|&u| u < 0.0)
            || self.unit_weight.iter().any(|&g| g <= 0.0)
        {
            return Some("a piece with ut < 0 or γ <= 0".into());
        }
        None
    }

    /// Number of pieces (one less than the vertices).
    pub fn pieces(&self) -> usize {
        self.x.len() - 1
    }

    /// The piece holding x: the last k with x_k ≤ x, at most the last
    /// piece (x at or beyond the far end belongs to it).
    pub fn piece_at(&self, x: f64) -> usize {
        let k = self.x.partition_point(|&xk| xk <= x);
        k.saturating_sub(1).min(self.pieces() - 1)
    }

    /// `piece_at(x)`, found by walking from piece `hint`: the search's
    /// footprints move along the ground a little at a time, so a short walk
    /// beats the binary search, whose cache misses were a fifth of a run.
    /// A walk longer than `NEAR` falls back to the binary search.
    pub fn piece_near(&self, hint: usize, x: f64) -> usize {
        const NEAR: usize = 8;
        let last = self.pieces() - 1;
        let mut k = hint.min(last);
        for _ in 0..NEAR {
            if k > 0 && self.x[k] > x {
                k -= 1;
            } else if k < last && self.x[k + 1] <= x {
                k += 1;
            } else {
                return k;
            }
        }
        self.piece_at(x)
    }

    /// Height of the surface at x, on the straight piece holding it.
    pub fn height_at(&self, x: f64) -> f64 {
        self.height_on(self.piece_at(x), x)
    }

    /// Height at x on piece k (x in or at the ends of it).
    pub fn height_on(&self, k: usize, x: f64) -> f64 {
        let lambda = (x - self.x[k]) / (self.x[k + 1] - self.x[k]);
        self.y[k] + lambda * (self.y[k + 1] - self.y[k])
    }

    /// The vertex at x: an existing one if x is one, else a new vertex on
    /// the piece holding x, both halves keeping the piece's state (nothing
    /// is interpolated but the height of a straight piece).
    pub fn split_at(&mut self, x: f64) -> usize {
        let k = self.piece_at(x);
        if self.x[k] == x {
            return k;
        }
        if self.x[k + 1] == x {
            return k + 1;
        }
        let y = self.height_at(x);
        self.x.insert(k + 1, x);
        self.y.insert(k + 1, y);
        self.accumulated_shear
            .insert(k + 1, self.accumulated_shear[k]);
        self.unit_weight.insert(k + 1, self.unit_weight[k]);
        k + 1
    }

    /// The x of the vertex at x or within `snap` of it (the nearer of the
    /// piece's two), made by `split_at` if there is none.
    pub fn split_near(&mut self, x: f64, snap: f64) -> f64 {
        let k = self.piece_at(x);
        let nearest = if x - self.x[k] <= self.x[k + 1] - x {
            k
        } else {
            k + 1
        };
        if (self.x[nearest] - x).abs() <= snap && nearest > 0 {
            return self.x[nearest];
        }
        let v = self.split_at(x);
        self.x[v]
    }

    /// Area of the columns of piece k above the floor: the trapezoid
    /// ½ (x_{k+1} − x_k)(y_k + y_{k+1} − 2 y_floor), exact on a straight piece.
    pub fn piece_area(&self, k: usize) -> f64 {
        self.piece_area_at(&self.y, k)
    }

    /// `piece_area` of piece k with the vertices at heights `y` (the
    /// heights an avalanche started from).
    fn piece_area_at(&self, y: &[f64], k: usize) -> f64 {
        let depth = |i: usize| y[i] - self.floor;
        0.5 * (self.x[k + 1] - self.x[k]) * (depth(k) + depth(k + 1))
    }

    /// Area of soil in front of the blade, above the floor.
    pub fn area(&self) -> f64 {
        compensated_sum((0..self.pieces()).map(|k| self.piece_area(k)))
    }

    /// Weight of soil in front of the blade and in the trench behind it,
    /// of the ground that existed at the start: M = Σ_k γ_k A_k + M_trench
    /// less what `extend_flat` appended.
    pub fn mass(&self) -> f64 {
        let pieces = (0..self.pieces()).map(|k| self.unit_weight[k] * self.piece_area(k));
        compensated_sum(pieces.chain([self.trench_mass, -self.appended_mass]))
    }
}

/// A reproducible stream of numbers in [0, 1) for the tests of the
/// ground's operations (a linear congruential generator).
#[cfg(test)]
pub(crate) fn test_draws(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitting_keeps_the_surface_and_the_mass() {
        let mut g = Vertices::flat(10.0, 0.3, 2.0, 1.5);
        g.y[5] = 0.4;
        g.unit_weight[4] = 1.2;
        g.accumulated_shear[4] = 0.7;
        let (m0, a0) = (g.mass(), g.area());
        let x = 0.5 * (g.x[4] + g.x[5]) + 0.01;
        let k = g.split_at(x);
        assert_eq!(g.x[k], x);
        assert_eq!(g.accumulated_shear[k - 1], 0.7);
        assert_eq!(g.accumulated_shear[k], 0.7);
        assert!((g.mass() - m0).abs() < 1e-13 * m0);
        assert!((g.area() - a0).abs() < 1e-13 * a0);
        assert_eq!(g.split_at(x), k, "an existing vertex is not split");
    }

    #[test]
    fn a_ground_no_run_makes_is_a_defect() {
        let mut g = Vertices::flat(10.0, 0.5, 2.0, 1.5);
        assert_eq!(g.defect(), None);
        g.x.swap(3, 4);
        assert!(g.defect().unwrap().contains("increase"));
        let mut g = Vertices::flat(10.0, 0.5, 2.0, 1.5);
        g.unit_weight.pop();
        assert!(g.defect().unwrap().contains("lengths"));
        let mut g = Vertices::flat(10.0, 0.5, 2.0, 1.5);
        g.y[2] = f64::NAN;
        assert!(g.defect().unwrap().contains("finite"));
    }

    #[test]
    fn flat_ground_has_no_piece_of_length_zero() {
        // Issue 50's case: 10 d over d/50, d = 5.549742791184853.
        let d = 5.549742791184853;
        let g = Vertices::flat(2.0 * d + 8.0 * d, d / 50.0, d, 1.0);
        assert_eq!(g.pieces(), 500);
        assert_eq!(g.defect(), None);
        let mut draw = test_draws(50);
        for _ in 0..2000 {
            let spacing = 10f64.powf(4.0 * draw() - 2.0);
            let length = (1.0 + (600.0 * draw()).floor()) * spacing;
            let g = Vertices::flat(length, spacing, 1.0, 1.0);
            assert!(
                g.defect().is_none(),
                "{length} over {spacing}: {:?}",
                g.defect()
            );
        }
    }

    #[test]
    fn flat_ground_holds_its_columns() {
        let g = Vertices::flat(10.0, 0.3, 2.0, 1.5);
        assert_eq!(*g.x.last().unwrap(), 10.0);
        assert!((g.mass() - 1.5 * 2.0 * 10.0).abs() < 1e-12);
        assert_eq!(g.piece_at(10.0), g.pieces() - 1);
        assert_eq!(g.piece_at(0.0), 0);
    }
}
