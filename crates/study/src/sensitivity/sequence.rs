//! The Sobol sequence in up to 21 dimensions, scrambled (Owen's linear
//! matrix scramble with a random digital shift, as SciPy's
//! `qmc.Sobol(scramble=True)` does; Matoušek 1998).
//!
//! Direction numbers: Joe & Kuo (2008), the file new-joe-kuo-6.21201, its
//! first 21 dimensions (dimension 1 is the van der Corput sequence). Points
//! are taken in Gray-code order (Antonov & Saleev 1979): point n is the XOR
//! of the direction numbers v_j of the set bits j of n ⊕ (n >> 1), as SciPy
//! orders them. Written here rather than taken from a crate: the crates
//! found (`sobol` 1.0.2 of 2020, its fork `sobol-qmc`) do not scramble and
//! carry 21 201 dimensions of tables for the ≤ 21 a study needs.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Bits of every coordinate: a coordinate is an integer of 32 bits / 2³².
const BITS: usize = 32;

/// The most dimensions this sequence has.
pub const MAX_DIMENSIONS: usize = 21;

/// (s, a, m₁ … m_s) of dimensions 2 … 21: the degree s of the primitive
/// polynomial, its inner coefficients a, the initial direction numbers m.
const JOE_KUO: [(usize, u32, &[u32]); MAX_DIMENSIONS - 1] = [
    (1, 0, &[1]),
    (2, 1, &[1, 3]),
    (3, 1, &[1, 3, 1]),
    (3, 2, &[1, 1, 1]),
    (4, 1, &[1, 1, 3, 3]),
    (4, 4, &[1, 3, 5, 13]),
    (5, 2, &[1, 1, 5, 5, 17]),
    (5, 4, &[1, 1, 5, 5, 5]),
    (5, 7, &[1, 1, 7, 11, 19]),
    (5, 11, &[1, 1, 5, 1, 1]),
    (5, 13, &[1, 1, 1, 3, 11]),
    (5, 14, &[1, 3, 5, 5, 31]),
    (6, 1, &[1, 3, 3, 9, 7, 49]),
    (6, 13, &[1, 1, 1, 15, 21, 21]),
    (6, 16, &[1, 3, 1, 13, 27, 49]),
    (6, 19, &[1, 1, 1, 15, 7, 5]),
    (6, 22, &[1, 3, 1, 15, 13, 25]),
    (6, 25, &[1, 1, 5, 5, 19, 61]),
    (7, 1, &[1, 3, 7, 11, 23, 15, 103]),
    (7, 4, &[1, 3, 7, 13, 13, 15, 69]),
];

/// The direction numbers v₁ … v₃₂ of dimension `dim` (from 0), each a
/// binary fraction of 32 bits: v_j = m_j / 2^j for j ≤ s, then the
/// recurrence of the primitive polynomial (Joe & Kuo 2008, eq. 2).
fn directions(dim: usize) -> [u32; BITS] {
    let mut v = [0u32; BITS];
    if dim == 0 {
        for (j, vj) in v.iter_mut().enumerate() {
            *vj = 1 << (BITS - 1 - j);
        }
        return v;
    }
    let (s, a, m) = JOE_KUO[dim - 1];
    for j in 0..BITS {
        v[j] = if j < s {
            m[j] << (BITS - 1 - j)
        } else {
            let mut x = v[j - s] ^ (v[j - s] >> s);
            for k in 1..s {
                if (a >> (s - 1 - k)) & 1 == 1 {
                    x ^= v[j - k];
                }
            }
            x
        };
    }
    v
}

/// `v` multiplied by a random lower-triangular binary matrix with a unit
/// diagonal, digits most significant first: output digit i is the parity
/// of digits 1 … i of `v` picked by row i (`rows[i]`).
fn scrambled(v: u32, rows: &[u32; BITS]) -> u32 {
    let mut out = 0u32;
    for (i, row) in rows.iter().enumerate() {
        let bit = BITS - 1 - i;
        out |= ((row & v).count_ones() & 1) << bit;
    }
    out
}

