//! The simulation: one increment after another (sequential limit analysis).
//!
//! Each `step()` finds the minimum-effort mechanism on the current surface
//! (`search`), records its force, updates the surface (`kinematics`) and
//! relaxes it (`avalanche`). The caller owns the loop, so the model can sit
//! inside a robot simulator or a notebook; `run_to_end` is the whole case.

use crate::avalanche::Avalanche;
use crate::band::Band;
use crate::case::{Case, CaseError};
use crate::crescent::Crescents;
use crate::face_friction::Face;
use crate::grid::Scheme;
use crate::ground::cutting::Cutting;
use crate::kinematics::{Advance, Kinematics, Update};
use crate::landscape::Candidate;
use crate::laws::Laws;
use crate::mechanism::Loads;
use crate::rake::Rake;
use crate::search::{Choice, Observer, Search, SearchInput};
use crate::spill::SideHeaps;
use crate::surface::Surface;

mod advance;
pub mod snapshot;

pub use crate::step::{ProfilePoint, StepError, StepRecord};

pub use advance::AdvanceError;
pub use snapshot::SnapshotError;

/// φ and ψ of fresh soil (ut = 0), radians.
fn fresh_angles(laws: &Laws) -> (f64, f64) {
    (
        laws.material.friction.at(0.0),
        laws.material.dilation.at(0.0),
    )
}

/// Depths the domain grows by when the search reaches its end.
const GROW_DEPTHS: f64 = 4.0;
/// No mechanism reaches further than this many depths ahead of the blade.
const MAX_REACH_DEPTHS: f64 = 1000.0;

/// A running simulation of one case.
#[derive(Clone, Debug)]
pub struct Simulation {
    case: Case,
    laws: Laws,
    /// The grid's shear for a raked blade (identity for 90°).
    rake: Rake,
    /// Steepest slopes on the grid, downhill and uphill in +x (`Rake`).
    repose_slopes: (f64, f64),
    surface: Surface,
    search: Search,
    kinematics: Kinematics,
    avalanche: Avalanche,
    /// Soil spilled around the edges of a blade of finite width.
    side: SideHeaps,
    /// w for a blade of finite width, else 1: forces and masses per blade.
    per_blade: f64,
    /// Increments done.
    done: usize,
    initial_mass: f64,
    /// The vertex ground, where the case sets `run.vertex_spacing` above 0
    /// (docs/model.md §19): it then holds the state and makes the
    /// increments, and `surface` stays as set up.
    vertices: Option<Box<Cutting>>,
}

impl Simulation {
    /// Validates the case and sets up flat ground.
    pub fn new(case: &Case) -> Result<Self, CaseError> {
        case.validate()?;
        let nodes = case.initial_nodes() as usize;
        let laws = Laws::new(case);
        let fresh = fresh_angles(&laws);
        let surface = Surface::flat(
            Self::scheme(case),
            case.deepest(),
            case.soil.unit_weight,
            fresh,
            nodes,
        );
        let initial_mass = surface.mass(0);
        let mut sim = Self::assemble(case.clone(), laws, surface, initial_mass);
        if case.run.vertex_spacing > 0.0 {
            let cutting = Cutting::new(case)?;
            sim.initial_mass = cutting.ground().mass();
            sim.vertices = Some(Box::new(cutting));
        }
        Ok(sim)
    }

    /// The node grid of a case: h = k v0.
    fn scheme(case: &Case) -> Scheme {
        Scheme {
            spacing: case.run.node_spacing,
            increment: case.run.increment,
            increments_per_node: case.increments_per_node(),
        }
    }

    /// A simulation of a validated case on `surface`, before its first
    /// increment: what the case determines is derived here, once.
    fn assemble(case: Case, laws: Laws, surface: Surface, initial_mass: f64) -> Self {
        let rake = Rake::new(case.blade.rake);
        // The repose slopes on the grid (M29), per unit of x'.
        let tan_repose = case.soil.repose.to_radians().tan();
        Simulation {
            laws,
            rake,
            repose_slopes: rake.repose_slopes(tan_repose),
            surface,
            search: Search::default(),
            kinematics: Kinematics::default(),
            avalanche: Avalanche::default(),
            side: SideHeaps::default(),
            per_blade: case.blade.width.unwrap_or(1.0),
            done: 0,
            initial_mass,
            vertices: None,
            case,
        }
    }

