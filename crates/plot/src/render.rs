//! Pictures to files: PNG (150 dpi) and SVG.

use crate::error::{text, DrawResult, PlotError};
use crate::theme;
use crate::typeset::Typeset;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Resolution written into PNG files: 150 dots per inch.
pub const PNG_DPI: u32 = 150;

/// A picture file format, chosen by the file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Portable Network Graphics, 150 dpi.
    Png,
    /// Scalable Vector Graphics, with real text.
    Svg,
}

impl Format {
    /// The file extension of the format, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Png => "png",
            Format::Svg => "svg",
        }
    }

    /// The format named by `path`'s extension (`.png` or `.svg`).
    pub fn of(path: &Path) -> Result<Format, PlotError> {
        match path.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("png") => Ok(Format::Png),
            Some(e) if e.eq_ignore_ascii_case("svg") => Ok(Format::Svg),
            _ => Err(PlotError::new(
                path,
                "the picture file must end in .png or .svg",
            )),
        }
    }
}

/// A picture that can be drawn on any plotters backend.
pub(crate) trait Picture {
    /// Width and height in pixels.
    fn size(&self) -> (u32, u32);
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult;
}

/// Draws `picture` into `path`, PNG or SVG by its extension.
pub(crate) fn save(picture: &impl Picture, path: &Path) -> Result<(), PlotError> {
    let format = Format::of(path)?;
    let bytes = match format {
        Format::Png => rgb(picture).and_then(|pixels| png_bytes(picture.size(), &pixels)),
        Format::Svg => svg(picture).map(String::into_bytes),
    };
    let bytes = bytes.map_err(|e| PlotError::new(path, e))?;
    std::fs::write(path, bytes).map_err(|e| PlotError::new(path, e))
}

/// The picture as RGB pixels, row by row.
pub(crate) fn rgb(picture: &impl Picture) -> Result<Vec<u8>, String> {
    theme::register_font();
    let (w, h) = picture.size();
    let mut buffer = vec![255u8; (w * h * 3) as usize];
    {
        let root = Typeset(BitMapBackend::with_buffer(&mut buffer, (w, h))).into_drawing_area();
        picture
            .draw(&root)
            .and_then(|()| root.present().map_err(text))?;
    }
    Ok(buffer)
}

fn svg(picture: &impl Picture) -> Result<String, String> {
    theme::register_font();
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, picture.size()).into_drawing_area();
        picture
            .draw(&root)
            .and_then(|()| root.present().map_err(text))?;
    }
    Ok(out)
}

/// Encodes RGB pixels as a PNG with a 150 dpi resolution chunk.
fn png_bytes((w, h): (u32, u32), rgb: &[u8]) -> Result<Vec<u8>, String> {
    let fail = text::<png::EncodingError>;
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let per_metre = (f64::from(PNG_DPI) / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(png::PixelDimensions {
        xppu: per_metre,
        yppu: per_metre,
        unit: png::Unit::Meter,
    }));
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(rgb).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{rgb, Picture};
    use crate::error::{text, DrawResult};
    use crate::theme::{font, FONT};
    use ab_glyph::{Font, FontRef, ScaleFont};
    use plotters::coord::Shift;
    use plotters::prelude::*;

    /// One line of black text on white, 40 px high.
    struct Line(&'static str);

    impl Picture for Line {
        fn size(&self) -> (u32, u32) {
            (200, 60)
        }

        fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult {
            root.fill(&WHITE).map_err(text)?;
            root.draw(&Text::new(self.0, (10, 10), font(40)))
                .map_err(text)
        }
    }

    /// The runs of columns that hold ink, as (first, last) pixel columns.
    fn inked_runs(text: &'static str) -> Vec<(usize, usize)> {
        let picture = Line(text);
        let (w, h) = picture.size();
        let pixels = rgb(&picture).unwrap();
        let inked = |x: usize| (0..h as usize).any(|y| pixels[(y * w as usize + x) * 3] < 128);
        let mut runs: Vec<(usize, usize)> = Vec::new();
        for x in 0..w as usize {
            if !inked(x) {
                continue;
            }
            match runs.last_mut() {
                Some(run) if run.1 + 1 == x => run.1 = x,
                _ => runs.push((x, x)),
            }
        }
        runs
    }

    /// Where the font puts each glyph's ink: the pen (advances and
    /// kerning) plus the glyph's left side bearing, from the font's metrics.
    fn ink_starts(text: &str, x: f32, size: f32) -> Vec<f32> {
        let font = FontRef::try_from_slice(FONT).unwrap();
        let font = font.as_scaled(size);
        let (mut pen, mut previous, mut starts) = (x, None, Vec::new());
        for c in text.chars() {
            let id = font.glyph_id(c);
            if let Some(p) = previous {
                pen += font.kern(p, id);
            }
            starts.push(pen + font.h_side_bearing(id));
            pen += font.h_advance(id);
            previous = Some(id);
        }
        starts
    }

    /// "(Jin" as the font sets it: each glyph's ink starts at the pen plus
    /// its bearing, so the J stands nearer the parenthesis than the i.
    /// Drawn from the pen without bearings (plotters), the J lay against
    /// the i and a gap opened after the parenthesis: "( Jin".
    #[test]
    fn glyphs_stand_where_the_font_puts_them() {
        let runs = inked_runs("(Jin");
        assert_eq!(runs.len(), 4, "{runs:?}");
        for (run, start) in runs.iter().zip(ink_starts("(Jin", 10.0, 40.0)) {
            assert!((run.0 as f32 - start).abs() <= 1.0, "{runs:?}: {start}");
        }
        let gap = |i: usize| runs[i + 1].0 - runs[i].1 - 1;
        assert!(gap(0) < gap(1), "\"( Jin\": {runs:?}");
    }
}
