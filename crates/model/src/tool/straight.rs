//! The tools today's mechanism takes, (M55): a straight profile whose
//! rotation θ is constant and whose cutting edge moves forward at unit
//! rate in s, x_edge(s) = s, is the paper's blade of rake α = α0 − θ (α0
//! the profile's face angle at rotation 0; a counter-clockwise rotation
//! leans a vertical blade back) on the depth path of its edge,
//! d(u) = −y_edge(u) at u = s. Nothing else about such a tool enters the
//! mechanism: the face is the straight line through the edge, and where
//! the profile ends above the soil does not matter to it (a straight
//! blade is taller than its pile).

use super::{Pose, Shape, Tool};
use crate::case::{CaseError, ROUND_OFF};

/// A straight blade's keys, as a translating straight tool gives them.
#[derive(Clone, Debug, PartialEq)]
pub struct StraightCut {
    /// α, degrees.
    pub rake: f64,
    /// [u, d] at every pose; empty where every pose is at the reference
    /// depth (a blade at constant depth).
    pub depth_path: Vec<[f64; 2]>,
    /// The last pose's s.
    pub travel: f64,
    /// The pivot from the cutting edge in the world's axes, fixed as the
    /// tool translates (`Blade::pivot`).
    pub pivot: [f64; 2],
    /// θ, the tool's constant rotation, degrees.
    pub rotation: f64,
}

impl Tool {
    /// The tool as today's blade (M55), with `depth` the reference depth
    /// of normalised forces; the error says, naming the key, why this tool
    /// needs a mechanism not built yet.
    pub fn straight_cut(&self, depth: f64) -> Result<StraightCut, CaseError> {
        let profile = self.profile()?;
        if !profile.is_straight() {
            return Err(unbuilt(
                "tool.shape",
                "a curved or bent profile: soilcut cuts with straight profiles so far",
            ));
        }
        let poses = self.motion.poses();
        let rotation = poses[0].1.rotation;
        if let Some(i) = poses.iter().position(|(_, p)| p.rotation != rotation) {
            return Err(unbuilt(
                "tool.motion",
                &format!("pose {i} rotates the tool: soilcut's tools translate so far"),
            ));
        }
        // A straight shape's own rake, exactly as given; else the angle of
        // the profile's first piece.
        let face = match &self.shape {
            Shape::Straight { rake, .. } => *rake,
            _ => profile.edge_angle(),
        };
        // A face turned to the vertical is vertical: face − θ rounds (100°
        // turned by 10° is 90.00000000000001°), and only a vertical blade
        // may follow a depth path.
        let rake = match face - rotation {
            a if (a - 90.0).abs() <= ROUND_OFF * 90.0 => 90.0,
            a => a,
        };
        if rake <= 0.0 || rake > 90.0 {
            return Err(CaseError::new(
                "tool.motion",
                format!(
                    "the face at rotation {rotation}° stands at α = {rake}° from the horizontal: \
                     soilcut's mechanism takes faces in (0°, 90°] (vertical or leaning back)"
                ),
            ));
        }
        let edge = profile.points()[0];
        let path = poses
            .iter()
            .enumerate()
            .map(|(i, (s, pose))| self.edge_depth(i, *s, pose, edge))
            .collect::<Result<Vec<_>, _>>()?;
        // Edges at the reference depth to round-off (a turned tool's edge
        // is at 19.999999999999996 for 20) cut at constant depth.
        let off_depth = path
            .iter()
            .position(|p| (p[1] - depth).abs() > ROUND_OFF * depth);
        if let (Some(i), true) = (off_depth, rake != 90.0) {
            let [s, d] = path[i];
            return Err(CaseError::new(
                "tool.motion",
                format!(
                    "pose {i} puts the cutting edge at depth {d} (s = {s}), not blade.depth = \
                     {depth}: a face leaning back (α = {rake}°) cuts at the constant depth \
                     blade.depth so far (set blade.depth, or move the edge at it)"
                ),
            ));
        }
        let start = poses[0].1;
        let [x, y] = start.place(self.pivot, edge);
        Ok(StraightCut {
            rake,
            depth_path: if off_depth.is_none() {
                Vec::new()
            } else {
                path
            },
            travel: self.motion.travel(),
            pivot: [start.x - x, start.y - y],
            rotation,
        })
    }

    /// [s, d] of the cutting edge at pose `i`, which today's blade needs
    /// at x = s and in the ground.
    fn edge_depth(
        &self,
        i: usize,
        s: f64,
        pose: &Pose,
        edge: [f64; 2],
    ) -> Result<[f64; 2], CaseError> {
        let [x, y] = pose.place(self.pivot, edge);
        if (x - s).abs() > 1e-9 * s.abs().max(1.0) {
            return Err(unbuilt(
                "tool.motion",
                &format!(
                    "pose {i} puts the cutting edge at x = {x} where s = {s}: soilcut's tools \
                     move forward at the rate of s from x = 0 so far"
                ),
            ));
        }
        if y >= 0.0 {
            return Err(CaseError::new(
                "tool.motion",
                format!(
                    "pose {i} puts the cutting edge at y = {y}, not below the surface: a \
                     translating blade cuts from within the ground"
                ),
            ));
        }
        Ok([s, -y])
    }
}

