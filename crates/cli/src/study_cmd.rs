//! `soilcut sweep`, `soilcut fit`, `soilcut converge`: studies made of many
//! runs (`soilcut-study`). The outputs of a study appear together or not
//! at all: they are written into a hidden sibling folder renamed into
//! place when complete.

use super::{CaseOutput, Failure};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use soilcut_io::{check_output_dir, read_measured, write_output_dir_then, OutputError, Override};
use soilcut_study::converge::{Converge, Refine};
use soilcut_study::fit::{parse_bounds, Fit};
use soilcut_study::sample::{Sample, Vary};
use soilcut_study::sweep::Sweep;
use soilcut_study::{BaseCase, StudyError};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

pub const SWEEP_EXAMPLES: &str = "\
Examples:
  soilcut sweep cases/paper/table1-hs.toml --vary soil.friction.peak=30:45:7 --vary soil.d50=0.3,0.6
      7 x 2 runs; writes out/table1-hs-sweep/{sweep.csv,timing.csv,sweep-<key>.png}
  soilcut sweep cases/paper/table1-hs.toml --vary soil.friction.peak=30:45 --vary soil.peak_shear=1:3 \\
      --sample lhs:100 --seed 1 --jobs 2 --set run.increment=0.2
  soilcut sweep cases/paper/table1-hs.toml --vary choices.band_shear=full,by-position --keep-runs";

pub const FIT_EXAMPLES: &str = "\
Examples:
  soilcut fit cases/paper/table1-hs.toml --measured lab.csv \\
      --free soil.friction.initial,soil.friction.peak,soil.peak_shear
      writes out/table1-hs-fit/{fit.md,fit.csv,curves.csv,best.toml,fit.png}
  soilcut fit case.toml --measured lab.csv --width 50 --free soil.friction.peak \\
      --bounds soil.friction.peak=30:45 --starts 6 --seed 2";

pub const CONVERGE_EXAMPLES: &str = "\
Examples:
  soilcut converge cases/paper/fig5.toml --levels 4
      increments v0, v0/2, v0/4, v0/8; writes out/fig5-converge/{converge.md,converge.csv,converge.png,timing.csv}
  soilcut converge cases/paper/fig5.toml --levels 3 --set run.increment=0.08";

/// Options every study takes.
#[derive(Args)]
pub struct Common {
    #[command(flatten)]
    target: CaseOutput,
    /// Worker threads [default: one per core]. Results do not depend on it.
    #[arg(long, value_name = "N", default_value_t = 0)]
    jobs: usize,
    /// No progress bar (it is shown only when stderr is a terminal).
    #[arg(long)]
    quiet: bool,
}

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

#[derive(Args)]
pub struct FitArgs {
    #[command(flatten)]
    common: Common,
    /// The measured curve: CSV with the columns u,force (case units, force per unit width).
    #[arg(long, value_name = "FILE")]
    measured: PathBuf,
    /// The keys to fit, comma-separated; they start at the case's values.
    #[arg(long, value_name = "KEY,...", value_delimiter = ',', required = true)]
    free: Vec<String>,
    /// Bounds of a free key, replacing its default (repeatable).
    #[arg(long, value_name = "KEY=LO:HI")]
    bounds: Vec<String>,
    /// The measured force is the total over this blade width: divide by it.
    #[arg(long, value_name = "W")]
    width: Option<f64>,
    /// Nelder-Mead starts: the case's values and N − 1 seeded others.
    #[arg(long, value_name = "N", default_value_t = 4)]
    starts: usize,
    /// Seed of the other starts.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Nelder-Mead iterations per start.
    #[arg(long, value_name = "N", default_value_t = 100)]
    iterations: u64,
}

#[derive(Args)]
pub struct ConvergeArgs {
    #[command(flatten)]
    common: Common,
    /// Levels: level k halves the resolution k times (see --refine).
    #[arg(long, value_name = "N", default_value_t = 4)]
    levels: usize,
    /// What each level halves: both the increment and the node spacing, the increment alone, or the node spacing alone (which must stay a whole multiple of the increment).
    #[arg(long, value_enum, default_value_t = RefineArg::Both)]
    refine: RefineArg,
    /// Relative change between the two finest levels under which a quantity counts as converged.
    #[arg(long, default_value_t = 0.02)]
    tolerance: f64,
}

/// `--refine` of `soilcut converge`.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum RefineArg {
    Both,
    Increment,
    NodeSpacing,
}

impl From<RefineArg> for Refine {
    fn from(r: RefineArg) -> Self {
        match r {
            RefineArg::Both => Refine::Both,
            RefineArg::Increment => Refine::Increment,
            RefineArg::NodeSpacing => Refine::NodeSpacing,
        }
    }
}

fn study_failure(path: &Path, e: StudyError) -> Failure {
    match e {
        StudyError::Output(e) => Failure::output(e),
        StudyError::Plot(message) => Failure {
            code: 1,
            path: path.to_path_buf(),
            message,
        },
        e => Failure::input(path, e),
    }
}

