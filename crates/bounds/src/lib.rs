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
//! assert!(b.lower_force() <= 1.5 + 1e-6 && 1.5 <= b.upper_force() + 1e-6);
//! ```

#![warn(missing_docs)]

pub mod conic;
mod edges;
pub mod instant;
pub mod lower;
pub mod mesh;
pub mod problem;
mod quadratic;
pub mod scale;
pub mod strength;
pub mod upper;

pub use conic::SolveError;
pub use instant::{Floor, Instant, InstantError, Options};
pub use lower::LowerBound;
pub use mesh::{Mesh, Side};
pub use problem::{Domain, Face, Ground, InputError, Problem, Soil};
pub use strength::Strength;
pub use upper::UpperBound;

use std::time::Instant as Clock;

/// Both bounds on one mesh, in the problem's units. A bound the solver
/// could not find holds the solver's status: the lower bound is infeasible
/// where no stress field on the mesh carries the ground's own weight with
/// its strength, whatever the face does (a slope steeper than its friction
/// angle, or one just below it on too coarse a mesh).
#[derive(Clone, Debug)]
pub struct Bracket {
    /// The mesh, in the problem's coordinates.
    pub mesh: Mesh,
    /// N, the mesh parameter.
    pub n: usize,
    /// The lower bound (forces and stresses in the problem's units).
    pub lower: Result<LowerBound, SolveError>,
    /// The upper bound (forces in the problem's units).
    pub upper: Result<UpperBound, SolveError>,
    /// Wall-clock time of the lower bound's assembly and solve, seconds.
    pub lower_seconds: f64,
    /// Wall-clock time of the upper bound's assembly and solve, seconds.
    pub upper_seconds: f64,
}

impl Bracket {
    /// The lower bound's force, NaN where it was not found.
    pub fn lower_force(&self) -> f64 {
        self.lower.as_ref().map_or(f64::NAN, |b| b.force)
    }

    /// The upper bound's force, NaN where it was not found.
    pub fn upper_force(&self) -> f64 {
        self.upper.as_ref().map_or(f64::NAN, |b| b.force)
    }
}

/// Largest mesh parameter N accepted (about 19 N² triangles on a rigid
/// floor, 58 N² with soil below the tip).
pub const MAX_MESH: usize = 64;

/// Solves both bounds on the mesh of parameter N (cells along the face near
/// the tip, in [1, [`MAX_MESH`]]).
pub fn bracket(p: &Problem, n: usize) -> Result<Bracket, InputError> {
    p.validate()?;
    if n == 0 || n > MAX_MESH {
        return Err(InputError {
            key: "mesh".into(),
            allowed: format!("in [1, {MAX_MESH}]"),
            value: n as f64,
        });
    }
    let scale = scale::Scale::of(p);
    let scaled = scale.problem(p);
    let mesh = Mesh::new(&scaled, n);
    let (s, h) = (scale.stress, scale.length);
    let clock = Clock::now();
    let lower = lower::solve(&scaled, &mesh).map(|mut b| {
        b.force *= s * h;
        b.stress
            .iter_mut()
            .flatten()
            .flatten()
            .for_each(|x| *x *= s);
        b
    });
    let lower_seconds = clock.elapsed().as_secs_f64();
    let clock = Clock::now();
    let upper = upper::solve(&scaled, &mesh).map(|mut b| {
        b.force *= s * h;
        b.shear_rate.iter_mut().for_each(|r| *r /= h);
        b.dissipation.iter_mut().for_each(|d| *d *= s * h);
        b
    });
    let upper_seconds = clock.elapsed().as_secs_f64();
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
