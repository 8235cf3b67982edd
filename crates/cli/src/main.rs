//! `soilcut`: the command line. Argument parsing and calls into
//! `soilcut-io`, `soilcut-model` and `soilcut-bounds` only.
//!
//! Exit codes: 0 success, 2 bad input (case file, `--set`, an occupied
//! output folder, a case without an admissible mechanism), 1 anything else
//! (I/O). Every error is one line on stderr: `error: <path>: <message>`.

// The doc comments of the argument structs are clap's help texts, shown as
// they are written (`out/<name>`), not rustdoc markup.
#![allow(rustdoc::invalid_html_tags)]

mod accuracy_cmd;
mod analytic_cmd;
mod bounds_cmd;
mod ensemble_cmd;
mod landscape_cmd;
mod sensitivity_cmd;
mod study_cmd;
mod sweep_cmd;
mod sweep_folder;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use soilcut_io::{
    read_case, record_case, write_run_into, InputError, LoadedCase, OutputDir, OutputError,
    Override, PictureError, RecordedRun,
};
use soilcut_model::Case;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const EXAMPLES: &str = "\
Examples:
  soilcut run cases/paper/original.toml
  soilcut run cases/paper/original.toml --set run.increment=0.02 --out out/fine
  soilcut check cases/paper/original.toml --set soil.friction.peak=36";

const RUN_EXAMPLES: &str = "\
Examples:
  soilcut run cases/paper/original.toml
      writes out/original/{history.csv,profile.csv,summary.json,case.resolved.toml,frames.csv},
      out/original/plots/{force,beta,deformation}.{png,svg} and out/original/animation.gif
  soilcut run cases/paper/original.toml --set run.increment=0.02
  soilcut run cases/paper/original.toml --set run.travel=20 --out out/short --force
  soilcut run cases/paper/table1-s.toml --ensemble 7
      writes out/table1-s/{ensemble.csv,summary.json,plots/envelope.{png,svg}} and
      one run folder per member, out/table1-s/k-3 ... out/table1-s/k+3";

const CHECK_EXAMPLES: &str = "\
Examples:
  soilcut check cases/paper/original.toml
  soilcut check cases/paper/original.toml --set run.increment=0.02";

const PLOT_EXAMPLES: &str = "\
Examples:
  soilcut plot out/original
      redraws out/original/plots/{force,beta,deformation}.{png,svg} and out/original/animation.gif";

const COMPARE_EXAMPLES: &str = "\
Examples:
  soilcut compare out/original out/fine
  soilcut compare out/original out/fine --measured tests.csv --out out/fig7.svg";

/// `soilcut --version`: the crate version and the commit it was built from
/// (`build.rs`; `unknown` when built without git).
const VERSION: &str = concat!(
    env!("CARGO_PKG_VERSION"),
    " (commit ",
    env!("SOILCUT_COMMIT"),
    ")"
);

