//! A fully resolved, validated simulation case: plain data, every default
//! already filled in by whoever read the case file (`defaults`), checked
//! by `Case::validate` (`validate`), with what is known against its
//! accuracy (`warnings`).
//!
//! Lengths are in any consistent unit (the paper's cases use mm); angles are
//! in degrees; unit weight in force per length³ of the same length unit.

mod defaults;
mod error;
mod valid;
pub(crate) mod validate;
mod warnings;

pub use defaults::{
    Class, GroundKind, RunKeys, DEFAULT_SAMPLES_PER_BAND, NODE_INCREMENTS_PER_DEPTH,
    NON_SOFTENING_SAMPLES_PER_BAND, NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH,
    NON_SOFTENING_VERTICES_PER_DEPTH, ORIGINAL_INCREMENTS_PER_DEPTH, RAKED_VERTICES_PER_DEPTH,
    VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH, VERTEX_INCREMENTS_PER_DEPTH, VERTICES_PER_DEPTH,
};
pub use error::CaseError;
pub use valid::ValidCase;
pub use validate::{
    MAGNITUDE, MAX_MERGE_TOLERANCE, MAX_NODES, MAX_SAMPLES_PER_BAND, MAX_SAMPLES_PER_DEPTH,
    MAX_STEPS, MAX_VERTICES, ROUND_OFF, THINNEST_WIDTH,
};

use serde::{Deserialize, Serialize};

/// Which of the paper's two models to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Model {
    /// Kashizadeh (2018): one slip line, incompressible, softening.
    Original,
    /// Jin & Hambleton: shear band of width dB, hardening-softening, dilatancy.
    Refined,
}

impl Model {
    /// The case file's word for the model: `original` or `refined`.
    pub fn name(self) -> &'static str {
        match self {
            Model::Original => "original",
            Model::Refined => "refined",
        }
    }
}

/// An angle that evolves with accumulated shear: `initial` at ut = 0,
/// `peak` at ut = up, `residual` from ut = ur on (degrees).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AngleLaw {
    /// At ut = 0 (φc, ψc), degrees.
    pub initial: f64,
    /// At ut = up (φp, ψp), degrees.
    pub peak: f64,
    /// From ut = ur on (φr, ψr), degrees.
    pub residual: f64,
}

impl AngleLaw {
    /// The same angle at every stage.
    pub fn constant(angle: f64) -> Self {
        AngleLaw {
            initial: angle,
            peak: angle,
            residual: angle,
        }
    }

    fn values(&self) -> [f64; 3] {
        [self.initial, self.peak, self.residual]
    }

    /// The least of the three angles, degrees: the law's minimum, as it is
    /// piecewise linear between them.
    pub fn min(&self) -> f64 {
        self.values().into_iter().fold(f64::INFINITY, f64::min)
    }
}

/// The blade: its depth (or depth path), face angle and face contact.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Blade {
    /// d: depth of the blade tip below the undisturbed surface.
    pub depth: f64,
    /// φw: blade-soil friction angle, degrees.
    pub wall_friction: f64,
    /// α: the face's angle from the horizontal on the soil side, degrees
    /// (90: the paper's vertical blade; less: the face leans back).
    pub rake: f64,
    /// a: blade-soil adhesion (stress), on the face contact.
    pub adhesion: f64,
    /// The tip depth as a piecewise-linear function of blade travel,
    /// [u, d] points (constant beyond the ends): the blade may deepen and
    /// rise. Empty: always `depth`, which is also the reference depth of
    /// normalised forces.
    pub depth_path: Vec<[f64; 2]>,
    /// w: the blade's width (a length). `None`: plane strain, forces per
    /// unit width; with a width, forces are per blade and the mechanism has
    /// side crescents (docs/model.md §16).
    pub width: Option<f64>,
    /// The tool's reference point (its pivot) from the cutting edge, in the
    /// world's axes (x forward, y up; lengths): the point `moment` is taken
    /// about, whose path is `tool_x`, `tool_y`. [0, 0]: the cutting edge.
    /// A `[tool]` sets it from `tool.pivot` at the tool's rotation (M55).
    #[serde(default)]
    pub pivot: [f64; 2],
    /// θ, the tool's rotation (degrees, counter-clockwise), reported as
    /// `tool_rotation`: 0 for a blade, whose face stands at `rake`; a
    /// straight tool's constant rotation, its face at α = α0 − θ (M55).
    #[serde(default)]
    pub rotation: f64,
}

