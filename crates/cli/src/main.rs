//! `soilcut`: the command line. Argument parsing and calls into
//! `soilcut-io` and `soilcut-model` only.
//!
//! Exit codes: 0 success, 2 bad input (case file, `--set`, an occupied
//! output folder, a case without an admissible mechanism), 1 anything else
//! (I/O). Every error is one line on stderr: `error: <path>: <message>`.

use clap::{Parser, Subcommand};
use soilcut_io::{read_case, write_output_dir, LoadedCase, OutputError, Override, RunOutput};
use soilcut_model::{Simulation, Summary};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

const EXAMPLES: &str = "\
Examples:
  soilcut run cases/paper/original.toml
  soilcut run cases/paper/original.toml --set run.increment=0.02 --out out/fine
  soilcut check cases/paper/original.toml --set soil.friction.peak=36";

const RUN_EXAMPLES: &str = "\
Examples:
  soilcut run cases/paper/original.toml
      writes out/original/{history.csv,profile.csv,summary.json,case.resolved.toml}
  soilcut run cases/paper/original.toml --set run.increment=0.02
  soilcut run cases/paper/original.toml --set run.travel=20 --out out/short --force";

const CHECK_EXAMPLES: &str = "\
Examples:
  soilcut check cases/paper/original.toml
  soilcut check cases/paper/original.toml --set run.increment=0.02";

/// Soil cutting by sequential limit analysis (Jin & Hambleton).
#[derive(Parser)]
#[command(name = "soilcut", version, after_help = EXAMPLES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a case and write its outputs into a new folder.
    #[command(after_help = RUN_EXAMPLES)]
    Run {
        /// The case file (TOML).
        case: PathBuf,
        /// Output folder [default: out/<name>].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Override a key of the case file, e.g. run.increment=0.02 (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Replace the output folder if it exists and is not empty.
        #[arg(long)]
        force: bool,
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

    fn output(e: OutputError) -> Self {
        Failure {
            // An occupied or unnamed folder is the user's choice; I/O is not.
            code: if matches!(e, OutputError::Io { .. }) {
                1
            } else {
                2
            },
            path: e.path().to_path_buf(),
            message: e.to_string(),
        }
    }
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Run {
            case,
            out,
            set,
            force,
        } => run(&case, out, &set, force),
        Command::Check { case, set } => check(&case, &set),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}: {}", f.path.display(), f.message);
            ExitCode::from(f.code)
        }
    }
}

fn load(path: &Path, set: &[String]) -> Result<LoadedCase, Failure> {
    let overrides = set
        .iter()
        .map(|s| s.parse::<Override>())
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Failure::input(path, e))?;
    read_case(path, &overrides).map_err(|e| Failure::input(path, e))
}

fn check(path: &Path, set: &[String]) -> Result<(), Failure> {
    let case = load(path, set)?.case;
    println!(
        "ok: {}: name {}, model {}, {} steps",
        path.display(),
        case.name,
        case.model.name(),
        case.steps()
    );
    Ok(())
}

fn run(path: &Path, out: Option<PathBuf>, set: &[String], force: bool) -> Result<(), Failure> {
    let loaded = load(path, set)?;
    let case = &loaded.case;
    let out = out.unwrap_or_else(|| Path::new("out").join(&case.name));
    soilcut_io::check_output_dir(&out, force).map_err(Failure::output)?;

    let mut sim = Simulation::new(case).map_err(|e| Failure::input(path, e))?;
    let start = Instant::now();
    let history = sim
        .run_to_end(|_| {})
        .map_err(|e| Failure::input(path, e))?;
    let wall_time_s = start.elapsed().as_secs_f64();
    let summary = Summary::new(case, &history, sim.initial_mass());
    let output = RunOutput {
        loaded: &loaded,
        history: &history,
        profile: &sim.profile(),
        summary: &summary,
        candidate_evaluations: sim.evaluations(),
        wall_time_s,
    };
    write_output_dir(&out, &output.files(), force).map_err(Failure::output)?;
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
