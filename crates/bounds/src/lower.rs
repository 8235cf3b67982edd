//! The lower bound: a statically admissible stress field (Sloan 1988;
//! Lyamin & Sloan 2002; Makrodimopoulos & Martin 2006, the second-order-cone
//! form).
//!
//! Stresses are linear in each triangle, with their own values at its three
//! nodes (σx, σy, τxy; tension positive), so every edge may carry a
//! statically admissible discontinuity. The program maximises the
//! horizontal force P_h of the face on the soil subject to
//!
//! ```text
//! ∂σx/∂x + ∂τxy/∂y = 0,  ∂τxy/∂x + ∂σy/∂y = γ        in each triangle    (L1)
//! (σ⁽¹⁾ − σ⁽²⁾)·n = 0                               at each node of each shared edge (L2)
//! σ·n = (0, −q n_y) on the ground, 0 on the trench floor                (L3)
//! |τ| ≤ −σn tan φw + a on the face                                       (L4)
//! √((σx − σy)² + (2τxy)²) ≤ 2c cos φ − (σx + σy) sin φ   at every node (L5)
//! P_h = ∫_face (σ·n)_x ds                                               (L6)
//! ```
//!
//! All are linear in the nodal stresses or (L5) a Lorentz cone of them; the
//! stress being linear along each edge and in each triangle, holding them
//! at the nodes holds them everywhere (the yield set is convex), so any
//! feasible field is statically admissible and P_h ≤ the collapse load. The
//! truncated boundaries carry no condition: the field is taken to continue
//! beyond them, which the domain checks (`crates/bounds/tests/domain.rs`) test by
//! enlarging the mesh.

use crate::conic::{Affine, Program, SolveError};
use crate::edges::Edges;
use crate::mesh::{twice_area, Mesh, Side};
use crate::problem::Problem;

/// The lower bound and its stress field.
#[derive(Clone, Debug)]
pub struct LowerBound {
    /// P_h, horizontal force of the face on the soil, per unit width.
    pub force: f64,
    /// (σx, σy, τxy) at each triangle's three nodes, tension positive.
    pub stress: Vec<[[f64; 3]; 3]>,
    /// Interior-point iterations.
    pub iterations: u32,
    /// Variables and constraint rows of the program.
    pub size: (usize, usize),
}

/// Variable of stress component k (0 σx, 1 σy, 2 τxy) at node l of triangle e.
fn var(e: usize, l: usize, k: usize) -> usize {
    9 * e + 3 * l + k
}

/// The traction σ·n at node l of triangle e: (t_x, t_y).
fn traction(e: usize, l: usize, n: [f64; 2]) -> (Affine, Affine) {
    let (sx, sy, t) = (var(e, l, 0), var(e, l, 1), var(e, l, 2));
    (
        Affine::of(vec![(sx, n[0]), (t, n[1])]),
        Affine::of(vec![(t, n[0]), (sy, n[1])]),
    )
}

/// (L1): b_i = y_j − y_k, c_i = x_k − x_j over the cyclic (i, j, k).
fn equilibrium(lp: &mut Program, mesh: &Mesh, e: usize, gamma: f64) {
    let p = mesh.triangles[e].map(|i| mesh.nodes[i]);
    let (mut fx, mut fy) = (Vec::new(), Vec::new());
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let (b, c) = (p[j][1] - p[k][1], p[k][0] - p[j][0]);
        fx.extend([(var(e, i, 0), b), (var(e, i, 2), c)]);
        fy.extend([(var(e, i, 2), b), (var(e, i, 1), c)]);
    }
    lp.zero(&Affine::of(fx));
    lp.zero(&Affine::of(fy).plus(-twice_area(p[0], p[1], p[2]) * gamma));
}

/// (L5) at node l of triangle e.
fn mohr_coulomb(lp: &mut Program, e: usize, l: usize, phi: f64, c: f64) {
    let (sx, sy, t) = (var(e, l, 0), var(e, l, 1), var(e, l, 2));
    let (s, k) = phi.sin_cos();
    lp.cone(
        &Affine::of(vec![(sx, -s), (sy, -s)]).plus(2.0 * c * k),
        &Affine::of(vec![(sx, 1.0), (sy, -1.0)]),
        &Affine::of(vec![(t, 2.0)]),
    );
}

/// (L2) across every shared edge, at both its nodes.
fn continuity(lp: &mut Program, mesh: &Mesh, edges: &Edges) {
    for ((e1, a1, b1), (e2, a2, b2)) in edges.interior(mesh) {
        let (n, _) = mesh.outward(mesh.triangles[e1][a1], mesh.triangles[e1][b1]);
        // The later triangle runs the edge the other way: its b2 is e1's a1.
        for (l1, l2) in [(a1, b2), (b1, a2)] {
            let (x1, y1) = traction(e1, l1, n);
            let (x2, y2) = traction(e2, l2, n);
            lp.zero(&difference(x1, x2));
            lp.zero(&difference(y1, y2));
        }
    }
}

