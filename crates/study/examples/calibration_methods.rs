//! The measured comparison of the global searches of `soilcut fit`,
//! differential evolution (`de`) and CMA-ES (`cmaes`), on the synthetic
//! recovery problems of the test suite (`crates/study/tests/synthetic`):
//! for each seeded truth (3 to 5 free keys of the refined case, 2 % noise, a start
//! anywhere in the bounds) and each search seed, the search alone (no
//! polish, no profiles) with each method's default population, and CMA-ES
//! with the population of differential evolution, at each budget of runs.
//!
//! A search with a smaller budget is the first runs of the one with the
//! largest (both methods stop at the last whole generation that fits, and
//! draw their random numbers in the same order whatever the budget; this
//! is checked on the first truth and seed), so each search is run once,
//! with the largest budget, and cut at each smaller one.
//!
//! For each (truth, method, seed, budget): the best RMS found against the
//! truth's own RMS on the same noisy curve; success when every key is
//! within 1° (angles) or 10 % of the truth; the runs until the best RMS so
//! far is within 1 % of the least RMS any search found for that truth.
//! Writes `runs.csv` (one row each) and `summary.md` (the table) into OUT.
//!
//! Usage: calibration_methods OUT TRUTHS SEEDS BUDGETS JOBS [KEY=VALUE ...]
//! with comma-separated lists, e.g.
//! `calibration_methods out 1,2,3,4 1,2,3 300,1000 2 run.travel=20 run.increment=0.2`.

#[path = "../tests/synthetic/mod.rs"]
mod synthetic;

use rayon::ThreadPool;
use soilcut_io::CsvText;
use soilcut_study::field;
use soilcut_study::fit::problem::{Point, Problem};
use soilcut_study::fit::search::{best_of, Search};
use soilcut_study::fit::Method;
use std::fmt::Write as _;
use std::time::Instant;
use synthetic::{recovered, Case};

/// The searches compared: each method at its default population, and
/// CMA-ES with the population of differential evolution (`--method cmaes
/// --population N`), which explores more before it first converges.
/// (name, method, with the population of differential evolution)
const METHODS: [(&str, Method, bool); 3] = [
    ("de", Method::DifferentialEvolution, false),
    ("cmaes", Method::CmaEs, false),
    ("cmaes-large", Method::CmaEs, true),
];

/// One search cut at one budget.
struct Row {
    truth: u64,
    keys: usize,
    method: &'static str,
    seed: u64,
    budget: usize,
    runs: usize,
    best_rms: f64,
    truth_rms: f64,
    success: bool,
    to_one_percent: Option<usize>,
    /// Wall time of the whole search (the largest budget).
    wall_s: f64,
    best: Vec<f64>,
    free: String,
    truth_values: Vec<f64>,
}

fn list<T: std::str::FromStr>(text: &str) -> Vec<T> {
    text.split(',')
        .map(|s| s.parse().ok().expect("a comma-separated list of numbers"))
        .collect()
}

/// The runs of a search with a budget: its whole generations that fit
/// (the first generation whatever the budget, as the searches do).
fn cut(search: &Search, budget: usize) -> usize {
    search
        .generations
        .iter()
        .map(|g| g.evaluations)
        .filter(|&n| n <= budget)
        .max()
        .unwrap_or(search.generations[0].evaluations)
}

/// Runs until the best RMS so far is within 1 % of `reference`.
fn to_one_percent(points: &[Point], reference: f64) -> Option<usize> {
    let mut best = f64::INFINITY;
    points
        .iter()
        .position(|p| {
            best = best.min(p.rms);
            best <= 1.01 * reference
        })
        .map(|i| i + 1)
}

