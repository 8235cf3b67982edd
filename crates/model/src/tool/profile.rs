//! A tool's profile: a polyline in the tool's own frame (x forward, y up
//! at rotation 0, lengths in the case's unit) from the cutting edge, its
//! first point. The soil side is on the right walking from the edge: +x
//! of a blade rising from its edge, above a bucket's floor running back
//! from its lip.

use crate::case::CaseError;

/// Points closer than this fraction of the profile's size are one point.
const COINCIDENT: f64 = 1e-12;

/// A tool's profile, checked: at least two points, finite, no piece of
/// zero length, no two pieces crossing or overlapping.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    points: Vec<[f64; 2]>,
}

impl Profile {
    /// The profile through `points` from the cutting edge; the error names
    /// `key` and what is wrong.
    pub fn new(points: Vec<[f64; 2]>, key: &str) -> Result<Self, CaseError> {
        if points.len() < 2 {
            return Err(CaseError::new(
                key,
                format!(
                    "needs at least two points, the cutting edge first (got {})",
                    points.len()
                ),
            ));
        }
        if let Some(i) = points.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
            return Err(CaseError::new(
                key,
                format!("point {i} is not finite (got {:?})", points[i]),
            ));
        }
        let profile = Profile { points };
        profile.check_pieces(key)?;
        Ok(profile)
    }

    /// The points, the cutting edge first.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// The largest distance of a point from the cutting edge.
    pub fn size(&self) -> f64 {
        let [x0, y0] = self.points[0];
        self.points
            .iter()
            .map(|[x, y]| (x - x0).hypot(y - y0))
            .fold(0.0, f64::max)
    }

    /// The face's angle at the cutting edge from the horizontal on the soil
    /// side, degrees, at rotation 0 (90: a vertical blade; less: its first
    /// piece leans back; more: it leans forward): α = atan2(Δy, −Δx) of the
    /// first piece.
    pub fn edge_angle(&self) -> f64 {
        let ([x0, y0], [x1, y1]) = (self.points[0], self.points[1]);
        (y1 - y0).atan2(x0 - x1).to_degrees()
    }

    /// Whether every point lies on the ray of the first piece from the
    /// cutting edge (a straight blade), to round-off.
    pub fn is_straight(&self) -> bool {
        let [x0, y0] = self.points[0];
        let [x1, y1] = self.points[1];
        let (dx, dy) = (x1 - x0, y1 - y0);
        let length = dx.hypot(dy);
        self.points[2..].iter().all(|&[x, y]| {
            let (px, py) = (x - x0, y - y0);
            let across = (dx * py - dy * px) / length;
            let along = (dx * px + dy * py) / length;
            across.abs() <= 1e-9 * self.size() && along > 0.0
        })
    }

    fn check_pieces(&self, key: &str) -> Result<(), CaseError> {
        let tiny = COINCIDENT * self.size();
        let pieces: Vec<[[f64; 2]; 2]> = self.points.windows(2).map(|w| [w[0], w[1]]).collect();
        for (i, [a, b]) in pieces.iter().enumerate() {
            if (b[0] - a[0]).hypot(b[1] - a[1]) <= tiny {
                return Err(CaseError::new(
                    key,
                    format!(
                        "points {i} and {} coincide: every piece needs a length",
                        i + 1
                    ),
                ));
            }
        }
        for i in 0..pieces.len() {
            for j in i + 1..pieces.len() {
                if pieces_meet(pieces[i], pieces[j], j == i + 1) {
                    return Err(CaseError::new(
                        key,
                        format!(
                            "crosses itself: piece {i} (points {i}-{}) meets piece {j} (points {j}-{})",
                            i + 1,
                            j + 1
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

/// The z of the cross product (b − a) × (c − a): > 0 where c is left of
/// the line a → b.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether c, on the line of a → b, lies within the segment a-b.
fn within(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    let t = (c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1]) * (b[1] - a[1]);
    t >= 0.0 && t <= (b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)
}

/// Whether two pieces share a point; `adjacent` pieces share their joint,
/// which does not count, but they meet where one folds back along the
/// other.
fn pieces_meet([a, b]: [[f64; 2]; 2], [c, d]: [[f64; 2]; 2], adjacent: bool) -> bool {
    if adjacent {
        // b == c: they overlap only if collinear and turning back.
        let back = (b[0] - a[0]) * (d[0] - c[0]) + (b[1] - a[1]) * (d[1] - c[1]);
        let lengths = (b[0] - a[0]).hypot(b[1] - a[1]) * (d[0] - c[0]).hypot(d[1] - c[1]);
        return orient(a, b, d).abs() <= 1e-12 * lengths && back < 0.0;
    }
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return true;
    }
    (o1 == 0.0 && within(a, b, c))
        || (o2 == 0.0 && within(a, b, d))
        || (o3 == 0.0 && within(c, d, a))
        || (o4 == 0.0 && within(c, d, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vertical_blade_has_the_paper_s_face_angle() {
        let p = Profile::new(vec![[0.0, 0.0], [0.0, 70.0]], "tool.points").unwrap();
        assert_eq!(p.edge_angle(), 90.0);
        assert!(p.is_straight());
        let raked = Profile::new(vec![[0.0, 0.0], [-1.0, 3f64.sqrt()]], "k").unwrap();
        assert!((raked.edge_angle() - 60.0).abs() < 1e-12);
    }

    #[test]
    fn a_profile_that_crosses_itself_is_refused_naming_the_pieces() {
        let z = vec![[0.0, 0.0], [0.0, 10.0], [-5.0, 2.0], [5.0, 5.0]];
        let e = Profile::new(z, "tool.points").unwrap_err();
        assert_eq!(e.key, "tool.points");
        assert!(e.message.contains("crosses itself: piece 0"), "{e}");
        // Folding back along itself is crossing too.
        let fold = vec![[0.0, 0.0], [0.0, 10.0], [0.0, 4.0]];
        assert!(Profile::new(fold, "k").is_err());
        // A closed hook touching its own edge.
        let hook = vec![[0.0, 0.0], [0.0, 10.0], [-5.0, 10.0], [0.0, 0.0]];
        assert!(Profile::new(hook, "k").is_err());
    }

    #[test]
    fn too_few_or_coincident_or_non_finite_points_are_refused() {
        assert!(Profile::new(vec![[0.0, 0.0]], "k").is_err());
        assert!(Profile::new(vec![[0.0, 0.0], [0.0, 0.0], [0.0, 1.0]], "k").is_err());
        assert!(Profile::new(vec![[0.0, 0.0], [f64::NAN, 1.0]], "k").is_err());
    }

    #[test]
    fn a_bent_profile_is_not_straight() {
        let bent = Profile::new(vec![[0.0, 0.0], [0.0, 10.0], [1.0, 20.0]], "k").unwrap();
        assert!(!bent.is_straight());
    }
}
