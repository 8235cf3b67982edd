//! Fonts, sizes, colours and axes shared by every picture.

use crate::render::{text, DrawResult};
use crate::{RunData, SurfacePoint};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::sync::Once;

/// The font family every picture uses; the bundled DejaVu Sans is
/// registered under it, and SVG viewers substitute their own sans-serif.
pub const FAMILY: &str = "sans-serif";

pub(crate) static FONT: &[u8] = include_bytes!("../fonts/DejaVuSans.ttf");

/// Registers the bundled font (once per process).
pub fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        if plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_err() {
            panic!("the bundled DejaVu Sans is a valid font");
        }
    });
}

/// Text sizes in pixels for one picture size.
#[derive(Clone, Copy, Debug)]
pub struct Sizes {
    pub title: u32,
    /// Axis descriptions and legend entries.
    pub desc: u32,
    /// Tick labels.
    pub tick: u32,
    /// Curve width.
    pub line: u32,
}

/// For the 1200 px wide pictures (8 in at 150 dpi): 30/26/22 px ≈ 14/12.5/10.5 pt.
pub const PAPER: Sizes = Sizes {
    title: 30,
    desc: 26,
    tick: 22,
    line: 3,
};

/// For the animation frames.
pub const SMALL: Sizes = Sizes {
    title: 20,
    desc: 18,
    tick: 15,
    line: 2,
};

pub const GRID: RGBColor = RGBColor(215, 215, 215);
pub const GROUND: RGBColor = RGBColor(236, 226, 202);
pub const GROUND_EDGE: RGBColor = RGBColor(110, 90, 60);
pub const BLADE: RGBColor = RGBColor(70, 70, 70);
pub const CURVE: RGBColor = RGBColor(31, 119, 180);
pub const SHEAR: RGBColor = RGBColor(160, 60, 40);
/// The side heaps' crest beside a blade of finite width.
pub const RIDGE: RGBColor = RGBColor(60, 110, 170);

/// Distinct colours for overlaid curves (Tableau 10).
pub const SERIES: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

/// The viridis colour map at t ∈ [0, 1], stopped at 0.85 so that the
/// lightest colour stays visible on the ground's fill.
pub fn viridis(t: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 44, 122),
        (59, 81, 139),
        (44, 113, 142),
        (33, 144, 141),
        (39, 173, 129),
        (92, 200, 99),
        (170, 220, 50),
        (253, 231, 37),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    } * 0.85;
    let s = t * (STOPS.len() - 1) as f64;
    let i = (s.floor() as usize).min(STOPS.len() - 2);
    let f = s - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

pub fn font(size: u32) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&BLACK)
}

/// Tick labels without trailing zeros: 0.5, 1, 2.25, −0.4.
pub fn tick(v: &f64) -> String {
    let v = if v.abs() < 1e-12 { 0.0 } else { *v };
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.replace('-', "−")
}

/// Height of the title band of a picture whose title font is `size`.
pub fn title_height(size: u32) -> u32 {
    size * 2
}

/// Draws `title` centred in a band of [`title_height`] across the top of
/// `area` (in a smaller font if it would not fit) and returns the area
/// below it.
pub fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    size: u32,
) -> Result<DrawingArea<DB, Shift>, String> {
    let (band, rest) = area.split_vertically(title_height(size));
    let (width, height) = band.dim_in_pixel();
    let mut fitted = size;
    while fitted > 10 {
        let (w, _) = band
            .estimate_text_size(title, &font(fitted))
            .map_err(text)?;
        if w + 40 <= width {
            break;
        }
        fitted -= 1;
    }
    let style = font(fitted).pos(Pos::new(HPos::Center, VPos::Center));
    band.draw(&Text::new(
        title,
        (width as i32 / 2, height as i32 / 2),
        style,
    ))
    .map_err(text)?;
    Ok(rest)
}

pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Grid, ticks and axis descriptions of a chart.
pub fn axes<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    x_desc: &str,
    y_desc: &str,
    sizes: Sizes,
) -> DrawResult {
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let x_labels = (w / (sizes.tick * 5)).clamp(2, 10) as usize;
    let y_labels = (h / (sizes.tick * 2)).clamp(2, 8) as usize;
    let mut mesh = chart.configure_mesh();
    mesh.bold_line_style(GRID)
        .light_line_style(TRANSPARENT)
        .axis_desc_style(font(sizes.desc))
        .label_style(font(sizes.tick))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .x_labels(x_labels)
        .y_labels(y_labels)
        .x_desc(x_desc)
        .y_desc(y_desc);
    mesh.draw().map_err(text)
}

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

/// The largest value of `values`, or `fallback` if none is positive.
pub fn top(values: impl Iterator<Item = f64>, fallback: f64) -> f64 {
    let m = values.filter(|v| v.is_finite()).fold(0.0, f64::max);
    if m > 0.0 {
        m
    } else {
        fallback
    }
}

/// The points of a curve worth drawing at the chart's resolution: the
/// curve simplified (Ramer–Douglas–Peucker) to within half a pixel, so
/// every peak and jump stays while wide strokes stay clean (plotters widens
/// a path by polygonising it, which frays on many tiny segments).
pub fn thin<'a, DB: DrawingBackend + 'a>(
    chart: &Chart<'a, DB>,
    points: &[(f64, f64)],
) -> Vec<(f64, f64)> {
    const TOLERANCE: f64 = 0.5;
    let pixels: Vec<(f64, f64)> = points
        .iter()
        .map(|p| {
            let (x, y) = chart.backend_coord(p);
            (f64::from(x), f64::from(y))
        })
        .collect();
    if points.len() < 3 {
        return points.to_vec();
    }
    let mut keep = vec![false; points.len()];
    keep[0] = true;
    keep[points.len() - 1] = true;
    let mut stack = vec![(0, points.len() - 1)];
    while let Some((a, b)) = stack.pop() {
        let (pa, pb) = (pixels[a], pixels[b]);
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        let length = dx.hypot(dy);
        let distance = |p: (f64, f64)| {
            if length == 0.0 {
                (p.0 - pa.0).hypot(p.1 - pa.1)
            } else {
                ((p.0 - pa.0) * dy - (p.1 - pa.1) * dx).abs() / length
            }
        };
        let far = (a + 1..b)
            .map(|i| (i, distance(pixels[i])))
            .fold((a, 0.0), |m, c| if c.1 > m.1 { c } else { m });
        if far.1 > TOLERANCE {
            keep[far.0] = true;
            stack.push((a, far.0));
            stack.push((far.0, b));
        }
    }
    let mut out = Vec::new();
    let mut last = None;
    for (i, p) in points.iter().enumerate() {
        if keep[i] && last != Some(pixels[i]) {
            out.push(*p);
            last = Some(pixels[i]);
        }
    }
    out
}

/// Whether `DB` draws vectors (SVG), where wide strokes are exact; on
/// bitmaps plotters widens a path by polygonising it, which spikes at
/// sharp turns, so there a wide curve is drawn as one-pixel paths side by side.
pub fn is_vector<DB: DrawingBackend>() -> bool {
    std::any::type_name::<DB>().contains("SVGBackend")
}

/// Draws `points` as a curve of `color` and `width`, thinned by [`thin`].
pub fn curve<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    points: &[(f64, f64)],
    color: RGBColor,
    width: u32,
) -> Result<(), String> {
    let thinned = thin(chart, points);
    if is_vector::<DB>() || width <= 1 {
        chart
            .draw_series(LineSeries::new(thinned, color.stroke_width(width)))
            .map_err(text)?;
        return Ok(());
    }
    let pixels: Vec<(i32, i32)> = thinned.iter().map(|p| chart.backend_coord(p)).collect();
    let area = chart.plotting_area().strip_coord_spec();
    let (x0, y0) = chart.plotting_area().get_base_pixel();
    let w = width as i32;
    for dx in -(w - 1) / 2..=w / 2 {
        for dy in -(w - 1) / 2..=w / 2 {
            if w >= 3 && dx.abs() + dy.abs() > w / 2 + (w - 1) / 2 {
                continue;
            }
            let path: Vec<(i32, i32)> = pixels
                .iter()
                .map(|&(x, y)| (x - x0 + dx, y - y0 + dy))
                .collect();
            area.draw(&PathElement::new(path, color.stroke_width(1)))
                .map_err(text)?;
        }
    }
    Ok(())
}

