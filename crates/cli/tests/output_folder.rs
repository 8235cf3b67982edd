//! The output folder against races, signals and debris (issue 50, items 4,
//! 5 and 9): two commands into one `--out`, a folder made at `--out`
//! while a command runs, Ctrl-C and SIGTERM, a killed run's staging folder,
//! an interrupted `--force` swap, an interrupted sweep, destinations that
//! cannot be written.

use crate::cli::Sandbox;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::Duration;

const REFINED: &str = include_str!("../../io/testdata/refined.toml");

/// A run of some seconds (10 000 increments): long enough for the test to
/// act while it runs.
const LONG: [&str; 6] = [
    "--set",
    "run.travel=200",
    "--set",
    "run.increment=0.02",
    "--no-plots",
    "-q",
];

/// A temporary folder holding `case.toml`, where the commands run.
struct Place {
    sandbox: Sandbox,
}

impl Place {
    fn new() -> Self {
        Place {
            sandbox: Sandbox::new(REFINED),
        }
    }

    fn path(&self, rel: &str) -> PathBuf {
        self.sandbox.path(rel)
    }

    fn entries(&self) -> Vec<String> {
        self.sandbox.entries()
    }

    fn command(&self, args: &[&str]) -> Command {
        let mut c = Command::new(env!("CARGO_BIN_EXE_soilcut"));
        c.args(args).current_dir(self.sandbox.dir.path());
        c
    }

    fn output(&self, args: &[&str]) -> Output {
        self.command(args).output().unwrap()
    }

