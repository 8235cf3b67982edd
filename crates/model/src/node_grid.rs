//! The node grid: the yardstick the vertex ground's defaults are judged
//! against (docs/model.md §9). Nodes every increment, h = v0, so the block
//! translates by exactly one node, and the exhaustive search over every
//! node (the stopping rule (M31) and the bounds prune only candidates that
//! cannot win). Each increment finds the minimum-effort mechanism on the
//! current surface (`node_search`), records its force, updates the surface
//! (`kinematics`) and relaxes it (`node_avalanche`), and a blade of finite
//! width spills around its edges into the side heaps (`side_heaps`).
//! Nothing outside this folder asks for it but the simulation's choice of
//! ground (`run.ground = "nodes"`) and the snapshot of its state.

pub mod face_node;
pub mod kinematics;
pub mod node_avalanche;
pub mod node_band;
pub mod node_search;
pub mod surface;

use crate::case::Case;
use crate::crescent::Crescents;
use crate::discretisation::{Context, Discretisation};
use crate::face_friction::Face;
use crate::landscape::Candidate;
use crate::laws::Laws;
use crate::mass::compensated_sum;
use crate::mechanism::Loads;
use crate::node_grid::face_node::FaceNode;
use crate::node_grid::kinematics::{Advance, Kinematics, Update};
use crate::node_grid::node_avalanche::Avalanche;
use crate::node_grid::node_band::Band;
use crate::node_grid::node_search::{Choice, Observer, Search, SearchInput};
use crate::node_grid::surface::Surface;
use crate::rake::Rake;
use crate::side_heaps::{Column, Edges, SideHeaps};
use crate::step::{force_factor, ProfilePoint, StepError, StepRecord};
use crate::tool::tool_state;
use std::ops::Range;

/// Depths the domain grows by when the search reaches its end.
const GROW_DEPTHS: f64 = 4.0;
/// No mechanism reaches further than this many depths ahead of the blade.
const MAX_REACH_DEPTHS: f64 = 1000.0;

/// φ and ψ of fresh soil (ut = 0), radians.
pub(crate) fn fresh_angles(laws: &Laws) -> (f64, f64) {
    (
        laws.material.friction.at(0.0),
        laws.material.dilation.at(0.0),
    )
}

/// The nodes and what works on them.
#[derive(Clone, Debug)]
pub(crate) struct NodeGrid {
    pub(crate) surface: Surface,
    pub(crate) search: Search,
    kinematics: Kinematics,
    avalanche: Avalanche,
    /// Soil spilled around the edges of a blade of finite width.
    pub(crate) side: SideHeaps,
    /// The strip's losses of one spill, summed compensated.
    lost: Vec<f64>,
    /// The grid's shear for a raked blade (identity for 90°).
    rake: Rake,
    /// Steepest slopes on the grid, downhill and uphill in +x (`Rake`).
    repose_slopes: (f64, f64),
    /// w for a blade of finite width, else 1: forces and masses per blade.
    per_blade: f64,
}

impl NodeGrid {
    /// Flat ground of fresh soil, as many nodes as the case starts with.
    pub(crate) fn flat(case: &Case, laws: &Laws) -> Self {
        let surface = Surface::flat(
            case.run.increment,
            case.deepest(),
            case.soil.unit_weight,
            fresh_angles(laws),
            case.initial_nodes() as usize,
        );
        Self::on(case, surface)
    }

    /// The grid of a validated case on `surface`, before its next
    /// increment: what the case determines is derived here, once.
    pub(crate) fn on(case: &Case, surface: Surface) -> Self {
        let rake = Rake::new(case.blade.rake);
        // The repose slopes on the grid (M29), per unit of x'.
        let tan_repose = case.soil.repose.to_radians().tan();
        NodeGrid {
            surface,
            search: Search::default(),
            kinematics: Kinematics::default(),
            avalanche: Avalanche::default(),
            side: SideHeaps::default(),
            lost: Vec::new(),
            rake,
            repose_slopes: rake.repose_slopes(tan_repose),
            per_blade: case.blade.width.unwrap_or(1.0),
        }
    }

