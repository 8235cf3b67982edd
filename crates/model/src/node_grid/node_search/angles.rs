//! The band angles of a candidate (docs/model.md §2.7): the means of the
//! node angles over the band's footprint, the m + 1 nodes j − m … j that
//! the band touches at the surface (`Band::footprint`; the emergence node
//! alone for a slip line),
//!
//!   φ_j = (1/(m+1)) Σ_{i=j−m}^{j} φ(ut_i),   ψ_j likewise, ut_j likewise   (M10)
//!
//! from prefix sums along the scan, so each candidate costs O(1).

use crate::laws::BandAngles;
use crate::node_grid::node_band::Band;
use crate::node_grid::surface::Surface;

/// Prefix sums of φ, ψ and ut from the blade node, one entry per node
/// scanned (reused from step to step).
#[derive(Clone, Debug, Default)]
pub(super) struct Prefix {
    sums: Vec<[f64; 3]>,
}

impl Prefix {
    /// Empties the sums for a scan from the blade node.
    pub(super) fn start(&mut self) {
        self.sums.clear();
        self.sums.push([0.0; 3]);
    }

    /// Adds node i, the next one after those summed.
    pub(super) fn push(&mut self, surface: &Surface, i: usize) {
        let last = *self.sums.last().expect("prefix starts with zero");
        self.sums.push([
            last[0] + surface.friction[i],
            last[1] + surface.dilation[i],
            last[2] + surface.accumulated_shear[i],
        ]);
    }

    /// Mean angles (M10) over the band's footprint, nodes j − m ..= j (the
    /// sums must cover the nodes before j).
    #[inline]
    pub(super) fn band_angles(
        &self,
        surface: &Surface,
        band: &Band,
        fresh: BandAngles,
    ) -> BandAngles {
        let (b, j) = (band.face.node, band.emergence);
        let m = band.footprint(&surface.height);
        if m == 0 {
            return node_angles(surface, j);
        }
        let before = self.sums[j - b];
        let lo = self.sums[j - m - b];
        if before[2] == lo[2] && surface.accumulated_shear[j] == 0.0 {
            return fresh;
        }
        let hi = [
            before[0] + surface.friction[j],
            before[1] + surface.dilation[j],
            before[2] + surface.accumulated_shear[j],
        ];
        window_angles(hi, lo, m)
    }
}

/// Mean angles (M10) over nodes j − m ..= j summed directly, without the
/// prefix sums (for a candidate computed on its own).
pub(super) fn footprint_angles(surface: &Surface, j: usize, m: usize) -> BandAngles {
    let sum = |i: usize| {
        [
            surface.friction[i],
            surface.dilation[i],
            surface.accumulated_shear[i],
        ]
    };
    let total = (j - m..=j)
        .map(sum)
        .fold([0.0; 3], |a, v| [a[0] + v[0], a[1] + v[1], a[2] + v[2]]);
    window_angles(total, [0.0; 3], m)
}

fn node_angles(surface: &Surface, j: usize) -> BandAngles {
    BandAngles {
        friction: surface.friction[j],
        dilation: surface.dilation[j],
        shear: surface.accumulated_shear[j],
        fresh: surface.accumulated_shear[j] == 0.0,
    }
}

/// Mean angles of the m + 1 nodes whose sums are `hi − lo`:
/// φ_j = (1/(m+1)) Σ φ(ut_i), ψ_j and ut_j likewise (M10).
fn window_angles(hi: [f64; 3], lo: [f64; 3], m: usize) -> BandAngles {
    let n = (m + 1) as f64;
    BandAngles {
        friction: (hi[0] - lo[0]) / n,
        dilation: (hi[1] - lo[1]) / n,
        shear: (hi[2] - lo[2]) / n,
        fresh: hi[2] - lo[2] == 0.0,
    }
}
