//! The angle of repose as a constraint (docs/model.md §6): sand cannot
//! stand steeper than θr. With s the largest rise per unit of weight
//! between neighbours, the downslope constraint makes g = y + s x
//! non-decreasing and the upslope one y − s x non-increasing; each is
//! restored by the pool-adjacent-violators algorithm, every pooled run
//! replaced by a line at exactly the angle of repose holding the same
//! weighted area. Both grounds pool (the node grid's `avalanche`, the
//! vertex ground's `vertices::avalanche`); what a pool is, and when a slope
//! is only round-off, is here.

/// Violations smaller than this fraction of s are round-off, not slopes.
pub(crate) const SLOPE_TOLERANCE: f64 = 1e-9;
/// Alternating passes before giving up on the last round-off residue.
pub(crate) const MAX_PASSES: usize = 64;

/// A pooled run of nodes: first node, node count, Σw, Σw g and their
/// quotient, the pool's mean of g (kept, not recomputed per comparison).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pool {
    pub(crate) start: usize,
    pub(crate) len: usize,
    pub(crate) weight: f64,
    pub(crate) weighted: f64,
    pub(crate) mean: f64,
}

impl Pool {
    /// One node of weight w and value g.
    pub(crate) fn new(start: usize, w: f64, g: f64) -> Self {
        let weighted = w * g;
        Pool {
            start,
            len: 1,
            weight: w,
            weighted,
            // (1 · g) / 1 = g exactly: no division for an inner node.
            mean: if w == 1.0 { g } else { weighted / w },
        }
    }

    /// This pool and the run `next` that follows it.
    pub(crate) fn merge(&mut self, next: &Pool) {
        self.len += next.len;
        self.weight += next.weight;
        self.weighted += next.weighted;
        self.mean = self.weighted / self.weight;
    }
}
