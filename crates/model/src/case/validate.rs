//! The allowed range of every key of a case (README, "Case files"): a value
//! outside it is an error naming the key and the range, never clamped.

use super::{
    BandAngleRule, BandStrengthRule, Case, CaseError, FaceFrictionRule, Ground, TimeScheme,
    VertexGround, INITIAL_REACH_DEPTHS,
};
use crate::tool::motion::MAX_ROTATION;

/// Largest number of surface nodes a case may need at the start (memory
/// guard: five f64 per node).
pub const MAX_NODES: f64 = 5.0e7;

/// Largest number of vertices the vertex ground may have at the start
/// (memory guard: the model holds about 0.2 kB a vertex, `soilcut run`
/// 40 bytes more a vertex for each of its up to 120 frames; measured in
/// docs/guide/case-keys.md, "Limits").
pub const MAX_VERTICES: f64 = 1.0e6;

/// Most increments a run may take (memory guard: `history.csv` holds a
/// record of 20 numbers, 160 bytes, an increment).
pub const MAX_STEPS: f64 = 1.0e6;

/// Most first-stage samples the vertex ground's search may take per
/// length `blade.depth` of ground (memory guard: it scans at most 1000
/// depths ahead of the face, 24 bytes a sample, so at most 240 MB).
pub const MAX_SAMPLES_PER_DEPTH: f64 = 1.0e4;

/// Most samples per band width, `run.samples_per_band` (8 by default).
pub const MAX_SAMPLES_PER_BAND: f64 = 1000.0;

/// The least increment, as a fraction of the ground's length at the start
/// (run.travel + 8 deepest depths): a finer one is below the round-off of
/// the ground's abscissae, where the face's advance and the search's
/// narrowing to the increment lose their digits (at 1e-15 of 160 the
/// golden-section search never ended, issue 50).
pub const ROUND_OFF: f64 = 1e-9;

/// The range of magnitudes of every length, unit weight and stress a case
/// gives (a value that may be 0 is 0 or in this range), in the case's own
/// units. Wide enough for any consistent units (nanometres to kilometres,
/// pascals to gigapascals, either way round), narrow enough that no
/// product the model forms overflows or underflows: the largest, a
/// blade's weight and force γ d² w or γ d³, stays within 1e±80, and the
/// widest ratio, c / (γ d), within 1e±60, far inside f64's 1e±308 (at
/// γ = 1e306 the initial mass was infinite: docs/fuzzing.md).
pub const MAGNITUDE: [f64; 2] = [1e-20, 1e20];

/// The largest `run.merge_tolerance`: beyond a tenth, vertices whose
/// pieces differ by a tenth of ur would be joined.
pub const MAX_MERGE_TOLERANCE: f64 = 0.1;

/// The narrowest blade, as a fraction of the deepest tip depth.
pub const THINNEST_WIDTH: f64 = 1e-6;

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

