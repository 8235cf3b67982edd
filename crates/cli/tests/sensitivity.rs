//! `soilcut sensitivity` on a shipped case, short and coarse.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn fig5() -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    root.join("cases/paper/fig5.toml").display().to_string()
}

fn soilcut(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .output()
        .unwrap()
}

/// Fig. 5 over u/d = 1 at d/50 (vertices d/25 apart): about 50 increments a run.
const COARSE: [&str; 6] = [
    "--set",
    "run.travel=20",
    "--set",
    "run.increment=0.4",
    "--set",
    "run.vertex_spacing=0.8",
];

/// Runs `args` on the coarse case, which must succeed.
fn coarse(mut args: Vec<&str>) {
    args.extend(COARSE);
    let done = soilcut(&args);
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(done.status.success(), "{stderr}");
}

/// Sobol indices of three keys and the dummy, N = 16 (96 runs); the
/// folder `out` written.
fn sobol(out: &Path, jobs: &str, seed: &str) -> PathBuf {
    let case = fig5();
    let o = out.display().to_string();
    let args = vec![
        "sensitivity",
        &case,
        "--method",
        "sobol",
        "--samples",
        "16",
        "--dummy",
        "--members",
        "1",
        "-q",
        "--vary",
        "soil.friction.peak=35:45",
        "--vary",
        "soil.peak_shear=1:3",
        "--vary",
        "blade.wall_friction=5:15",
        "--jobs",
        jobs,
        "--seed",
        seed,
        "--out",
        &o,
    ];
    coarse(args);
    out.to_path_buf()
}

/// A Morris study of the coarse case with `extra` arguments, into `out`.
fn morris(out: &Path, extra: &[&str]) {
    let (case, o) = (fig5(), out.display().to_string());
    let mut args = vec![
        "sensitivity",
        &case,
        "--method",
        "morris",
        "-q",
        "--out",
        &o,
    ];
    args.extend(extra);
    coarse(args);
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

#[test]
fn indices_do_not_depend_on_threads_and_the_dummy_s_are_zero() {
    let tmp = tempfile::tempdir().unwrap();
    let one = sobol(&tmp.path().join("j1"), "1", "3");
    let two = sobol(&tmp.path().join("j2"), "2", "3");
    let other = sobol(&tmp.path().join("s4"), "2", "4");
    for name in [
        "indices.csv",
        "samples.csv",
        "tornado.csv",
        "summary.json",
        "sensitivity.md",
        "indices.png",
        "tornado.png",
    ] {
        let bytes = |dir: &Path| std::fs::read(dir.join(name)).unwrap();
        assert_eq!(bytes(&one), bytes(&two), "{name}");
    }
    assert!(!one.join("morris.png").exists(), "μ*-σ is Morris's");
    assert_ne!(read(&one, "indices.csv"), read(&other, "indices.csv"));
    let indices = read(&one, "indices.csv");
    let rows: Vec<Vec<&str>> = indices
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(
        rows.len(),
        8 * 4,
        "seven outputs and one window, four inputs"
    );
    // A band spacing some run lacks (fewer than two peaks in u/d = 1) has
    // no indices: its fields are empty.
    for row in rows.iter().filter(|r| r[2].is_empty()) {
        assert_eq!(row[0], "band_spacing", "{row:?}");
    }
    for row in rows.iter().filter(|r| !r[2].is_empty()) {
        let v: Vec<f64> = row[2..].iter().map(|x| x.parse().unwrap()).collect();
        assert!(v[5] >= v[1], "{row:?}: ST above S1 within the intervals");
        if row[1] == "dummy" {
            assert!(
                v[1] <= 0.0 && 0.0 <= v[2] && v[4] <= 0.0 && 0.0 <= v[5],
                "{row:?}"
            );
        }
    }
    let samples = read(&one, "samples.csv");
    assert_eq!(samples.lines().count(), 1 + 16 * 5 + 16);
    // The tornado: the case and three keys at two ends, the dummy not.
    let tornado = read(&one, "tornado.csv");
    assert_eq!(tornado.lines().count(), 1 + 7);
    assert_eq!(read(&one, "timing.csv").lines().count(), 1 + 96 + 7);
    assert!(read(&one, "summary.json").contains("\"complete\": true"));
}

#[test]
fn members_give_each_output_a_chaos_share() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("m");
    morris(
        &out,
        &[
            "--samples",
            "3",
            "--members",
            "3",
            "--vary",
            "soil.friction.peak=35:45",
            "--vary",
            "blade.wall_friction=5:15",
        ],
    );
    let summary: serde_json::Value = serde_json::from_str(&read(&out, "summary.json")).unwrap();
    assert_eq!(summary["runs"], 3 * 3 * 3);
    assert_eq!(summary["tornado_runs"], (2 * 2 + 1) * 3);
    for picture in ["indices.png", "morris.png", "tornado.png"] {
        assert!(out.join(picture).exists(), "{picture}");
    }
    for o in summary["outputs"].as_array().unwrap() {
        if o["undefined_runs"] == 0 {
            let share = o["chaos_share"].as_f64().unwrap();
            assert!((0.0..1.0).contains(&share), "{o}");
        }
    }
    let samples = read(&out, "samples.csv");
    let ks: Vec<&str> = samples
        .lines()
        .skip(1)
        .take(3)
        .map(|l| l.split(',').nth(2).unwrap())
        .collect();
    assert_eq!(ks, ["-1", "0", "1"]);
    assert!(read(&out, "indices.csv")
        .starts_with("output,key,mu_star,mu_star_low,mu_star_high,sigma,mu\n"));
    // The band spacing of a run with fewer than two force peaks is empty;
    // the summary counts those runs and the output has no indices.
    let spacing = &columns(&samples)["band_spacing"];
    let lacking = spacing.iter().filter(|x| x.is_empty()).count();
    let of = |name: &str| {
        let all = summary["outputs"].as_array().unwrap();
        all.iter().find(|o| o["output"] == name).unwrap().clone()
    };
    assert_eq!(of("band_spacing")["undefined_runs"], lacking);
    assert_eq!(of("final_beta_deg")["unit"], "°");
    if lacking > 0 {
        assert!(of("band_spacing")["chaos_share"].is_null());
    }
}

