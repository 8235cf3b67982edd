//! The two bounds' fields at one instant, side by side: where the upper
//! bound's mechanism shears (beside soilcut's band) and how much of the
//! soil's strength the lower bound's stress field mobilises.

use crate::axes::{axes, titled};
use crate::error::{text, DrawResult};
use crate::render::{save, Picture};
use crate::theme::{self, PAPER};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// One instant's fields, lengths divided by d with x measured from the
/// blade tip, for [`draw_bounds`].
#[derive(Clone, Debug, PartialEq)]
pub struct BoundsFields {
    /// Title of the picture.
    pub title: String,
    /// The mesh's triangles, three (x, y) corners each.
    pub triangles: Vec<[(f64, f64); 3]>,
    /// Per triangle: the upper bound's plastic shear rate (with its edges'
    /// slip spread over it), any unit (drawn relative to its largest
    /// value); NaN where there is no upper bound.
    pub shear: Vec<f64>,
    /// Per triangle: the lower bound's mobilised strength, in [0, 1]; NaN
    /// where there is no lower bound.
    pub mobilised: Vec<f64>,
    /// soilcut's band: the tip and the emergence point.
    pub band: [(f64, f64); 2],
    /// The ground surface, from the face on.
    pub surface: Vec<(f64, f64)>,
    /// The blade face: the tip and where it meets the ground.
    pub face: [(f64, f64); 2],
    /// The x range drawn.
    pub x_range: (f64, f64),
    /// The y range drawn.
    pub y_range: (f64, f64),
}

/// Draws the upper bound's shear rate (left, white to red by the square
/// root of its fraction of the largest, so that a band shows beside the
/// tip's fan) with soilcut's band (dashed) and the lower bound's mobilised
/// strength (right, white to blue), 1600 × 700 px, PNG or SVG by `path`'s
/// extension.
pub fn draw_bounds(fields: &BoundsFields, path: &Path) -> Result<(), PlotError> {
    let n = fields.triangles.len();
    if n == 0 || fields.shear.len() != n || fields.mobilised.len() != n {
        return Err(PlotError::new(
            path,
            "one shear rate and one mobilised strength per triangle",
        ));
    }
    save(fields, path)
}

/// White at 0 to `full` at 1 (clamped); light grey for NaN.
fn shade(value: f64, full: RGBColor) -> RGBColor {
    if !value.is_finite() {
        return RGBColor(225, 225, 225);
    }
    let t = value.clamp(0.0, 1.0);
    let mix = |c: u8| (255.0 - t * (255.0 - f64::from(c))).round() as u8;
    RGBColor(mix(full.0), mix(full.1), mix(full.2))
}

impl BoundsFields {
    fn panel<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        title: &str,
        values: &[f64],
        full: RGBColor,
        band: bool,
    ) -> DrawResult {
        let area = titled(area, title, PAPER.desc)?;
        let mut chart = ChartBuilder::on(&area)
            .margin(15)
            .x_label_area_size(PAPER.desc * 3)
            .y_label_area_size(PAPER.desc * 3)
            .build_cartesian_2d(
                self.x_range.0..self.x_range.1,
                self.y_range.0..self.y_range.1,
            )
            .map_err(text)?;
        axes(&mut chart, "(x − u)/d (–)", "y/d (–)", PAPER)?;
        chart
            .draw_series(
                self.triangles
                    .iter()
                    .zip(values)
                    .map(|(t, &v)| Polygon::new(t.to_vec(), shade(v, full).filled())),
            )
            .map_err(text)?;
        chart
            .draw_series(LineSeries::new(
                self.surface.iter().copied(),
                theme::GROUND_EDGE.stroke_width(2),
            ))
            .map_err(text)?;
        chart
            .draw_series(LineSeries::new(self.face, theme::BLADE.stroke_width(6)))
            .map_err(text)?;
        if band {
            chart
                .draw_series(DashedLineSeries::new(
                    self.band,
                    12,
                    8,
                    BLACK.stroke_width(3),
                ))
                .map_err(text)?;
        }
        Ok(())
    }
}

impl Picture for BoundsFields {
    fn size(&self) -> (u32, u32) {
        (1600, 700)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.title, PAPER.title)?;
        let (left, right) = area.split_horizontally(800);
        let largest = self.shear.iter().copied().fold(0.0, f64::max);
        let shear: Vec<f64> = self
            .shear
            .iter()
            .map(|s| {
                if largest > 0.0 {
                    (s / largest).sqrt()
                } else {
                    *s
                }
            })
            .collect();
        self.panel(
            &left,
            "upper bound: shear rate (red), soilcut's band (dashed)",
            &shear,
            RGBColor(200, 30, 30),
            true,
        )?;
        self.panel(
            &right,
            "lower bound: strength mobilised (blue: at yield)",
            &self.mobilised,
            RGBColor(30, 70, 200),
            false,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shades_run_from_white_to_the_full_colour() {
        let red = RGBColor(200, 30, 30);
        assert_eq!(shade(0.0, red), RGBColor(255, 255, 255));
        assert_eq!(shade(1.0, red), red);
        assert_eq!(shade(7.0, red), red);
        assert_eq!(shade(f64::NAN, red), RGBColor(225, 225, 225));
    }

    fn fields(mobilised: Vec<f64>) -> BoundsFields {
        BoundsFields {
            title: "two triangles".into(),
            triangles: vec![
                [(0.0, -1.0), (1.0, -1.0), (0.0, 0.0)],
                [(1.0, -1.0), (1.0, 0.0), (0.0, 0.0)],
            ],
            shear: vec![1.0, 0.2],
            mobilised,
            surface: vec![(0.0, 0.0), (1.0, 0.0)],
            band: [(0.0, -1.0), (1.0, 0.0)],
            face: [(0.0, -1.0), (0.0, 0.0)],
            x_range: (-0.5, 1.5),
            y_range: (-1.2, 0.3),
        }
    }

    #[test]
    fn draws_the_same_file_twice_and_refuses_missing_values() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.svg"), dir.path().join("b.svg"));
        draw_bounds(&fields(vec![0.5, f64::NAN]), &a).unwrap();
        draw_bounds(&fields(vec![0.5, f64::NAN]), &b).unwrap();
        assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        assert!(draw_bounds(&fields(vec![0.5]), &dir.path().join("c.png")).is_err());
    }
}
