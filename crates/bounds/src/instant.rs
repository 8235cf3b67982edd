//! One instant of a soilcut run as a bound problem, and soilcut's own force
//! there beside the bracket.
//!
//! The ground as it stands before the increment evaluated at blade travel
//! u (docs/model.md §1.2): the surface nodes from the face on, each column
//! with its friction angle φ(ut_i) and unit weight γ_i, the case's cohesion
//! c; the face at the case's rake, with φw and adhesion a; the surcharge q.
//! Below the tip level the soil is fresh (φ at ut = 0, γ0): soilcut's floor
//! (§1.1) is rigid there, which [`Floor::Rigid`] keeps (the bound problem
//! is then exactly soilcut's, mechanisms free in shape above the floor),
//! and [`Floor::Soil`] replaces by deformable soil under the tip and the
//! trench. soilcut's force is that of the increment evaluated on this
//! ground, its horizontal component (`StepRecord::force_h`).

use crate::bracket::{bracket, Bracket};
use crate::problem::InputError;
use crate::problem::{Domain, Face, Ground, Problem, Soil, MIN_RAKE};
use crate::strength::Strength;
use soilcut_model::material::Material;
use soilcut_model::surface::Surface;
use soilcut_model::{Case, CaseError, Simulation, StepError, StepRecord};

/// What lies below the tip level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Floor {
    /// soilcut's rigid floor at the tip level (docs/model.md §1.1).
    #[default]
    Rigid,
    /// Deformable fresh soil to `Domain::default().depth` face heights below
    /// the tip and as far behind it, under the trench.
    Soil,
}

/// How to take an instant's bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// N, the mesh parameter ([`crate::Mesh::new`]).
    pub mesh: usize,
    /// What lies below the tip level.
    pub floor: Floor,
    /// The soil's strength in the bounds.
    pub strength: Strength,
}

/// The bracket at one instant and soilcut's force there.
#[derive(Clone, Debug)]
pub struct Instant {
    /// The increment soilcut evaluated on this ground.
    pub record: StepRecord,
    /// The bound problem (the ground as it stood).
    pub problem: Problem,
    /// Both bounds.
    pub bracket: Bracket,
}

impl Instant {
    /// soilcut's horizontal force over the lower bound's (NaN without one).
    pub fn ratio_lower(&self) -> f64 {
        self.record.force_h / self.bracket.lower_force()
    }

    /// soilcut's horizontal force over the upper bound's (NaN without one).
    pub fn ratio_upper(&self) -> f64 {
        self.record.force_h / self.bracket.upper_force()
    }
}

/// Why an instant's bounds could not be found.
#[derive(Clone, Debug, PartialEq)]
pub enum InstantError {
    /// The case is invalid.
    Case(CaseError),
    /// soilcut found no mechanism on the way.
    Step(StepError),
    /// The ground as it stands is outside the bounds' ranges.
    Bounds(InputError),
    /// The case has a blade of finite width; the bounds are plane strain.
    FiniteWidth(f64),
    /// The case's rake is below the bounds' range (its mesh's columns
    /// parallel to the face would lie too flat).
    Rake(f64),
    /// The case runs on the vertex ground (`run.vertex_spacing`), whose
    /// ground the bounds do not read yet: they take the node grid's.
    VertexGround(f64),
}

impl std::fmt::Display for InstantError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            InstantError::Case(e) => e.fmt(f),
            InstantError::Step(e) => e.fmt(f),
            InstantError::Bounds(e) => e.fmt(f),
            InstantError::FiniteWidth(w) => write!(
                f,
                "blade.width = {w}: the bounds are plane strain; remove blade.width"
            ),
            InstantError::Rake(a) => write!(
                f,
                "blade.rake = {a}: the bounds take a rake in [{MIN_RAKE}, 90] degrees"
            ),
            InstantError::VertexGround(h) => write!(
                f,
                "run.vertex_spacing = {h}: the bounds take the node grid's ground; remove run.vertex_spacing"
            ),
        }
    }
}

impl std::error::Error for InstantError {}

/// Steps `sim` to the first increment evaluated at u ≥ `at`·d (d the case's
/// `blade.depth`; the last increment if `at` lies beyond it), as `soilcut
/// landscape --at` does.
pub fn advance_to(sim: &mut Simulation, at: f64) -> Result<(), StepError> {
    let case = sim.case();
    let before = case
        .increments_to(at * case.blade.depth)
        .min(case.steps() - 1);
    while sim.steps_done() < before {
        sim.step()?;
    }
    Ok(())
}

