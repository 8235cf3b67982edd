//! The simulation on the vertex ground (`run.vertex_spacing` > 0,
//! docs/model.md §1.2-§7): Coulomb's wedge on the first increment, mass over a
//! run, the node grid's results where the two agree by design, and a cost
//! that follows what changes (its vertices do not multiply with the
//! resolution).

use crate::common;

use soilcut_model::summary::sheared_fraction;
use soilcut_model::{AdvanceError, Simulation, SnapshotError, TimeScheme};

/// Table 1 S (softening only) on the vertex ground, vertices d/50 apart.
fn table1_s(travel_depths: f64, per_depth: f64) -> soilcut_model::Case {
    common::on_vertices(common::refined("table1-s", travel_depths, per_depth), 50.0)
}

/// Every increment's mass within 1e-12 of the initial mass `m0`.
fn mass_is_kept(history: &[soilcut_model::StepRecord], m0: f64) {
    for r in history {
        let drift = (r.mass - m0).abs() / m0;
        assert!(drift < 1e-12, "step {}: {}", r.step, r.mass);
    }
}

#[test]
fn the_first_increment_is_coulombs_wedge_anywhere_on_the_ground() {
    // The band may emerge between vertices, then snaps to one within half
    // the spacing: the force's error is second order in that distance.
    for (spacing, tolerance) in [(50.0, 1e-4), (2000.0, 1e-7)] {
        wedge_within(spacing, tolerance);
    }
}

fn wedge_within(per_depth: f64, tolerance: f64) {
    for (phi, phi_w) in [(20.0, 10.0), (30.0, 0.0), (35.0, 10.0), (40.0, 20.0)] {
        // Vertices at least a quarter increment apart (their range).
        let mut case = common::original(1.0, 250f64.max(per_depth / 4.0));
        case.soil.friction.initial = phi;
        case.soil.friction.peak = phi;
        case.soil.friction.residual = phi;
        case.blade.wall_friction = phi_w;
        let case = common::on_vertices(case, per_depth);
        let got = Simulation::new(&case).unwrap().step().unwrap().force_norm;
        let expected = 0.5 * common::coulomb_kp(phi, phi_w);
        let rel = (got - expected) / expected;
        assert!(
            rel < tolerance,
            "d/{per_depth}, φ={phi} φw={phi_w}: {got} vs {expected}"
        );
        assert!(rel > -1e-12, "no mechanism beats the exact minimum");
    }
}

#[test]
fn a_run_keeps_its_mass_and_follows_the_node_grid() {
    let d = 20.0;
    let (history, sim) = common::run(&table1_s(3.0, 250.0));
    mass_is_kept(&history, sim.initial_mass());
    let nodes = common::refined("table1-s", 3.0, 250.0);
    let (reference, node_sim) = common::run(&nodes);
    // Both keep the band's state where it was; they differ in where a band
    // may emerge (anywhere, or at nodes) and in the avalanches' vertices.
    let (ours, theirs) = (
        common::window_means(&history, d, 3),
        common::window_means(&reference, d, 3),
    );
    for (w, (a, b)) in ours.iter().zip(&theirs).enumerate() {
        assert!((a - b).abs() < 0.015 * b, "window {w}: {a} vs {b}");
    }
    // The sheared fraction is one of length, not of points, which crowd
    // where the bands emerged on the vertex ground: both grounds agree.
    let sheared = |s: &Simulation| sheared_fraction(s.case(), &s.profile());
    let (a, b) = (sheared(&sim), sheared(&node_sim));
    assert!((a - b).abs() < 0.03, "sheared fraction {a} vs {b}");
}

#[test]
fn the_vertices_do_not_multiply_with_the_resolution() {
    // On the node grid the nodes double with each halving of v0; on the
    // vertex ground a band's points snap to the vertices within half the
    // spacing, so the ground keeps about as many.
    let count = |per_depth: f64| {
        let (_, sim) = common::run(&table1_s(2.0, per_depth));
        sim.profile().len() as f64
    };
    let (coarse, fine) = (count(250.0), count(1000.0));
    assert!(
        fine < 1.5 * coarse,
        "{coarse} vertices at d/250, {fine} at d/1000"
    );
}

