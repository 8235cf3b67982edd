//! The update of the free surface after an increment (MODEL.md section 3).
//!
//! Original model (incompressible, Fig. 1b): the block above the slip line
//! A→j translates by v0 (1, tan β*). On the grid Δx = v0 that is an exact
//! shift of nodes b..j−1 to b+1..j with a rise of v0 tan β*; nodes beyond j
//! are unchanged. Nodes of the block carry their state with them; node j,
//! where the slip line emerges, keeps the state of the slip surface and
//! accumulates Δut = v0 / cos β*.
//!
//! The face sweeps the triangle (x_b, −d), (x_b + v0, −d), (x_b + v0, −d +
//! v0 tan β*) below the slip line, of area ½ v0² tan β*. That soil is pushed
//! up the face with the block rather than dropped: the new face node rises by
//! a further v0 tan β*, which (half trapezoid weight) adds exactly that area,
//! so the area of soil is conserved to round-off.

use crate::search::Choice;
use crate::surface::Surface;

/// Applies the original model's update; returns Δut of the slip line.
pub fn slide_block(surface: &mut Surface, blade: usize, choice: &Choice) -> f64 {
    let (j, dx) = (choice.node, surface.spacing);
    let rise = dx * choice.tan_beta;
    let h = &mut surface.height;
    h.copy_within(blade..j, blade + 1);
    for y in &mut h[blade + 1..=j] {
        *y += rise;
    }
    h[blade + 1] += rise;
    surface
        .accumulated_shear
        .copy_within(blade..j - 1, blade + 1);
    surface.unit_weight.copy_within(blade..j - 1, blade + 1);
    let slip = dx * (1.0 + choice.tan_beta * choice.tan_beta).sqrt();
    surface.accumulated_shear[j] += slip;
    slip
}
