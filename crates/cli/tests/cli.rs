//! The `soilcut` binary end to end: bad inputs, outputs, the output folder.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use tempfile::TempDir;

/// Short cases (100 increments) shared with soilcut-io's unit tests.
const BASE: &str = include_str!("../../io/testdata/original.toml");
pub(crate) const REFINED: &str = include_str!("../../io/testdata/refined.toml");

const SHORT: [&str; 4] = ["--set", "run.travel=20", "--set", "run.increment=0.2"];

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn paper_case() -> PathBuf {
    workspace().join("cases/paper/original.toml")
}

/// A temporary working folder holding `case.toml`.
pub(crate) struct Sandbox {
    pub(crate) dir: TempDir,
}

impl Sandbox {
    pub(crate) fn new(case: &str) -> Self {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("case.toml"), case).unwrap();
        Sandbox { dir }
    }

    pub(crate) fn path(&self, rel: &str) -> PathBuf {
        self.dir.path().join(rel)
    }

    pub(crate) fn soilcut(&self, args: &[&str]) -> Output {
        Command::new(env!("CARGO_BIN_EXE_soilcut"))
            .args(args)
            .current_dir(self.dir.path())
            .output()
            .unwrap()
    }

    /// The names in the folder, sorted.
    pub(crate) fn entries(&self) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(self.dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

pub(crate) fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn assert_ok(o: &Output) {
    assert!(o.status.success(), "{:?}: {}", o.status, stderr(o));
}

/// `soilcut run` and `soilcut check` of `case` with `set` must both fail
/// with exit code 2 and exactly one stderr line starting with `prefix`
/// (after `error: case.toml: `, or `error: --set S: ` for one of `set`),
/// and `run` must create no output folder.
fn assert_bad_input(case: &str, set: &[&str], prefix: &str) -> String {
    let sandbox = Sandbox::new(case);
    let mut sets = Vec::new();
    for s in set {
        sets.extend(["--set", s]);
    }
    let mut line = String::new();
    for command in ["run", "check"] {
        let mut args = vec![command, "case.toml"];
        args.extend(&sets);
        let o = sandbox.soilcut(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{command}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        assert_eq!(err.lines().count(), 1, "one line: {err}");
        let places = std::iter::once("case.toml".to_string())
            .chain(set.iter().map(|s| format!("--set {s}")));
        let expected: Vec<String> = places.map(|p| format!("error: {p}: {prefix}")).collect();
        assert!(
            expected.iter().any(|e| err.starts_with(e)),
            "expected one of {expected:?}, got {err:?}"
        );
        assert!(stdout(&o).is_empty(), "{}", stdout(&o));
        line = err;
    }
    assert_eq!(sandbox.entries(), ["case.toml"], "no output folder");
    line
}

#[test]
fn malformed_toml() {
    let case = BASE.replace("depth = 20.0", "depth = = 20.0");
    assert_bad_input(&case, &[], "line 5: ");
    assert_bad_input("name = \"unterminated", &[], "line 1: ");
}

#[test]
fn missing_key() {
    let case = BASE.replace("depth = 20.0\n", "");
    assert_bad_input(&case, &[], "blade.depth: ");
    assert_bad_input(&BASE.replace("name = \"base\"\n", ""), &[], "name: ");
}

/// What the vertex ground does not do is refused by `run` and `check`
/// alike, naming its key (docs/model.md §9).
#[test]
fn the_time_scheme_is_refused_where_it_cannot_run() {
    assert_bad_input(
        REFINED,
        &[
            "run.vertex_spacing=0.4",
            "choices.face_friction=\"sign\"",
            "run.time_scheme=\"midpoint-force\"",
        ],
        "run.time_scheme: \"midpoint-force\" needs choices.face_friction = \"mobilised\"",
    );
    assert_bad_input(
        REFINED,
        &["run.ground=\"nodes\"", "run.time_scheme=\"midpoint-force\""],
        "run.time_scheme: is a key of run.ground = \"vertices\"",
    );
}

/// A key of the other ground exits 2 naming it, and an old node-grid file
/// (`run.vertex_spacing = 0`) runs on the node grid with a notice that
/// names the key to write instead (issue 49).
#[test]
fn a_key_of_the_other_ground_is_refused_and_an_old_file_noticed() {
    assert_bad_input(
        REFINED,
        &["run.ground=\"nodes\"", "run.vertex_spacing=0.4"],
        "run.vertex_spacing: is a key of run.ground = \"vertices\"",
    );
    assert_bad_input(
        REFINED,
        &["run.node_spacing=0.04"],
        "run.node_spacing: is no longer a key",
    );
    let sandbox = Sandbox::new(REFINED);
    let o = sandbox.soilcut(&["check", "case.toml", "--set", "run.vertex_spacing=0"]);
    assert_ok(&o);
    assert!(
        stderr(&o).contains("notice: case.toml: run.vertex_spacing = 0 is the old way to choose the node grid: write run.ground = \"nodes\""),
        "{}",
        stderr(&o)
    );
    assert!(
        stdout(&o).contains("node grid (the yardstick)"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn unknown_key_in_file() {
    let case = BASE.replace("[blade]", "[blade]\nheight = 100.0");
    let line = assert_bad_input(&case, &[], "blade.height: unknown key");
    assert!(
        line.contains("wall_friction"),
        "lists the valid keys: {line}"
    );
}

#[test]
fn unknown_key_via_set() {
    assert_bad_input(BASE, &["soil.frction.peak=36"], "soil.frction: unknown key");
    assert_bad_input(BASE, &["speed=3"], "speed: unknown key");
}

#[test]
fn a_bad_set_value_names_the_set_not_the_file() {
    let line = assert_bad_input(BASE, &["run.increment=abc"], "run.increment: ");
    assert!(
        line.starts_with("error: --set run.increment=abc: "),
        "{line}"
    );
    // The last --set of the key is the one in force.
    let set = [
        "soil.friction.peak=30",
        "run.travel=5",
        "soil.friction.peak=95",
    ];
    let line = assert_bad_input(BASE, &set, "soil.friction.peak: ");
    assert!(
        line.starts_with("error: --set soil.friction.peak=95: "),
        "{line}"
    );
    // A table set whole is named for the key below it that is wrong.
    let set = ["soil.friction={ peak = 95, residual = 30 }"];
    let line = assert_bad_input(BASE, &set, "soil.friction.peak: ");
    assert!(line.starts_with("error: --set soil.friction="), "{line}");
    // An error in the file, untouched by the --set, names the file.
    let case = BASE.replace("depth = 20.0", "depth = -1.0");
    let line = assert_bad_input(&case, &["run.travel=5"], "blade.depth: ");
    assert!(line.starts_with("error: case.toml: "), "{line}");
}

#[test]
fn a_number_beyond_a_float_is_out_of_range_not_a_string() {
    let line = assert_bad_input(BASE, &["run.increment=1e400"], "1e400 is out of range");
    assert!(
        line.starts_with("error: --set run.increment=1e400: "),
        "{line}"
    );
    assert!(!line.contains("string"), "{line}");
}

#[test]
fn malformed_set() {
    let line = assert_bad_input(BASE, &["run.increment"], "expected key.path=value");
    assert!(line.starts_with("error: --set run.increment: "), "{line}");
    // The argument is named with its control characters escaped: one line.
    let sandbox = Sandbox::new(BASE);
    let o = sandbox.soilcut(&["check", "case.toml", "--set", "run.incr\nement"]);
    assert_eq!(
        stderr(&o),
        "error: --set run.incr\\nement: expected key.path=value\n"
    );
    assert_bad_input(BASE, &["run.increment.x=1"], "run.increment.x: ");
}

#[test]
fn depth_not_positive() {
    assert_bad_input(BASE, &["blade.depth=0"], "blade.depth: ");
    assert_bad_input(BASE, &["blade.depth=-20"], "blade.depth: ");
}

#[test]
fn increment_not_positive() {
    assert_bad_input(BASE, &["run.increment=0"], "run.increment: ");
    assert_bad_input(BASE, &["run.increment=-0.2"], "run.increment: ");
}

#[test]
fn increment_not_below_depth() {
    assert_bad_input(BASE, &["run.increment=20"], "run.increment: ");
    assert_bad_input(BASE, &["run.increment=25"], "run.increment: ");
}

#[test]
fn travel_not_positive() {
    assert_bad_input(BASE, &["run.travel=0"], "run.travel: ");
    assert_bad_input(BASE, &["run.travel=-1"], "run.travel: ");
}

#[test]
fn friction_outside_open_range() {
    assert_bad_input(BASE, &["soil.friction.peak=90"], "soil.friction.peak: ");
    assert_bad_input(
        BASE,
        &["soil.friction.residual=0"],
        "soil.friction.residual: ",
    );
    assert_bad_input(
        REFINED,
        &["soil.friction.initial=-1"],
        "soil.friction.initial: ",
    );
}

#[test]
fn wall_friction_outside_range() {
    assert_bad_input(BASE, &["blade.wall_friction=-1"], "blade.wall_friction: ");
    // Must be below every friction angle: the residual is 30°.
    assert_bad_input(BASE, &["blade.wall_friction=30"], "blade.wall_friction: ");
    assert_bad_input(BASE, &["blade.wall_friction=40"], "blade.wall_friction: ");
}

#[test]
fn residual_above_peak() {
    assert_bad_input(
        BASE,
        &["soil.friction.residual=36"],
        "soil.friction.residual: ",
    );
}

#[test]
fn nan_is_refused() {
    let case = BASE.replace("depth = 20.0", "depth = nan");
    let line = assert_bad_input(&case, &[], "blade.depth: ");
    assert!(line.contains("finite"), "{line}");
    assert_bad_input(BASE, &["soil.unit_weight=nan"], "soil.unit_weight: ");
}

#[test]
fn infinity_is_refused() {
    let case = BASE.replace("travel = 20.0", "travel = inf");
    let line = assert_bad_input(&case, &[], "run.travel: ");
    assert!(line.contains("finite"), "{line}");
    assert_bad_input(BASE, &["blade.wall_friction=-inf"], "blade.wall_friction: ");
}

#[test]
fn no_admissible_mechanism() {
    // φ + φw ≥ 90°: no β > 0 with β + φ + φw < 90°.
    let set = [
        "soil.friction.peak=80",
        "soil.friction.residual=80",
        "blade.wall_friction=10",
    ];
    let line = assert_bad_input(BASE, &set, "soil.friction.peak: ");
    assert!(line.contains("90°"), "{line}");
}

#[test]
fn refined_only_key_in_original_case() {
    let case = BASE.replace("residual_shear = 4.0", "residual_shear = 4.0\nd50 = 0.6");
    let line = assert_bad_input(&case, &[], "soil.d50: ");
    assert!(line.contains("model = \"refined\" only"), "{line}");
    let line = assert_bad_input(
        BASE,
        &["soil.friction.initial=20"],
        "soil.friction.initial: ",
    );
    assert!(line.contains("refined"), "{line}");
}

#[test]
fn both_band_width_keys() {
    let case = REFINED.replace("d50 = 0.6", "d50 = 0.6\nband_width = 4.2");
    let line = assert_bad_input(&case, &[], "soil.band_width: ");
    assert!(
        line.contains("soil.band_width_d50"),
        "names both keys: {line}"
    );
}

#[test]
fn bad_face_friction() {
    for case in [BASE, REFINED] {
        let line = assert_bad_input(
            case,
            &["choices.face_friction=\"smooth\""],
            "choices.face_friction: ",
        );
        assert!(
            line.contains("mobilised") && line.contains("sign"),
            "names the allowed values: {line}"
        );
    }
}

#[test]
fn bad_name() {
    assert_bad_input(BASE, &["name=\"../escape\""], "name: ");
}

#[test]
fn missing_case_file() {
    let sandbox = Sandbox::new(BASE);
    let o = sandbox.soilcut(&["run", "nowhere.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
    assert!(stderr(&o).starts_with("error: nowhere.toml: "));
    assert_eq!(sandbox.entries(), ["case.toml"]);
}

/// `check` prints a fine increment in exponent form (it read "0"), the
/// count and the size of history.csv it would write; a run that long
/// says so on stderr before it starts.
#[test]
fn check_and_a_long_run_tell_the_increments_and_their_cost() {
    let sandbox = Sandbox::new(REFINED);
    let fine = ["--set", "run.travel=0.3", "--set", "run.increment=3e-7"];
    let mut args = vec!["check", "case.toml"];
    args.extend(fine);
    let o = sandbox.soilcut(&args);
    assert_ok(&o);
    let text = stdout(&o);
    assert!(
        text.contains("1000000 steps (history.csv about 300 MB)"),
        "{text}"
    );
    assert!(
        text.contains("; increment 3e-7 (d/66666666.67); "),
        "{text}"
    );
    let long = ["--set", "run.increment=2e-4", "--out", "o", "--no-plots"];
    let mut run = Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(["run", "case.toml"])
        .args(long)
        .current_dir(sandbox.dir.path())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    let mut err = std::io::BufReader::new(run.stderr.take().unwrap());
    std::io::BufRead::read_line(&mut err, &mut line).unwrap();
    run.kill().unwrap();
    run.wait().unwrap();
    assert!(
        line.starts_with("note: case.toml: 100000 steps (history.csv about 30 MB); ")
            && line.contains("increment 2e-4 (d/100000)"),
        "{line}"
    );
}

#[test]
fn refined_case_checks() {
    let sandbox = Sandbox::new(REFINED);
    let o = sandbox.soilcut(&["check", "case.toml"]);
    assert_ok(&o);
    assert_eq!(
        stdout(&o).trim(),
        "ok: case.toml: name refined, model refined, 100 steps (history.csv about 30 kB)\n  \
         vertex ground, vertices every 0.4 (d/50); increment 0.2 (d/100); \
         time scheme midpoint-force; 8 samples per band"
    );
    // The node grid, and an increment that is no whole fraction of d.
    let o = sandbox.soilcut(&[
        "check",
        "case.toml",
        "--set",
        "run.ground=\"nodes\"",
        "--set",
        "run.increment=0.6",
    ]);
    assert_ok(&o);
    assert!(
        stdout(&o).ends_with(
            "  node grid (the yardstick), nodes every increment 0.6 (d/33.33); time scheme \
             explicit; every candidate\n"
        ),
        "{}",
        stdout(&o)
    );
}

fn run_base(sandbox: &Sandbox, out: &str, extra: &[&str]) -> Output {
    let mut args = vec!["run", "case.toml", "--out", out];
    args.extend(extra);
    sandbox.soilcut(&args)
}

#[test]
fn default_output_folder_and_result_line() {
    let sandbox = Sandbox::new(BASE);
    let o = sandbox.soilcut(&["run", "case.toml"]);
    assert_ok(&o);
    let out = stdout(&o);
    assert_eq!(out.lines().count(), 1, "{out}");
    assert!(
        out.contains("100 steps") && out.contains("max force_norm"),
        "{out}"
    );
    assert!(
        out.contains(&format!("out{}base", std::path::MAIN_SEPARATOR)),
        "{out}"
    );
    let mut files: Vec<String> = fs::read_dir(sandbox.path("out/base"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(
        files,
        [
            ".soilcut",
            "animation.gif",
            "case.resolved.toml",
            "frames.csv",
            "history.csv",
            "plots",
            "profile.csv",
            "summary.json"
        ]
    );
    assert_eq!(sandbox.entries(), ["case.toml", "out"], "no staging left");
}

#[test]
fn same_case_gives_identical_history() {
    let sandbox = Sandbox::new(BASE);
    assert_ok(&run_base(&sandbox, "a", &[]));
    assert_ok(&run_base(&sandbox, "b", &[]));
    let a = fs::read(sandbox.path("a/history.csv")).unwrap();
    let b = fs::read(sandbox.path("b/history.csv")).unwrap();
    assert!(a.len() > 1000);
    assert!(a == b, "history.csv differs between two runs");
    let a = fs::read(sandbox.path("a/profile.csv")).unwrap();
    assert!(a == fs::read(sandbox.path("b/profile.csv")).unwrap());
}

#[test]
fn history_csv_layout() {
    let sandbox = Sandbox::new(BASE);
    assert_ok(&run_base(&sandbox, "o", &[]));
    let text = fs::read_to_string(sandbox.path("o/history.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "step,u,u_over_d,force,force_norm,force_h,force_v,beta_deg,x_emergence,mass,y_emergence,friction_deg,slip,dilation_deg,dilation_area,depth,mass_spilled,weight,force_factor,face_friction_deg,moment,tool_x,tool_y,tool_rotation"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 100, "one row per increment");
    assert!(rows.iter().all(|r| r.len() == 24));
    assert_eq!(rows[0][0], 1.0);
    assert_eq!(rows[1][1], 0.2, "u of step 2");
    assert_eq!(rows[1][2], 0.2 / 20.0, "u_over_d");
    let profile = fs::read_to_string(sandbox.path("o/profile.csv")).unwrap();
    assert!(profile.starts_with("x,y,accumulated_shear,unit_weight,ridge_height\n"));
    assert!(profile.lines().count() > 100);
}

#[test]
fn summary_json_fields_and_mass_conservation() {
    let sandbox = Sandbox::new(BASE);
    assert_ok(&run_base(&sandbox, "o", &[]));
    let text = fs::read_to_string(sandbox.path("o/summary.json")).unwrap();
    let s: serde_json::Value = serde_json::from_str(&text).unwrap();
    for key in [
        "name",
        "title",
        "model",
        "initial_force_norm",
        "max_force_norm",
        "u_over_d_at_max",
        "final_force_norm",
        "peaks",
        "peak_prominence_rule",
        "mass_drift_rel",
        "steps",
        "candidate_evaluations",
        "wall_time_s",
    ] {
        assert!(s.get(key).is_some(), "summary.json lacks {key}: {text}");
    }
    assert_eq!(s["name"], "base");
    assert_eq!(s["title"], "base", "title defaults to the name");
    assert_eq!(s["model"], "original");
    assert_eq!(s["steps"], 100);
    assert!(s["peak_prominence_rule"].as_str().unwrap().contains("0.05"));
    let drift = s["mass_drift_rel"].as_f64().unwrap();
    assert!(drift.abs() < 1e-12, "mass drift {drift}");
    // Coulomb's passive wedge, φ = 35°, φw = 10°: ½ Kp ≈ 2.654.
    let first = s["initial_force_norm"].as_f64().unwrap();
    assert!((first - 2.654).abs() < 0.01, "{first}");
    assert!(s["max_force_norm"].as_f64().unwrap() >= first);
}

#[test]
fn existing_folder_refused_then_replaced_with_force() {
    let sandbox = Sandbox::new(BASE);
    fs::create_dir(sandbox.path("o")).unwrap();
    fs::write(sandbox.path("o/stale.txt"), "old").unwrap();
    let o = run_base(&sandbox, "o", &[]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: o: ") && err.contains("--force"),
        "{err}"
    );
    assert_eq!(
        fs::read_to_string(sandbox.path("o/stale.txt")).unwrap(),
        "old"
    );

    let o = run_base(&sandbox, "o", &["--force"]);
    assert_eq!(o.status.code(), Some(2), "soilcut did not write o");
    assert!(stderr(&o).contains("did not write it"), "{}", stderr(&o));
    assert!(sandbox.path("o/stale.txt").exists());

    assert_ok(&run_base(&sandbox, "p", &[]));
    fs::write(sandbox.path("p/stale.txt"), "old").unwrap();
    assert_ok(&run_base(&sandbox, "p", &["--force"]));
    assert!(
        !sandbox.path("p/stale.txt").exists(),
        "--force replaces a folder soilcut wrote"
    );
    assert!(sandbox.path("p/history.csv").exists());
    assert_eq!(
        sandbox.entries(),
        ["case.toml", "o", "p"],
        "nothing left aside"
    );
}

#[test]
fn a_run_that_stops_keeps_its_increments_marked_as_stopped() {
    let sandbox = Sandbox::new(BASE);
    // The bin ends 0.4 beyond the travel: the slip lines reach its wall first.
    let set = ["--set", "run.travel=80", "--set", "bin.length=80.4"];
    let o = run_base(&sandbox, "o", &set);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("no admissible mechanism at increment") && err.contains("kept in o"),
        "{err}"
    );
    let text = fs::read_to_string(sandbox.path("o/summary.json")).unwrap();
    let s: serde_json::Value = serde_json::from_str(&text).unwrap();
    let steps = s["steps"].as_u64().unwrap();
    assert!(steps > 100, "{text}");
    assert_eq!(s["stopped"]["increment"].as_u64(), Some(steps + 1));
    assert!(s["stopped"]["reason"]
        .as_str()
        .unwrap()
        .contains("bin.length"));
    let history = fs::read_to_string(sandbox.path("o/history.csv")).unwrap();
    assert_eq!(history.lines().count() as u64, steps + 1, "header and rows");
    assert!(sandbox.path("o/plots/force.png").exists());
    assert_ok(&run_base(&sandbox, "p", &[]));
    let finished = fs::read_to_string(sandbox.path("p/summary.json")).unwrap();
    assert!(!finished.contains("stopped"), "{finished}");
}

#[test]
fn a_file_is_never_replaced_by_an_output_folder() {
    let sandbox = Sandbox::new(BASE);
    fs::write(sandbox.path("notes.txt"), "mine").unwrap();
    for extra in [&[][..], &["--force"]] {
        let o = run_base(&sandbox, "notes.txt", extra);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        let err = stderr(&o);
        assert!(
            err.starts_with("error: notes.txt: ") && err.contains("not a folder (a file)"),
            "{err}"
        );
    }
    assert_eq!(
        fs::read_to_string(sandbox.path("notes.txt")).unwrap(),
        "mine"
    );
}

#[test]
fn set_changes_the_resolved_case() {
    let sandbox = Sandbox::new(BASE);
    let set = [
        "--set",
        "soil.friction.peak=36",
        "--set",
        "soil.repose=33.5",
    ];
    assert_ok(&run_base(&sandbox, "o", &set));
    let text = fs::read_to_string(sandbox.path("o/case.resolved.toml")).unwrap();
    let case = soilcut_io::parse_case(&text, &[]).unwrap().case;
    assert_eq!(case.soil.friction.peak, 36.0);
    assert_eq!(case.soil.friction.initial, 36.0);
    assert_eq!(case.soil.repose, 33.5);
    assert_eq!(case.run.increment, 0.2);
}

#[test]
fn resolved_case_round_trip() {
    let sandbox = Sandbox::new(BASE);
    let paper = paper_case();
    let mut args = vec!["run", paper.to_str().unwrap(), "--out", "a"];
    args.extend(SHORT);
    assert_ok(&sandbox.soilcut(&args));
    let resolved = fs::read_to_string(sandbox.path("a/case.resolved.toml")).unwrap();

    let overrides: Vec<soilcut_io::Override> = ["run.travel=20", "run.increment=0.2"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    let original = soilcut_io::read_case(&paper, &overrides).unwrap();
    let again = soilcut_io::parse_case(&resolved, &[]).unwrap();
    assert_eq!(again.case, original.case);
    assert_eq!(again.resolved_toml(), resolved);

    // Running the resolved file reproduces the run bit for bit.
    assert_ok(&sandbox.soilcut(&["run", "a/case.resolved.toml", "--out", "b"]));
    let a = fs::read(sandbox.path("a/history.csv")).unwrap();
    assert!(a == fs::read(sandbox.path("b/history.csv")).unwrap());
}

fn case_files(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            case_files(&path, found);
        } else if path.extension().is_some_and(|e| e == "toml") {
            found.push(path);
        }
    }
}

/// A tine narrower than a sixth of its depth runs, with a warning; the
/// paper's cases have none.
#[test]
fn a_narrow_tine_is_warned_about() {
    let check = |case: &str, set: &[&str]| {
        let mut command = Command::new(env!("CARGO_BIN_EXE_soilcut"));
        command.arg("check").arg(workspace().join(case));
        for s in set {
            command.args(["--set", s]);
        }
        let o = command.output().unwrap();
        assert_ok(&o);
        stderr(&o)
    };
    assert_eq!(check("cases/paper/table1-s.toml", &[]), "");
    assert_eq!(check("cases/paper/fig8b.toml", &[]), "");
    // A tine narrower than a sixth of its depth runs, with a warning.
    let tine = "cases/tools/tine.toml";
    let narrow = check(tine, &["blade.width=20"]);
    assert!(narrow.starts_with("warning: blade.width = 20"), "{narrow}");
    assert_eq!(check(tine, &[]), "");
}

/// `--quiet` hides progress, not the warnings: a narrow tine's run warns
/// on stderr with -q, and its summary.json lists the warning (an empty
/// list where nothing is known against the case).
#[test]
fn warnings_survive_quiet_and_are_in_summary_json() {
    let sandbox = Sandbox::new(BASE);
    let tine = workspace().join("cases/tools/tine.toml");
    let tine = tine.to_str().unwrap();
    let short = ["--set", "run.travel=15", "--no-plots", "-q"];
    let run = |out: &str, width: &str| {
        let width = format!("blade.width={width}");
        let mut args = vec!["run", tine, "--set", &width, "--out", out];
        args.extend(short);
        let o = sandbox.soilcut(&args);
        assert_ok(&o);
        assert_eq!(stdout(&o), "", "-q: no result line");
        let text = fs::read_to_string(sandbox.path(&format!("{out}/summary.json"))).unwrap();
        let s: serde_json::Value = serde_json::from_str(&text).unwrap();
        (stderr(&o), s["warnings"].clone())
    };
    let (err, warnings) = run("narrow", "20");
    assert!(err.starts_with("warning: blade.width = 20"), "{err}");
    let listed = warnings.as_array().expect("a list of warnings");
    assert_eq!(listed.len(), 1, "{warnings}");
    assert_eq!(format!("warning: {}\n", listed[0].as_str().unwrap()), err);
    let (err, warnings) = run("wide", "50");
    assert_eq!(err, "");
    assert_eq!(warnings, serde_json::json!([]));
}

/// A width that is not a length > 0 is refused with exit code 2, naming
/// the key.
#[test]
fn a_bad_blade_width_names_the_key() {
    for bad in ["0", "-5", "nan", "\"wide\""] {
        let o = Command::new(env!("CARGO_BIN_EXE_soilcut"))
            .arg("check")
            .arg(workspace().join("cases/tools/tine.toml"))
            .args(["--set", &format!("blade.width={bad}")])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(stderr(&o).contains("blade.width"), "{bad}: {}", stderr(&o));
    }
}

/// `soil.d50` beyond the range of lengths is refused where the band width
/// is a length too (which does not use d50), and an empty
/// `blade.depth_path`, each naming the key and what it takes.
#[test]
fn a_grain_size_out_of_range_and_an_empty_depth_path_name_their_key() {
    let length = REFINED.replace("band_width_d50 = 7", "band_width = 4.2");
    for d50 in ["1e300", "1e-300"] {
        let set = format!("soil.d50={d50}");
        let line = assert_bad_input(&length, &[&set], "soil.d50: ");
        assert!(line.contains("a length in [1e-20, 1e20]"), "{line}");
    }
    let line = assert_bad_input(REFINED, &["blade.depth_path=[]"], "blade.depth_path: ");
    assert!(line.contains("at least one point"), "{line}");
    let one = ["blade.depth_path=[[0, 20]]"];
    let o = Sandbox::new(REFINED).soilcut(&["check", "case.toml", "--set", one[0]]);
    assert_ok(&o);
}

/// A title past 200 characters is refused naming `title` (or `name`, which
/// it defaults to), as it heads every picture; 200 are taken.
#[test]
fn a_title_past_200_characters_is_refused() {
    let titled = |title: &str| BASE.replacen("\n", &format!("\ntitle = \"{title}\"\n"), 1);
    let long = "é".repeat(201);
    let line = assert_bad_input(&titled(&long), &[], "title: ");
    assert!(
        line.contains("at most 200 characters") && line.contains("(got 201)"),
        "{line}"
    );
    let named = BASE.replacen(
        "name = \"base\"",
        &format!("name = \"{}\"", "n".repeat(201)),
        1,
    );
    assert_bad_input(&named, &[], "name: the title is at most 200");
    let o = Sandbox::new(&titled(&"é".repeat(200))).soilcut(&["check", "case.toml"]);
    assert_ok(&o);
}

#[test]
fn check_accepts_every_case_file() {
    let mut found = Vec::new();
    case_files(&workspace().join("cases"), &mut found);
    assert!(found.iter().any(|p| p.ends_with("paper/original.toml")));
    for path in found {
        let o = Command::new(env!("CARGO_BIN_EXE_soilcut"))
            .arg("check")
            .arg(&path)
            .output()
            .unwrap();
        assert_ok(&o);
        assert!(stdout(&o).starts_with("ok: "), "{}", stdout(&o));
    }
}

#[test]
fn help_shows_examples() {
    let sandbox = Sandbox::new(BASE);
    for args in [&["--help"][..], &["run", "--help"], &["check", "--help"]] {
        let o = sandbox.soilcut(args);
        assert_ok(&o);
        let text = stdout(&o);
        assert!(text.contains("Examples:"), "{args:?}: {text}");
        assert!(text.contains("soilcut "), "{args:?}: {text}");
    }
    let text = stdout(&sandbox.soilcut(&["run", "--help"]));
    assert!(text.contains("soilcut run cases/paper/original.toml --set run.increment=0.02"));
}

/// `soilcut --version` names the version and the commit the binary was
/// built from: HEAD of this work tree when git can tell (`build.rs`).
#[test]
fn every_option_shows_one_default_at_most() {
    let commands = [
        "run",
        "check",
        "analytic",
        "plot",
        "compare",
        "landscape",
        "sweep",
        "fit",
        "converge",
        "accuracy",
        "sensitivity",
    ];
    for command in commands {
        let o = Command::new(env!("CARGO_BIN_EXE_soilcut"))
            .args([command, "--help"])
            .output()
            .unwrap();
        let help = stdout(&o);
        // An option's entry runs from its `-` line (indented by at most six
        // columns: `  -q, --quiet` or `      --vary`) to the next one.
        let mut entries: Vec<String> = Vec::new();
        for line in help.lines() {
            let indent = line.len() - line.trim_start().len();
            if line.trim_start().starts_with('-') && indent <= 6 {
                entries.push(String::new());
            }
            if let Some(entry) = entries.last_mut() {
                entry.push_str(line);
                entry.push('\n');
            }
        }
        assert!(!entries.is_empty(), "{command}: no options read in {help}");
        for entry in entries {
            assert!(
                entry.matches("[default").count() <= 1,
                "{command}: two defaults in {entry}"
            );
        }
    }
}

#[test]
fn a_folder_that_is_not_a_run_is_named_so() {
    let sandbox = Sandbox::new(BASE);
    std::fs::create_dir(sandbox.path("empty")).unwrap();
    for args in [vec!["plot", "empty"], vec!["compare", "empty"]] {
        let o = sandbox.soilcut(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = stderr(&o);
        assert!(
            err.starts_with(
                "error: empty: not a run folder: a run folder is one `soilcut run` wrote"
            ),
            "{err}"
        );
        assert!(!err.contains("cannot read"), "{err}");
    }
    let err = stderr(&sandbox.soilcut(&["plot", "nowhere"]));
    assert!(err.starts_with("error: nowhere: no such folder: "), "{err}");
}

#[test]
fn version_names_the_commit() {
    let o = Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .arg("--version")
        .output()
        .unwrap();
    assert_ok(&o);
    let text = stdout(&o);
    let prefix = concat!("soilcut ", env!("CARGO_PKG_VERSION"), " (commit ");
    let commit = text
        .trim_end()
        .strip_prefix(prefix)
        .and_then(|rest| rest.strip_suffix(')'))
        .unwrap_or_else(|| panic!("{text}"));
    let head = Command::new("git")
        .args(["rev-parse", "--verify", "HEAD"])
        .current_dir(workspace())
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    match head {
        Some(head) => {
            assert_eq!(commit.len(), 12, "{text}");
            assert!(head.starts_with(commit), "{text} is not HEAD {head}");
        }
        None => assert!(
            commit == "unknown" || commit.chars().all(|c| c.is_ascii_hexdigit()),
            "{text}"
        ),
    }
}

/// Every example command in the help texts names a valid case and valid
/// `--set`s (checked with `check`, from the workspace root).
#[test]
fn help_examples_are_valid() {
    let mut examples = 0;
    for args in [&["--help"][..], &["run", "--help"], &["check", "--help"]] {
        let help = Command::new(env!("CARGO_BIN_EXE_soilcut"))
            .args(args)
            .output()
            .unwrap();
        for line in stdout(&help).lines() {
            let Some(example) = line.trim().strip_prefix("soilcut ") else {
                continue;
            };
            let mut words = example.split_whitespace().skip(1);
            let mut check = vec!["check".to_string()];
            while let Some(word) = words.next() {
                match word {
                    // Options of `run` alone, with their values.
                    "--out" | "--ensemble" | "--jobs" => {
                        words.next();
                    }
                    "--force" => {}
                    w => check.push(w.to_string()),
                }
            }
            let o = Command::new(env!("CARGO_BIN_EXE_soilcut"))
                .args(&check)
                .current_dir(workspace())
                .output()
                .unwrap();
            assert!(o.status.success(), "{line}: {}", stderr(&o));
            examples += 1;
        }
    }
    assert!(examples >= 6, "{examples} examples");
}

/// The landscape's least candidate is the force the run records at the
/// same increment, and every candidate's ratio to it is at least 1.
#[test]
fn landscape_least_candidate_is_the_recorded_force() {
    // The landscape holds the forces the search compares, at the start of
    // the increment: the force the step records under the explicit rule
    // (the midpoint force, the vertex ground's default, records the same
    // band's half an increment on).
    let sandbox = Sandbox::new(REFINED);
    let explicit = ["--set", "run.time_scheme=explicit"];
    let mut args = vec!["landscape", "case.toml", "--at", "0.5", "--out", "ls"];
    args.extend(explicit);
    let o = sandbox.soilcut(&args);
    assert_ok(&o);
    assert!(stdout(&o).contains("u/d = 0.500"), "{}", stdout(&o));
    let mut args = vec!["run", "case.toml", "--out", "run", "--no-plots"];
    args.extend(explicit);
    assert_ok(&sandbox.soilcut(&args));
    assert!(sandbox.path("ls/landscape.png").is_file());
    let rows = |file: &str, key: &str| -> Vec<Vec<f64>> {
        let text = fs::read_to_string(sandbox.path(file)).unwrap();
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        assert!(header.contains(&key), "{file}: {header:?}");
        lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect()
    };
    let landscape = rows("ls/landscape.csv", "force_over_least");
    assert!(landscape.len() > 50, "{} candidates", landscape.len());
    let least = landscape.iter().map(|r| r[4]).fold(f64::INFINITY, f64::min);
    assert!(landscape.iter().all(|r| r[6] >= 1.0));
    let history = rows("run/history.csv", "force");
    let at_half = history.iter().find(|r| r[2] == 0.5).expect("u/d = 0.5 row");
    assert_eq!(least, at_half[3]);
}

#[test]
fn landscape_outside_the_travel_is_refused() {
    for at in ["1.5", "-0.1", "NaN"] {
        let sandbox = Sandbox::new(REFINED);
        let o = sandbox.soilcut(&["landscape", "case.toml", "--at", at]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{at}: {err}");
        assert!(
            err.starts_with(
                "error: case.toml: --at must be a number from 0 to run.travel / blade.depth = 1 "
            ),
            "{err}"
        );
        assert_eq!(sandbox.entries(), ["case.toml"], "no output folder");
    }
}

/// A map of landscapes: one column per u/d = 0, E, 2E, …, each holding the
/// least force (ratio exactly 1) and no ratio below it.
#[test]
fn landscape_map_has_the_least_force_in_every_column() {
    let sandbox = Sandbox::new(REFINED);
    let o = sandbox.soilcut(&["landscape", "case.toml", "--every", "0.25", "--out", "map"]);
    assert_ok(&o);
    assert!(
        stdout(&o).starts_with("5 landscapes from u/d = 0 to 1.000"),
        "{}",
        stdout(&o)
    );
    assert!(sandbox.path("map/landscape_map.png").is_file());
    let text = fs::read_to_string(sandbox.path("map/landscape_map.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("u_over_d,distance_over_d,force_over_least")
    );
    let mut columns: Vec<(String, Vec<f64>)> = Vec::new();
    for line in lines {
        let (u, rest) = line.split_once(',').unwrap();
        let ratio: f64 = rest.split(',').nth(1).unwrap().parse().unwrap();
        match columns.last_mut() {
            Some((last, ratios)) if last == u => ratios.push(ratio),
            _ => columns.push((u.to_string(), vec![ratio])),
        }
    }
    let us: Vec<&str> = columns.iter().map(|c| c.0.as_str()).collect();
    assert_eq!(us, ["0", "0.25", "0.5", "0.75", "1"]);
    for (u, ratios) in &columns {
        assert!(ratios.contains(&1.0), "u/d {u}");
        assert!(ratios.iter().all(|&r| r >= 1.0), "u/d {u}");
    }
}

#[test]
fn landscape_needs_one_valid_moment() {
    let sandbox = Sandbox::new(REFINED);
    for (args, says) in [
        (
            vec!["--every", "0"],
            "--every must be a number above 0, at most run.travel / blade.depth = 1 ",
        ),
        (vec!["--every", "2"], "--every must be"),
        (vec!["--every", "inf"], "--every must be"),
    ] {
        let mut all = vec!["landscape", "case.toml"];
        all.extend(&args);
        let o = sandbox.soilcut(&all);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.starts_with(&format!("error: case.toml: {says}")),
            "{err}"
        );
    }
    for args in [vec![], vec!["--at", "0.5", "--every", "0.25"]] {
        let mut all = vec!["landscape", "case.toml"];
        all.extend(&args);
        let o = sandbox.soilcut(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o).matches("error:").count(), 1, "{}", stderr(&o));
    }
    assert_eq!(sandbox.entries(), ["case.toml"], "no output folder");
}

/// A tool (docs/model.md §21): `check` says which blade it is (M55); a
/// profile that crosses itself, a pose path going backwards and a tool
/// the mechanism cannot take yet exit 2 naming their key, before any
/// folder.
#[test]
fn a_tool_is_checked_by_its_keys_and_told_as_its_blade() {
    let file = workspace().join("cases/tools/straight-profile.toml");
    let tool = fs::read_to_string(&file).unwrap();
    let sandbox = Sandbox::new(&tool);
    let o = sandbox.soilcut(&["check", "case.toml"]);
    assert_ok(&o);
    assert!(
        stdout(&o).contains("tool: a straight profile, pivot [0.0, 0.0], 2 poses over s = 0 to 100: the blade of rake 90° at constant depth"),
        "{}",
        stdout(&o)
    );
    let points = "tool.points=[[0.0, 0.0], [0.0, 10.0], [-5.0, 2.0], [5.0, 5.0]]";
    assert_bad_input(
        &tool,
        &["tool.shape=\"points\"", "tool.rake=90", points],
        "tool.rake: is not a key",
    );
    let crossing = tool
        .replace("shape = \"straight\"", "shape = \"points\"")
        .replace(
            "rake = 90.0           # α at rotation 0, degrees (90: vertical)\n",
            "",
        )
        .replace(
            "height = 70.0",
            "points = [[0.0, 0.0], [0.0, 10.0], [-5.0, 2.0], [5.0, 5.0]]",
        );
    assert_bad_input(&crossing, &[], "tool.points: crosses itself: piece 0");
    let back =
        "tool.motion=[[0.0, 0.0, -20.0, 0.0], [50.0, 50.0, -20.0, 0.0], [40.0, 60.0, -20.0, 0.0]]";
    assert_bad_input(&tool, &[back], "tool.motion: goes backwards in s: pose 2");
    let curl = "tool.motion=[[0.0, 0.0, -20.0, 0.0], [50.0, 50.0, -20.0, 10.0]]";
    assert_bad_input(&tool, &[curl], "tool.motion: pose 1 rotates the tool");
    let bucket = tool
        .replace("shape = \"straight\"", "shape = \"bucket\"")
        .replace(
            "rake = 90.0           # α at rotation 0, degrees (90: vertical)\n",
            "",
        )
        .replace("height = 70.0", "floor = 40.0\nback_radius = 30.0");
    assert_bad_input(&bucket, &[], "tool.shape: a curved or bent profile");
}
