//! Horizontal bars by category, in a grid of panels: a sensitivity
//! study's indices with their intervals, and its tornado of one-at-a-time
//! ranges. The categories (keys) run down the y axis, where their names
//! have room.

use crate::error::{text, DrawResult};
use crate::grid::{draw_grid, Cell, DESC, LEGEND, TICK};
use crate::panels::{range, span_tick};
use crate::theme::{font, GRID, SERIES};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// One bar: from the panel's origin to `value`, with a whisker from `low`
/// to `high` where both are finite (NaN `value`: no bar).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bar {
    /// Where the bar ends.
    pub value: f64,
    /// The whisker's lower end (NaN: none).
    pub low: f64,
    /// The whisker's upper end (NaN: none).
    pub high: f64,
}

impl Bar {
    /// A bar without a whisker.
    pub fn plain(value: f64) -> Self {
        Bar {
            value,
            low: f64::NAN,
            high: f64::NAN,
        }
    }
}

/// Bars of one colour, one a category, in the categories' order.
#[derive(Clone, Debug, PartialEq)]
pub struct BarSeries {
    /// Legend entry.
    pub label: String,
    /// One bar a category.
    pub bars: Vec<Bar>,
}

/// One chart of bars: the categories from the top down, each category's
/// bars side by side (one of each series), all from `origin`.
#[derive(Clone, Debug, PartialEq)]
pub struct BarPanel {
    /// Label of the x axis (the bars' quantity and unit).
    pub x_label: String,
    /// The categories' names, from the top.
    pub categories: Vec<String>,
    /// The series, in legend order.
    pub series: Vec<BarSeries>,
    /// Where every bar starts (0 for indices; a tornado's case value),
    /// drawn as a vertical line.
    pub origin: f64,
    /// The origin line's legend entry (none if empty).
    pub origin_label: String,
}

/// Draws `panels`, `columns` to a row under `title`, into `path` (PNG or
/// SVG by its extension), the panels' size as [`crate::draw_panels`]'.
pub fn draw_bars(
    title: &str,
    panels: &[BarPanel],
    columns: usize,
    path: &Path,
) -> Result<(), PlotError> {
    draw_grid(title, panels, columns, path)
}

impl Cell for BarPanel {
    fn draw_cell<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult {
        draw_bar_panel(self, area)
    }
}

/// Share of a category's height its bars fill (the rest parts the
/// categories).
const BAND: f64 = 0.8;

fn draw_bar_panel<DB: DrawingBackend>(
    panel: &BarPanel,
    area: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let n = panel.categories.len().max(1);
    let ends = panel
        .series
        .iter()
        .flat_map(|s| s.bars.iter().flat_map(|b| [b.value, b.low, b.high]));
    let (x0, x1) = range(ends.chain([panel.origin]));
    let legend = legend_share(panel, area);
    // The legend stands at the upper right, in room added beyond the bars.
    let x1 = x0 + (x1 - x0) / (1.0 - legend).max(0.3);
    let names = panel.categories.iter();
    let widest = names
        .map(|c| area.estimate_text_size(c, &font(TICK)).map_or(0, |b| b.0))
        .max()
        .unwrap_or(0);
    let top = n as f64 - 0.5;
    let mut chart = ChartBuilder::on(area)
        .margin(14)
        .margin_right(24)
        .x_label_area_size(DESC * 3)
        .y_label_area_size(widest + 16)
        .build_cartesian_2d(x0..x1, -0.5..top)
        .map_err(text)?;
    // Category i is drawn at y = n − 1 − i (the first on top); labels are
    // asked for at every half, and only the whole ones named.
    let name = |y: &f64| {
        let i = top - 0.5 - y.round();
        let whole = (y - y.round()).abs() < 1e-9 && (0.0..n as f64).contains(&i);
        match whole {
            true => panel
                .categories
                .get(i as usize)
                .cloned()
                .unwrap_or_default(),
            false => String::new(),
        }
    };
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .axis_desc_style(font(DESC))
        .label_style(font(TICK))
        .bold_line_style(GRID)
        .light_line_style(TRANSPARENT)
        .disable_y_mesh()
        .x_labels(6)
        .y_labels(2 * n + 1)
        .x_label_formatter(&|x| span_tick(*x, x1 - x0))
        .y_label_formatter(&name)
        .draw()
        .map_err(text)?;
    let origin = [(panel.origin, -0.5), (panel.origin, top)];
    let line = chart
        .draw_series(std::iter::once(PathElement::new(
            origin,
            BLACK.stroke_width(2),
        )))
        .map_err(text)?;
    if !panel.origin_label.is_empty() {
        line.label(panel.origin_label.as_str()).legend(|(x, y)| {
            PathElement::new([(x + 10, y - 8), (x + 10, y + 8)], BLACK.stroke_width(2))
        });
    }
    let height = BAND / panel.series.len().max(1) as f64;
    for (j, series) in panel.series.iter().enumerate() {
        let colour = SERIES[j % SERIES.len()];
        // The series' row within each category, the first on top.
        let row = |i: usize| (n - 1 - i) as f64 + BAND / 2.0 - height * (j as f64 + 0.5);
        draw_series_bars(&mut chart, series, panel.origin, height, &row, colour)?;
    }
    chart
        .configure_series_labels()
        .label_font(font(LEGEND))
        .background_style(WHITE.mix(0.9))
        .border_style(RGBColor(180, 180, 180))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(text)
}

