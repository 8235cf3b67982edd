//! A tool of any shape on any motion (docs/model.md §21): a rigid profile
//! in plane strain, a polyline in the tool's own frame from its cutting
//! edge (`profile`, made from a few parameters by `shapes`), its reference
//! point (the pivot, about which the moment is taken), and the motion of
//! its pose, a piecewise-linear path of (x, y, rotation) in a progress s
//! (`motion`).
//!
//! The mechanism of today's blade takes the tools that reduce to it
//! (`straight`, (M55)): a straight profile translating forward at a
//! constant rotation is a blade of that rake along a depth path, its
//! pivot a fixed offset from the cutting edge, about which `moment`
//! takes the face force at a third of its contact (`moment`, (M56)). Every
//! other tool is refused by name until its mechanism (the face it takes,
//! the soil it carries) is built.

mod moment;
pub(crate) mod motion;
mod profile;
mod shapes;
mod straight;

pub use moment::{tool_state, ToolState};
pub use motion::{Motion, Pose};
pub use profile::Profile;
pub use shapes::Shape;
pub use straight::StraightCut;

/// A rigid tool: its shape, its reference point in the shape's frame, and
/// its motion.
#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    /// The shape, whose profile (`Tool::profile`) runs from the cutting edge.
    pub shape: Shape,
    /// The reference point (pivot) in the tool's frame, a length each.
    pub pivot: [f64; 2],
    /// The pose of the pivot along the progress s.
    pub motion: Motion,
}

impl Tool {
    /// The tool's profile (its shape's).
    pub fn profile(&self) -> Result<Profile, crate::case::CaseError> {
        self.shape.profile()
    }
}
