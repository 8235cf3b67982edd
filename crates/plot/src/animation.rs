//! The cutting process as an animated GIF.

use crate::axes::{axes, round_up, title_height, titled, top};
use crate::curves::{Quantity, U_DESC};
use crate::deformation::{draw_band, draw_ground, draw_outline, evenly, X_DESC, Y_DESC};
use crate::error::{text, DrawResult};
use crate::ground::{Extent, GroundPanel};
use crate::lines::curve;
use crate::render::{rgb, Picture};
use crate::theme::{self, font, SMALL};
use crate::{Frame, PlotError, RunData};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::collections::HashMap;
use std::fs;
use std::path::Path;

/// Frames drawn at most (evenly spaced among the run's).
pub const MAX_FRAMES: usize = 150;
/// Display time of each frame, in hundredths of a second.
pub const FRAME_DELAY: u16 = 5;
/// Display time of the last frame before the animation repeats.
pub const LAST_DELAY: u16 = 250;

/// Draws the cutting process as an animated GIF, one picture per frame of
/// `run.frames` (at most `MAX_FRAMES` = 150, evenly spaced): top, to equal
/// scales in x/d and y/d, the ground at that moment, the blade (its tip
/// at that moment's depth, the trench floor behind it where the tip went)
/// and the slip line or shear band of the increment just done; below, the force
/// curve P/(γ0 d²) growing up to that moment, with a dot at its end.
/// Frames show for 0.05 s (the last for 2.5 s), so 120 frames last about
/// 8.5 s; 960 px wide. Unchanged pixels are transparent in each frame
/// after the first, which keeps the file small.
pub fn draw_animation(run: &RunData, path: &Path) -> Result<(), PlotError> {
    if run.frames.is_empty() {
        return Err(PlotError::new(path, "the run has no frames to animate"));
    }
    let frames = evenly(&run.frames.iter().collect::<Vec<_>>(), MAX_FRAMES);
    let extent = Extent::of(run, run.frames.iter().map(|f| f.surface.as_slice()));
    let layout = GroundPanel::new(extent, WIDTH, MAX_GROUND, (MARGIN, X_LABELS, Y_LABELS));
    let scene = |frame| Scene::new(run, frame, layout);
    let fail = |e: String| PlotError::new(path, e);
    let size = scene(frames[0]).size();
    let samples = [0, frames.len() / 2, frames.len() - 1]
        .map(|i| rgb(&scene(frames[i])))
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let mut gif = Gif::new(size, &samples).map_err(fail)?;
    for (i, frame) in frames.iter().enumerate() {
        let delay = if i + 1 == frames.len() {
            LAST_DELAY
        } else {
            FRAME_DELAY
        };
        let pixels = rgb(&scene(frame)).map_err(fail)?;
        gif.push(&pixels, delay).map_err(fail)?;
    }
    fs::write(path, gif.finish().map_err(fail)?).map_err(|e| PlotError::new(path, e))
}

const WIDTH: u32 = 960;
const MARGIN: u32 = 10;
const Y_LABELS: u32 = 75;
const X_LABELS: u32 = 55;
const MAX_GROUND: f64 = 380.0;
const FORCE: u32 = 270;

struct Scene<'a> {
    run: &'a RunData,
    frame: &'a Frame,
    layout: GroundPanel,
}

impl<'a> Scene<'a> {
    fn new(run: &'a RunData, frame: &'a Frame, layout: GroundPanel) -> Self {
        Scene { run, frame, layout }
    }
}

impl Picture for Scene<'_> {
    fn size(&self) -> (u32, u32) {
        (
            WIDTH,
            title_height(SMALL.title) + self.layout.height() + FORCE,
        )
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let (run, frame, ext) = (self.run, self.frame, self.layout.extent);
        let d = run.depth;
        let area = titled(root, &run.title, SMALL.title)?;
        let (ground_area, force_area) = area.split_vertically(self.layout.height());
        let done = &run.history[..frame.step.min(run.history.len())];

        let mut chart = self.layout.chart(&ground_area, ext.y)?;
        axes(&mut chart, X_DESC, Y_DESC, SMALL)?;
        draw_ground(&mut chart, run, &frame.surface, frame.u, ext)?;
        if let Some(h) = done.last() {
            draw_band(
                &mut chart,
                h,
                ext.x.1,
                d,
                run.band_width,
                theme::SERIES[3],
                SMALL.line,
            )?;
        }
        draw_outline(&mut chart, run, &frame.surface, frame.u, ext, SMALL)?;
        let (x1, y1) = chart.backend_coord(&(ext.x.1, ext.y.1));
        let label = format!("u/d = {:.2}", frame.u / d);
        let style = font(SMALL.desc).pos(Pos::new(HPos::Right, VPos::Top));
        root.draw(&Text::new(label, (x1 - 12, y1 + 10), style))
            .map_err(text)?;

        let u_max = round_up(top(run.history.iter().map(|h| h.u / d), 1.0));
        let f_max = top(run.history.iter().map(|h| h.force_norm), 1.0) * 1.1;
        let mut chart = ChartBuilder::on(&force_area)
            .margin(MARGIN)
            .margin_right(MARGIN + 20)
            .x_label_area_size(X_LABELS)
            .y_label_area_size(Y_LABELS)
            .build_cartesian_2d(0.0..u_max, 0.0..f_max)
            .map_err(text)?;
        axes(&mut chart, U_DESC, Quantity::Force.desc(), SMALL)?;
        let points = done.iter().map(|h| (h.u / d, h.force_norm));
        let points: Vec<(f64, f64)> = points.collect();
        curve(&mut chart, &points, theme::CURVE, SMALL.line)?;
        chart
            .draw_series(
                points
                    .last()
                    .copied()
                    .map(|p| Circle::new(p, 5, theme::SERIES[3].filled())),
            )
            .map_err(text)?;
        Ok(())
    }
}

