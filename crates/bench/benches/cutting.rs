//! `cargo bench -p soilcut-bench`: whole runs of the shipped cases and one
//! increment on a developed pile. Each reports time and, as the item
//! counter, candidate evaluations (so divan prints evaluations per second).

use divan::counter::ItemsCount;
use divan::Bencher;
use soilcut_bench::{developed, run, shipped_case};
use soilcut_model::Simulation;

fn main() {
    divan::main();
}

/// Whole run of `cases/paper/fig5.toml` on the node grid (nodes every
/// increment, the exhaustive search) at increments d/200 to d/2000
/// (`docs/performance.md`: run time against the increment).
#[divan::bench(args = [200, 250, 500, 1000, 2000], sample_count = 3, sample_size = 1)]
fn fig5_run(bencher: Bencher, per_depth: u32) {
    let increment = format!("run.increment={}", 20.0 / per_depth as f64);
    let case = shipped_case("paper/fig5.toml", &[&increment, "run.ground=\"nodes\""]);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// Whole run of fig5 on the vertex ground (`run.vertex_spacing` = d/50,
/// issue 28) at increments d/250 to d/2000, beside `fig5_run`'s node grid
/// in the same bench run: the cost per halving of the increment.
#[divan::bench(args = [250, 500, 1000, 2000], sample_count = 3, sample_size = 1)]
fn fig5_run_vertices(bencher: Bencher, per_depth: u32) {
    let increment = format!("run.increment={}", 20.0 / per_depth as f64);
    let case = shipped_case("paper/fig5.toml", &[&increment, "run.vertex_spacing=0.4"]);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// Whole run of each paper case whose default ground is the vertex ground
/// on the node grid instead, at the node grid's default increment (d/1250
/// where the soil softens, d/500 where it never does), beside
/// `paper_case_at_defaults`.
#[divan::bench(
    args = ["original", "table1-s", "fig8b", "table1-hs", "fig5"],
    sample_count = 3,
    sample_size = 1
)]
fn paper_case_on_nodes(bencher: Bencher, name: &str) {
    let case = shipped_case(&format!("paper/{name}.toml"), &["run.ground=\"nodes\""]);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// Whole run of each paper case at its defaults (the targets of issue 19:
/// `docs/performance.md`, "Time to accuracy in the ensemble sense").
#[divan::bench(
    args = ["original", "table1-s", "fig8b", "table1-hs", "fig5"],
    sample_count = 3,
    sample_size = 1
)]
fn paper_case_at_defaults(bencher: Bencher, name: &str) {
    let case = shipped_case(&format!("paper/{name}.toml"), &[]);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// Whole run of the original model's case at d/500 (its increment until
/// the defaults of issue 11), for comparison with earlier figures.
#[divan::bench(sample_count = 5, sample_size = 1)]
fn original_run(bencher: Bencher) {
    let case = shipped_case("paper/original.toml", &["run.increment=0.04"]);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// One `step()` of fig5 at d/1000 on the vertex ground (vertices d/50
/// apart) on the pile developed after 3 d of travel: the control tick.
#[divan::bench(sample_count = 20, sample_size = 20)]
fn fig5_step_on_vertices(bencher: Bencher) {
    let case = shipped_case(
        "paper/fig5.toml",
        &["run.increment=0.02", "run.vertex_spacing=0.4"],
    );
    let developed = developed(&case, 3.0);
    bencher
        .with_inputs(|| developed.clone())
        .bench_local_values(|mut sim| {
            sim.step().unwrap();
            sim
        });
}

/// One `step()` of fig5 at d/1000 on the node grid, on the pile developed
/// after 3 d of travel.
#[divan::bench(sample_count = 20, sample_size = 20)]
fn fig5_step_on_developed_pile(bencher: Bencher) {
    let case = shipped_case(
        "paper/fig5.toml",
        &["run.increment=0.02", "run.ground=\"nodes\""],
    );
    let developed = developed(&case, 3.0);
    let mut probe = Simulation::clone(&developed);
    let before = probe.evaluations();
    probe.step().unwrap();
    let evaluations = probe.evaluations() - before;
    bencher
        .counter(ItemsCount::new(evaluations))
        .with_inputs(|| developed.clone())
        .bench_local_values(|mut sim| {
            sim.step().unwrap();
            sim
        });
}

/// A planner's branch of fig5 at d/1000 on the pile developed after 3 d of
/// travel on the node grid (`docs/performance.md`, "Snapshots"): copying
/// the state, writing it as bytes and restoring it; the counter is the
/// snapshot's bytes.
mod snapshot {
    use super::*;
    use divan::counter::BytesCount;
    use std::sync::LazyLock;

    static DEVELOPED: LazyLock<Simulation> = LazyLock::new(|| {
        let case = shipped_case(
            "paper/fig5.toml",
            &["run.increment=0.02", "run.ground=\"nodes\""],
        );
        developed(&case, 3.0)
    });

    fn bytes() -> BytesCount {
        BytesCount::new(DEVELOPED.snapshot().len())
    }

    #[divan::bench(sample_count = 50, sample_size = 10)]
    fn clone(bencher: Bencher) {
        bencher
            .counter(bytes())
            .bench(|| divan::black_box(&*DEVELOPED).clone());
    }

    #[divan::bench(sample_count = 50, sample_size = 10)]
    fn snapshot(bencher: Bencher) {
        bencher
            .counter(bytes())
            .bench(|| divan::black_box(&*DEVELOPED).snapshot());
    }

    #[divan::bench(sample_count = 50, sample_size = 10)]
    fn from_snapshot(bencher: Bencher) {
        let data = DEVELOPED.snapshot();
        bencher
            .counter(bytes())
            .bench(|| Simulation::from_snapshot(divan::black_box(&data)).unwrap());
    }
}

/// Whole run of the finite-width tools (`cases/tools/tine.toml`,
/// `dozer.toml`) with their width and, for the cost of the crescents and the
/// spill, the same case in plane strain (`blade.width` removed).
#[divan::bench(
    args = ["tine", "tine-plane-strain", "dozer", "dozer-plane-strain"],
    sample_count = 3,
    sample_size = 1
)]
fn finite_width_tool(bencher: Bencher, name: &str) {
    let (tool, plane) = match name.strip_suffix("-plane-strain") {
        Some(tool) => (tool, true),
        None => (name, false),
    };
    let mut case = shipped_case(&format!("tools/{tool}.toml"), &[]);
    if plane {
        case.blade.width = None;
    }
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// Whole run of Fig. 5's soil at its defaults with one key changed (issue
/// 38: every cut on the vertex ground), beside the plain case in the same
/// bench run: raked at 60°, a depth path 20 → 24 → 20 mm, in a bin 8 d
/// long, 40 mm wide, and, for the ratio to before, the raked and the wide
/// case on the node grid.
#[divan::bench(
    args = ["plain", "rake60", "depth-path", "bin", "width40", "width40-nodes", "rake60-nodes"],
    sample_count = 3,
    sample_size = 1
)]
fn fig5_configuration(bencher: Bencher, name: &str) {
    let overrides: &[&str] = match name {
        "plain" => &[],
        "rake60" => &["blade.rake=60"],
        "depth-path" => &["blade.depth_path=[[0, 20], [40, 24], [80, 20]]"],
        "bin" => &["bin.length=160"],
        "width40" => &["blade.width=40"],
        "width40-nodes" => &["blade.width=40", "run.ground=\"nodes\""],
        _ => &["blade.rake=60", "run.ground=\"nodes\""],
    };
    let case = shipped_case("paper/fig5.toml", overrides);
    let evaluations = run(&case);
    bencher
        .counter(ItemsCount::new(evaluations))
        .bench(|| run(divan::black_box(&case)));
}

