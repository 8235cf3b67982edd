//! `soilcut landscape`: the force of every candidate band at one moment of
//! a run (the landscape of minimum effort), or a map of such landscapes
//! through the run.

use crate::{load, CaseOutput, Failure, Moment};
use soilcut_io::{
    far_ties, landscape_at, landscape_csv, landscape_map, landscape_map_csv, LoadedCase,
    OutputError, MAP_BIN,
};
use soilcut_model::landscape::near_minimum;
use soilcut_model::{Candidate, Simulation};
use soilcut_plot::{draw_landscape, draw_landscape_map, Landscape, LandscapeMap, PlotError};
use std::path::Path;

pub const EXAMPLES: &str = "\
Examples:
  soilcut landscape cases/paper/table1-hs.toml --at 4
      writes out/table1-hs-landscape/{landscape.csv,landscape.png,case.resolved.toml}
  soilcut landscape cases/paper/table1-hs.toml --every 0.05
      writes out/table1-hs-landscape/{landscape_map.csv,landscape_map.png,case.resolved.toml}
  soilcut landscape cases/paper/fig5.toml --at 2.5 --set run.increment=0.02 --out out/fig5-fine-ls";

#[derive(clap::Args)]
pub struct LandscapeArgs {
    #[command(flatten)]
    target: CaseOutput,
    #[command(flatten)]
    moment: Moment,
}

pub fn landscape(args: LandscapeArgs) -> Result<(), Failure> {
    let target = &args.target;
    let path = target.case.as_path();
    let loaded = load(path, &target.set)?;
    let case = &loaded.case;
    args.moment.check(case, path)?;
    let out = target.out_or(&format!("{}-landscape", case.name));
    let claim = target.claim(&out)?;
    let mut sim = Simulation::start(case);
    let taken = match (args.moment.at, args.moment.every) {
        (Some(at), _) => one(&mut sim, &loaded, at, path)?,
        (None, every) => map(&mut sim, &loaded, every.unwrap_or(1.0), path)?,
    };
    claim
        .write_then(&taken.files, |staged| {
            let file = staged.join(taken.picture.name());
            taken.picture.draw(&file).map_err(|e| OutputError::Io {
                path: file,
                source: std::io::Error::other(e.message),
            })
        })
        .map_err(Failure::output)?;
    println!("{}; outputs in {}", taken.summary, out.display());
    Ok(())
}

/// What a landscape command writes and prints.
struct Taken {
    /// (name, contents) of the data files.
    files: Vec<(&'static str, String)>,
    picture: Picture,
    summary: String,
}

enum Picture {
    One(Landscape),
    Map(LandscapeMap),
}

impl Picture {
    fn name(&self) -> &'static str {
        match self {
            Picture::One(_) => "landscape.png",
            Picture::Map(_) => "landscape_map.png",
        }
    }

    fn draw(&self, file: &Path) -> Result<(), PlotError> {
        match self {
            Picture::One(p) => draw_landscape(p, file),
            Picture::Map(p) => draw_landscape_map(p, file),
        }
    }
}

/// One landscape, at the first increment at or beyond u/d = `at`.
fn one(sim: &mut Simulation, loaded: &LoadedCase, at: f64, path: &Path) -> Result<Taken, Failure> {
    let case = &loaded.case;
    let d = case.blade.depth;
    let candidates = landscape_at(sim, at).map_err(|e| Failure::input(path, e))?;
    let u = sim.blade_position();
    let picture = Landscape {
        title: format!("{}: every candidate band at u/d = {:.3}", case.title, u / d),
        points: candidates
            .iter()
            .map(|c| ((c.x_emergence - u) / d, c.force_norm))
            .collect(),
    };
    let files = vec![
        ("landscape.csv", landscape_csv(&candidates, u, d)),
        ("case.resolved.toml", loaded.resolved_toml()),
    ];
    Ok(Taken {
        files,
        picture: Picture::One(picture),
        summary: describe(&candidates, u, d),
    })
}

/// Landscapes at u/d = 0, `every`, 2 `every`, … (each at the first
/// increment at or beyond), binned by distance ahead of the tip.
fn map(
    sim: &mut Simulation,
    loaded: &LoadedCase,
    every: f64,
    path: &Path,
) -> Result<Taken, Failure> {
    let case = &loaded.case;
    let columns = landscape_map(sim, every).map_err(|e| Failure::input(path, e))?;
    let far_ties = far_ties(&columns);
    let summary = format!(
        "{} landscapes from u/d = 0 to {:.3}; in {far_ties} of them a band more than 1 d from the least came within 1 % of it",
        columns.len(),
        columns.last().map_or(0.0, |c| c.0)
    );
    let files = vec![
        ("landscape_map.csv", landscape_map_csv(&columns)),
        ("case.resolved.toml", loaded.resolved_toml()),
    ];
    let picture = LandscapeMap {
        title: format!(
            "{}: how near each band comes to the least force",
            case.title
        ),
        bin: MAP_BIN,
        columns,
    };
    Ok(Taken {
        files,
        picture: Picture::Map(picture),
        summary,
    })
}

/// One line: the least candidate and how many others come near it.
fn describe(candidates: &[Candidate], u: f64, d: f64) -> String {
    let Some(least) = candidates.iter().min_by(|a, b| a.force.total_cmp(&b.force)) else {
        return "no admissible candidate".into();
    };
    let near: Vec<f64> = candidates
        .iter()
        .filter(|c| c.force <= 1.01 * least.force)
        .map(|c| c.x_emergence)
        .collect();
    let span =
        near.iter().fold(f64::MIN, |a, &x| a.max(x)) - near.iter().fold(f64::MAX, |a, &x| a.min(x));
    format!(
        "u/d = {:.3}: {} candidates; least force_norm {:.4} at {:.2} d ahead (β = {:.2}°); {} within 0.1 %, {} within 1 % over {:.2} d",
        u / d,
        candidates.len(),
        least.force_norm,
        (least.x_emergence - u) / d,
        least.beta_deg,
        near_minimum(candidates, 0.001),
        near.len(),
        span / d
    )
}