    /// Depth of the blade tip now.
    fn tip_depth(&self, case: &Case) -> f64 {
        case.tip_depth(self.blade_position())
    }

    /// Cohesion, adhesion and surcharge for this increment's face contact.
    fn loads(&self, case: &Case) -> Loads {
        // The face from the tip to the surface: y_b + d high.
        let rise = self.surface.height[self.surface.face.node] + self.tip_depth(case);
        Loads::at_face(case, &self.rake, rise)
    }

    /// Rise of the tip per unit of travel over the next increment.
    fn climb(&self, case: &Case) -> f64 {
        let u = self.blade_position();
        let v0 = case.run.increment;
        (case.tip_depth(u) - case.tip_depth(u + v0)) / v0
    }

    /// The increment's mechanism on the current ground; with `observer`,
    /// a survey that hands it every admissible candidate (`Search::survey`).
    fn find_mechanism(
        &mut self,
        at: &Context,
        face: Face,
        observer: Option<Observer>,
    ) -> Option<Choice> {
        let c = at.case;
        let d = self.tip_depth(c);
        let dx = self.surface.spacing;
        let node = self.surface.face.node;
        let crescents = Crescents::of(c, &self.side, (self.surface.x(node), node, dx));
        let input = SearchInput {
            laws: at.laws,
            blade: self.surface.face.node,
            depth: d,
            band_width: c.soil.band_width,
            face,
            rake: self.rake,
            grow_nodes: (GROW_DEPTHS * d / dx).ceil() as usize,
            loads: self.loads(c),
            crescents,
        };
        let reach = self.surface.face.node + (MAX_REACH_DEPTHS * d / dx).ceil() as usize;
        // The end wall: candidates need a node ahead of them before it.
        let max_nodes = c.wall_node().map_or(reach, |w| reach.min(w + 1));
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
    fn no_mechanism(&self, at: &Context) -> StepError {
        StepError::no_mechanism(at.done + 1, self.blade_position(), at.case.bin.length)
    }

    /// The candidate `choice` as the landscape shows it.
    fn candidate(&self, case: &Case, choice: &Choice) -> Candidate {
        // Far-field candidates may lie beyond the nodes held: flat ground.
        let y = self.surface.height.get(choice.node).copied().unwrap_or(0.0);
        Candidate {
            x_emergence: self
                .rake
                .x(self.surface.x(choice.node), y, self.tip_depth(case)),
            y_emergence: y,
            beta_deg: choice.tan_beta.atan().to_degrees(),
            force: choice.force * self.per_blade,
            force_norm: choice.force / case.force_scale(),
            friction_deg: choice.friction.to_degrees(),
            dilation_deg: choice.dilation.to_degrees(),
        }
    }

    /// How the face moves in the next increment, in which the tip goes
    /// `deepening` deeper: one node.
    fn advance(&self, deepening: f64) -> Advance {
        Advance {
            deepening,
            face: FaceNode {
                node: self.surface.face.node + 1,
            },
        }
    }

    /// Moves the soil for the chosen mechanism (§3): the block, the band
    /// and the face by one increment, with the tip at `depth` going to its
    /// depth at u + v0; the angles of the nodes whose shear changed follow.
    fn move_soil(&mut self, at: &Context, choice: &Choice, (u, depth): (f64, f64)) -> Update {
        let (j, c) = (choice.node, at.case);
        let band = Band::new(
            self.surface.face,
            j,
            (choice.grid_slope, choice.tan_beta),
            c.soil.band_width,
            depth,
            self.surface.spacing,
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
        self.surface
            .refresh_angles(&at.laws.material, update.state_from..j + 1);
        self.surface.disturb(j + 1);
        update
    }

    /// Lets the slopes the increment changed avalanche (§6), at the face
    /// and around the band emerging at node `j`, and a blade of finite
    /// width spill its pile around its edges (§16.5).
    fn relax(&mut self, at: &Context, update: &Update, j: usize) {
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
        self.surface.refresh_angles(&at.laws.material, moved);
        if let Some(width) = at.case.blade.width {
            let tan_repose = at.case.soil.repose.to_radians().tan();
            let ahead = first..self.surface.pristine_from.min(self.surface.len());
            self.spill(Edges { width, tan_repose }, ahead);
        }
    }

    /// Spills the strip's soil at `nodes` (ahead of the face) into the
    /// side heaps (M45), each node a node of their field; the strip's loss
    /// by its own mass rule (M24), so that the balance is exact.
    fn spill(&mut self, edges: Edges, nodes: Range<usize>) {
        let first = self.surface.face.node;
        self.side.reach(self.surface.len());
        self.lost.clear();
        for i in nodes {
            let s = &mut self.surface;
            let gamma = s.unit_weight[i];
            let column = Column {
                height: s.height[i],
                unit_weight: gamma,
            };
            let Some(kept) = self.side.spill_at_node(i, column, edges) else {
                continue;
            };
            let before = gamma * s.column_area(i, first);
            s.height[i] = kept;
            self.lost.push(before - gamma * s.column_area(i, first));
        }
        self.side.spilled += compensated_sum(self.lost.iter().copied());
    }
}

impl Discretisation for NodeGrid {
    fn blade_position(&self) -> f64 {
        self.surface.x(self.surface.face.node)
    }

    fn mass(&self) -> f64 {
        self.surface.mass(self.surface.face.node) * self.per_blade
    }

    fn mass_spilled(&self) -> f64 {
        self.side.spilled * self.per_blade
    }

    fn evaluations(&self) -> u64 {
        self.search.evaluations
    }

    fn floor(&self) -> f64 {
        self.surface.floor
    }

    /// The nodes from the face on, at their physical x (`Rake`).
    fn profile(&self, at: &Context) -> Vec<ProfilePoint> {
        let s = &self.surface;
        let d = at.case.blade.depth;
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

    /// Every admissible candidate with its force, nearest the blade first,
    /// up to the stopping bound (`Search::survey`).
    fn landscape(&mut self, at: &Context) -> Result<Vec<Candidate>, StepError> {
        let mut choices = Vec::new();
        let mut record = |c: &Choice| choices.push(*c);
        let face = at.laws.face.for_climb(self.climb(at.case));
        if self.find_mechanism(at, face, Some(&mut record)).is_none() {
            return Err(self.no_mechanism(at));
        }
        Ok(choices
            .iter()
            .map(|choice| self.candidate(at.case, choice))
            .collect())
    }

    /// The increment (§1–§6), its force components by (M12).
    fn step(&mut self, at: &Context) -> Result<StepRecord, StepError> {
        let c = at.case;
        let u = self.blade_position();
        let face = at.laws.face.for_climb(self.climb(c));
        let choice = self
            .find_mechanism(at, face, None)
            .ok_or_else(|| self.no_mechanism(at))?;
        let depth = self.tip_depth(c);
        let face_top = self.surface.height[self.surface.face.node];
        let y_emergence = self.surface.height[choice.node];
        let x_emergence = self.rake.x(self.surface.x(choice.node), y_emergence, depth);
        let update = self.move_soil(at, &choice, (u, depth));
        self.relax(at, &update, choice.node);
        let mobilisation = face.mobilisation(choice.tan_beta, choice.dilation);
        let omega = at.laws.face.angle(mobilisation);
        let force = choice.force * self.per_blade;
        // The reaction is at ω = m φw + α − 90° from the horizontal,
        // the ω of the chosen mechanism's Eq. (1) (M12, M41).
        let (force_h, force_v) = (force * omega.cos(), force * omega.sin());
        let tool = tool_state(&c.blade, u, depth, face_top, [force_h, force_v]);
        Ok(StepRecord {
            step: at.done + 1,
            u,
            u_over_d: u / c.blade.depth,
            force,
            force_norm: choice.force / c.force_scale(),
            force_h,
            force_v,
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
            weight: choice.weight * self.per_blade,
            force_factor: force_factor(choice.force, choice.weight),
            face_friction_deg: mobilisation * c.blade.wall_friction,
            moment: tool.moment,
            tool_x: tool.x,
            tool_y: tool.y,
            tool_rotation: tool.rotation,
        })
    }
}
