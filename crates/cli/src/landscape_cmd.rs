//! `soilcut landscape`: the force of every candidate band at one moment of
//! a run (the landscape of minimum effort).

use crate::{load, Failure};
use soilcut_io::{landscape_csv, write_output_dir_then, OutputError};
use soilcut_model::landscape::near_minimum;
use soilcut_model::{Candidate, Simulation};
use soilcut_plot::{draw_landscape, Landscape};
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "\
Examples:
  soilcut landscape cases/paper/table1-hs.toml --at 4
      writes out/table1-hs-landscape/{landscape.csv,landscape.png,case.resolved.toml}
  soilcut landscape cases/paper/fig5.toml --at 2.5 --set run.increment=0.02 --out out/fig5-fine-ls";

#[derive(clap::Args)]
pub struct LandscapeArgs {
    /// The case file (TOML).
    case: PathBuf,
    /// Blade displacement u/d at which to take the landscape: that of the
    /// first increment at or beyond it, or of the last increment (0 to
    /// run.travel / blade.depth).
    #[arg(long, value_name = "U_OVER_D", allow_negative_numbers = true)]
    at: f64,
    /// Override a key of the case file, e.g. run.increment=0.02 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<String>,
    /// Output folder [default: out/<name>-landscape].
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Replace the output folder if it exists and is not empty.
    #[arg(long)]
    force: bool,
}

pub fn landscape(args: LandscapeArgs) -> Result<(), Failure> {
    let path = args.case.as_path();
    let loaded = load(path, &args.set)?;
    let case = &loaded.case;
    let d = case.blade.depth;
    let last = case.run.travel / d;
    if !(args.at.is_finite() && (0.0..=last).contains(&args.at)) {
        let message = format!(
            "--at must be a number from 0 to run.travel / blade.depth = {last} (got {})",
            args.at
        );
        return Err(Failure::input(path, message));
    }
    let out = args
        .out
        .unwrap_or_else(|| Path::new("out").join(format!("{}-landscape", case.name)));
    soilcut_io::check_output_dir(&out, args.force).map_err(Failure::output)?;
    let mut sim = Simulation::new(case).map_err(|e| Failure::input(path, e))?;
    // Increments before the one evaluated at u ≥ at d (u = steps × v0).
    let before = ((args.at * d / case.run.increment) - 1e-9).ceil().max(0.0) as usize;
    while sim.steps_done() < before.min(case.steps() - 1) {
        sim.step().map_err(|e| Failure::input(path, e))?;
    }
    let candidates = sim.landscape().map_err(|e| Failure::input(path, e))?;
    let u = sim.blade_position();
    let picture = Landscape {
        title: format!("{}: every candidate band at u/d = {:.3}", case.title, u / d),
        points: candidates
            .iter()
            .map(|c| ((c.x_emergence - u) / d, c.force_norm))
            .collect(),
    };
    let files = [
        ("landscape.csv", landscape_csv(&candidates, u, d)),
        ("case.resolved.toml", loaded.resolved_toml()),
    ];
    write_output_dir_then(&out, &files, args.force, |staged| {
        let png = staged.join("landscape.png");
        draw_landscape(&picture, &png).map_err(|e| OutputError::Io {
            path: png,
            source: std::io::Error::other(e.message),
        })
    })
    .map_err(Failure::output)?;
    println!("{}", describe(&candidates, u, d, &out));
    Ok(())
}

/// One line: the least candidate and how many others come near it.
fn describe(candidates: &[Candidate], u: f64, d: f64, out: &Path) -> String {
    let Some(least) = candidates.iter().min_by(|a, b| a.force.total_cmp(&b.force)) else {
        return format!("no admissible candidate; outputs in {}", out.display());
    };
    let near: Vec<f64> = candidates
        .iter()
        .filter(|c| c.force <= 1.01 * least.force)
        .map(|c| c.x_emergence)
        .collect();
    let span =
        near.iter().fold(f64::MIN, |a, &x| a.max(x)) - near.iter().fold(f64::MAX, |a, &x| a.min(x));
    format!(
        "u/d = {:.3}: {} candidates; least force_norm {:.4} at {:.2} d ahead (β = {:.2}°); {} within 0.1 %, {} within 1 % over {:.2} d; outputs in {}",
        u / d,
        candidates.len(),
        least.force_norm,
        (least.x_emergence - u) / d,
        least.beta_deg,
        near_minimum(candidates, 0.001),
        near.len(),
        span / d,
        out.display()
    )
}
