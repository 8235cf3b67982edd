//! The blade's geometry in the ground pictures, in units of the blade
//! depth d: a plate whose face runs from the tip (u, −1) up and back at the
//! rake α, the points (u − s cos α, −1 + s sin α), s ≥ 0 (α = 90°: the
//! vertical blade). The soil in front lies above the face line, the trench
//! floor behind the tip at y = −1.

use crate::style::Extent;

/// Whether `rake` (degrees) is the vertical blade, drawn exactly as before
/// inclined blades existed (an axis-aligned rectangle).
pub(crate) fn is_vertical(rake: f64) -> bool {
    rake == 90.0
}

/// The blade's outline: a plate `thickness` thick (normal to the face)
/// behind the face, from the tip (`tip_x`, −1) along the face up to
/// y = `top`, its ends cut horizontally (so the tip sits on the trench
/// floor), clipped to x ≥ `left` (a low rake reaches far back). Corners
/// counter-clockwise from the back of the tip; the face is the edge from
/// the second corner (the tip) to the third.
pub(crate) fn blade_outline(
    tip_x: f64,
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
    let top_x = tip_x - (top + 1.0) * cot;
    let plate = [
        (tip_x - width, -1.0),
        (tip_x, -1.0),
        (top_x, top),
        (top_x - width, top),
    ];
    clip_left(&plate, left)
}

/// The soil in front of the blade as a polygon, from the bottom of the
/// picture below the tip (`tip_x`, −1) up to the tip, along the face to
/// the first point of `surface` (where the face meets it, in units of d),
/// along the surface and down the right edge. For the vertical blade the
/// tip is left out (it lies on the straight edge up to the surface), which
/// keeps those pictures as they were drawn before inclined blades.
pub(crate) fn ground_outline(
    surface: &[(f64, f64)],
    tip_x: f64,
    rake: f64,
    ext: Extent,
) -> Vec<(f64, f64)> {
    let floor = ext.y.0;
    let mut outline = vec![(tip_x, floor)];
    if !is_vertical(rake) {
        outline.push((tip_x, -1.0));
    }
    outline.extend_from_slice(surface);
    let last_y = outline.last().map_or(0.0, |p| p.1);
    outline.push((ext.x.1, last_y));
    outline.push((ext.x.1, floor));
    outline
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
        let b = blade_outline(3.0, 90.0, 0.1, 2.0, -0.25);
        assert_eq!(b, vec![(2.9, -1.0), (3.0, -1.0), (3.0, 2.0), (2.9, 2.0)]);
    }

    #[test]
    fn inclined_face_runs_from_the_tip_up_and_back_at_the_rake() {
        let (tip, t, top) = (5.0, 0.1, 2.0);
        for rake in [20.0f64, 45.0, 60.0, 89.0] {
            let b = blade_outline(tip, rake, t, top, -100.0);
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
        let g = ground_outline(&surface, tip, rake, ext);
        assert_eq!(g[..3], [(tip, -1.25), (tip, -1.0), start]);
        assert_eq!(g[g.len() - 2..], [(8.0, 0.0), (8.0, -1.25)]);
        // The edge from the tip to the surface is the face, at α.
        let angle = (g[2].1 - g[1].1).atan2(g[1].0 - g[2].0).to_degrees();
        assert!((angle - rake).abs() < 1e-9, "{angle}");
        // Vertical: no extra corner at the tip.
        let v = ground_outline(&[(tip, 1.2), (7.0, 0.0)], tip, 90.0, ext);
        assert_eq!(v[..2], [(tip, -1.25), (tip, 1.2)]);
        assert_eq!(v.len(), 5);
    }

    #[test]
    fn a_low_rake_is_clipped_at_the_left_edge() {
        let left = -0.25;
        let b = blade_outline(0.0, 20.0, 0.1, 1.0, left);
        assert!(b.iter().all(|p| p.0 >= left - 1e-12), "{b:?}");
        assert!(b.iter().any(|p| p.0 == left));
        assert_eq!(b[1], (0.0, -1.0), "the tip stays");
        assert!(area2(&b) > 0.0);
        // Entirely in view: unchanged.
        let whole = blade_outline(4.0, 20.0, 0.1, 0.5, left);
        assert_eq!(whole.len(), 4);
        assert!(whole.iter().all(|p| p.0 > left));
    }
}
