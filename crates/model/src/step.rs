//! What an increment produces, the record of `history.csv`, and why one
//! cannot be made; a point of the free surface. Shared by the node grid's
//! `Simulation` and the vertex ground's `Cutting`, which both make them.

use std::fmt;

/// What one increment produced. Forces and masses are per unit width, or
/// per blade for a blade of finite width (`blade.width`). The fields are
/// the columns of `history.csv`, in its order (`StepRecord::COLUMNS`
/// names them once for the files and the front ends).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepRecord {
    /// Increment number, from 1.
    pub step: usize,
    /// Blade displacement at which the mechanism is evaluated (0 for step 1).
    pub u: f64,
    /// u / d, d the reference depth `blade.depth`.
    pub u_over_d: f64,
    /// P*: resultant blade force.
    pub force: f64,
    /// P* / (γ0 d²), d the reference depth `blade.depth` (P* / (γ0 d² w)
    /// for a blade of width w).
    pub force_norm: f64,
    /// Horizontal (draft) component P* cos φw.
    pub force_h: f64,
    /// Vertical component P* sin φw, upward on the blade.
    pub force_v: f64,
    /// β*, degrees.
    pub beta_deg: f64,
    /// Emergence point of the slip line (lower band boundary).
    pub x_emergence: f64,
    /// Weight of soil ahead of the blade after the increment (ground that
    /// existed at the start).
    pub mass: f64,
    /// y of the emergence point.
    pub y_emergence: f64,
    /// Friction angle of the chosen mechanism, degrees.
    pub friction_deg: f64,
    /// Δut of the band (slip line) in this increment.
    pub slip: f64,
    /// Band dilation angle ψ of the chosen mechanism, degrees.
    pub dilation_deg: f64,
    /// Area added by the band's dilation in this increment (Δuv A0 / dB).
    pub dilation_area: f64,
    /// Depth of the blade tip during the increment.
    pub depth: f64,
    /// Weight of soil that has spilled around the blade's edges into the
    /// side heaps (0 in plane strain): `mass + mass_spilled` is conserved.
    pub mass_spilled: f64,
    /// W, the weight of the chosen mechanism's block (the soil between the
    /// face, the band's lower boundary and the surface, at the start of
    /// the increment): per unit width, or per blade (W w) for a blade of
    /// finite width.
    pub weight: f64,
    /// P* / W, both per unit width: Eq. (1)'s factor
    /// sin(β + φ) / cos(β + φ + ω) where the case has no cohesion,
    /// adhesion, surcharge or side crescents (those add to P, not to W);
    /// 0 for a block of no weight (`force_factor`).
    pub force_factor: f64,
    /// The face force's angle from the face's normal, m φw, degrees: the
    /// wall friction the block mobilises (positive: the block rises along
    /// the face; ω = m φw + α − 90° from the horizontal, (M41)).
    pub face_friction_deg: f64,
    /// M, the moment of the face force about the tool's pivot (force ×
    /// length, counter-clockwise positive), the force a third up the
    /// contact (M56).
    pub moment: f64,
    /// x of the tool's pivot (`blade.pivot` from the cutting edge; the
    /// edge itself by default).
    pub tool_x: f64,
    /// y of the tool's pivot.
    pub tool_y: f64,
    /// The tool's rotation, degrees (0 for a blade).
    pub tool_rotation: f64,
}