/// Draws `points` as dots of `radius` pixels, one per pixel they fall on.
pub fn dots<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    points: &[(f64, f64)],
    color: RGBColor,
    radius: u32,
) -> Result<(), String> {
    let mut seen = std::collections::HashSet::new();
    let unique: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| seen.insert(chart.backend_coord(p)))
        .copied()
        .collect();
    chart
        .draw_series(
            unique
                .into_iter()
                .map(|p| Circle::new(p, radius, color.filled())),
        )
        .map_err(text)?;
    Ok(())
}

/// The smallest of 1, 2, 2.5, 5 × 10ⁿ at least `v` (a round axis end).
pub fn round_up(v: f64) -> f64 {
    if !(v.is_finite() && v > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(v.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&c| c >= v * (1.0 - 1e-9))
        .unwrap_or(10.0 * p)
}

/// How a legend entry is drawn.
#[derive(Clone, Copy, Debug)]
pub enum Mark {
    Line(RGBColor),
    /// A line of this width, px.
    Stroke(RGBColor, u32),
    Dashed(RGBColor),
    Block(RGBColor),
    Dot(RGBColor),
}

/// A legend laid out in rows across a picture, above its charts (never
/// over data): entries left to right, wrapping when a row is full, each
/// row centred.
pub struct Legend {
    rows: Vec<Vec<(String, Mark, u32)>>,
    sizes: Sizes,
}

const MARK: u32 = 50;
const GAP: u32 = 40;

impl Legend {
    pub fn new(entries: Vec<(String, Mark)>, width: u32, sizes: Sizes) -> Legend {
        register_font();
        let mut rows: Vec<Vec<(String, Mark, u32)>> = vec![Vec::new()];
        let mut used = 0;
        for (label, mark) in entries {
            let text_w = font(sizes.desc).font.box_size(&label).map_or(0, |b| b.0);
            let w = MARK + 10 + text_w;
            let row = rows.last_mut().expect("a row");
            if !row.is_empty() && used + GAP + w > width {
                rows.push(Vec::new());
                used = 0;
            }
            let row = rows.last_mut().expect("a row");
            used += if row.is_empty() { w } else { GAP + w };
            row.push((label, mark, w));
        }
        Legend { rows, sizes }
    }

    fn row_height(&self) -> u32 {
        self.sizes.desc * 3 / 2
    }

    pub fn height(&self) -> u32 {
        self.rows.len() as u32 * self.row_height() + self.sizes.desc / 2
    }

    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult {
        let width = area.dim_in_pixel().0 as i32;
        let line = self.sizes.line;
        for (r, row) in self.rows.iter().enumerate() {
            let total: u32 = row.iter().map(|e| e.2).sum::<u32>() + GAP * (row.len() as u32 - 1);
            let mut x = (width - total as i32) / 2;
            let y = (r as u32 * self.row_height() + self.row_height() / 2) as i32;
            for (label, mark, w) in row {
                let m = MARK as i32;
                match *mark {
                    Mark::Line(c) => area.draw(&PathElement::new(
                        vec![(x, y), (x + m, y)],
                        c.stroke_width(line + 1),
                    )),
                    Mark::Stroke(c, width) => area.draw(&PathElement::new(
                        vec![(x, y), (x + m, y)],
                        c.stroke_width(width),
                    )),
                    Mark::Dashed(c) => (0..4).try_for_each(|k| {
                        let x0 = x + k * m / 4;
                        area.draw(&PathElement::new(
                            vec![(x0, y), (x0 + m / 6, y)],
                            c.stroke_width(1),
                        ))
                    }),
                    Mark::Block(c) => {
                        area.draw(&Rectangle::new([(x, y - 8), (x + m, y + 8)], c.filled()))
                    }
                    Mark::Dot(c) => area.draw(&Circle::new((x + m / 2, y), 5, c.filled())),
                }
                .map_err(text)?;
                let style = font(self.sizes.desc).pos(Pos::new(HPos::Left, VPos::Center));
                area.draw(&Text::new(label.as_str(), (x + m + 10, y), style))
                    .map_err(text)?;
                x += *w as i32 + GAP as i32;
            }
        }
        Ok(())
    }
}
