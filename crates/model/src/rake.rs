//! An inclined blade face (rake α < 90°, leaning back) by a shear of the
//! coordinates that makes the face vertical.
//!
//! With c = cot α, the map x' = x + (y + d) c (y unchanged) takes the face
//! x = x_b − (y + d) c to the vertical line x' = x_b. It preserves areas
//! (determinant 1), so weights and mass are computed in x' unchanged, and
//! straight lines stay straight: a line at tan β becomes one at
//! tan β' = tan β / (1 + c tan β). The block that slides along a slip line
//! at β + ψ while staying against the face moves by
//! λ (cos(β + ψ), sin(β + ψ)), λ = v0 sin α / sin(α + β + ψ), which in x' is
//! exactly (v0, v0 tan(β + ψ)') : the one-node shift of the vertical blade.
//! So the whole model runs on a grid in x' and only the angles that enter
//! Eq. (1) and the slip are converted; α = 90° is the identity.
//!
//! Eq. (1) for rake α is the vertical blade's with the wall friction φw
//! replaced by φw + (α − 90°): sin(α + β + φ + φw) = cos(β + φ + φw + α − 90°).

/// The shear of coordinates for a rake angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rake {
    /// c = cot α (0 for the vertical blade).
    pub cot: f64,
    /// α − 90° (radians), added to the wall friction in Eq. (1).
    pub offset: f64,
}

impl Rake {
    /// `rake` in degrees.
    pub fn new(rake: f64) -> Self {
        if rake == 90.0 {
            Rake {
                cot: 0.0,
                offset: 0.0,
            }
        } else {
            let alpha = rake.to_radians();
            Rake {
                cot: 1.0 / alpha.tan(),
                offset: alpha - std::f64::consts::FRAC_PI_2,
            }
        }
    }

    /// tan β of a line whose slope on the grid (in x') is `grid_slope`, the
    /// inverse of (M34), or `None` where the line would not go forward
    /// (β ≥ 90°).
    #[inline]
    pub fn physical(&self, grid_slope: f64) -> Option<f64> {
        if self.cot == 0.0 {
            // The identity; the same value as the division below gives.
            return Some(grid_slope);
        }
        let run = 1.0 - self.cot * grid_slope;
        (run > 0.0).then(|| grid_slope / run)
    }

    /// The grid slope (in x') of a line at tan β = `t`:
    /// tan β' = tan β / (1 + cot α tan β) (M34).
    #[inline]
    pub fn grid(&self, t: f64) -> f64 {
        t / (1.0 + self.cot * t)
    }

    /// The steepest grid slopes, downhill and uphill in +x, of sand at
    /// repose tan θr = `tan_repose`: a physical slope ∓tan θr is the grid
    /// slope ∓tan θr / (1 ∓ tan θr cot α). A grid segment falling by s per
    /// unit of x' falls physically by s / (1 + s cot α) < tan α, so where
    /// θr ≥ α (a face flatter than the repose) every downhill slope the grid
    /// can hold is stable and the downhill limit is infinite: soil lies on
    /// the face as on ground flatter than its repose. Times Δx these are
    /// s_down and s_up (M29).
    pub fn repose_slopes(&self, tan_repose: f64) -> (f64, f64) {
        let run = 1.0 - tan_repose * self.cot;
        let down = if run > 0.0 {
            tan_repose / run
        } else {
            f64::INFINITY
        };
        (down, tan_repose / (1.0 + tan_repose * self.cot))
    }

    /// Physical x of the point (x', y) with the tip at depth d: the inverse
    /// of the shear x' = x + (y + d) cot α (M33).
    #[inline]
    pub fn x(&self, x_grid: f64, y: f64, depth: f64) -> f64 {
        x_grid - (y + depth) * self.cot
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertical_blade_is_the_identity() {
        let r = Rake::new(90.0);
        assert_eq!(r.physical(0.37), Some(0.37));
        assert_eq!(r.grid(0.37), 0.37);
        assert_eq!(r.x(3.0, -0.5, 1.0), 3.0);
    }

    #[test]
    fn repose_slopes_are_the_physical_repose_on_the_grid() {
        let r = Rake::new(60.0);
        let t = 30f64.to_radians().tan();
        let (down, up) = r.repose_slopes(t);
        assert!((r.physical(-down).unwrap() + t).abs() < 1e-12);
        assert!((r.physical(up).unwrap() - t).abs() < 1e-12);
        // A face flatter than the repose: no downhill limit on the grid.
        let flat = Rake::new(30.0).repose_slopes(35f64.to_radians().tan());
        assert_eq!(flat.0, f64::INFINITY);
        assert!(flat.1.is_finite());
    }

    #[test]
    fn slopes_convert_both_ways() {
        let r = Rake::new(60.0);
        for t in [0.1, 0.5, 1.7] {
            let back = r.physical(r.grid(t)).unwrap();
            assert!((back - t).abs() < 1e-14 * t);
        }
        // A line that would lean back past the vertical is not a mechanism.
        assert!(r.physical(1.0 / r.cot).is_none());
    }

    #[test]
    fn block_moves_one_grid_node_per_blade_increment() {
        // λ (cos θ, sin θ) with λ = v0 sin α / sin(α + θ), θ = β + ψ, has
        // x' displacement v0 and y displacement v0 · (grid slope of θ).
        let (alpha, theta, v0) = (50f64.to_radians(), 25f64.to_radians(), 0.3);
        let r = Rake::new(50.0);
        let lambda = v0 * alpha.sin() / (alpha + theta).sin();
        let (dx, dy) = (lambda * theta.cos(), lambda * theta.sin());
        assert!((dx + dy * r.cot - v0).abs() < 1e-15);
        assert!((dy - v0 * r.grid(theta.tan())).abs() < 1e-15);
    }
}
