//! `soilcut accuracy SCHEME REFERENCE`: one ensemble folder judged against
//! another by the ensemble rule (docs/model.md §12), from their files.

use super::Failure;
use soilcut_study::accuracy::{Agreement, Spread, Verdict};
use soilcut_study::ensemble::{accuracy_rule, RecordedSpread};
use std::path::PathBuf;

pub const EXAMPLES: &str = "\
Examples:
  soilcut run cases/paper/table1-s.toml --ensemble 7 --set run.increment=0.08 --out out/s-d250
  soilcut run cases/paper/table1-s.toml --ensemble 7 --set run.increment=0.01 --out out/s-d2000
  soilcut accuracy out/s-d250 out/s-d2000
      every unit-window ensemble mean against the reference's, with its tolerance";

/// The arguments of `soilcut accuracy`.
#[derive(clap::Args)]
pub struct AccuracyArgs {
    /// The ensemble folder to judge (written by `soilcut run --ensemble`).
    scheme: PathBuf,
    /// The reference ensemble folder (the reference grid at a fine increment).
    reference: PathBuf,
    /// Print one JSON object instead of the table, with every row of it.
    #[arg(long)]
    json: bool,
}

/// Prints the verdict of every window and of the whole run.
pub fn accuracy(args: AccuracyArgs) -> Result<(), Failure> {
    let read = |dir: &PathBuf| {
        RecordedSpread::read(dir).map_err(|e| Failure::input(&e.path.clone(), e.message))
    };
    let (scheme, reference) = (read(&args.scheme)?, read(&args.reference)?);
    if scheme.windows.len() != reference.windows.len() {
        return Err(Failure::input(
            &args.scheme,
            format!(
                "{} unit windows against the reference's {}: the two ensembles must run the same travel",
                scheme.windows.len(),
                reference.windows.len()
            ),
        ));
    }
    let a = scheme.agreement(&reference);
    if args.json {
        println!("{}", json(&scheme, &reference, &a));
    } else {
        print_table(&scheme, &reference, &a);
    }
    Ok(())
}

/// The agreement as one JSON object, every row of the table in it: each
/// window's u/d range, both ensembles' mean and sd, the deviation, the
/// tolerance and the verdict (numbers that are not finite are null).
fn json(scheme: &RecordedSpread, reference: &RecordedSpread, a: &Agreement) -> String {
    let row = |s: &Spread, r: &Spread, v: &Verdict| {
        serde_json::json!({
            "scheme": {"mean": s.mean, "std": s.std},
            "reference": {"mean": r.mean, "std": r.std},
            "deviation": v.deviation,
            "tolerance": v.tolerance,
            "within": v.ok(),
        })
    };
    let windows: Vec<serde_json::Value> = a
        .windows
        .iter()
        .enumerate()
        .map(|(w, v)| {
            let mut window = row(&scheme.windows[w], &reference.windows[w], v);
            window["u_over_d_from"] = w.into();
            window["u_over_d_to"] = (w + 1).into();
            window
        })
        .collect();
    serde_json::json!({
        "accurate": a.accurate(),
        "worst_ratio": a.worst_ratio(),
        "whole_run": row(&scheme.whole_run, &reference.whole_run, &a.whole_run),
        "windows": windows,
        "rule": accuracy_rule(),
    })
    .to_string()
}

/// The table: a row a window and one for the whole run, then the verdict.
fn print_table(scheme: &RecordedSpread, reference: &RecordedSpread, a: &Agreement) {
    println!("{}\nrule: {}\n", scheme.title, accuracy_rule());
    println!(
        "window   scheme (mean ± sd)   reference (mean ± sd)   deviation   tolerance   within"
    );
    let rows = a
        .windows
        .iter()
        .enumerate()
        .map(|(w, v)| {
            (
                format!("{w}-{}", w + 1),
                &scheme.windows[w],
                &reference.windows[w],
                v,
            )
        })
        .chain([(
            "whole".to_string(),
            &scheme.whole_run,
            &reference.whole_run,
            &a.whole_run,
        )]);
    for (name, s, r, v) in rows {
        println!(
            "{name:<8} {:>9.4} ± {:<8.4} {:>11.4} ± {:<8.4} {:>+9.2} % {:>9.2} %   {}",
            s.mean,
            s.std,
            r.mean,
            r.std,
            v.deviation * 100.0,
            v.tolerance * 100.0,
            if v.ok() { "yes" } else { "no" }
        );
    }
    println!("\naccurate: {}", if a.accurate() { "yes" } else { "no" });
}