/// The soil: unit weight, material laws (docs/model.md §4), band width,
/// repose and the loads of the extended equation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Soil {
    /// γ0: initial unit weight.
    pub unit_weight: f64,
    /// φc → φp → φr (degrees). The original model has `initial == peak`.
    pub friction: AngleLaw,
    /// ψc → ψp → ψr (degrees). The original model has all zero.
    pub dilation: AngleLaw,
    /// up: accumulated shear at the peak (0 in the original model).
    pub peak_shear: f64,
    /// ur: accumulated shear at which the residual values are reached.
    pub residual_shear: f64,
    /// θr: angle of repose for avalanching, degrees.
    pub repose: f64,
    /// dB: shear band width (0 in the original model: a slip line).
    pub band_width: f64,
    /// c: cohesion (stress) on the slip surface.
    pub cohesion: f64,
    /// q: surcharge pressure on the free surface.
    pub surcharge: f64,
}

impl Soil {
    /// Whether φ(ut) falls anywhere along the law (φr < φp, or φp < φc).
    pub fn softens(&self) -> bool {
        let f = &self.friction;
        f.residual < f.peak || f.peak < f.initial
    }
}

/// How far the blade goes, in what increments, and on which ground.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Run {
    /// Total blade displacement (length).
    pub travel: f64,
    /// v0: blade displacement per increment (length).
    pub increment: f64,
    /// The discretisation of the ground (`run.ground`), with its own keys.
    pub ground: Ground,
}

/// The discretisation a case runs on (`run.ground`): one choice, each with
/// its own keys, so that no number of one ground means "the other ground".
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Ground {
    /// `"vertices"`, the default: the free surface as vertices that the
    /// bands create and the soil carries (docs/model.md §1.2, §3).
    Vertices(VertexGround),
    /// `"nodes"`: the node grid, nodes every increment (h = v0) and an
    /// exhaustive search: the yardstick the defaults are judged against
    /// (docs/model.md §9).
    Nodes,
}

impl Ground {
    /// The case file's word for the ground: `vertices` or `nodes`.
    pub fn name(&self) -> &'static str {
        match self {
            Ground::Vertices(_) => "vertices",
            Ground::Nodes => "nodes",
        }
    }

    /// h, the spacing of the vertex ground's points; None on the node
    /// grid, whose nodes are every increment.
    pub fn vertex_spacing(&self) -> Option<f64> {
        match self {
            Ground::Vertices(v) => Some(v.spacing),
            Ground::Nodes => None,
        }
    }
}

/// The keys of the vertex ground (docs/model.md §1.2).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct VertexGround {
    /// h (`run.vertex_spacing`, length): vertices every h on flat ground,
    /// and a band's points snap to a vertex within h/2.
    pub spacing: f64,
    /// K (`run.samples_per_band`): candidates the search's first stage
    /// evaluates per band width dB (0: every vertex; (M47)).
    pub samples_per_band: f64,
    /// When in the increment a band's strength is taken
    /// (`run.time_scheme`, (M51)).
    pub time_scheme: TimeScheme,
    /// Relative tolerance within which a vertex that carries no
    /// information is removed after each increment (`run.merge_tolerance`,
    /// 0: none, the default; (M50)).
    pub merge_tolerance: f64,
}

