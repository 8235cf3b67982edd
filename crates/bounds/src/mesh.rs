//! A structured triangulation of the soil: columns of nodes parallel to the
//! face above the tip level (vertical below it), levels graded towards the
//! tip, each quadrilateral cell cut by its diagonals into four triangles
//! (the "union jack" pattern that suits both bounds).
//!
//! N, the mesh parameter, is the number of cells along the face near the
//! tip: the cell size grows from h/(2N) at the tip by half of the distance
//! from it, s(r) = (h/N)(½ + ½ r/h) (so h/N at one face height away), to
//! resolve the tip's stress and velocity singularity while keeping the far
//! field coarse.

use crate::problem::Problem;

/// Which boundary an edge lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The blade's face.
    Face,
    /// The ground surface (carries the surcharge).
    Surface,
    /// The trench floor behind the blade (load-free).
    Trench,
    /// A truncation of the half-space (ahead, below, behind).
    Far,
}

/// Nodes, counter-clockwise triangles and tagged boundary edges. Boundary
/// edges run counter-clockwise around the soil, so (dy, −dx)/L along one is
/// its outward normal.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Node coordinates (x, y).
    pub nodes: Vec<[f64; 2]>,
    /// Triangles as node indices, counter-clockwise.
    pub triangles: Vec<[usize; 3]>,
    /// Boundary edges (from, to, side).
    pub boundary: Vec<(usize, usize, Side)>,
}

/// Positions from 0 to `length` with spacing s(r) = fine + growth·r,
/// stretched to end exactly at `length`.
fn graded(length: f64, fine: f64, growth: f64) -> Vec<f64> {
    let mut r = vec![0.0];
    if length <= 0.0 {
        return r;
    }
    let mut last = 0.0;
    while last < length {
        last += fine + growth * last;
        r.push(last);
    }
    // Merge a last sliver into its neighbour.
    if r.len() > 2 && last - length > 0.5 * (last - r[r.len() - 2]) {
        r.remove(r.len() - 2);
        last = r[r.len() - 1];
    }
    r.iter().map(|v| v * length / last).collect()
}

/// Twice the signed area of triangle (a, b, c).
pub fn twice_area(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
}

/// The mesh's lines: the x of every column of nodes (at the tip's level),
/// the y of the levels below the tip, and the levels above it as fractions
/// of the way from the tip to the column's top.
struct Lines {
    columns: Vec<f64>,
    /// The column through the tip: the face's, vertical below, parallel to
    /// the face above (from it on).
    tip_column: usize,
    below: Vec<f64>,
    above: Vec<f64>,
}

impl Lines {
    fn of(p: &Problem, n: usize) -> Lines {
        let h = p.face_height();
        let (xa, ya) = (p.face.tip_x, p.face.tip_y);
        let n = n.max(1) as f64;
        let spacing = |len: f64| graded(len, 0.5 * h / n, 0.5 / n);
        let back = if p.domain.depth > 0.0 {
            p.domain.back
        } else {
            0.0
        };
        let mut columns: Vec<f64> = spacing(back * h).iter().rev().map(|r| xa - r).collect();
        let tip_column = columns.len() - 1;
        columns.extend(spacing(p.domain.reach * h).iter().skip(1).map(|r| xa + r));
        let below = spacing(p.domain.depth * h)
            .iter()
            .rev()
            .map(|r| ya - r)
            .collect();
        let above = spacing(h).iter().skip(1).map(|r| r / h).collect();
        Lines {
            columns,
            tip_column,
            below,
            above,
        }
    }

    /// The boundary sides of cell (j, k) of a column pair with `levels`
    /// levels, edge by edge counter-clockwise from the bottom.
    fn sides(&self, j: usize, k: usize, levels: usize) -> [Option<Side>; 4] {
        let top = if j < self.tip_column {
            Side::Trench
        } else {
            Side::Surface
        };
        [
            (k == 0).then_some(Side::Far),
            (j + 2 == self.columns.len()).then_some(Side::Far),
            (k + 2 == levels).then_some(top),
            if j == self.tip_column && k + 1 >= self.below.len() {
                Some(Side::Face)
            } else if j == 0 {
                Some(Side::Far)
            } else {
                None
            },
        ]
    }
}