/// The band rules beyond the default run on the vertex ground as on the
/// reference grid (Table 1 S, 3 d, vertices d/50 at d/250 against nodes
/// at d/2000): by position, every unit window within 2 % (measured 0.2-1.3
/// %); the paper's per-node unit weight within 2 % (0.1-0.9 %), and it
/// loses soil on both grounds (the band's dilation divides γ instead of
/// adding volume; −1.3 % of the mass on the grid, −2.1 % here), where the
/// default keeps it.
#[test]
fn the_band_rules_run_on_the_vertex_ground_as_on_the_grid() {
    use soilcut_model::{BandShearRule, UnitWeightRule};
    let d = 20.0;
    let by_position = |mut case: soilcut_model::Case| {
        case.choices.band_shear = BandShearRule::ByPosition;
        case
    };
    let per_node = |mut case: soilcut_model::Case| {
        case.choices.unit_weight = UnitWeightRule::PerNodeFormula;
        case
    };
    let rules: [(&str, &dyn Fn(soilcut_model::Case) -> soilcut_model::Case); 2] = [
        ("by-position", &by_position),
        ("per-node-formula", &per_node),
    ];
    for (rule, with) in rules {
        let (ours, sim) = common::run(&with(table1_s(3.0, 250.0)));
        let grid = common::refined("table1-s", 3.0, 2000.0);
        let (theirs, _) = common::run(&with(grid));
        let windows = |h| common::window_means(h, d, 3);
        for (w, (a, b)) in windows(&ours).iter().zip(&windows(&theirs)).enumerate() {
            assert!((a - b).abs() < 0.02 * b, "{rule}, window {w}: {a} vs {b}");
        }
        let drift = ours.last().unwrap().mass / sim.initial_mass() - 1.0;
        match rule {
            "by-position" => assert!(drift.abs() < 1e-12, "{rule}: drift {drift:e}"),
            _ => assert!(drift < -1e-3, "{rule}: drift {drift:e}"),
        }
    }
}

/// `run.samples_per_band = 0` on the vertex ground is the exhaustive
/// search: every emergence point v0 apart and every vertex, its local
/// minima narrowed to v0. On the same ground it never ends above the
/// sampled search (K = 8): the two runs take the same increments, bit for
/// bit, until one of them picks another band, and before that the
/// exhaustive force is never the higher.
#[test]
fn the_exhaustive_vertex_search_is_never_above_the_sampled() {
    let sampled = table1_s(2.0, 250.0);
    let mut exhaustive = sampled.clone();
    exhaustive
        .run
        .vertices_mut()
        .expect("on the vertex ground")
        .samples_per_band = 0.0;
    let (a, _) = common::run(&sampled);
    let (b, _) = common::run(&exhaustive);
    let mut same = 0;
    for (s, e) in a.iter().zip(&b) {
        assert!(
            e.force <= s.force * (1.0 + 1e-12),
            "step {}: exhaustive {} above sampled {}",
            s.step,
            e.force,
            s.force
        );
        if s != e {
            break;
        }
        same += 1;
    }
    assert!(same > 10, "only {same} increments on the same ground");
}

#[test]
fn a_snapshot_on_the_vertex_ground_continues_bit_for_bit() {
    let mut sim = Simulation::new(&table1_s(2.0, 250.0)).unwrap();
    for _ in 0..300 {
        sim.step().unwrap();
    }
    let bytes = sim.snapshot();
    let mut restored = Simulation::from_snapshot(&bytes).unwrap();
    assert_eq!(restored.profile(), sim.profile());
    for _ in 0..100 {
        assert_eq!(restored.step().unwrap(), sim.step().unwrap());
    }
    assert_eq!(restored.evaluations(), sim.evaluations());
    // A case on the node grid with the vertex ground's state is refused.
    let mut other = table1_s(2.0, 250.0);
    other.run.ground = soilcut_model::Ground::Nodes;
    let nodes = Simulation::new(&other).unwrap().snapshot();
    assert!(Simulation::from_snapshot(&nodes).is_ok());
    let corrupt = bytes.len() / 2;
    let mut flipped = bytes.clone();
    flipped[corrupt] ^= 0x10;
    assert_eq!(
        Simulation::from_snapshot(&flipped).err(),
        Some(SnapshotError::Corrupt)
    );
}