impl Run {
    /// The vertex ground's keys, `None` on the node grid.
    pub fn vertices(&self) -> Option<&VertexGround> {
        match &self.ground {
            Ground::Vertices(v) => Some(v),
            Ground::Nodes => None,
        }
    }

    /// The spacing of the ground's points: `run.vertex_spacing` on the
    /// vertex ground, the increment on the node grid (length).
    pub fn spacing(&self) -> f64 {
        match &self.ground {
            Ground::Vertices(v) => v.spacing,
            Ground::Nodes => self.increment,
        }
    }

    /// The ground, increment and time scheme, in words, each as a length
    /// and as a fraction of the blade depth `depth` (`soilcut check`).
    pub fn describe(&self, depth: f64) -> String {
        let of_depth = |length: f64| {
            let short = significant(length);
            let n = depth / length;
            if (n - n.round()).abs() <= 1e-9 * n {
                format!("{short} (d/{n:.0})")
            } else {
                format!("{short} (d/{n:.2})")
            }
        };
        let increment = of_depth(self.increment);
        match &self.ground {
            Ground::Vertices(v) => format!(
                "vertex ground, vertices every {}; increment {increment}; time scheme {}; {} per band",
                of_depth(v.spacing),
                v.time_scheme.name(),
                match v.samples_per_band {
                    0.0 => "every candidate".to_string(),
                    1.0 => "1 sample".to_string(),
                    k => format!("{k} samples"),
                }
            ),
            Ground::Nodes => format!(
                "node grid (the yardstick), nodes every increment {increment}; time scheme explicit; every candidate"
            ),
        }
    }

    /// The vertex ground's keys to change, `None` on the node grid.
    pub fn vertices_mut(&mut self) -> Option<&mut VertexGround> {
        match &mut self.ground {
            Ground::Vertices(v) => Some(v),
            Ground::Nodes => None,
        }
    }
}

/// `length` to 6 decimals from 0.01 up, below in exponent form to 6
/// significant digits (1e-7 read "0"), trailing zeros dropped.
fn significant(length: f64) -> String {
    let trim = |digits: &str| {
        let digits = digits.trim_end_matches('0');
        digits.trim_end_matches('.').to_string()
    };
    if length >= 0.01 {
        return trim(&format!("{length:.6}"));
    }
    let text = format!("{length:.5e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) => format!("{}e{exponent}", trim(mantissa)),
        None => text,
    }
}

/// When in the increment the chosen band's strength is taken.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum TimeScheme {
    /// At the start of the increment, the state the search saw (the
    /// paper's, and the node grid's only scheme).
    #[default]
    Explicit,
    /// The search's band kept; its force and angles taken on its own
    /// state half an increment on, ut + ½ Δut, wherever its footprint
    /// holds soil a band has sheared (on fresh soil, as explicit, so the
    /// first increment is Coulomb's wedge). The vertex ground only
    /// (docs/model.md §2.12).
    MidpointForce,
}

impl TimeScheme {
    /// The case file's word for the scheme: `explicit` or `midpoint-force`.
    pub fn name(self) -> &'static str {
        match self {
            TimeScheme::Explicit => "explicit",
            TimeScheme::MidpointForce => "midpoint-force",
        }
    }
}

/// How a candidate band takes its angles from the nodes it touches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum BandAngleRule {
    /// Mean of φ(ut_i) and ψ(ut_i) over the band's nodes (the default,
    /// docs/model.md §2.7).
    #[default]
    MeanOfAngles,
    /// φ and ψ of the mean ut over the band's nodes.
    AngleOfMeanShear,
}

/// Which soil a candidate band's strength is taken from (vertex ground
/// only).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum BandStrengthRule {
    /// Means over the band's footprint [x − L, x] near its emergence
    /// point (M10, M17): the paper's rule, the default.
    #[default]
    Footprint,
    /// Beyond the paper (M53, docs/model.md §20): means over the columns
    /// the band crosses from the face to its emergence point, weighted by
    /// the band's length in each, each column's φ at least the angle its
    /// surface stands at (up to the repose), ψ and ut as they are.
    CrossedColumns,
    /// As `CrossedColumns` without the floor: each column's φ(ut) as its
    /// law gives it (M53 with the floor's cap at 0°).
    CrossedColumnsUnfloored,
}

