//! Both bounds on one mesh: validation, scaling, the mesh, the two
//! programs and their wall times.

use crate::conic::SolveError;
use crate::lower::{self, LowerBound};
use crate::mesh::Mesh;
use crate::problem::{InputError, Problem, Steep};
use crate::scale::Scale;
use crate::upper::{self, UpperBound};
use std::time::Instant as Clock;

/// Both bounds on one mesh, in the problem's units. Where a piece of
/// cohesionless surface is steeper than its soil's friction angle
/// ([`Problem::steep`]) the ground cannot stand under its own weight: no
/// lower bound exists and the upper bound is unbounded below, so neither is
/// sought (status [`SolveError::STEEP`], `steep` says where). Otherwise a
/// bound the solver could not find holds the solver's status: the lower
/// bound is infeasible where no stress field on the mesh carries the
/// ground's own weight with its strength, whatever the face does (a slope
/// just below its friction angle on too coarse a mesh).
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
    /// The steepest piece of the surface that cannot stand, if any.
    pub steep: Option<Steep>,
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
    let scale = Scale::of(p);
    let scaled = scale.problem(p);
    let mesh = Mesh::new(&scaled, n);
    let mesh_out = Mesh {
        nodes: mesh.nodes.iter().map(|&q| scale.point(q)).collect(),
        ..mesh.clone()
    };
    let steep = p.steep();
    if steep.is_some() {
        return Ok(Bracket {
            mesh: mesh_out,
            n,
            lower: Err(SolveError::steep()),
            upper: Err(SolveError::steep()),
            lower_seconds: 0.0,
            upper_seconds: 0.0,
            steep,
        });
    }
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
    Ok(Bracket {
        mesh: mesh_out,
        n,
        lower,
        upper,
        lower_seconds,
        upper_seconds,
        steep,
    })
}
