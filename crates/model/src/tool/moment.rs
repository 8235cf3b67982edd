//! Where the face force acts, and its moment about the tool's pivot (M56).
//!
//! A rigid-block mechanism gives the resultant P on the face, not how it
//! is spread over the contact. The contact runs up the face from the
//! cutting edge, at the tip's depth, to the soil's surface at the face.
//! soilcut takes the resultant at a third of that contact from the edge:
//! the centroid of a pressure that grows linearly with depth below the
//! soil's top at the face, which is Coulomb's and Rankine's for the weight
//! of a cohesionless wedge and the Fundamental Earthmoving Equation's
//! point for its γ term (its cohesion, adhesion and surcharge terms act at
//! half the contact; soilcut applies the whole resultant at the third, the
//! weight being what dominates in sand). With the edge at (u, −t), the
//! face at α from the horizontal (leaning back for α < 90°) and the soil
//! at the face up to y_f,
//!
//! ```text
//! ℓ = max(y_f + t, 0) / 3,   A = (u − ℓ cot α, −t + ℓ)              (M56)
//! M = (A_x − O_x) F_y − (A_y − O_y) F_x,   F = (−P_h, P_v)
//! ```
//!
//! with O the pivot and F the soil's force on the tool (the draft P_h
//! pushes it back, P_v up); M is counter-clockwise positive, the sense of
//! a bucket's curl (its lip turning up), per unit width as the forces are
//! (per blade with `blade.width`).

use crate::case::Blade;
use crate::rake::Rake;

/// The tool's columns of an increment: its pose and the moment on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ToolState {
    /// M about the pivot (force × length, counter-clockwise positive).
    pub moment: f64,
    /// x of the pivot (length).
    pub x: f64,
    /// y of the pivot (length).
    pub y: f64,
    /// The tool's rotation, degrees.
    pub rotation: f64,
}

/// The cutting edge at (u, −`tip`), the soil at the face up to
/// `face_top`, the soil's force (`force_h`, `force_v`) on the face: the
/// tool's pose and the moment on it about its pivot (M56).
pub fn tool_state(blade: &Blade, u: f64, tip: f64, face_top: f64, force: [f64; 2]) -> ToolState {
    let [force_h, force_v] = force;
    let lever = (face_top + tip).max(0.0) / 3.0;
    let at = [u - lever * Rake::new(blade.rake).cot, -tip + lever];
    let pivot = [u + blade.pivot[0], -tip + blade.pivot[1]];
    ToolState {
        moment: (at[0] - pivot[0]) * force_v + (at[1] - pivot[1]) * force_h,
        x: pivot[0],
        y: pivot[1],
        rotation: blade.rotation,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blade(rake: f64, pivot: [f64; 2]) -> Blade {
        Blade {
            depth: 20.0,
            wall_friction: 10.0,
            rake,
            adhesion: 0.0,
            depth_path: Vec::new(),
            width: None,
            pivot,
            rotation: 0.0,
        }
    }

    #[test]
    fn a_horizontal_push_a_third_up_the_contact_turns_a_tool_pivoted_at_its_edge_back() {
        // Vertical blade, tip 20 deep, soil up to 10 at the face: the
        // contact is 30 long, the force acts 10 above the edge.
        let s = tool_state(&blade(90.0, [0.0, 0.0]), 5.0, 20.0, 10.0, [3.0, 0.0]);
        assert_eq!(s.moment, 30.0);
        assert_eq!([s.x, s.y], [5.0, -20.0]);
        // Pivoted 70 above the edge, the push below it turns it clockwise.
        let s = tool_state(&blade(90.0, [0.0, 70.0]), 5.0, 20.0, 10.0, [3.0, 0.0]);
        assert_eq!(s.moment, -180.0);
        assert_eq!(s.y, 50.0);
    }

    #[test]
    fn on_a_raked_face_the_point_leans_back_with_it() {
        // α = 45°: the point a third up the contact is as far behind the
        // edge as above it, so a vertical force has the lever −ℓ.
        let s = tool_state(&blade(45.0, [0.0, 0.0]), 0.0, 20.0, 10.0, [0.0, 2.0]);
        assert!((s.moment - (-20.0)).abs() < 1e-12, "{}", s.moment);
    }

    #[test]
    fn no_contact_puts_the_force_at_the_edge() {
        let s = tool_state(&blade(90.0, [1.0, 0.0]), 0.0, 20.0, -25.0, [3.0, 4.0]);
        assert_eq!(s.moment, -4.0);
    }
}
