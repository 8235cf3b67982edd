//! `soilcut_study::sensitivity`: the estimators against indices known
//! analytically, and the study's rules.

use soilcut_study::sensitivity::{Function, Method, Model, Range, Sensitivity, SensitivityResult};
use std::f64::consts::PI;

fn study(
    function: Function,
    ranges: &[(&str, f64, f64)],
    method: Method,
    samples: usize,
) -> Sensitivity {
    Sensitivity {
        model: Model::Function(function),
        ranges: ranges
            .iter()
            .map(|&(key, lo, hi)| Range {
                key: key.into(),
                lo,
                hi,
            })
            .collect(),
        method,
        samples,
        members: 1,
        dummy: false,
        seed: 1,
        jobs: 1,
    }
}

fn ishigami(samples: usize) -> Sensitivity {
    let r = [("x1", -PI, PI), ("x2", -PI, PI), ("x3", -PI, PI)];
    study(
        Function::Ishigami,
        &r,
        Method::Sobol {
            second_order: false,
        },
        samples,
    )
}

fn run(s: &Sensitivity) -> SensitivityResult {
    s.run(&soilcut_study::no_progress).unwrap()
}

/// Rows of indices.csv as (output, key, numbers).
fn rows(result: &SensitivityResult) -> Vec<(String, String, Vec<f64>)> {
    result
        .indices_csv()
        .lines()
        .skip(1)
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            let numbers = f[2..].iter().map(|x| x.parse().unwrap()).collect();
            (f[0].to_string(), f[1].to_string(), numbers)
        })
        .collect()
}

/// Ishigami (a = 7, b = 0.1) at N = 2^13 base points (40 960 runs):
/// S1 and ST within 0.02 of the analytic values.
#[test]
fn sobol_indices_of_ishigami_are_the_analytic_ones() {
    let s1 = [0.3139, 0.4424, 0.0];
    let st = [0.5576, 0.4424, 0.2437];
    let result = run(&ishigami(1 << 13));
    let rows = rows(&result);
    assert_eq!(rows.len(), 3);
    for (j, (_, key, v)) in rows.iter().enumerate() {
        assert!(
            (v[0] - s1[j]).abs() < 0.02,
            "{key}: S1 {} against {}",
            v[0],
            s1[j]
        );
        assert!(
            (v[3] - st[j]).abs() < 0.02,
            "{key}: ST {} against {}",
            v[3],
            st[j]
        );
        assert!(
            v[1] < v[0] && v[0] < v[2] && v[4] < v[3] && v[3] < v[5],
            "{key}: {v:?}"
        );
    }
}

/// Ishigami's only interaction is x1 × x3: S2_13 = b² π⁸ (1/18 − 1/50) /
/// V = 0.2437, S2_12 = S2_23 = 0. At N = 2^13 base points (65 536 runs)
/// each S2 is within 0.03 of its value and within its interval of it;
/// indices2.csv has a row per pair, and the second-order rows leave S1
/// and ST where they were.
#[test]
fn second_order_indices_of_ishigami_are_the_analytic_ones() {
    let mut s = ishigami(1 << 13);
    s.method = Method::Sobol { second_order: true };
    assert_eq!(s.runs(), (1 << 13) * 8);
    let result = run(&s);
    let text = result.indices2_csv();
    let pair_rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let pairs: Vec<(&str, &str)> = pair_rows.iter().map(|r| (r[1], r[2])).collect();
    assert_eq!(pairs, [("x1", "x2"), ("x1", "x3"), ("x2", "x3")]);
    for (row, analytic) in pair_rows.iter().zip([0.0, 0.2437, 0.0]) {
        let [s2, low, high] = [3, 4, 5].map(|i| row[i].parse::<f64>().unwrap());
        assert!((s2 - analytic).abs() < 0.03, "{row:?} against {analytic}");
        assert!(
            low <= analytic && analytic <= high,
            "{row:?} against {analytic}"
        );
    }
    let first = rows(&result);
    let without = rows(&run(&ishigami(1 << 13)));
    for (a, b) in first.iter().zip(&without) {
        assert!(
            (a.2[0] - b.2[0]).abs() < 0.01 && (a.2[3] - b.2[3]).abs() < 0.01,
            "{a:?} {b:?}"
        );
    }
}