/// How much of Δut the band's nodes accumulate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum BandShearRule {
    /// Every node in the band the full Δut (the default, docs/model.md §3.6).
    #[default]
    Full,
    /// A node at relative position f in the band (0 at the lower boundary,
    /// 1 at the upper) accumulates f Δut, its displacement relative to the
    /// ground below the band.
    ByPosition,
}

/// How the band's unit weight is updated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum UnitWeightRule {
    /// One uniform γ over the band's nodes, chosen so that the weight of
    /// soil is unchanged (docs/model.md §5.3: the band as a whole).
    #[default]
    BandUniform,
    /// The paper's A_new = A0 (1 + Δut tan ψ / dB) applied to each band
    /// node's γ on its own: does not conserve mass (for comparison only).
    PerNodeFormula,
}

/// How the face's friction follows the block's slip along the face
/// (docs/model.md §2.6).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum FaceFrictionRule {
    /// Mobilised continuously with the slip over a small range (regularised
    /// Coulomb friction, (M41)): the default, docs/model.md §2.6.
    #[default]
    Mobilised,
    /// Full +φw for a block rising along the face, full −φw otherwise,
    /// also at zero slip (M9): the rule before issue 20, for comparison.
    Sign,
}

/// The choices the paper leaves open (docs/model.md §14), for studying
/// their effect.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Choices {
    /// A candidate band's φ and ψ from its footprint (docs/model.md §2.7).
    pub band_angles: BandAngleRule,
    /// How much of Δut the band's nodes accumulate (docs/model.md §3.6).
    pub band_shear: BandShearRule,
    /// How the band's unit weight is updated (docs/model.md §5).
    pub unit_weight: UnitWeightRule,
    /// How the face friction follows the block's slip (docs/model.md §2.6);
    /// the only choice of both models.
    pub face_friction: FaceFrictionRule,
    /// Which soil a band's strength is taken from: its footprint (the
    /// paper's) or the columns it crosses (M53, docs/model.md §20); the
    /// vertex ground only.
    pub band_strength: BandStrengthRule,
}

/// The soil bin: where the ground ends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Bin {
    /// Distance from the blade's start (x = 0) to a rigid, frictionless end
    /// wall ahead of it: no slip line emerges beyond it and the pile stops
    /// at it. `None`: the ground is unbounded.
    pub length: Option<f64>,
}

/// One simulation case: what the case file says, every default filled in.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Case {
    /// Names the output folder (`out/<name>`).
    pub name: String,
    /// Free text for the outputs.
    pub title: String,
    /// The paper's original or refined model.
    pub model: Model,
    /// The blade and its path.
    pub blade: Blade,
    /// The soil.
    pub soil: Soil,
    /// Travel and increment.
    pub run: Run,
    /// The soil bin's end wall (none: unbounded ground; docs/model.md §10).
    pub bin: Bin,
    /// Variants of the refined model's open choices (defaults: docs/model.md §14).
    pub choices: Choices,
}

/// Depths of flat ground ahead of the blade's final position at the start;
/// the domain grows beyond that only when the search needs it.
pub const INITIAL_REACH_DEPTHS: f64 = 8.0;

impl Case {
    /// Number of increments: the run ends at the first increment at or beyond
    /// `travel` (a travel within 1e-9 of a whole number of increments counts
    /// as that number).
    pub fn steps(&self) -> usize {
        self.increments_to(self.run.travel).max(1)
    }

