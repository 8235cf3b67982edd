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
/// back with the motion it was steered along, which reads back to the
/// steered case.
#[test]
fn a_steered_tool_is_written_with_its_steered_motion() {
    let loaded = read_case(&root().join("cases/tools/straight-profile.toml"), &[]).unwrap();
    let mut sim = soilcut_model::Simulation::start(&loaded.case);
    sim.advance_to(150.0, Some(15.0)).unwrap();
    let steered = loaded.steered(sim.case());
    let text = steered.resolved_toml();
    assert!(
        text.contains("[tool]") && !text.contains("depth_path"),
        "{text}"
    );
    let again = parse_case(&text, &[]).unwrap();
    assert_eq!(again.case, steered.case);
    assert_eq!(again.case.run.travel, 150.0);
}

/// The columns of `history.csv` by name, one vector each.
fn columns(csv: &str) -> std::collections::HashMap<String, Vec<f64>> {
    let mut lines = csv.lines();
    let names: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    names
        .iter()
        .enumerate()
        .map(|(i, n)| (n.clone(), rows.iter().map(|r| r[i]).collect()))
        .collect()
}

/// (M56) on flat ground: the first increment's contact is the depth d,
/// so about the cutting edge of a vertical blade the draft acts d/3 up
/// (the Coulomb wedge's linear pressure) and the vertical force on the
/// face has no lever.
#[test]
fn the_first_moment_about_the_edge_is_the_draft_a_third_up() {
    let h = columns(&history(&shipped("paper/fig5.toml")));
    let expected = h["force_h"][0] * 20.0 / 3.0;
    assert!(
        (h["moment"][0] - expected).abs() <= 1e-12 * expected,
        "{} {expected}",
        h["moment"][0]
    );
    assert!(h["moment"]
        .iter()
        .zip(&h["force_h"])
        .all(|(m, f)| m * f >= 0.0));
    // The pile raises the contact and with it the lever.
    let last = h["moment"].len() - 1;
    assert!(h["moment"][last] / h["force_h"][last] > 20.0 / 3.0 * 1.5);
}

/// A tool pivoted 50 above its edge: the pivot's path is the edge's plus
/// a fixed offset, the rotation the tool's, and the moment about the
/// pivot is the one about the edge less the offset's lever.
#[test]
fn a_pivot_s_path_and_moment_follow_the_cutting_edge() {
    let inclined = shipped("tools/inclined.toml");
    let as_tool = |tool: &str| {
        edited(
            &inclined,
            &[
                (
                    "rake = 60.0           # α, degrees from the horizontal (90 = vertical)",
                    "",
                ),
                ("travel = 100.0     # 5 d", ""),
                (
                    "[soil]",
                    &format!("[tool]\nshape = \"straight\"\nheight = 70.0\n{tool}\n\n[soil]"),
                ),
            ],
        )
    };
    // The face at 60° as the shape gives it: the blade's run exactly.
    let raised = as_tool("rake = 60.0\npivot = [0.0, 50.0]\nmotion = [[0.0, 0.0, 30.0, 0.0], [100.0, 100.0, 30.0, 0.0]]");
    let tool = columns(&history(&raised));
    let blade = columns(&history(&inclined));
    assert_eq!(tool["force"], blade["force"]);
    for i in 0..tool["u"].len() {
        assert_eq!(tool["tool_x"][i], blade["u"][i]);
        assert_eq!(tool["tool_y"][i], -blade["depth"][i] + 50.0);
        let about_pivot = blade["moment"][i] - 50.0 * blade["force_h"][i];
        let scale = blade["moment"][i].abs().max(1.0);
        assert!(
            (tool["moment"][i] - about_pivot).abs() <= 1e-12 * scale,
            "row {i}"
        );
    }
    // A vertical profile turned 30° counter-clockwise about the pivot: its
    // edge 50 sin 30° ahead of the pivot and 50 cos 30° below it.
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let (x0, y0) = (-50.0 * sin, 50.0 * cos - 20.0);
    let turned = as_tool(&format!(
        "pivot = [0.0, 50.0]\nmotion = [[0.0, {x0}, {y0}, 30.0], [100.0, {}, {y0}, 30.0]]",
        100.0 + x0
    ));
    let tool = columns(&history(&turned));
    for (i, u) in tool["u"].iter().enumerate() {
        assert!((tool["tool_x"][i] - (u + x0)).abs() < 1e-9, "row {i}");
        assert!((tool["tool_y"][i] - y0).abs() < 1e-9, "row {i}");
        assert_eq!(tool["tool_rotation"][i], 30.0);
    }
}
