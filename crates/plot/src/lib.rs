//! soilcut-plot: the pictures of a soilcut run, drawn from plain data.
//!
//! A pure drawing library: it reads nothing from disk and takes a run as
//! [`RunData`] (the command line fills it from a run's output files).
//! Every picture is deterministic: the same data gives byte-identical files.
//!
//! * [`draw_force`]: normalised blade force P/(γ0 d²) against u/d (paper Fig. 5a).
//! * [`draw_beta`]: the slip-line angle β* in degrees against u/d (Fig. 5b).
//! * [`draw_deformation`]: the pattern of deformation (Figs. 4 and 6).
//! * [`draw_animation`]: an animated GIF of the cutting process.
//! * [`draw_compare`]: force and β* of several runs overlaid (Fig. 7).
//! * [`draw_envelope`]: the force of an ensemble's members, its mean and
//!   spread.
//! * [`draw_landscape`]: the force of every candidate band of one increment.
//! * [`draw_landscape_map`]: how near each place comes to the least force,
//!   increment after increment.
//! * [`draw_panels`]: panels of points and lines (parameter studies).
//! * [`draw_bounds`]: the limit-analysis bounds' fields at one instant.
//! * [`draw_bars`]: horizontal bars by category, with intervals
//!   (sensitivity indices, tornado ranges).
//!
//! Lengths are drawn divided by the blade depth d (the case's length unit
//! is not stored with a run), so every axis is dimensionless.
//!
//! Text uses the bundled DejaVu Sans (`fonts/`), never system fonts; the SVG
//! files name the generic family `sans-serif`.

#![warn(missing_docs)]

mod animation;
mod axes;
mod bars;
mod blade;
mod bounds;
mod curves;
mod deformation;
mod envelope;
mod error;
mod grid;
mod ground;
mod landscape;
mod legend;
mod lines;
mod panels;
mod render;
mod theme;
mod typeset;

pub use animation::draw_animation;
pub use bars::{draw_bars, Bar, BarPanel, BarSeries};
pub use bounds::{draw_bounds, BoundsFields};
pub use curves::{draw_beta, draw_compare, draw_force};
pub use deformation::draw_deformation;
pub use envelope::{draw_envelope, Envelope};
pub use error::PlotError;
pub use landscape::{draw_landscape, draw_landscape_map, Landscape, LandscapeMap};
pub use panels::{draw_panels, Panel, Series, SeriesMark};
pub use render::Format;

use std::path::{Path, PathBuf};

/// One increment of a run (a row of `history.csv`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Increment {
    /// Increment number, from 1.
    pub step: usize,
    /// Blade displacement u at which the mechanism was evaluated: the blade
    /// tip was at (u, −`depth`).
    pub u: f64,
    /// P*/(γ0 d²).
    pub force_norm: f64,
    /// β*, degrees.
    pub beta_deg: f64,
    /// Where the slip line (lower band boundary) met the surface.
    pub x_emergence: f64,
    /// y of that point (0: undisturbed ground).
    pub y_emergence: f64,
    /// Depth of the blade tip during the increment (length): the run's
    /// [`RunData::depth`] unless the blade followed a depth path.
    pub depth: f64,
}

/// A node of the ground surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// x of the node, physical (the blade's start at 0).
    pub x: f64,
    /// Height, 0 = undisturbed ground.
    pub y: f64,
    /// Accumulated shear ut (length).
    pub accumulated_shear: f64,
}

/// The ground surface at one moment of the run.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Increments done (0 = flat ground before the first).
    pub step: usize,
    /// Blade position: the tip is at (u, −[`RunData::tip_depth`] (u)).
    pub u: f64,
    /// The surface from the face on (its first point is where the face
    /// meets the surface, behind the tip for an inclined blade).
    pub surface: Vec<SurfacePoint>,
}