    /// Increments that bring the blade from its start to displacement `u`
    /// (a length, ≥ 0): the first whole increment at or beyond u, n =
    /// ⌈u / v0⌉, where a u within 1e-9 (relative) of a whole number of
    /// increments counts as that number. `run.travel`'s rule and
    /// `Simulation::advance_to`'s.
    pub fn increments_to(&self, u: f64) -> usize {
        let ratio = u / self.run.increment;
        (ratio - 1e-9 * ratio.max(1.0)).ceil().max(0.0) as usize
    }

    /// γ0 d², d = `blade.depth`: the force scale of the paper's P/(γ0 d²),
    /// for forces per unit width (force/length).
    pub fn force_scale(&self) -> f64 {
        self.soil.unit_weight * self.blade.depth * self.blade.depth
    }

    /// The last node of the node grid (nodes every increment): the node
    /// at or before the end wall (`bin.length`), if there is one.
    pub fn wall_node(&self) -> Option<usize> {
        self.wall_point(self.run.increment)
    }

    /// The last point, `spacing` apart from x = 0, at or before the end
    /// wall (round-off of the quotient forgiven), if there is a wall.
    fn wall_point(&self, spacing: f64) -> Option<usize> {
        let length = self.bin.length?;
        Some((length / spacing * (1.0 + 1e-12)).floor() as usize)
    }

    /// Points of the ground at the start (nodes, or vertices on the vertex
    /// ground, `Run::spacing` apart): the travel plus
    /// `INITIAL_REACH_DEPTHS`, N0 = ceil((travel + 8 d_max) / Δx) + 2 (M30).
    /// With an end wall, no more than the points up to it.
    pub fn initial_nodes(&self) -> f64 {
        self.nodes_to_depth(self.deepest())
    }

    /// `initial_nodes` with the tip no deeper than `deepest` (an upper
    /// bound of the case's own, which the count grows with).
    pub(crate) fn nodes_to_depth(&self, deepest: f64) -> f64 {
        let spacing = self.run.spacing();
        let reach = self.run.travel + INITIAL_REACH_DEPTHS * deepest;
        let nodes = (reach / spacing).ceil() + 2.0;
        self.wall_point(spacing)
            .map_or(nodes, |wall| nodes.min(wall as f64 + 1.0))
    }

    /// The tip depth at blade displacement u (`blade.depth_path`, linear
    /// between its points, constant beyond them; else `blade.depth`).
    pub fn tip_depth(&self, u: f64) -> f64 {
        let path = &self.blade.depth_path;
        // The path's u increases (`Case::validate`): a binary search, as a
        // steered session's path grows a point a tick.
        match path.partition_point(|p| p[0] <= u) {
            k if k == path.len() => path.last().map_or(self.blade.depth, |p| p[1]),
            0 => path[0][1],
            k => {
                let ([u0, d0], [u1, d1]) = (path[k - 1], path[k]);
                d0 + (d1 - d0) * (u - u0) / (u1 - u0)
            }
        }
    }

    /// The fastest the tip climbs along `blade.depth_path`, the largest
    /// (d_i − d_{i+1}) / (u_{i+1} − u_i) (a rise per unit of travel); 0 where
    /// it never climbs. The search's bounds hold for any climb up to it.
    pub fn steepest_climb(&self) -> f64 {
        let path = &self.blade.depth_path;
        path.windows(2)
            .map(|w| climb(w[0], w[1]))
            .fold(0.0, f64::max)
    }

    /// The deepest the tip goes: soil below it never moves.
    pub fn deepest(&self) -> f64 {
        let path = self.blade.depth_path.iter().map(|p| p[1]);
        path.fold(self.blade.depth, f64::max)
    }
}

/// The tip's rise per unit of travel from path point `from` to `to`
/// ([u, depth] each): (d_from − d_to) / (u_to − u_from), negative where it
/// deepens.
pub(crate) fn climb(from: [f64; 2], to: [f64; 2]) -> f64 {
    (from[1] - to[1]) / (to[0] - from[0])
}
