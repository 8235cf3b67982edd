//! The simulation: one increment after another (sequential limit analysis).
//!
//! Each `step()` finds the minimum-effort mechanism on the current surface
//! (`search`), records its force, updates the surface (`kinematics`) and
//! relaxes it (`avalanche`). The caller owns the loop, so the model can sit
//! inside a robot simulator or a notebook; `run_to_end` is the whole case.

use crate::avalanche::Avalanche;
use crate::case::{Case, CaseError, Model};
use crate::kinematics::slide_block;
use crate::material::Material;
use crate::mechanism::ForceFactor;
use crate::search::{Choice, Search, SearchInput};
use crate::surface::Surface;
use std::fmt;

/// Depths of flat ground ahead of the blade's final position at the start;
/// the domain grows beyond that only when the search needs it.
const INITIAL_REACH_DEPTHS: f64 = 8.0;
/// Depths the domain grows by when the search reaches its end.
const GROW_DEPTHS: f64 = 4.0;
/// No mechanism reaches further than this many depths ahead of the blade.
const MAX_REACH_DEPTHS: f64 = 1000.0;

/// What one increment produced. Forces are per unit width.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepRecord {
    /// Increment number, from 1.
    pub step: usize,
    /// Blade displacement at which the mechanism is evaluated (0 for step 1).
    pub u: f64,
    /// P*: resultant blade force.
    pub force: f64,
    /// P* / (γ0 d²).
    pub force_norm: f64,
    /// Horizontal (draft) component P* cos φw.
    pub force_h: f64,
    /// Vertical component P* sin φw, upward on the blade.
    pub force_v: f64,
    /// β*, degrees.
    pub beta_deg: f64,
    /// Friction angle of the chosen mechanism, degrees.
    pub friction_deg: f64,
    /// Emergence point of the slip line (lower band boundary).
    pub x_emergence: f64,
    pub y_emergence: f64,
    /// Δut of the slip line in this increment.
    pub slip: f64,
    /// Weight of soil after the increment (ground that existed at the start).
    pub mass: f64,
}

/// Why an increment could not be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum StepError {
    /// No candidate satisfies β > 0, β + φ + φw < 90° within reach.
    NoAdmissibleMechanism { step: usize, u: f64 },
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::NoAdmissibleMechanism { step, u } => write!(
                f,
                "no admissible mechanism at increment {step} (u = {u}): every candidate violates β > 0 and β + φ + φw < 90°"
            ),
        }
    }
}

impl std::error::Error for StepError {}

/// A point of the free surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfilePoint {
    pub x: f64,
    pub y: f64,
    pub accumulated_shear: f64,
    pub unit_weight: f64,
}

/// The material law with Eq. (1) coefficients cached for the common states.
#[derive(Debug)]
struct Laws {
    material: Material,
    wall_friction: f64,
    residual_shear: f64,
    fresh_factor: ForceFactor,
    residual_factor: ForceFactor,
    /// Lower bound of P/W over every admissible mechanism.
    min_factor: f64,
}

impl Laws {
    fn new(case: &Case) -> Self {
        let material = Material::new(&case.soil);
        let wall_friction = case.blade.wall_friction.to_radians();
        let factor = |phi: f64| ForceFactor::new(phi, wall_friction);
        Laws {
            fresh_factor: factor(material.friction.at(0.0)),
            residual_factor: factor(case.soil.friction.residual.to_radians()),
            min_factor: factor(material.friction.min()).at_zero_angle(),
            residual_shear: case.soil.residual_shear,
            material,
            wall_friction,
        }
    }

    /// Eq. (1) coefficients at node j (the original model's slip line takes
    /// the friction angle of its emergence node).
    fn node_factor(&self, surface: &Surface, j: usize) -> ForceFactor {
        let ut = surface.accumulated_shear[j];
        if ut == 0.0 {
            self.fresh_factor
        } else if ut >= self.residual_shear {
            self.residual_factor
        } else {
            ForceFactor::new(self.material.friction.at(ut), self.wall_friction)
        }
    }
}

/// A running simulation of one case.
#[derive(Debug)]
pub struct Simulation {
    case: Case,
    laws: Laws,
    tan_repose: f64,
    surface: Surface,
    search: Search,
    avalanche: Avalanche,
    /// Increments done; the blade is at node `done`.
    done: usize,
    initial_mass: f64,
}

