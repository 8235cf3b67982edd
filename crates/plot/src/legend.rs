//! Legends: entries in rows above a picture's charts.

use crate::error::{text, DrawResult};
use crate::theme::{font, register_font, Sizes};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

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