impl Common {
    /// The base case, the output folder (checked to be free) and the case name.
    fn start(&self, study: &str) -> Result<(BaseCase, PathBuf), Failure> {
        let path = &self.target.case;
        let overrides = self
            .target
            .set
            .iter()
            .map(|s| s.parse::<Override>())
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| Failure::input(path, e))?;
        let base = BaseCase::read(path, overrides).map_err(|e| Failure::input(path, e))?;
        let name = base
            .load(&[])
            .map_err(|e| Failure::input(path, e))?
            .case
            .name;
        let out = self.target.out_or(&format!("{name}-{study}"));
        check_output_dir(&out, self.target.force).map_err(Failure::output)?;
        Ok((base, out))
    }

    /// A progress callback: a bar on stderr when it is a terminal.
    fn progress(&self, unit: &'static str) -> impl Fn(usize, usize) + Sync {
        let show = !self.quiet && std::io::stderr().is_terminal();
        let bar: OnceLock<ProgressBar> = OnceLock::new();
        move |done, total| {
            if !show {
                return;
            }
            let bar = bar.get_or_init(|| {
                let style = ProgressStyle::with_template(&format!(
                    "{{bar:40}} {{pos}}/{{len}} {unit} [{{elapsed_precise}}, eta {{eta}}]"
                ))
                .expect("a valid template");
                ProgressBar::new(total as u64).with_style(style)
            });
            bar.set_position(done as u64);
            if done == total {
                bar.finish_and_clear();
            }
        }
    }
}

/// Writes a study's outputs: `write` fills a hidden sibling folder, which
/// then replaces `out` (with `--force`) or becomes it
/// (`write_output_dir_then`); a failure of `write` is returned as it is.
fn write_study(
    out: &Path,
    force: bool,
    write: impl FnOnce(&Path) -> Result<(), StudyError>,
) -> Result<(), StudyError> {
    let mut failed = None;
    let placed = write_output_dir_then(out, &[], force, |dir| {
        write(dir).map_err(|e| {
            let source = std::io::Error::other(e.to_string());
            failed = Some(e);
            OutputError::Io {
                path: dir.to_path_buf(),
                source,
            }
        })
    });
    match failed {
        Some(e) => Err(e),
        None => placed.map_err(StudyError::Output),
    }
}

fn text_files(dir: &Path, files: &[(&str, String)]) -> Result<(), StudyError> {
    for (name, contents) in files {
        let path = dir.join(name);
        std::fs::write(&path, contents)
            .map_err(|source| StudyError::Output(OutputError::Io { path, source }))?;
    }
    Ok(())
}

pub fn sweep(args: SweepArgs) -> Result<(), Failure> {
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
    let mut sweep = Sweep {
        base,
        varies,
        sample,
        jobs: c.jobs,
        keep_runs: None,
    };
    let runs = sweep.points().map_err(fail)?.len();
    let mut result = None;
    write_study(&out, c.target.force, |dir| {
        if args.keep_runs {
            sweep.keep_runs = Some(dir.join("runs"));
        }
        let r = sweep.run(&c.progress("runs"))?;
        text_files(
            dir,
            &[("sweep.csv", r.csv()), ("timing.csv", r.timing_csv())],
        )?;
        r.draw(dir)?;
        result = Some(r);
        Ok(())
    })
    .map_err(fail)?;
    let failed = result.map_or(0, |r| r.failed());
    println!(
        "sweep: {runs} runs ({failed} failed), outputs in {}",
        out.display()
    );
    Ok(())
}

pub fn fit(args: FitArgs) -> Result<(), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let fail = |e| study_failure(path, e);
    let (base, out) = c.start("fit")?;
    let bounds = args
        .bounds
        .iter()
        .map(|b| parse_bounds(b))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    let mut measured =
        read_measured(&args.measured).map_err(|e| Failure::input(&args.measured, e))?;
    if let Some(w) = args.width {
        if !(w.is_finite() && w > 0.0) {
            return Err(Failure::input(
                path,
                format!("--width {w}: must be a finite number > 0"),
            ));
        }
        measured.iter_mut().for_each(|p| p.1 /= w);
    }
    let title = base
        .load(&[])
        .map_err(|e| Failure::input(path, e))?
        .case
        .title;
    let fit = Fit {
        base,
        free: args.free.clone(),
        bounds,
        measured,
        starts: args.starts,
        seed: args.seed,
        max_iters: args.iterations,
        jobs: c.jobs,
    };
    let mut summary = String::new();
    write_study(&out, c.target.force, |dir| {
        let r = fit.run(&c.progress("Nelder-Mead runs"))?;
        text_files(
            dir,
            &[
                ("fit.md", r.markdown(&title)),
                ("fit.csv", r.csv()),
                ("curves.csv", r.curves_csv()),
                ("best.toml", r.best_toml()),
            ],
        )?;
        r.draw(&dir.join("fit.png"))?;
        let best: Vec<String> = r
            .params
            .iter()
            .zip(&r.best)
            .map(|(p, x)| format!("{} = {x:.4}", p.key))
            .collect();
        summary = format!(
            "RMS error {:.4} (start {:.4}), {}",
            r.best_rms,
            r.start_rms,
            best.join(", ")
        );
        Ok(())
    })
    .map_err(fail)?;
    println!("fit: {summary}; outputs in {}", out.display());
    Ok(())
}

pub fn converge(args: ConvergeArgs) -> Result<(), Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let fail = |e| study_failure(path, e);
    let (base, out) = c.start("converge")?;
    let study = Converge {
        base,
        levels: args.levels,
        refine: args.refine.into(),
        tolerance: args.tolerance,
        jobs: c.jobs,
    };
    let mut verdicts = String::new();
    write_study(&out, c.target.force, |dir| {
        let r = study.run(&c.progress("levels"))?;
        text_files(
            dir,
            &[
                ("converge.csv", r.csv()),
                ("converge.md", r.markdown()),
                ("timing.csv", r.timing_csv()),
            ],
        )?;
        r.draw(&dir.join("converge.png"))?;
        let converged = r.converged().iter().filter(|v| **v == Some(true)).count();
        verdicts = format!(
            "{converged} of {} quantities converged",
            r.converged().len()
        );
        Ok(())
    })
    .map_err(fail)?;
    println!("converge: {}, outputs in {}", verdicts, out.display());
    Ok(())
}
