//! The node grid's running bound before the footprint (docs/model.md
//! §2.8): φ_lo, the least friction angle of the nodes scanned so far, and
//! Eq. (1) at it (`force_bounds::Lower`), which no candidate ahead can
//! beat with a weaker band.

use super::input::SearchInput;
use crate::force_bounds::Lower;
use crate::node_grid::surface::Surface;

/// φ_lo, the least friction angle of the nodes scanned so far, and Eq. (1)
/// at it: the bound before the footprint.
#[derive(Clone, Copy)]
pub(super) struct LeastFriction {
    phi: f64,
    pub(super) lower: Lower,
}

impl LeastFriction {
    /// The friction angle of the face node.
    pub(super) fn new(phi: f64, input: &SearchInput) -> Self {
        LeastFriction {
            phi,
            lower: Lower::new(phi, input.laws),
        }
    }

    /// Takes in nodes j − 1 and j (a footprint ends at j).
    #[inline]
    pub(super) fn include(&mut self, surface: &Surface, j: usize, input: &SearchInput) {
        let (here, before) = (surface.friction[j], surface.friction[j - 1]);
        if here < self.phi || before < self.phi {
            self.phi = self.phi.min(here).min(before);
            self.lower = Lower::new(self.phi, input.laws);
        }
    }
}
