//! Panels of points and lines in a grid under one title: the pictures of
//! parameter studies (sweep, fit, convergence), which plot any quantity
//! against any other.

use crate::error::{text, DrawResult};
use crate::render::{save, Picture};
use crate::theme::{FAMILY, SERIES};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Panel size in pixels.
const PANEL: (u32, u32) = (600, 420);
/// Height of the title band.
const TITLE_HEIGHT: u32 = 50;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SeriesMark {
    /// A dot per point.
    Points,
    /// A line through the points in order.
    Line,
}

/// One set of (x, y) points of a panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend entry (none if empty).
    pub label: String,
    /// The (x, y) points.
    pub points: Vec<(f64, f64)>,
    /// Dots or a line.
    pub mark: SeriesMark,
}

impl Series {
    /// A series drawn as dots.
    pub fn points(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            mark: SeriesMark::Points,
        }
    }

    /// A series drawn as a line.
    pub fn line(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            mark: SeriesMark::Line,
        }
    }
}

/// One chart of a picture.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    /// Label of the x axis.
    pub x_label: String,
    /// Label of the y axis.
    pub y_label: String,
    /// The series drawn in the panel, in legend order.
    pub series: Vec<Series>,
}

/// Draws `panels`, `columns` to a row under `title`, into `path` (PNG or
/// SVG by its extension), each panel 600 × 420 px.
pub fn draw_panels(
    title: &str,
    panels: &[Panel],
    columns: usize,
    path: &Path,
) -> Result<(), PlotError> {
    let columns = columns.clamp(1, panels.len().max(1));
    save(
        &Panels {
            title,
            panels,
            columns,
            rows: panels.len().div_ceil(columns).max(1),
        },
        path,
    )
}

struct Panels<'a> {
    title: &'a str,
    panels: &'a [Panel],
    columns: usize,
    rows: usize,
}

impl Picture for Panels<'_> {
    fn size(&self) -> (u32, u32) {
        (
            PANEL.0 * self.columns as u32,
            PANEL.1 * self.rows as u32 + TITLE_HEIGHT,
        )
    }

    /// Row by row; a last row with fewer panels shares the whole width
    /// among them, so that no panel is left empty.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let (top, body) = root.split_vertically(TITLE_HEIGHT);
        top.titled(self.title, (FAMILY, 26)).map_err(text)?;
        let rows = body.split_evenly((self.rows, 1));
        for (panels, row) in self.panels.chunks(self.columns).zip(&rows) {
            for (panel, area) in panels.iter().zip(&row.split_evenly((1, panels.len()))) {
                draw_panel(panel, area)?;
            }
        }
        Ok(())
    }
}

/// (lo, hi) of `values` with a 5 % margin; a single value gets ±1 (or ±5 %).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 0.0 {
        0.05 * span
    } else if lo != 0.0 {
        0.05 * lo.abs()
    } else {
        1.0
    };
    (lo - pad, hi + pad)
}