fn difference(mut a: Affine, b: Affine) -> Affine {
    a.terms.extend(b.terms.iter().map(|&(j, v)| (j, -v)));
    a.constant -= b.constant;
    a
}

/// (L3), (L4) and the objective −(L6) on the boundary edges.
fn boundary(lp: &mut Program, p: &Problem, mesh: &Mesh, edges: &Edges) {
    let (tan_w, adhesion) = (p.face.friction_deg.to_radians().tan(), p.face.adhesion);
    for &(a, b, side) in &mesh.boundary {
        let (e, la, lb) = edges.boundary(mesh, a, b);
        let (n, len) = mesh.outward(a, b);
        for l in [la, lb] {
            let (tx, ty) = traction(e, l, n);
            match side {
                Side::Surface => {
                    lp.zero(&tx);
                    lp.zero(&ty.plus(p.surcharge * n[1]));
                }
                Side::Trench => {
                    lp.zero(&tx);
                    lp.zero(&ty);
                }
                Side::Face => face_node(lp, e, l, n, len, tan_w, adhesion),
                Side::Far => {}
            }
        }
    }
}

/// (L4) at one node of a face edge, and its share −½ L t_x of −P_h.
fn face_node(lp: &mut Program, e: usize, l: usize, n: [f64; 2], len: f64, tan_w: f64, a: f64) {
    let (tx, ty) = traction(e, l, n);
    // σn = t·n, τ = t·s with s = (−n_y, n_x); row: a − σn tan φw ∓ τ ≥ 0.
    for sign in [1.0, -1.0] {
        let mut row = Affine::default().plus(a);
        for (j, v) in &tx.terms {
            row.terms.push((*j, -tan_w * n[0] * v + sign * n[1] * v));
        }
        for (j, v) in &ty.terms {
            row.terms.push((*j, -tan_w * n[1] * v - sign * n[0] * v));
        }
        lp.nonnegative(&row);
    }
    for (j, v) in tx.terms {
        lp.cost(j, -0.5 * len * v);
    }
}

/// Solves the lower-bound program on a mesh of a validated problem.
pub fn solve(p: &Problem, mesh: &Mesh) -> Result<LowerBound, SolveError> {
    let mut lp = Program::default();
    let ne = mesh.triangles.len();
    lp.variables(9 * ne);
    let edges = Edges::new(mesh);
    for e in 0..ne {
        let c = mesh.centroid(e);
        let soil = p.soil_at(c[0], c[1]);
        equilibrium(&mut lp, mesh, e, soil.unit_weight);
        for l in 0..3 {
            mohr_coulomb(&mut lp, e, l, soil.friction_deg.to_radians(), soil.cohesion);
        }
    }
    continuity(&mut lp, mesh, &edges);
    boundary(&mut lp, p, mesh, &edges);
    let sol = lp.solve()?;
    let stress = (0..ne)
        .map(|e| [0, 1, 2].map(|l| [0, 1, 2].map(|k| sol.x[var(e, l, k)])))
        .collect();
    Ok(LowerBound {
        force: -sol.objective,
        stress,
        iterations: sol.iterations,
        size: lp.size(),
    })
}

/// The fraction of the strength a stress mobilises,
/// √((σx − σy)² + (2τxy)²) / (2c cos φ − (σx + σy) sin φ): 1 at yield (L5);
/// φ in degrees.
pub fn mobilised(stress: [f64; 3], friction_deg: f64, cohesion: f64) -> f64 {
    let [sx, sy, t] = stress;
    let (s, k) = friction_deg.to_radians().sin_cos();
    let radius = (sx - sy).hypot(2.0 * t);
    let strength = 2.0 * cohesion * k - (sx + sy) * s;
    if strength > 0.0 {
        (radius / strength).min(1.0)
    } else if radius > 0.0 {
        1.0
    } else {
        0.0
    }
}

impl LowerBound {
    /// Per triangle of `mesh` (in `p`'s coordinates), the largest fraction
    /// of the strength its nodes mobilise.
    pub fn mobilised(&self, p: &Problem, mesh: &Mesh) -> Vec<f64> {
        (0..mesh.triangles.len())
            .map(|e| {
                let c = mesh.centroid(e);
                let soil = p.soil_at(c[0], c[1]);
                self.stress[e]
                    .iter()
                    .map(|&s| mobilised(s, soil.friction_deg, soil.cohesion))
                    .fold(0.0, f64::max)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rankine_passive_state_is_at_yield_and_hydrostatic_is_not() {
        // φ = 30°: σx = Kp σy with Kp = 3 is at yield; σx = σy mobilises none.
        assert!((mobilised([-3.0, -1.0, 0.0], 30.0, 0.0) - 1.0).abs() < 1e-12);
        assert_eq!(mobilised([-1.0, -1.0, 0.0], 30.0, 0.0), 0.0);
        // σx = 2 σy: R = 1 of 1.5.
        assert!((mobilised([-2.0, -1.0, 0.0], 30.0, 0.0) - 2.0 / 3.0).abs() < 1e-12);
    }
}
