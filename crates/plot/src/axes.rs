//! Titles, axes and tick labels of the charts, and round axis ends.

use crate::error::{text, DrawResult};
use crate::theme::{font, Sizes, GRID};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Tick labels without trailing zeros: 0.5, 1, 2.25, −0.4.
pub fn tick(v: &f64) -> String {
    let v = if v.abs() < 1e-12 { 0.0 } else { *v };
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.replace('-', "−")
}

/// Height of the title band of a picture whose title font is `size`.
pub fn title_height(size: u32) -> u32 {
    size * 2
}

/// Draws `title` centred in a band of [`title_height`] across the top of
/// `area` (in a smaller font if it would not fit) and returns the area
/// below it.
pub fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    size: u32,
) -> Result<DrawingArea<DB, Shift>, String> {
    let (band, rest) = area.split_vertically(title_height(size));
    let (width, height) = band.dim_in_pixel();
    let mut fitted = size;
    while fitted > 10 {
        let (w, _) = band
            .estimate_text_size(title, &font(fitted))
            .map_err(text)?;
        if w + 40 <= width {
            break;
        }
        fitted -= 1;
    }
    let style = font(fitted).pos(Pos::new(HPos::Center, VPos::Center));
    band.draw(&Text::new(
        title,
        (width as i32 / 2, height as i32 / 2),
        style,
    ))
    .map_err(text)?;
    Ok(rest)
}

pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Grid, ticks and axis descriptions of a chart.
pub fn axes<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    x_desc: &str,
    y_desc: &str,
    sizes: Sizes,
) -> DrawResult {
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let x_labels = (w / (sizes.tick * 5)).clamp(2, 10) as usize;
    let y_labels = (h / (sizes.tick * 2)).clamp(2, 8) as usize;
    let mut mesh = chart.configure_mesh();
    mesh.bold_line_style(GRID)
        .light_line_style(TRANSPARENT)
        .axis_desc_style(font(sizes.desc))
        .label_style(font(sizes.tick))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .x_labels(x_labels)
        .y_labels(y_labels)
        .x_desc(x_desc)
        .y_desc(y_desc);
    mesh.draw().map_err(text)
}

/// The largest value of `values`, or `fallback` if none is positive.
pub fn top(values: impl Iterator<Item = f64>, fallback: f64) -> f64 {
    let m = values.filter(|v| v.is_finite()).fold(0.0, f64::max);
    if m > 0.0 {
        m
    } else {
        fallback
    }
}

/// The smallest of 1, 1.2, … 2, 2.5, … 5, 6, … 10 × 10ⁿ at least `v` (a
/// round axis end): at most a fifth of the axis is left empty (1, 2, 2.5,
/// 5 alone left 40 % of a 3 d run's axis empty).
pub fn round_up(v: f64) -> f64 {
    if !(v.is_finite() && v > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(v.log10().floor());
    [
        1.0, 1.2, 1.4, 1.6, 1.8, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0,
    ]
    .into_iter()
    .map(|m| m * p)
    .find(|&c| c >= v * (1.0 - 1e-9))
    .unwrap_or(10.0 * p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_ends_leave_at_most_a_fifth_empty() {
        assert_eq!(round_up(3.0), 3.0);
        assert_eq!(round_up(3.5), 3.5);
        assert_eq!(round_up(3.2), 3.5);
        assert_eq!(round_up(1.3), 1.4);
        assert_eq!(round_up(0.46), 0.5);
        for k in 1..2000 {
            let v = k as f64 * 0.01;
            let end = round_up(v);
            assert!(
                end >= v * (1.0 - 1e-9) && (end - v) / end <= 0.2 + 1e-12,
                "{v}: {end}"
            );
        }
    }
}
