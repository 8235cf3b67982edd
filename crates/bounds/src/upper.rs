//! The upper bound: a kinematically admissible velocity field
//! (Makrodimopoulos & Martin 2007: six-node triangles, quadratic velocity,
//! the flow rule at the vertices).
//!
//! The velocity (u, v) is quadratic in each triangle, with its own values
//! at the triangle's six nodes, so the strain rate (εx = ∂u/∂x,
//! εy = ∂v/∂y, γxy = ∂u/∂y + ∂v/∂x; extension positive) is linear in each
//! triangle and every edge may carry a velocity discontinuity. Associated Mohr–Coulomb flow in
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
//! with the jump linear along each face edge (its mid-side node's jump is
//! the mean of its ends'), held at the ends. Every edge between two
//! triangles is such an interface with the soil of the earlier triangle
//! (φ, c) (Sloan & Kleeman 1995: discontinuities everywhere, with a linear
//! jump), the truncated boundaries (and the rigid floor) one with the
//! stationary soil beyond, with the adjacent soil's φ and c. Balancing the power of the face with the
//! dissipation and the power of gravity and surcharge,
//!
//! ```text
//! P_h · 1 = ∫ D dA + Σ_edges ∫ c ζ ds + ∫ γ v dA + ∫_ground q n_y v ds     (U3)
//! ```
//!
//! and the least right-hand side over the admissible fields is the upper
//! bound on the horizontal force (exact integrals: ∫ v dA over a six-node
//! triangle is A/3 times the sum of the mid-side values; ∫ v ds over a
//! quadratic edge is L/6 (v_a + 4 v_m + v_b)).

use crate::conic::{Affine, Program, SolveError};
use crate::edges::{Edges, Half};
use crate::mesh::{twice_area, Mesh, Side};
use crate::problem::Problem;
use crate::quadratic::gradients_at_vertex;

/// The upper bound and its mechanism.
#[derive(Clone, Debug)]
pub struct UpperBound {
    /// P_h, horizontal force of the face on the soil, per unit width.
    pub force: f64,
    /// (u, v) at each triangle's three vertices, per unit blade velocity.
    pub velocity: Vec<[[f64; 2]; 3]>,
    /// Where the soil fails, per triangle: its mean plastic shear strain
    /// rate ρ (U1), plus the slip ζ of its edges' discontinuities in the
    /// soil spread over it (half an edge's ∫ ζ ds to each side, all of a
    /// truncation's, over the area; not the slip on the face): per unit
    /// blade velocity per unit length.
    pub shear_rate: Vec<f64>,
    /// Dissipation in each triangle and its share of its edges' in the
    /// soil, power per unit width.
    pub dissipation: Vec<f64>,
    /// Interior-point iterations.
    pub iterations: u32,
    /// Variables and constraint rows of the program.
    pub size: (usize, usize),
}

/// The velocity unknowns: the index of u (v next) at each triangle's six
/// nodes (vertices 0-2, then the mid-sides of sides (0,1), (1,2), (2,0)).
struct Velocity {
    of: Vec<[usize; 6]>,
}

impl Velocity {
    /// The index of u at the node of triangle e's side (e, a, b) that is
    /// its end a, its end b or its middle.
    fn side(&self, (e, a, b): Half) -> [usize; 3] {
        // Side s joins vertices s and s + 1.
        let s = if (a + 1) % 3 == b { a } else { b };
        [self.of[e][a], self.of[e][3 + s], self.of[e][b]]
    }
}

