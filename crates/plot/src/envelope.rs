//! The force envelope of an ensemble: every member's P/(γ0 d²) against u/d,
//! the ensemble mean over the band of mean ± one standard deviation over the
//! members (increment by increment, shaded), and each unit window's ensemble
//! mean as a black step. Members differ by 1-2 % at most, less than a
//! line's width on the force's scale, so a second panel below draws each
//! member's and the band's deviation from the mean on a scale of their own.

use crate::axes::{round_up, title_height, titled, top, Chart};
use crate::curves::curve_chart;
use crate::error::{text, DrawResult};
use crate::legend::{Legend, Mark};
use crate::lines::curve;
use crate::render::{save, Picture};
use crate::theme::{self, PAPER};
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

const MEMBER: RGBColor = RGBColor(110, 140, 185);
/// The band's shade: orange (255, 127, 14) at a third on white.
const SHADE: RGBColor = RGBColor(255, 212, 175);
const WIDTH: u32 = 1200;
const CHART: u32 = 600;
const DEVIATION: u32 = 330;

impl Envelope {
    fn legend(&self) -> Legend {
        let rows = vec![
            (
                format!("{} members", self.members.len()),
                Mark::Line(MEMBER),
            ),
            ("ensemble mean".to_string(), Mark::Line(theme::CURVE)),
            (
                "mean ± 1 standard deviation".to_string(),
                Mark::Block(SHADE),
            ),
            ("unit-window ensemble mean".to_string(), Mark::Line(BLACK)),
        ];
        Legend::new(rows, WIDTH - 80, PAPER)
    }
}

impl Picture for Envelope {
    fn size(&self) -> (u32, u32) {
        let title = title_height(PAPER.title);
        (WIDTH, title + self.legend().height() + CHART + DEVIATION)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let area = titled(root, &self.title, PAPER.title)?;
        let legend = self.legend();
        let (legend_area, charts) = area.split_vertically(legend.height());
        legend.draw(&legend_area)?;
        let (force_area, deviation_area) = charts.split_vertically(CHART);
        let all = || self.members.iter().flatten();
        let x1 = round_up(top(all().map(|p| p.0), 1.0));
        let y1 = top(all().map(|p| p.1), 1.0) * 1.1;
        let force = "P/(γ₀d²) (–)";
        let mut chart = curve_chart(&force_area, (0.0, x1), (0.0, y1), force, PAPER)?;
        self.draw_curves(&mut chart, &self.members, &self.mean, &self.band)?;
        for &(from, to, mean) in &self.windows {
            curve(&mut chart, &[(from, mean), (to, mean)], BLACK, PAPER.line)?;
        }
        let (members, band) = self.deviations();
        let reach = members
            .iter()
            .flatten()
            .map(|p| p.1.abs())
            .chain(band.iter().map(|b| b.2.abs()))
            .fold(0.0, f64::max);
        let label = "member − mean (–)";
        let reach = nice_ceiling(1.05 * reach);
        let mut chart = curve_chart(&deviation_area, (0.0, x1), (-reach, reach), label, PAPER)?;
        let zero = [(0.0, 0.0), (x1, 0.0)];
        self.draw_curves(&mut chart, &members, &zero, &band)
    }
}

/// The least of 1, 2, 5 × 10^k at or above `x` (1 for none): an axis
/// reaching to it ends on a tick.
fn nice_ceiling(x: f64) -> f64 {
    if !(x > 0.0 && x.is_finite()) {
        return 1.0;
    }
    let decade = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * decade)
        .find(|&v| v >= x)
        .unwrap_or(10.0 * decade)
}

/// (u/d, value) points.
type Curve = Vec<(f64, f64)>;

impl Envelope {
    /// The band shaded, the members over it, the mean over them.
    fn draw_curves<'a, DB: DrawingBackend + 'a>(
        &self,
        chart: &mut Chart<'a, DB>,
        members: &[Curve],
        mean: &[(f64, f64)],
        band: &[(f64, f64, f64)],
    ) -> DrawResult {
        let outline: Vec<(f64, f64)> = band
            .iter()
            .map(|b| (b.0, b.1))
            .chain(band.iter().rev().map(|b| (b.0, b.2)))
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(outline, SHADE.filled())))
            .map_err(text)?;
        for member in members {
            curve(chart, member, MEMBER, 1)?;
        }
        curve(chart, mean, theme::CURVE, PAPER.line - 1)
    }

    /// Each member's and the band's deviation from the mean, increment by
    /// increment (members and mean share the increments; a member that
    /// stopped early has fewer).
    fn deviations(&self) -> (Vec<Curve>, Vec<(f64, f64, f64)>) {
        let members = self
            .members
            .iter()
            .map(|m| {
                m.iter()
                    .zip(&self.mean)
                    .map(|(p, q)| (p.0, p.1 - q.1))
                    .collect()
            })
            .collect();
        let band = self
            .band
            .iter()
            .zip(&self.mean)
            .map(|(b, q)| (b.0, b.1 - q.1, b.2 - q.1))
            .collect();
        (members, band)
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
            members: vec![member(0.1), member(0.102)],
            mean: member(0.101),
            band: (0..50)
                .map(|i| {
                    (
                        i as f64 / 10.0,
                        1.0 + 0.1 * i as f64,
                        1.0 + 0.102 * i as f64,
                    )
                })
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
    fn the_deviation_axis_ends_on_a_tick() {
        assert_eq!(nice_ceiling(0.27), 0.5);
        assert_eq!(nice_ceiling(0.012), 0.02);
        assert_eq!(nice_ceiling(3.0), 5.0);
        assert_eq!(nice_ceiling(0.0), 1.0);
    }

    /// The members' spread, 1 % of the force, fills the deviation panel:
    /// the band's shade spans much of its height at u/d ≈ 4.5 (on the
    /// force's scale the spread lay within a line's width).
    #[test]
    fn the_spread_is_drawn_on_a_scale_of_its_own() {
        let picture = envelope();
        let pixels = crate::render::rgb(&picture).unwrap();
        let (w, h) = picture.size();
        let (w, h) = (w as usize, h as usize);
        let shaded = |y: usize| {
            let i = (y * w + w * 9 / 10) * 3;
            pixels[i..i + 3] == [SHADE.0, SHADE.1, SHADE.2]
        };
        let rows: Vec<usize> = (h - DEVIATION as usize..h).filter(|&y| shaded(y)).collect();
        let span = rows.last().zip(rows.first()).map_or(0, |(b, t)| b - t);
        assert!(span > 60, "the band spans {span} px at u/d = 4.5");
    }

    #[test]
    fn no_members_is_an_error() {
        let mut e = envelope();
        e.members.clear();
        let dir = tempfile::tempdir().unwrap();
        assert!(draw_envelope(&e, &dir.path().join("e.png")).is_err());
    }
}
