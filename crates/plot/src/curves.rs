//! Curves against u/d: the force (paper Fig. 5a), β* (Fig. 5b) and the
//! comparison of several runs (Fig. 7).

use crate::axes::{axes, round_up, title_height, titled, top, Chart};
use crate::error::{text, DrawResult};
use crate::legend::{Legend, Mark};
use crate::lines::{curve, dots};
use crate::render::{save, Picture};
use crate::theme::{self, Sizes, PAPER};
use crate::{Increment, Measured, PlotError, RunData};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// A quantity plotted against u/d.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quantity {
    Force,
    Beta,
}

impl Quantity {
    pub(crate) fn of(self, h: &Increment) -> f64 {
        match self {
            Quantity::Force => h.force_norm,
            Quantity::Beta => h.beta_deg,
        }
    }

    pub(crate) fn desc(self) -> &'static str {
        match self {
            Quantity::Force => "P/(γ₀d²) (–)",
            Quantity::Beta => "β* (°)",
        }
    }
}

pub(crate) const U_DESC: &str = "u/d (–)";

/// Draws the normalised blade force P*/(γ0 d²) of every increment against
/// the blade displacement u/d (paper Fig. 5a), titled with the case title.
/// PNG or SVG by `path`'s extension, 1200 × 800 px.
pub fn draw_force(run: &RunData, path: &Path) -> Result<(), PlotError> {
    save(
        &Single {
            run,
            q: Quantity::Force,
        },
        path,
    )
}

/// Draws β*, the angle of the chosen slip line (lower band boundary) above
/// the horizontal, in degrees against u/d (paper Fig. 5b). Its jumps are
/// the moments a new slip line forms farther ahead of the blade.
pub fn draw_beta(run: &RunData, path: &Path) -> Result<(), PlotError> {
    save(
        &Single {
            run,
            q: Quantity::Beta,
        },
        path,
    )
}

/// Overlays the force (top panel) and β* (bottom panel) curves of `runs`
/// against u/d, each run in its own colour and width, the first the widest,
/// with its title in the legend (paper Fig. 7): runs that coincide (one
/// case at two increments) stay visible under one another. A `measured` curve (u, force per unit width, in the
/// first run's length unit) is drawn as black dots, normalised by the first
/// run's d and γ0. PNG or SVG by `path`'s extension, 1200 px wide.
pub fn draw_compare(
    runs: &[RunData],
    measured: Option<&Measured>,
    path: &Path,
) -> Result<(), PlotError> {
    if runs.is_empty() {
        return Err(PlotError::new(path, "no run to compare"));
    }
    save(&Compare { runs, measured }, path)
}

/// The x range of the curves: 0 to the largest u/d, rounded up.
fn u_range(runs: &[&RunData]) -> (f64, f64) {
    let hi = top(
        runs.iter()
            .flat_map(|r| r.history.iter().map(move |h| h.u / r.depth)),
        1.0,
    );
    (0.0, round_up(hi))
}

/// 0 to 10 % above the largest value.
fn value_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    (0.0, top(values, 1.0) * 1.1)
}

/// Builds a chart of the curves' layout on `area`, against u/d.
pub(crate) fn curve_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    x: (f64, f64),
    y: (f64, f64),
    y_desc: &str,
    sizes: Sizes,
) -> Result<Chart<'a, DB>, String> {
    let mut chart = ChartBuilder::on(area)
        .margin(20)
        .margin_right(45)
        .x_label_area_size(sizes.desc * 3)
        .y_label_area_size(sizes.desc * 4)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(text)?;
    axes(&mut chart, U_DESC, y_desc, sizes)?;
    Ok(chart)
}

fn points(run: &RunData, q: Quantity) -> Vec<(f64, f64)> {
    run.history
        .iter()
        .map(|h| (h.u / run.depth, q.of(h)))
        .collect()
}

