//! Panels of points and lines in a grid under one title: the pictures of
//! parameter studies (sweep, fit, convergence), which plot any quantity
//! against any other.

use crate::error::{text, DrawResult};
use crate::grid::{draw_grid, Cell, DESC, LEGEND, TICK};
use crate::theme::{font, GRID, SERIES};
use crate::PlotError;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

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
/// SVG by its extension), each panel 600 × 450 px, the picture at least
/// 1200 px wide (a single column's panels widen).
pub fn draw_panels(
    title: &str,
    panels: &[Panel],
    columns: usize,
    path: &Path,
) -> Result<(), PlotError> {
    draw_grid(title, panels, columns, path)
}

impl Cell for Panel {
    fn draw_cell<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult {
        draw_panel(self, area)
    }
}

/// (lo, hi) of `values` with a 5 % margin; a single value gets ±1 (or ±5 %).
pub(crate) fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    // Values that differ by round-off only are one value: an axis spanning
    // 10⁻⁹ of them would label every tick alike.
    let span = match hi - lo {
        span if span <= 1e-9 * lo.abs().max(hi.abs()) => 0.0,
        span => span,
    };
    let (lo, hi) = if span == 0.0 { (lo, lo) } else { (lo, hi) };
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
    let (scale, y_label) = y_scale(panel);
    let scaled = Panel {
        x_label: panel.x_label.clone(),
        y_label,
        series: panel
            .series
            .iter()
            .map(|s| Series {
                points: s.points.iter().map(|p| (p.0, p.1 * scale)).collect(),
                ..s.clone()
            })
            .collect(),
    };
    let panel = &scaled;
    let all = || panel.series.iter().flat_map(|s| s.points.iter());
    let (x0, x1) = range(all().map(|p| p.0));
    let (y0, y1) = range(all().map(|p| p.1));
    let labelled = panel.series.iter().any(|s| !s.label.is_empty());
    let legend = legend_box(panel, area);
    let ((x1, y1), corner) = match labelled {
        true => legend_room(panel, (x0, x1), (y0, y1), legend),
        false => ((x1, y1), SeriesLabelPosition::UpperLeft),
    };
    // Counts (levels, runs) across: a tick between them means nothing.
    let whole = all().all(|p| p.0.fract() == 0.0) && x1 - x0 <= 20.0;
    let x_tick = |x: f64| match whole && x.fract().abs() > 1e-9 {
        true => String::new(),
        false => span_tick(x, x1 - x0),
    };
    let mut chart = ChartBuilder::on(area)
        .margin(14)
        .margin_right(24)
        .x_label_area_size(DESC * 3)
        .y_label_area_size(DESC * 5 + 10)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(text)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .axis_desc_style(font(DESC))
        .label_style(font(TICK))
        .bold_line_style(GRID)
        .light_line_style(TRANSPARENT)
        // Whole numbers only: a tick (and its grid line) at each of them,
        // none between.
        .x_labels(match whole {
            true => ((x1 - x0).floor() as usize + 1).clamp(2, 6),
            false => 6,
        })
        .y_labels(6)
        .x_label_formatter(&|x| x_tick(*x))
        .y_label_formatter(&|y| span_tick(*y, y1 - y0))
        .draw()
        .map_err(text)?;
    for (i, s) in panel.series.iter().enumerate() {
        let look = Look {
            colour: SERIES[i % SERIES.len()],
            shape: i / SERIES.len(),
        };
        draw_series(&mut chart, s, look)?;
    }
    if labelled {
        chart
            .configure_series_labels()
            .label_font(font(LEGEND))
            .background_style(WHITE.mix(0.9))
            .border_style(RGBColor(180, 180, 180))
            .position(corner)
            .draw()
            .map_err(text)?;
    }
    Ok(())
}

type PanelChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The power of ten a panel's y values are shown in, with the axis label
/// saying so: values below 10⁻³ or from 10⁵ on read as 1.07 (×10⁻¹⁵), and
/// plotters' ticks on spans of 10⁻¹⁵ fell outside the panel.
fn y_scale(panel: &Panel) -> (f64, String) {
    let largest = panel
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1.abs()))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    if largest == 0.0 || (1e-3..1e5).contains(&largest) {
        return (1.0, panel.y_label.clone());
    }
    let exponent = largest.log10().floor() as i32;
    let label = match panel.y_label.rsplit_once(" (") {
        Some((name, unit)) => format!("{name} (×10{} {unit}", superscript(exponent)),
        None => format!("{} (×10{})", panel.y_label, superscript(exponent)),
    };
    (10f64.powi(-exponent), label.replace(" –)", ")"))
}

