//! The shapes users have, made into profiles from a few parameters
//! (lengths in the case's unit, angles in degrees): the straight blade,
//! the curved blade and the bucket. Arcs are made of pieces of at most
//! `ARC_STEP` degrees (a chord within R (1 − cos 1°) ≈ 1.5e-4 R of the
//! arc).

use super::profile::Profile;
use crate::case::validate::{open_range, positive};
use crate::case::CaseError;

/// The largest turn of one piece of an arc, degrees.
const ARC_STEP: f64 = 2.0;

/// A tool's shape as the case file gives it.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Today's blade: a straight face above its cutting edge.
    Straight {
        /// α from the horizontal on the soil side, degrees (90: vertical).
        rake: f64,
        /// The face's top above the edge, a length.
        height: f64,
    },
    /// A curved blade: an arc from its cutting edge turning toward the
    /// soil (a moldboard that curls forward at its top).
    Curved {
        /// The face's angle at the edge, as a rake, degrees.
        edge_angle: f64,
        /// The arc's radius, a length.
        radius: f64,
        /// The arc's turn, degrees.
        sweep: f64,
    },
    /// A bucket: from its lip, a flat floor running back, then a back wall
    /// turning up to the rim.
    Bucket {
        /// The floor's length.
        floor: f64,
        /// The back wall's radius, a length.
        back_radius: f64,
        /// The back wall's turn, degrees (180: a semicircle whose end, the
        /// rim, is above the floor's end).
        back_sweep: f64,
    },
    /// Any polyline, the cutting edge first.
    Points(Vec<[f64; 2]>),
}

impl Shape {
    /// The profile of the shape, cutting edge at the origin (for `Points`,
    /// where the case puts it); the error names the key under `tool`.
    pub fn profile(&self) -> Result<Profile, CaseError> {
        match self {
            Shape::Straight { rake, height } => {
                open_range("tool.rake", *rake, 0.0, 180.0, "°")?;
                positive("tool.height", *height)?;
                // cot 90° is 0 exactly, so a vertical blade's top is above its edge.
                let cot = if *rake == 90.0 {
                    0.0
                } else {
                    1.0 / rake.to_radians().tan()
                };
                Profile::new(vec![[0.0, 0.0], [-height * cot, *height]], "tool.rake")
            }
            Shape::Curved {
                edge_angle,
                radius,
                sweep,
            } => {
                open_range("tool.edge_angle", *edge_angle, 0.0, 180.0, "°")?;
                positive("tool.radius", *radius)?;
                open_range("tool.sweep", *sweep, 0.0, 180.0, "°")?;
                let mut points = vec![[0.0, 0.0]];
                arc(&mut points, 180.0 - edge_angle, *radius, *sweep);
                Profile::new(points, "tool.sweep")
            }
            Shape::Bucket {
                floor,
                back_radius,
                back_sweep,
            } => {
                positive("tool.floor", *floor)?;
                positive("tool.back_radius", *back_radius)?;
                open_range("tool.back_sweep", *back_sweep, 0.0, 270.0, "°")?;
                let mut points = vec![[0.0, 0.0], [-floor, 0.0]];
                arc(&mut points, 180.0, *back_radius, *back_sweep);
                Profile::new(points, "tool.back_sweep")
            }
            Shape::Points(points) => Profile::new(points.clone(), "tool.points"),
        }
    }
}

/// Appends to `points` an arc of `radius` from their last point, leaving
/// it on `heading` and turning right (toward the soil side) through
/// `sweep`, in pieces of at most `ARC_STEP`.
fn arc(points: &mut Vec<[f64; 2]>, heading: f64, radius: f64, sweep: f64) {
    let start = *points.last().expect("an arc starts from a point");
    let h = heading.to_radians();
    // The centre is on the right of the heading.
    let centre = [start[0] + radius * h.sin(), start[1] - radius * h.cos()];
    let pieces = (sweep / ARC_STEP).ceil().max(1.0) as usize;
    for k in 1..=pieces {
        let turned = h - (sweep * k as f64 / pieces as f64).to_radians();
        points.push([
            centre[0] - radius * turned.sin(),
            centre[1] + radius * turned.cos(),
        ]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: [f64; 2], b: [f64; 2]) -> bool {
        (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12
    }

    #[test]
    fn a_straight_shape_is_the_blade_of_its_rake_and_height() {
        let p = Shape::Straight {
            rake: 60.0,
            height: 30.0,
        }
        .profile()
        .unwrap();
        assert!(p.is_straight());
        assert!((p.edge_angle() - 60.0).abs() < 1e-12);
        let top = p.points()[1];
        assert!((top[1] - 30.0).abs() < 1e-12 && (top[0] + 30.0 / 3f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn the_bucket_s_back_wall_is_a_semicircle_ending_above_the_floor_s_end() {
        let p = Shape::Bucket {
            floor: 40.0,
            back_radius: 30.0,
            back_sweep: 180.0,
        }
        .profile()
        .unwrap();
        let pts = p.points();
        assert_eq!(pts.len(), 2 + 90);
        assert!(near(pts[1], [-40.0, 0.0]));
        assert!(near(pts[1 + 45], [-70.0, 30.0]));
        assert!(near(*pts.last().unwrap(), [-40.0, 60.0]));
        for q in &pts[1..] {
            let r = (q[0] + 40.0).hypot(q[1] - 30.0);
            assert!((r - 30.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_curved_blade_leaves_its_edge_at_its_edge_angle_and_curls_forward() {
        let p = Shape::Curved {
            edge_angle: 60.0,
            radius: 50.0,
            sweep: 90.0,
        }
        .profile()
        .unwrap();
        // The first piece's angle is the edge angle plus half its turn.
        assert!((p.edge_angle() - 61.0).abs() < 1e-9);
        let top = *p.points().last().unwrap();
        // At α = 150° the face leans forward: the top is ahead of the arc's
        // farthest point back.
        let back = p
            .points()
            .iter()
            .map(|q| q[0])
            .fold(f64::INFINITY, f64::min);
        assert!(top[0] > back && top[1] > 0.0);
    }

    #[test]
    fn bad_parameters_name_their_key() {
        let e = Shape::Straight {
            rake: 0.0,
            height: 1.0,
        }
        .profile()
        .unwrap_err();
        assert_eq!(e.key, "tool.rake");
        let e = Shape::Bucket {
            floor: 40.0,
            back_radius: -1.0,
            back_sweep: 180.0,
        }
        .profile()
        .unwrap_err();
        assert_eq!(e.key, "tool.back_radius");
    }
}
