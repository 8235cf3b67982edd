//! The region of ground a run's pictures show, and panels of it drawn to
//! equal scales in x/d and y/d.

use crate::axes::Chart;
use crate::error::text;
use crate::{RunData, SurfacePoint};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The region of a run's ground pictures, in units of the blade depth d.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extent {
    pub x: (f64, f64),
    pub y: (f64, f64),
}

impl Extent {
    /// From 0.25 d behind the blade's start (or behind where an inclined
    /// face meets the ground, if that is farther back) and 0.25 d below its
    /// tip (its deepest, for a blade that follows a depth path) to 0.5 d beyond the farthest ground that any of `surfaces` shows
    /// moved (at least 1.5 d ahead of the blade) and 0.3 d above the highest
    /// surface point there. Long shallow bands of the refined model can
    /// emerge farther ahead, where the ground hardly moves; they are cut at
    /// the right edge.
    pub fn of<'a>(run: &RunData, surfaces: impl IntoIterator<Item = &'a [SurfacePoint]>) -> Self {
        let d = run.depth;
        let surfaces: Vec<&[SurfacePoint]> = surfaces.into_iter().collect();
        let mut x_far = run.history.last().map_or(0.0, |h| h.u) + 1.5 * d;
        for s in &surfaces {
            x_far = x_far.max(disturbed_end(s, d));
        }
        let x_hi = x_far / d + 0.5;
        let mut y_top: f64 = 0.0;
        for s in &surfaces {
            for p in s.iter().filter(|p| p.x / d <= x_hi) {
                y_top = y_top.max(p.y);
            }
        }
        // An inclined face meets the surface behind the tip: keep that
        // ground in view (at the blade's start it lies left of x = 0).
        let x_lo = surfaces
            .iter()
            .filter_map(|s| s.first())
            .fold(-0.25f64, |lo, p| lo.min(p.x / d - 0.25));
        Extent {
            x: (x_lo, x_hi),
            y: (
                (-1.25f64).min(-run.deepest() / d - 0.25),
                (y_top / d + 0.3).max(0.5),
            ),
        }
    }

    pub fn width(&self) -> f64 {
        self.x.1 - self.x.0
    }

    pub fn height(&self) -> f64 {
        self.y.1 - self.y.0
    }
}

/// A panel of ground drawn to equal scales in x/d and y/d: its plotting
/// area is `scale` pixels per d both ways, and `slack` pixels of the width
/// it could use are added to its right margin.
#[derive(Clone, Copy, Debug)]
pub struct GroundPanel {
    pub extent: Extent,
    pub scale: f64,
    pub slack: u32,
    pub margin: u32,
    pub x_labels: u32,
    pub y_labels: u32,
}

impl GroundPanel {
    /// The largest equal scale that fits `extent` into a panel `width`
    /// wide whose plotting area is at most `max_height` tall.
    pub fn new(extent: Extent, width: u32, max_height: f64, sizes: (u32, u32, u32)) -> Self {
        let (margin, x_labels, y_labels) = sizes;
        let available = f64::from(width - 2 * margin - y_labels);
        let scale = (available / extent.width()).min(max_height / extent.height());
        let slack = (available - (scale * extent.width()).floor()) as u32;
        GroundPanel {
            extent,
            scale,
            slack,
            margin,
            x_labels,
            y_labels,
        }
    }

    /// Height of the whole panel in pixels.
    pub fn height(&self) -> u32 {
        2 * self.margin + (self.scale * self.extent.height()).floor() as u32 + self.x_labels
    }

    /// A chart on `area` spanning the extent in x and `y` (the extent's
    /// own y range for the ground; another for a panel sharing the x axis).
    pub fn chart<'b, DB: DrawingBackend>(
        &self,
        area: &'b DrawingArea<DB, Shift>,
        y: (f64, f64),
    ) -> Result<Chart<'b, DB>, String> {
        ChartBuilder::on(area)
            .margin(self.margin)
            .margin_right(self.margin + self.slack)
            .x_label_area_size(self.x_labels)
            .y_label_area_size(self.y_labels)
            .build_cartesian_2d(self.extent.x.0..self.extent.x.1, y.0..y.1)
            .map_err(text)
    }
}

/// x of the last surface node that moved visibly (by more than 10⁻³ d).
pub fn disturbed_end(surface: &[SurfacePoint], d: f64) -> f64 {
    surface
        .iter()
        .rev()
        .find(|p| p.y.abs() > 1e-3 * d)
        .map_or(0.0, |p| p.x)
}
