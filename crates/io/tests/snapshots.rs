//! A simulation restored from a snapshot continues bit for bit as the
//! original does (docs/model.md §17): every paper case, the tine (a blade
//! of finite width, side heaps) and the scoop (a depth path), restored at
//! several points of their runs and compared record by record, profile by
//! profile, with `==`.

use soilcut_io::read_case;
use soilcut_model::{Case, Ground, Simulation};
use std::collections::BTreeMap;
use std::path::Path;

/// The shipped case at increment d / `per_depth` over `travel_depths`
/// depths (none: its own travel), as `--set run.increment=… --set
/// run.travel=…` would give.
fn shortened(name: &str, per_depth: f64, travel_depths: Option<f64>) -> Case {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../cases")
        .join(name);
    let mut case = read_case(&path, &[]).unwrap().case.into_case();
    let d = case.blade.depth;
    case.run.increment = d / per_depth;
    if let Some(depths) = travel_depths {
        case.run.travel = depths * d;
    }
    case
}

/// Restores the run at each of `points` (increments done) and checks that
/// the rest of it, the final profile and the final state equal the
/// original's. One run of the original, snapshotted on its way at the
/// points, gives both the snapshots and the history to compare with.
fn continues_bit_for_bit(case: &Case, points: &[usize]) {
    let mut original = Simulation::new(case).unwrap();
    let (mut full, mut taken) = (Vec::new(), BTreeMap::new());
    while !original.is_done() {
        if points.contains(&original.steps_done()) {
            taken.insert(original.steps_done(), original.snapshot());
        }
        full.push(original.step().unwrap());
    }
    let (profile, state) = (original.profile(), original.snapshot());
    for &at in points {
        let mut restored = Simulation::from_snapshot(&taken[&at]).unwrap();
        assert_eq!(restored.steps_done(), at, "{}", case.name);
        let rest = restored.run_to_end(|_| {}).unwrap();
        assert!(
            rest == full[at..],
            "{} restored after {at} increments",
            case.name
        );
        assert!(restored.profile() == profile, "{} after {at}", case.name);
        assert!(restored.snapshot() == state, "{} after {at}", case.name);
    }
}

/// After one increment, at 1 d and 2.5 d of travel and three increments
/// before the end.
fn points(case: &Case) -> Vec<usize> {
    let d = case.blade.depth;
    let mut at = vec![1, case.increments_to(d), case.increments_to(2.5 * d)];
    at.push(case.steps() - 3);
    at
}

/// Every paper case, on its own ground and on the node grid.
#[test]
fn every_paper_case_continues_bit_for_bit_on_either_ground() {
    for name in ["original", "table1-s", "table1-hs", "fig5", "fig8b"] {
        let case = shortened(&format!("paper/{name}.toml"), 100.0, Some(3.0));
        continues_bit_for_bit(&case, &points(&case));
        let mut nodes = case;
        nodes.run.ground = Ground::Nodes;
        continues_bit_for_bit(&nodes, &points(&nodes));
    }
}

#[test]
fn the_tine_continues_bit_for_bit() {
    let case = shortened("tools/tine.toml", 100.0, None);
    assert!(case.blade.width.is_some());
    continues_bit_for_bit(&case, &points(&case));
}

#[test]
fn the_scoop_continues_bit_for_bit() {
    // Its whole path (in, along, out) at d/40; also while it rises.
    let case = shortened("tools/scoop.toml", 40.0, None);
    let mut at = points(&case);
    at.push(case.increments_to(4.0 * case.blade.depth));
    continues_bit_for_bit(&case, &at);
}
