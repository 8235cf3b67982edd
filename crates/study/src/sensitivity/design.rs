//! The designs of a sensitivity study, in the unit cube [0, 1)^D (each
//! coordinate then scaled to its key's range, lo + (hi − lo) u).

use super::sequence::Sequence;
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Saltelli's design (Saltelli et al. 2010) for first-order and total
/// indices of `d` inputs: `n` points of the scrambled Sobol sequence in 2d
/// dimensions, A = their first d coordinates, B = their last d; for each
/// point i the rows A_i, A_B^(1)_i … A_B^(d)_i (A_i with coordinate j taken
/// from B_i), then with `second_order` B_A^(1)_i … B_A^(d)_i (B_i with
/// coordinate j taken from A_i), and B_i: n (d + 2), or n (2d + 2), rows in
/// the order SALib's `sobol.analyze(..., calc_second_order=...)` reads them.
pub fn saltelli(d: usize, n: usize, second_order: bool, seed: u64) -> Vec<Vec<f64>> {
    let sequence = Sequence::new(2 * d, Some(seed));
    let mut rows = Vec::with_capacity(n * rows_per_point(d, second_order));
    let crossed = |to: &[f64], from: &[f64], j: usize| {
        let mut row = to.to_vec();
        row[j] = from[j];
        row
    };
    for i in 0..n {
        let point = sequence.point(i as u32);
        let (a, b) = point.split_at(d);
        rows.push(a.to_vec());
        rows.extend((0..d).map(|j| crossed(a, b, j)));
        if second_order {
            rows.extend((0..d).map(|j| crossed(b, a, j)));
        }
        rows.push(b.to_vec());
    }
    rows
}

/// Rows of Saltelli's design a base point: d + 2, or 2d + 2 with the
/// second-order rows.
pub fn rows_per_point(d: usize, second_order: bool) -> usize {
    if second_order {
        2 * d + 2
    } else {
        d + 2
    }
}

/// The step Δ = p / (2 (p − 1)) of a Morris design on `levels` = p levels
/// (p even): half the levels' span, so that every level has a partner Δ
/// away (Morris 1991; SALib's `_compute_delta`).
pub fn morris_delta(levels: usize) -> f64 {
    levels as f64 / (2.0 * (levels as f64 - 1.0))
}

/// Morris's design: `r` trajectories of d + 1 points on the grid
/// {0, 1/(p−1), …, 1} of p = `levels` levels (p even). A trajectory starts
/// at a random grid point and moves one input at a time, in a random
/// order, by +Δ where that stays on the grid and −Δ otherwise (a level
/// l < p/2 moves up p/2 levels, any other down): r (d + 1) rows.
pub fn morris(d: usize, r: usize, levels: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let half = levels / 2;
    let grid = |l: usize| l as f64 / (levels - 1) as f64;
    let mut rows = Vec::with_capacity(r * (d + 1));
    for _ in 0..r {
        let mut at: Vec<usize> = (0..d).map(|_| rng.random_range(0..levels)).collect();
        let mut order: Vec<usize> = (0..d).collect();
        order.shuffle(&mut rng);
        rows.push(at.iter().map(|&l| grid(l)).collect());
        for j in order {
            at[j] = if at[j] < half {
                at[j] + half
            } else {
                at[j] - half
            };
            rows.push(at.iter().map(|&l| grid(l)).collect());
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn saltelli_rows_take_one_coordinate_from_the_other_matrix() {
        assert_eq!(
            saltelli(3, 4, false, 1),
            {
                let all = saltelli(3, 4, true, 1);
                let first: Vec<Vec<f64>> = all
                    .chunks(8)
                    .flat_map(|p| [&p[..4], &p[7..]].concat())
                    .collect();
                first
            },
            "the second-order rows come between A_B and B, the rest unchanged"
        );
        let rows = saltelli(3, 4, true, 1);
        assert_eq!(rows.len(), 4 * 8);
        for point in rows.chunks(8) {
            let (a, b) = (&point[0], &point[7]);
            for j in 0..3 {
                for k in 0..3 {
                    let (ab, ba) = if k == j { (b, a) } else { (a, b) };
                    assert_eq!(point[1 + j][k], ab[k]);
                    assert_eq!(point[4 + j][k], ba[k]);
                }
            }
        }
    }

    #[test]
    fn morris_trajectories_move_each_input_once_by_delta() {
        let (d, levels) = (4, 4);
        let rows = morris(d, 20, levels, 3);
        let delta = morris_delta(levels);
        for trajectory in rows.chunks(d + 1) {
            let mut moved = vec![0; d];
            for step in trajectory.windows(2) {
                let changed: Vec<usize> = (0..d).filter(|&k| step[0][k] != step[1][k]).collect();
                assert_eq!(changed.len(), 1);
                let k = changed[0];
                assert!(((step[1][k] - step[0][k]).abs() - delta).abs() < 1e-15);
                assert!((0.0..=1.0).contains(&step[1][k]));
                moved[k] += 1;
            }
            assert_eq!(moved, vec![1; d]);
        }
        assert_ne!(rows, morris(d, 20, levels, 4), "the seed matters");
    }
}