/// The error of a tool whose mechanism is not built yet.
fn unbuilt(key: &str, what: &str) -> CaseError {
    CaseError::new(
        key,
        format!(
            "{what} (docs/model.md §21: the chord of a curved face, rotation and the soil \
             a bucket carries are the next steps)"
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tool::Motion;

    fn tool(shape: Shape, pivot: [f64; 2], rows: &[[f64; 4]]) -> Tool {
        Tool {
            shape,
            pivot,
            motion: Motion::new(rows, "tool.motion").unwrap(),
        }
    }

    const VERTICAL: Shape = Shape::Straight {
        rake: 90.0,
        height: 70.0,
    };

    #[test]
    fn a_vertical_blade_at_constant_depth_is_the_paper_s_blade() {
        let t = tool(
            VERTICAL,
            [0.0, 0.0],
            &[[0.0, 0.0, -20.0, 0.0], [100.0, 100.0, -20.0, 0.0]],
        );
        let cut = t.straight_cut(20.0).unwrap();
        assert_eq!(cut.rake, 90.0);
        assert!(cut.depth_path.is_empty());
        assert_eq!(cut.travel, 100.0);
        // At another depth than the reference it is a (flat) depth path.
        let deeper = t.straight_cut(25.0).unwrap();
        assert_eq!(deeper.depth_path, vec![[0.0, 20.0], [100.0, 20.0]]);
    }

    #[test]
    fn a_pivot_above_the_edge_and_a_rotation_lean_the_face_back() {
        let rows = [[0.0, 0.0, 50.0, 30.0], [10.0, 10.0, 50.0, 30.0]];
        // Pivot 70 above the edge: rotated 30° counter-clockwise, the edge is
        // 70 sin 30° = 35 ahead of the pivot... which is not x = s.
        let e = tool(VERTICAL, [0.0, 70.0], &rows)
            .straight_cut(20.0)
            .unwrap_err();
        assert!(e.message.contains("cutting edge at x = 34.9"), "{e}");
        let rows = [[0.0, -35.0, 50.0, 30.0], [10.0, -25.0, 50.0, 30.0]];
        // The edge 70 cos 30° − 50 deep: a raked blade at that depth, which
        // must be blade.depth.
        let d = 70.0 * 30f64.to_radians().cos() - 50.0;
        let cut = tool(VERTICAL, [0.0, 70.0], &rows).straight_cut(d).unwrap();
        assert!((cut.rake - 60.0).abs() < 1e-12);
        assert!(cut.depth_path.is_empty());
        let e = tool(VERTICAL, [0.0, 70.0], &rows)
            .straight_cut(20.0)
            .unwrap_err();
        assert!(e.message.contains("set blade.depth"), "{e}");
    }

    #[test]
    fn round_off_of_a_turn_is_no_depth_path_and_no_rake() {
        // A face at 100° turned 10°: vertical, at constant depth, though
        // 100 − 10 and the turned edge's height round.
        let shape = Shape::Straight {
            rake: 100.3,
            height: 70.0,
        };
        let theta = 100.3 - 90.0;
        let pivot = [0.0, 50.0];
        let turned = Pose {
            x: 0.0,
            y: 0.0,
            rotation: theta,
        }
        .place(pivot, [0.0, 0.0]);
        let (x, y) = (-turned[0], -20.0 - turned[1]);
        let rows = [[0.0, x, y, theta], [10.0, 10.0 + x, y, theta]];
        let cut = tool(shape, pivot, &rows).straight_cut(20.0).unwrap();
        assert_eq!(cut.rake, 90.0);
        assert!(cut.depth_path.is_empty(), "{:?}", cut.depth_path);
        // A raked face that changes depth is refused by its motion.
        let deeper = [[0.0, 0.0, -20.0, 0.0], [10.0, 10.0, -25.0, 0.0]];
        let raked = Shape::Straight {
            rake: 60.0,
            height: 70.0,
        };
        let e = tool(raked, [0.0, 0.0], &deeper)
            .straight_cut(20.0)
            .unwrap_err();
        assert_eq!(e.key, "tool.motion");
        assert!(e.message.contains("pose 1"), "{e}");
    }

    #[test]
    fn what_the_mechanism_cannot_take_yet_is_refused_by_name() {
        let curved = Shape::Curved {
            edge_angle: 60.0,
            radius: 40.0,
            sweep: 60.0,
        };
        let flat = [[0.0, 0.0, -20.0, 0.0], [10.0, 10.0, -20.0, 0.0]];
        let e = tool(curved, [0.0, 0.0], &flat)
            .straight_cut(20.0)
            .unwrap_err();
        assert_eq!(e.key, "tool.shape");
        let curl = [[0.0, 0.0, -20.0, 0.0], [10.0, 10.0, -20.0, 5.0]];
        assert_eq!(
            tool(VERTICAL, [0.0, 0.0], &curl)
                .straight_cut(20.0)
                .unwrap_err()
                .key,
            "tool.motion"
        );
        let above = [[0.0, 0.0, 1.0, 0.0], [10.0, 10.0, -20.0, 0.0]];
        assert_eq!(
            tool(VERTICAL, [0.0, 0.0], &above)
                .straight_cut(20.0)
                .unwrap_err()
                .key,
            "tool.motion"
        );
        let forward = [[0.0, 0.0, -20.0, -10.0], [10.0, 10.0, -20.0, -10.0]];
        let e = tool(VERTICAL, [0.0, 0.0], &forward)
            .straight_cut(20.0)
            .unwrap_err();
        assert!(e.message.contains("α = 100°"), "{e}");
    }
}
