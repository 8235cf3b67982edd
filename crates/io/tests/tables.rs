//! A run's numbers as front ends hand them out (`RecordedRun::tables`) are
//! its files' numbers bit for bit, and read back from the files they are
//! the same values: Python's arrays and `soilcut run`'s files cannot
//! disagree.

use soilcut_io::{parse_case, record_files, Columns, RunTables};
use soilcut_model::Simulation;

const ORIGINAL: &str = include_str!("../testdata/original.toml");

fn bits(c: &Columns) -> Vec<(String, Vec<u64>)> {
    c.iter()
        .map(|(n, v)| (n.to_string(), v.iter().map(|x| x.to_bits()).collect()))
        .collect()
}

#[test]
fn tables_are_the_files_numbers() {
    let set = ["run.travel=6".parse().unwrap()];
    let loaded = parse_case(ORIGINAL, &set).unwrap();
    let mut sim = Simulation::new(&loaded.case).unwrap();
    let run = record_files(&loaded, &mut sim, || {}).unwrap();
    let t = &run.tables;
    assert_eq!(t.history.len(), run.history.len());
    assert!(t.history.len() > 10 && !t.profile.is_empty() && !t.frames.is_empty());
    for (i, r) in run.history.iter().enumerate() {
        assert_eq!(t.history.column("force").unwrap()[i], r.force);
        assert_eq!(t.history.column("step").unwrap()[i], r.step as f64);
    }
    let back = RunTables::from_files(&run.files).unwrap();
    assert_eq!(bits(&back.history), bits(&t.history));
    assert_eq!(bits(&back.profile), bits(&t.profile));
    assert_eq!(bits(&back.frames), bits(&t.frames));
    assert_eq!(
        back.summary, t.summary,
        "summary.json reads back to the value"
    );
    let file = |name: &str| &run.files.iter().find(|(n, _)| *n == name).unwrap().1;
    assert_eq!(t.history.csv(), *file("history.csv"));
    assert_eq!(t.frames.csv(), *file("frames.csv"));
    assert_eq!(t.summary["steps"], run.history.len());
}

#[test]
fn missing_or_bad_files_are_named() {
    let e = RunTables::from_files::<&str>(&[]).unwrap_err();
    assert_eq!(e.path.to_str(), Some("summary.json"), "{e}");
    let files = [
        ("summary.json", "{}".to_string()),
        ("history.csv", "step,u\n1,x\n".to_string()),
    ];
    let e = RunTables::from_files(&files).unwrap_err();
    assert_eq!(e.path.to_str(), Some("history.csv"), "{e}");
}