#[test]
fn the_landscape_holds_the_first_stage_and_the_step_refines_it() {
    let mut sim = Simulation::new(&table1_s(2.0, 250.0)).unwrap();
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let candidates = sim.landscape().unwrap();
    let least = candidates
        .iter()
        .map(|c| c.force_norm)
        .fold(f64::INFINITY, f64::min);
    let chosen = sim.step().unwrap().force_norm;
    assert!(candidates.len() > 100, "{} candidates", candidates.len());
    // The second stage narrows the least sample's bracket, and the point it
    // finds may snap to a vertex: the landscape holds that candidate too,
    // so its least is the force the step records.
    assert_eq!(least, chosen);
}

#[test]
fn advance_to_goes_beyond_the_travel_and_steers_the_tip() {
    let case = table1_s(0.5, 250.0);
    let mut sim = Simulation::new(&case).unwrap();
    let beyond = case.run.travel + 1.0;
    let records = sim.advance_to(beyond, None).unwrap();
    assert_eq!(records.len(), sim.steps_done());
    assert!(
        sim.blade_position() >= beyond - 1e-9,
        "{}",
        sim.blade_position()
    );
    // Steering the tip makes a depth path, which the vertex ground runs.
    let shallower = 0.9 * case.blade.depth;
    sim.advance_to(beyond + 1.0, Some(shallower)).unwrap();
    assert_eq!(
        sim.case().run.ground.name(),
        "vertices",
        "still on the vertex ground"
    );
    assert!((sim.tip_depth() - shallower).abs() < 1e-9);
    // A depth below the ground the simulation holds stays refused.
    let e = sim
        .advance_to(beyond + 2.0, Some(1.1 * case.blade.depth))
        .unwrap_err();
    assert!(
        matches!(&e, AdvanceError::Argument { name: "depth", .. }),
        "{e}"
    );
}

/// The increments of `which` on vertices d/50 apart at d/250 under the
/// explicit and the midpoint rule, in step up to the first that differs
/// (until then the two states are the same): the records before it, and
/// the pair at it.
fn until_they_part(which: &str) -> (usize, soilcut_model::StepRecord, soilcut_model::StepRecord) {
    let case = common::on_vertices(common::refined(which, 0.5, 250.0), 50.0);
    let mut midpoint = case.clone();
    midpoint
        .run
        .vertices_mut()
        .expect("on the vertex ground")
        .time_scheme = TimeScheme::MidpointForce;
    let (mut e, mut m) = (
        Simulation::new(&case).unwrap(),
        Simulation::new(&midpoint).unwrap(),
    );
    for same in 0.. {
        let (a, b) = (e.step().unwrap(), m.step().unwrap());
        if a != b {
            return (same, a, b);
        }
        assert!(!e.is_done(), "{which}: the two rules never part");
    }
    unreachable!()
}

