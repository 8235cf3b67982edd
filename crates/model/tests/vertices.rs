//! The vertex ground (issue 28): an increment's motion is the exact map of
//! docs/model.md §3 on material vertices. Checked against closed forms on
//! flat ground (the band's area A0 and its dilation, the affine image of
//! a non-dilating band), conservation of mass and area over many
//! increments, and state that travels with the block untouched.

use soilcut_model::vertices::motion::Cut;
use soilcut_model::vertices::Vertices;

const DEPTH: f64 = 1.0;
const FLOOR: f64 = 2.0;
const REPOSE: f64 = 33.0;

/// The cut of a band of width `band_width` at angle β (degrees) with
/// dilation ψ (degrees) through the ground, emerging where its lower
/// boundary from the tip meets the surface.
fn cut(ground: &Vertices, beta: f64, psi: f64, band_width: f64, v0: f64) -> Cut {
    let (beta, psi) = (beta.to_radians(), psi.to_radians());
    let t = beta.tan();
    let x0 = ground.x[0];
    let above = |k: usize| ground.y[k] - (-DEPTH + t * (ground.x[k] - x0));
    let k = (1..ground.x.len()).find(|&k| above(k) <= 0.0).unwrap();
    let lambda = above(k - 1) / (above(k - 1) - above(k));
    let emergence = ground.x[k - 1] + lambda * (ground.x[k] - ground.x[k - 1]);
    Cut {
        depth: DEPTH,
        deepening: 0.0,
        rake: soilcut_model::rake::Rake::new(90.0),
        emergence,
        thickness: band_width / beta.cos(),
        width: band_width,
        min_spacing: 0.25 * v0,
        snap: 0.0,
        advance: v0,
        rise: v0 * (beta + psi).tan(),
        slip: if band_width > 0.0 {
            v0 * psi.cos() / (beta + psi).cos()
        } else {
            v0 / beta.cos()
        },
        tan_psi: if band_width > 0.0 { psi.tan() } else { 0.0 },
        band_shear: Default::default(),
        unit_weight: Default::default(),
    }
}

fn assert_close(a: f64, b: f64, tolerance: f64, what: &str) {
    assert!(
        (a - b).abs() <= tolerance * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

#[test]
fn a_band_through_flat_ground_dilates_by_its_closed_form() {
    let mut ground = Vertices::flat(6.0, 0.05, FLOOR, 1.0);
    let c = cut(&ground, 30.0, 10.0, 0.1, 0.01);
    let (mass, area) = (ground.mass(), ground.area());
    let moved = ground.apply(&c).expect("a band through flat ground");
    // A0: the strip between the lower and upper boundary below y = 0, a
    // parallelogram less the corner above the surface (M19).
    let t = 30f64.to_radians().tan();
    let a0 = c.thickness * c.emergence - 0.5 * c.thickness * c.thickness / t;
    let dilation = a0 * c.slip * c.tan_psi / c.width;
    assert_close(moved.dilation_area, dilation, 1e-12, "dilation");
    assert_close(ground.mass(), mass, 1e-13, "mass");
    let left_behind = c.advance * (FLOOR - DEPTH);
    assert_close(ground.area(), area - left_behind + dilation, 1e-13, "area");
    assert_eq!(ground.x[0], c.advance, "the face moved by v0");
}

#[test]
fn without_dilation_the_band_moves_by_the_exact_affine_map() {
    let mut ground = Vertices::flat(6.0, 0.05, FLOOR, 1.0);
    let c = cut(&ground, 25.0, 0.0, 0.12, 0.01);
    let before = ground.clone();
    let t = 25f64.to_radians().tan();
    let moved = ground.apply(&c).unwrap();
    // Every old vertex between the face's piece and the emergence point
    // lands where the map takes it: the block by (v0, rise), band soil by
    // its share g of that; nothing is resampled.
    for k in 2..before.x.len() {
        let (x, y) = (before.x[k], before.y[k]);
        if x >= c.emergence {
            break;
        }
        let g = ((y + DEPTH - t * x) / c.thickness).clamp(0.0, 1.0);
        let (xn, yn) = (x + g * c.advance, y + g * c.rise);
        let k = ground
            .x
            .iter()
            .position(|&v| (v - xn).abs() < 1e-12)
            .unwrap();
        assert_close(ground.y[k], yn, 1e-12, "image height");
    }
    assert!(moved.band.start > 0 && moved.band.end > moved.band.start);
}

#[test]
fn the_block_carries_its_state_untouched() {
    let mut ground = Vertices::flat(6.0, 0.05, FLOOR, 1.0);
    ground.accumulated_shear[3] = 0.375;
    let (x3, y3) = (ground.x[3], ground.y[3]);
    let c = cut(&ground, 30.0, 5.0, 0.1, 0.01);
    ground.apply(&c).unwrap();
    assert_eq!(ground.accumulated_shear[3], 0.375);
    assert_eq!(ground.x[3], x3 + c.advance);
    assert_eq!(ground.y[3], y3 + c.rise);
}

#[test]
fn a_slip_line_slides_the_block_and_shears_its_surface() {
    let mut ground = Vertices::flat(6.0, 0.05, FLOOR, 1.0);
    let c = cut(&ground, 30.0, 0.0, 0.0, 0.01);
    let mass = ground.mass();
    let moved = ground.apply(&c).unwrap();
    assert_eq!(moved.band.len(), 1);
    assert_eq!(ground.accumulated_shear[moved.band.start], c.slip);
    assert_close(ground.mass(), mass, 1e-13, "mass");
    assert!(ground.x.windows(2).all(|w| w[1] > w[0]));
}

#[test]
fn many_increments_keep_mass_and_an_ordered_ground() {
    for (band_width, psi) in [(0.1, 10.0), (0.1, -5.0), (0.0, 0.0)] {
        let mut ground = Vertices::flat(12.0, 0.04, FLOOR, 1.0);
        let mass = ground.mass();
        for step in 0..300 {
            // The band steepens and flattens as it would over a cut.
            let beta = 28.0 + 6.0 * (step as f64 * 0.05).sin();
            let c = cut(&ground, beta, psi, band_width, 0.01);
            ground.apply(&c).expect("a band the vertices resolve");
            let s = REPOSE.to_radians().tan();
            ground.relax((s, s), 0.04);
            assert!(ground.x.windows(2).all(|w| w[1] > w[0]), "step {step}");
        }
        assert_close(ground.mass(), mass, 1e-11, "mass after 300 increments");
        let s = REPOSE.to_radians().tan();
        for k in 0..ground.pieces() {
            let slope = (ground.y[k + 1] - ground.y[k]) / (ground.x[k + 1] - ground.x[k]);
            assert!(slope.abs() <= s * (1.0 + 1e-6), "piece {k} slope {slope}");
        }
        // The block's soil piles up in front of the face.
        assert!(ground.y[0] > 0.2, "pile height {}", ground.y[0]);
    }
}