fn superscript(n: i32) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => "⁰¹²³⁴⁵⁶⁷⁸⁹"
                .chars()
                .nth(d.to_digit(10).unwrap_or(0) as usize)
                .unwrap_or(d),
        })
        .collect()
}

/// A series' colour, and its dots' shape: a circle for the palette's
/// first round of series, then a triangle, a square and a cross, so that
/// more series than colours (a study's fifteen keys) stay apart.
#[derive(Clone, Copy)]
struct Look {
    colour: RGBColor,
    shape: usize,
}

/// The styles of a dot's four shapes (circle, triangle, square, cross),
/// all transparent but `look`'s own (or all, for no dot).
fn shape_styles(look: Option<Look>) -> [ShapeStyle; 4] {
    let mut styles = [TRANSPARENT.filled(); 4];
    if let Some(look) = look {
        styles[look.shape % 4] = match look.shape % 4 {
            3 => look.colour.stroke_width(2),
            _ => look.colour.filled(),
        };
    }
    styles
}

/// A dot of the shape `styles` draws at `$at` (a data point or a pixel of
/// the legend), `$r` pixels: one element type for every shape, so that
/// the series and its legend entry are drawn alike.
macro_rules! marker {
    ($at:expr, $styles:expr, $r:expr) => {{
        let [circle, triangle, square, cross] = $styles;
        EmptyElement::at($at)
            + Circle::new((0, 0), $r, circle)
            + TriangleMarker::new((0, 0), $r + 1, triangle)
            + Rectangle::new([(-$r, -$r), ($r, $r)], square)
            + Cross::new((0, 0), $r, cross)
    }};
}

/// A series: dots (smaller where there are many), or a line broken where a value is missing (a lone
/// point between gaps is a dot, which a line of one point would not
/// show); its legend entry drawn as the series is.
fn draw_series<'a, DB: DrawingBackend + 'a>(
    chart: &mut PanelChart<'a, DB>,
    s: &Series,
    look: Look,
) -> DrawResult {
    let colour = look.colour;
    // Many dots shrink, so that a line drawn over them (a fit over the
    // measured points) stays visible.
    let radius = if s.points.len() > 60 { 2 } else { 4 };
    let dots = shape_styles(Some(look));
    for run in finite_runs(&s.points) {
        match (s.mark, run) {
            (SeriesMark::Points, _) | (SeriesMark::Line, [_]) => {
                chart
                    .draw_series(run.iter().map(|&p| marker!(p, dots, radius)))
                    .map_err(text)?;
            }
            (SeriesMark::Line, _) => {
                let line = LineSeries::new(run.iter().copied(), colour.stroke_width(2));
                chart.draw_series(line).map_err(text)?;
            }
        }
    }
    if !s.label.is_empty() {
        // One element type for both marks: the one not drawn is transparent.
        let (dot, line) = match s.mark {
            SeriesMark::Points => (dots, TRANSPARENT.stroke_width(0)),
            SeriesMark::Line => (shape_styles(None), colour.stroke_width(3)),
        };
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())
            .map_err(text)?
            .label(s.label.as_str())
            .legend(move |(x, y)| {
                marker!((x + 10, y), dot, 5) + PathElement::new([(-10, 0), (10, 0)], line)
            });
    }
    Ok(())
}

/// The runs of consecutive finite points: a line is not drawn across a
/// missing value.
fn finite_runs(points: &[(f64, f64)]) -> impl Iterator<Item = &[(f64, f64)]> {
    points
        .split(|p| !(p.0.is_finite() && p.1.is_finite()))
        .filter(|run| !run.is_empty())
}

/// The legend's size as fractions of the plotting area (estimated from
/// its text).
fn legend_box<DB: DrawingBackend>(panel: &Panel, area: &DrawingArea<DB, Shift>) -> (f64, f64) {
    let labels: Vec<&str> = panel
        .series
        .iter()
        .filter(|s| !s.label.is_empty())
        .map(|s| s.label.as_str())
        .collect();
    let widest = labels
        .iter()
        .map(|l| area.estimate_text_size(l, &font(LEGEND)).map_or(0, |b| b.0))
        .max()
        .unwrap_or(0);
    let (w, h) = area.dim_in_pixel();
    let plot_w = f64::from(w.saturating_sub(DESC * 4 + 50).max(1));
    let plot_h = f64::from(h.saturating_sub(DESC * 3 + 30).max(1));
    let box_w = f64::from(widest + 50);
    let box_h = f64::from(LEGEND * 3 / 2) * labels.len() as f64 + 14.0;
    (box_w / plot_w, box_h / plot_h)
}

