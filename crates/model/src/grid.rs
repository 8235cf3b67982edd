//! Where the blade face lies on the node grid x_i = i h (docs/model.md §9).
//!
//! On the reference grid (h = v0) the face is on node b. On a coarse grid
//! (h = k v0) it lies δ = (a whole number of increments) ahead of node b's
//! grid point, and node b holds the soil column at the face. Node i ≥ b is
//! then i − b − δ/h spacings from the face, the face's segment to node
//! b + 1 is h − δ long, and the trapezoid rule over the nodes from the face
//! weighs node i by half of each segment it bounds. The surface, the band,
//! the search and the update take both from here.

mod band;

pub use band::Band;

/// The face's node b and its offset δ/h from that node's grid point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FaceNode {
    /// Node b, which holds the soil column at the face.
    pub node: usize,
    /// δ / h, in [0, 1) (0 on the reference grid).
    pub offset: f64,
}

impl FaceNode {
    /// (x_i − x_face) / h for the face or a node i ahead of it:
    /// i − b − δ/h, and 0 at the face.
    #[inline]
    pub fn spacings(&self, i: usize) -> f64 {
        if i == self.node {
            0.0
        } else {
            (i - self.node) as f64 - self.offset
        }
    }

    /// Length of the segment from node i to node i + 1, in spacings: the
    /// face's is 1 − δ/h.
    #[inline]
    pub fn segment(&self, i: usize) -> f64 {
        if i == self.node {
            1.0 - self.offset
        } else {
            1.0
        }
    }

    /// Trapezoid weight of node i ≥ b among the nodes from the face on,
    /// the far end aside: ½ (1 − δ/h) at the face, 1 − ½ δ/h next to it,
    /// 1 beyond (half of each segment the node bounds).
    #[inline]
    pub fn node_weight(&self, i: usize) -> f64 {
        if i == self.node {
            0.5 * (1.0 - self.offset)
        } else if i == self.node + 1 {
            1.0 - 0.5 * self.offset
        } else {
            1.0
        }
    }
}

/// The discretisation of a case, chosen once and held by the surface: the
/// node spacing h is a whole multiple k of the blade increment v0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scheme {
    /// h, the node spacing (length).
    pub spacing: f64,
    /// v0, the blade's advance per increment (length).
    pub increment: f64,
    /// k = h / v0, whole (`Case::increments_per_node`).
    pub increments_per_node: usize,
}

impl Scheme {
    /// Whether the reference update applies: a block translating by v0
    /// moves exactly one node, which needs h = v0 to the last bit (a
    /// spacing within round-off of v0 takes the coarse update, with k = 1).
    pub fn reference(&self) -> bool {
        self.increment == self.spacing
    }

    /// v0 / h: the fraction of a spacing the face moves per increment (the
    /// Courant number of the coarse update's remap).
    pub fn courant(&self) -> f64 {
        self.increment / self.spacing
    }

    /// The face after increment number `step` (from 1), node `face` before
    /// it: one node every k increments, in between offset by a whole
    /// number of increments, δ/h = (step mod k) / k.
    pub fn face_after(&self, step: usize, face: usize) -> FaceNode {
        let k = self.increments_per_node;
        let sub = step % k;
        FaceNode {
            node: if sub == 0 { face + 1 } else { face },
            offset: sub as f64 / k as f64,
        }
    }
}