/// A (scrambled) Sobol sequence of a given dimension.
#[derive(Clone, Debug)]
pub struct Sequence {
    directions: Vec<[u32; BITS]>,
    shift: Vec<u32>,
}

impl Sequence {
    /// The sequence in `dims` dimensions (1 … [`MAX_DIMENSIONS`]), the
    /// plain one for `scramble` `None`, else scrambled with that seed.
    pub fn new(dims: usize, scramble: Option<u64>) -> Sequence {
        assert!(
            (1..=MAX_DIMENSIONS).contains(&dims),
            "a Sobol sequence of 1 to {MAX_DIMENSIONS} dimensions"
        );
        let mut directions: Vec<[u32; BITS]> = (0..dims).map(directions).collect();
        let mut shift = vec![0u32; dims];
        if let Some(seed) = scramble {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            for (v, shift) in directions.iter_mut().zip(&mut shift) {
                let mut rows = [0u32; BITS];
                for (i, row) in rows.iter_mut().enumerate() {
                    let bit = BITS - 1 - i;
                    // Random digits above the diagonal's, the diagonal 1.
                    let above = u32::MAX.checked_shl(bit as u32 + 1).unwrap_or(0);
                    *row = (rng.random::<u32>() & above) | (1 << bit);
                }
                for vj in v.iter_mut() {
                    *vj = scrambled(*vj, &rows);
                }
                *shift = rng.random::<u32>();
            }
        }
        Sequence { directions, shift }
    }

    /// Point `n` (from 0), each coordinate in [0, 1).
    pub fn point(&self, n: u32) -> Vec<f64> {
        let gray = n ^ (n >> 1);
        self.directions
            .iter()
            .zip(&self.shift)
            .map(|(v, shift)| {
                let mut x = *shift;
                for (j, vj) in v.iter().enumerate() {
                    if (gray >> j) & 1 == 1 {
                        x ^= vj;
                    }
                }
                f64::from(x) / (1u64 << BITS) as f64
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first 2^m points of a Sobol sequence put one point in each
    /// of the 2^m intervals [k/2^m, (k+1)/2^m) of every coordinate, and,
    /// for every pair of dimensions, one in each of the 2^m cells of a
    /// (t, m, 2)-net at t = 0 for the first two (the van der Corput
    /// sequence and its partner): true of the plain and the scrambled one.
    #[test]
    fn the_first_points_fill_every_stratum_once() {
        for scramble in [None, Some(7)] {
            let seq = Sequence::new(MAX_DIMENSIONS, scramble);
            let m = 6;
            let n = 1usize << m;
            let points: Vec<Vec<f64>> = (0..n as u32).map(|i| seq.point(i)).collect();
            for d in 0..MAX_DIMENSIONS {
                let mut strata: Vec<usize> =
                    points.iter().map(|p| (p[d] * n as f64) as usize).collect();
                strata.sort();
                assert_eq!(strata, (0..n).collect::<Vec<_>>(), "dimension {}", d + 1);
            }
            // Dimensions 1 and 2: every 2^3 × 2^3 cell holds one point.
            let mut cells: Vec<usize> = points
                .iter()
                .map(|p| (p[0] * 8.0) as usize * 8 + (p[1] * 8.0) as usize)
                .collect();
            cells.sort();
            assert_eq!(cells, (0..n).collect::<Vec<_>>());
        }
    }

    /// The plain sequence's points are those of SciPy 1.17's
    /// `qmc.Sobol(d=21, scramble=False)` (Joe and Kuo's direction
    /// numbers) to SciPy's 30 bits, deep into the sequence.
    #[test]
    fn the_plain_sequence_is_joe_and_kuo_s() {
        let seq = Sequence::new(MAX_DIMENSIONS, None);
        for (n, expected) in SCIPY_POINTS {
            for (d, (x, e)) in seq.point(n).iter().zip(expected).enumerate() {
                let below = (x - e).abs() < 1.0 / (1u64 << 30) as f64;
                assert!(below, "point {n}, dimension {}: {x} against {e}", d + 1);
            }
        }
    }

    include!("sequence_scipy.rs");
}
