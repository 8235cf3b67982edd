//! The run a case gets where its file leaves a key out: its ground, the
//! ground's keys and the increment. Each default is a claim about its class
//! of case (the model, whether the soil softens, the rake, the face
//! friction), chosen by the ensemble rule (docs/model.md §12.1) against
//! the node grid at d/2000 and rechosen whenever the model's numbers
//! change; the figures are in the studies each constant cites.
//! `Run::resolve` is the one place that applies them.

use super::{
    Blade, CaseError, FaceFrictionRule, Ground, Model, Run, Soil, TimeScheme, VertexGround,
};

/// Increments per blade depth of the original model (one slip line), on
/// either ground: d/250 (`docs/studies/every-class/`, rows "original",
/// "tine", "dozer"; on the node grid `docs/studies/ensemble-accuracy/`).
pub const ORIGINAL_INCREMENTS_PER_DEPTH: f64 = 250.0;

/// Increments per blade depth of the original model in a soil bin: d/1000,
/// with vertices `ORIGINAL_BIN_VERTICES_PER_DEPTH`. As its slip line nears
/// the end wall the force climbs steeply, and d/250 with d/50 missed
/// Fig. 5's soil in an 8 d bin by 2.96 of its tolerance in the last unit
/// window; these hold every bin of the family with margin, at most 0.42 of
/// it (`docs/studies/every-class/families.md`).
pub const ORIGINAL_BIN_INCREMENTS_PER_DEPTH: f64 = 1000.0;

/// Vertex spacings per blade depth of the original model in a soil bin:
/// h = d/100 (`ORIGINAL_BIN_INCREMENTS_PER_DEPTH`).
pub const ORIGINAL_BIN_VERTICES_PER_DEPTH: f64 = 100.0;

/// Increments per blade depth on the vertex ground of the refined model in
/// softening soil with the midpoint force: d/350, the coarsest of d/250 to
/// d/500 accurate on every paper case at both vertex spacings tried
/// (`docs/studies/vertex-ground/`).
pub const VERTEX_INCREMENTS_PER_DEPTH: f64 = 350.0;

/// Increments per blade depth on the vertex ground under the explicit
/// rule (the sign rule of the face friction, or `run.time_scheme =
/// "explicit"` given): d/500 (`docs/studies/vertex-ground/`).
pub const VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH: f64 = 500.0;

/// Increments per blade depth on the vertex ground of the refined model
/// where the soil never softens, with the midpoint force: d/250
/// (`docs/studies/every-class/`, rows "never softening").
pub const NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH: f64 = 250.0;

/// Vertex spacings per blade depth in softening soil under a vertical
/// blade: h = d/50 (`docs/studies/vertex-ground/`).
pub const VERTICES_PER_DEPTH: f64 = 50.0;

/// Vertex spacings per blade depth in softening soil under a raked blade:
/// h = d/100, since the ground lies in the sheared coordinates of `Rake`,
/// where the band is thinner by tan β' / tan β (M16)
/// (`docs/studies/every-class/`, row "fig5-rake60").
pub const RAKED_VERTICES_PER_DEPTH: f64 = 100.0;

/// Vertex spacings per blade depth where the soil never softens, in either
/// model, vertical or raked: h = d/25. No softened band localises the
/// mechanism, so a band's strength is a smooth mean
/// (`docs/studies/every-class/`, rows "never softening").
pub const NON_SOFTENING_VERTICES_PER_DEPTH: f64 = 25.0;

/// `run.samples_per_band` in soil that softens: 8 candidates per band
/// width in the search's first stage ((M47), docs/model.md §2.8).
pub const DEFAULT_SAMPLES_PER_BAND: f64 = 8.0;

/// `run.samples_per_band` where the soil never softens: 1, as no patch of
/// weak soil localises the least band (`docs/studies/every-class/`).
pub const NON_SOFTENING_SAMPLES_PER_BAND: f64 = 1.0;

/// Increments per blade depth of the node grid's refined model, which no
/// class defaults to: d/1250 in softening soil, d/500 where it never
/// softens (`docs/studies/ensemble-accuracy/`). The yardstick is run at
/// d/2000 by the studies, which give the increment.
pub const NODE_INCREMENTS_PER_DEPTH: [f64; 2] = [1250.0, 500.0];

/// Which ground a case file names (`run.ground`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroundKind {
    /// `"vertices"`, the default.
    Vertices,
    /// `"nodes"`, the yardstick.
    Nodes,
}

