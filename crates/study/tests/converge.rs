//! Convergence studies on a short, coarse case.

use soilcut_study::converge::{Converge, ConvergeResult, Refine, QUANTITIES};
use soilcut_study::{no_progress, BaseCase};

const REFINED: &str = include_str!("../../io/testdata/refined.toml");

fn converge(jobs: usize) -> Converge {
    let set = ["run.travel=40", "run.increment=1"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    Converge {
        base: BaseCase::new(REFINED.to_string(), set).unwrap(),
        levels: 3,
        refine: Refine::Both,
        tolerance: 0.02,
        jobs,
    }
}

#[test]
fn one_row_per_level_with_halved_increments() {
    let result = converge(2).run(&no_progress).unwrap();
    let csv = result.csv();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 3);
    assert!(lines[0].starts_with("level,increment,spacing,steps,band_jumps,mean_force_norm,"));
    assert!(
        lines[0].ends_with(",window_max_0_1,window_max_1_2"),
        "{}",
        lines[0]
    );
    let increments: Vec<f64> = result.levels.iter().map(|l| l.increment).collect();
    assert_eq!(increments, [1.0, 0.5, 0.25]);
    // The case's own ground, the vertex ground at its default h = d/50,
    // halved with the increment.
    let spacings: Vec<f64> = result.levels.iter().map(|l| l.spacing).collect();
    assert_eq!(spacings, [0.4, 0.2, 0.1]);
    let steps: Vec<usize> = result.levels.iter().map(|l| l.steps).collect();
    assert_eq!(steps, [40, 80, 160]);
    for l in &result.levels {
        assert_eq!(l.window_mean.len(), 2, "travel 2 d: two windows");
        for (mean, max) in l.window_mean.iter().zip(&l.window_max) {
            assert!(mean <= max);
        }
        assert!(l.pile_height_d > 0.0);
    }
    assert_eq!(
        result.levels[2].profile_rms_d, 0.0,
        "the finest against itself"
    );
    assert!(result.levels[0].profile_rms_d > 0.0);
    let changes = result.changes();
    assert_eq!(changes.len(), 2);
    assert_eq!(changes[0].len(), QUANTITIES.len() + 2);
    let md = result.markdown();
    assert!(md.contains("## Verdict"), "{md}");
    assert_eq!(
        md.matches(": converged").count()
            + md.matches(": not converged").count()
            + md.matches(": undetermined").count(),
        QUANTITIES.len() + 2
    );
    // Counts are whole numbers in the per-level table: its last column.
    for l in &result.levels {
        let row = format!("| {} | {} |", l.level, l.increment);
        let line = md.lines().find(|x| x.starts_with(&row)).unwrap();
        let peaks = line.trim_end_matches(" |").rsplit("| ").next().unwrap();
        assert_eq!(peaks, l.peaks.to_string(), "{line}");
    }
    let tmp = tempfile::tempdir().unwrap();
    result.draw(&tmp.path().join("converge.png")).unwrap();
}

#[test]
fn same_table_on_any_number_of_threads() {
    let one = converge(1).run(&no_progress).unwrap();
    let two = converge(2).run(&no_progress).unwrap();
    assert_eq!(one.csv(), two.csv());
    assert_eq!(one.markdown(), two.markdown());
}

/// The study of `set` on the test case, refining `refine`.
fn study_of(set: &[&str], refine: Refine) -> Converge {
    let mut study = converge(2);
    study.base = BaseCase::new(
        REFINED.to_string(),
        set.iter().map(|s| s.parse().unwrap()).collect(),
    )
    .unwrap();
    study.refine = refine;
    study
}

#[test]
fn the_increment_or_the_vertex_spacing_alone() {
    let set = [
        "run.travel=40",
        "run.increment=0.25",
        "run.vertex_spacing=1",
    ];
    let grid = |r: &ConvergeResult| -> Vec<(f64, f64)> {
        r.levels.iter().map(|l| (l.increment, l.spacing)).collect()
    };
    let r = study_of(&set, Refine::VertexSpacing)
        .run(&no_progress)
        .unwrap();
    assert_eq!(grid(&r), [(0.25, 1.0), (0.25, 0.5), (0.25, 0.25)]);
    assert!(r
        .markdown()
        .contains("vertex spacing h/2^k at the case's increment v0 on the vertex ground"));
    let r = study_of(&set, Refine::Increment).run(&no_progress).unwrap();
    assert_eq!(grid(&r), [(0.25, 1.0), (0.125, 1.0), (0.0625, 1.0)]);
}

#[test]
fn the_node_grid_converges_its_increment_only() {
    let set = ["run.travel=40", "run.increment=1", "run.ground=\"nodes\""];
    let r = study_of(&set, Refine::Both).run(&no_progress).unwrap();
    let spacings: Vec<f64> = r.levels.iter().map(|l| l.spacing).collect();
    assert_eq!(spacings, [1.0, 0.5, 0.25], "nodes every increment");
    assert!(r.markdown().contains("on the node grid"));
    let e = study_of(&set, Refine::VertexSpacing)
        .run(&no_progress)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--refine vertex-spacing"), "{e}");
}

/// Level 0 is the case's own run on its own ground, bit for bit: before
/// issue 49 it set run.node_spacing and so ran the node grid.
#[test]
fn level_0_is_the_run_of_the_case_itself() {
    for set in [
        &["run.travel=40"][..],
        &["run.travel=40", "run.ground=\"nodes\"", "run.increment=1"],
    ] {
        let study = study_of(set, Refine::Both);
        let own = study.base.run(&[]).unwrap();
        let level = &study.run(&no_progress).unwrap().levels[0];
        let force: Vec<(f64, f64)> = own
            .history
            .iter()
            .map(|r| (r.u / 20.0, r.force_norm))
            .collect();
        assert_eq!(level.force, force, "{set:?}");
        assert_eq!(level.max_force_norm, own.summary.max_force_norm);
    }
}
