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
use crate::strength::{Field, Strength};
use soilcut_model::material::Material;
use soilcut_model::{Case, CaseError, ProfilePoint, Simulation, StepError, StepRecord, Until};

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
    /// Which friction angle each column is given.
    pub field: Field,
}

/// The mesh parameter N the bounds take unless told (`soilcut bounds
/// --mesh`, Python's `mesh`).
pub const DEFAULT_MESH: usize = 8;

/// The options every front end starts from: mesh N = [`DEFAULT_MESH`],
/// soilcut's rigid floor, the associated strength, each column its own φ.
impl Default for Options {
    fn default() -> Self {
        Options {
            mesh: DEFAULT_MESH,
            floor: Floor::default(),
            strength: Strength::default(),
            field: Field::default(),
        }
    }
}

impl Floor {
    /// The option's word (`--floor`).
    pub fn name(self) -> &'static str {
        match self {
            Floor::Rigid => "rigid",
            Floor::Soil => "soil",
        }
    }
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
        }
    }
}

impl std::error::Error for InstantError {}

/// The ground of `sim` as it stands, as a bound problem: each column's
/// strength by `strength` (from its φ(ut), ψ(ut)), then `field`.
pub fn problem_of(sim: &Simulation, floor: Floor, strength: Strength, field: Field) -> Problem {
    let case = sim.case();
    let profile = sim.profile();
    let c = case.soil.cohesion;
    // φ(ut) and ψ(ut) of the profile's state, as the model's laws give them
    // (on the node grid the surface's angles are these, cached).
    let fresh = Material::new(&case.soil);
    let soil = |p: &ProfilePoint| {
        let own = Soil {
            friction_deg: fresh.friction.at(p.accumulated_shear).to_degrees(),
            cohesion: c,
            unit_weight: p.unit_weight,
        };
        strength.apply(own, fresh.dilation.at(p.accumulated_shear).to_degrees())
    };
    let mut ground = Ground {
        x: profile.iter().map(|p| p.x).collect(),
        y: profile.iter().map(|p| p.y).collect(),
        soil: profile.iter().map(soil).collect(),
    };
    field.apply(&mut ground);
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
    p.domain = domain(&p, &profile, case.soil.unit_weight, floor);
    p
}

/// The default domain, reaching 2 face heights past the disturbed ground
/// (the pile and the bands behind it: the last point of the profile whose
/// height or state is not the fresh flat ground's) if that is further.
fn domain(p: &Problem, profile: &[ProfilePoint], unit_weight: f64, floor: Floor) -> Domain {
    let h = p.face_height();
    let fresh =
        |q: &ProfilePoint| q.y == 0.0 && q.accumulated_shear == 0.0 && q.unit_weight == unit_weight;
    let last = profile.iter().rposition(|q| !fresh(q)).map_or(0, |i| i + 1);
    let disturbed = (profile[last.min(profile.len() - 1)].x - p.face.tip_x) / h;
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

/// A case the bounds can take: plane strain, a rake in their range.
fn check(case: &Case) -> Result<(), InstantError> {
    if let Some(w) = case.blade.width {
        return Err(InstantError::FiniteWidth(w));
    }
    if case.blade.rake < MIN_RAKE {
        return Err(InstantError::Rake(case.blade.rake));
    }
    Ok(())
}

/// Runs `case` to u/d = `at` and brackets the collapse load of the ground
/// there; soilcut's increment on that ground is evaluated too.
pub fn at(case: &Case, at: f64, options: Options) -> Result<Instant, InstantError> {
    check(case)?;
    let mut sim = Simulation::new(case).map_err(InstantError::Case)?;
    sim.drive(Until::Instant(at), &mut ())
        .map_err(InstantError::Step)?;
    instant(&mut sim, options)
}

/// Brackets at u/d = 0, E, 2E, … through the whole run of `case` (each at
/// the first increment at or beyond), E = `every` > 0.
pub fn every(case: &Case, every: f64, options: Options) -> Result<Vec<Instant>, InstantError> {
    check(case)?;
    let mut sim = Simulation::new(case).map_err(InstantError::Case)?;
    let mut out: Vec<Instant> = Vec::new();
    for at in sim.samples_every(every, case.steps().saturating_sub(1)) {
        sim.drive(Until::Increments(at), &mut ())
            .map_err(InstantError::Step)?;
        out.push(instant(&mut sim, options)?);
    }
    Ok(out)
}

/// The bracket of `sim`'s ground as it stands and soilcut's next increment
/// on it (which advances `sim` by one increment).
pub fn instant(sim: &mut Simulation, options: Options) -> Result<Instant, InstantError> {
    let problem = problem_of(sim, options.floor, options.strength, options.field);
    let bracket = bracket(&problem, options.mesh).map_err(InstantError::Bounds)?;
    let record = sim.step().map_err(InstantError::Step)?;
    Ok(Instant {
        record,
        problem,
        bracket,
    })
}
