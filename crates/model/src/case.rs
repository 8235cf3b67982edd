//! A fully resolved, validated simulation case: plain data, every default
//! already filled in by whoever read the case file.
//!
//! Lengths are in any consistent unit (the paper's cases use mm); angles are
//! in degrees; unit weight in force per length³ of the same length unit.

use serde::{Deserialize, Serialize};
use std::fmt;

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

/// `run.increment` when a case does not give it: v0 = d / 500, the
/// coarsest of d/250, d/500 and d/1000 that is accurate by the ensemble rule
/// (docs/model.md §12.1, (M40)) on every paper case, against the reference
/// grid's ensemble at d/2000 (`docs/studies/ensemble-accuracy/`); the node
/// spacing defaults to `default_node_spacing`.
pub const DEFAULT_INCREMENTS_PER_DEPTH: f64 = 500.0;

/// Node spacings per blade depth of the default coarse grid, used where
/// the soil never softens: h = d / 25 at v0 = d / 500 is accurate by the
/// ensemble rule on Fig. 8b (`docs/studies/ensemble-accuracy/`).
pub const COARSE_NODES_PER_DEPTH: f64 = 25.0;

/// `run.node_spacing` when a case does not give it, for the increment v0:
/// the reference grid (h = v0) where the soil softens, as only there does
/// a coarse grid converge to a limit of its own (docs/model.md §9); else
/// the whole number of increments nearest below d / 25 (at least one).
pub fn default_node_spacing(soil: &Soil, depth: f64, increment: f64) -> f64 {
    if soil.softens() {
        return increment;
    }
    let per_node = (depth / COARSE_NODES_PER_DEPTH / increment).floor();
    per_node.max(1.0) * increment
}

impl Soil {
    /// Whether φ(ut) falls anywhere along the law (φr < φp, or φp < φc).
    pub fn softens(&self) -> bool {
        let f = &self.friction;
        f.residual < f.peak || f.peak < f.initial
    }
}

/// How far the blade goes and in what increments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Run {
    /// Total blade displacement.
    pub travel: f64,
    /// v0: blade displacement per increment.
    pub increment: f64,
    /// h: spacing of the surface nodes, a whole multiple k = h / v0 of the
    /// increment (k = 1 is the reference scheme; see `surface`).
    pub node_spacing: f64,
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

/// Largest number of surface nodes a case may need at the start (memory
/// guard: five f64 per node).
pub const MAX_NODES: f64 = 5.0e7;

/// The range of magnitudes of every length, unit weight and stress a case
/// gives (a value that may be 0 is 0 or in this range), in the case's own
/// units. Wide enough for any consistent units (nanometres to kilometres,
/// pascals to gigapascals, either way round), narrow enough that no
/// product the model forms overflows or underflows: the largest, a
/// blade's weight and force γ d² w or γ d³, stays within 1e±80, and the
/// widest ratio, c / (γ d), within 1e±60, far inside f64's 1e±308 (at
/// γ = 1e306 the initial mass was infinite: docs/fuzzing.md).
pub const MAGNITUDE: [f64; 2] = [1e-20, 1e20];

/// The narrowest blade, as a fraction of the deepest tip depth.
pub const THINNEST_WIDTH: f64 = 1e-6;

/// Depths of flat ground ahead of the blade's final position at the start;
/// the domain grows beyond that only when the search needs it.
pub const INITIAL_REACH_DEPTHS: f64 = 8.0;

/// Why a case cannot be run: the offending key (dotted path as in the case
/// file) and what it must satisfy.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseError {
    /// The case-file key, dotted (`soil.friction.peak`).
    pub key: String,
    /// What the value must satisfy, and the value given.
    pub message: String,
}

