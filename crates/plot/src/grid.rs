//! A grid of panels under one title: the layout of the studies' pictures
//! (points and lines, bars), one size and one set of text sizes for all.

use crate::axes::{title_height, titled};
use crate::error::{text, DrawResult};
use crate::render::{save, Picture};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Panel size in pixels.
const PANEL: (u32, u32) = (600, 450);
/// The narrowest picture: a single column of panels is as wide as the
/// run's pictures, so that its text is the same size beside them.
const MIN_WIDTH: u32 = 1200;
/// Title, axis descriptions, tick labels and legend entries, px: at 150
/// dpi about 12, 9.5, 8 and 8 pt (the run's pictures: 14, 12.5, 10.5).
pub(crate) const TITLE: u32 = 26;
pub(crate) const DESC: u32 = 20;
pub(crate) const TICK: u32 = 17;
pub(crate) const LEGEND: u32 = 17;

/// A chart that draws itself into one cell of a [`Grid`].
pub(crate) trait Cell {
    fn draw_cell<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> DrawResult;
}

/// Panels `columns` to a row under a title.
pub(crate) struct Grid<'a, P> {
    pub title: &'a str,
    pub panels: &'a [P],
    pub columns: usize,
    pub rows: usize,
}

impl<'a, P: Cell> Grid<'a, P> {
    /// `panels`, `columns` to a row (at least one, at most as many as
    /// there are panels).
    pub fn new(title: &'a str, panels: &'a [P], columns: usize) -> Self {
        let columns = columns.clamp(1, panels.len().max(1));
        Grid {
            title,
            panels,
            columns,
            rows: panels.len().div_ceil(columns).max(1),
        }
    }
}

impl<P: Cell> Picture for Grid<'_, P> {
    fn size(&self) -> (u32, u32) {
        (
            (PANEL.0 * self.columns as u32).max(MIN_WIDTH),
            PANEL.1 * self.rows as u32 + title_height(TITLE),
        )
    }

    /// Row by row; a last row with fewer panels shares the whole width
    /// among them, so that no panel is left empty.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
        root.fill(&WHITE).map_err(text)?;
        let body = titled(root, self.title, TITLE)?;
        let rows = body.split_evenly((self.rows, 1));
        for (panels, row) in self.panels.chunks(self.columns).zip(&rows) {
            for (panel, area) in panels.iter().zip(&row.split_evenly((1, panels.len()))) {
                panel.draw_cell(area)?;
            }
        }
        Ok(())
    }
}

/// Draws `panels`, `columns` to a row under `title`, into `path` (PNG or
/// SVG by its extension), each panel 600 × 450 px, the picture at least
/// 1200 px wide (a single column's panels widen).
pub(crate) fn draw_grid<P: Cell>(
    title: &str,
    panels: &[P],
    columns: usize,
    path: &Path,
) -> Result<(), PlotError> {
    save(&Grid::new(title, panels, columns), path)
}