#[test]
fn bad_designs_exit_2_naming_the_argument_before_any_run() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("bad");
    let (case, o) = (fig5(), out.display().to_string());
    for (extra, named) in [
        (
            ["--vary", "soil.friction.peak=45:45", "--samples", "16"],
            "--vary soil.friction.peak=45:45",
        ),
        (
            ["--vary", "soil.friction.peak=abc:45", "--samples", "16"],
            "--vary soil.friction.peak=abc:45",
        ),
        (
            ["--vary", "soil.frict=30:40", "--samples", "16"],
            "--vary soil.frict=30:40",
        ),
        (
            ["--vary", "soil.friction.peak=35:45", "--samples", "12"],
            "--samples 12",
        ),
        // φr = 30 of Fig. 5 above φp where φp < 30: refused, not run to it.
        (
            ["--vary", "soil.friction.peak=25:45", "--samples", "16"],
            "soil.friction.residual: must be <= soil.friction.peak",
        ),
    ] {
        let mut args = vec!["sensitivity", &case, "--method", "sobol", "--out", &o];
        args.extend(extra);
        let done = soilcut(&args);
        let stderr = String::from_utf8_lossy(&done.stderr);
        assert_eq!(done.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(named), "{stderr}");
        assert!(!out.exists(), "nothing written for {named}");
    }
}

/// The columns of a CSV file by name (no quoted fields).
fn columns(text: &str) -> std::collections::BTreeMap<String, Vec<String>> {
    let mut lines = text.lines();
    let names: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let column = |i: usize| rows.iter().map(|r| r[i].to_string()).collect();
    names
        .iter()
        .enumerate()
        .map(|(i, n)| (n.to_string(), column(i)))
        .collect()
}

fn numbers(column: &[String]) -> Vec<f64> {
    column.iter().map(|x| x.parse().unwrap()).collect()
}

