//! Curves and dots on a chart, thinned to what its pixels can show.

use crate::axes::Chart;
use crate::error::text;
use plotters::prelude::*;

/// The points of a curve worth drawing at the chart's resolution: the
/// curve simplified (Ramer–Douglas–Peucker) to within half a pixel, so
/// every peak and jump stays while wide strokes stay clean (plotters widens
/// a path by polygonising it, which frays on many tiny segments).
pub fn thin<'a, DB: DrawingBackend + 'a>(
    chart: &Chart<'a, DB>,
    points: &[(f64, f64)],
) -> Vec<(f64, f64)> {
    const TOLERANCE: f64 = 0.5;
    let pixels: Vec<(f64, f64)> = points
        .iter()
        .map(|p| {
            let (x, y) = chart.backend_coord(p);
            (f64::from(x), f64::from(y))
        })
        .collect();
    if points.len() < 3 {
        return points.to_vec();
    }
    let mut keep = vec![false; points.len()];
    keep[0] = true;
    keep[points.len() - 1] = true;
    let mut stack = vec![(0, points.len() - 1)];
    while let Some((a, b)) = stack.pop() {
        let (pa, pb) = (pixels[a], pixels[b]);
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        let length = dx.hypot(dy);
        let distance = |p: (f64, f64)| {
            if length == 0.0 {
                (p.0 - pa.0).hypot(p.1 - pa.1)
            } else {
                ((p.0 - pa.0) * dy - (p.1 - pa.1) * dx).abs() / length
            }
        };
        let far = (a + 1..b)
            .map(|i| (i, distance(pixels[i])))
            .fold((a, 0.0), |m, c| if c.1 > m.1 { c } else { m });
        if far.1 > TOLERANCE {
            keep[far.0] = true;
            stack.push((a, far.0));
            stack.push((far.0, b));
        }
    }
    let mut out = Vec::new();
    let mut last = None;
    for (i, p) in points.iter().enumerate() {
        if keep[i] && last != Some(pixels[i]) {
            out.push(*p);
            last = Some(pixels[i]);
        }
    }
    out
}

/// Whether `DB` draws vectors (SVG), where wide strokes are exact; on
/// bitmaps plotters widens a path by polygonising it, which spikes at
/// sharp turns, so there a wide curve is drawn as one-pixel paths side by side.
pub fn is_vector<DB: DrawingBackend>() -> bool {
    std::any::type_name::<DB>().contains("SVGBackend")
}

/// Draws `points` as a curve of `color` and `width`, thinned by [`thin`].
pub fn curve<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    points: &[(f64, f64)],
    color: RGBColor,
    width: u32,
) -> Result<(), String> {
    let thinned = thin(chart, points);
    if is_vector::<DB>() || width <= 1 {
        chart
            .draw_series(LineSeries::new(thinned, color.stroke_width(width)))
            .map_err(text)?;
        return Ok(());
    }
    let pixels: Vec<(i32, i32)> = thinned.iter().map(|p| chart.backend_coord(p)).collect();
    let area = chart.plotting_area().strip_coord_spec();
    let (x0, y0) = chart.plotting_area().get_base_pixel();
    let w = width as i32;
    for dx in -(w - 1) / 2..=w / 2 {
        for dy in -(w - 1) / 2..=w / 2 {
            if w >= 3 && dx.abs() + dy.abs() > w / 2 + (w - 1) / 2 {
                continue;
            }
            let path: Vec<(i32, i32)> = pixels
                .iter()
                .map(|&(x, y)| (x - x0 + dx, y - y0 + dy))
                .collect();
            area.draw(&PathElement::new(path, color.stroke_width(1)))
                .map_err(text)?;
        }
    }
    Ok(())
}

/// Draws `points` as dots of `radius` pixels, one per pixel they fall on.
pub fn dots<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    points: &[(f64, f64)],
    color: RGBColor,
    radius: u32,
) -> Result<(), String> {
    let mut seen = std::collections::HashSet::new();
    let unique: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| seen.insert(chart.backend_coord(p)))
        .copied()
        .collect();
    chart
        .draw_series(
            unique
                .into_iter()
                .map(|p| Circle::new(p, radius, color.filled())),
        )
        .map_err(text)?;
    Ok(())
}