    fn spawn(&self, args: &[&str]) -> Child {
        self.command(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    }

    /// The hidden names soilcut made beside `name` (`.NAME.…`).
    fn hidden(&self, name: &str) -> Vec<String> {
        let prefix = format!(".{name}.");
        let mut found = self.entries();
        found.retain(|e| e.starts_with(&prefix));
        found
    }
}

/// Polls until `done` holds or `child` has exited; whether `done` held.
/// Polling only waits: no assertion depends on how long anything takes.
fn wait_until(child: &mut Child, mut done: impl FnMut() -> bool) -> bool {
    loop {
        if done() {
            return true;
        }
        if child.try_wait().unwrap().is_some() {
            return done();
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn signal(child: &Child, name: &str) {
    let status = Command::new("kill")
        .args(["-s", name, &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn run_args<'a>(out: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["run", "case.toml", "--out", out];
    args.extend(extra);
    args
}

fn sweep_args<'a>(out: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "sweep",
        "case.toml",
        "--vary",
        "soil.friction.peak=30:40:4",
        "--jobs",
        "1",
        "--quiet",
        "--out",
        out,
        "--set",
        "run.travel=200",
        "--set",
        "run.increment=0.02",
    ];
    args.extend(extra);
    args
}

/// Whether soilcut has taken `name`: anything of its at or beside it.
fn claimed(place: &Place, name: &str) -> bool {
    !place.hidden(name).is_empty() || place.path(name).exists()
}

#[test]
fn a_second_command_into_the_same_out_is_refused() {
    let place = Place::new();
    let mut first = place.spawn(&sweep_args("o", &[]));
    assert!(wait_until(&mut first, || claimed(&place, "o")));
    let second = place.output(&sweep_args("o", &[]));
    let err = stderr(&second);
    assert_eq!(second.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: o: ") && err.contains("another soilcut"),
        "{err}"
    );
    let first = first.wait_with_output().unwrap();
    assert!(first.status.success(), "{}", stderr(&first));
    let csv = fs::read_to_string(place.path("o/sweep.csv")).unwrap();
    assert_eq!(csv.lines().count(), 5, "the first sweep's four runs: {csv}");
    assert!(place.hidden("o").is_empty(), "{:?}", place.entries());
}

/// A folder made at `--out` while a command runs: `user` makes it (its
/// file `mine.txt`) once the command has taken the name.
fn user_folder_survives(place: &Place, args: &[&str]) -> String {
    let mut child = place.spawn(args);
    assert!(wait_until(&mut child, || !place.hidden("o").is_empty()));
    fs::create_dir(place.path("o")).expect("the command is still running");
    fs::write(place.path("o/mine.txt"), "mine").unwrap();
    let o = child.wait_with_output().unwrap();
    assert_eq!(
        fs::read_to_string(place.path("o/mine.txt")).unwrap(),
        "mine",
        "the user's folder is kept"
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(place.hidden("o").is_empty(), "{:?}", place.entries());
    stderr(&o)
}

#[test]
fn a_folder_made_at_out_during_a_run_is_never_deleted() {
    let place = Place::new();
    let err = user_folder_survives(&place, &run_args("o", &LONG));
    assert!(err.contains("appeared"), "{err}");
    // The run's outputs are kept beside it, under a name the error gives.
    let kept = err.rsplit(' ').next().unwrap().trim();
    assert!(place.path(kept).join("history.csv").is_file(), "{err}");
}

#[test]
fn a_folder_made_at_out_during_a_study_is_never_deleted() {
    let place = Place::new();
    let args = study_args(&["converge", "case.toml", "--levels", "2"]);
    let err = user_folder_survives(&place, &args);
    assert!(err.contains("appeared"), "{err}");
}

/// A study's `command` (its words) into `o` on one thread, of some
/// seconds.
fn study_args<'a>(command: &[&'a str]) -> Vec<&'a str> {
    let mut args = command.to_vec();
    args.extend(["--jobs", "1", "--quiet", "--out", "o"]);
    args.extend(["--set", "run.travel=200", "--set", "run.increment=0.04"]);
    args
}

/// `args` into `o`, stopped by `signal` once its staging folder exists:
/// nothing of it is left.
fn stopped_leaves_nothing(args: &[&str], name: &str) {
    let place = Place::new();
    let mut child = place.spawn(args);
    assert!(
        wait_until(&mut child, || !place.hidden("o").is_empty()),
        "a staging folder while it runs"
    );
    signal(&child, name);
    let o = child.wait_with_output().unwrap();
    assert!(!o.status.success(), "{name}: {}", stderr(&o));
    assert_eq!(place.entries(), ["case.toml"], "{name}: nothing left");
}

#[test]
fn ctrl_c_and_sigterm_leave_no_staging_folder() {
    for name in ["INT", "TERM"] {
        stopped_leaves_nothing(&run_args("o", &LONG), name);
    }
}

#[test]
fn a_stopped_fit_leaves_no_staging_folder() {
    let place = Place::new();
    fs::write(place.path("lab.csv"), "u,force\n1,10\n2,20\n").unwrap();
    let measured = place.path("lab.csv").display().to_string();
    let fit = ["fit", "case.toml", "--measured", &measured];
    let args = study_args(&[&fit[..], &["--free", "soil.friction.peak"]].concat());
    stopped_leaves_nothing(&args, "TERM");
}

#[test]
fn a_killed_runs_staging_folder_is_cleaned_by_the_next_run() {
    let place = Place::new();
    let mut child = place.spawn(&run_args("o", &LONG));
    assert!(wait_until(&mut child, || !place.hidden("o").is_empty()));
    signal(&child, "KILL");
    child.wait().unwrap();
    assert!(!place.hidden("o").is_empty(), "SIGKILL cannot be caught");
    let o = place.output(&run_args("p", &["--set", "run.travel=2", "--no-plots"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(place.entries(), ["case.toml", "p"]);
}

#[test]
fn an_interrupted_force_swap_is_restored_by_the_next_run() {
    let place = Place::new();
    let short = ["--set", "run.travel=2", "--no-plots"];
    assert!(place.output(&run_args("p", &short)).status.success());
    // As a kill between the two renames of --force left it: the old
    // results aside under a process's number that is not running.
    fs::rename(place.path("p"), place.path(".p.old-4194999-0")).unwrap();
    let o = place.output(&run_args("q", &short));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(place.entries(), ["case.toml", "p", "q"]);
    assert!(place.path("p/history.csv").is_file());
}

#[test]
fn an_interrupted_sweep_keeps_its_finished_runs() {
    let place = Place::new();
    let mut child = place.spawn(&sweep_args("o", &["--keep-runs"]));
    let csv = place.path("o/sweep.csv");
    let rows = || fs::read_to_string(&csv).map_or(0, |t| t.lines().count().saturating_sub(1));
    assert!(
        wait_until(&mut child, || rows() >= 1),
        "sweep.csv holds each run as it finishes"
    );
    signal(&child, "INT");
    let o = child.wait_with_output().unwrap();
    assert!(!o.status.success(), "{}", stderr(&o));
    let kept = rows();
    assert!((1..4).contains(&kept), "{kept} of 4 runs");
    let text = fs::read_to_string(place.path("o/summary.json")).unwrap();
    let s: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(s["complete"], false, "{text}");
    assert_eq!(s["finished"].as_u64(), Some(kept as u64), "{text}");
    assert!(s["stopped"].as_str().unwrap().contains("SIGINT"), "{text}");
    let runs = fs::read_dir(place.path("o/runs")).unwrap().count();
    assert!(runs >= kept, "{runs} run folders for {kept} rows");
    assert_eq!(place.entries(), ["case.toml", "o"], "nothing hidden left");
}

#[test]
fn a_finished_sweep_says_it_is_complete() {
    let place = Place::new();
    let o = place.output(&sweep_args("o", &["--set", "run.travel=4"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(place.path("o/summary.json")).unwrap();
    let s: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(s["complete"], true, "{text}");
    assert_eq!(s["finished"].as_u64(), Some(4), "{text}");
    assert!(s.get("stopped").is_none(), "{text}");
}

/// `args` refused with exit code 2, the error naming the argument
/// `named`; nothing made. The error.
fn argument_refused(args: &[&str], named: &str) -> String {
    let place = Place::new();
    let o = place.output(args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.starts_with(&format!("error: {named}: ")), "{err}");
    assert_eq!(place.entries(), ["case.toml"], "no folder");
    err
}

#[test]
fn a_vary_value_of_the_wrong_type_is_refused_before_any_run() {
    let vary = "soil.friction.peak=abc";
    let args = ["sweep", "case.toml", "--vary", vary, "--out", "o"];
    let err = argument_refused(&args, &format!("--vary {vary}"));
    assert!(
        err.contains("expected a number, got the string \"abc\""),
        "{err}"
    );
}

/// `--out out` is refused before the run with exit code 2 and an error
/// naming `named` that contains `says`; nothing is made.
fn refused_before_running(out: &str, named: &str, says: &str) {
    let place = Place::new();
    fs::write(place.path("afile.txt"), "mine").unwrap();
    let o = place.output(&run_args(out, &LONG));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{out}: {err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with(&format!("error: {named}: ")),
        "{out}: {err}"
    );
    assert!(err.contains(says), "{out}: {err}");
    assert!(!err.contains(".tmp-"), "names no hidden folder: {err}");
    assert_eq!(place.entries(), ["afile.txt", "case.toml"], "{out}");
}

#[test]
fn a_destination_that_cannot_be_made_is_refused_before_running() {
    refused_before_running("afile.txt/sub", "afile.txt", "not a folder");
    refused_before_running(".", ".", "without a name");
    let long = "n".repeat(256);
    refused_before_running(&long, &long, "bytes");
    if Path::new("/proc/self").exists() {
        refused_before_running("/proc/nope", "/proc/nope", "choose another --out");
    }
}

/// Every command that writes a folder at `--out` checks it before it runs
/// (the run, the ensemble, landscape, bounds and the studies): exit 2,
/// the error naming the file in the way, nothing made.
#[test]
fn every_command_with_out_checks_it_before_running() {
    let vary = ["--vary", "soil.friction.peak=35,40"];
    let commands: [&[&str]; 8] = [
        &["run", "case.toml"],
        &["run", "case.toml", "--ensemble", "3"],
        &["landscape", "case.toml", "--at", "0.5"],
        &["bounds", "case.toml", "--at", "0.5"],
        &["sweep", "case.toml", vary[0], vary[1]],
        &[
            "fit",
            "case.toml",
            "--measured",
            "m.csv",
            "--free",
            "soil.friction.peak",
        ],
        &["converge", "case.toml", "--levels", "2"],
        &[
            "sensitivity",
            "case.toml",
            "--method",
            "morris",
            "--vary",
            "soil.friction.peak=35:40",
        ],
    ];
    for command in commands {
        let place = Place::new();
        fs::write(place.path("afile.txt"), "mine").unwrap();
        fs::write(place.path("m.csv"), "u,force\n0,1\n10,2\n").unwrap();
        let mut args = command.to_vec();
        args.extend(["--out", "afile.txt/sub"]);
        // A long run's keys (not its flags, which are run's own).
        args.extend(&LONG[..4]);
        let o = place.output(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{command:?}: {err}");
        assert!(
            err.starts_with("error: afile.txt: ") && err.contains("choose another --out"),
            "{command:?}: {err}"
        );
        assert_eq!(place.entries(), ["afile.txt", "case.toml", "m.csv"]);
    }
}

#[test]
fn a_folder_given_with_a_trailing_dot_is_that_folder() {
    let place = Place::new();
    let o = place.output(&run_args("x/.", &["--set", "run.travel=2", "--no-plots"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(place.path("x/history.csv").is_file());
    assert_eq!(place.entries(), ["case.toml", "x"]);
}

#[test]
fn a_set_value_with_a_line_break_is_refused() {
    let two = "run.travel=10\nblade.depth=5";
    let args = ["run", "case.toml", "--set", two, "--out", "o"];
    let err = argument_refused(&args, "--set run.travel=10\\nblade.depth=5");
    assert!(err.contains("line break"), "{err}");
}
