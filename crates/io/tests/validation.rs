//! docs/validation.md quotes soilcut's first force and its mean force over
//! the first depth of travel for every validation case (written by
//! validation/compare.py); this reruns the cases, shortened to one depth of
//! travel, and checks the quoted numbers to their printed precision.

use soilcut_io::read_case;
use soilcut_model::Simulation;
use std::path::Path;

const CUTS: [&str; 3] = ["vertical", "raked30", "deep"];

/// The cells of the first table row of `doc` after `from` that starts with `| name |`.
fn row<'a>(doc: &'a str, from: &str, name: &str) -> Vec<&'a str> {
    let start = doc.find(from).unwrap_or_else(|| panic!("no {from:?}"));
    let prefix = format!("| {name} |");
    let line = doc[start..]
        .lines()
        .find(|l| l.starts_with(&prefix))
        .unwrap_or_else(|| panic!("no row {name} after {from:?}"));
    line.trim_matches('|').split('|').map(str::trim).collect()
}

fn number(cell: &str) -> f64 {
    cell.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn the_validation_page_quotes_the_cases_numbers() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/validation.md")).unwrap();
    for name in CUTS {
        let file = root.join(format!("cases/validation/{name}.toml"));
        let mut case = read_case(&file, &[]).unwrap().case;
        case.run.travel = case.blade.depth;
        let history = Simulation::new(&case).unwrap().run_to_end(|_| {}).unwrap();
        let first = history[0].force_norm;
        let mean = history.iter().map(|r| r.force_norm).sum::<f64>() / history.len() as f64;
        let quoted_first = number(row(&doc, "first force: soilcut", name)[1]);
        let quoted_mean = number(row(&doc, "Mean force per unit of u/d", name)[1]);
        assert!(
            (first - quoted_first).abs() <= 0.0005,
            "{name}: first {first} vs {quoted_first}"
        );
        assert!(
            (mean - quoted_mean).abs() <= 0.005,
            "{name}: mean {mean} vs {quoted_mean}"
        );
    }
}
