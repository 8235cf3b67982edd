//! `soilcut sweep`, `soilcut fit`, `soilcut converge`: studies made of many
//! runs (`soilcut-study`). The outputs of a fit or a convergence study
//! appear together or not at all: they are written into a hidden staging
//! folder published when complete. A sweep writes its runs into its
//! folder as they finish (`sweep_cmd`).

use super::{CaseOutput, Failure};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use soilcut_io::{read_measured_curve, OutputDir, OutputError};
use soilcut_study::converge::ensembles::EnsembleConverge;
use soilcut_study::converge::{Converge, Refine};
use soilcut_study::fit::{measured_width, parse_bounds, Compare, Fit, FitResult, Method};
use soilcut_study::{BaseCase, StudyError};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

pub const FIT_EXAMPLES: &str = "\
Examples:
  soilcut fit cases/paper/table1-hs.toml --measured lab.csv \\
      --free soil.friction.initial,soil.friction.peak,soil.peak_shear
      writes out/table1-hs-fit/{fit.md,fit.csv,curves.csv,profiles.csv,search.csv,best.toml,
      fit.png,profiles.png,search.png}
  soilcut fit case.toml --measured lab.csv --width 50 --free soil.friction.peak \\
      --bounds soil.friction.peak=30:45 --objective smooth:2 --seed 2
  soilcut fit shallow.toml --measured shallow.csv --also deep.toml=deep.csv \\
      --free soil.friction.peak,soil.peak_shear --evaluations 2000";

pub const CONVERGE_EXAMPLES: &str = "\
Examples:
  soilcut converge cases/paper/fig5.toml --set run.increment=0.04 --levels 3
      increments v0, v0/2, v0/4 (d/500 to d/2000); writes out/fig5-converge/{converge.md,converge.csv,converge.png,timing.csv}
  soilcut converge cases/paper/fig5.toml --levels 3 --set run.increment=0.08
  soilcut converge cases/paper/table1-s.toml --levels 3 --set run.increment=0.08 --ensemble 7
      each level an ensemble of 7 perturbed runs, judged against the finest by the ensemble rule";

/// Options every study takes.
#[derive(Args)]
pub struct Common {
    #[command(flatten)]
    pub target: CaseOutput,
    /// Worker threads [default: one per core]. Results do not depend on it.
    #[arg(long, value_name = "N", default_value_t = 0, hide_default_value = true)]
    pub jobs: usize,
    /// No progress bar (it is shown only when stderr is a terminal); warnings are still printed.
    #[arg(long, short)]
    pub quiet: bool,
}

#[derive(Args)]
pub struct FitArgs {
    #[command(flatten)]
    common: Common,
    /// The measured curve of the case: CSV with the columns u,force and
    /// optionally weight (case units, force per unit width); `,` `;` or tab.
    #[arg(long, value_name = "FILE")]
    measured: PathBuf,
    /// Another test fitted at once: its case file and measured curve
    /// (repeatable). The free keys are shared; --set applies to every case.
    #[arg(long, value_name = "CASE=FILE")]
    also: Vec<String>,
    /// The keys to fit, comma-separated; they start at the case's values.
    #[arg(long, value_name = "KEY,...", value_delimiter = ',', required = true)]
    free: Vec<String>,
    /// Bounds of a free key, replacing its default (repeatable).
    #[arg(long, value_name = "KEY=LO:HI")]
    bounds: Vec<String>,
    /// The measured forces are totals over this blade width: divide by it.
    #[arg(long, value_name = "W")]
    width: Option<f64>,
    /// raw, smooth:W (both curves smoothed over a window W) or means:W
    /// (means over consecutive windows W); W in the case length unit.
    #[arg(long, value_name = "raw|smooth:W|means:W", default_value = "raw")]
    objective: String,
    /// The global search: de (differential evolution) or cmaes (CMA-ES
    /// with restarts).
    #[arg(long, value_name = "de|cmaes", default_value = "de")]
    method: String,
    /// Runs of the global search.
    #[arg(long, value_name = "N", default_value_t = soilcut_study::fit::EVALUATIONS)]
    evaluations: usize,
    /// Population of the search [default: max(16, 8 × free keys) for de,
    /// 4 + ⌊3 ln(free keys)⌋ for cmaes's first run, doubled at each restart].
    #[arg(long, value_name = "N", default_value_t = 0, hide_default_value = true)]
    population: usize,
    /// Seed of the search. Results do not depend on --jobs.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Nelder-Mead iterations of the polish of the best point.
    #[arg(long, value_name = "N", default_value_t = soilcut_study::fit::POLISH_ITERATIONS)]
    polish: u64,
    /// Grid of each key's profile across its bounds (0: no profiles, no intervals).
    #[arg(long, value_name = "N", default_value_t = soilcut_study::fit::PROFILE_GRID)]
    profile_points: usize,
}