/// (U1) at the vertices of triangle e; its dissipation and gravity's power
/// go into the cost, its ρ variables are returned.
fn element(lp: &mut Program, p: &Problem, mesh: &Mesh, vel: &Velocity, e: usize) -> usize {
    let pts = mesh.triangles[e].map(|i| mesh.nodes[i]);
    let c = mesh.centroid(e);
    let soil = p.soil_at(c[0], c[1]);
    let (sin, cos) = soil.friction_deg.to_radians().sin_cos();
    let area = 0.5 * twice_area(pts[0], pts[1], pts[2]);
    let rho = lp.variables(3);
    let six = vel.of[e];
    for k in 0..3 {
        let (dx, dy, a2) = gradients_at_vertex(pts, k);
        let (mut ex, mut ey, mut g) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..6 {
            ex.push((six[i], dx[i] / a2));
            ey.push((six[i] + 1, dy[i] / a2));
            g.push((six[i], dy[i] / a2));
            g.push((six[i] + 1, dx[i] / a2));
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
        lp.cost(m + 1, soil.unit_weight * area / 3.0);
    }
    rho
}

/// What lies across an interface from the soil: a rigid body moving at a
/// given velocity (the face, the stationary soil beyond a truncation) or
/// the soil of another triangle.
#[derive(Clone, Copy)]
enum Across {
    Rigid([f64; 2]),
    Soil([usize; 3]),
}

/// An interface: what lies across, its friction and its cohesion (or
/// adhesion).
struct Interface {
    across: Across,
    tan_phi: f64,
    cohesion: f64,
}

/// A slip ζ at one end of an edge, for the picture: its variable, a
/// triangle beside the edge, the length of edge it stands for there and
/// the interface's cohesion.
struct Slip {
    zeta: usize,
    element: usize,
    length: f64,
    cohesion: f64,
}

/// (U2) on the edge whose nodes (end, middle, end) are `inside`, with
/// outward normal n and length `len`: the jump linear along it, the
/// interface held at both ends, its dissipation into the cost.
fn interface_edge(
    lp: &mut Program,
    inside: [usize; 3],
    n: [f64; 2],
    len: f64,
    f: &Interface,
) -> [usize; 2] {
    // Δ_m = (Δ_a + Δ_b)/2, Δ = w − w_across (a rigid body's jump is linear).
    for k in 0..2 {
        let mut t = vec![
            (inside[1] + k, 1.0),
            (inside[0] + k, -0.5),
            (inside[2] + k, -0.5),
        ];
        if let Across::Soil(out) = f.across {
            t.extend([(out[1] + k, -1.0), (out[0] + k, 0.5), (out[2] + k, 0.5)]);
        }
        lp.zero(&Affine::of(t));
    }
    [0, 2].map(|end| {
        let across = match f.across {
            Across::Rigid(v) => Across::Rigid(v),
            Across::Soil(out) => Across::Soil([out[end]; 3]),
        };
        let zeta = interface_node(lp, inside[end], across, n, f.tan_phi);
        lp.cost(zeta, 0.5 * len * f.cohesion);
        zeta
    })
}

/// (U2) at one node, the soil's u at `w` (v next), with outward normal n
/// (m = −n, s = (−n_y, n_x)): the jump Δ = w − w_across.
fn interface_node(lp: &mut Program, w: usize, across: Across, n: [f64; 2], tan_phi: f64) -> usize {
    let zeta = lp.variables(1);
    let mut normal = vec![(zeta, -tan_phi), (w, -n[0]), (w + 1, -n[1])];
    let mut tangent = vec![(w, -n[1]), (w + 1, n[0])];
    let (mut vn, mut vs) = (0.0, 0.0);
    match across {
        Across::Rigid(v) => {
            vn = v[0] * n[0] + v[1] * n[1];
            vs = -v[0] * n[1] + v[1] * n[0];
        }
        Across::Soil(out) => {
            normal.extend([(out[0], n[0]), (out[0] + 1, n[1])]);
            tangent.extend([(out[0], n[1]), (out[0] + 1, -n[0])]);
        }
    }
    // Δ·m − ζ tan φ = −w·n + w_across·n − ζ tan φ = 0.
    lp.zero(&Affine::of(normal).plus(vn));
    // ζ ± Δ·s ≥ 0, Δ·s = −u n_y + v n_x − w_across·s.
    for sign in [1.0, -1.0] {
        let mut t: Vec<(usize, f64)> = tangent.iter().map(|&(j, a)| (j, sign * a)).collect();
        t.push((zeta, 1.0));
        lp.nonnegative(&Affine::of(t).plus(-sign * vs));
    }
    zeta
}

/// The soil's interface properties at triangle e.
fn soil_interface(p: &Problem, mesh: &Mesh, e: usize, across: Across) -> Interface {
    let c = mesh.centroid(e);
    let soil = p.soil_at(c[0], c[1]);
    Interface {
        across,
        tan_phi: soil.friction_deg.to_radians().tan(),
        cohesion: soil.cohesion,
    }
}

/// The surcharge's share of (U3) on the ground, and (U2) on the face, on
/// the truncations and between triangles; the slips, for the picture.
fn edges(lp: &mut Program, p: &Problem, mesh: &Mesh, vel: &Velocity) -> Vec<Slip> {
    let edges = Edges::new(mesh);
    let mut slips = Vec::new();
    for &(a, b, side) in &mesh.boundary {
        let half = edges.boundary(mesh, a, b);
        let (n, len) = mesh.outward(a, b);
        let nodes = vel.side(half);
        let interface = match side {
            Side::Surface => {
                for (i, w) in nodes.iter().zip([1.0, 4.0, 1.0]) {
                    lp.cost(i + 1, p.surcharge * n[1] * len * w / 6.0);
                }
                continue;
            }
            Side::Trench => continue,
            Side::Face => Interface {
                across: Across::Rigid([1.0, 0.0]),
                tan_phi: p.face.friction_deg.to_radians().tan(),
                cohesion: p.face.adhesion,
            },
            Side::Far => soil_interface(p, mesh, half.0, Across::Rigid([0.0, 0.0])),
        };
        for zeta in interface_edge(lp, nodes, n, len, &interface) {
            // The soil's slip on the face is not the soil failing.
            if side == Side::Far {
                slips.push(Slip {
                    zeta,
                    element: half.0,
                    length: len,
                    cohesion: interface.cohesion,
                });
            }
        }
    }
    for (first, second) in edges.interior(mesh) {
        let t = mesh.triangles[first.0];
        let (n, len) = mesh.outward(t[first.1], t[first.2]);
        // The later triangle runs the edge the other way.
        let [a, m, b] = vel.side(second);
        let interface = soil_interface(p, mesh, first.0, Across::Soil([b, m, a]));
        for zeta in interface_edge(lp, vel.side(first), n, len, &interface) {
            for element in [first.0, second.0] {
                slips.push(Slip {
                    zeta,
                    element,
                    length: 0.5 * len,
                    cohesion: interface.cohesion,
                });
            }
        }
    }
    slips
}

/// Solves the upper-bound program on a mesh of a validated problem.
pub fn solve(p: &Problem, mesh: &Mesh) -> Result<UpperBound, SolveError> {
    let mut lp = Program::default();
    let ne = mesh.triangles.len();
    let vel = Velocity {
        of: (0..ne).map(|_| [0; 6].map(|_| lp.variables(2))).collect(),
    };
    let rho: Vec<usize> = (0..ne)
        .map(|e| element(&mut lp, p, mesh, &vel, e))
        .collect();
    let slips = edges(&mut lp, p, mesh, &vel);
    let sol = lp.solve()?;
    let velocity = vel
        .of
        .iter()
        .map(|six| [0, 1, 2].map(|k| [sol.x[six[k]], sol.x[six[k] + 1]]))
        .collect();
    let area = |e: usize| {
        let t = mesh.triangles[e].map(|i| mesh.nodes[i]);
        0.5 * twice_area(t[0], t[1], t[2])
    };
    let mut shear_rate: Vec<f64> = rho
        .iter()
        .map(|&r| (sol.x[r] + sol.x[r + 1] + sol.x[r + 2]) / 3.0)
        .collect();
    let mut dissipation: Vec<f64> = (0..ne)
        .map(|e| {
            let c = mesh.centroid(e);
            let soil = p.soil_at(c[0], c[1]);
            soil.cohesion * soil.friction_deg.to_radians().cos() * area(e) * shear_rate[e]
        })
        .collect();
    for s in &slips {
        // An end's share ½ L ζ of the edge's ∫ ζ ds.
        let slip = 0.5 * s.length * sol.x[s.zeta];
        shear_rate[s.element] += slip / area(s.element);
        dissipation[s.element] += s.cohesion * slip;
    }
    Ok(UpperBound {
        force: sol.objective,
        velocity,
        shear_rate,
        dissipation,
        iterations: sol.iterations,
        size: lp.size(),
    })
}