type BarChart<'a, DB> = crate::axes::Chart<'a, DB>;

/// One series' bars, each at height `row(i)` of its category i, and their
/// whiskers; its legend entry a box of its colour.
fn draw_series_bars<'a, DB: DrawingBackend + 'a>(
    chart: &mut BarChart<'a, DB>,
    series: &BarSeries,
    origin: f64,
    height: f64,
    row: &dyn Fn(usize) -> f64,
    colour: RGBColor,
) -> DrawResult {
    let half = 0.45 * height;
    let drawn = series
        .bars
        .iter()
        .enumerate()
        .filter(|(_, b)| b.value.is_finite());
    let boxes = drawn.clone().map(|(i, b)| {
        Rectangle::new(
            [(origin, row(i) - half), (b.value, row(i) + half)],
            colour.filled(),
        )
    });
    chart
        .draw_series(boxes)
        .map_err(text)?
        .label(series.label.as_str())
        .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], colour.filled()));
    let whiskers = drawn.filter(|(_, b)| b.low.is_finite() && b.high.is_finite());
    let cap = 0.5 * half;
    for (i, b) in whiskers {
        let y = row(i);
        let lines = [
            vec![(b.low, y), (b.high, y)],
            vec![(b.low, y - cap), (b.low, y + cap)],
            vec![(b.high, y - cap), (b.high, y + cap)],
        ];
        let elements = lines
            .into_iter()
            .map(|l| PathElement::new(l, BLACK.stroke_width(2)));
        chart.draw_series(elements).map_err(text)?;
    }
    Ok(())
}

/// The legend's width as a fraction of the plotting area's (estimated
/// from its text).
fn legend_share<DB: DrawingBackend>(panel: &BarPanel, area: &DrawingArea<DB, Shift>) -> f64 {
    let labels = panel.series.iter().map(|s| s.label.as_str());
    let widest = labels
        .chain([panel.origin_label.as_str()])
        .map(|l| area.estimate_text_size(l, &font(LEGEND)).map_or(0, |b| b.0))
        .max()
        .unwrap_or(0);
    let (w, _) = area.dim_in_pixel();
    f64::from(widest + 60) / f64::from(w.saturating_sub(DESC * 5).max(1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Grid;
    use crate::render::{rgb, Picture};

    fn panel(values: [f64; 2]) -> BarPanel {
        BarPanel {
            x_label: "S1 (–)".into(),
            categories: vec!["soil.friction.peak".into(), "dummy".into()],
            series: vec![BarSeries {
                label: "S1".into(),
                bars: values
                    .iter()
                    .map(|&v| Bar {
                        value: v,
                        low: v - 0.1,
                        high: v + 0.1,
                    })
                    .collect(),
            }],
            origin: 0.0,
            origin_label: String::new(),
        }
    }

    /// The series' colour fills the rows of the categories that have a
    /// bar, the first category on top; a NaN bar draws nothing.
    #[test]
    fn a_category_s_bar_stands_in_its_row() {
        let panels = [panel([0.9, f64::NAN])];
        let picture = Grid::new("t", &panels, 1);
        let (w, h) = picture.size();
        let pixels = rgb(&picture).unwrap();
        let blue = |y: usize| {
            (0..w as usize)
                .filter(|x| {
                    let i = (y * w as usize + x) * 3;
                    pixels[i..i + 3] == [31, 119, 180]
                })
                .count()
        };
        let rows: Vec<usize> = (0..h as usize).filter(|&y| blue(y) > 100).collect();
        assert!(!rows.is_empty());
        let middle = h as usize / 2;
        assert!(
            rows.iter().all(|&y| y < middle),
            "{rows:?} against {middle}"
        );
    }

    #[test]
    fn draws_a_deterministic_png() {
        let tmp = tempfile::tempdir().unwrap();
        let panels = [panel([0.5, 0.02]), panel([-0.1, 0.3])];
        let (a, b) = (tmp.path().join("a.png"), tmp.path().join("b.png"));
        draw_bars("indices", &panels, 2, &a).unwrap();
        draw_bars("indices", &panels, 2, &b).unwrap();
        let bytes = std::fs::read(&a).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        assert_eq!(bytes, std::fs::read(&b).unwrap());
    }
}