/// Soil cutting by sequential limit analysis (Jin & Hambleton).
#[derive(Parser)]
#[command(name = "soilcut", version = VERSION, after_help = EXAMPLES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a case and write its outputs into a new folder.
    #[command(after_help = RUN_EXAMPLES)]
    Run {
        #[command(flatten)]
        target: CaseOutput,
        /// Do not draw the pictures (plots/ and animation.gif); `soilcut plot` can draw them later.
        #[arg(long)]
        no_plots: bool,
        /// No progress bar and no summary line (warnings are still printed).
        #[arg(long, short)]
        quiet: bool,
        /// Run N members with imperceptible perturbations (soil.d50 × (1 + 0.001 k), or
        /// blade.wall_friction + 0.01° × k in the original model; k = −3 … 3 for 7) in
        /// parallel: each member's folder k-3 … k+3, ensemble.csv (the spread of every
        /// unit-window mean), summary.json and plots/envelope.{png,svg}.
        #[arg(long, value_name = "N")]
        ensemble: Option<usize>,
        /// Worker threads for --ensemble [default: one per core]. Results do not depend on it.
        #[arg(
            long,
            value_name = "N",
            default_value_t = 0,
            hide_default_value = true,
            requires = "ensemble"
        )]
        jobs: usize,
    },
    /// Read and validate a case without running it.
    #[command(after_help = CHECK_EXAMPLES)]
    Check {
        /// The case file (TOML).
        case: PathBuf,
        /// Override a key of the case file, e.g. run.increment=0.02 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Print the analytical baselines (Rankine, Coulomb, FEE) for a case's initial flat ground.
    #[command(after_help = analytic_cmd::EXAMPLES)]
    Analytic {
        /// The case file (TOML).
        case: PathBuf,
        /// Override a key of the case file, e.g. soil.cohesion=5 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Redraw the pictures of a finished run from its files (no simulation).
    #[command(after_help = PLOT_EXAMPLES)]
    Plot {
        /// The run's output folder.
        dir: PathBuf,
    },
    /// Overlay the force and β* curves of finished runs (paper Fig. 7).
    #[command(after_help = COMPARE_EXAMPLES)]
    Compare {
        /// The runs' output folders; the legend shows each case's title, or
        /// the folder's last components where titles are equal.
        #[arg(required = true, value_name = "OUTDIR")]
        dirs: Vec<PathBuf>,
        /// The picture to write, .png or .svg.
        #[arg(long, value_name = "FILE", default_value = "compare.png")]
        out: PathBuf,
        /// A measured curve: CSV with columns u,force (u in the case's length
        /// unit, force per unit width in γ·length²), normalised by the first
        /// run's γ0 d².
        #[arg(long, value_name = "FILE")]
        measured: Option<PathBuf>,
    },
    /// The force of every candidate band at one moment of a run.
    #[command(after_help = landscape_cmd::EXAMPLES)]
    Landscape(landscape_cmd::LandscapeArgs),
    /// Rigorous lower and upper bounds on the ground's collapse load at an instant, beside soilcut's force.
    #[command(after_help = bounds_cmd::EXAMPLES)]
    Bounds(bounds_cmd::BoundsArgs),
    /// Run a case for many values of its keys (a grid or a Latin-hypercube sample), in parallel.
    #[command(after_help = sweep_cmd::SWEEP_EXAMPLES)]
    Sweep(sweep_cmd::SweepArgs),
    /// Morris screening or Sobol indices of a case's forces over ranges of its keys, chaos-aware.
    #[command(after_help = sensitivity_cmd::EXAMPLES)]
    Sensitivity(sensitivity_cmd::SensitivityArgs),
    /// Fit keys of a case to a measured force-displacement curve.
    #[command(after_help = study_cmd::FIT_EXAMPLES)]
    Fit(study_cmd::FitArgs),
    /// Run a case with the increment halved level after level and report what converges.
    #[command(after_help = study_cmd::CONVERGE_EXAMPLES)]
    Converge(study_cmd::ConvergeArgs),
    /// Judge one ensemble folder against a reference ensemble folder by the ensemble rule.
    #[command(after_help = accuracy_cmd::EXAMPLES)]
    Accuracy(accuracy_cmd::AccuracyArgs),
}

/// The case and the folder its outputs go to: the options of every command
/// that runs a case into a new folder.
#[derive(clap::Args)]
struct CaseOutput {
    /// The case file (TOML).
    case: PathBuf,
    /// Override a key of the case file, e.g. run.increment=0.02 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<String>,
    /// Output folder [default: out/<name>, or out/<name>-<command> for landscape and the studies].
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Replace the output folder if it exists and is not empty.
    #[arg(long)]
    force: bool,
}

impl CaseOutput {
    /// The `--set` overrides.
    fn overrides(&self) -> Result<Vec<Override>, Failure> {
        overrides(&self.set)
    }

    /// Claims `out` for the command's outputs (`OutputDir::claim`), before
    /// it runs.
    fn claim(&self, out: &Path) -> Result<OutputDir, Failure> {
        OutputDir::claim(out, self.force).map_err(Failure::output)
    }

    /// `--out`, or out/`name`.
    fn out_or(&self, name: &str) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| Path::new("out").join(name))
    }
}

/// The moment of a run a command looks at: one instant, or instants
/// through the whole run.
#[derive(clap::Args)]
#[group(required = true, multiple = false)]
struct Moment {
    /// Blade displacement u/d of the instant: that of the first increment
    /// at or beyond it, or of the last increment (0 to run.travel /
    /// blade.depth).
    #[arg(long, value_name = "U_OVER_D", allow_negative_numbers = true)]
    at: Option<f64>,
    /// Instead of one instant, take one at u/d = 0, E, 2E, … through the
    /// whole run (E in (0, run.travel / blade.depth]).
    #[arg(long, value_name = "E", allow_negative_numbers = true)]
    every: Option<f64>,
}

impl Moment {
    /// Checks --at or --every against the case's travel.
    fn check(&self, case: &Case, path: &Path) -> Result<(), Failure> {
        let checked = match (self.at, self.every) {
            (Some(at), _) => soilcut_io::check_landscape_at(case, "--at", at),
            (None, Some(every)) => soilcut_io::check_landscape_every(case, "--every", every),
            (None, None) => Err("give --at or --every".into()),
        };
        checked.map_err(|message| Failure::input(path, message))
    }
}

/// An error to print as `error: <path>: <message>` with its exit code.
struct Failure {
    code: u8,
    path: PathBuf,
    message: String,
}

impl Failure {
    fn input(path: &Path, message: impl ToString) -> Self {
        Failure {
            code: 2,
            path: path.to_path_buf(),
            message: message.to_string(),
        }
    }