/// A steered control tick of fig5 at its defaults on the pile developed
/// after 3 d of travel, with `points` points of depth path behind the blade
/// (a steered session's history, a point a tick: 100 000 are a 1 kHz
/// controller's 100 s): a tick costs what it changes, not the path's
/// length (issue 39).
#[divan::bench(args = [2, 100_000], sample_count = 20, sample_size = 20)]
fn fig5_steered_tick_after_path(bencher: Bencher, points: usize) {
    steered_ticks(bencher, points, 5.0);
}

/// The same with the case's travel ending at 3 d, so that every tick runs
/// past it: a tick checks what a longer travel can break, not the path.
#[divan::bench(args = [2, 100_000], sample_count = 20, sample_size = 20)]
fn fig5_steered_tick_past_travel_after_path(bencher: Bencher, points: usize) {
    steered_ticks(bencher, points, 3.0);
}

/// Ticks of one steered session of fig5 after 3 d, `points` points of path
/// behind the blade, the case's travel `travel` d.
fn steered_ticks(bencher: Bencher, points: usize, travel: f64) {
    let mut case = shipped_case("paper/fig5.toml", &[]);
    let (d, behind) = (case.blade.depth, 3.0 * case.blade.depth);
    case.run.travel = travel * d;
    case.blade.depth_path = (0..points)
        .map(|i| [behind * i as f64 / points as f64, d])
        .collect();
    // One session, tick after tick (a copy per tick would make each
    // tick's new point reallocate the copied path).
    let mut sim = developed(&case, 3.0);
    bencher.bench_local(|| {
        let x = sim.blade_position() + sim.case().run.increment;
        sim.advance_to(x, Some(sim.tip_depth() * 0.9995)).unwrap();
    });
}

/// A control tick of fig5 at its defaults on the pile developed after 3 d
/// of travel, steered and not: `advance_to` the next increment (d/350),
/// the tip going 0.1 % shallower over it (steered: a depth path made and
/// validated each tick, on the vertex ground since issue 38) or staying.
#[divan::bench(args = ["unsteered", "steered"], sample_count = 20, sample_size = 20)]
fn fig5_control_tick(bencher: Bencher, name: &str) {
    let case = shipped_case("paper/fig5.toml", &[]);
    let developed = developed(&case, 3.0);
    let steered = name == "steered";
    bencher
        .with_inputs(|| developed.clone())
        .bench_local_values(|mut sim| {
            let x = sim.blade_position() + sim.case().run.increment;
            let depth = steered.then(|| sim.tip_depth() * 0.999);
            sim.advance_to(x, depth).unwrap();
            sim
        });
}
