//! The shear band of one node-grid candidate (paper Fig. 3a;
//! docs/model.md §3.2, §9.1): its lower boundary from the tip to emergence
//! node j, its nodes' relative positions, its area below the surface and
//! its footprint in nodes.

use super::face_node::FaceNode;
use crate::band::stretch;

/// The band of one candidate or chosen mechanism.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// The blade face: its node b.
    pub face: FaceNode,
    /// Emergence node j of the lower boundary.
    pub emergence: usize,
    /// Slope of the lower boundary on the grid (tan β, or its sheared value
    /// for a raked blade: `Rake`).
    pub tan_beta: f64,
    /// e: vertical thickness of the band on the grid (dB / cos β for a
    /// vertical blade).
    pub thickness: f64,
    /// dB: the band's width (normal to it).
    pub width: f64,
    /// Blade tip depth d.
    pub depth: f64,
    /// Node spacing Δx.
    pub spacing: f64,
}

impl Band {
    /// The band of width dB whose lower boundary has slope (`grid_slope`,
    /// `tan_beta`) = (on the grid, physically) (equal for a vertical blade;
    /// the grid's vertical thickness is e = dB / cos β times their ratio,
    /// (M16)).
    pub fn new(
        face: FaceNode,
        emergence: usize,
        (grid_slope, tan_beta): (f64, f64),
        band_width: f64,
        depth: f64,
        spacing: f64,
    ) -> Self {
        let stretch = stretch(grid_slope, tan_beta);
        Band {
            face,
            emergence,
            tan_beta: grid_slope,
            thickness: band_width * (1.0 + tan_beta * tan_beta).sqrt() * stretch,
            width: band_width,
            depth,
            spacing,
        }
    }

    /// Height of the lower boundary at node i.
    pub fn lower(&self, i: usize) -> f64 {
        -self.depth + self.face.spacings(i) * self.spacing * self.tan_beta
    }

    /// Relative position g_i of surface node i above the lower boundary
    /// (in band thicknesses; ∞ for a slip line above it).
    pub fn position(&self, height: f64, i: usize) -> f64 {
        let z = height - self.lower(i);
        if self.thickness > 0.0 {
            z / self.thickness
        } else if z > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    }

    /// Area of the band below the free surface between the face and the
    /// emergence node: ∫ clip(y − lower, 0, e) dx over the piecewise linear
    /// surface, integrated exactly (split where the surface crosses the
    /// upper boundary). This is A0 of the dilation (M19).
    pub fn area_below(&self, height: &[f64]) -> f64 {
        if self.thickness == 0.0 {
            return 0.0;
        }
        let (dx, e) = (self.spacing, self.thickness);
        let mut area = 0.0;
        let b = self.face.node;
        let mut g0 = self.position(height[b], b);
        let nodes = height.iter().enumerate();
        for (i, &y) in nodes.take(self.emergence + 1).skip(b + 1) {
            let g1 = self.position(y, i);
            area += e * dx * clipped_mean(g0, g1);
            g0 = g1;
        }
        area
    }

    /// Number of nodes m behind the emergence node whose soil the band
    /// touches at the surface, estimated in O(1): the upper boundary meets a
    /// surface of slope s at a distance e / (tan β − s) behind j; s is the
    /// secant slope over the flat-ground footprint e / tan β, so
    /// m = floor(e m0 / (Δx tan β m0 − (y_j − y_{j−m0}))) (M17). Exact where
    /// the surface is straight over the footprint.
    #[inline]
    pub fn footprint(&self, height: &[f64]) -> usize {
        let (j, b) = (self.emergence, self.face.node);
        if self.thickness == 0.0 {
            return 0;
        }
        let reach = j - b;
        // The rise of the lower boundary per node is r = Δx tan β.
        let r = self.spacing * self.tan_beta;
        let flat = round_to_nodes(self.thickness / r);
        let m0 = flat.clamp(1, reach);
        // e / ((tan β − s) Δx) with s = (y_j − y_{j−m0}) / (m0 Δx).
        let opening = r * m0 as f64 - (height[j] - height[j - m0]);
        if opening <= 0.0 {
            return reach;
        }
        let m = self.thickness * m0 as f64 / opening;
        if m >= reach as f64 {
            reach
        } else {
            m as usize
        }
    }
}

/// Nearest whole number of nodes (ties to even) for 0 ≤ x, without a libm
/// call: adding and subtracting 1.5 · 2⁵² rounds.
fn round_to_nodes(x: f64) -> usize {
    const ROUNDING: f64 = 6_755_399_441_055_744.0;
    if x >= 1e15 {
        usize::MAX
    } else {
        ((x + ROUNDING) - ROUNDING) as usize
    }
}

/// Mean of min(g, 1) over a segment on which g is linear from g0 to g1 ≥ 0.
fn clipped_mean(g0: f64, g1: f64) -> f64 {
    let (lo, hi) = if g0 <= g1 { (g0, g1) } else { (g1, g0) };
    if hi <= 1.0 {
        0.5 * (lo + hi)
    } else if lo >= 1.0 {
        1.0
    } else {
        // Fraction λ of the segment below the upper boundary.
        let lambda = (1.0 - lo) / (hi - lo);
        lambda * 0.5 * (lo + 1.0) + (1.0 - lambda)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_area_on_flat_ground_is_a_parallelogram_less_its_corner() {
        // Flat ground y = 0, d = 1, β = 45°: lower boundary reaches y = 0 at
        // x = 1; band of vertical thickness e cut by the surface.
        let n = 1001;
        let dx = 1.0 / (n - 1) as f64;
        let height = vec![0.0; n + 5];
        let dband = 0.1;
        let band = Band::new(FaceNode::default(), n - 1, (1.0, 1.0), dband, 1.0, dx);
        let e = band.thickness;
        // Strip between y = x − 1 and y = x − 1 + e, below y = 0, x ∈ [0, 1]:
        // e·1 minus the triangle above y = 0 (legs e, e).
        let expected = e * 1.0 - 0.5 * e * e;
        assert!((band.area_below(&height) - expected).abs() < 1e-12);
        let m = band.footprint(&height);
        assert!((m as f64 * dx - e).abs() <= dx, "footprint {m}");
    }

    #[test]
    fn slip_line_has_no_area_and_no_footprint() {
        let height = vec![0.0; 50];
        let band = Band::new(FaceNode::default(), 40, (0.5, 0.5), 0.0, 1.0, 0.05);
        assert_eq!(band.area_below(&height), 0.0);
        assert_eq!(band.footprint(&height), 0);
        assert_eq!(band.position(0.0, 40), 0.0);
        assert_eq!(band.position(0.3, 20), f64::INFINITY);
    }
}
