//! The look every picture shares: the bundled font, text sizes and colours.

use plotters::prelude::*;
use std::sync::Once;

/// The font family every picture uses; the bundled DejaVu Sans is
/// registered under it, and SVG viewers substitute their own sans-serif.
pub const FAMILY: &str = "sans-serif";

pub(crate) static FONT: &[u8] = include_bytes!("../fonts/DejaVuSans.ttf");

/// Registers the bundled font (once per process).
pub fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        if plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_err() {
            panic!("the bundled DejaVu Sans is a valid font");
        }
    });
}

/// Text sizes in pixels for one picture size.
#[derive(Clone, Copy, Debug)]
pub struct Sizes {
    pub title: u32,
    /// Axis descriptions and legend entries.
    pub desc: u32,
    /// Tick labels.
    pub tick: u32,
    /// Curve width.
    pub line: u32,
}

/// For the 1200 px wide pictures (8 in at 150 dpi): 30/26/22 px ≈ 14/12.5/10.5 pt.
pub const PAPER: Sizes = Sizes {
    title: 30,
    desc: 26,
    tick: 22,
    line: 3,
};

/// For the animation frames.
pub const SMALL: Sizes = Sizes {
    title: 20,
    desc: 18,
    tick: 15,
    line: 2,
};

pub const GRID: RGBColor = RGBColor(215, 215, 215);
pub const GROUND: RGBColor = RGBColor(236, 226, 202);
pub const GROUND_EDGE: RGBColor = RGBColor(110, 90, 60);
pub const BLADE: RGBColor = RGBColor(70, 70, 70);
pub const CURVE: RGBColor = RGBColor(31, 119, 180);
pub const SHEAR: RGBColor = RGBColor(160, 60, 40);
/// The side heaps' crest beside a blade of finite width.
pub const RIDGE: RGBColor = RGBColor(60, 110, 170);

/// Distinct colours for overlaid curves (Tableau 10).
pub const SERIES: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

/// The viridis colour map at t ∈ [0, 1], stopped at 0.85 so that the
/// lightest colour stays visible on the ground's fill.
pub fn viridis(t: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 44, 122),
        (59, 81, 139),
        (44, 113, 142),
        (33, 144, 141),
        (39, 173, 129),
        (92, 200, 99),
        (170, 220, 50),
        (253, 231, 37),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    } * 0.85;
    let s = t * (STOPS.len() - 1) as f64;
    let i = (s.floor() as usize).min(STOPS.len() - 2);
    let f = s - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

pub fn font(size: u32) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&BLACK)
}
