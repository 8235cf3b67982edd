//! Latency of one `step()` on a developed pile, as a controller calling
//! soilcut once per control tick would see it: each paper case at its
//! defaults is run to u = 3 d, then the next 500 steps are timed one by
//! one; prints the median, the 99th percentile and the largest, in µs.
//!
//! ```sh
//! cargo run --release -p soilcut-bench --example step_latency
//! ```

use soilcut_bench::{developed, shipped_case};
use std::time::Instant;

const CASES: [&str; 5] = ["original", "table1-s", "table1-hs", "fig5", "fig8b"];
const STEPS: usize = 500;

fn main() {
    println!("| case | d/v0 | ground | median µs | 99th percentile µs | largest µs |");
    println!("|---|---|---|---|---|---|");
    for name in CASES {
        let mut case = shipped_case(&format!("paper/{name}.toml"), &[]);
        // Travel enough for 3 d and the timed steps at any default
        // increment (Fig. 8b's 5 d at d/250 ends 250 steps after 3 d).
        case.run.travel = 10.0 * case.blade.depth;
        let d = case.blade.depth;
        let ground = match case.run.vertices() {
            Some(v) => format!("vertices d/{:.0}", d / v.spacing),
            None => format!("nodes d/{:.0}", d / case.run.increment),
        };
        let mut sim = developed(&case, 3.0);
        let mut micros: Vec<f64> = (0..STEPS)
            .map(|_| {
                let start = Instant::now();
                sim.step().expect("a shipped case runs");
                start.elapsed().as_secs_f64() * 1e6
            })
            .collect();
        micros.sort_by(f64::total_cmp);
        let at = |q: f64| micros[((STEPS - 1) as f64 * q).round() as usize];
        println!(
            "| {name} | {:.0} | {ground} | {:.1} | {:.1} | {:.1} |",
            d / case.run.increment,
            at(0.5),
            at(0.99),
            at(1.0)
        );
    }
}
