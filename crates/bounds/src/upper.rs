//! The upper bound: a kinematically admissible velocity field
//! (Makrodimopoulos & Martin 2007: six-node triangles, quadratic velocity,
//! the flow rule at the vertices).
//!
//! The velocity (u, v) is quadratic and continuous over the soil, so the
//! strain rate (εx = ∂u/∂x, εy = ∂v/∂y, γxy = ∂u/∂y + ∂v/∂x; extension
//! positive) is linear in each triangle. Associated Mohr–Coulomb flow in
//! plane strain admits the strain rates with
//!
//! ```text
//! εx + εy = ρ sin φ,  √((εx − εy)² + γxy²) ≤ ρ,  dissipation D = c cos φ ρ     (U1)
//! ```
//!
//! held at the three vertices with ρ linear: then (U1) holds everywhere
//! (convexity) and ∫ D dA = c cos φ (A/3) Σ ρ_k bounds the dissipation from
//! above. The face is a rigid plate moving at V = (1, 0); the soil slides
//! on it through an associated Mohr–Coulomb interface (φw, a): with the
//! jump Δ = w − V of the soil's velocity w, m the face's normal into the
//! soil and s its tangent,
//!
//! ```text
//! Δ·m = ζ tan φw,  |Δ·s| ≤ ζ,  dissipation a ζ per unit length             (U2)
//! ```
//!
//! with the jump linear along each face edge (its mid-side node's velocity
//! is the mean of its ends'), held at the ends. The truncated boundaries
//! (and the rigid floor) are interfaces of the same kind with the
//! stationary soil beyond, with the adjacent soil's φ and c. Balancing the power of the face with the
//! dissipation and the power of gravity and surcharge,
//!
//! ```text
//! P_h · 1 = ∫ D dA + ∫_face a ζ ds + ∫ γ v dA + ∫_ground q n_y v ds          (U3)
//! ```
//!
//! and the least right-hand side over the admissible fields is the upper
//! bound on the horizontal force (exact integrals: ∫ v dA over a six-node
//! triangle is A/3 times the sum of the mid-side values; ∫ v ds over a
//! quadratic edge is L/6 (v_a + 4 v_m + v_b)).

use crate::conic::{Affine, Program, SolveError};
use crate::edges::Edges;
use crate::mesh::{twice_area, Mesh, Side};
use crate::problem::Problem;
use crate::quadratic::{gradients_at_vertex, Quadratic};

/// The upper bound and its mechanism.
#[derive(Clone, Debug)]
pub struct UpperBound {
    /// P_h, horizontal force of the face on the soil, per unit width.
    pub force: f64,
    /// (u, v) at each mesh vertex, per unit blade velocity.
    pub velocity: Vec<[f64; 2]>,
    /// ρ averaged over each triangle: the plastic shear strain rate
    /// √((εx − εy)² + γxy²) where the soil fails (per unit blade velocity
    /// per unit length).
    pub shear_rate: Vec<f64>,
    /// Dissipation in each triangle, c cos φ (A/3) Σ ρ_k (power per unit width).
    pub dissipation: Vec<f64>,
    /// Interior-point iterations.
    pub iterations: u32,
    /// Variables and constraint rows of the program.
    pub size: (usize, usize),
}

/// The velocity unknowns: the index of u at each node (v next).
struct Velocity {
    of: Vec<usize>,
}

impl Velocity {
    /// Adds coefficient a on component k (0 u, 1 v) of node i.
    fn term(&self, terms: &mut Vec<(usize, f64)>, i: usize, k: usize, a: f64) {
        terms.push((self.of[i] + k, a));
    }
}

fn unknowns(lp: &mut Program, quad: &Quadratic) -> Velocity {
    Velocity {
        of: (0..quad.count).map(|_| lp.variables(2)).collect(),
    }
}

/// (U1) at the vertices of triangle e, its dissipation and gravity's power.
fn element(
    lp: &mut Program,
    p: &Problem,
    mesh: &Mesh,
    quad: &Quadratic,
    vel: &Velocity,
    e: usize,
) -> usize {
    let pts = mesh.triangles[e].map(|i| mesh.nodes[i]);
    let c = mesh.centroid(e);
    let soil = p.soil_at(c[0], c[1]);
    let (sin, cos) = soil.friction_deg.to_radians().sin_cos();
    let area = 0.5 * twice_area(pts[0], pts[1], pts[2]);
    let rho = lp.variables(3);
    let six = quad.nodes[e];
    for k in 0..3 {
        let (dx, dy, a2) = gradients_at_vertex(pts, k);
        let (mut ex, mut ey, mut g) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..6 {
            vel.term(&mut ex, six[i], 0, dx[i] / a2);
            vel.term(&mut ey, six[i], 1, dy[i] / a2);
            vel.term(&mut g, six[i], 0, dy[i] / a2);
            vel.term(&mut g, six[i], 1, dx[i] / a2);
        }
        let mut volumetric: Vec<(usize, f64)> = ex.iter().chain(&ey).copied().collect();
        volumetric.push((rho + k, -sin));
        lp.zero(&Affine::of(volumetric));
        let deviator = ex
            .into_iter()
            .chain(ey.into_iter().map(|(j, a)| (j, -a)))
            .collect();
        lp.cone(
            &Affine::of(vec![(rho + k, 1.0)]),
            &Affine::of(deviator),
            &Affine::of(g),
        );
        lp.cost(rho + k, soil.cohesion * cos * area / 3.0);
    }
    for &m in &six[3..] {
        lp.cost(vel.of[m] + 1, soil.unit_weight * area / 3.0);
    }
    rho
}

