//! The pattern of deformation (paper Figs. 4 and 6): ground, blade and the
//! slip lines or shear bands of the run, with the accumulated shear below.

use crate::axes::{axes, round_up, tick, title_height, titled, top, Chart};
use crate::blade::{
    blade_outline, ground_outline, height_at, is_level, is_vertical, slip_start, trench_floor,
};
use crate::error::{text, DrawResult};
use crate::ground::{Extent, GroundPanel};
use crate::legend::{Legend, Mark};
use crate::lines::{curve, thin};
use crate::render::{save, Picture};
use crate::theme::{self, font, viridis, Sizes, PAPER};
use crate::{Increment, PlotError, RunData, SurfacePoint};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// Draws the pattern of deformation of a run. Top panel, to equal scales
/// in x/d and y/d: the ground at the end of the run (filled), the blade at
/// its final position, the initial ground line (dashed) and a readable
/// subset of the chosen slip lines (original model) or shear bands of
/// width dB (refined model, shaded between the lower boundary and the
/// parallel upper one), each where it was when it was active: from the
/// blade tip (u, −t) of its increment (t the tip's depth then, d but for
/// a blade following a depth path) to its emergence point (cut at the right edge, 0.5 d
/// beyond the ground that moved visibly), coloured by u/d (colour bar on
/// the right). The subset is every increment whose emergence point
/// jumped plus 24 evenly spaced ones. Bottom panel, sharing the x axis:
/// the shear ut accumulated by the soil along the final surface, as ut/d.
/// Where the whole ground, to equal scales, is a strip (a long run: bands
/// emerging 20-30 d ahead squash a pile 2 d high into a few pixels), a
/// third panel shows the ground near the blade at the end, to equal scales
/// of its own. PNG or SVG by `path`'s extension, 1200 px wide, as tall as
/// the ground needs.
pub fn draw_deformation(run: &RunData, path: &Path) -> Result<(), PlotError> {
    save(&Deformation::new(run), path)
}

const WIDTH: u32 = 1200;
/// Width of the colour bar column.
const BAR: u32 = 170;
const MARGIN: u32 = 15;
const Y_LABELS: u32 = 110;
const X_LABELS: u32 = 78;
/// Largest height of the ground's plotting area.
const MAX_GROUND: f64 = 650.0;
/// Height of the accumulated shear's plotting area.
const SHEAR: u32 = 220;
/// Evenly spaced slip lines drawn besides those of the jumps.
const EVEN_BANDS: usize = 24;
/// At most this many slip lines of jumps (evenly spaced among them).
const MAX_JUMPS: usize = 40;
/// A ground plotting area lower than this, px, gets the panel near the
/// blade.
const STRIP: f64 = 250.0;
/// Largest height of that panel's plotting area.
const MAX_NEAR: f64 = 420.0;

pub(crate) const X_DESC: &str = "x/d (–)";
pub(crate) const Y_DESC: &str = "y/d (–)";

struct Deformation<'a> {
    run: &'a RunData,
    extent: Extent,
    panel: GroundPanel,
    /// The ground near the blade, where the whole is a strip.
    near: Option<GroundPanel>,
    bands: Vec<&'a Increment>,
}

impl<'a> Deformation<'a> {
    fn new(run: &'a RunData) -> Self {
        let extent = Extent::of(run, [run.profile.as_slice()]);
        let sizes = (MARGIN, X_LABELS, Y_LABELS);
        let panel = GroundPanel::new(extent, WIDTH - BAR, MAX_GROUND, sizes);
        let near = (panel.scale * extent.height() < STRIP)
            .then(|| GroundPanel::new(near_blade(run, extent), WIDTH - BAR, MAX_NEAR, sizes));
        Deformation {
            run,
            extent,
            panel,
            near,
            bands: chosen_bands(&run.history),
        }
    }

    fn ground_height(&self) -> u32 {
        self.panel.height()
    }

    fn near_height(&self) -> u32 {
        self.near.map_or(0, |p| p.height() + NEAR_TITLE)
    }
}

/// Height of the line naming the panel near the blade.
const NEAR_TITLE: u32 = 30;

