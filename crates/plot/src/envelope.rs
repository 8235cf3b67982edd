//! The force envelope of an ensemble: every member's P/(γ0 d²) against u/d
//! drawn faint, the ensemble mean and its band (mean ± one standard
//! deviation over the members, increment by increment) bold, and each unit
//! window's ensemble mean as a black step.

use crate::render::{save, text, DrawResult, Picture};
use crate::style::{self, axes, curve, round_up, titled, top, Legend, Mark, PAPER};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// What the envelope picture shows. Every curve is (u/d, P/(γ0 d²)).
#[derive(Clone, Debug, PartialEq)]
pub struct Envelope {
    /// The picture's title (the case's title and the number of members).
    pub title: String,
    /// Each member's force, increment by increment.
    pub members: Vec<Vec<(f64, f64)>>,
    /// The ensemble mean at each increment.
    pub mean: Vec<(f64, f64)>,
    /// Mean − and + one standard deviation at each increment: (u/d, low, high).
    pub band: Vec<(f64, f64, f64)>,
    /// Each unit window's ensemble mean: (from u/d, to u/d, mean).
    pub windows: Vec<(f64, f64, f64)>,
}

/// Draws `envelope` into `path` (PNG or SVG by its extension), 1200 px wide.
pub fn draw_envelope(envelope: &Envelope, path: &Path) -> Result<(), PlotError> {
    if envelope.members.is_empty() {
        return Err(PlotError::new(path, "an ensemble without members"));
    }
    save(envelope, path)
}

const MEMBER: RGBColor = RGBColor(175, 196, 222);
const BAND: RGBColor = RGBColor(255, 127, 14);
const WIDTH: u32 = 1200;
const CHART: u32 = 760;

impl Envelope {
    fn legend(&self) -> Legend {
        let rows = vec![
            (
                format!("{} members", self.members.len()),
                Mark::Line(MEMBER),
            ),
            ("ensemble mean".to_string(), Mark::Line(style::CURVE)),
            ("mean ± 1 standard deviation".to_string(), Mark::Line(BAND)),
            ("unit-window ensemble mean".to_string(), Mark::Line(BLACK)),
        ];
        Legend::new(rows, WIDTH - 80, PAPER)
    }
}

impl Picture for Envelope {
    fn size(&self) -> (u32, u32) {
        let title = style::title_height(PAPER.title);
        (WIDTH, title + self.legend().height() + CHART)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.title, PAPER.title)?;
        let legend = self.legend();
        let (legend_area, chart_area) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let all = || self.members.iter().flatten();
        let x1 = round_up(top(all().map(|p| p.0), 1.0));
        let y1 = top(all().map(|p| p.1), 1.0) * 1.1;
        let mut chart = ChartBuilder::on(&chart_area)
            .margin(20)
            .margin_right(45)
            .x_label_area_size(PAPER.desc * 3)
            .y_label_area_size(PAPER.desc * 4)
            .build_cartesian_2d(0.0..x1, 0.0..y1)
            .map_err(text)?;
        axes(&mut chart, "u/d (–)", "P/(γ₀d²) (–)", PAPER)?;
        for member in &self.members {
            curve(&mut chart, member, MEMBER, 1)?;
        }
        let low: Vec<(f64, f64)> = self.band.iter().map(|b| (b.0, b.1)).collect();
        let high: Vec<(f64, f64)> = self.band.iter().map(|b| (b.0, b.2)).collect();
        curve(&mut chart, &low, BAND, 2)?;
        curve(&mut chart, &high, BAND, 2)?;
        curve(&mut chart, &self.mean, style::CURVE, PAPER.line + 1)?;
        for &(from, to, mean) in &self.windows {
            curve(&mut chart, &[(from, mean), (to, mean)], BLACK, PAPER.line)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn envelope() -> Envelope {
        let member = |s: f64| {
            (0..50)
                .map(|i| (i as f64 / 10.0, 1.0 + s * i as f64))
                .collect()
        };
        Envelope {
            title: "test: 2 members".into(),
            members: vec![member(0.1), member(0.12)],
            mean: member(0.11),
            band: (0..50)
                .map(|i| (i as f64 / 10.0, 1.0 + 0.1 * i as f64, 1.0 + 0.12 * i as f64))
                .collect(),
            windows: vec![(0.0, 1.0, 1.5), (1.0, 2.0, 2.6)],
        }
    }

    #[test]
    fn draws_png_and_svg_deterministically() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["e.png", "e.svg"] {
            let (a, b) = (
                dir.path().join(name),
                dir.path().join(format!("again-{name}")),
            );
            draw_envelope(&envelope(), &a).unwrap();
            draw_envelope(&envelope(), &b).unwrap();
            assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        }
        let svg = std::fs::read_to_string(dir.path().join("e.svg")).unwrap();
        assert!(svg.contains("2 members") && svg.contains("ensemble mean"));
    }

    #[test]
    fn no_members_is_an_error() {
        let mut e = envelope();
        e.members.clear();
        let dir = tempfile::tempdir().unwrap();
        assert!(draw_envelope(&e, &dir.path().join("e.png")).is_err());
    }
}
