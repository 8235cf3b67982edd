//! Which triangles share each edge, found in element order (deterministic).

use crate::mesh::Mesh;
use std::collections::HashMap;

/// One side of a triangle: (element, local index of the edge's first node,
/// local index of its second), in the triangle's counter-clockwise order.
pub type Half = (usize, usize, usize);

/// The edges of a mesh by their (smaller, larger) node pair.
pub struct Edges {
    map: HashMap<(usize, usize), Vec<Half>>,
}

fn key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

impl Edges {
    /// Collects every triangle's three sides.
    pub fn new(mesh: &Mesh) -> Edges {
        let mut map: HashMap<(usize, usize), Vec<Half>> = HashMap::new();
        for (e, t) in mesh.triangles.iter().enumerate() {
            for l in 0..3 {
                let m = (l + 1) % 3;
                map.entry(key(t[l], t[m])).or_default().push((e, l, m));
            }
        }
        Edges { map }
    }

    /// The interior edges as (earlier triangle's side, later triangle's side),
    /// in the order of the later triangle and its sides.
    pub fn interior(&self, mesh: &Mesh) -> Vec<(Half, Half)> {
        let mut out = Vec::new();
        for (e, t) in mesh.triangles.iter().enumerate() {
            for l in 0..3 {
                let halves = &self.map[&key(t[l], t[(l + 1) % 3])];
                if halves.len() == 2 && halves[1].0 == e {
                    out.push((halves[0], halves[1]));
                }
            }
        }
        out
    }

    /// The triangle side on boundary edge (a, b), oriented from a to b.
    pub fn boundary(&self, mesh: &Mesh, a: usize, b: usize) -> Half {
        let (e, l, m) = self.map[&key(a, b)][0];
        if mesh.triangles[e][l] == a {
            (e, l, m)
        } else {
            (e, m, l)
        }
    }
}