/// On Σ c_i x_i every elementary effect of x_i is c_i (range 1): μ* = μ
/// = c_i, σ = 0, and the ranking by μ* is that of the coefficients.
#[test]
fn morris_ranks_a_linear_function_s_keys_by_their_coefficients() {
    let r = [("x1", 0.0, 1.0), ("x2", 0.0, 1.0), ("x3", 0.0, 1.0)];
    let result = run(&study(
        Function::Linear,
        &r,
        Method::Morris { levels: 4 },
        10,
    ));
    let rows = rows(&result);
    for (j, (_, key, v)) in rows.iter().enumerate() {
        let c = (j + 1) as f64;
        assert!(
            (v[0] - c).abs() < 1e-12 && (v[4] - c).abs() < 1e-12,
            "{key}: {v:?}"
        );
        assert!(v[3].abs() < 1e-12, "{key}: σ {}", v[3]);
    }
    let mut by_mu_star: Vec<(f64, &str)> = rows.iter().map(|r| (r.2[0], r.1.as_str())).collect();
    by_mu_star.sort_by(|a, b| b.0.total_cmp(&a.0));
    let order: Vec<&str> = by_mu_star.iter().map(|r| r.1).collect();
    assert_eq!(order, ["x3", "x2", "x1"]);
}

/// The dummy input no evaluation reads has S1 and ST intervals holding
/// 0, where a real input does not.
#[test]
fn a_dummy_input_has_indices_of_zero() {
    let mut s = ishigami(256);
    s.dummy = true;
    let rows = rows(&run(&s));
    let dummy = rows.iter().find(|r| r.1 == "dummy").unwrap();
    let v = &dummy.2;
    assert!(
        v[1] <= 0.0 && 0.0 <= v[2] && v[4] <= 0.0 && 0.0 <= v[5],
        "{v:?}"
    );
    let x2 = &rows[1].2;
    assert!(x2[1] > 0.0 && x2[4] > 0.0, "{x2:?}");
}

/// Any number of threads and the same seed give the same files; another
/// seed another design.
#[test]
fn results_do_not_depend_on_threads_but_on_the_seed() {
    let mut s = ishigami(64);
    let one = run(&s).indices_csv();
    s.jobs = 3;
    assert_eq!(run(&s).indices_csv(), one);
    s.seed = 2;
    assert_ne!(run(&s).indices_csv(), one);
}

/// Sample sizes below an estimator's least, a range with lo >= hi and a
/// function given the wrong inputs are refused before any run.
#[test]
fn bad_designs_are_refused() {
    for (samples, method) in [
        (
            8,
            Method::Sobol {
                second_order: false,
            },
        ),
        (
            100,
            Method::Sobol {
                second_order: false,
            },
        ),
        (1, Method::Morris { levels: 4 }),
    ] {
        let mut s = ishigami(samples);
        s.method = method;
        let e = s.check().unwrap_err().to_string();
        assert!(e.contains("--samples"), "{e}");
    }
    let e = Method::named("morris", 4, true).unwrap_err().to_string();
    assert!(e.contains("--second-order"), "{e}");
    let mut s = ishigami(16);
    s.method = Method::Morris { levels: 3 };
    assert!(s.check().unwrap_err().to_string().contains("--levels 3"));
    for bad in ["a=2:1", "a=1:1", "a=1:2:3", "a=x,y"] {
        let e = Range::parse(bad).unwrap_err().to_string();
        assert!(e.starts_with(&format!("--vary {bad}")), "{e}");
    }
    let mut s = ishigami(16);
    s.ranges.pop();
    assert!(s.check().is_err());
}

/// A short, coarse Morris study of the refined test case, two members a
/// point: its runs made one by one, in reverse order, by [`Model::run`]
/// and handed to `analyse` (as an executor of another process would),
/// give `run`'s files, but for the wall times.
#[test]
fn runs_made_one_by_one_and_analysed_are_the_study() {
    let set = ["run.travel=10", "run.increment=1"].map(|s| s.parse().unwrap());
    let text = include_str!("../../io/testdata/refined.toml").to_string();
    let s = Sensitivity {
        model: Model::Case(soilcut_study::BaseCase::new(text, set.to_vec()).unwrap()),
        ranges: vec![
            Range::new("soil.friction.peak", 33.0, 40.0).unwrap(),
            Range::new("blade.wall_friction", 5.0, 15.0).unwrap(),
        ],
        method: Method::Morris { levels: 4 },
        samples: 2,
        members: 2,
        dummy: true,
        seed: 3,
        jobs: 2,
    };
    let whole = run(&s);
    let plan = s.plan().unwrap();
    assert_eq!(plan.runs.len(), s.runs());
    let mut rows: Vec<_> = plan.runs.iter().rev().map(|r| s.model.run(r)).collect();
    rows.reverse();
    let parts = s.analyse(plan.clone(), rows.clone()).unwrap();
    let without_timing = |r: &SensitivityResult| {
        let mut files = r.files();
        files.retain(|(name, _)| *name != "timing.csv");
        files
    };
    assert!(whole.analysis.is_ok());
    assert_eq!(without_timing(&parts), without_timing(&whole));
    rows.swap(0, 1);
    let e = s.analyse(plan, rows).unwrap_err().to_string();
    assert!(e.contains("row 1"), "{e}");
}