/// Everything the pictures of one run need.
#[derive(Clone, Debug, PartialEq)]
pub struct RunData {
    /// The case title, used as the pictures' title and legend entry.
    pub title: String,
    /// Blade depth d (length): the reference depth that lengths are drawn
    /// in units of (the tip's depth in each increment is
    /// [`Increment::depth`]).
    pub depth: f64,
    /// Rake α, degrees: the face's angle from the horizontal on the soil
    /// side (90: vertical; less: the face leans back from the tip).
    pub rake: f64,
    /// Initial unit weight γ0 (to normalise measured forces).
    pub unit_weight: f64,
    /// Shear band width dB (length); 0 draws slip lines (original model).
    pub band_width: f64,
    /// The increments in order.
    pub history: Vec<Increment>,
    /// The final surface from the blade face on.
    pub profile: Vec<SurfacePoint>,
    /// Surfaces during the run, in order (for the animation).
    pub frames: Vec<Frame>,
    /// (x, crest height) of the side heaps beside a blade of finite width,
    /// along the final surface (empty in plane strain).
    pub ridges: Vec<(f64, f64)>,
}

impl Default for RunData {
    /// An empty run of a vertical blade.
    fn default() -> Self {
        RunData {
            title: String::new(),
            depth: 0.0,
            rake: 90.0,
            unit_weight: 0.0,
            band_width: 0.0,
            history: Vec::new(),
            profile: Vec::new(),
            frames: Vec::new(),
            ridges: Vec::new(),
        }
    }
}

impl RunData {
    /// Depth of the blade tip at blade displacement `u`: linear between
    /// the increments' depths, the first one's before them; past the last
    /// increment the last one's trend for at most one increment (the blade
    /// ends one increment beyond its last mechanism), then constant.
    /// [`RunData::depth`] for a run without increments.
    pub fn tip_depth(&self, u: f64) -> f64 {
        let h = &self.history;
        match h.iter().position(|k| k.u > u) {
            Some(0) => h[0].depth,
            Some(k) => {
                let (a, b) = (&h[k - 1], &h[k]);
                a.depth + (b.depth - a.depth) * (u - a.u) / (b.u - a.u)
            }
            None => match h.as_slice() {
                [] => self.depth,
                [.., a, b] if b.depth != a.depth && b.u > a.u => {
                    let run = (u - b.u).min(b.u - a.u);
                    b.depth + (b.depth - a.depth) * run / (b.u - a.u)
                }
                [.., b] => b.depth,
            },
        }
    }

    /// Where the blade ends: one increment beyond the last mechanism.
    pub fn final_position(&self) -> f64 {
        match self.history.as_slice() {
            [] => 0.0,
            [.., b] => b.u + increment(&self.history),
        }
    }

    /// The deepest the tip goes during the run (at least `depth`).
    pub fn deepest(&self) -> f64 {
        let depths = self.history.iter().map(|h| h.depth);
        depths
            .chain([self.tip_depth(self.final_position())])
            .fold(self.depth, f64::max)
    }
}

/// The blade displacement of one increment (0 for fewer than two).
pub(crate) fn increment(history: &[Increment]) -> f64 {
    match history {
        [.., a, b] => b.u - a.u,
        _ => 0.0,
    }
}

/// A measured force-displacement curve: (u, force per unit width), in the
/// case's length unit and γ·length².
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Measured {
    /// Legend entry.
    pub label: String,
    /// (u, force) points.
    pub points: Vec<(f64, f64)>,
}

/// The picture files of one run, written by [`draw_run`] into a folder.
pub const RUN_PICTURES: [&str; 3] = ["force", "beta", "deformation"];

/// Draws `force`, `beta` and `deformation`, each as PNG and SVG, into
/// `dir` (created if needed). Returns the files written.
pub fn draw_run(run: &RunData, dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    std::fs::create_dir_all(dir).map_err(|e| PlotError::new(dir, e))?;
    let mut written = Vec::new();
    type Draw = fn(&RunData, &Path) -> Result<(), PlotError>;
    let pictures: [(&str, Draw); 3] = [
        (RUN_PICTURES[0], draw_force),
        (RUN_PICTURES[1], draw_beta),
        (RUN_PICTURES[2], draw_deformation),
    ];
    for format in [Format::Png, Format::Svg] {
        for (name, draw) in pictures {
            let path = dir.join(format!("{name}.{}", format.extension()));
            draw(run, &path)?;
            written.push(path);
        }
    }
    Ok(written)
}