/// Index of the transparent colour in every frame.
const TRANSPARENT_INDEX: u8 = 255;

/// A GIF being written: one global palette of the most frequent colours of
/// some sample frames; each frame after the first holds only the rectangle
/// that changed, with unchanged pixels transparent.
struct Gif {
    encoder: gif::Encoder<Vec<u8>>,
    palette: Vec<[u8; 3]>,
    lookup: HashMap<[u8; 3], u8>,
    previous: Option<Vec<u8>>,
    size: (u16, u16),
}

impl Gif {
    fn new(size: (u32, u32), samples: &[Vec<u8>]) -> Result<Self, String> {
        let w = u16::try_from(size.0).map_err(text)?;
        let h = u16::try_from(size.1).map_err(text)?;
        let mut counts: HashMap<[u8; 3], u64> = HashMap::new();
        for s in samples {
            for p in s.chunks_exact(3) {
                *counts.entry([p[0], p[1], p[2]]).or_default() += 1;
            }
        }
        let mut colours: Vec<([u8; 3], u64)> = counts.into_iter().collect();
        colours.sort_unstable_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let palette: Vec<[u8; 3]> = colours
            .iter()
            .take(TRANSPARENT_INDEX as usize)
            .map(|c| c.0)
            .collect();
        let mut flat: Vec<u8> = palette.iter().flatten().copied().collect();
        flat.resize(256 * 3, 255);
        let mut encoder = gif::Encoder::new(Vec::new(), w, h, &flat).map_err(text)?;
        encoder.set_repeat(gif::Repeat::Infinite).map_err(text)?;
        Ok(Gif {
            encoder,
            palette,
            lookup: HashMap::new(),
            previous: None,
            size: (w, h),
        })
    }

    /// The palette index nearest to `c`.
    fn index(&mut self, c: [u8; 3]) -> u8 {
        let palette = &self.palette;
        *self.lookup.entry(c).or_insert_with(|| {
            let dist = |p: &[u8; 3]| {
                (0..3)
                    .map(|k| (i32::from(p[k]) - i32::from(c[k])).pow(2))
                    .sum::<i32>()
            };
            (0..palette.len())
                .min_by_key(|&i| dist(&palette[i]))
                .unwrap_or(0) as u8
        })
    }

    fn push(&mut self, rgb: &[u8], delay: u16) -> Result<(), String> {
        let (w, h) = (usize::from(self.size.0), usize::from(self.size.1));
        let mut last = ([0u8; 3], 0u8);
        let mut indices = Vec::with_capacity(w * h);
        for (i, p) in rgb.chunks_exact(3).enumerate() {
            let c = [p[0], p[1], p[2]];
            if i == 0 || c != last.0 {
                last = (c, self.index(c));
            }
            indices.push(last.1);
        }
        let frame = match &self.previous {
            None => gif::Frame {
                width: self.size.0,
                height: self.size.1,
                buffer: indices.clone().into(),
                ..gif::Frame::default()
            },
            Some(prev) => changed_part(prev, &indices, w, h),
        };
        let frame = gif::Frame {
            delay,
            dispose: gif::DisposalMethod::Keep,
            ..frame
        };
        self.encoder.write_frame(&frame).map_err(text)?;
        self.previous = Some(indices);
        Ok(())
    }

    fn finish(self) -> Result<Vec<u8>, String> {
        self.encoder.into_inner().map_err(text)
    }
}

/// The smallest rectangle holding every pixel that differs between `prev`
/// and `next`, with the unchanged ones transparent (1 × 1 if none differ).
fn changed_part(prev: &[u8], next: &[u8], w: usize, h: usize) -> gif::Frame<'static> {
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for y in 0..h {
        for x in 0..w {
            if prev[y * w + x] != next[y * w + x] {
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
            }
        }
    }
    if x0 > x1 {
        (x0, y0, x1, y1) = (0, 0, 0, 0);
    }
    let mut buffer = Vec::with_capacity((x1 - x0 + 1) * (y1 - y0 + 1));
    for y in y0..=y1 {
        for x in x0..=x1 {
            let (a, b) = (prev[y * w + x], next[y * w + x]);
            buffer.push(if a == b { TRANSPARENT_INDEX } else { b });
        }
    }
    gif::Frame {
        left: x0 as u16,
        top: y0 as u16,
        width: (x1 - x0 + 1) as u16,
        height: (y1 - y0 + 1) as u16,
        transparent: Some(TRANSPARENT_INDEX),
        buffer: buffer.into(),
        ..gif::Frame::default()
    }
}