/// The force as a line; β* as dots, since the refined model's β* can
/// alternate between two bands from one increment to the next, which a
/// line would smear into a solid block.
fn draw_quantity<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    q: Quantity,
    points: &[(f64, f64)],
    (color, width): (RGBColor, u32),
) -> DrawResult {
    match q {
        Quantity::Force => curve(chart, points, color, width),
        Quantity::Beta => dots(chart, points, color, width / 2 + 1),
    }
}

struct Single<'a> {
    run: &'a RunData,
    q: Quantity,
}

impl Picture for Single<'_> {
    fn size(&self) -> (u32, u32) {
        (1200, 800)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.run.title, PAPER.title)?;
        let y = value_range(self.run.history.iter().map(|h| self.q.of(h)));
        let mut chart = curve_chart(&area, u_range(&[self.run]), y, self.q.desc(), PAPER)?;
        let look = (theme::CURVE, PAPER.line);
        draw_quantity(&mut chart, self.q, &points(self.run, self.q), look)
    }
}

struct Compare<'a> {
    runs: &'a [RunData],
    measured: Option<&'a Measured>,
}

const PANEL: u32 = 430;
const WIDTH: u32 = 1200;

impl Compare<'_> {
    fn legend(&self) -> Legend {
        let mut rows: Vec<(String, Mark)> = self
            .runs
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let (color, width) = self.look(i);
                (r.title.clone(), Mark::Stroke(color, width))
            })
            .collect();
        if let Some(m) = self.measured {
            rows.push((m.label.clone(), Mark::Dot(BLACK)));
        }
        Legend::new(rows, WIDTH - 80, PAPER)
    }

    /// Run `i`'s colour and line width: 3 px wider than the next run's,
    /// the last at the width of a single curve.
    fn look(&self, i: usize) -> (RGBColor, u32) {
        let later = (self.runs.len() - 1 - i) as u32;
        (series_color(i), PAPER.line + 3 * later.min(4))
    }

    /// The measured points as (u/d, P/(γ0 d²)) of the first run.
    fn measured_norm(&self) -> Vec<(f64, f64)> {
        let first = &self.runs[0];
        let (d, g) = (first.depth, first.unit_weight);
        self.measured
            .map(|m| {
                m.points
                    .iter()
                    .map(|&(u, f)| (u / d, f / (g * d * d)))
                    .collect()
            })
            .unwrap_or_default()
    }
}

fn series_color(i: usize) -> RGBColor {
    theme::SERIES[i % theme::SERIES.len()]
}

impl Picture for Compare<'_> {
    fn size(&self) -> (u32, u32) {
        let title = title_height(PAPER.title);
        (WIDTH, title + self.legend().height() + 2 * PANEL)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, "Blade force and slip-line angle", PAPER.title)?;
        let legend = self.legend();
        let (legend_area, panels) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let refs: Vec<&RunData> = self.runs.iter().collect();
        let measured = self.measured_norm();
        let (u0, mut u1) = u_range(&refs);
        u1 = measured.iter().map(|p| p.0).fold(u1, f64::max);
        let (top_area, bottom_area) = panels.split_vertically(PANEL);
        for (area, q) in [(top_area, Quantity::Force), (bottom_area, Quantity::Beta)] {
            let mut values: Vec<f64> = self
                .runs
                .iter()
                .flat_map(|r| r.history.iter().map(move |h| q.of(h)))
                .collect();
            if q == Quantity::Force {
                values.extend(measured.iter().map(|p| p.1));
            }
            let y = value_range(values.into_iter());
            let mut chart = curve_chart(&area, (u0, u1), y, q.desc(), PAPER)?;
            for (i, run) in self.runs.iter().enumerate() {
                draw_quantity(&mut chart, q, &points(run, q), self.look(i))?;
            }
            if q == Quantity::Force {
                chart
                    .draw_series(measured.iter().map(|&p| Circle::new(p, 5, BLACK.filled())))
                    .map_err(text)?;
            }
        }
        Ok(())
    }
}
