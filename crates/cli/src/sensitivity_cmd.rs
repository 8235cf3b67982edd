//! `soilcut sensitivity`: Morris screening or Sobol indices of a case's
//! outputs over ranges of its keys (`soilcut-study`'s `sensitivity`). Its
//! files appear together, once every run has finished; a study one of
//! whose runs failed writes samples.csv and a summary saying so, no
//! indices, and exits 2.

use super::Failure;
use crate::study_cmd::{study_failure, text_files, write_study, Common};
use clap::Args;
use soilcut_study::sensitivity::{
    Function, Method, Model, Range, Sensitivity, DEFAULT_LEVELS, DEFAULT_MEMBERS,
};
use soilcut_study::StudyError;
use std::time::Instant;

pub const EXAMPLES: &str = "\
Examples:
  soilcut sensitivity cases/paper/fig5.toml --method morris --samples 10 \\
      --vary soil.friction.peak=35:45 --vary soil.peak_shear=1:3 --vary blade.wall_friction=5:15
      writes out/fig5-sensitivity/{indices.csv,samples.csv,tornado.csv,summary.json,sensitivity.md,
      timing.csv,indices.png,morris.png,tornado.png}
  soilcut sensitivity cases/paper/fig5.toml --method sobol --samples 256 --members 3 --dummy \\
      --vary soil.friction.peak=35:45 --vary soil.peak_shear=1:3 --seed 2 --jobs 2";

#[derive(Args)]
pub struct SensitivityArgs {
    #[command(flatten)]
    common: Common,
    /// A key and its range lo:hi, lo < hi (repeatable).
    #[arg(long, value_name = "KEY=LO:HI", required = true)]
    vary: Vec<String>,
    /// morris (screening: μ*, σ of elementary effects) or sobol (first-order and total indices).
    #[arg(long, value_enum)]
    method: MethodArg,
    /// Morris: trajectories r (20 when not given); Sobol: base points N, a power of 2 (512 when
    /// not given); the runs are r (keys + 1) or N (keys + 2) (N (2 keys + 2) with
    /// --second-order), and the tornado's 2 keys + 1, times --members.
    #[arg(long, value_name = "N")]
    samples: Option<usize>,
    /// Sobol: also the second-order index S2 of every pair of inputs, in indices2.csv (N (2 keys
    /// + 2) runs instead of N (keys + 2)).
    #[arg(long)]
    second_order: bool,
    /// Levels p of Morris's grid (even).
    #[arg(long, value_name = "P", default_value_t = DEFAULT_LEVELS)]
    levels: usize,
    /// Run each design point, and the tornado's, as an ensemble of K perturbed members (the
    /// ensembles' rule): indices of the ensemble mean, and each output's chaos share (6 when
    /// not given, the least K that keeps the chaos within 5 % of Fig. 5's variance; 1 for a
    /// test function).
    #[arg(long, value_name = "K")]
    members: Option<usize>,
    /// Seed of the design and the bootstrap. Results do not depend on --jobs.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Add an input `dummy` that no run reads: its indices show the estimators' noise floor.
    #[arg(long)]
    dummy: bool,
    /// Evaluate a test function (ishigami, linear) of the varied inputs instead of the case.
    #[arg(long, hide = true)]
    function: Option<String>,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum MethodArg {
    Morris,
    Sobol,
}

/// The study of `args`, checked before anything is written.
fn prepare(args: &SensitivityArgs) -> Result<(Sensitivity, std::path::PathBuf), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let fail = |e| study_failure(path, e);
    let (base, out) = c.start("sensitivity")?;
    let ranges = args
        .vary
        .iter()
        .map(|v| Range::parse(v))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let (model, members) = match &args.function {
        Some(name) => (Model::Function(Function::parse(name).map_err(fail)?), 1),
        None => (Model::Case(base), DEFAULT_MEMBERS),
    };
    let name = match args.method {
        MethodArg::Morris => "morris",
        MethodArg::Sobol => "sobol",
    };
    let method = Method::named(name, args.levels, args.second_order).map_err(fail)?;
    let study = Sensitivity {
        model,
        ranges,
        method,
        samples: args.samples.unwrap_or(method.default_samples()),
        members: args.members.unwrap_or(members),
        dummy: args.dummy,
        seed: args.seed,
        jobs: c.jobs,
    };
    study.check().map_err(|e| match e {
        StudyError::Key(e) => Failure::argument(path, "--vary", &args.vary, e),
        e => fail(e),
    })?;
    Ok((study, out))
}

pub fn sensitivity(args: SensitivityArgs) -> Result<(), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let (study, out) = prepare(&args)?;
    let start = Instant::now();
    let mut result = None;
    write_study(c.claim(&out)?, |dir| {
        let r = study.run(&c.progress("runs"))?;
        text_files(dir, &r.files())?;
        r.draw(dir)?;
        result = Some(r);
        Ok(())
    })
    .map_err(|e| study_failure(path, e))?;
    let Some(r) = result else {
        return Ok(());
    };
    if let Err(e) = &r.analysis {
        return Err(Failure::input(
            &out,
            format!(
                "{e}; no indices: samples.csv has every run, summary.json says it is not complete"
            ),
        ));
    }
    if !c.quiet {
        let seconds = start.elapsed().as_secs_f64();
        println!(
            "sensitivity: {} runs in {seconds:.1} s ({:.1} runs/s), outputs in {}",
            r.runs.len() + r.tornado_runs.len(),
            (r.runs.len() + r.tornado_runs.len()) as f64 / seconds,
            out.display()
        );
    }
    Ok(())
}