impl Mesh {
    /// The mesh of a (validated) problem with N cells along the face near
    /// the tip, N ≥ 1.
    pub fn new(p: &Problem, n: usize) -> Mesh {
        let lines = Lines::of(p, n);
        let mut mesh = Mesh {
            nodes: Vec::new(),
            triangles: Vec::new(),
            boundary: Vec::new(),
        };
        let grid = mesh.add_columns(p, &lines);
        for j in 0..lines.columns.len() - 1 {
            let levels = grid[j].len().min(grid[j + 1].len());
            for k in 0..levels - 1 {
                let corners = [
                    grid[j][k],
                    grid[j + 1][k],
                    grid[j + 1][k + 1],
                    grid[j][k + 1],
                ];
                mesh.add_cell(corners, lines.sides(j, k, levels));
            }
        }
        mesh
    }

    /// The nodes of every column, bottom up: the levels below the tip,
    /// then, from the tip's column on, the levels above it up to the
    /// column's top along lines parallel to the face. Their indices by
    /// column.
    fn add_columns(&mut self, p: &Problem, lines: &Lines) -> Vec<Vec<usize>> {
        let (ya, cot) = (p.face.tip_y, p.cot_rake());
        lines
            .columns
            .iter()
            .enumerate()
            .map(|(j, &x0)| {
                let mut ids: Vec<usize> = lines.below.iter().map(|&y| self.add([x0, y])).collect();
                if j >= lines.tip_column {
                    let top = p.column_top(x0);
                    for f in &lines.above {
                        let y = ya + f * (top - ya);
                        ids.push(self.add([x0 - (y - ya) * cot, y]));
                    }
                }
                ids
            })
            .collect()
    }

    fn add(&mut self, point: [f64; 2]) -> usize {
        self.nodes.push(point);
        self.nodes.len() - 1
    }

    /// Four triangles about the cell's centre; `sides[i]` tags the edge
    /// from corner i to corner i + 1 when it is on the boundary.
    fn add_cell(&mut self, corners: [usize; 4], sides: [Option<Side>; 4]) {
        let mut centre = [0.0, 0.0];
        for &c in &corners {
            centre[0] += 0.25 * self.nodes[c][0];
            centre[1] += 0.25 * self.nodes[c][1];
        }
        let m = self.add(centre);
        for i in 0..4 {
            let (a, b) = (corners[i], corners[(i + 1) % 4]);
            self.triangles.push([a, b, m]);
            if let Some(side) = sides[i] {
                self.boundary.push((a, b, side));
            }
        }
    }

    /// The unit outward normal and length of boundary edge (a, b).
    pub fn outward(&self, a: usize, b: usize) -> ([f64; 2], f64) {
        let (p, q) = (self.nodes[a], self.nodes[b]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let len = dx.hypot(dy);
        ([dy / len, -dx / len], len)
    }

    /// The centroid of triangle e.
    pub fn centroid(&self, e: usize) -> [f64; 2] {
        let t = self.triangles[e];
        let mut c = [0.0, 0.0];
        for &i in &t {
            c[0] += self.nodes[i][0] / 3.0;
            c[1] += self.nodes[i][1] / 3.0;
        }
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn graded_ends_at_length_and_grows() {
        let r = graded(3.0, 0.05, 0.05);
        assert_eq!(r[0], 0.0);
        assert!((r[r.len() - 1] - 3.0).abs() < 1e-12);
        let steps: Vec<f64> = r.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(steps
            .windows(2)
            .all(|s| s[1] >= s[0] * 0.999 || s[1] > 0.02));
    }
}