pub(crate) fn positive(key: &str, value: f64) -> Result<(), CaseError> {
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

pub(crate) fn open_range(
    key: &str,
    value: f64,
    lo: f64,
    hi: f64,
    unit: &str,
) -> Result<(), CaseError> {
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
    /// Checks every value against its allowed range; the error names the key.
    pub fn validate(&self) -> Result<(), CaseError> {
        positive("blade.depth", self.blade.depth)?;
        self.validate_friction()?;
        self.validate_wall_friction()?;
        self.validate_soil()?;
        self.validate_loads()?;
        self.validate_run()?;
        self.validate_bin()?;
        self.validate_band_strength()
    }

    /// `choices.band_strength`: the crossed columns (M53) on the vertex
    /// ground only, whose pieces are the columns (the node grid's nodes
    /// hold no column to cross), and with the mean of the columns' angles,
    /// since each column's φ is floored on its own.
    fn validate_band_strength(&self) -> Result<(), CaseError> {
        if self.choices.band_strength == BandStrengthRule::Footprint {
            return Ok(());
        }
        if self.run.ground == Ground::Nodes {
            return Err(CaseError::new(
                "choices.band_strength",
                "\"crossed-columns\" and \"crossed-columns-unfloored\" run on the vertex ground \
                 only (run.ground = \"vertices\"), whose pieces are the columns the band \
                 crosses; the node grid takes \"footprint\"",
            ));
        }
        if self.choices.band_angles == BandAngleRule::AngleOfMeanShear {
            return Err(CaseError::new(
                "choices.band_strength",
                "the crossed columns need choices.band_angles = \"mean-of-angles\": each \
                 column's φ is its own (floored at the angle it stands at), which a φ of the \
                 mean ut cannot hold",
            ));
        }
        Ok(())
    }

    /// `run.time_scheme`: the midpoint force under the mobilised face
    /// friction only.
    fn validate_time_scheme(&self, ground: &VertexGround) -> Result<(), CaseError> {
        if ground.time_scheme == TimeScheme::MidpointForce
            && self.choices.face_friction == FaceFrictionRule::Sign
        {
            return Err(CaseError::new(
                "run.time_scheme",
                "\"midpoint-force\" needs choices.face_friction = \"mobilised\": under \"sign\" \
                 the face friction jumps from -φw to +φw with the band's dilation, which the \
                 band the search chose can cross half an increment on; \"explicit\" runs it",
            ));
        }
        Ok(())
    }

    /// The vertex ground's keys: its spacing in (0, blade.depth), its
    /// samples ≥ 0, its time scheme and merge tolerance.
    fn validate_vertex_ground(&self, ground: &VertexGround) -> Result<(), CaseError> {
        let h = ground.spacing;
        positive("run.vertex_spacing", h)?;
        if h >= self.blade.depth {
            return Err(CaseError::new(
                "run.vertex_spacing",
                format!(
                    "must be in (0, blade.depth = {}) (got {h})",
                    self.blade.depth
                ),
            ));
        }
        let least = 0.25 * self.run.increment;
        if h < least {
            // Pieces shorter than v0/4 are joined by every increment
            // (`Ground::merge_close`), and a face piece that short took
            // the swept soil as a spike that avalanched over the whole
            // ground ahead: vertices and memory grew with every increment.
            return Err(CaseError::new(
                "run.vertex_spacing",
                format!(
                    "must be >= run.increment / 4 = {least}: pieces shorter are joined by every increment (got {h})"
                ),
            ));
        }
        let samples = ground.samples_per_band;
        non_negative("run.samples_per_band", samples)?;
        if samples > MAX_SAMPLES_PER_BAND {
            return Err(CaseError::new(
                "run.samples_per_band",
                format!("must be in [0, {MAX_SAMPLES_PER_BAND}] (got {samples})"),
            ));
        }
        self.validate_samples_per_depth(samples)?;
        self.validate_time_scheme(ground)?;
        let tolerance = finite("run.merge_tolerance", ground.merge_tolerance)?;
        if !(0.0..=MAX_MERGE_TOLERANCE).contains(&tolerance) {
            return Err(CaseError::new(
                "run.merge_tolerance",
                format!("must be in [0, {MAX_MERGE_TOLERANCE}] (got {tolerance})"),
            ));
        }
        Ok(())
    }

    /// The vertex ground's first-stage samples per length d of ground, at
    /// most [`MAX_SAMPLES_PER_DEPTH`]: K d / dB for a band (K samples per
    /// band width), d / v0 for the exhaustive search (K = 0, a sample
    /// every increment), 64 for a slip line.
    fn validate_samples_per_depth(&self, samples: f64) -> Result<(), CaseError> {
        let (d, band, v0) = (self.blade.depth, self.soil.band_width, self.run.increment);
        let most = MAX_SAMPLES_PER_DEPTH;
        if samples == 0.0 && d / v0 > most {
            return Err(CaseError::new(
                "run.increment",
                format!(
                    "must be >= blade.depth / {most:e} = {} where run.samples_per_band = 0 samples the search every increment: at most {most:e} samples per depth (got {v0})",
                    d / most
                ),
            ));
        }
        if samples > 0.0 && band > 0.0 && samples * d / band > most {
            return Err(CaseError::new(
                "soil.band_width",
                format!(
                    "must be >= run.samples_per_band x blade.depth / {most:e} = {}: the search takes at most {most:e} samples per depth, K d / dB (got {band}; or fewer run.samples_per_band)",
                    samples * d / most
                ),
            ));
        }
        Ok(())
    }

    /// The end wall must leave the blade room to travel and a mechanism
    /// ahead of it; on the sheared grid of a raked blade a vertical wall is
    /// no fixed node, so it needs a vertical blade.
    fn validate_bin(&self) -> Result<(), CaseError> {
        let Some(length) = self.bin.length else {
            return Ok(());
        };
        let least = self.run.travel + 2.0 * self.run.increment;
        if finite("bin.length", length)? < least {
            return Err(CaseError::new(
                "bin.length",
                format!("must be >= run.travel + 2 run.increment = {least} (got {length})"),
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

    /// The tool's pivot and rotation, which a `[tool]` sets (M55, M56):
    /// lengths 0 or in [`MAGNITUDE`] either way, a rotation within
    /// ±`MAX_ROTATION`.
    fn validate_pivot(&self) -> Result<(), CaseError> {
        for (key, value) in [
            ("tool.pivot", self.blade.pivot[0]),
            ("tool.pivot", self.blade.pivot[1]),
        ] {
            in_magnitude(key, finite(key, value)?.abs(), true)?;
        }
        let rotation = finite("tool.motion", self.blade.rotation)?;
        if rotation.abs() > MAX_ROTATION {
            return Err(CaseError::new(
                "tool.motion",
                format!("the rotation must be within ±{MAX_ROTATION}° (got {rotation}°)"),
            ));
        }
        Ok(())
    }

    fn validate_loads(&self) -> Result<(), CaseError> {
        let rake = finite("blade.rake", self.blade.rake)?;
        self.validate_rake(rake)?;
        non_negative("blade.adhesion", self.blade.adhesion)?;
        self.validate_depth_path()?;
        self.validate_pivot()?;
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
        positive("soil.unit_weight", self.soil.unit_weight)?;
        self.validate_friction_order()?;
        self.validate_dilation_and_shear()
    }

    /// φ + φw < 90° for every friction angle, and the initial and residual
    /// angles at most the peak.
    fn validate_friction_order(&self) -> Result<(), CaseError> {
        let f = &self.soil.friction;
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
        Ok(())
    }

    /// Dilation angles within ±45°, the shear strains ordered, the angle
    /// of repose and a band narrower than the blade is deep.
    fn validate_dilation_and_shear(&self) -> Result<(), CaseError> {
        let s = &self.soil;
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

    /// The rules a longer `run.travel` can break, for a case that passed
    /// `validate` with a shorter one and whose tip goes no deeper than
    /// `deepest` (a simulation's floor): the travel itself, the end wall
    /// ahead of it and the points of the ground at the start, counted at
    /// `deepest`. Where that count is over, the full `validate` decides
    /// with the case's own deepest point (O(path)); else this is O(1), so
    /// a tick that runs past the travel does not cost the length of the
    /// path a session has steered (`Simulation::advance_to`).
    pub(crate) fn validate_longer_travel(&self, deepest: f64) -> Result<(), CaseError> {
        positive("run.travel", self.run.travel)?;
        // In `validate`'s order, so that a travel that breaks two rules
        // is refused by the same one.
        if self.validate_extent(deepest).is_err() {
            return self.validate();
        }
        self.validate_bin()
    }

    fn validate_depth_path(&self) -> Result<(), CaseError> {
        self.validate_depth_points(0)
    }

    /// The rules of `blade.depth_path` for its points from `from` on (each
    /// against the one before it) and for the path as a whole: what a
    /// steered tick checks of the points it adds (`Simulation::advance_to`).
    pub(crate) fn validate_depth_points(&self, from: usize) -> Result<(), CaseError> {
        let key = "blade.depth_path";
        let path = &self.blade.depth_path;
        for (k, &[u, d]) in path.iter().enumerate().skip(from) {
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
        if let Ground::Vertices(ground) = &self.run.ground {
            self.validate_vertex_ground(ground)?;
        }
        self.validate_extent(self.deepest())
    }

    /// The rules of the ground's extent with the tip no deeper than
    /// `deepest`, which a longer `run.travel` can break: the increment
    /// above the round-off of the ground's abscissae ([`ROUND_OFF`]), the
    /// points of the ground at the start ([`MAX_NODES`] nodes,
    /// [`MAX_VERTICES`] vertices) and the increments ([`MAX_STEPS`]).
    fn validate_extent(&self, deepest: f64) -> Result<(), CaseError> {
        let (travel, v0) = (self.run.travel, self.run.increment);
        let least = ROUND_OFF * (travel + INITIAL_REACH_DEPTHS * deepest);
        if v0 < least {
            return Err(CaseError::new(
                "run.increment",
                format!(
                    "must be >= {ROUND_OFF:e} x (run.travel + {INITIAL_REACH_DEPTHS} x the deepest tip depth) = {least:e}, the round-off of the ground's abscissae (got {v0:e})"
                ),
            ));
        }
        let nodes = self.nodes_to_depth(deepest);
        let (key, points, most) = match self.run.ground {
            Ground::Vertices(_) => ("run.vertex_spacing", "vertices", MAX_VERTICES),
            Ground::Nodes => ("run.increment", "nodes", MAX_NODES),
        };
        if nodes > most {
            return Err(CaseError::new(
                key,
                format!(
                    "too fine: (run.travel + {INITIAL_REACH_DEPTHS} blade.depth) / {key} must be <= {most:e} {points} (got {nodes:.3e})"
                ),
            ));
        }
        let steps = travel / v0;
        if steps > MAX_STEPS {
            return Err(CaseError::new(
                "run.increment",
                format!(
                    "too fine: run.travel / run.increment must be <= {MAX_STEPS:e} increments (got {steps:.3e}); a coarser increment or a shorter run.travel"
                ),
            ));
        }
        Ok(())
    }
}
