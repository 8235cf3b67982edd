//! Synthetic-truth recovery: a curve made by soilcut from known values,
//! with 2 % seeded noise, fitted from a start 20 % away.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use soilcut_io::Override;
use soilcut_study::fit::{rms_error, Fit};
use soilcut_study::{no_progress, BaseCase};

const REFINED: &str = include_str!("../../io/testdata/refined.toml");

/// Table 1 HS (φc 20°, φp 35°, up 2) over 1.5 d at d/40.
fn truth_overrides() -> Vec<Override> {
    ["run.travel=30", "run.increment=0.5"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect()
}

/// The truth's force at every other increment, times 1 + 0.02 n with n
/// standard normal (Box-Muller, seeded).
fn measured() -> Vec<(f64, f64)> {
    let truth = BaseCase::new(REFINED.to_string(), truth_overrides()).unwrap();
    let run = truth.run(&[]).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(2024);
    run.history
        .iter()
        .step_by(2)
        .map(|r| {
            let (a, b): (f64, f64) = (rng.random(), rng.random());
            let n = (-2.0 * (1.0 - a).ln()).sqrt() * (std::f64::consts::TAU * b).cos();
            (r.u, r.force * (1.0 + 0.02 * n))
        })
        .collect()
}

fn fit(jobs: usize) -> Fit {
    let mut set = truth_overrides();
    // 20 % away from the truth.
    for s in [
        "soil.friction.initial=16",
        "soil.friction.peak=42",
        "soil.peak_shear=2.4",
    ] {
        set.push(s.parse().unwrap());
    }
    Fit {
        base: BaseCase::new(REFINED.to_string(), set).unwrap(),
        free: vec![
            "soil.friction.initial".into(),
            "soil.friction.peak".into(),
            "soil.peak_shear".into(),
        ],
        bounds: vec![],
        measured: measured(),
        starts: 4,
        seed: 11,
        max_iters: 60,
        jobs,
    }
}

#[test]
fn recovers_the_truth_from_20_percent_away() {
    let result = fit(2).run(&no_progress).unwrap();
    let [phi_c, phi_p, up] = result.best[..] else {
        panic!()
    };
    assert!((phi_c - 20.0).abs() < 1.0, "φc = {phi_c}");
    assert!((phi_p - 35.0).abs() < 1.0, "φp = {phi_p}");
    assert!((up - 2.0).abs() < 0.2, "up = {up}");
    assert!(result.best_rms < 0.5 * result.start_rms);
    assert_eq!(
        result.best_rms,
        rms_error(&result.best_run, &result.measured)
    );
}

#[test]
fn same_files_on_any_number_of_threads() {
    let mut one = fit(1);
    let mut two = fit(2);
    for f in [&mut one, &mut two] {
        f.starts = 3;
        f.max_iters = 15;
    }
    let (a, b) = (
        one.run(&no_progress).unwrap(),
        two.run(&no_progress).unwrap(),
    );
    assert_eq!(a.csv(), b.csv());
    assert_eq!(a.curves_csv(), b.curves_csv());
    assert_eq!(a.markdown("x"), b.markdown("x"));
    assert_eq!(a.best_toml(), b.best_toml());
    assert_eq!(a.starts.len(), 3 + 1, "the starts and the polish");
}

#[test]
fn measured_curve_must_lie_within_the_travel() {
    let mut f = fit(1);
    f.measured.push((31.0, 1.0));
    let e = f.run(&no_progress).unwrap_err().to_string();
    assert!(e.contains("run.travel = 30"), "{e}");
    let mut f = fit(1);
    f.free.push("run.increment".into());
    let e = f.run(&no_progress).unwrap_err().to_string();
    assert!(e.contains("--bounds run.increment=lo:hi"), "{e}");
}
