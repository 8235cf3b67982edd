//! Synthetic-truth recovery: curves made by soilcut from seeded random
//! values of 3 to 5 free keys of the refined model, with 2 % seeded noise
//! (weighted 1/P², as a user with such noise would), fitted from starts
//! anywhere in the bounds. Short travel (1.5 d) at a coarse increment
//! (d/50) so that it is quick.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use soilcut_io::Override;
use soilcut_study::fit::problem::Problem;
use soilcut_study::fit::{Compare, Fit, FitResult, Test};
use soilcut_study::{no_progress, BaseCase};

const REFINED: &str = include_str!("../../io/testdata/refined.toml");

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

/// d = 20 over 1.5 d at d/50.
fn coarse() -> Vec<Override> {
    ["run.travel=30", "run.increment=0.4"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect()
}

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
struct Case {
    keys: Vec<(&'static str, f64, f64)>,
    truth: Vec<f64>,
    fit: Fit,
}

fn draw(rng: &mut ChaCha8Rng, keys: &[(&str, f64, f64)], inner: f64) -> Vec<f64> {
    keys.iter()
        .map(|&(_, lo, hi)| {
            let margin = 0.5 * (1.0 - inner) * (hi - lo);
            lo + margin + (hi - lo - 2.0 * margin) * rng.random::<f64>()
        })
        .collect()
}

/// A set of values at which the case runs.
fn runnable(rng: &mut ChaCha8Rng, keys: &[(&str, f64, f64)], inner: f64) -> Vec<f64> {
    loop {
        let x = draw(rng, keys, inner);
        let mut o = coarse();
        o.extend(keys.iter().zip(&x).map(|(k, &v)| set(k.0, v)));
        if BaseCase::new(REFINED.to_string(), o).is_ok_and(|b| b.run(&[]).is_ok()) {
            return x;
        }
    }
}

fn case(seed: u64, jobs: usize, evaluations: usize) -> Case {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = rng.random_range(3..=5);
    let mut keys: Vec<(&str, f64, f64)> = KEYS.to_vec();
    while keys.len() > n {
        keys.remove(rng.random_range(0..keys.len()));
    }
    let truth = runnable(&mut rng, &keys, 0.8);
    let mut o = coarse();
    o.extend(keys.iter().zip(&truth).map(|(k, &v)| set(k.0, v)));
    let run = BaseCase::new(REFINED.to_string(), o)
        .unwrap()
        .run(&[])
        .unwrap();
    let measured: Vec<(f64, f64)> = run
        .history
        .iter()
        .map(|r| (r.u, r.force * (1.0 + 0.02 * normal(&mut rng))))
        .collect();
    let start = runnable(&mut rng, &keys, 1.0);
    let mut o = coarse();
    o.extend(keys.iter().zip(&start).map(|(k, &v)| set(k.0, v)));
    // The noise is 2 % of the force: weights 1/P² make it of one level.
    let mean = measured.iter().map(|p| p.1.abs()).sum::<f64>() / measured.len() as f64;
    let weights = measured.iter().map(|p| (mean / p.1).powi(2)).collect();
    let fit = Fit {
        tests: vec![Test {
            name: format!("truth {seed}"),
            base: BaseCase::new(REFINED.to_string(), o).unwrap(),
            weights,
            measured,
        }],
        free: keys.iter().map(|k| k.0.to_string()).collect(),
        bounds: keys
            .iter()
            .map(|&(k, lo, hi)| (k.to_string(), lo, hi))
            .collect(),
        compare: Compare::Raw,
        evaluations,
        population: 0,
        seed,
        polish_iterations: 30,
        profile_grid: 7,
        jobs,
    };
    Case { keys, truth, fit }
}

/// Every determined key within 1° (angles) or 10 % and inside its
/// interval: the failures, and how many keys were determined.
fn check(c: &Case, r: &FitResult) -> (Vec<String>, usize) {
    let (mut failures, mut determined) = (Vec::new(), 0);
    for (j, (&(key, ..), &truth)) in c.keys.iter().zip(&c.truth).enumerate() {
        let best = r.best.x[j];
        let p = &r.profiles[j];
        eprintln!(
            "{key}: truth {truth:.3}, best {best:.3}, interval {:?}..{:?}, {}",
            p.lower,
            p.upper,
            r.verdict(j)
        );
        if !p.determined {
            continue;
        }
        determined += 1;
        let tolerance = if key.starts_with("soil.friction") || key.starts_with("soil.dilation") {
            1.0
        } else {
            0.1 * truth
        };
        if (best - truth).abs() > tolerance {
            failures.push(format!("{key}: best {best}, truth {truth}"));
        }
        let (lo, hi) = (p.lower.unwrap(), p.upper.unwrap());
        if !(lo <= truth && truth <= hi) {
            failures.push(format!("{key}: truth {truth} outside {lo}..{hi}"));
        }
    }
    (failures, determined)
}

#[test]
fn recovers_every_key_it_calls_determined() {
    let (mut failures, mut determined) = (Vec::new(), Vec::new());
    for seed in 1..=3 {
        let c = case(seed, 2, 400);
        let r = c.fit.run(&no_progress).unwrap();
        eprintln!(
            "seed {seed}: RMS {} after {} runs",
            r.best.rms, r.evaluations
        );
        let problem = Problem::new(&r.tests, r.compare, &r.params);
        let (t, noise) = (problem.evaluate(&c.truth), r.noise.as_ref().unwrap());
        eprintln!(
            "truth: RMS {}, Δχ² {}; threshold {:?}",
            t.rms,
            noise.chi2(&t) - noise.chi2(&r.best),
            r.threshold
        );
        let (f, d) = check(&c, &r);
        failures.extend(f);
        determined.push(d);
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(
        determined.iter().all(|&d| d >= 1),
        "keys determined per truth: {determined:?}"
    );
}

#[test]
fn same_files_on_any_number_of_threads() {
    let (mut one, mut two) = (case(7, 1, 48).fit, case(7, 2, 48).fit);
    for f in [&mut one, &mut two] {
        f.polish_iterations = 4;
        f.profile_grid = 2;
    }
    let (a, b) = (
        one.run(&no_progress).unwrap(),
        two.run(&no_progress).unwrap(),
    );
    assert_eq!(a.csv(), b.csv());
    assert_eq!(a.curves_csv(), b.curves_csv());
    assert_eq!(a.profiles_csv(), b.profiles_csv());
    assert_eq!(a.search_csv(), b.search_csv());
    assert_eq!(a.markdown("x"), b.markdown("x"));
}

#[test]
fn measured_curve_must_lie_within_the_travel() {
    let mut f = case(7, 1, 16).fit;
    f.tests[0].measured.push((31.0, 1.0));
    f.tests[0].weights.push(1.0);
    let e = f.run(&no_progress).unwrap_err().to_string();
    assert!(e.contains("run.travel = 30"), "{e}");
    let mut f = case(7, 1, 16).fit;
    f.free.push("run.increment".into());
    let e = f.run(&no_progress).unwrap_err().to_string();
    assert!(e.contains("--bounds run.increment=lo:hi"), "{e}");
}
