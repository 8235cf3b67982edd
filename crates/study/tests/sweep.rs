//! Sweeps on a short, coarse case (Table 1 HS over 0.5 d at d/20).

use soilcut_study::sample::{Sample, Vary};
use soilcut_study::sweep::Sweep;
use soilcut_study::{no_progress, BaseCase};
use std::sync::atomic::{AtomicUsize, Ordering};

const REFINED: &str = include_str!("../../io/testdata/refined.toml");

fn sweep(varies: &[&str], sample: Sample, jobs: usize) -> Sweep {
    let set = ["run.travel=10", "run.increment=1"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    Sweep {
        base: BaseCase::new(REFINED.to_string(), set).unwrap(),
        varies: varies.iter().map(|v| v.parse::<Vary>().unwrap()).collect(),
        sample,
        jobs,
        keep_runs: None,
    }
}

#[test]
fn grid_runs_every_combination_in_order() {
    let s = sweep(
        &["soil.friction.peak=33:37:3", "soil.d50=0.3,0.6"],
        Sample::Grid,
        2,
    );
    let calls = AtomicUsize::new(0);
    let result = s
        .run(&|done, total| {
            assert_eq!(total, 6);
            assert!(done <= total);
            calls.fetch_add(1, Ordering::Relaxed);
        })
        .unwrap();
    assert_eq!(
        calls.load(Ordering::Relaxed),
        7,
        "0 and after each of 6 runs"
    );
    assert_eq!(result.rows.len(), 3 * 2);
    assert_eq!(result.failed(), 0);
    let csv = result.csv();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "run,soil.friction.peak,soil.d50,status,error,initial_force_norm,max_force_norm,u_over_d_at_max,final_force_norm,peaks,mean_force_norm_last_half,mass_drift_rel,band_jumps,steps"
    );
    assert!(lines[1].starts_with("1,33,0.3,ok,,"), "{}", lines[1]);
    assert!(lines[2].starts_with("2,33,0.6,ok,,"), "{}", lines[2]);
    assert!(lines[6].starts_with("6,37,0.6,ok,,"), "{}", lines[6]);
    for row in &result.rows {
        let f = row.outcome.as_ref().unwrap();
        assert_eq!(f.steps, 10);
        assert!(f.max_force_norm >= f.initial_force_norm);
    }
    assert_eq!(result.timing_csv().lines().count(), 7);
}

#[test]
fn a_failed_combination_is_a_row_with_its_error() {
    let s = sweep(&["soil.friction.initial=20,40"], Sample::Grid, 2);
    let result = s.run(&no_progress).unwrap();
    assert_eq!(result.failed(), 1);
    assert!(result.rows[0].outcome.is_ok());
    let e = result.rows[1].outcome.as_ref().unwrap_err();
    assert!(e.starts_with("soil.friction.initial: must be <="), "{e}");
    let csv = result.csv();
    let line = csv.lines().nth(2).unwrap();
    assert!(
        line.starts_with("2,40,failed,soil.friction.initial: must be <="),
        "{line}"
    );
    assert!(line.ends_with(",,,,,,,,,"), "empty figures: {line}");
}

#[test]
fn same_files_on_any_number_of_threads() {
    let varies = [
        "soil.friction.peak=31:40",
        "soil.peak_shear=1:3",
        "choices.band_shear=full,by-position",
    ];
    let sample = Sample::Lhs { runs: 8, seed: 5 };
    let one = sweep(&varies, sample, 1).run(&no_progress).unwrap();
    let two = sweep(&varies, sample, 2).run(&no_progress).unwrap();
    assert_eq!(one.csv(), two.csv());
    assert_eq!(one.failed(), 0);
    let other = sweep(&varies, Sample::Lhs { runs: 8, seed: 6 }, 2)
        .run(&no_progress)
        .unwrap();
    assert_ne!(one.csv(), other.csv(), "the seed matters");
}

#[test]
fn kept_runs_and_plots_are_written() {
    let tmp = tempfile::tempdir().unwrap();
    let mut s = sweep(
        &["soil.friction.initial=20,40", "soil.d50=0.3,0.6"],
        Sample::Grid,
        2,
    );
    s.keep_runs = Some(tmp.path().join("runs"));
    let result = s.run(&no_progress).unwrap();
    let mut kept: Vec<String> = std::fs::read_dir(tmp.path().join("runs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    kept.sort();
    assert_eq!(
        kept,
        ["run-0001", "run-0002"],
        "failed runs leave no folder"
    );
    let history = std::fs::read_to_string(tmp.path().join("runs/run-0002/history.csv")).unwrap();
    assert_eq!(history.lines().count(), 11);
    let resolved =
        std::fs::read_to_string(tmp.path().join("runs/run-0002/case.resolved.toml")).unwrap();
    assert!(resolved.contains("d50 = 0.6"), "{resolved}");
    let written = result.draw(tmp.path()).unwrap();
    assert_eq!(written.len(), 2, "one picture per numeric key");
    assert!(written[0].ends_with("sweep-soil.friction.initial.png"));
}
