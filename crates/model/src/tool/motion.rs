//! The motion of a tool: its pose (x, y of its pivot in the world, its
//! rotation about the pivot) as a piecewise-linear function of a progress
//! s (a length: the run's increments are steps of s), from s = 0 to the
//! last pose's s, which is the run's travel.

use crate::case::CaseError;

/// Largest rotation a pose may give, degrees either way.
pub const MAX_ROTATION: f64 = 360.0;

/// A tool's pose: its pivot at (x, y) in the world (x from the cutting
/// edge's start, y up from the undisturbed surface) and its `rotation`
/// about the pivot, degrees, counter-clockwise positive (a bucket's curl,
/// its lip turning up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// x of the pivot.
    pub x: f64,
    /// y of the pivot.
    pub y: f64,
    /// Rotation about the pivot, degrees.
    pub rotation: f64,
}

impl Pose {
    /// Where the tool-frame point `p` is in the world at this pose, with
    /// `pivot` the pivot in the tool's frame.
    pub fn place(&self, pivot: [f64; 2], p: [f64; 2]) -> [f64; 2] {
        let (sin, cos) = self.rotation.to_radians().sin_cos();
        let (dx, dy) = (p[0] - pivot[0], p[1] - pivot[1]);
        if self.rotation == 0.0 {
            // Exactly a translation, so that a translating tool's points
            // are its pose's sums (a straight blade's depth is exact).
            return [self.x + dx, self.y + dy];
        }
        [self.x + cos * dx - sin * dy, self.y + sin * dx + cos * dy]
    }
}

/// A pose path: poses at strictly increasing s from s = 0, linear between.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// (s, pose), s strictly increasing, the first at 0.
    poses: Vec<(f64, Pose)>,
}

impl Motion {
    /// The motion through `rows` [s, x, y, rotation], the error naming
    /// `key`: at least two, finite, s from 0 strictly increasing (the path
    /// never goes back in its parameter), rotations within ±`MAX_ROTATION`.
    pub fn new(rows: &[[f64; 4]], key: &str) -> Result<Self, CaseError> {
        if rows.len() < 2 {
            return Err(CaseError::new(
                key,
                format!(
                    "needs at least two poses [s, x, y, rotation] (got {})",
                    rows.len()
                ),
            ));
        }
        for (i, row) in rows.iter().enumerate() {
            if !row.iter().all(|v| v.is_finite()) {
                return Err(CaseError::new(
                    key,
                    format!("pose {i} is not finite (got {row:?})"),
                ));
            }
            if row[3].abs() > MAX_ROTATION {
                return Err(CaseError::new(
                    key,
                    format!(
                        "pose {i}: rotation must be within ±{MAX_ROTATION}° (got {}°)",
                        row[3]
                    ),
                ));
            }
        }
        if rows[0][0] != 0.0 {
            return Err(CaseError::new(
                key,
                format!("the first pose is at s = 0 (got s = {})", rows[0][0]),
            ));
        }
        if let Some(i) = (1..rows.len()).find(|&i| rows[i][0] <= rows[i - 1][0]) {
            return Err(CaseError::new(
                key,
                format!(
                    "goes backwards in s: pose {i} at s = {} after s = {} (s must increase strictly)",
                    rows[i][0],
                    rows[i - 1][0]
                ),
            ));
        }
        let poses = rows
            .iter()
            .map(|&[s, x, y, rotation]| (s, Pose { x, y, rotation }))
            .collect();
        Ok(Motion { poses })
    }

    /// The poses with their s.
    pub fn poses(&self) -> &[(f64, Pose)] {
        &self.poses
    }

    /// The last pose's s: the run's travel.
    pub fn travel(&self) -> f64 {
        self.poses.last().expect("a motion has poses").0
    }

    /// The pose at progress `s`, linear between poses, the end poses held
    /// beyond the ends.
    pub fn at(&self, s: f64) -> Pose {
        let i = self.poses.partition_point(|(si, _)| *si <= s);
        if i == 0 {
            return self.poses[0].1;
        }
        if i == self.poses.len() {
            return self.poses[i - 1].1;
        }
        let ((s0, a), (s1, b)) = (self.poses[i - 1], self.poses[i]);
        let t = (s - s0) / (s1 - s0);
        let mix = |p: f64, q: f64| p + t * (q - p);
        Pose {
            x: mix(a.x, b.x),
            y: mix(a.y, b.y),
            rotation: mix(a.rotation, b.rotation),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pose_path_going_backwards_is_refused_naming_the_pose() {
        let rows = [
            [0.0, 0.0, 0.0, 0.0],
            [5.0, 5.0, 0.0, 0.0],
            [4.0, 6.0, 0.0, 0.0],
        ];
        let e = Motion::new(&rows, "tool.motion").unwrap_err();
        assert_eq!(e.key, "tool.motion");
        assert!(e.message.contains("goes backwards in s: pose 2"), "{e}");
        let late = [[1.0, 0.0, 0.0, 0.0], [5.0, 5.0, 0.0, 0.0]];
        assert!(Motion::new(&late, "tool.motion").is_err());
        let spun = [[0.0, 0.0, 0.0, 0.0], [5.0, 5.0, 0.0, 400.0]];
        assert!(Motion::new(&spun, "tool.motion").is_err());
    }

    #[test]
    fn poses_are_linear_between_and_held_beyond() {
        let rows = [[0.0, 0.0, -2.0, 0.0], [10.0, 10.0, -4.0, 30.0]];
        let m = Motion::new(&rows, "k").unwrap();
        let p = m.at(2.5);
        assert_eq!((p.x, p.y, p.rotation), (2.5, -2.5, 7.5));
        assert_eq!(m.at(12.0), m.at(10.0));
        assert_eq!(m.travel(), 10.0);
    }

    #[test]
    fn a_rotation_turns_points_about_the_pivot() {
        let pose = Pose {
            x: 1.0,
            y: 2.0,
            rotation: 90.0,
        };
        let q = pose.place([0.0, 1.0], [1.0, 1.0]);
        assert!((q[0] - 1.0).abs() < 1e-15 && (q[1] - 3.0).abs() < 1e-15);
    }
}