#[derive(Args)]
pub struct ConvergeArgs {
    #[command(flatten)]
    common: Common,
    /// Levels: level k halves the resolution k times (see --refine).
    #[arg(long, value_name = "N", default_value_t = 4)]
    levels: usize,
    /// What each level halves on the case's own ground: the increment and the vertex spacing together, the increment alone, or the vertex spacing alone (the vertex ground only; the node grid's nodes are every increment).
    #[arg(long, value_enum, default_value_t = RefineArg::Both)]
    refine: RefineArg,
    /// Relative change between the two finest levels under which a quantity counts as converged.
    #[arg(long, default_value_t = 0.02)]
    tolerance: f64,
    /// Make every level an ensemble of N perturbed runs (as `soilcut run --ensemble N`) and
    /// judge each level against the finest by the ensemble rule (docs/model.md §12).
    #[arg(long, value_name = "N")]
    ensemble: Option<usize>,
}

/// `--refine` of `soilcut converge`.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum RefineArg {
    Both,
    Increment,
    VertexSpacing,
}

impl From<RefineArg> for Refine {
    fn from(r: RefineArg) -> Self {
        match r {
            RefineArg::Both => Refine::Both,
            RefineArg::Increment => Refine::Increment,
            RefineArg::VertexSpacing => Refine::VertexSpacing,
        }
    }
}

pub fn study_failure(path: &Path, e: StudyError) -> Failure {
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
    /// The base case and the output folder (`--out`, or out/NAME-`study`).
    pub fn start(&self, study: &str) -> Result<(BaseCase, PathBuf), Failure> {
        let path = &self.target.case;
        let overrides = self.target.overrides()?;
        let base = BaseCase::read(path, overrides)
            .map_err(|e| Failure::argument(path, "--set", &self.target.set, e))?;
        let name = base
            .load(&[])
            .map_err(|e| Failure::input(path, e))?
            .case
            .name
            .clone();
        Ok((base, self.target.out_or(&format!("{name}-{study}"))))
    }

    /// Claims `out` (`OutputDir::claim`), before the study runs.
    pub fn claim(&self, out: &Path) -> Result<OutputDir, Failure> {
        self.target.claim(out)
    }

    /// A progress callback: a bar on stderr when it is a terminal.
    pub fn progress(&self, unit: &'static str) -> impl Fn(usize, usize) + Sync {
        progress(self.quiet, unit)
    }
}