/// A column of `history.csv`: its name and a record's value in it.
pub type Column = (&'static str, fn(&StepRecord) -> f64);

impl StepRecord {
    /// The columns of `history.csv`, in order, named once (soilcut-io's
    /// `HISTORY`, the C ABI's record and Python's `Step` take them from
    /// here, and so does the finiteness check of `Simulation::step`; a
    /// field becomes a column by one line here).
    pub const COLUMNS: [Column; 24] = [
        ("step", |r| r.step as f64),
        ("u", |r| r.u),
        ("u_over_d", |r| r.u_over_d),
        ("force", |r| r.force),
        ("force_norm", |r| r.force_norm),
        ("force_h", |r| r.force_h),
        ("force_v", |r| r.force_v),
        ("beta_deg", |r| r.beta_deg),
        ("x_emergence", |r| r.x_emergence),
        ("mass", |r| r.mass),
        ("y_emergence", |r| r.y_emergence),
        ("friction_deg", |r| r.friction_deg),
        ("slip", |r| r.slip),
        ("dilation_deg", |r| r.dilation_deg),
        ("dilation_area", |r| r.dilation_area),
        ("depth", |r| r.depth),
        ("mass_spilled", |r| r.mass_spilled),
        ("weight", |r| r.weight),
        ("force_factor", |r| r.force_factor),
        ("face_friction_deg", |r| r.face_friction_deg),
        ("moment", |r| r.moment),
        ("tool_x", |r| r.tool_x),
        ("tool_y", |r| r.tool_y),
        ("tool_rotation", |r| r.tool_rotation),
    ];

    /// The first column whose value is not finite, and the value.
    pub fn not_finite(&self) -> Option<(&'static str, f64)> {
        Self::COLUMNS
            .iter()
            .map(|&(name, value)| (name, value(self)))
            .find(|(_, v)| !v.is_finite())
    }
}

/// P / W for the record, 0 where the block weighs nothing (a band through
/// air at the face of a tip pulled up, or ground thinner than round-off):
/// there is no weight for Eq. (1) to multiply, and a record holds no NaN.
pub(crate) fn force_factor(force: f64, weight: f64) -> f64 {
    if weight > 0.0 {
        force / weight
    } else {
        0.0
    }
}

/// Why an increment could not be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum StepError {
    /// No candidate satisfies β > 0, β + φ + φw < 90° within reach.
    NoAdmissibleMechanism {
        /// The increment, from 1.
        step: usize,
        /// Blade displacement at its start.
        u: f64,
    },
    /// No admissible slip line emerges before the end wall (`bin.length`).
    NoMechanismBeforeWall {
        /// The increment, from 1.
        step: usize,
        /// Blade displacement at its start.
        u: f64,
        /// `bin.length`, the wall's distance from the blade's start.
        length: f64,
    },
    /// The increment left a number of its record not finite (NaN or
    /// infinite): the run cannot go on from it. The record's mass sums
    /// every piece's (or node's) weight, so a height, abscissa or unit
    /// weight of the ground that stops being finite shows there.
    NotFinite {
        /// The increment, from 1.
        step: usize,
        /// Blade displacement at its start.
        u: f64,
        /// The column of `history.csv` that is not finite (the first).
        quantity: &'static str,
        /// Its value: NaN or ±∞.
        value: f64,
    },
    /// A step asked for after the case's travel has been reached: the
    /// caller's mistake, not the soil's (`advance_to` goes further).
    TravelReached {
        /// The increments done, all of the case's.
        steps: usize,
    },
}

impl StepError {
    /// Why increment `step`, the blade at u, has no mechanism: none before
    /// the end wall where there is one (`length`, `bin.length`), else none
    /// admissible at all (either ground).
    pub(crate) fn no_mechanism(step: usize, u: f64, wall: Option<f64>) -> Self {
        match wall {
            Some(length) => StepError::NoMechanismBeforeWall { step, u, length },
            None => StepError::NoAdmissibleMechanism { step, u },
        }
    }

    /// The error of an increment whose `record` holds a number that is not
    /// finite, if it does.
    pub(crate) fn not_finite(record: &StepRecord) -> Option<Self> {
        let (quantity, value) = record.not_finite()?;
        Some(StepError::NotFinite {
            step: record.step,
            u: record.u,
            quantity,
            value,
        })
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::NoAdmissibleMechanism { step, u } => write!(
                f,
                "no admissible mechanism at increment {step} (u = {u}): every candidate violates β > 0 and β + φ + φw < 90°"
            ),
            StepError::NoMechanismBeforeWall { step, u, length } => write!(
                f,
                "no admissible mechanism at increment {step} (u = {u}) emerges before the end wall at bin.length = {length}: shorten run.travel or lengthen the bin"
            ),
            StepError::NotFinite {
                step,
                u,
                quantity,
                value,
            } => write!(
                f,
                "increment {step} (u = {u}) made {quantity} = {value}, not a finite number: the run stops there, keeping the increments before it (a defect of soilcut, not of the case: please report it with the case)"
            ),
            StepError::TravelReached { steps } => write!(
                f,
                "the case's travel has been reached ({steps} increments): no step beyond run.travel; advance_to(x) goes further"
            ),
        }
    }
}

impl std::error::Error for StepError {}

/// A point of the free surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfilePoint {
    /// x, physical (the face at x = u for a vertical blade).
    pub x: f64,
    /// y: surface height (0: undisturbed ground).
    pub y: f64,
    /// ut: shear accumulated by the soil at the node.
    pub accumulated_shear: f64,
    /// γ of the node's soil column.
    pub unit_weight: f64,
    /// Crest height of the side heaps beside the blade's path (0 in plane
    /// strain), above the original ground.
    pub ridge_height: f64,
}