/// The ground of `sim` as it stands, as a bound problem (on the node grid).
pub fn problem_of(
    sim: &Simulation,
    floor: Floor,
    strength: Strength,
) -> Result<Problem, InstantError> {
    let case = sim.case();
    let surface = sim
        .surface()
        .ok_or(InstantError::VertexGround(case.run.vertex_spacing))?;
    let first = surface.face.node;
    let profile = sim.profile();
    let c = case.soil.cohesion;
    let soil = |i: usize, unit_weight: f64| {
        let own = Soil {
            friction_deg: surface.friction[first + i].to_degrees(),
            cohesion: c,
            unit_weight,
        };
        strength.apply(own, surface.dilation[first + i].to_degrees())
    };
    let ground = Ground {
        x: profile.iter().map(|p| p.x).collect(),
        y: profile.iter().map(|p| p.y).collect(),
        soil: profile
            .iter()
            .enumerate()
            .map(|(i, p)| soil(i, p.unit_weight))
            .collect(),
    };
    let fresh = Material::new(&case.soil);
    let below = strength.apply(
        Soil {
            friction_deg: fresh.friction.at(0.0).to_degrees(),
            cohesion: c,
            unit_weight: case.soil.unit_weight,
        },
        fresh.dilation.at(0.0).to_degrees(),
    );
    let depth = sim.tip_depth();
    let mut p = Problem {
        face: Face {
            tip_x: sim.blade_position(),
            tip_y: -depth,
            rake_deg: case.blade.rake,
            friction_deg: case.blade.wall_friction,
            adhesion: case.blade.adhesion,
        },
        ground,
        below,
        surcharge: case.soil.surcharge,
        domain: Domain::default(),
    };
    p.domain = domain(&p, surface, floor);
    Ok(p)
}

/// The default domain, reaching 2 face heights past the disturbed ground
/// (the pile and the bands behind it) if that is further.
fn domain(p: &Problem, surface: &Surface, floor: Floor) -> Domain {
    let h = p.face_height();
    let last = surface.pristine_from.min(surface.len() - 1);
    let disturbed = (surface.x(last) - p.face.tip_x) / h;
    let base = Domain::default();
    Domain {
        reach: base.reach.max(disturbed + 2.0).min(100.0),
        depth: match floor {
            Floor::Rigid => 0.0,
            Floor::Soil => base.depth,
        },
        ..base
    }
}

/// A case the bounds can take: plane strain, a rake in their range, on
/// the node grid.
fn check(case: &Case) -> Result<(), InstantError> {
    if let Some(w) = case.blade.width {
        return Err(InstantError::FiniteWidth(w));
    }
    if case.blade.rake < MIN_RAKE {
        return Err(InstantError::Rake(case.blade.rake));
    }
    if case.run.vertex_spacing > 0.0 {
        return Err(InstantError::VertexGround(case.run.vertex_spacing));
    }
    Ok(())
}

/// Runs `case` to u/d = `at` and brackets the collapse load of the ground
/// there; soilcut's increment on that ground is evaluated too.
pub fn at(case: &Case, at: f64, options: Options) -> Result<Instant, InstantError> {
    check(case)?;
    let mut sim = Simulation::new(case).map_err(InstantError::Case)?;
    advance_to(&mut sim, at).map_err(InstantError::Step)?;
    instant(&mut sim, options)
}

/// Brackets at u/d = 0, E, 2E, … through the whole run of `case` (each at
/// the first increment at or beyond), E = `every` > 0.
pub fn every(case: &Case, every: f64, options: Options) -> Result<Vec<Instant>, InstantError> {
    check(case)?;
    let mut sim = Simulation::new(case).map_err(InstantError::Case)?;
    let d = case.blade.depth;
    let mut out: Vec<Instant> = Vec::new();
    while !sim.is_done() {
        if sim.blade_position() / d >= out.len() as f64 * every - 1e-9 {
            out.push(instant(&mut sim, options)?);
        } else {
            sim.step().map_err(InstantError::Step)?;
        }
    }
    Ok(out)
}

/// The bracket of `sim`'s ground as it stands and soilcut's next increment
/// on it (which advances `sim` by one increment).
pub fn instant(sim: &mut Simulation, options: Options) -> Result<Instant, InstantError> {
    let problem = problem_of(sim, options.floor, options.strength)?;
    let bracket = bracket(&problem, options.mesh).map_err(InstantError::Bounds)?;
    let record = sim.step().map_err(InstantError::Step)?;
    Ok(Instant {
        record,
        problem,
        bracket,
    })
}
