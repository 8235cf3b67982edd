//! Where the blade face lies on the node grid x_i = i h, h = v0
//! (docs/model.md §9.1): on node b, which holds the soil column at the face.
//! Node i ≥ b is i − b spacings from the face, and the trapezoid rule over
//! the nodes from the face weighs the face's node by ½. The surface, the
//! band, the search and the update take both from here.

/// The face's node b.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FaceNode {
    /// Node b, which holds the soil column at the face.
    pub node: usize,
}

impl FaceNode {
    /// (x_i − x_face) / h for the face or a node i ahead of it: i − b.
    #[inline]
    pub fn spacings(&self, i: usize) -> f64 {
        (i - self.node) as f64
    }

    /// Trapezoid weight of node i ≥ b among the nodes from the face on,
    /// the far end aside: ½ at the face, 1 beyond.
    #[inline]
    pub fn node_weight(&self, i: usize) -> f64 {
        if i == self.node {
            0.5
        } else {
            1.0
        }
    }
}