/// An interface between the soil and a rigid body moving at `rigid`: the
/// face (φw, a) or the stationary soil beyond a truncation (φ, c).
struct Interface {
    rigid: [f64; 2],
    tan_phi: f64,
    cohesion: f64,
}

/// The surcharge's share of (U3) on the ground, and (U2) on the face and
/// on the truncations.
fn boundary(
    lp: &mut Program,
    p: &Problem,
    mesh: &Mesh,
    edges: &Edges,
    quad: &Quadratic,
    vel: &Velocity,
) {
    for &(a, b, side) in &mesh.boundary {
        let (n, len) = mesh.outward(a, b);
        let m = quad.middle(a, b);
        let interface = match side {
            Side::Surface => {
                for (i, w) in [(a, 1.0), (m, 4.0), (b, 1.0)] {
                    lp.cost(vel.of[i] + 1, p.surcharge * n[1] * len * w / 6.0);
                }
                continue;
            }
            Side::Trench => continue,
            Side::Face => Interface {
                rigid: [1.0, 0.0],
                tan_phi: p.face.friction_deg.to_radians().tan(),
                cohesion: p.face.adhesion,
            },
            Side::Far => {
                let c = mesh.centroid(edges.boundary(mesh, a, b).0);
                let soil = p.soil_at(c[0], c[1]);
                Interface {
                    rigid: [0.0, 0.0],
                    tan_phi: soil.friction_deg.to_radians().tan(),
                    cohesion: soil.cohesion,
                }
            }
        };
        // The jump is linear along the edge: w_m = (w_a + w_b)/2.
        for k in 0..2 {
            let t = vec![
                (vel.of[m] + k, 1.0),
                (vel.of[a] + k, -0.5),
                (vel.of[b] + k, -0.5),
            ];
            lp.zero(&Affine::of(t));
        }
        for i in [a, b] {
            let zeta = interface_node(lp, vel, i, n, &interface);
            lp.cost(zeta, 0.5 * len * interface.cohesion);
        }
    }
}

/// (U2) at node i of an interface with outward normal n (m = −n,
/// s = (−n_y, n_x)): the jump Δ = w − V.
fn interface_node(lp: &mut Program, vel: &Velocity, i: usize, n: [f64; 2], f: &Interface) -> usize {
    let zeta = lp.variables(1);
    let (u, v) = (vel.of[i], vel.of[i] + 1);
    let vn = f.rigid[0] * n[0] + f.rigid[1] * n[1];
    let vs = -f.rigid[0] * n[1] + f.rigid[1] * n[0];
    // Δ·m − ζ tan φ = −w·n + V·n − ζ tan φ = 0.
    lp.zero(&Affine::of(vec![(zeta, -f.tan_phi), (u, -n[0]), (v, -n[1])]).plus(vn));
    // ζ ± Δ·s ≥ 0, Δ·s = −u n_y + v n_x − V·s.
    for sign in [1.0, -1.0] {
        let t = vec![(zeta, 1.0), (u, -sign * n[1]), (v, sign * n[0])];
        lp.nonnegative(&Affine::of(t).plus(-sign * vs));
    }
    zeta
}

/// Solves the upper-bound program on a mesh of a validated problem.
pub fn solve(p: &Problem, mesh: &Mesh) -> Result<UpperBound, SolveError> {
    let mut lp = Program::default();
    let quad = Quadratic::new(mesh);
    let vel = unknowns(&mut lp, &quad);
    let edges = Edges::new(mesh);
    let rho: Vec<usize> = (0..mesh.triangles.len())
        .map(|e| element(&mut lp, p, mesh, &quad, &vel, e))
        .collect();
    boundary(&mut lp, p, mesh, &edges, &quad, &vel);
    let sol = lp.solve()?;
    let velocity = (0..mesh.nodes.len())
        .map(|i| [sol.x[vel.of[i]], sol.x[vel.of[i] + 1]])
        .collect();
    let shear_rate: Vec<f64> = rho
        .iter()
        .map(|&r| (sol.x[r] + sol.x[r + 1] + sol.x[r + 2]) / 3.0)
        .collect();
    let dissipation = (0..mesh.triangles.len())
        .map(|e| {
            let c = mesh.centroid(e);
            let soil = p.soil_at(c[0], c[1]);
            let p3 = mesh.triangles[e].map(|i| mesh.nodes[i]);
            let area = 0.5 * twice_area(p3[0], p3[1], p3[2]);
            soil.cohesion * soil.friction_deg.to_radians().cos() * area * shear_rate[e]
        })
        .collect();
    Ok(UpperBound {
        force: sol.objective,
        velocity,
        shear_rate,
        dissipation,
        iterations: sol.iterations,
        size: lp.size(),
    })
}