#[test]
fn the_midpoint_force_keeps_the_band_and_takes_the_state_half_an_increment_on() {
    // Softening from the start (Table 1 S) and hardening only (Fig. 8b):
    // the first band that shears soil an earlier one sheared has, half an
    // increment on, a lower, or higher, strength than at the start.
    for (which, softens) in [("table1-s", true), ("fig8b", false)] {
        let (same, e, m) = until_they_part(which);
        // Fresh soil: the first increment is the explicit one, Coulomb's
        // wedge, bit for bit.
        assert!(same >= 1, "{which}");
        assert_eq!(m.force < e.force, softens, "{which}: {m:?} vs {e:?}");
        // Where the soil softens the band is the one least at the start;
        // where it never does, the least half an increment on (M51a),
        // whose force is at least its own start's, so at least the least's.
        let same_band = (e.x_emergence, e.beta_deg) == (m.x_emergence, m.beta_deg);
        assert!(same_band || !softens, "{which}: {m:?} vs {e:?}");
        if !same_band {
            continue;
        }
        assert_eq!(
            m.friction_deg < e.friction_deg,
            softens,
            "{which}: {m:?} vs {e:?}"
        );
        // Every point of the footprint half an increment's shear on: the
        // mean φ moves by no more than the law's steepest slope times it.
        let soil = common::refined(which, 0.5, 250.0).soil;
        let f = soil.friction;
        let hardening = if soil.peak_shear > 0.0 {
            (f.peak - f.initial).abs() / soil.peak_shear
        } else {
            0.0
        };
        let softening = (f.peak - f.residual) / (soil.residual_shear - soil.peak_shear);
        let steepest = hardening.max(softening);
        let moved = (m.friction_deg - e.friction_deg).abs();
        assert!(
            moved > 0.0 && moved <= steepest * 0.5 * e.slip * (1.0 + 1e-9),
            "{which}: {moved} degrees"
        );
    }
}

#[test]
fn merging_quiet_vertices_keeps_the_mass_and_thins_the_ground() {
    // Table 1 S over 2 d: with run.merge_tolerance the vertices between
    // pieces of nearly equal state on a nearly straight ground go, the mass
    // stays exact and the force stays near the unmerged run's.
    let plain = table1_s(2.0, 250.0);
    let mut merged = plain.clone();
    merged
        .run
        .vertices_mut()
        .expect("on the vertex ground")
        .merge_tolerance = 0.03;
    let (ours, sim) = common::run(&merged);
    let (theirs, plain_sim) = common::run(&plain);
    mass_is_kept(&ours, sim.initial_mass());
    let (fewer, more) = (sim.profile().len(), plain_sim.profile().len());
    assert!(fewer < more, "{fewer} vertices merged, {more} not");
    let d = merged.blade.depth;
    let (a, b) = (
        common::window_means(&ours, d, 2),
        common::window_means(&theirs, d, 2),
    );
    for (w, (a, b)) in a.iter().zip(&b).enumerate() {
        assert!((a - b).abs() < 0.02 * b, "window {w}: {a} vs {b}");
    }
}

/// Fig. 8b's soil (hardening only) at its defaults on the vertex ground:
/// vertices d/25 apart, d/250, the midpoint force, one sample per band.
fn fig8b_at_defaults(travel_depths: f64) -> soilcut_model::Case {
    let mut case = common::on_vertices(common::refined("fig8b", travel_depths, 250.0), 25.0);
    let v = case.run.vertices_mut().expect("on the vertex ground");
    v.samples_per_band = 1.0;
    v.time_scheme = TimeScheme::MidpointForce;
    case
}

#[test]
fn a_hardening_soil_chooses_its_band_by_the_midpoint_force() {
    // Where the soil never softens the search compares the bands half an
    // increment on (M51a): the force the step records is the least of the
    // landscape's, which holds every first-stage candidate's midpoint
    // force (the second stage may go below them, the snap 0.1 % above).
    let mut sim = Simulation::new(&fig8b_at_defaults(2.0)).unwrap();
    while sim.steps_done() < 300 {
        let least = sim
            .landscape()
            .unwrap()
            .iter()
            .map(|c| c.force)
            .fold(f64::INFINITY, f64::min);
        let chosen = sim.step().unwrap().force;
        assert!(chosen <= least * (1.0 + 1e-3), "{chosen} above {least}");
    }
    // A band chosen at the start that hardens over the increment past
    // another put lone increments 3-10 % above both neighbours into Fig.
    // 8b's curve (about 60 over 4 d); the paper's curve has none.
    let (history, sim) = common::run(&fig8b_at_defaults(2.0));
    mass_is_kept(&history, sim.initial_mass());
    for w in history.windows(3) {
        let rise = w[1].force / w[0].force.max(w[2].force) - 1.0;
        assert!(
            rise < 0.01,
            "step {}: {rise} above both neighbours",
            w[1].step
        );
    }
}