/// The ends (x1, y1) of the axes and the legend's corner: the corner
/// whose box covers no point of the series if one does; else the y axis is
/// raised until the box fits above every point, in an upper corner (a
/// legend over the start of a curve hid it, issue 41), or, for a box too
/// tall for that (many series), the x axis is widened until it fits beside
/// them, on the right.
fn legend_room(
    panel: &Panel,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    (w, h): (f64, f64),
) -> ((f64, f64), SeriesLabelPosition) {
    let (corner, covered) = legend_corner(panel, (x0, x1), (y0, y1), (w, h));
    if covered == 0 {
        return ((x1, y1), corner);
    }
    // A gap of 2 % of the widened axis between the points and the box.
    if h < 0.5 {
        let raised = y0 + (y1 - y0) / (0.98 - h);
        let (corner, _) = legend_corner(panel, (x0, x1), (y0, raised), (w, h));
        return ((x1, raised), corner);
    }
    if w < 0.5 {
        let widened = x0 + (x1 - x0) / (0.98 - w);
        return ((widened, y1), SeriesLabelPosition::UpperRight);
    }
    ((x1, y1), corner)
}

/// The corner of the plotting area whose legend box of `size` (fractions
/// of the area) covers the fewest points of the series, lines followed
/// between their points, and how many it covers: the legend hides as
/// little as it can.
fn legend_corner(
    panel: &Panel,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    (w, h): (f64, f64),
) -> (SeriesLabelPosition, usize) {
    let scaled = |p: &(f64, f64)| ((p.0 - x0) / (x1 - x0), (p.1 - y0) / (y1 - y0));
    let mut samples = Vec::new();
    for s in &panel.series {
        for run in finite_runs(&s.points) {
            samples.push(scaled(&run[0]));
            for pair in run.windows(2) {
                let (a, b) = (scaled(&pair[0]), scaled(&pair[1]));
                samples.extend((1..=16).map(|k| {
                    let t = f64::from(k) / 16.0;
                    (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
                }));
            }
        }
    }
    let corners = [
        (SeriesLabelPosition::UpperLeft, (0.0, 1.0 - h)),
        (SeriesLabelPosition::UpperRight, (1.0 - w, 1.0 - h)),
        (SeriesLabelPosition::LowerRight, (1.0 - w, 0.0)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.0)),
    ];
    let covered = |(left, bottom): (f64, f64)| {
        samples
            .iter()
            .filter(|p| p.0 >= left && p.0 <= left + w && p.1 >= bottom && p.1 <= bottom + h)
            .count()
    };
    corners
        .into_iter()
        .map(|(corner, at)| (corner, covered(at)))
        .min_by_key(|&(_, n)| n)
        .unwrap_or((SeriesLabelPosition::UpperLeft, 0))
}

