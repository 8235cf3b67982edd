//! Synthetic-truth calibration problems, shared by the recovery test
//! (`tests/fit.rs`) and the comparison of the global searches
//! (`crates/study/examples/calibration_methods.rs`): curves made by
//! soilcut from seeded random values of 3 to 5 free keys of the refined
//! model, with 2 % seeded noise (weighted 1/P², as a user with such
//! noise would), to be fitted from a start anywhere in the bounds.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use soilcut_io::Override;
use soilcut_study::fit::{is_angle, Compare, Fit, Method, Test};
use soilcut_study::BaseCase;

const REFINED: &str = include_str!("../../../io/testdata/refined.toml");

/// Keys that may be free and the box each is fitted in (the truth is drawn
/// from its inner 80 %, the case's start from anywhere in it).
const KEYS: [(&str, f64, f64); 6] = [
    ("soil.friction.initial", 12.0, 28.0),
    ("soil.friction.peak", 30.0, 44.0),
    ("soil.peak_shear", 1.0, 3.0),
    ("soil.friction.residual", 24.0, 32.0),
    ("soil.residual_shear", 3.0, 6.0),
    ("soil.dilation.peak", 0.0, 10.0),
];

fn set(key: &str, x: f64) -> Override {
    format!("{key}={x}").parse().unwrap()
}

/// A standard normal number (Box-Muller).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let (a, b): (f64, f64) = (rng.random(), rng.random());
    (-2.0 * (1.0 - a).ln()).sqrt() * (std::f64::consts::TAU * b).cos()
}

/// A seeded problem: its free keys, their truth and the fit from a start
/// anywhere in the bounds.
pub struct Case {
    pub keys: Vec<(&'static str, f64, f64)>,
    pub truth: Vec<f64>,
    pub fit: Fit,
}

fn draw(rng: &mut ChaCha8Rng, keys: &[(&str, f64, f64)], inner: f64) -> Vec<f64> {
    keys.iter()
        .map(|&(_, lo, hi)| {
            let margin = 0.5 * (1.0 - inner) * (hi - lo);
            lo + margin + (hi - lo - 2.0 * margin) * rng.random::<f64>()
        })
        .collect()
}

/// The case's overrides: `resolution` then the keys' values.
fn overrides(resolution: &[&str], keys: &[(&str, f64, f64)], x: &[f64]) -> Vec<Override> {
    let mut o: Vec<Override> = resolution.iter().map(|s| s.parse().unwrap()).collect();
    o.extend(keys.iter().zip(x).map(|(k, &v)| set(k.0, v)));
    o
}

/// A set of values at which the case runs.
fn runnable(
    rng: &mut ChaCha8Rng,
    keys: &[(&str, f64, f64)],
    inner: f64,
    resolution: &[&str],
) -> Vec<f64> {
    loop {
        let x = draw(rng, keys, inner);
        let o = overrides(resolution, keys, &x);
        if BaseCase::new(REFINED.to_string(), o).is_ok_and(|b| b.run(&[]).is_ok()) {
            return x;
        }
    }
}

/// The problem of seed `seed` with the case's travel and increment set by
/// `resolution` (overrides such as `run.travel=30`); the fit searches by
/// differential evolution with the seed `seed`, `evaluations` runs, on
/// `jobs` threads.
pub fn case(seed: u64, jobs: usize, evaluations: usize, resolution: &[&str]) -> Case {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = rng.random_range(3..=5);
    let mut keys: Vec<(&str, f64, f64)> = KEYS.to_vec();
    while keys.len() > n {
        keys.remove(rng.random_range(0..keys.len()));
    }
    let truth = runnable(&mut rng, &keys, 0.8, resolution);
    let run = BaseCase::new(REFINED.to_string(), overrides(resolution, &keys, &truth))
        .unwrap()
        .run(&[])
        .unwrap();
    let measured: Vec<(f64, f64)> = run
        .history
        .iter()
        .map(|r| (r.u, r.force * (1.0 + 0.02 * normal(&mut rng))))
        .collect();
    let start = runnable(&mut rng, &keys, 1.0, resolution);
    // The noise is 2 % of the force: weights 1/P² make it of one level.
    let mean = measured.iter().map(|p| p.1.abs()).sum::<f64>() / measured.len() as f64;
    let weights = measured.iter().map(|p| (mean / p.1).powi(2)).collect();
    let fit = Fit {
        tests: vec![Test {
            name: format!("truth {seed}"),
            base: BaseCase::new(REFINED.to_string(), overrides(resolution, &keys, &start)).unwrap(),
            weights,
            measured,
        }],
        free: keys.iter().map(|k| k.0.to_string()).collect(),
        bounds: keys
            .iter()
            .map(|&(k, lo, hi)| (k.to_string(), lo, hi))
            .collect(),
        compare: Compare::Raw,
        method: Method::DifferentialEvolution,
        evaluations,
        population: 0,
        seed,
        polish_iterations: 30,
        profile_grid: 7,
        jobs,
    };
    Case { keys, truth, fit }
}

/// Whether `best` recovers `truth` of `key`: within 1° (angles) or 10 %.
pub fn recovered(key: &str, best: f64, truth: f64) -> bool {
    let tolerance = if is_angle(key) { 1.0 } else { 0.1 * truth };
    (best - truth).abs() <= tolerance
}