    /// A case error that a command-line argument's key caused (`--set`,
    /// `--vary`: the error's key at, above or below the argument's, the
    /// last such argument) names that argument rather than the case file:
    /// the value to mend is there.
    fn argument(path: &Path, flag: &str, args: &[String], e: InputError) -> Self {
        let key = match &e {
            InputError::Key(k) => k.key.as_str(),
            _ => return Failure::input(path, e),
        };
        let related = |arg: &&String| {
            let given = arg.split_once('=').map_or(arg.as_str(), |(k, _)| k).trim();
            let within = |outer: &str, inner: &str| {
                inner == outer
                    || inner
                        .strip_prefix(outer)
                        .is_some_and(|r| r.starts_with('.'))
            };
            within(given, key) || within(key, given)
        };
        match args.iter().rev().find(related) {
            Some(arg) => Failure::input(&named(flag, arg), e),
            None => Failure::input(path, e),
        }
    }

    /// A `--set` argument that is not `key.path=value` (or whose value is
    /// beyond a number), named as the argument.
    fn set(arg: &str, e: InputError) -> Self {
        let message = match e {
            InputError::Override { message, .. } => message,
            e => e.to_string(),
        };
        Failure::input(&named("--set", arg), message)
    }

    fn output(e: OutputError) -> Self {
        Failure {
            // A folder refused before the run (occupied, unnamed, held by another
            // command, not makeable) is the user's to choose again; I/O is not.
            code: if matches!(e, OutputError::Io { .. }) {
                1
            } else {
                2
            },
            path: e.path().to_path_buf(),
            message: e.to_string(),
        }
    }

    fn picture(e: PictureError) -> Self {
        match e {
            PictureError::Read(e) => Failure::input(&e.path.clone(), e.message),
            PictureError::Draw(e) => Failure {
                code: 1,
                path: e.path,
                message: e.message,
            },
        }
    }
}

fn main() -> ExitCode {
    stop_cleanly_on_signals();
    let result = match Cli::parse().command {
        Command::Run {
            target,
            no_plots,
            quiet,
            ensemble: Some(members),
            jobs,
        } => ensemble_cmd::run_ensemble(&target, members, jobs, !no_plots, quiet),
        Command::Run {
            target,
            no_plots,
            quiet,
            ensemble: None,
            ..
        } => run(target, !no_plots, quiet),
        Command::Check { case, set } => check(&case, &set),
        Command::Analytic { case, set } => load(&case, &set).map(|loaded| {
            print!("{}", analytic_cmd::report(&loaded.case));
        }),
        Command::Plot { dir } => plot(&dir),
        Command::Compare {
            dirs,
            out,
            measured,
        } => compare(&dirs, measured.as_deref(), &out),
        Command::Landscape(args) => landscape_cmd::landscape(args),
        Command::Bounds(args) => bounds_cmd::bounds(args),
        Command::Sweep(args) => sweep_cmd::sweep(args),
        Command::Sensitivity(args) => sensitivity_cmd::sensitivity(args),
        Command::Fit(args) => study_cmd::fit(args),
        Command::Converge(args) => study_cmd::converge(args),
        Command::Accuracy(args) => accuracy_cmd::accuracy(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}: {}", f.path.display(), f.message);
            ExitCode::from(f.code)
        }
    }
}

/// Ctrl-C (SIGINT), SIGTERM and SIGHUP end the command as before, but
/// first remove its staging folders and lock files and let a folder
/// written in place (a sweep's) mark itself as stopped
/// (`soilcut_io::abandon_outputs`); the exit code is 128 + the signal's
/// number, as the shell reports a process the signal ended.
fn stop_cleanly_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    // Without the handler the signals end the process as they did.
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            let name = match signal {
                SIGINT => "SIGINT",
                SIGTERM => "SIGTERM",
                _ => "SIGHUP",
            };
            soilcut_io::abandon_outputs(name);
            eprintln!("error: stopped by {name}; unfinished outputs were removed");
            std::process::exit(128 + signal);
        }
    });
}

/// A command-line argument as the "path" of an error: `--set KEY=VALUE`,
/// its control characters escaped so that the message stays one line.
fn named(flag: &str, arg: &str) -> PathBuf {
    PathBuf::from(format!("{flag} {}", soilcut_io::visible(arg)))
}

/// The `--set` arguments as overrides; a malformed one is named as itself.
fn overrides(set: &[String]) -> Result<Vec<Override>, Failure> {
    set.iter()
        .map(|s| s.parse::<Override>().map_err(|e| Failure::set(s, e)))
        .collect()
}

fn load(path: &Path, set: &[String]) -> Result<LoadedCase, Failure> {
    let overrides = overrides(set)?;
    let loaded =
        read_case(path, &overrides).map_err(|e| Failure::argument(path, "--set", set, e))?;
    // Shown even with --quiet: the file will stop working as written.
    for notice in loaded.notices() {
        eprintln!("notice: {}: {notice}", path.display());
    }
    Ok(loaded)
}