    /// The case being run.
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
        match &self.vertices {
            Some(cutting) => cutting.ground().x[0],
            None => self.surface.x(self.surface.face.node),
        }
    }

    /// The nodes as the model holds them: on the grid, whose x is the
    /// physical x only for a vertical blade (`Rake`; `profile` converts).
    pub fn surface(&self) -> &Surface {
        &self.surface
    }

    /// Current weight of soil ahead of the blade (ground that existed at
    /// the start), per blade for a blade of finite width.
    pub fn mass(&self) -> f64 {
        match &self.vertices {
            Some(cutting) => cutting.ground().mass(),
            None => self.surface.mass(self.surface.face.node) * self.per_blade,
        }
    }

    /// Weight of soil spilled into the side heaps so far (M45), per blade.
    pub fn mass_spilled(&self) -> f64 {
        self.side.spilled * self.per_blade
    }

    /// Weight of soil at the start (docs/model.md (M24)), per blade for a
    /// blade of finite width.
    pub fn initial_mass(&self) -> f64 {
        self.initial_mass * self.per_blade
    }

    /// Candidate evaluations so far (for benchmarks).
    pub fn evaluations(&self) -> u64 {
        match &self.vertices {
            Some(cutting) => cutting.evaluations(),
            None => self.search.evaluations,
        }
    }

    /// The free surface from the face to the end of the domain.
    pub fn profile(&self) -> Vec<ProfilePoint> {
        if let Some(cutting) = &self.vertices {
            return cutting.profile();
        }
        let s = &self.surface;
        let d = self.case.blade.depth;
        (s.face.node..s.len())
            .map(|i| ProfilePoint {
                x: self.rake.x(s.x(i), s.height[i], d),
                y: s.height[i],
                accumulated_shear: s.accumulated_shear[i],
                unit_weight: s.unit_weight[i],
                ridge_height: self.side.height.get(i).copied().unwrap_or(0.0),
            })
            .collect()
    }

    /// Cohesion, adhesion and surcharge for this increment's face contact.
    fn loads(&self) -> Loads {
        // The face from the tip to the surface: y_b + d high.
        let rise = self.surface.height[self.surface.face.node] + self.tip_depth();
        Loads::at_face(&self.case, &self.rake, rise)
    }

    /// P / (γ0 d²), d the reference depth `blade.depth`, for P per unit
    /// width.
    fn normalised(&self, force: f64) -> f64 {
        force / self.case.force_scale()
    }

    /// Rise of the tip per unit of travel over the next increment.
    fn climb(&self) -> f64 {
        let u = self.blade_position();
        let v0 = self.case.run.increment;
        (self.case.tip_depth(u) - self.case.tip_depth(u + v0)) / v0
    }

    /// Depth of the blade tip now.
    pub fn tip_depth(&self) -> f64 {
        self.case.tip_depth(self.blade_position())
    }

    /// The increment's mechanism on the current ground; with `observer`,
    /// a survey that hands it every admissible candidate (`Search::survey`).
    fn find_mechanism(&mut self, face: Face, observer: Option<Observer>) -> Option<Choice> {
        let d = self.tip_depth();
        let dx = self.surface.scheme.spacing;
        let c = &self.case;
        let crescents = c.blade.width.map(|width| Crescents {
            width,
            unit_weight: c.soil.unit_weight,
            tan_repose: c.soil.repose.to_radians().tan(),
            face_x: self.surface.x(self.surface.face.node),
            spacing: dx,
            ridges: self.side.any_from(self.surface.face.node),
            ridge_height: &self.side.height,
            ridge_unit_weight: &self.side.unit_weight,
        });
        let input = SearchInput {
            laws: &self.laws,
            blade: self.surface.face.node,
            depth: d,
            band_width: self.case.soil.band_width,
            face,
            rake: self.rake,
            grow_nodes: (GROW_DEPTHS * d / dx).ceil() as usize,
            loads: self.loads(),
            crescents,
            stride: self.case.search_stride(),
        };
        let reach = self.surface.face.node + (MAX_REACH_DEPTHS * d / dx).ceil() as usize;
        // The end wall: candidates need a node ahead of them before it.
        let max_nodes = self.case.wall_node().map_or(reach, |w| reach.min(w + 1));
        let choice = match observer {
            None => self.search.run(&mut self.surface, &input, max_nodes),
            Some(observe) => self
                .search
                .survey(&mut self.surface, &input, max_nodes, observe),
        }?;
        // A band far out on undisturbed ground needs its nodes (and one more).
        let missing = (choice.node + 2).saturating_sub(self.surface.len());
        if missing > 0 {
            self.surface.grow(missing.max(input.grow_nodes));
        }
        Some(choice)
    }

    /// Why the next increment has no mechanism.
    fn no_mechanism(&self) -> StepError {
        let (step, u) = (self.done + 1, self.blade_position());
        match self.case.bin.length {
            Some(length) => StepError::NoMechanismBeforeWall { step, u, length },
            None => StepError::NoAdmissibleMechanism { step, u },
        }
    }

    /// Every admissible candidate of the next increment with its force,
    /// nearest the blade first, up to where the stopping bound proves that
    /// none further can beat the least (`search`); nothing is advanced, and
    /// the next `step` is the one it would have been. Fails as `step`
    /// would if no candidate is admissible.
    pub fn landscape(&mut self) -> Result<Vec<Candidate>, StepError> {
        if let Some(cutting) = &mut self.vertices {
            return cutting.landscape();
        }
        let mut choices = Vec::new();
        let mut record = |c: &Choice| choices.push(*c);
        let found = self.find_mechanism(self.laws.face.for_climb(self.climb()), Some(&mut record));
        if found.is_none() {
            return Err(self.no_mechanism());
        }
        let depth = self.tip_depth();
        Ok(choices
            .iter()
            .map(|choice| {
                // Far-field candidates may lie beyond the nodes held: flat ground.
                let y = self.surface.height.get(choice.node).copied().unwrap_or(0.0);
                Candidate {
                    x_emergence: self.rake.x(self.surface.x(choice.node), y, depth),
                    y_emergence: y,
                    beta_deg: choice.tan_beta.atan().to_degrees(),
                    force: choice.force * self.per_blade,
                    force_norm: self.normalised(choice.force),
                    friction_deg: choice.friction.to_degrees(),
                    dilation_deg: choice.dilation.to_degrees(),
                }
            })
            .collect())
    }

    /// How the face moves in the next increment, in which the tip goes
    /// `deepening` deeper: one node every k increments, in between offset
    /// by a whole number of increments.
    fn advance(&self, deepening: f64) -> Advance {
        let scheme = &self.surface.scheme;
        Advance {
            deepening,
            face: scheme.face_after(self.done + 1, self.surface.face.node),
        }
    }

    /// Advances the blade by one increment; after the case's travel,
    /// `StepError::TravelReached`.
    pub fn step(&mut self) -> Result<StepRecord, StepError> {
        if self.is_done() {
            return Err(StepError::TravelReached { steps: self.done });
        }
        if let Some(cutting) = &mut self.vertices {
            let record = cutting.step()?;
            self.done += 1;
            return Ok(record);
        }
        let u = self.blade_position();
        let face = self.laws.face.for_climb(self.climb());
        let choice = self
            .find_mechanism(face, None)
            .ok_or_else(|| self.no_mechanism())?;
        let depth = self.tip_depth();
        let y_emergence = self.surface.height[choice.node];
        let x_emergence = self.rake.x(self.surface.x(choice.node), y_emergence, depth);
        let update = self.move_soil(&choice, u, depth);
        self.done += 1;
        self.relax(&update, choice.node);
        let omega = self
            .laws
            .face
            .angle(face.mobilisation(choice.tan_beta, choice.dilation));
        let force = choice.force * self.per_blade;
        Ok(StepRecord {
            step: self.done,
            u,
            u_over_d: u / self.case.blade.depth,
            force,
            force_norm: self.normalised(choice.force),
            // The reaction is at ω = m φw + α − 90° from the horizontal,
            // the ω of the chosen mechanism's Eq. (1) (M12, M41).
            force_h: force * omega.cos(),
            force_v: force * omega.sin(),
            beta_deg: choice.tan_beta.atan().to_degrees(),
            friction_deg: choice.friction.to_degrees(),
            dilation_deg: choice.dilation.to_degrees(),
            x_emergence,
            y_emergence,
            depth,
            slip: update.slip,
            dilation_area: update.dilation_area,
            mass: self.mass(),
            mass_spilled: self.mass_spilled(),
        })
    }

    /// Moves the soil for the chosen mechanism (§3): the block, the band
    /// and the face by one increment, with the tip at `depth` going to its
    /// depth at u + v0; the angles of the nodes whose shear changed follow.
    fn move_soil(&mut self, choice: &Choice, u: f64, depth: f64) -> Update {
        let (j, c) = (choice.node, &self.case);
        let band = Band::new(
            self.surface.face,
            j,
            (choice.grid_slope, choice.tan_beta),
            c.soil.band_width,
            depth,
            self.surface.scheme.spacing,
        );
        let advance = self.advance(c.tip_depth(u + c.run.increment) - depth);
        let update = self.kinematics.apply(
            &mut self.surface,
            &band,
            choice,
            c.choices,
            &self.rake,
            advance,
        );
        self.surface.trench_mass += update.trench_mass;
        self.laws
            .refresh_angles(&mut self.surface, update.state_from..j + 1);
        self.surface.disturb(j + 1);
        update
    }

    /// Lets the slopes the increment changed avalanche (§6), at the face
    /// and around the band emerging at node `j`, and a blade of finite
    /// width spill its pile around its edges (§16.5).
    fn relax(&mut self, update: &Update, j: usize) {
        let first = self.surface.face.node;
        let at_face = first..first + 3;
        let band_nodes = update.first_band_node.saturating_sub(2)..j + 2;
        let moved = self.avalanche.relax(
            &mut self.surface,
            first,
            self.repose_slopes,
            &[at_face, band_nodes],
        );
        self.surface.disturb(moved.end);
        self.laws.refresh_angles(&mut self.surface, moved);
        if let Some(width) = self.case.blade.width {
            let tan_repose = self.case.soil.repose.to_radians().tan();
            let ahead = first..self.surface.pristine_from.min(self.surface.len());
            self.side.spill(&mut self.surface, width, tan_repose, ahead);
        }
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