fn search(
    pool: &ThreadPool,
    c: &Case,
    problem: &Problem,
    (method, de_sized): (Method, bool),
    seed: u64,
    budget: usize,
) -> (Search, f64) {
    let mut fit = c.fit.clone();
    if de_sized {
        // The case's fit is by differential evolution: its population.
        fit.population = c.fit.population(c.keys.len());
    }
    fit.method = method;
    fit.seed = seed;
    fit.evaluations = budget;
    let start = Instant::now();
    let s = pool.install(|| fit.search(problem, &|_| {}));
    (s, start.elapsed().as_secs_f64())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    assert!(
        args.len() >= 5,
        "usage: calibration_methods OUT TRUTHS SEEDS BUDGETS JOBS [KEY=VALUE ...]"
    );
    let out = std::path::PathBuf::from(&args[0]);
    let (truths, seeds): (Vec<u64>, Vec<u64>) = (list(&args[1]), list(&args[2]));
    let budgets: Vec<usize> = list(&args[3]);
    let jobs: usize = args[4].parse().expect("JOBS: a number");
    let resolution: Vec<&str> = args[5..].iter().map(String::as_str).collect();
    let largest = *budgets.iter().max().expect("a budget");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .expect("threads");
    let mut rows = Vec::new();
    for &t in &truths {
        let c = synthetic::case(t, jobs, largest, &resolution);
        let params = c.fit.params().expect("the synthetic keys");
        let problem = Problem::new(&c.fit.tests, c.fit.compare, &params);
        let truth_rms = problem.evaluate(&c.truth).rms;
        let mut searches = Vec::new();
        for (name, method, de_sized) in METHODS {
            for &seed in &seeds {
                let (s, wall) = search(&pool, &c, &problem, (method, de_sized), seed, largest);
                if t == truths[0] && seed == seeds[0] {
                    let least = *budgets.iter().min().expect("a budget");
                    let (short, _) = search(&pool, &c, &problem, (method, de_sized), seed, least);
                    assert_eq!(short.points, s.points[..cut(&s, least)], "{name}: a prefix");
                }
                eprintln!(
                    "truth {t} {name} seed {seed}: RMS {} (truth {truth_rms}), {wall:.1} s",
                    s.best.rms
                );
                searches.push((name, seed, s, wall));
            }
        }
        let reference = searches
            .iter()
            .map(|s| s.2.best.rms)
            .fold(f64::INFINITY, f64::min);
        for (name, seed, s, wall) in &searches {
            for &budget in &budgets {
                let runs = cut(s, budget);
                let points = &s.points[..runs];
                let best = best_of(points);
                let success = c
                    .keys
                    .iter()
                    .zip(&c.truth)
                    .zip(&best.x)
                    .all(|((k, &truth), &x)| recovered(k.0, x, truth));
                rows.push(Row {
                    truth: t,
                    keys: c.keys.len(),
                    method: name,
                    seed: *seed,
                    budget,
                    runs,
                    best_rms: best.rms,
                    truth_rms,
                    success,
                    to_one_percent: to_one_percent(points, reference),
                    wall_s: *wall,
                    best: best.x.clone(),
                    free: c.keys.iter().map(|k| k.0).collect::<Vec<_>>().join(" "),
                    truth_values: c.truth.clone(),
                });
            }
        }
    }
    std::fs::create_dir_all(&out).expect("the output folder");
    std::fs::write(out.join("runs.csv"), runs_csv(&rows)).expect("runs.csv");
    let summary = summary(&rows, &budgets);
    std::fs::write(out.join("summary.md"), &summary).expect("summary.md");
    print!("{summary}");
}

fn runs_csv(rows: &[Row]) -> String {
    let mut s = CsvText::named(&[
        "truth",
        "keys",
        "method",
        "seed",
        "budget",
        "runs",
        "best_rms",
        "truth_rms",
        "ratio",
        "success",
        "runs_to_1pct",
        "search_wall_s",
        "free",
        "truth_values",
        "best",
    ]);
    for r in rows {
        let four = |v: &[f64]| {
            let v: Vec<String> = v.iter().map(|x| format!("{x:.4}")).collect();
            v.join(" ")
        };
        s.fields(&[
            r.truth.to_string(),
            r.keys.to_string(),
            r.method.to_string(),
            r.seed.to_string(),
            r.budget.to_string(),
            r.runs.to_string(),
            field::number(r.best_rms),
            field::number(r.truth_rms),
            field::number(r.best_rms / r.truth_rms),
            r.success.to_string(),
            r.to_one_percent.map_or(String::new(), |n| n.to_string()),
            format!("{:.2}", r.wall_s),
            r.free.clone(),
            four(&r.truth_values),
            four(&r.best),
        ]);
    }
    s.finish()
}

/// A count of runs, "–" for none.
fn runs_text(x: f64) -> String {
    if x.is_nan() {
        "–".to_string()
    } else {
        format!("{x:.0}")
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    0.5 * (v[(n - 1) / 2] + v[n / 2])
}

/// The table: per method and budget, over every truth and seed.
fn summary(rows: &[Row], budgets: &[usize]) -> String {
    let largest = budgets.iter().copied().max().unwrap_or(0);
    let mut s = String::from(
        "| method | budget | searches | success | best RMS / truth's RMS: median | worst | within 1 % of the least RMS found | runs to get there: median | worst | wall time of the searches (s) |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for &budget in budgets {
        for (name, ..) in METHODS {
            let these: Vec<&Row> = rows
                .iter()
                .filter(|r| r.method == name && r.budget == budget)
                .collect();
            let ratio: Vec<f64> = these.iter().map(|r| r.best_rms / r.truth_rms).collect();
            let wall = if budget == largest {
                format!("{:.0}", these.iter().map(|r| r.wall_s).sum::<f64>())
            } else {
                "–".to_string()
            };
            let reached: Vec<f64> = these
                .iter()
                .filter_map(|r| r.to_one_percent)
                .map(|n| n as f64)
                .collect();
            let _ = writeln!(
                s,
                "| {name} | {budget} | {} | {} | {:.3} | {:.3} | {} | {} | {} | {} |",
                these.len(),
                these.iter().filter(|r| r.success).count(),
                median(ratio.clone()),
                ratio.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                reached.len(),
                runs_text(median(reached.clone())),
                runs_text(reached.iter().copied().fold(f64::NAN, f64::max)),
                wall,
            );
        }
    }
    s
}
