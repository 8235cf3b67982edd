//! The blade's geometry in the ground pictures, in units of the blade
//! depth d: a plate whose face runs from the tip (u, −t) up and back at the
//! rake α, the points (u − s cos α, −t + s sin α), s ≥ 0 (α = 90°: the
//! vertical blade), where t is the tip's depth (1 but for a blade that
//! follows a depth path). The soil in front lies above the face line, the
//! trench floor behind the tip where the tip went: y = −t(x).

use crate::ground::Extent;
use crate::{Increment, RunData};

/// Whether `rake` (degrees) is the vertical blade, drawn exactly as before
/// inclined blades existed (an axis-aligned rectangle).
pub(crate) fn is_vertical(rake: f64) -> bool {
    rake == 90.0
}

/// The blade's outline: a plate `thickness` thick (normal to the face)
/// behind the face, from the tip `tip` along the face up to
/// y = `top`, its ends cut horizontally (so the tip sits on the trench
/// floor), clipped to x ≥ `left` (a low rake reaches far back). Corners
/// counter-clockwise from the back of the tip; the face is the edge from
/// the second corner (the tip) to the third.
pub(crate) fn blade_outline(
    tip: (f64, f64),
    rake: f64,
    thickness: f64,
    top: f64,
    left: f64,
) -> Vec<(f64, f64)> {
    let alpha = rake.to_radians();
    let (cot, width) = if is_vertical(rake) {
        (0.0, thickness)
    } else {
        (1.0 / alpha.tan(), thickness / alpha.sin())
    };
    let (tip_x, tip_y) = tip;
    let top_x = tip_x - (top - tip_y) * cot;
    let plate = [
        (tip_x - width, tip_y),
        (tip_x, tip_y),
        (top_x, top),
        (top_x - width, top),
    ];
    clip_left(&plate, left)
}

/// The soil in front of the blade as a polygon, from the bottom of the
/// picture below the tip `tip` up to the tip, along the face to
/// the first point of `surface` (where the face meets it, in units of d),
/// along the surface and down the right edge. For the vertical blade the
/// tip is left out (it lies on the straight edge up to the surface), which
/// keeps those pictures as they were drawn before inclined blades.
pub(crate) fn ground_outline(
    surface: &[(f64, f64)],
    tip: (f64, f64),
    rake: f64,
    ext: Extent,
) -> Vec<(f64, f64)> {
    let floor = ext.y.0;
    let mut outline = vec![(tip.0, floor)];
    if !is_vertical(rake) {
        outline.push(tip);
    }
    outline.extend_from_slice(surface);
    let last_y = outline.last().map_or(0.0, |p| p.1);
    outline.push((ext.x.1, last_y));
    outline.push((ext.x.1, floor));
    outline
}

/// The trench floor behind the blade when its tip is at displacement `u`
/// (length), in units of d: y = −t(x)/d along the path the tip took, from
/// x = `left` (in units of d; behind the start the floor is at the
/// starting depth) to the tip (u/d, −t(u)/d), through the tip's position
/// at each increment between. Stretches at one depth are one segment, so a
/// blade at a constant depth gives the two points (`left`, −t), (u/d, −t).
pub(crate) fn trench_floor(run: &RunData, u: f64, left: f64) -> Vec<(f64, f64)> {
    let d = run.depth;
    let tip = (u / d, -run.tip_depth(u) / d);
    let start = (left, -run.tip_depth(left * d) / d);
    let mut floor = vec![start];
    let passed = run.history.iter().map(|h| (h.u / d, -h.depth / d));
    for p in passed.filter(|p| p.0 > left && p.0 < tip.0).chain([tip]) {
        // A point between two at its height adds nothing.
        if let [.., a, b] = floor[..] {
            if a.1 == b.1 && b.1 == p.1 {
                floor.pop();
            }
        }
        floor.push(p);
    }
    floor
}

/// Where the slip line (lower band boundary) of increment `h` starts, in
/// units of d: at the blade's tip then, (u, −t).
pub(crate) fn slip_start(h: &Increment, d: f64) -> (f64, f64) {
    (h.u / d, -h.depth / d)
}

/// The height of the polyline `floor` (x increasing) at `x`, its end
/// heights beyond its ends.
pub(crate) fn height_at(floor: &[(f64, f64)], x: f64) -> f64 {
    match floor.iter().position(|p| p.0 > x) {
        Some(0) => floor[0].1,
        Some(k) => {
            let (a, b) = (floor[k - 1], floor[k]);
            a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
        }
        None => floor.last().map_or(0.0, |p| p.1),
    }
}

/// Whether the trench floor `floor` is level (a blade at one depth).
pub(crate) fn is_level(floor: &[(f64, f64)]) -> bool {
    floor.iter().all(|p| p.1 == floor[0].1)
}

