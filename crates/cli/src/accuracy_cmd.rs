//! `soilcut accuracy SCHEME REFERENCE`: one ensemble folder judged against
//! another by the ensemble rule (docs/model.md §12), from their files.

use super::Failure;
use soilcut_study::accuracy::{Agreement, Verdict};
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
    /// Print one JSON object instead of the table.
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
        println!("{}", json(&a));
    } else {
        print_table(&scheme, &reference, &a);
    }
    Ok(())
}

/// The agreement as one JSON object.
fn json(a: &Agreement) -> String {
    let verdict = |v: &Verdict| {
        format!(
            "{{\"deviation\": {}, \"tolerance\": {}, \"within\": {}}}",
            v.deviation,
            v.tolerance,
            v.ok()
        )
    };
    let windows: Vec<String> = a.windows.iter().map(verdict).collect();
    format!(
        "{{\"accurate\": {}, \"worst_ratio\": {}, \"whole_run\": {}, \"windows\": [{}]}}",
        a.accurate(),
        a.worst_ratio(),
        verdict(&a.whole_run),
        windows.join(", ")
    )
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
