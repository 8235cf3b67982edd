//! The landscape of minimum effort: the force of every candidate band of
//! one increment against how far ahead of the blade it emerges.

use crate::axes::{axes, round_up, titled};
use crate::error::{text, DrawResult};
use crate::legend::{Legend, Mark};
use crate::lines::dots;
use crate::render::{save, Picture};
use crate::theme::{self, PAPER};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// The candidates of one increment, for [`draw_landscape`].
#[derive(Clone, Debug, PartialEq)]
pub struct Landscape {
    /// Title of the picture.
    pub title: String,
    /// (distance of the emergence point ahead of the blade tip / d, P/(γ0 d²)),
    /// one point per candidate.
    pub points: Vec<(f64, f64)>,
}

/// The force axis spans these multiples of the least force: near
/// β + φ + φw = 90° forces grow without bound and would flatten the rest,
/// and the interest is in how many candidates come near the least.
const SHOWN: (f64, f64) = (0.9, 2.0);
/// The band drawn above the least force: candidates inside it are nearly as
/// good as the chosen one.
const NEAR: f64 = 0.01;

/// Draws every candidate's force against where it emerges (dots), the least
/// one (red) and the level 1 % above it (dashed), 1200 × 800 px, PNG or SVG
/// by `path`'s extension.
pub fn draw_landscape(landscape: &Landscape, path: &Path) -> Result<(), PlotError> {
    if landscape.points.is_empty() {
        return Err(PlotError::new(path, "no candidate to draw"));
    }
    save(landscape, path)
}

impl Landscape {
    fn least(&self) -> (f64, f64) {
        self.points
            .iter()
            .copied()
            .fold((0.0, f64::INFINITY), |a, p| if p.1 < a.1 { p } else { a })
    }
}

impl Picture for Landscape {
    fn size(&self) -> (u32, u32) {
        (1200, 800)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.title, PAPER.title)?;
        let legend = Legend::new(
            vec![
                ("candidate".into(), Mark::Dot(theme::CURVE)),
                ("least force (chosen)".into(), Mark::Dot(RED)),
                ("1 % above the least".into(), Mark::Dashed(BLACK)),
            ],
            1120,
            PAPER,
        );
        let (legend_area, plot_area) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let least = self.least();
        let (y_min, y_max) = (least.1 * SHOWN.0, least.1 * SHOWN.1);
        let shown: Vec<(f64, f64)> = self
            .points
            .iter()
            .copied()
            .filter(|p| p.1 <= y_max)
            .collect();
        let x_max = round_up(shown.iter().map(|p| p.0).fold(0.0, f64::max));
        let mut chart = ChartBuilder::on(&plot_area)
            .margin(20)
            .margin_right(45)
            .x_label_area_size(PAPER.desc * 3)
            .y_label_area_size(PAPER.desc * 4)
            .build_cartesian_2d(0.0..x_max, y_min..y_max)
            .map_err(text)?;
        axes(
            &mut chart,
            "distance ahead of the blade tip / d (–)",
            "P/(γ₀d²) (–)",
            PAPER,
        )?;
        dots(&mut chart, &shown, theme::CURVE, 2)?;
        let level = least.1 * (1.0 + NEAR);
        chart
            .draw_series(DashedLineSeries::new(
                [(0.0, level), (x_max, level)],
                10,
                6,
                BLACK.stroke_width(1),
            ))
            .map_err(text)?;
        chart
            .draw_series([Circle::new(least, 6, RED.filled())])
            .map_err(text)?;
        Ok(())
    }
}

/// Landscapes taken through a run, for [`draw_landscape_map`].
#[derive(Clone, Debug, PartialEq)]
pub struct LandscapeMap {
    /// Title of the picture.
    pub title: String,
    /// Width of the distance bins, in d.
    pub bin: f64,
    /// One column per landscape: u/d, and for each distance bin (start / d)
    /// the least P/P* of its candidates.
    pub columns: Vec<(f64, Vec<(f64, f64)>)>,
}

/// Levels of P/P* − 1 that set a cell's colour, with their legend labels.
const LEVELS: [(f64, &str); 3] = [
    (0.001, "within 0.1 %"),
    (0.01, "within 1 %"),
    (0.05, "within 5 %"),
];