/// The ground near the blade at the end of the run: from 1 d behind the
/// face to 1 d beyond the pile's toe (the first node ahead of the face
/// back within 0.05 d of the original ground), at least 3 d ahead, within
/// the whole's extent.
fn near_blade(run: &RunData, whole: Extent) -> Extent {
    let d = run.depth;
    let face = run.final_position() / d;
    let toe = run
        .profile
        .iter()
        .map(|p| (p.x / d, p.y / d))
        .find(|&(x, y)| x > face && y.abs() < 0.05)
        .map_or(whole.x.1, |(x, _)| x);
    Extent {
        x: (
            (face - 1.0).max(whole.x.0),
            (toe + 1.0).max(face + 3.0).min(whole.x.1),
        ),
        y: whole.y,
    }
}

/// Indices of the slip lines to draw: each increment whose emergence point
/// differs from the previous one (at most [`MAX_JUMPS`], evenly spaced)
/// and [`EVEN_BANDS`] evenly spaced increments, in order.
fn chosen_bands(history: &[Increment]) -> Vec<&Increment> {
    let n = history.len();
    if n == 0 {
        return Vec::new();
    }
    let jumps: Vec<usize> = (0..n)
        .filter(|&i| i == 0 || history[i].x_emergence != history[i - 1].x_emergence)
        .collect();
    let mut chosen = evenly(&jumps, MAX_JUMPS);
    let all: Vec<usize> = (0..n).collect();
    chosen.extend(evenly(&all, EVEN_BANDS));
    chosen.sort_unstable();
    chosen.dedup();
    chosen.into_iter().map(|i| &history[i]).collect()
}

/// At most `count` items of `items`, evenly spaced, first and last included.
pub(crate) fn evenly<T: Copy>(items: &[T], count: usize) -> Vec<T> {
    if items.len() <= count {
        return items.to_vec();
    }
    let last = items.len() - 1;
    let mut picked: Vec<usize> = (0..count)
        .map(|k| (k * last + (count - 1) / 2) / (count - 1).max(1))
        .collect();
    picked.dedup();
    picked.into_iter().map(|i| items[i]).collect()
}

impl Picture for Deformation<'_> {
    fn size(&self) -> (u32, u32) {
        let shear = 2 * MARGIN + SHEAR + X_LABELS;
        let legend = self.legend().height();
        let ground = self.ground_height() + self.near_height();
        (WIDTH, title_height(PAPER.title) + legend + ground + shear)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let run = self.run;
        let d = run.depth;
        let area = titled(root, &run.title, PAPER.title)?;
        let legend = self.legend();
        let (legend_area, area) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let (upper, lower) = area.split_vertically(self.ground_height());
        let (lower, near_area) = lower.split_vertically(2 * MARGIN + SHEAR + X_LABELS);
        let (ground_area, bar_area) = upper.split_horizontally(WIDTH - BAR);
        let (shear_area, _) = lower.split_horizontally(WIDTH - BAR);
        let u_max = round_up(top(run.history.iter().map(|h| h.u / d), 1.0));
        self.draw_ground_panel(&ground_area, &self.panel, u_max)?;
        colour_bar(root, &bar_area, u_max, PAPER)?;
        if let Some(near) = &self.near {
            let (name, near_area) = near_area.split_vertically(NEAR_TITLE);
            let style = font(PAPER.desc).pos(Pos::new(HPos::Left, VPos::Center));
            let words = "near the blade at the end of the run (equal scales)";
            name.draw(&Text::new(
                words,
                (Y_LABELS as i32, NEAR_TITLE as i32 / 2),
                style,
            ))
            .map_err(text)?;
            let (near_area, _) = near_area.split_horizontally(WIDTH - BAR);
            self.draw_ground_panel(&near_area, near, u_max)?;
        }

        let shear: Vec<(f64, f64)> = run
            .profile
            .iter()
            .map(|p| (p.x / d, p.accumulated_shear / d))
            .filter(|p| p.0 <= self.extent.x.1)
            .collect();
        let shear_top = top(shear.iter().map(|p| p.1), 0.1) * 1.15;
        let mut chart = self.panel.chart(&shear_area, (0.0, shear_top))?;
        axes(&mut chart, X_DESC, "uₜ/d (–)", PAPER)?;
        chart
            .draw_series(stems(&chart, &shear).into_iter().map(|(x, top)| {
                PathElement::new(vec![(x, 0.0), (x, top)], theme::SHEAR.stroke_width(2))
            }))
            .map_err(text)?;
        Ok(())
    }
}

