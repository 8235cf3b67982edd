//! The six-node triangle (its vertices, then the mid-sides of sides (0,1),
//! (1,2), (2,0)): the derivatives of its quadratic shape functions at the
//! vertices.
//!
//! In area coordinates L_i the shape functions are N_i = L_i (2 L_i − 1) at
//! the vertices and N_ij = 4 L_i L_j at the mid-sides, with
//! ∂L_i/∂x = b_i/(2A), ∂L_i/∂y = c_i/(2A), b_i = y_j − y_k, c_i = x_k − x_j.
//! At vertex k: ∂N_k = 3 ∂L_k, ∂N_i = −∂L_i (i ≠ k), ∂N_kj = 4 ∂L_j, and the
//! mid-side opposite k contributes nothing.

use crate::mesh::twice_area;

/// 2A·∂N/∂x and 2A·∂N/∂y of the six shape functions at vertex k of
/// triangle `p`, and 2A.
pub fn gradients_at_vertex(p: [[f64; 2]; 3], k: usize) -> ([f64; 6], [f64; 6], f64) {
    let mut b = [0.0; 3];
    let mut c = [0.0; 3];
    for i in 0..3 {
        let (j, l) = ((i + 1) % 3, (i + 2) % 3);
        b[i] = p[j][1] - p[l][1];
        c[i] = p[l][0] - p[j][0];
    }
    let (mut dx, mut dy) = ([0.0; 6], [0.0; 6]);
    for i in 0..3 {
        let f = if i == k { 3.0 } else { -1.0 };
        dx[i] = f * b[i];
        dy[i] = f * c[i];
    }
    // Mid-side s joins vertices s and s + 1.
    for s in 0..3 {
        let (i, j) = (s, (s + 1) % 3);
        let other = if i == k {
            Some(j)
        } else if j == k {
            Some(i)
        } else {
            None
        };
        if let Some(o) = other {
            dx[3 + s] = 4.0 * b[o];
            dy[3 + s] = 4.0 * c[o];
        }
    }
    (dx, dy, twice_area(p[0], p[1], p[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quadratic field u = x² + 3xy − y is reproduced exactly: its
    /// gradient at each vertex.
    #[test]
    fn gradients_are_exact_for_a_quadratic() {
        let p = [[0.3, 0.1], [1.7, 0.4], [0.6, 1.5]];
        let u = |x: f64, y: f64| x * x + 3.0 * x * y - y;
        let mid = |a: [f64; 2], b: [f64; 2]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        let pts = [
            p[0],
            p[1],
            p[2],
            mid(p[0], p[1]),
            mid(p[1], p[2]),
            mid(p[2], p[0]),
        ];
        for k in 0..3 {
            let (dx, dy, a2) = gradients_at_vertex(p, k);
            let gx: f64 = (0..6).map(|i| dx[i] * u(pts[i][0], pts[i][1])).sum::<f64>() / a2;
            let gy: f64 = (0..6).map(|i| dy[i] * u(pts[i][0], pts[i][1])).sum::<f64>() / a2;
            let (x, y) = (p[k][0], p[k][1]);
            assert!((gx - (2.0 * x + 3.0 * y)).abs() < 1e-12);
            assert!((gy - (3.0 * x - 1.0)).abs() < 1e-12);
        }
    }
}