fn check(path: &Path, set: &[String]) -> Result<(), Failure> {
    // Loading validates the case.
    let loaded = load(path, set)?;
    let case = &loaded.case;
    warn_accuracy(case);
    println!(
        "ok: {}: name {}, model {}, {}",
        path.display(),
        case.name,
        case.model.name(),
        extent(case)
    );
    println!("  {}", case.run.describe(case.blade.depth));
    if let Some(line) = loaded.tool_line() {
        println!("  {line}");
    }
    Ok(())
}

/// Bytes of `history.csv` an increment, about: 297 in Fig. 5, 254 in the
/// original model's case (`soilcut run cases/paper/fig5.toml`, its
/// history.csv's size over its 1750 rows).
const HISTORY_ROW_BYTES: f64 = 300.0;

/// Runs from this many increments on say so before they start.
const LONG_RUN: usize = 100_000;

/// The increments of a run and what they write: `1750 steps (history.csv
/// about 525 kB)`.
fn extent(case: &Case) -> String {
    let bytes = case.steps() as f64 * HISTORY_ROW_BYTES;
    let (size, unit) = [(1e9, "GB"), (1e6, "MB"), (1e3, "kB")]
        .into_iter()
        .find(|(scale, _)| bytes >= *scale)
        .map_or((bytes, "B"), |(scale, unit)| (bytes / scale, unit));
    format!(
        "{} steps (history.csv about {size:.0} {unit})",
        case.steps()
    )
}

/// A case that runs but is known to cost accuracy: shown even with
/// --quiet, which hides progress only (summary.json lists them too).
fn warn_accuracy(case: &Case) {
    for warning in case.accuracy_warnings() {
        eprintln!("warning: {warning}");
    }
}

fn run(target: CaseOutput, plots: bool, quiet: bool) -> Result<(), Failure> {
    let path = target.case.as_path();
    let loaded = load(path, &target.set)?;
    let case = &loaded.case;
    let out = target.out_or(&case.name);
    let claim = target.claim(&out)?;

    warn_accuracy(case);
    if case.steps() >= LONG_RUN && !quiet {
        eprintln!(
            "note: {}: {}; {}",
            path.display(),
            extent(case),
            case.run.describe(case.blade.depth)
        );
    }
    let bar = progress_bar(case.steps(), quiet);
    let RecordedRun {
        files,
        summary,
        stopped,
        ..
    } = record_case(&loaded, || bar.inc(1));
    bar.finish_and_clear();
    if let Some(e) = stopped {
        return Err(stopped_run(path, &out, summary.steps, e, || {
            write_run_into(claim, &files, plots).map(drop)
        }));
    }
    write_run_into(claim, &files, plots).map_err(Failure::output)?;
    if quiet {
        return Ok(());
    }
    println!(
        "{}: {} steps, max force_norm {:.4} at u/d = {:.3}, outputs in {}",
        case.name,
        summary.steps,
        summary.max_force_norm,
        summary.u_over_d_at_max,
        out.display()
    );
    Ok(())
}

/// The error of a run that stopped at `e` after `steps` increments, once
/// `write` has kept them (if any) in `out`, marked as stopped: the exit
/// code stays that of bad input.
fn stopped_run(
    path: &Path,
    out: &Path,
    steps: usize,
    e: soilcut_model::StepError,
    write: impl FnOnce() -> Result<(), OutputError>,
) -> Failure {
    if steps == 0 {
        return Failure::input(path, e);
    }
    match write() {
        Ok(()) => Failure::input(
            path,
            format!(
                "{e}; the run stopped there: its {steps} increments are kept in {} (summary.json's \"stopped\" says where and why)",
                out.display()
            ),
        ),
        Err(w) => Failure::output(w),
    }
}

/// A progress bar on stderr, only if it is a terminal and not `quiet`.
fn progress_bar(steps: usize, quiet: bool) -> ProgressBar {
    if quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(steps as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} increments, {elapsed} (eta {eta})")
    {
        bar.set_style(style);
    }
    bar
}

fn plot(dir: &Path) -> Result<(), Failure> {
    let written = soilcut_io::draw_run_dir(dir).map_err(Failure::picture)?;
    println!("{}: {} pictures drawn", dir.display(), written.len());
    Ok(())
}

fn compare(dirs: &[PathBuf], measured: Option<&Path>, out: &Path) -> Result<(), Failure> {
    soilcut_plot::Format::of(out).map_err(|e| Failure::input(out, e.message))?;
    soilcut_io::compare(dirs, measured, out).map_err(Failure::picture)?;
    println!("{}: {} runs compared", out.display(), dirs.len());
    Ok(())
}