impl Deformation<'_> {
    /// The ground, the bands and the blade in `panel`'s extent, bands
    /// coloured by u/d up to `u_max`.
    fn draw_ground_panel<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        panel: &GroundPanel,
        u_max: f64,
    ) -> DrawResult {
        let (run, ext) = (self.run, panel.extent);
        let d = run.depth;
        let mut chart = panel.chart(area, ext.y)?;
        axes(&mut chart, X_DESC, Y_DESC, PAPER)?;
        let u_final = run.final_position();
        draw_ground(&mut chart, run, &run.profile, u_final, ext)?;
        for h in &self.bands {
            let color = viridis(h.u / d / u_max);
            let width = PAPER.line - 1;
            draw_band(&mut chart, h, ext.x.1, d, run.band_width, color, width)?;
        }
        draw_outline(&mut chart, run, &run.profile, u_final, ext, PAPER)?;
        draw_ridges(&mut chart, run, ext)
    }

    /// The legend above both panels.
    fn legend(&self) -> Legend {
        let what = if self.run.band_width > 0.0 {
            "shear bands, coloured by u/d"
        } else {
            "slip lines, coloured by u/d"
        };
        let mut entries = vec![
            ("initial ground".to_string(), Mark::Dashed(BLACK)),
            ("ground surface".to_string(), Mark::Line(theme::GROUND_EDGE)),
            ("blade".to_string(), Mark::Block(theme::BLADE)),
            (what.to_string(), Mark::Line(viridis(0.5))),
            (
                "shear accumulated along the surface".to_string(),
                Mark::Line(theme::SHEAR),
            ),
        ];
        if !self.run.ridges.is_empty() {
            entries.push(if crest_stretches(self.run, f64::INFINITY).is_empty() {
                (
                    "side heaps' crest: level with the ground surface".to_string(),
                    Mark::Line(theme::GROUND_EDGE),
                )
            } else {
                (
                    "side heaps' crest beside the blade".to_string(),
                    Mark::Dashed(theme::RIDGE),
                )
            });
        }
        Legend::new(entries, WIDTH - 60, PAPER)
    }
}

/// The crest of the side heaps beside a blade of finite width (dashed), over
/// the ground in front of the blade, where it stands off the ground
/// surface.
fn draw_ridges<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    run: &RunData,
    ext: Extent,
) -> DrawResult {
    for stretch in crest_stretches(run, ext.x.1) {
        chart
            .draw_series(DashedLineSeries::new(
                thin(chart, &stretch),
                10,
                6,
                theme::RIDGE.stroke_width(PAPER.line),
            ))
            .map_err(text)?;
    }
    Ok(())
}

/// The stretches of the side heaps' crest (in d, up to x = `x_max`) that
/// stand off the final ground surface by more than a line's width (d/200):
/// where the crest is the ground's own height, a dashed line on the ground
/// line would hide it and say nothing.
fn crest_stretches(run: &RunData, x_max: f64) -> Vec<Vec<(f64, f64)>> {
    const APART: f64 = 0.005;
    let d = run.depth;
    let ground: Vec<(f64, f64)> = run.profile.iter().map(|p| (p.x / d, p.y / d)).collect();
    let mut stretches: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current = Vec::new();
    for &(x, h) in &run.ridges {
        let p = (x / d, h / d);
        let off = p.0 <= x_max && ground_at(&ground, p.0).is_some_and(|y| (p.1 - y).abs() > APART);
        if off {
            current.push(p);
        } else if !current.is_empty() {
            stretches.push(std::mem::take(&mut current));
        }
    }
    stretches.push(current);
    stretches.retain(|s| s.len() >= 2);
    stretches
}

/// The height of `ground` (points in increasing x) at `x`, linearly
/// between its points; None outside them.
fn ground_at(ground: &[(f64, f64)], x: f64) -> Option<f64> {
    let i = ground.partition_point(|p| p.0 < x);
    match (i.checked_sub(1).and_then(|k| ground.get(k)), ground.get(i)) {
        (_, Some(b)) if b.0 == x => Some(b.1),
        (Some(a), Some(b)) => Some(a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)),
        _ => None,
    }
}