impl CaseError {
    /// The error for `key` with `message`.
    pub fn new(key: &str, message: impl Into<String>) -> Self {
        CaseError {
            key: key.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for CaseError {}

fn finite(key: &str, value: f64) -> Result<f64, CaseError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(CaseError::new(
            key,
            format!("must be a finite number (got {value})"),
        ))
    }
}

/// A length, unit weight or stress: `value` in [`MAGNITUDE`], or 0 when
/// `zero` allows it.
fn in_magnitude(key: &str, value: f64, zero: bool) -> Result<(), CaseError> {
    let [least, greatest] = MAGNITUDE;
    if (least..=greatest).contains(&value) || (zero && value == 0.0) {
        return Ok(());
    }
    let or_zero = if zero { "0 or " } else { "" };
    Err(CaseError::new(
        key,
        format!("must be {or_zero}in [{least:e}, {greatest:e}] (got {value:?})"),
    ))
}

fn positive(key: &str, value: f64) -> Result<(), CaseError> {
    if finite(key, value)? > 0.0 {
        in_magnitude(key, value, false)
    } else {
        Err(CaseError::new(key, format!("must be > 0 (got {value})")))
    }
}

fn non_negative(key: &str, value: f64) -> Result<(), CaseError> {
    if finite(key, value)? >= 0.0 {
        in_magnitude(key, value, true)
    } else {
        Err(CaseError::new(key, format!("must be >= 0 (got {value})")))
    }
}

fn open_range(key: &str, value: f64, lo: f64, hi: f64, unit: &str) -> Result<(), CaseError> {
    let v = finite(key, value)?;
    if v > lo && v < hi {
        Ok(())
    } else {
        Err(CaseError::new(
            key,
            format!("must be in ({lo}{unit}, {hi}{unit}) (got {value}{unit})"),
        ))
    }
}

impl Case {
    /// Why the results may be less accurate than they look, one sentence
    /// each (empty when nothing is known against the case):
    /// * nodes coarser than the increment where the soil softens converge
    ///   to a limit of their own (docs/model.md §9);
    /// * a blade narrower than a sixth of its depth fails the soil
    ///   sideways below a critical depth, which the side crescents do not
    ///   describe (docs/model.md §16.4).
    pub fn accuracy_warnings(&self) -> Vec<String> {
        let (h, v0) = (self.run.node_spacing, self.run.increment);
        let mut warnings = Vec::new();
        if self.soil.softens() && h > v0 {
            warnings.push(format!(
                "run.node_spacing = {h} is coarser than run.increment = {v0} in soil that \
                 softens: such a grid converges to a limit of its own, 7-18 times the \
                 ensemble rule's tolerance off the reference grid in the unit-window mean \
                 forces of Table 1 S, HS and Fig. 5 (docs/model.md §9, §12.1); leave \
                 run.node_spacing out for the reference grid"
            ));
        }
        if let Some(w) = self.blade.width {
            let d = self.deepest();
            if w < d * crate::crescent::NARROWEST {
                warnings.push(format!(
                    "blade.width = {w} is narrower than 1/6 of the deepest tip depth {d}: \
                     below a critical depth of about 6 widths a narrow tine fails the soil \
                     sideways (Godwin & Spoor 1977), which the side crescents do not \
                     describe, so the force is underestimated there (docs/model.md §16.4)"
                ));
            }
        }
        warnings
    }

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

    /// Checks every value against its allowed range; the error names the key.
    pub fn validate(&self) -> Result<(), CaseError> {
        positive("blade.depth", self.blade.depth)?;
        self.validate_friction()?;
        self.validate_wall_friction()?;
        self.validate_soil()?;
        self.validate_loads()?;
        self.validate_run()?;
        self.validate_bin()
    }

    /// The end wall must leave the blade room to travel and a mechanism
    /// ahead of it; on the sheared grid of a raked blade a vertical wall is
    /// no fixed node, so it needs a vertical blade.
    fn validate_bin(&self) -> Result<(), CaseError> {
        let Some(length) = self.bin.length else {
            return Ok(());
        };
        let least = self.run.travel + 2.0 * self.run.node_spacing;
        if finite("bin.length", length)? < least {
            return Err(CaseError::new(
                "bin.length",
                format!("must be >= run.travel + 2 run.node_spacing = {least} (got {length})"),
            ));
        }
        in_magnitude("bin.length", length, false)?;
        if self.blade.rake != 90.0 {
            return Err(CaseError::new(
                "bin.length",
                format!(
                    "needs a vertical blade, blade.rake = 90° (got {}°)",
                    self.blade.rake
                ),
            ));
        }
        Ok(())
    }

    /// The last node of the ground: the node at or before the end wall
    /// (`bin.length`), if there is one.
    pub fn wall_node(&self) -> Option<usize> {
        let length = self.bin.length?;
        Some((length / self.run.node_spacing * (1.0 + 1e-12)).floor() as usize)
    }

    fn validate_loads(&self) -> Result<(), CaseError> {
        let rake = finite("blade.rake", self.blade.rake)?;
        self.validate_rake(rake)?;
        non_negative("blade.adhesion", self.blade.adhesion)?;
        self.validate_depth_path()?;
        if let Some(width) = self.blade.width {
            positive("blade.width", width)?;
            // The search compares P / w: the side crescents' force over a
            // vanishing width overflows to an infinite force (found by
            // fuzzing, docs/fuzzing.md: w = 1e-310). A millionth of the
            // depth is far below any tine (the model warns below d/6).
            let least = THINNEST_WIDTH * self.deepest();
            if width < least {
                return Err(CaseError::new(
                    "blade.width",
                    format!(
                        "must be >= {THINNEST_WIDTH:e} x the deepest tip depth = {least} (got {width})"
                    ),
                ));
            }
        }
        // −a Lb cos(α + β + φ) never lowers the force if α + φ ≥ 90°; the
        // search's bounds rely on that.
        let phi_min = self.soil.friction.min();
        if self.blade.adhesion > 0.0 && rake + phi_min < 90.0 {
            return Err(CaseError::new(
                "blade.adhesion",
                format!(
                    "must be 0 unless blade.rake + every friction angle ≥ 90° (got {rake}° + {phi_min}°)"
                ),
            ));
        }
        non_negative("soil.cohesion", self.soil.cohesion)?;
        non_negative("soil.surcharge", self.soil.surcharge)
    }

