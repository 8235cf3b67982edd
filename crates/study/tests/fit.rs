//! Synthetic-truth recovery: curves made by soilcut from seeded random
//! values of 3 to 5 free keys of the refined model, with 2 % seeded noise
//! (weighted 1/P², as a user with such noise would), fitted from starts
//! anywhere in the bounds ([`synthetic`]). Short travel (1.5 d) at a
//! coarse increment (d/50) so that it is quick.

use crate::synthetic;

use soilcut_study::fit::problem::Problem;
use soilcut_study::fit::{FitResult, Method};
use soilcut_study::no_progress;
use synthetic::{recovered, Case};

/// d = 20 over 1.5 d at d/50, with the face friction rule and the ground
/// the recovery was established on. Under the mobilised rule (issue 20)
/// two of the three truths fall outside their profile intervals at this
/// coarse increment (seed 1: the truth's Δχ² 12.7 against the threshold
/// 9.49); on the vertex ground (issue 28: the default of these softening
/// cases since) one of the eight determined keys does (seed 1's φr 30.13
/// outside 30.27-31.22, its truth's Δχ² 14.2 against 9.49): open questions of the smoothness in the keys at
/// coarse increments, not of the fit's machinery, which this test checks.
const COARSE: [&str; 4] = [
    "run.travel=30",
    "run.increment=0.4",
    "run.ground=\"nodes\"",
    "choices.face_friction=sign",
];

fn case(seed: u64, jobs: usize, evaluations: usize) -> Case {
    synthetic::case(seed, jobs, evaluations, &COARSE)
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
        if !recovered(key, best, truth) {
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
    // Not vacuous: keys are determined. Not every truth need have one:
    // at seed 2 the χ² of the best values and their own ensemble members
    // spread over 687 (the chaos of this coarse case, against a bootstrap
    // threshold of about 10 for its 2 % noise), so its intervals are as
    // wide as the chaos makes the curves indistinguishable (`fit::chaos`).
    assert!(
        determined.iter().sum::<usize>() >= 4,
        "keys determined per truth: {determined:?}"
    );
}

/// The files of a short fit by `method` on 1 and 2 threads.
fn same_files_on_any_number_of_threads(method: Method) {
    let (mut one, mut two) = (case(7, 1, 48).fit, case(7, 2, 48).fit);
    for f in [&mut one, &mut two] {
        f.method = method;
        f.polish_iterations = 4;
        f.profile_grid = 2;
    }
    let (a, b) = (
        one.run(&no_progress).unwrap(),
        two.run(&no_progress).unwrap(),
    );
    assert_eq!(a.best, b.best);
    assert_eq!(a.csv(), b.csv());
    assert_eq!(a.curves_csv(), b.curves_csv());
    assert_eq!(a.profiles_csv(), b.profiles_csv());
    assert_eq!(a.search_csv(), b.search_csv());
    assert_eq!(a.markdown("x"), b.markdown("x"));
}

#[test]
fn differential_evolution_gives_the_same_files_on_any_number_of_threads() {
    same_files_on_any_number_of_threads(Method::DifferentialEvolution);
}

#[test]
fn cma_es_gives_the_same_files_on_any_number_of_threads() {
    same_files_on_any_number_of_threads(Method::CmaEs);
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

/// The noise row of `fit.md`'s test table: (σ, RMS at best).
fn noise_row(md: &str) -> (f64, f64) {
    let header = md
        .lines()
        .position(|l| l.contains("noise level σ"))
        .unwrap_or_else(|| panic!("no noise table:\n{md}"));
    let row = md.lines().nth(header + 2).unwrap();
    let cells: Vec<f64> = row
        .split('|')
        .filter_map(|c| c.trim().parse().ok())
        .collect();
    (cells[cells.len() - 2], cells[cells.len() - 1])
}

/// `fit.md` prints the σ its χ² uses, the noise of a residual of the
/// test's mean weight (its weights here are 1/P², far from 1), and with
/// `--profile-points 0` neither a threshold (it had "Δχ² ≤ NaN") nor the
/// profiles' picture, which it did not draw (issue 50 item 6).
#[test]
fn fit_md_says_the_noise_its_chi2_uses_and_only_what_it_drew() {
    let mut f = case(7, 1, 16).fit;
    f.polish_iterations = 4;
    f.profile_grid = 0;
    let r = f.run(&no_progress).unwrap();
    let md = r.markdown("x");
    assert!(!md.contains("NaN"), "{md}");
    assert!(!md.contains("profiles.png"), "{md}");
    let (sigma, rms) = noise_row(&md);
    let (n, p) = (f.tests[0].measured.len() as f64, f.free.len() as f64);
    let expected = rms * (n / (n - p)).sqrt();
    assert!(
        (sigma / expected - 1.0).abs() < 1e-4,
        "σ {sigma}, RMS {rms}"
    );
    // χ² at the best is then N − p, the residuals' degrees of freedom.
    let chi2 = r.noise.as_ref().unwrap().chi2(&r.best);
    assert!((chi2 - (n - p)).abs() < 1e-6 * n, "{chi2}");
    f.profile_grid = 2;
    let md = f.run(&no_progress).unwrap().markdown("x");
    assert!(md.contains("(profiles.png)") && !md.contains("NaN"), "{md}");
}