/// For each pixel column of `points`: its first x and largest value, so
/// that a one-pixel stem per column shows every spike however narrow.
fn stems<'a, DB: DrawingBackend + 'a>(
    chart: &Chart<'a, DB>,
    points: &[(f64, f64)],
) -> Vec<(f64, f64)> {
    let mut out: Vec<(i32, (f64, f64))> = Vec::new();
    for &(x, y) in points {
        let column = chart.backend_coord(&(x, y)).0;
        match out.last_mut() {
            Some((c, stem)) if *c == column => stem.1 = stem.1.max(y),
            _ => out.push((column, (x, y))),
        }
    }
    out.into_iter().map(|(_, stem)| stem).collect()
}

/// The ground fill with the blade's tip at displacement `u`: below the
/// trench floor behind the tip (where the tip went, see [`trench_floor`])
/// and the soil in front of the face below `surface`, which starts where
/// the face meets it, down to the bottom of the picture (below the
/// deepest tip); for an inclined blade (`rake` < 90°) the soil's left
/// boundary is the face line from the tip up to that point.
pub(crate) fn draw_ground<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    run: &RunData,
    surface: &[SurfacePoint],
    u: f64,
    ext: Extent,
) -> DrawResult {
    let d = run.depth;
    let trench = trench_floor(run, u, ext.x.0);
    let tip = trench[trench.len() - 1];
    let floor = ext.y.0;
    if is_level(&trench) {
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(ext.x.0, floor), tip],
                theme::GROUND.filled(),
            )))
            .map_err(text)?;
    } else {
        let mut below = thin(chart, &trench);
        below.extend([(tip.0, floor), (ext.x.0, floor)]);
        chart
            .draw_series(std::iter::once(Polygon::new(below, theme::GROUND.filled())))
            .map_err(text)?;
    }
    let outline = ground_outline(&visible(surface, d, ext), tip, run.rake, ext);
    chart
        .draw_series(std::iter::once(Polygon::new(
            outline,
            theme::GROUND.filled(),
        )))
        .map_err(text)?;
    chart
        .draw_series(DashedLineSeries::new(
            [(ext.x.0, 0.0), (ext.x.1, 0.0)],
            12,
            8,
            BLACK.stroke_width(1),
        ))
        .map_err(text)?;
    Ok(())
}

/// The surface line, the trench floor (see [`trench_floor`]) and the
/// blade with its tip at displacement `u` (an inclined plate for
/// `rake` < 90°, see [`blade_outline`]), drawn over the bands; the blade
/// reaches the top of the picture.
pub(crate) fn draw_outline<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    run: &RunData,
    surface: &[SurfacePoint],
    u: f64,
    ext: Extent,
    sizes: Sizes,
) -> DrawResult {
    let d = run.depth;
    let edge = theme::GROUND_EDGE.stroke_width(sizes.line);
    curve(
        chart,
        &visible(surface, d, ext),
        theme::GROUND_EDGE,
        sizes.line,
    )?;
    let trench = trench_floor(run, u, ext.x.0);
    let tip = trench[trench.len() - 1];
    if is_level(&trench) {
        chart
            .draw_series(LineSeries::new([trench[0], tip], edge))
            .map_err(text)?;
    } else {
        curve(chart, &trench, theme::GROUND_EDGE, sizes.line)?;
    }
    let face = tip.0;
    let thickness = 0.06 * ext.height().min(ext.width()).max(1.0) / 1.5;
    if is_vertical(run.rake) && is_level(&trench) {
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(face - thickness, tip.1), (face, ext.y.1)],
                theme::BLADE.filled(),
            )))
            .map_err(text)?;
    } else if is_vertical(run.rake) {
        // A deepening blade's back stands on the floor its tip cut.
        let back = face - thickness;
        let plate = vec![
            (back, height_at(&trench, back)),
            tip,
            (face, ext.y.1),
            (back, ext.y.1),
        ];
        chart
            .draw_series(std::iter::once(Polygon::new(plate, theme::BLADE.filled())))
            .map_err(text)?;
    } else {
        let plate = blade_outline(tip, run.rake, thickness, ext.y.1, ext.x.0);
        chart
            .draw_series(std::iter::once(Polygon::new(plate, theme::BLADE.filled())))
            .map_err(text)?;
    }
    Ok(())
}

/// The surface points within the picture, in units of d.
fn visible(surface: &[SurfacePoint], d: f64, ext: Extent) -> Vec<(f64, f64)> {
    let mut points = Vec::new();
    for p in surface {
        points.push((p.x / d, p.y / d));
        if p.x / d > ext.x.1 {
            break;
        }
    }
    points
}