impl Simulation {
    /// Validates the case and sets up flat ground.
    pub fn new(case: &Case) -> Result<Self, CaseError> {
        case.validate()?;
        let (d, dx) = (case.blade.depth, case.run.increment);
        let reach = case.run.travel + INITIAL_REACH_DEPTHS * d;
        let nodes = (reach / dx).ceil() as usize + 2;
        let surface = Surface::flat(dx, d, case.soil.unit_weight, nodes);
        let initial_mass = surface.mass(0);
        Ok(Simulation {
            laws: Laws::new(case),
            tan_repose: case.soil.repose.to_radians().tan(),
            surface,
            search: Search::default(),
            avalanche: Avalanche::default(),
            done: 0,
            initial_mass,
            case: case.clone(),
        })
    }

    pub fn case(&self) -> &Case {
        &self.case
    }

    /// Increments done so far.
    pub fn steps_done(&self) -> usize {
        self.done
    }

    /// Whether the case's travel has been reached.
    pub fn is_done(&self) -> bool {
        self.done >= self.case.steps()
    }

    /// Blade displacement u (the face is at x = u).
    pub fn blade_position(&self) -> f64 {
        self.surface.x(self.done)
    }

    pub fn surface(&self) -> &Surface {
        &self.surface
    }

    /// Current weight of soil (ground that existed at the start).
    pub fn mass(&self) -> f64 {
        self.surface.mass(self.done)
    }

    pub fn initial_mass(&self) -> f64 {
        self.initial_mass
    }

    /// Candidate evaluations so far (for benchmarks).
    pub fn evaluations(&self) -> u64 {
        self.search.evaluations
    }

    /// The free surface from the face to the end of the domain.
    pub fn profile(&self) -> Vec<ProfilePoint> {
        let s = &self.surface;
        (self.done..s.len())
            .map(|i| ProfilePoint {
                x: s.x(i),
                y: s.height[i],
                accumulated_shear: s.accumulated_shear[i],
                unit_weight: s.unit_weight[i],
            })
            .collect()
    }

    fn find_mechanism(&mut self) -> Option<Choice> {
        let d = self.case.blade.depth;
        let dx = self.surface.spacing;
        let laws = &self.laws;
        let factor = |s: &Surface, j: usize, _t: f64| laws.node_factor(s, j);
        let input = SearchInput {
            blade: self.done,
            depth: d,
            min_factor: laws.min_factor,
            factor: &factor,
            grow_nodes: (GROW_DEPTHS * d / dx).ceil() as usize,
        };
        let max_nodes = self.done + (MAX_REACH_DEPTHS * d / dx).ceil() as usize;
        self.search.run(&mut self.surface, &input, max_nodes)
    }

    /// Advances the blade by one increment.
    pub fn step(&mut self) -> Result<StepRecord, StepError> {
        let u = self.blade_position();
        let step = self.done + 1;
        let choice = self
            .find_mechanism()
            .ok_or(StepError::NoAdmissibleMechanism { step, u })?;
        let j = choice.node;
        let friction_deg = self
            .laws
            .material
            .friction
            .at(self.surface.accumulated_shear[j])
            .to_degrees();
        let (x_emergence, y_emergence) = (self.surface.x(j), self.surface.height[j]);
        let slip = match self.case.model {
            Model::Original | Model::Refined => slide_block(&mut self.surface, self.done, &choice),
        };
        self.done += 1;
        self.avalanche
            .relax(&mut self.surface, self.done, self.tan_repose);
        let c = &self.case;
        Ok(StepRecord {
            step,
            u,
            force: choice.force,
            force_norm: choice.force / (c.soil.unit_weight * c.blade.depth * c.blade.depth),
            force_h: choice.force * self.laws.wall_friction.cos(),
            force_v: choice.force * self.laws.wall_friction.sin(),
            beta_deg: choice.tan_beta.atan().to_degrees(),
            friction_deg,
            x_emergence,
            y_emergence,
            slip,
            mass: self.mass(),
        })
    }

    /// Runs the remaining increments of the case, calling `observer` after
    /// each one.
    pub fn run_to_end(
        &mut self,
        mut observer: impl FnMut(&StepRecord),
    ) -> Result<Vec<StepRecord>, StepError> {
        let mut history = Vec::with_capacity(self.case.steps().saturating_sub(self.done));
        while !self.is_done() {
            let record = self.step()?;
            observer(&record);
            history.push(record);
        }
        Ok(history)
    }
}