    fn validate_wall_friction(&self) -> Result<(), CaseError> {
        let phi_w = finite("blade.wall_friction", self.blade.wall_friction)?;
        let phi_min = self.soil.friction.min();
        if !(0.0..phi_min).contains(&phi_w) {
            return Err(CaseError::new(
                "blade.wall_friction",
                format!(
                    "must be in [0°, {phi_min}°), below every soil friction angle (got {phi_w}°)"
                ),
            ));
        }
        Ok(())
    }

    fn friction_keys(&self) -> [(&'static str, f64); 3] {
        let f = &self.soil.friction;
        [
            ("soil.friction.initial", f.initial),
            ("soil.friction.peak", f.peak),
            ("soil.friction.residual", f.residual),
        ]
    }

    fn validate_friction(&self) -> Result<(), CaseError> {
        for (key, v) in self.friction_keys() {
            open_range(key, v, 0.0, 90.0, "°")?;
        }
        Ok(())
    }

    fn validate_soil(&self) -> Result<(), CaseError> {
        let s = &self.soil;
        positive("soil.unit_weight", s.unit_weight)?;
        let f = &s.friction;
        for (key, v) in self.friction_keys() {
            // β > 0 and β + φ + φw < 90° must leave room for a mechanism.
            if v + self.blade.wall_friction >= 90.0 {
                return Err(CaseError::new(
                    key,
                    format!(
                        "φ + φw must be < 90° for any admissible mechanism (β + φ + φw < 90°, β > 0); got {v}° + {}°",
                        self.blade.wall_friction
                    ),
                ));
            }
        }
        if f.residual > f.peak {
            return Err(CaseError::new(
                "soil.friction.residual",
                format!(
                    "must be <= soil.friction.peak ({}°) (got {}°)",
                    f.peak, f.residual
                ),
            ));
        }
        if f.initial > f.peak {
            return Err(CaseError::new(
                "soil.friction.initial",
                format!(
                    "must be <= soil.friction.peak ({}°) (got {}°)",
                    f.peak, f.initial
                ),
            ));
        }
        let d = &s.dilation;
        for (key, v) in [
            ("soil.dilation.initial", d.initial),
            ("soil.dilation.peak", d.peak),
            ("soil.dilation.residual", d.residual),
        ] {
            open_range(key, v, -45.0, 45.0, "°")?;
        }
        non_negative("soil.peak_shear", s.peak_shear)?;
        non_negative("soil.residual_shear", s.residual_shear)?;
        if s.residual_shear < s.peak_shear {
            return Err(CaseError::new(
                "soil.residual_shear",
                format!(
                    "must be >= soil.peak_shear ({}) (got {})",
                    s.peak_shear, s.residual_shear
                ),
            ));
        }
        open_range("soil.repose", s.repose, 0.0, 90.0, "°")?;
        non_negative("soil.band_width", s.band_width)?;
        if s.band_width >= self.blade.depth {
            return Err(CaseError::new(
                "soil.band_width",
                format!(
                    "must be < blade.depth ({}) (got {})",
                    self.blade.depth, s.band_width
                ),
            ));
        }
        Ok(())
    }

    fn validate_rake(&self, rake: f64) -> Result<(), CaseError> {
        if !(20.0..=90.0).contains(&rake) {
            return Err(CaseError::new(
                "blade.rake",
                format!("must be in [20°, 90°] (got {rake}°)"),
            ));
        }
        // Eq. (1) grows with φ only while sin(α − φw) > 0.
        if self.blade.wall_friction >= rake {
            return Err(CaseError::new(
                "blade.wall_friction",
                format!(
                    "must be below blade.rake ({rake}°) (got {}°)",
                    self.blade.wall_friction
                ),
            ));
        }
        Ok(())
    }

    fn validate_depth_path(&self) -> Result<(), CaseError> {
        let key = "blade.depth_path";
        let path = &self.blade.depth_path;
        for (k, &[u, d]) in path.iter().enumerate() {
            finite(key, u)?;
            finite(key, d)?;
            let [least, greatest] = MAGNITUDE;
            let scaled = |v: f64| (least..=greatest).contains(&v);
            if !(u == 0.0 || scaled(u)) || !scaled(d) {
                return Err(CaseError::new(
                    key,
                    format!(
                        "point {k}: needs u 0 or in [{least:e}, {greatest:e}] and depth in [{least:e}, {greatest:e}] (got [{u:?}, {d:?}])"
                    ),
                ));
            }
            if k > 0 && u <= path[k - 1][0] {
                return Err(CaseError::new(
                    key,
                    format!(
                        "point {k}: u must increase from point to point (got [{u}, {d}] after {:?})",
                        path[k - 1]
                    ),
                ));
            }
        }
        if !path.is_empty() && self.blade.rake != 90.0 {
            return Err(CaseError::new(
                key,
                format!(
                    "needs a vertical blade, blade.rake = 90° (got {}°)",
                    self.blade.rake
                ),
            ));
        }
        if let Some(shallowest) = path.first().map(|p| p[1]) {
            if self.run.increment >= shallowest || self.soil.band_width >= shallowest {
                return Err(CaseError::new(
                    key,
                    format!(
                        "the shallowest depth ({shallowest}) must exceed run.increment and the band width"
                    ),
                ));
            }
        }
        Ok(())
    }

    fn validate_run(&self) -> Result<(), CaseError> {
        positive("run.travel", self.run.travel)?;
        positive("run.increment", self.run.increment)?;
        if self.run.increment >= self.blade.depth {
            return Err(CaseError::new(
                "run.increment",
                format!(
                    "must be in (0, blade.depth = {}) (got {})",
                    self.blade.depth, self.run.increment
                ),
            ));
        }
        self.validate_node_spacing()?;
        let nodes = self.initial_nodes();
        if nodes > MAX_NODES {
            return Err(CaseError::new(
                "run.node_spacing",
                format!(
                    "too fine: (run.travel + {INITIAL_REACH_DEPTHS} blade.depth) / run.node_spacing must be <= {MAX_NODES:e} nodes (got {nodes:.3e})"
                ),
            ));
        }
        Ok(())
    }

    fn validate_node_spacing(&self) -> Result<(), CaseError> {
        let (h, v0) = (self.run.node_spacing, self.run.increment);
        positive("run.node_spacing", h)?;
        if h >= self.blade.depth {
            return Err(CaseError::new(
                "run.node_spacing",
                format!(
                    "must be in (0, blade.depth = {}) (got {h})",
                    self.blade.depth
                ),
            ));
        }
        let ratio = h / v0;
        if ratio < 1.0 - 1e-9 || (ratio - ratio.round()).abs() > 1e-9 * ratio {
            return Err(CaseError::new(
                "run.node_spacing",
                format!(
                    "must be a whole multiple (1, 2, 3, ...) of run.increment = {v0} (got {h}, {ratio} increments)"
                ),
            ));
        }
        Ok(())
    }

    /// γ0 d², d = `blade.depth`: the force scale of the paper's P/(γ0 d²),
    /// for forces per unit width (force/length).
    pub fn force_scale(&self) -> f64 {
        self.soil.unit_weight * self.blade.depth * self.blade.depth
    }

    /// k = h / v0: increments per node spacing (1: the reference scheme).
    pub fn increments_per_node(&self) -> usize {
        (self.run.node_spacing / self.run.increment)
            .round()
            .max(1.0) as usize
    }

    /// Surface nodes at the start: the travel plus `INITIAL_REACH_DEPTHS`,
    /// N0 = ceil((travel + 8 d_max) / Δx) + 2 (M30). With an end wall, no
    /// more than the nodes up to it.
    pub fn initial_nodes(&self) -> f64 {
        let reach = self.run.travel + INITIAL_REACH_DEPTHS * self.deepest();
        let nodes = (reach / self.run.node_spacing).ceil() + 2.0;
        self.wall_node()
            .map_or(nodes, |wall| nodes.min(wall as f64 + 1.0))
    }

    /// The tip depth at blade displacement u (`blade.depth_path`, linear
    /// between its points, constant beyond them; else `blade.depth`).
    pub fn tip_depth(&self, u: f64) -> f64 {
        let path = &self.blade.depth_path;
        match path.iter().position(|p| p[0] > u) {
            None => path.last().map_or(self.blade.depth, |p| p[1]),
            Some(0) => path[0][1],
            Some(k) => {
                let ([u0, d0], [u1, d1]) = (path[k - 1], path[k]);
                d0 + (d1 - d0) * (u - u0) / (u1 - u0)
            }
        }
    }

    /// The deepest the tip goes: soil below it never moves.
    pub fn deepest(&self) -> f64 {
        let path = self.blade.depth_path.iter().map(|p| p[1]);
        path.fold(self.blade.depth, f64::max)
    }
}