/// The outputs of a run are those of `soilcut run`'s files for the same
/// keys: the means over the run and its unit windows, the last β*, the
/// pile's height over d; a varied travel keeps the windows every run
/// covers (40 to 70 at d = 20: two).
#[test]
fn outputs_are_those_of_each_run_s_own_files() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("o");
    morris(
        &out,
        &[
            "--samples",
            "2",
            "--members",
            "1",
            "--vary",
            "soil.friction.peak=35:45",
            "--vary",
            "run.travel=40:70",
        ],
    );
    let case = fig5();
    let samples = read(&out, "samples.csv");
    let header: Vec<&str> = samples.lines().next().unwrap().split(',').collect();
    assert_eq!(
        header[7..],
        [
            "initial_force_norm",
            "max_force_norm",
            "mean_force_norm",
            "band_spacing",
            "final_beta_deg",
            "pile_height",
            "pile_area",
            "mean_force_norm_w1",
            "mean_force_norm_w2",
        ]
    );
    let study = columns(&samples);
    let (peak, travel) = (&study["soil.friction.peak"][0], &study["run.travel"][0]);
    let run = tmp.path().join("run");
    let (p, t) = (
        format!("soil.friction.peak={peak}"),
        format!("run.travel={travel}"),
    );
    let r = run.display().to_string();
    let mut args = vec!["run", &case, "--no-plots", "-q", "--out", &r];
    args.extend(COARSE);
    // After the coarse case's travel, which `coarse` would put last.
    args.extend(["--set", &p, "--set", &t]);
    let done = soilcut(&args);
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let history = columns(&read(&run, "history.csv"));
    let (u, force) = (numbers(&history["u"]), numbers(&history["force_norm"]));
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let first: Vec<f64> = u
        .iter()
        .zip(&force)
        .filter(|(u, _)| **u / 20.0 < 1.0)
        .map(|p| *p.1)
        .collect();
    let heights = numbers(&columns(&read(&run, "profile.csv"))["y"]);
    let value = |name: &str| study[name][0].parse::<f64>().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    assert!(close(value("mean_force_norm"), mean(&force)));
    assert!(close(value("mean_force_norm_w1"), mean(&first)));
    assert_eq!(
        value("final_beta_deg"),
        numbers(&history["beta_deg"]).pop().unwrap()
    );
    let top = heights.iter().copied().fold(0.0, f64::max);
    assert_eq!(value("pile_height"), top / 20.0);
    // The tornado's run of φp at its lower end, the travel the case's.
    let tornado = columns(&read(&out, "tornado.csv"));
    assert_eq!(tornado["end"], ["case", "lo", "hi", "lo", "hi"]);
    assert_eq!(tornado["key"][1], "soil.friction.peak");
    assert_eq!(tornado["value"][1], "35");
    let alone = tmp.path().join("alone");
    let a = alone.display().to_string();
    let mut args = vec!["run", &case, "--no-plots", "-q", "--out", &a];
    args.extend(COARSE);
    args.extend(["--set", "soil.friction.peak=35"]);
    let done = soilcut(&args);
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let forces = numbers(&columns(&read(&alone, "history.csv"))["force_norm"]);
    let at_lo: f64 = tornado["mean_force_norm"][1].parse().unwrap();
    assert!(close(at_lo, mean(&forces)));
    assert!(value("pile_area") > 0.0 && value("pile_area") < top / 20.0 * 70.0 / 20.0);
}

/// Without --members a case's points are ensembles of the measured
/// default K, and the help says so.
#[test]
fn a_case_s_points_are_ensembles_of_the_default_members() {
    use soilcut_study::sensitivity::DEFAULT_MEMBERS;
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("k");
    morris(
        &out,
        &["--samples", "2", "--vary", "blade.wall_friction=5:15"],
    );
    let summary: serde_json::Value = serde_json::from_str(&read(&out, "summary.json")).unwrap();
    assert_eq!(summary["members"], DEFAULT_MEMBERS);
    assert_eq!(summary["runs"], 2 * 2 * DEFAULT_MEMBERS);
    assert_eq!(summary["tornado_runs"], 3 * DEFAULT_MEMBERS);
    let help = soilcut(&["sensitivity", "--help"]);
    let help = String::from_utf8_lossy(&help.stdout)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        help.contains(&format!("({DEFAULT_MEMBERS} when not given")),
        "{help}"
    );
}
