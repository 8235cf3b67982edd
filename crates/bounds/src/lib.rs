//! soilcut-bounds: rigorous lower and upper bounds on the force a rigid
//! blade needs to cut the ground in front of it, by finite-element limit
//! analysis (FELA) in plane strain, as second-order-cone programs solved by
//! an interior-point method (`clarabel`). A pure library: no files, no
//! terminal.
//!
//! The [`Problem`] is the ground as it stands (surface, per-column friction,
//! cohesion and unit weight), a rigid face with friction φw and adhesion a,
//! a surcharge q, and the soil below the tip. Both bounds find the largest
//! horizontal force P_h the face can exert on the soil:
//!
//! - [`lower`]: a statically admissible stress field (equilibrium, stress
//!   discontinuities at every edge, Mohr–Coulomb yield as a cone) proves
//!   that the soil carries P_h^L without collapse: P_h^L ≤ P_h.
//! - [`upper`]: a kinematically admissible velocity field (the face at unit
//!   horizontal velocity) whose dissipation, net of the power of gravity and
//!   surcharge, is P_h^U ≥ P_h.
//!
//! The theorems hold for a perfectly plastic soil with associated flow
//! (dilation ψ = φ) and an associated face interface: for a soil with
//! ψ < φ the bracket bounds the associated soil of the same strength.
//!
//! ```
//! use soilcut_bounds::{Problem, Soil};
//! let sand = Soil { friction_deg: 30.0, cohesion: 0.0, unit_weight: 1.0 };
//! let p = Problem::flat(1.0, sand, 0.0, 0.0, 0.0);
//! let b = soilcut_bounds::bracket(&p, 2).unwrap();
//! // Rankine: ½ Kp γ d² = 1.5 (Kp = 3).
//! assert!(b.lower.force <= 1.5 + 1e-6 && 1.5 <= b.upper.force + 1e-6);
//! ```

#![warn(missing_docs)]

pub mod conic;
mod edges;
pub mod lower;
pub mod mesh;
pub mod problem;
mod quadratic;
pub mod scale;
pub mod upper;

pub use lower::LowerBound;
pub use mesh::{Mesh, Side};
pub use problem::{Domain, Face, Ground, InputError, Problem, Soil};
pub use upper::UpperBound;

use std::time::Instant;

/// Both bounds on one mesh, in the problem's units.
#[derive(Clone, Debug)]
pub struct Bracket {
    /// The mesh, in the problem's coordinates.
    pub mesh: Mesh,
    /// N, the mesh parameter.
    pub n: usize,
    /// The lower bound (forces and stresses in the problem's units).
    pub lower: LowerBound,
    /// The upper bound (forces in the problem's units).
    pub upper: UpperBound,
    /// Wall-clock time of the lower bound's assembly and solve, seconds.
    pub lower_seconds: f64,
    /// Wall-clock time of the upper bound's assembly and solve, seconds.
    pub upper_seconds: f64,
}

/// Why a bracket could not be found.
#[derive(Clone, Debug, PartialEq)]
pub enum BoundsError {
    /// An input out of range.
    Input(InputError),
    /// The conic solver failed (which bound, and its status).
    Solver(&'static str, conic::SolveError),
}

impl std::fmt::Display for BoundsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BoundsError::Input(e) => e.fmt(f),
            BoundsError::Solver(which, e) => write!(f, "{which} bound: {e}"),
        }
    }
}

impl std::error::Error for BoundsError {}

/// Largest mesh parameter N accepted (about 54 N² triangles).
pub const MAX_MESH: usize = 64;

/// Solves both bounds on the mesh of parameter N (cells along the face near
/// the tip, in [1, [`MAX_MESH`]]).
pub fn bracket(p: &Problem, n: usize) -> Result<Bracket, BoundsError> {
    p.validate().map_err(BoundsError::Input)?;
    if n == 0 || n > MAX_MESH {
        return Err(BoundsError::Input(InputError {
            key: "mesh".into(),
            allowed: format!("in [1, {MAX_MESH}]"),
            value: n as f64,
        }));
    }
    let scale = scale::Scale::of(p);
    let scaled = scale.problem(p);
    let mesh = Mesh::new(&scaled, n);
    let clock = Instant::now();
    let mut lower = lower::solve(&scaled, &mesh).map_err(|e| BoundsError::Solver("lower", e))?;
    let lower_seconds = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    let mut upper = upper::solve(&scaled, &mesh).map_err(|e| BoundsError::Solver("upper", e))?;
    let upper_seconds = clock.elapsed().as_secs_f64();
    let (s, h) = (scale.stress, scale.length);
    lower.force *= s * h;
    for node in lower.stress.iter_mut().flatten().flatten() {
        *node *= s;
    }
    upper.force *= s * h;
    upper.shear_rate.iter_mut().for_each(|r| *r /= h);
    upper.dissipation.iter_mut().for_each(|d| *d *= s * h);
    let mesh = Mesh {
        nodes: mesh.nodes.iter().map(|&q| scale.point(q)).collect(),
        ..mesh
    };
    Ok(Bracket {
        mesh,
        n,
        lower,
        upper,
        lower_seconds,
        upper_seconds,
    })
}
