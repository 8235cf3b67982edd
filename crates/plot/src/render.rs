//! Pictures to files: PNG (150 dpi), SVG, and the errors of both.

use crate::style;
use crate::typeset::Typeset;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt;
use std::path::{Path, PathBuf};

/// Resolution written into PNG files: 150 dots per inch.
pub const PNG_DPI: u32 = 150;

/// Why a picture could not be drawn or written.
#[derive(Debug)]
pub struct PlotError {
    /// The file that could not be drawn or written.
    pub path: PathBuf,
    /// What went wrong, on one line.
    pub message: String,
}

impl PlotError {
    pub(crate) fn new(path: &Path, message: impl ToString) -> Self {
        PlotError {
            path: path.to_path_buf(),
            message: message
                .to_string()
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" "),
        }
    }
}

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.message)
    }
}

impl std::error::Error for PlotError {}

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

/// Errors of drawing, as text (plotters' errors depend on the backend).
pub(crate) type DrawResult = Result<(), String>;

/// Converts any drawing error into the message of a [`DrawResult`].
pub(crate) fn text<E: fmt::Display>(e: E) -> String {
    e.to_string()
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
    style::register_font();
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
    style::register_font();
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
