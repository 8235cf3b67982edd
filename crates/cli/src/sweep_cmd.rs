//! `soilcut sweep`: a case run for many values of its keys. Its folder is
//! published when the sweep starts and holds each run as it finishes
//! (`sweep_folder`), so that a sweep stopped partway keeps its finished
//! runs, its `summary.json` saying so.

use super::Failure;
use crate::study_cmd::{study_failure, Common};
use crate::sweep_folder::SweepFolder;
use clap::Args;
use soilcut_study::sample::{Sample, Vary};
use soilcut_study::sweep::Sweep;
use soilcut_study::StudyError;

pub const SWEEP_EXAMPLES: &str = "\
Examples:
  soilcut sweep cases/paper/table1-hs.toml --vary soil.friction.peak=30:45:7 --vary soil.d50=0.3,0.6
      7 x 2 runs; writes out/table1-hs-sweep/{sweep.csv,summary.json,timing.csv,sweep-<key>.png}
  soilcut sweep cases/paper/table1-hs.toml --vary soil.friction.peak=30:45 --vary soil.peak_shear=1:3 \\
      --sample lhs:100 --seed 1 --jobs 2 --set run.increment=0.2
  soilcut sweep cases/paper/table1-hs.toml --vary choices.band_shear=full,by-position --keep-runs";

#[derive(Args)]
pub struct SweepArgs {
    #[command(flatten)]
    common: Common,
    /// A key and its values: lo:hi:n (grid), lo:hi (sampled) or a,b,c (repeatable).
    #[arg(long, value_name = "KEY=SPEC", required = true)]
    vary: Vec<String>,
    /// grid (every combination) or lhs:N (a Latin-hypercube sample of N runs).
    #[arg(long, value_name = "grid|lhs:N", default_value = "grid")]
    sample: String,
    /// Seed of the Latin-hypercube sample.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Also write each run's usual output folder, runs/run-NNNN.
    #[arg(long)]
    keep_runs: bool,
}

/// The sweep of `args`, its keys and values checked (every run would fail
/// alike otherwise) before anything is written; the number of runs.
fn prepare(args: &SweepArgs) -> Result<(Sweep, usize, std::path::PathBuf), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let fail = |e| study_failure(path, e);
    let (base, out) = c.start("sweep")?;
    let varies = args
        .vary
        .iter()
        .map(|v| v.parse::<Vary>())
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let sample = Sample::parse(&args.sample, args.seed).map_err(fail)?;
    let sweep = Sweep {
        base,
        varies,
        sample,
        jobs: c.jobs,
        keep_runs: None,
    };
    let runs = sweep
        .points()
        .map_err(|e| match e {
            StudyError::Key(e) => Failure::argument(path, "--vary", &args.vary, e),
            e => fail(e),
        })?
        .len();
    Ok((sweep, runs, out))
}

pub fn sweep(args: SweepArgs) -> Result<(), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let fail = |e| study_failure(path, e);
    let (mut sweep, runs, out) = prepare(&args)?;
    let keys: Vec<String> = sweep.varies.iter().map(|v| v.key.clone()).collect();
    let folder = SweepFolder::start(c.claim(&out)?, keys, runs).map_err(Failure::output)?;
    if args.keep_runs {
        sweep.keep_runs = Some(out.join("runs"));
    }
    let result = match sweep.run_each(&c.progress("runs"), &|row| folder.add(row)) {
        Ok(result) => result,
        Err(e) => {
            folder.stop(&e.to_string());
            return Err(fail(e));
        }
    };
    folder.finish(&result).map_err(fail)?;
    let first_error = result.rows.iter().find_map(|row| row.outcome.clone().err());
    let failed = result.failed();
    println!(
        "sweep: {runs} runs ({failed} failed), outputs in {}",
        out.display()
    );
    match first_error {
        // Nothing to study: say so by the exit code too.
        Some(first) if failed == runs => Err(Failure::input(
            &out,
            format!("every run failed; the first: {first}"),
        )),
        _ => Ok(()),
    }
}