fn draw_panel<DB: DrawingBackend>(panel: &Panel, area: &DrawingArea<DB, Shift>) -> DrawResult {
    let all = || panel.series.iter().flat_map(|s| s.points.iter());
    let (x0, x1) = range(all().map(|p| p.0));
    let (y0, y1) = range(all().map(|p| p.1));
    // Counts (levels, runs) across: a tick between them means nothing.
    let whole = all().all(|p| p.0.fract() == 0.0) && x1 - x0 <= 20.0;
    let x_tick = |x: f64| match whole && x.fract().abs() > 1e-9 {
        true => String::new(),
        false => span_tick(x, x1 - x0),
    };
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(78)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(text)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .axis_desc_style((FAMILY, 18))
        .label_style((FAMILY, 14))
        .light_line_style(RGBColor(235, 235, 235))
        .x_labels(6)
        .y_labels(6)
        .x_label_formatter(&|x| x_tick(*x))
        .y_label_formatter(&|y| span_tick(*y, y1 - y0))
        .draw()
        .map_err(text)?;
    let finite = |p: &&(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for (i, s) in panel.series.iter().enumerate() {
        let colour = SERIES[i % SERIES.len()];
        let points: Vec<(f64, f64)> = s.points.iter().filter(finite).copied().collect();
        let drawn = match s.mark {
            SeriesMark::Points => chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
                .map_err(text)?,
            SeriesMark::Line => chart
                .draw_series(LineSeries::new(points, colour.stroke_width(2)))
                .map_err(text)?,
        };
        if !s.label.is_empty() {
            drawn.label(s.label.as_str()).legend(move |(x, y)| {
                PathElement::new([(x, y), (x + 20, y)], colour.stroke_width(3))
            });
        }
    }
    if panel.series.iter().any(|s| !s.label.is_empty()) {
        chart
            .configure_series_labels()
            .label_font((FAMILY, 14))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .position(SeriesLabelPosition::UpperLeft)
            .draw()
            .map_err(text)?;
    }
    Ok(())
}

/// A tick label on an axis spanning `span`: enough decimals to tell ticks
/// apart and no trailing zeros (1, 2.5, not 1.00, 2.50), or scientific
/// notation for very small or large spans.
fn span_tick(value: f64, span: f64) -> String {
    if value.abs() < 1e-9 * span {
        "0".to_string()
    } else if !(1e-3..1e5).contains(&span) {
        format!("{value:.2e}")
    } else {
        let decimals = (2.0 - span.log10().floor()).clamp(0.0, 6.0) as usize;
        let fixed = format!("{value:.decimals$}");
        match fixed.contains('.') {
            true => fixed
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_string(),
            false => fixed,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_fit_the_span() {
        assert_eq!(span_tick(32.5, 10.0), "32.5");
        assert_eq!(span_tick(1.25, 0.5), "1.25");
        assert_eq!(span_tick(2.0, 4.0), "2");
        assert_eq!(span_tick(0.06, 0.07), "0.06");
        assert_eq!(span_tick(2e-15, 4e-15), "2.00e-15");
        assert_eq!(span_tick(1500.0, 2000.0), "1500");
        assert_eq!(span_tick(-1.26e-29, 1e-13), "0");
    }

    /// Three panels two to a row: the third spans the last row, whose right
    /// half is drawn on, not left white.
    #[test]
    fn no_panel_is_left_empty() {
        let panel = |label: &str| Panel {
            x_label: "level".into(),
            y_label: "y".into(),
            series: vec![Series::line(label, vec![(1.0, 1.0), (2.0, 3.0)])],
        };
        let panels = [panel("a"), panel("b"), panel("c")];
        let picture = Panels {
            title: "t",
            panels: &panels,
            columns: 2,
            rows: 2,
        };
        let (w, h) = picture.size();
        let pixels = crate::render::rgb(&picture).unwrap();
        let (w, h) = (w as usize, h as usize);
        let inked = (h * 3 / 4..h)
            .flat_map(|y| (w * 3 / 4..w).map(move |x| (y * w + x) * 3))
            .filter(|&i| pixels[i..i + 3] != [255, 255, 255])
            .count();
        assert!(
            inked > 1000,
            "{inked} pixels drawn in the last row's right half"
        );
    }

    #[test]
    fn draws_a_deterministic_png() {
        let tmp = tempfile::tempdir().unwrap();
        let panels = vec![
            Panel {
                x_label: "φp (°)".into(),
                y_label: "P/(γ0 d²)".into(),
                series: vec![Series::points(
                    "",
                    vec![(30.0, 1.0), (35.0, 2.0), (40.0, f64::NAN)],
                )],
            },
            Panel {
                x_label: "u/d".into(),
                y_label: "force".into(),
                series: vec![
                    Series::line("a", vec![(0.0, 1.0), (1.0, 1.5)]),
                    Series::line("b", vec![(0.0, 1.2)]),
                ],
            },
        ];
        let (a, b) = (tmp.path().join("a.png"), tmp.path().join("b.png"));
        draw_panels("test", &panels, 2, &a).unwrap();
        draw_panels("test", &panels, 2, &b).unwrap();
        let bytes = std::fs::read(&a).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        assert_eq!(bytes, std::fs::read(&b).unwrap());
        assert!(draw_panels("x", &panels, 1, &tmp.path().join("no/such.png")).is_err());
    }
}
