//! The pictures of a sensitivity study: `indices.png` (each output's
//! indices with their intervals), `morris.png` (μ* against σ, Morris
//! only) and `tornado.png` (a case's one-at-a-time ranges).

use super::analysis::{Indices, OutputIndices};
use super::outputs::unit_of;
use super::runs::SensitivityResult;
use crate::error::StudyError;
use soilcut_plot::{draw_bars, draw_panels, Bar, BarPanel, BarSeries, Panel, Series};
use std::path::{Path, PathBuf};

/// Panels to a row.
const COLUMNS: usize = 3;

impl SensitivityResult {
    /// Draws `indices.png`, `morris.png` (Morris) and `tornado.png` (a
    /// case) into `dir`, each output a panel; nothing if a run failed (no
    /// indices), no panel for an output without indices. Returns the files
    /// written.
    pub fn draw(&self, dir: &Path) -> Result<Vec<PathBuf>, StudyError> {
        let Ok(analysis) = &self.analysis else {
            return Ok(Vec::new());
        };
        let mut written = Vec::new();
        let indices: Vec<BarPanel> = analysis
            .iter()
            .filter_map(|o| self.index_panel(o))
            .collect();
        if !indices.is_empty() {
            let title = match analysis.first().map(|o| &o.indices) {
                Some(Indices::Morris(_)) => "Morris: μ* of the ensemble mean, 95 % intervals",
                _ => "Sobol: S1 and ST of the ensemble mean, 95 % intervals",
            };
            written.push(dir.join("indices.png"));
            draw_bars(title, &indices, COLUMNS, &written[written.len() - 1])?;
        }
        let morris: Vec<Panel> = analysis
            .iter()
            .filter_map(|o| self.morris_panel(o))
            .collect();
        if !morris.is_empty() {
            written.push(dir.join("morris.png"));
            let title = "Morris: μ* against σ of the elementary effects";
            draw_panels(title, &morris, COLUMNS, &written[written.len() - 1])?;
        }
        let tornado: Vec<BarPanel> = self
            .outputs
            .iter()
            .filter_map(|o| self.tornado_panel(o))
            .collect();
        if !tornado.is_empty() {
            written.push(dir.join("tornado.png"));
            let title =
                "Tornado: each key at the ends of its range, the others at the case's values";
            draw_bars(title, &tornado, COLUMNS, &written[written.len() - 1])?;
        }
        Ok(written)
    }

    /// Output `o`'s indices by key: S1 and ST (Sobol), μ* (Morris), each
    /// with its interval; None without indices.
    fn index_panel(&self, o: &OutputIndices) -> Option<BarPanel> {
        let interval = |i: &super::bootstrap::Interval| Bar {
            value: i.value,
            low: i.low,
            high: i.high,
        };
        let (series, x_label) = match &o.indices {
            Indices::Sobol(Some(all)) => (
                vec![
                    series("S1", all.inputs.iter().map(|i| interval(&i.s1)).collect()),
                    series("ST", all.inputs.iter().map(|i| interval(&i.st)).collect()),
                ],
                format!("{}: S1, ST (–)", o.name),
            ),
            Indices::Morris(all) => (
                vec![series(
                    "μ*",
                    all.iter().map(|i| interval(&i.mu_star)).collect(),
                )],
                format!("{}: μ* ({})", o.name, per_range(&o.name)),
            ),
            Indices::Sobol(None) | Indices::Undefined { .. } => return None,
        };
        Some(BarPanel {
            x_label,
            categories: self.keys.clone(),
            series,
            origin: 0.0,
            origin_label: String::new(),
        })
    }

    /// Output `o`'s keys as points (μ*, σ), one series a key, and the
    /// line σ = μ* from the origin: above it a key's effects change sign
    /// or size across the ranges (interactions, non-linearity), below it
    /// they are near one value (Morris only).
    fn morris_panel(&self, o: &OutputIndices) -> Option<Panel> {
        let Indices::Morris(all) = &o.indices else {
            return None;
        };
        let unit = per_range(&o.name);
        let points = self.keys.iter().zip(all);
        let mut series: Vec<Series> = points
            .map(|(key, i)| Series::points(key, vec![(i.mu_star.value, i.sigma)]))
            .collect();
        let ends = all.iter().flat_map(|i| [i.mu_star.value, i.sigma]);
        let top = ends.filter(|v| v.is_finite()).fold(0.0, f64::max);
        series.push(Series::line("σ = μ*", vec![(0.0, 0.0), (top, top)]));
        Some(Panel {
            x_label: format!("{}: μ* ({unit})", o.name),
            y_label: format!("σ ({unit})"),
            series,
        })
    }

    /// Output `name`'s tornado: each key's bars to its value at lo and at
    /// hi from the case's, widest range on top; None without a tornado or
    /// a case value of the output.
    fn tornado_panel(&self, name: &str) -> Option<BarPanel> {
        let ranges = self.tornado_ranges(name)?;
        if !ranges.case.is_finite() {
            return None;
        }
        let keys = &ranges.keys;
        let categories = keys
            .iter()
            .map(|r| self.study.ranges[r.0].key.clone())
            .collect();
        Some(BarPanel {
            x_label: format!("{name} ({})", unit_of(name)),
            categories,
            series: vec![
                series("key at lo", keys.iter().map(|r| Bar::plain(r.1)).collect()),
                series("key at hi", keys.iter().map(|r| Bar::plain(r.2)).collect()),
            ],
            origin: ranges.case,
            origin_label: "the case".to_string(),
        })
    }
}

/// The unit of an elementary effect of output `name`: its unit per key
/// range (the range taken as 1).
fn per_range(name: &str) -> String {
    match unit_of(name) {
        "–" => "per key range".to_string(),
        unit => format!("{unit} per key range"),
    }
}

fn series(label: &str, bars: Vec<Bar>) -> BarSeries {
    BarSeries {
        label: label.to_string(),
        bars,
    }
}
