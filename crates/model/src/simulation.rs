//! The simulation: one increment after another (sequential limit analysis).
//!
//! Each `step()` finds the minimum-effort mechanism on the current ground,
//! records its force, moves the soil by it and relaxes the slopes, on the
//! vertex ground (`vertices::cutting`) or the node grid (`node_grid`), as
//! the case's `run.ground` says: which one is decided once, when the simulation is set up (`Discretised`). The
//! caller owns the loop, so the model can sit inside a robot simulator or
//! a notebook; `run_to_end` is the whole case.

use crate::case::{Case, CaseError, Ground, ValidCase};
use crate::discretisation::{Context, Discretisation};
use crate::landscape::Candidate;
use crate::laws::Laws;
use crate::node_grid::NodeGrid;
use crate::vertices::cutting::Cutting;

mod advance;
mod driver;
#[cfg(test)]
mod finite;
#[cfg(test)]
mod node_grid_area;
pub mod snapshot;

pub use crate::step::{ProfilePoint, StepError, StepRecord};

pub use advance::AdvanceError;
pub use driver::{Observer, Until};
pub use snapshot::SnapshotError;

/// The ground a simulation runs on, chosen from its case once.
#[derive(Clone, Debug)]
enum Discretised {
    Nodes(Box<NodeGrid>),
    Vertices(Box<Cutting>),
}

impl Discretised {
    /// The ground of the case's `run.ground`, flat, of fresh soil.
    fn flat(case: &Case, laws: &Laws) -> Self {
        match case.run.ground {
            Ground::Vertices(keys) => Discretised::Vertices(Box::new(Cutting::new(case, keys))),
            Ground::Nodes => Discretised::Nodes(Box::new(NodeGrid::flat(case, laws))),
        }
    }

    /// The ground, to be asked: what both grounds answer goes through
    /// here, and only what one of them alone has (its nodes, its vertices)
    /// is matched on elsewhere.
    fn get(&self) -> &dyn Discretisation {
        match self {
            Discretised::Nodes(nodes) => nodes.as_ref(),
            Discretised::Vertices(cutting) => cutting.as_ref(),
        }
    }

    /// The ground, to be advanced.
    fn get_mut(&mut self) -> &mut dyn Discretisation {
        match self {
            Discretised::Nodes(nodes) => nodes.as_mut(),
            Discretised::Vertices(cutting) => cutting.as_mut(),
        }
    }
}

/// A running simulation of one case.
#[derive(Clone, Debug)]
pub struct Simulation {
    case: ValidCase,
    laws: Laws,
    ground: Discretised,
    /// Increments done.
    done: usize,
    /// Weight of soil at the start, per blade for a blade of finite width.
    initial_mass: f64,
    /// The error of an increment that left a number not finite
    /// (`StepError::NotFinite`): its ground moved, so every later step and
    /// landscape gives it again rather than go on from that state.
    failed: Option<StepError>,
}

impl Simulation {
    /// Validates the case and sets up flat ground.
    pub fn new(case: &Case) -> Result<Self, CaseError> {
        Ok(Simulation::start(&case.clone().validated()?))
    }

    /// Sets up flat ground for a case already validated.
    pub fn start(case: &ValidCase) -> Self {
        let laws = Laws::new(case);
        let ground = Discretised::flat(case, &laws);
        // Per blade for a blade of finite width, as `mass` is.
        let initial_mass = ground.get().mass();
        Simulation {
            case: case.clone(),
            laws,
            ground,
            done: 0,
            initial_mass,
            failed: None,
        }
    }

    /// The ground and what it is given of the simulation's state.
    fn parts(&mut self) -> (&mut dyn Discretisation, Context<'_>) {
        let at = Context {
            case: &self.case,
            laws: &self.laws,
            done: self.done,
        };
        (self.ground.get_mut(), at)
    }

    /// What a ground is given to answer a question.
    fn context(&self) -> Context<'_> {
        Context {
            case: &self.case,
            laws: &self.laws,
            done: self.done,
        }
    }

    /// The case being run (as steered so far).
    pub fn case(&self) -> &ValidCase {
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
        self.ground.get().blade_position()
    }

    /// Current weight of soil ahead of the blade (ground that existed at
    /// the start), per blade for a blade of finite width.
    pub fn mass(&self) -> f64 {
        self.ground.get().mass()
    }

    /// Weight of soil spilled into the side heaps so far (M45), per blade.
    pub fn mass_spilled(&self) -> f64 {
        self.ground.get().mass_spilled()
    }

    /// Weight of soil at the start (docs/model.md (M24)), per blade for a
    /// blade of finite width.
    pub fn initial_mass(&self) -> f64 {
        self.initial_mass
    }

    /// Candidate evaluations so far (for benchmarks).
    pub fn evaluations(&self) -> u64 {
        self.ground.get().evaluations()
    }

    /// The free surface from the face to the end of the domain.
    pub fn profile(&self) -> Vec<ProfilePoint> {
        self.ground.get().profile(&self.context())
    }

    /// Depth of the blade tip now.
    pub fn tip_depth(&self) -> f64 {
        self.case.tip_depth(self.blade_position())
    }

    /// Every admissible candidate of the next increment with its force,
    /// nearest the blade first, up to where the stopping bound proves that
    /// none further can beat the least (`search`); nothing is advanced, and
    /// the next `step` is the one it would have been (on the vertex ground,
    /// the first stage's samples, `Cutting`). Fails as `step` would if no
    /// candidate is admissible.
    pub fn landscape(&mut self) -> Result<Vec<Candidate>, StepError> {
        if let Some(e) = &self.failed {
            return Err(e.clone());
        }
        let (ground, at) = self.parts();
        ground.landscape(&at)
    }

    /// Advances the blade by one increment; after the case's travel,
    /// `StepError::TravelReached`. An increment whose record (and with it
    /// the mass, the sum over the whole ground) holds a number that is not
    /// finite is `StepError::NotFinite`, which every later step gives too:
    /// no record with NaN or ∞ leaves the model (issue 50).
    pub fn step(&mut self) -> Result<StepRecord, StepError> {
        if let Some(e) = &self.failed {
            return Err(e.clone());
        }
        if self.is_done() {
            return Err(StepError::TravelReached { steps: self.done });
        }
        let (ground, at) = self.parts();
        let record = ground.step(&at)?;
        if let Some(e) = StepError::not_finite(&record) {
            self.failed = Some(e.clone());
            return Err(e);
        }
        self.done += 1;
        Ok(record)
    }

    /// Runs the remaining increments of the case (`drive` to its end),
    /// calling `observer` after each one, and returns their records.
    pub fn run_to_end(
        &mut self,
        mut observer: impl FnMut(&StepRecord),
    ) -> Result<Vec<StepRecord>, StepError> {
        let mut history = Vec::with_capacity(self.case.steps().saturating_sub(self.done));
        self.drive(Until::End, &mut |_: &Simulation, record: &StepRecord| {
            observer(record);
            history.push(*record);
        })?;
        Ok(history)
    }
}