/// The part of the convex polygon `points` with x ≥ `left`
/// (Sutherland-Hodgman against one edge).
fn clip_left(points: &[(f64, f64)], left: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(points.len() + 2);
    for (i, &p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        let (p_in, q_in) = (p.0 >= left, q.0 >= left);
        if p_in {
            out.push(p);
        }
        if p_in != q_in {
            let t = (left - p.0) / (q.0 - p.0);
            out.push((left, p.1 + t * (q.1 - p.1)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: (f64, f64), b: (f64, f64)) -> bool {
        (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12
    }

    /// Twice the signed area (positive counter-clockwise).
    fn area2(p: &[(f64, f64)]) -> f64 {
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum()
    }

    #[test]
    fn vertical_blade_is_the_rectangle_behind_the_face() {
        let b = blade_outline((3.0, -1.0), 90.0, 0.1, 2.0, -0.25);
        assert_eq!(b, vec![(2.9, -1.0), (3.0, -1.0), (3.0, 2.0), (2.9, 2.0)]);
    }

    #[test]
    fn inclined_face_runs_from_the_tip_up_and_back_at_the_rake() {
        let (tip, t, top) = (5.0, 0.1, 2.0);
        for rake in [20.0f64, 45.0, 60.0, 89.0] {
            let b = blade_outline((tip, -1.0), rake, t, top, -100.0);
            assert_eq!(b.len(), 4, "{rake}");
            assert!(area2(&b) > 0.0, "{rake}: counter-clockwise");
            // The tip is on the trench floor and the face leaves it at α
            // from the horizontal, leaning back (up and to the left).
            assert_eq!(b[1], (tip, -1.0));
            let (dx, dy) = (b[2].0 - b[1].0, b[2].1 - b[1].1);
            assert!(dx < 0.0 && (dy - top - 1.0).abs() < 1e-12, "{rake}");
            let angle = dy.atan2(-dx).to_degrees();
            assert!((angle - rake).abs() < 1e-9, "{rake}: {angle}");
            // Points (u − s cos α, −1 + s sin α) are on the face.
            let a = rake.to_radians();
            let s = 1.7;
            let p = (tip - s * a.cos(), -1.0 + s * a.sin());
            let cross = dx * (p.1 - b[1].1) - dy * (p.0 - b[1].0);
            assert!(cross.abs() < 1e-12, "{rake}");
            // The back is parallel to the face, `t` behind it (normal
            // distance), and the plate's ends are horizontal.
            assert!(close((b[3].0 - b[0].0, b[3].1 - b[0].1), (dx, dy)));
            let normal = (b[1].0 - b[0].0) * a.sin();
            assert!((normal - t).abs() < 1e-12, "{rake}: {normal}");
            assert_eq!((b[0].1, b[3].1), (-1.0, top));
        }
    }

    #[test]
    fn soil_in_front_follows_the_face_from_the_tip_to_the_surface() {
        let ext = Extent {
            x: (-1.0, 8.0),
            y: (-1.25, 2.0),
        };
        let (tip, rake) = (5.0, 60.0f64);
        let cot = 1.0 / rake.to_radians().tan();
        // A surface starting on the face at height 1.2, then falling.
        let start = (tip - 2.2 * cot, 1.2);
        let surface = [start, (start.0 + 0.5, 1.2), (7.0, 0.0)];
        let g = ground_outline(&surface, (tip, -1.0), rake, ext);
        assert_eq!(g[..3], [(tip, -1.25), (tip, -1.0), start]);
        assert_eq!(g[g.len() - 2..], [(8.0, 0.0), (8.0, -1.25)]);
        // The edge from the tip to the surface is the face, at α.
        let angle = (g[2].1 - g[1].1).atan2(g[1].0 - g[2].0).to_degrees();
        assert!((angle - rake).abs() < 1e-9, "{angle}");
        // Vertical: no extra corner at the tip.
        let v = ground_outline(&[(tip, 1.2), (7.0, 0.0)], (tip, -1.0), 90.0, ext);
        assert_eq!(v[..2], [(tip, -1.25), (tip, 1.2)]);
        assert_eq!(v.len(), 5);
    }

    /// A run of 10 increments of 1 with d = 10, its tip deepening from 5
    /// to 10 over u = 2..6 (or at 10 throughout).
    fn run(deepening: bool) -> RunData {
        let depth = |u: f64| {
            if deepening {
                5.0 + 5.0 * ((u - 2.0) / 4.0).clamp(0.0, 1.0)
            } else {
                10.0
            }
        };
        let history = (0..10)
            .map(|i| {
                let u = i as f64;
                Increment {
                    step: i + 1,
                    u,
                    force_norm: 1.0,
                    beta_deg: 20.0,
                    x_emergence: u + 20.0,
                    y_emergence: 0.0,
                    depth: depth(u),
                }
            })
            .collect();
        RunData {
            depth: 10.0,
            history,
            ..RunData::default()
        }
    }

    #[test]
    fn tip_depth_follows_the_increments() {
        let r = run(true);
        assert_eq!(r.tip_depth(-1.0), 5.0, "the starting depth before");
        assert_eq!(r.tip_depth(2.0), 5.0);
        assert!((r.tip_depth(3.5) - 6.875).abs() < 1e-12);
        assert_eq!(r.tip_depth(9.0), 10.0);
        assert_eq!(r.final_position(), 10.0);
        assert_eq!(r.tip_depth(10.0), 10.0);
        assert_eq!(r.deepest(), 10.0);
        // A run ending on the slope: the last trend for one increment.
        let mut short = run(true);
        short.history.truncate(4);
        assert_eq!(short.final_position(), 4.0);
        assert!((short.tip_depth(4.0) - 7.5).abs() < 1e-12);
        assert!((short.tip_depth(9.0) - 7.5).abs() < 1e-12, "then constant");
        assert!((short.deepest() - 10.0).abs() < 1e-12, "at least d");
        let mut deeper = run(true);
        deeper.history[9].depth = 15.0;
        assert_eq!(deeper.deepest(), 20.0, "trend of the last increment");
        assert_eq!(RunData::default().tip_depth(3.0), 0.0);
    }

    #[test]
    fn a_constant_depth_floor_is_one_level_segment() {
        let r = run(false);
        let floor = trench_floor(&r, 10.0, -0.25);
        assert_eq!(floor, vec![(-0.25, -1.0), (1.0, -1.0)]);
        assert!(is_level(&floor));
        assert_eq!(slip_start(&r.history[3], r.depth), (0.3, -1.0));
    }

    #[test]
    fn a_deepening_floor_follows_the_tips_path() {
        let r = run(true);
        // Blade at u = 7.5: the floor is at the starting depth behind the
        // start and up to u = 2, slopes down to d at u = 6, then is level
        // to the tip.
        let floor = trench_floor(&r, 7.5, -0.25);
        assert!(!is_level(&floor));
        assert_eq!(floor[0], (-0.25, -0.5));
        assert_eq!(*floor.last().unwrap(), (0.75, -1.0), "the tip");
        for w in floor.windows(2) {
            assert!(w[0].0 < w[1].0 && w[0].1 >= w[1].1, "{floor:?}");
        }
        assert!(floor.contains(&(0.2, -0.5)) && floor.contains(&(0.6, -1.0)));
        for &(x, y) in &floor {
            assert!((y + r.tip_depth(x * r.depth) / r.depth).abs() < 1e-12);
        }
        for x in [-0.1, 0.1, 0.3, 0.45, 0.7] {
            let want = -r.tip_depth(x * r.depth) / r.depth;
            assert!((height_at(&floor, x) - want).abs() < 1e-12, "{x}");
        }
        // Level stretches are single segments.
        assert_eq!(floor.len(), 7, "{floor:?}");
        // Midway down the slope the tip is at that moment's depth.
        let floor = trench_floor(&r, 4.0, -0.25);
        assert_eq!(*floor.last().unwrap(), (0.4, -0.75));
        // Each slip line starts at its increment's tip.
        for h in &r.history {
            let (x, y) = slip_start(h, r.depth);
            assert_eq!((x, y), (h.u / 10.0, -h.depth / 10.0));
        }
        assert_eq!(slip_start(&r.history[0], r.depth), (0.0, -0.5));
    }

    #[test]
    fn the_picture_reaches_below_the_deepest_tip() {
        let surface = [crate::SurfacePoint {
            x: 0.0,
            y: 0.0,
            accumulated_shear: 0.0,
        }];
        let mut r = run(true);
        assert_eq!(Extent::of(&r, [&surface[..]]).y.0, -1.25);
        for h in &mut r.history {
            h.depth *= 2.0;
        }
        assert_eq!(Extent::of(&r, [&surface[..]]).y.0, -2.25);
    }

    #[test]
    fn a_low_rake_is_clipped_at_the_left_edge() {
        let left = -0.25;
        let b = blade_outline((0.0, -1.0), 20.0, 0.1, 1.0, left);
        assert!(b.iter().all(|p| p.0 >= left - 1e-12), "{b:?}");
        assert!(b.iter().any(|p| p.0 == left));
        assert_eq!(b[1], (0.0, -1.0), "the tip stays");
        assert!(area2(&b) > 0.0);
        // Entirely in view: unchanged.
        let whole = blade_outline((5.0, -1.0), 20.0, 0.1, 0.5, left);
        assert_eq!(whole.len(), 4);
        assert!(whole.iter().all(|p| p.0 > left));
    }
}