/// The slip line of increment `h` from the blade tip (`h.u`, −`h.depth`) to the emergence
/// point; with `band_width` > 0 also the band's upper boundary, parallel
/// and `band_width` above it (normal distance), and the band shaded; cut
/// at `x_max` (in units of d).
pub(crate) fn draw_band<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    h: &Increment,
    x_max: f64,
    d: f64,
    band_width: f64,
    color: RGBColor,
    width: u32,
) -> DrawResult {
    let a = slip_start(h, d);
    let mut b = (h.x_emergence / d, h.y_emergence / d);
    if b.0 > x_max && b.0 > a.0 {
        b = (x_max, a.1 + (b.1 - a.1) * (x_max - a.0) / (b.0 - a.0));
    }
    if band_width > 0.0 && b.0 > a.0 {
        let tan = (b.1 - a.1) / (b.0 - a.0);
        let e = band_width / d * (1.0 + tan * tan).sqrt();
        let upper = [(a.0, a.1 + e), (b.0, b.1 + e)];
        chart
            .draw_series(std::iter::once(Polygon::new(
                vec![a, b, upper[1], upper[0]],
                color.mix(0.15).filled(),
            )))
            .map_err(text)?;
        chart
            .draw_series(LineSeries::new(upper, color.stroke_width(width.max(1))))
            .map_err(text)?;
    }
    chart
        .draw_series(LineSeries::new([a, b], color.stroke_width(width.max(1))))
        .map_err(text)?;
    Ok(())
}

/// A vertical colour bar of u/d from 0 to `u_max`, aligned with the
/// ground panel's plotting area.
pub(crate) fn colour_bar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    area: &DrawingArea<DB, Shift>,
    u_max: f64,
    sizes: Sizes,
) -> DrawResult {
    let mut chart = ChartBuilder::on(area)
        .margin_top(MARGIN)
        .margin_bottom(MARGIN + X_LABELS)
        .margin_left(20)
        .margin_right(10)
        .right_y_label_area_size(sizes.tick * 3)
        .build_cartesian_2d(0.0..1.0, 0.0..u_max)
        .map_err(text)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(6)
        .y_label_formatter(&tick)
        .label_style(font(sizes.tick))
        .draw()
        .map_err(text)?;
    let n = 200;
    chart
        .draw_series((0..n).map(|i| {
            let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
            Rectangle::new(
                [(0.0, t0 * u_max), (1.0, t1 * u_max)],
                viridis((t0 + t1) / 2.0).filled(),
            )
        }))
        .map_err(text)?;
    let (x, y) = chart.backend_coord(&(0.5, 0.0));
    let style = font(sizes.desc).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new("u/d (–)", (x + 10, y + 12), style))
        .map_err(text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SurfacePoint;

    fn run(ridges: Vec<(f64, f64)>) -> RunData {
        let profile = (0..=10)
            .map(|k| SurfacePoint {
                x: f64::from(k),
                y: 5.0 - 0.5 * f64::from(k),
                accumulated_shear: 0.0,
            })
            .collect();
        RunData {
            title: "t".into(),
            depth: 10.0,
            rake: 90.0,
            unit_weight: 1.0,
            band_width: 0.0,
            history: Vec::new(),
            profile,
            frames: Vec::new(),
            ridges,
        }
    }

    /// A crest level with the ground is not drawn over the ground line;
    /// one standing above it is.
    #[test]
    fn the_crest_is_drawn_only_off_the_ground() {
        let level: Vec<(f64, f64)> = (0..=10)
            .map(|k| (f64::from(k), 5.0 - 0.5 * f64::from(k)))
            .collect();
        assert!(crest_stretches(&run(level), f64::INFINITY).is_empty());
        let raised: Vec<(f64, f64)> = (0..=10)
            .map(|k| {
                (
                    f64::from(k),
                    5.0 - 0.5 * f64::from(k) + if k < 5 { 1.0 } else { 0.0 },
                )
            })
            .collect();
        let stretches = crest_stretches(&run(raised), f64::INFINITY);
        assert_eq!(stretches.len(), 1);
        assert_eq!(stretches[0].len(), 5);
        assert_eq!(stretches[0][0], (0.0, 0.6));
    }
}