/// A tick label on an axis spanning `span`: enough decimals to tell ticks
/// apart and no trailing zeros (1, 2.5, not 1.00, 2.50), or scientific
/// notation, with as many digits, for very small or large values.
pub(crate) fn span_tick(value: f64, span: f64) -> String {
    let magnitude = value.abs().max(span);
    if value.abs() < 1e-9 * span {
        "0".to_string()
    } else if !(1e-3..1e5).contains(&magnitude) {
        let digits = ((magnitude / span).log10().ceil() + 1.0).clamp(2.0, 12.0) as usize;
        format!("{value:.digits$e}")
    } else {
        let decimals = (2.0 - span.log10().floor()).clamp(0.0, 12.0) as usize;
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
    use crate::grid::Grid;
    use crate::render::Picture;

    /// A panel of `series` on axes labelled x and y.
    fn xy(series: Vec<Series>) -> Panel {
        Panel {
            x_label: "x".into(),
            y_label: "y".into(),
            series,
        }
    }

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

    #[test]
    fn ticks_of_a_narrow_span_differ() {
        let labels: Vec<String> = [1.3201, 1.3202, 1.3203]
            .iter()
            .map(|&v| span_tick(v, 0.0004))
            .collect();
        assert_eq!(labels, ["1.3201", "1.3202", "1.3203"]);
        let small: Vec<String> = [1.0e-7, 1.1e-7]
            .iter()
            .map(|&v| span_tick(v, 2e-8))
            .collect();
        assert_ne!(small[0], small[1]);
        // Round-off differences are one value, drawn with a margin around it.
        let (lo, hi) = range([1.32, 1.32 + 2e-16].into_iter());
        assert!(hi - lo > 0.1, "{lo} {hi}");
    }

    #[test]
    fn tiny_values_are_shown_in_a_power_of_ten_named_on_the_axis() {
        let panel = Panel {
            x_label: "x".into(),
            y_label: "mass drift Δm/m₀ (–)".into(),
            series: vec![Series::points("", vec![(1.0, -1.07e-15), (2.0, 3e-17)])],
        };
        let (scale, label) = y_scale(&panel);
        assert_eq!(scale, 1e15);
        assert_eq!(label, "mass drift Δm/m₀ (×10⁻¹⁵)");
        let plain = Panel {
            y_label: "P (γ·length²)".into(),
            series: vec![Series::points("", vec![(1.0, 3.0)])],
            ..panel
        };
        assert_eq!(y_scale(&plain), (1.0, "P (γ·length²)".to_string()));
    }

    #[test]
    fn a_line_breaks_at_a_missing_value() {
        let p = [
            (0.0, 1.0),
            (1.0, f64::NAN),
            (2.0, 3.0),
            (3.0, 4.0),
            (4.0, f64::NAN),
        ];
        let runs: Vec<&[(f64, f64)]> = finite_runs(&p).collect();
        assert_eq!(runs, [&p[0..1], &p[2..4]]);
    }

    #[test]
    fn the_legend_goes_where_it_covers_the_fewest_points() {
        let panel = |points: Vec<(f64, f64)>| xy(vec![Series::line("a", points)]);
        // A line starting high at the left: not the upper left corner.
        let falling = panel(vec![(0.0, 10.0), (10.0, 0.0)]);
        let (corner, _) = legend_corner(&falling, (0.0, 10.0), (0.0, 10.0), (0.4, 0.2));
        assert!(
            matches!(corner, SeriesLabelPosition::UpperRight),
            "{corner:?}"
        );
        let rising = panel(vec![(0.0, 0.0), (10.0, 10.0)]);
        let (corner, _) = legend_corner(&rising, (0.0, 10.0), (0.0, 10.0), (0.4, 0.2));
        assert!(
            matches!(corner, SeriesLabelPosition::UpperLeft),
            "{corner:?}"
        );
    }

    #[test]
    fn where_every_corner_holds_a_curve_the_axis_makes_room_for_the_legend() {
        // Five curves fanning out from both ends, as converge's quantities
        // do: every corner of the box holds points until the axis rises.
        let series = (0..5)
            .map(|i| {
                let a = f64::from(i) * 2.5;
                Series::line("q", vec![(0.0, a), (5.0, 10.0 - a), (10.0, a)])
            })
            .collect();
        let panel = xy(series);
        let (_, covered) = legend_corner(&panel, (0.0, 10.0), (0.0, 10.0), (0.4, 0.3));
        assert!(covered > 0, "the test needs crowded corners");
        let ((_, top), corner) = legend_room(&panel, (0.0, 10.0), (0.0, 10.0), (0.4, 0.3));
        assert!(top > 10.0, "the axis rose: {top}");
        let (again, covered) = legend_corner(&panel, (0.0, 10.0), (0.0, top), (0.4, 0.3));
        assert_eq!(covered, 0, "the legend covers no point");
        assert_eq!(format!("{again:?}"), format!("{corner:?}"));
    }

    #[test]
    fn a_legend_too_tall_to_rise_above_the_points_goes_beside_them() {
        // Fifteen keys' dots, as a Morris panel's, over the whole panel: a
        // box of 0.7 of its height covers some wherever it sits.
        let series = (0..15)
            .map(|i| {
                let v = f64::from(i) * 10.0 / 14.0;
                Series::points("key", vec![(v, v), (10.0 - v, v)])
            })
            .collect();
        let panel = xy(series);
        let (_, covered) = legend_corner(&panel, (0.0, 10.0), (0.0, 10.0), (0.3, 0.7));
        assert!(covered > 0, "the test needs crowded corners");
        let ((right, top), _) = legend_room(&panel, (0.0, 10.0), (0.0, 10.0), (0.3, 0.7));
        assert_eq!(top, 10.0, "no rise would be enough");
        assert!(right > 10.0, "the x axis widened: {right}");
        let (_, covered) = legend_corner(&panel, (0.0, right), (0.0, 10.0), (0.3, 0.7));
        assert_eq!(covered, 0, "the legend covers no point");
    }

    /// A single column is as wide as the run's pictures, and the title
    /// sits clear of the top edge.
    #[test]
    fn one_column_is_full_width_and_the_title_is_clear_of_the_top() {
        let panels = [xy(vec![Series::points("", vec![(1.0, 1.0), (2.0, 3.0)])])];
        let picture = Grid::new("A title", &panels, 1);
        let (w, _) = picture.size();
        assert_eq!(w, 1200);
        let pixels = crate::render::rgb(&picture).unwrap();
        let row = w as usize * 3;
        let first_inked = pixels.chunks(row).position(|r| r.iter().any(|&c| c != 255));
        assert!(first_inked.is_some_and(|y| y >= 10), "{first_inked:?}");
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
        let picture = Grid::new("t", &panels, 2);
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