/// Draws, against u/d (across) and the distance ahead of the blade tip
/// (up), how near each place comes to the least force of its increment:
/// red where the band emerges, then within 0.1 %, 1 % and 5 % of it, grey
/// beyond. 1200 × 800 px, PNG or SVG by `path`'s extension.
pub fn draw_landscape_map(map: &LandscapeMap, path: &Path) -> Result<(), PlotError> {
    if map.columns.is_empty() {
        return Err(PlotError::new(path, "no landscape to draw"));
    }
    save(map, path)
}

fn level_colour(k: usize) -> RGBColor {
    theme::viridis(k as f64 / LEVELS.len() as f64)
}

impl Picture for LandscapeMap {
    fn size(&self) -> (u32, u32) {
        (1200, 800)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.title, PAPER.title)?;
        let mut entries = vec![("least force".to_string(), Mark::Block(RED))];
        for (k, (_, label)) in LEVELS.iter().enumerate() {
            entries.push((label.to_string(), Mark::Block(level_colour(k))));
        }
        entries.push(("beyond".into(), Mark::Block(theme::GRID)));
        let legend = Legend::new(entries, 1120, PAPER);
        let (legend_area, plot_area) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let u_max = self.columns.iter().map(|c| c.0).fold(0.0, f64::max);
        let width = self.column_width();
        let reach = self.columns.iter().flat_map(|c| c.1.iter().map(|b| b.0));
        let y_max = round_up(reach.fold(0.0, f64::max) + self.bin);
        let mut chart = ChartBuilder::on(&plot_area)
            .margin(20)
            .margin_right(45)
            .x_label_area_size(PAPER.desc * 3)
            .y_label_area_size(PAPER.desc * 4)
            .build_cartesian_2d(0.0..u_max + width, 0.0..y_max)
            .map_err(text)?;
        axes(
            &mut chart,
            "u/d (–)",
            "distance ahead of the blade tip / d (–)",
            PAPER,
        )?;
        let spans = self.column_spans();
        let cells = self
            .columns
            .iter()
            .zip(spans)
            .flat_map(|((_, bins), (u, end))| {
                bins.iter().map(move |&(start, ratio)| {
                    let colour = if ratio == 1.0 {
                        RED
                    } else {
                        LEVELS
                            .iter()
                            .position(|l| ratio - 1.0 <= l.0)
                            .map_or(theme::GRID, level_colour)
                    };
                    Rectangle::new([(u, start), (end, start + self.bin)], colour.filled())
                })
            });
        chart.draw_series(cells).map_err(text)?;
        Ok(())
    }
}

impl LandscapeMap {
    /// Each column's (start, end) in u/d: to the next column's start, so
    /// that columns a whole increment apart, whose spacing in u/d varies
    /// by rounding, leave no white seam between them; the last one as
    /// wide as the narrowest.
    fn column_spans(&self) -> Vec<(f64, f64)> {
        let width = self.column_width();
        let starts: Vec<f64> = self.columns.iter().map(|c| c.0).collect();
        starts
            .iter()
            .enumerate()
            .map(|(i, &u)| (u, starts.get(i + 1).copied().unwrap_or(u + width)))
            .collect()
    }

    /// The smallest spacing of the columns in u/d (1 for a single one).
    fn column_width(&self) -> f64 {
        self.columns
            .windows(2)
            .map(|w| w[1].0 - w[0].0)
            .fold(f64::INFINITY, f64::min)
            .min(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Columns whose spacing varies by an increment's rounding abut: no
    /// white seam between them.
    #[test]
    fn columns_abut_without_seams() {
        let map = LandscapeMap {
            title: "t".into(),
            bin: 0.1,
            columns: [0.0, 0.097, 0.2, 0.297]
                .into_iter()
                .map(|u| (u, vec![(0.0, 1.0)]))
                .collect(),
        };
        let spans = map.column_spans();
        for pair in spans.windows(2) {
            assert_eq!(pair[0].1, pair[1].0, "{spans:?}");
        }
        assert!((spans[3].1 - 0.394).abs() < 1e-12, "{spans:?}");
    }
}