/// The run keys as a case file gives them, `None` where it leaves one out.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RunKeys {
    /// `run.travel` (length).
    pub travel: f64,
    /// `run.increment` (length).
    pub increment: Option<f64>,
    /// `run.ground`.
    pub ground: Option<GroundKind>,
    /// `run.vertex_spacing` (length), the vertex ground's.
    pub vertex_spacing: Option<f64>,
    /// `run.samples_per_band`, the vertex ground's.
    pub samples_per_band: Option<f64>,
    /// `run.time_scheme`, the vertex ground's.
    pub time_scheme: Option<TimeScheme>,
    /// `run.merge_tolerance`, the vertex ground's.
    pub merge_tolerance: Option<f64>,
}

impl RunKeys {
    /// The vertex ground's keys the file gives, by name.
    fn vertex_keys(&self) -> impl Iterator<Item = &'static str> {
        [
            ("run.vertex_spacing", self.vertex_spacing.is_some()),
            ("run.samples_per_band", self.samples_per_band.is_some()),
            ("run.time_scheme", self.time_scheme.is_some()),
            ("run.merge_tolerance", self.merge_tolerance.is_some()),
        ]
        .into_iter()
        .filter_map(|(key, given)| given.then_some(key))
    }
}

/// What the defaults of a case depend on: its class.
#[derive(Clone, Copy, Debug)]
pub struct Class<'a> {
    /// The paper's original or refined model.
    pub model: Model,
    /// The soil (whether it softens).
    pub soil: &'a Soil,
    /// The blade (its depth and rake).
    pub blade: &'a Blade,
    /// The face friction rule (the time scheme it allows).
    pub face_friction: FaceFrictionRule,
    /// Whether the soil ends at a bin's wall (`bin.length`).
    pub in_bin: bool,
}

impl Run {
    /// The run of `keys`, each key left out taken from the defaults of the
    /// case's class; a key of the vertex ground on the node grid is an
    /// error naming it. Ranges are `Case::validate`'s.
    pub fn resolve(keys: &RunKeys, class: Class<'_>) -> Result<Run, CaseError> {
        let ground = match keys.ground.unwrap_or(GroundKind::Vertices) {
            GroundKind::Vertices => Ground::Vertices(vertex_ground(keys, class)),
            GroundKind::Nodes => {
                if let Some(key) = keys.vertex_keys().next() {
                    return Err(CaseError::new(
                        key,
                        "is a key of run.ground = \"vertices\"; the node grid (run.ground = \
                         \"nodes\") has nodes every run.increment and searches every node: \
                         remove the key, or leave run.ground out for the vertex ground",
                    ));
                }
                Ground::Nodes
            }
        };
        let increment = keys
            .increment
            .unwrap_or_else(|| class.blade.depth / increments_per_depth(&ground, class));
        Ok(Run {
            travel: keys.travel,
            increment,
            ground,
        })
    }
}

/// The vertex ground of `keys`, with the defaults of the class.
fn vertex_ground(keys: &RunKeys, class: Class<'_>) -> VertexGround {
    let softens = class.soil.softens();
    let d = class.blade.depth;
    let per_depth = match (softens, class.blade.rake == 90.0) {
        _ if class.model == Model::Original && class.in_bin => ORIGINAL_BIN_VERTICES_PER_DEPTH,
        (false, _) => NON_SOFTENING_VERTICES_PER_DEPTH,
        (true, true) => VERTICES_PER_DEPTH,
        (true, false) => RAKED_VERTICES_PER_DEPTH,
    };
    let samples = if softens {
        DEFAULT_SAMPLES_PER_BAND
    } else {
        NON_SOFTENING_SAMPLES_PER_BAND
    };
    // The midpoint force needs the mobilised face friction
    // (`Case::validate`).
    let scheme = match class.face_friction {
        FaceFrictionRule::Mobilised => TimeScheme::MidpointForce,
        FaceFrictionRule::Sign => TimeScheme::Explicit,
    };
    VertexGround {
        spacing: keys.vertex_spacing.unwrap_or(d / per_depth),
        samples_per_band: keys.samples_per_band.unwrap_or(samples),
        time_scheme: keys.time_scheme.unwrap_or(scheme),
        merge_tolerance: keys.merge_tolerance.unwrap_or(0.0),
    }
}

/// Increments per blade depth of `run.increment`'s default on `ground`.
fn increments_per_depth(ground: &Ground, class: Class<'_>) -> f64 {
    let softens = class.soil.softens();
    match (ground, class.model) {
        (_, Model::Original) if class.in_bin => ORIGINAL_BIN_INCREMENTS_PER_DEPTH,
        (_, Model::Original) => ORIGINAL_INCREMENTS_PER_DEPTH,
        (Ground::Vertices(v), _) => match v.time_scheme {
            TimeScheme::Explicit => VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH,
            TimeScheme::MidpointForce if softens => VERTEX_INCREMENTS_PER_DEPTH,
            TimeScheme::MidpointForce => NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH,
        },
        (Ground::Nodes, Model::Refined) => NODE_INCREMENTS_PER_DEPTH[usize::from(!softens)],
    }
}
