//! Tools that reduce to today's blade (docs/model.md §21, (M55)): a straight
//! profile translating at a constant rotation gives the history of the blade
//! it is, bit for bit.

use soilcut_io::{parse_case, read_case, record_case};
use std::path::Path;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

fn shipped(name: &str) -> String {
    std::fs::read_to_string(root().join("cases").join(name)).unwrap()
}

/// `history.csv` of a case's text.
fn history(text: &str) -> String {
    let loaded = parse_case(text, &[]).unwrap_or_else(|e| panic!("{e}\n{text}"));
    let run = record_case(&loaded, || {});
    assert!(run.stopped.is_none());
    let (_, csv) = run.files.iter().find(|(n, _)| *n == "history.csv").unwrap();
    csv.clone()
}

/// `text` with `from` replaced by `to`, which must be there once.
fn edited(text: &str, edits: &[(&str, &str)]) -> String {
    let mut text = text.to_string();
    for (from, to) in edits {
        assert_eq!(text.matches(from).count(), 1, "{from}");
        text = text.replacen(from, to, 1);
    }
    text
}

#[test]
fn the_straight_profile_case_is_fig5_bit_for_bit() {
    let tool = shipped("tools/straight-profile.toml");
    let blade = shipped("paper/fig5.toml");
    // Every column the two share: today, all of them.
    assert_eq!(history(&tool), history(&blade));
    let loaded = read_case(&root().join("cases/tools/straight-profile.toml"), &[]).unwrap();
    let again = parse_case(&loaded.resolved_toml(), &[]).unwrap();
    assert_eq!(again.case, loaded.case, "case.resolved.toml reads back");
    assert!(loaded.resolved_toml().contains("[tool]"));
}

#[test]
fn a_straight_profile_on_a_path_is_the_depth_path_and_a_raked_one_the_rake() {
    let deepening = shipped("tools/deepening.toml");
    let as_tool = edited(
        &deepening,
        &[
            ("depth_path = [[0.0, 10.0], [40.0, 20.0]]", ""),
            ("travel = 100.0", ""),
            (
                "[soil]",
                "[tool]\nshape = \"straight\"\nheight = 70.0\n\
                 motion = [[0.0, 0.0, -10.0, 0.0], [40.0, 40.0, -20.0, 0.0], [100.0, 100.0, -20.0, 0.0]]\n\n[soil]",
            ),
        ],
    );
    assert_eq!(history(&as_tool), history(&deepening));
    let inclined = shipped("tools/inclined.toml");
    // The pivot 50 above the edge: a vertical profile turned 30°
    // counter-clockwise about it leans back to α = 60°, its edge at
    // (50 sin 30°, 50 − 50 cos 30°) from the pivot's place.
    let (dx, dy) = (
        50.0 * 30f64.to_radians().sin(),
        50.0 * 30f64.to_radians().cos(),
    );
    let motion = format!(
        "motion = [[0.0, {}, {}, 30.0], [100.0, {}, {}, 30.0]]",
        -dx,
        dy - 20.0,
        100.0 - dx,
        dy - 20.0
    );
    let rotated = edited(
        &inclined,
        &[
            ("rake = 60.0           # α, degrees from the horizontal (90 = vertical)", ""),
            ("travel = 100.0     # 5 d", ""),
            (
                "[soil]",
                &format!(
                    "[tool]\nshape = \"straight\"\nheight = 70.0\npivot = [0.0, 50.0]\n{motion}\n\n[soil]"
                ),
            ),
        ],
    );
    let loaded = parse_case(&rotated, &[]).unwrap();
    assert!(
        (loaded.case.blade.rake - 60.0).abs() < 1e-12,
        "{}",
        loaded.case.blade.rake
    );
    // A straight shape's own rake is exact.
    let raked = edited(
        &inclined,
        &[
            (
                "rake = 60.0           # α, degrees from the horizontal (90 = vertical)",
                "",
            ),
            ("travel = 100.0     # 5 d", ""),
            (
                "[soil]",
                "[tool]\nshape = \"straight\"\nrake = 60.0\nheight = 70.0\n\
                 motion = [[0.0, 0.0, -20.0, 0.0], [100.0, 100.0, -20.0, 0.0]]\n\n[soil]",
            ),
        ],
    );
    assert_eq!(history(&raked), history(&inclined));
}

#[test]
fn a_run_travel_shortens_a_tool_s_motion() {
    let tool = shipped("tools/straight-profile.toml");
    let blade = shipped("paper/fig5.toml");
    let short = ["run.travel=10".parse().unwrap()];
    let a = parse_case(&tool, &short).unwrap();
    let b = parse_case(&blade, &short).unwrap();
    assert_eq!(a.case.run.travel, 10.0);
    let again = parse_case(&a.resolved_toml(), &[]).unwrap();
    assert_eq!(again.case, a.case);
    let history = |l: &soilcut_io::LoadedCase| record_case(l, || {}).history;
    assert_eq!(history(&a), history(&b));
}

#[test]
fn keys_of_the_blade_a_tool_gives_are_refused_naming_them() {
    let tool = shipped("tools/straight-profile.toml");
    for (set, key) in [
        ("blade.rake=80", "blade.rake"),
        ("blade.depth_path=[[0.0, 20.0]]", "blade.depth_path"),
        ("run.travel=150", "run.travel"),
        ("tool.radius=5", "tool.radius"),
        (
            "tool.motion=[[0.0, 0.0, -20.0, 0.0], [0.0, 1.0, -20.0, 0.0]]",
            "tool.motion",
        ),
        ("tool.shape=\"points\"", "tool.rake"),
    ] {
        let o = [set.parse().unwrap()];
        let e = parse_case(&tool, &o).unwrap_err().to_string();
        assert!(e.starts_with(&format!("{key}:")), "{set}: {e}");
    }
}

/// A tool steered from Python or C (`Simulation::advance_to`) is written
/// back as the blade it reduces to, which reads back to the steered case.
#[test]
fn a_steered_tool_is_written_as_its_blade() {
    let loaded = read_case(&root().join("cases/tools/straight-profile.toml"), &[]).unwrap();
    let mut sim = soilcut_model::Simulation::start(&loaded.case);
    sim.advance_to(150.0, Some(15.0)).unwrap();
    let steered = loaded.steered(sim.case());
    let text = steered.resolved_toml();
    assert!(!text.contains("[tool]"), "{text}");
    let again = parse_case(&text, &[]).unwrap();
    assert_eq!(again.case, steered.case);
    assert_eq!(again.case.run.travel, 150.0);
}