/// A progress callback over `unit`s (runs, levels, members): a bar on
/// stderr when it is a terminal and not `quiet`.
pub fn progress(quiet: bool, unit: &'static str) -> impl Fn(usize, usize) + Sync {
    let show = !quiet && std::io::stderr().is_terminal();
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

/// Writes a study's outputs: `write` fills the staging folder of `out`,
/// which is then published (`OutputDir::write_then`); a failure of
/// `write` is returned as it is.
pub fn write_study(
    out: OutputDir,
    write: impl FnOnce(&Path) -> Result<(), StudyError>,
) -> Result<(), StudyError> {
    let mut failed = None;
    let placed = out.write_then(&[], |dir| {
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
        None => placed.map(drop).map_err(StudyError::Output),
    }
}

pub fn text_files<N: AsRef<str>>(dir: &Path, files: &[(N, String)]) -> Result<(), StudyError> {
    for (name, contents) in files {
        let path = dir.join(name.as_ref());
        std::fs::write(&path, contents)
            .map_err(|source| StudyError::Output(OutputError::Io { path, source }))?;
    }
    Ok(())
}

/// A measured curve as a test of `base`, its forces divided by `w`.
fn test_of(name: &Path, base: BaseCase, w: f64) -> Result<soilcut_study::fit::Test, Failure> {
    let curve = read_measured_curve(name).map_err(|e| Failure::input(name, e))?;
    Ok(soilcut_study::fit::Test::per_width(
        name.display().to_string(),
        base,
        &curve.points,
        curve.weights,
        w,
    ))
}

/// The tests of a fit: `--measured` against the case, then every
/// `--also CASE=FILE`, each curve's forces divided by `width`.
fn tests_of(
    args: &FitArgs,
    base: BaseCase,
    width: f64,
) -> Result<Vec<soilcut_study::fit::Test>, Failure> {
    let c = &args.common;
    let path = &c.target.case;
    let mut tests = vec![test_of(&args.measured, base, width)?];
    for also in &args.also {
        let (case, measured) = also
            .split_once('=')
            .ok_or_else(|| Failure::input(path, format!("--also {also}: expected CASE=FILE")))?;
        let case = Path::new(case);
        let other =
            BaseCase::read(case, c.target.overrides()?).map_err(|e| Failure::input(case, e))?;
        tests.push(test_of(Path::new(measured), other, width)?);
    }
    Ok(tests)
}

/// The line `soilcut fit` ends with: the RMS errors and every key's best
/// value with its interval and verdict.
fn summary_of(r: &FitResult) -> String {
    let best: Vec<String> = r
        .params
        .iter()
        .enumerate()
        .map(|(j, p)| {
            format!(
                "{} = {:.4} [{}, {}]",
                p.key,
                r.best.x[j],
                r.interval_text(j),
                r.verdict(j)
            )
        })
        .collect();
    format!(
        "RMS error {:.4} (start {:.4}), {}",
        r.best.rms,
        r.start.rms,
        best.join(", ")
    )
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
    let compare: Compare = args.objective.parse().map_err(fail)?;
    let method: Method = args.method.parse().map_err(fail)?;
    let case = base
        .load(&[])
        .map_err(|e| Failure::input(path, e))?
        .case
        .into_case();
    let width = measured_width(args.width, &case, "--width").map_err(fail)?;
    let title = case.title;
    let tests = tests_of(&args, base, width)?;
    let fit = Fit {
        tests,
        free: args.free.clone(),
        bounds,
        compare,
        method,
        evaluations: args.evaluations,
        population: args.population,
        seed: args.seed,
        polish_iterations: args.polish,
        profile_grid: args.profile_points,
        jobs: c.jobs,
    };
    // The free keys and their bounds, before the folder is claimed.
    fit.params().map_err(|e| match e {
        StudyError::Key(e) => Failure::argument(path, "--free", &args.free, e),
        e => fail(e),
    })?;
    let mut summary = String::new();
    write_study(c.claim(&out)?, |dir| {
        let r = fit.run(&c.progress("runs"))?;
        text_files(dir, &r.files(&title))?;
        r.draw(dir)?;
        summary = summary_of(&r);
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
    if let Some(members) = args.ensemble {
        let study = EnsembleConverge {
            base,
            levels: args.levels,
            refine: args.refine.into(),
            members,
            jobs: c.jobs,
        };
        let claim = c.claim(&out)?;
        return converge_ensembles(&study, c, claim, &out).map_err(fail);
    }
    let study = Converge {
        base,
        levels: args.levels,
        refine: args.refine.into(),
        tolerance: args.tolerance,
        jobs: c.jobs,
    };
    let mut verdicts = String::new();
    write_study(c.claim(&out)?, |dir| {
        let r = study.run(&c.progress("levels"))?;
        converge_files(dir, r.csv(), r.markdown(), r.timing_csv())?;
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

/// The files of `soilcut converge`, with or without `--ensemble`.
fn converge_files(
    dir: &Path,
    csv: String,
    markdown: String,
    timing: String,
) -> Result<(), StudyError> {
    text_files(
        dir,
        &[
            ("converge.csv", csv),
            ("converge.md", markdown),
            ("timing.csv", timing),
        ],
    )
}

/// `soilcut converge --ensemble N`: the levels' ensembles and their verdicts.
fn converge_ensembles(
    study: &EnsembleConverge,
    c: &Common,
    claim: OutputDir,
    out: &Path,
) -> Result<(), StudyError> {
    let mut verdicts = String::new();
    write_study(claim, |dir| {
        let r = study.run(&c.progress("members"))?;
        converge_files(dir, r.csv(), r.markdown(), r.timing_csv())?;
        let accurate: Vec<String> = r
            .agreements()
            .iter()
            .zip(&r.levels)
            .map(|(a, l)| {
                format!(
                    "level {} {}",
                    l.level,
                    if a.accurate() { "yes" } else { "no" }
                )
            })
            .collect();
        verdicts = format!("accurate against the finest level: {}", accurate.join(", "));
        Ok(())
    })?;
    println!("converge: {verdicts}; outputs in {}", out.display());
    Ok(())
}
