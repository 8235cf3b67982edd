//! Snapshots refuse bytes they cannot restore with an error naming why
//! (never a panic), and `advance_to` lands where its rule says
//! (docs/model.md §17). Bit-for-bit continuation on the shipped cases is
//! tested in crates/io/tests/snapshots.rs, which reads their files.

use crate::common;

use soilcut_model::simulation::snapshot::{CHECKSUM_BYTES, CRATE_VERSION, FORMAT_VERSION, MAGIC};
use soilcut_model::{AdvanceError, Case, Simulation, SnapshotError, StepError};

/// The original model's case, 3 d at d/50, after `steps` increments.
fn stepped(steps: usize) -> Simulation {
    let mut sim = Simulation::new(&common::original(3.0, 50.0)).unwrap();
    for _ in 0..steps {
        sim.step().unwrap();
    }
    sim
}

/// The rest of the run and the final profile.
fn rest(
    mut sim: Simulation,
) -> (
    Vec<soilcut_model::StepRecord>,
    Vec<soilcut_model::ProfilePoint>,
) {
    let history = sim.run_to_end(|_| {}).unwrap();
    (history, sim.profile())
}

#[test]
fn a_restored_simulation_continues_as_the_original() {
    let sim = stepped(40);
    let restored = Simulation::from_snapshot(&sim.snapshot()).unwrap();
    assert_eq!(restored.case(), sim.case());
    assert_eq!(restored.steps_done(), 40);
    assert_eq!(restored.evaluations(), sim.evaluations());
    assert_eq!(restored.snapshot(), sim.snapshot());
    assert_eq!(rest(restored), rest(sim));
}

#[test]
fn the_note_comes_back() {
    let sim = stepped(3);
    let (_, note) = Simulation::from_snapshot_with_note(&sim.snapshot_with_note(b"text")).unwrap();
    assert_eq!(note, b"text");
}

/// The snapshot without its checksum.
fn unsealed(mut bytes: Vec<u8>) -> Vec<u8> {
    bytes.truncate(bytes.len() - CHECKSUM_BYTES);
    bytes
}

#[test]
fn every_truncation_is_an_error_naming_where() {
    let bytes = stepped(5).snapshot();
    for len in (0..bytes.len()).step_by(7).chain([bytes.len() - 1]) {
        let e = Simulation::from_snapshot(&bytes[..len]).unwrap_err();
        let ok = matches!(
            e,
            SnapshotError::Truncated { .. } | SnapshotError::NotASnapshot
        );
        assert!(ok, "length {len}: {e}");
    }
    let e = Simulation::from_snapshot(&unsealed(bytes.clone())).unwrap_err();
    assert!(e.to_string().contains("truncated"), "{e}");
    let mut longer = bytes;
    longer.push(0);
    assert_eq!(
        Simulation::from_snapshot(&longer).unwrap_err(),
        SnapshotError::TrailingBytes { count: 1 }
    );
}

#[test]
fn a_changed_byte_is_an_error() {
    let bytes = stepped(5).snapshot();
    let header = MAGIC.len() + 4 + 8 + CRATE_VERSION.len();
    for at in (0..bytes.len()).step_by(11) {
        for flip in [0x01u8, 0x80] {
            let mut bad = bytes.clone();
            bad[at] ^= flip;
            let e = Simulation::from_snapshot(&bad).unwrap_err();
            if at >= header + 8 {
                // Past the header and the body's length: only the checksum
                // can tell.
                assert_eq!(e, SnapshotError::Corrupt, "byte {at}");
            }
        }
    }
}

/// `bytes` with the format version `format` and the crate version `version`.
fn other_version(bytes: &[u8], format: u32, version: &str) -> Vec<u8> {
    let rest = &bytes[MAGIC.len() + 4 + 8 + CRATE_VERSION.len()..];
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(&format.to_le_bytes());
    out.extend_from_slice(&(version.len() as u64).to_le_bytes());
    out.extend_from_slice(version.as_bytes());
    out.extend_from_slice(rest);
    out
}

#[test]
fn a_snapshot_of_another_version_is_refused() {
    let bytes = stepped(2).snapshot();
    let e = Simulation::from_snapshot(&other_version(&bytes, FORMAT_VERSION + 1, CRATE_VERSION))
        .unwrap_err();
    assert!(matches!(e, SnapshotError::Version { format, .. } if format == FORMAT_VERSION + 1));
    assert!(e.to_string().contains("another version"), "{e}");
    let e = Simulation::from_snapshot(&other_version(&bytes, FORMAT_VERSION, "0.0.9")).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::Version {
            format: FORMAT_VERSION,
            crate_version: "0.0.9".into()
        }
    );
    assert!(e.to_string().contains("soilcut 0.0.9"), "{e}");
    let e = Simulation::from_snapshot(b"not a snapshot at all").unwrap_err();
    assert_eq!(e, SnapshotError::NotASnapshot);
}

#[test]
fn random_bytes_never_panic() {
    // A fixed linear congruential sequence: deterministic garbage, some of
    // it behind a valid magic and version.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        (state >> 33) as u8
    };
    let header = other_version(&stepped(0).snapshot(), FORMAT_VERSION, CRATE_VERSION);
    let header = &header[..MAGIC.len() + 4 + 8 + CRATE_VERSION.len()];
    for len in [0, 3, 8, 40, 300] {
        let garbage: Vec<u8> = (0..len).map(|_| next()).collect();
        assert!(Simulation::from_snapshot(&garbage).is_err());
        let mut framed = header.to_vec();
        framed.extend_from_slice(&garbage);
        assert!(Simulation::from_snapshot(&framed).is_err());
    }
}

/// `body` framed and sealed as a snapshot of this build: the header, its
/// length and a matching CRC-32, so that only the body's decoding can
/// refuse it.
fn sealed(body: &[u8]) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    out.extend_from_slice(&(CRATE_VERSION.len() as u64).to_le_bytes());
    out.extend_from_slice(CRATE_VERSION.as_bytes());
    out.extend_from_slice(&(body.len() as u64).to_le_bytes());
    out.extend_from_slice(body);
    let sum = crc32fast::hash(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    out
}

#[test]
fn a_sealed_but_spoilt_body_is_an_error_naming_it() {
    let bytes = stepped(5).snapshot();
    let start = MAGIC.len() + 4 + 8 + CRATE_VERSION.len() + 8;
    let body = &bytes[start..bytes.len() - CHECKSUM_BYTES];
    assert!(Simulation::from_snapshot(&sealed(body)).is_ok());
    for len in (0..body.len()).step_by(13) {
        let e = Simulation::from_snapshot(&sealed(&body[..len])).unwrap_err();
        let named = e.to_string().contains("body") || matches!(e, SnapshotError::Case(_));
        assert!(named, "body cut to {len} bytes: {e}");
    }
    let mut longer = body.to_vec();
    longer.push(0);
    let e = Simulation::from_snapshot(&sealed(&longer)).unwrap_err();
    assert!(e.to_string().contains("1 bytes left over"), "{e}");
    // Any byte changed: refused or restored, never a panic.
    for at in (0..body.len()).step_by(5) {
        let mut bad = body.to_vec();
        bad[at] = bad[at].wrapping_add(0x5b);
        let _ = Simulation::from_snapshot(&sealed(&bad));
    }
}

#[test]
fn a_clone_continues_as_the_original() {
    let sim = stepped(30);
    assert_eq!(rest(sim.clone()), rest(sim));
}

fn case() -> Case {
    common::original(3.0, 50.0)
}

#[test]
fn advance_to_lands_on_the_first_whole_increment_at_or_beyond_x() {
    let c = case();
    let v0 = c.run.increment;
    let mut sim = Simulation::new(&c).unwrap();
    let mut stepped = Simulation::new(&c).unwrap();
    // 2.5 increments: 3; exactly 5 increments (to round-off): 5; the same
    // position again: nothing.
    let cases = [
        (2.5 * v0, 3),
        (5.0 * v0 * (1.0 + 1e-12), 5),
        (4.5 * v0, 5),
        (6.001 * v0, 7),
    ];
    for (x, done) in cases {
        let records = sim.advance_to(x, None).unwrap();
        assert_eq!(sim.steps_done(), done, "x = {x}");
        assert!(sim.blade_position() >= x * (1.0 - 1e-9), "x = {x}");
        assert!(sim.blade_position() < x + v0, "x = {x}");
        let mut expected = Vec::new();
        while stepped.steps_done() < done {
            expected.push(stepped.step().unwrap());
        }
        assert_eq!(records, expected, "x = {x}");
    }
    assert_eq!(rest(sim), rest(stepped));
}

#[test]
fn a_step_past_the_travel_is_the_models_error_and_changes_nothing() {
    let mut c = case();
    c.run.travel = 3.0 * c.run.increment;
    let mut sim = Simulation::new(&c).unwrap();
    sim.run_to_end(|_| {}).unwrap();
    let before = sim.snapshot();
    let e = sim.step().unwrap_err();
    assert_eq!(e, StepError::TravelReached { steps: 3 });
    assert!(e.to_string().contains("travel has been reached"), "{e}");
    assert_eq!(sim.snapshot(), before);
    // advance_to goes beyond the travel, and a step after it is refused again.
    sim.advance_to(4.0 * c.run.increment, None).unwrap();
    assert_eq!(
        sim.step().unwrap_err(),
        StepError::TravelReached { steps: 4 }
    );
}

#[test]
fn advance_to_refuses_bad_positions_and_changes_nothing() {
    let mut sim = Simulation::new(&case()).unwrap();
    sim.advance_to(0.2 * case().run.travel, None).unwrap();
    let before = sim.snapshot();
    for x in [f64::NAN, f64::INFINITY, -1.0, 0.0, 0.1 * case().run.travel] {
        let e = sim.advance_to(x, None).unwrap_err();
        assert!(
            matches!(e, AdvanceError::Argument { name: "x", .. }),
            "{x}: {e}"
        );
    }
    let d = case().blade.depth;
    for depth in [f64::NAN, 0.0, -d, 1.5 * d, 0.5 * case().run.increment] {
        let e = sim
            .advance_to(0.3 * case().run.travel, Some(depth))
            .unwrap_err();
        assert!(
            matches!(e, AdvanceError::Argument { name: "depth", .. }),
            "{depth}: {e}"
        );
    }
    assert_eq!(sim.snapshot(), before);
}

#[test]
fn advance_to_steers_the_tip_linearly_to_the_depth() {
    let c = case();
    let d = c.blade.depth;
    let mut sim = Simulation::new(&c).unwrap();
    sim.advance_to(0.5 * d, None).unwrap();
    let (u0, x) = (sim.blade_position(), 1.5 * d);
    let records = sim.advance_to(x, Some(0.6 * d)).unwrap();
    assert_eq!(sim.tip_depth(), 0.6 * d);
    assert_eq!(sim.case().tip_depth(x), 0.6 * d);
    // Each increment's tip depth on the line from (u0, d) to (x, 0.6 d).
    for r in &records {
        let line = d + (0.6 * d - d) * (r.u - u0) / (x - u0);
        assert!(
            (r.depth - line).abs() < 1e-9 * d,
            "u = {}: {} vs {line}",
            r.u,
            r.depth
        );
    }
    assert!(records.windows(2).all(|w| w[1].depth < w[0].depth));
    // Back down, beyond the case's travel: the travel follows.
    let far = 1.2 * c.run.travel;
    sim.advance_to(far, Some(d)).unwrap();
    assert_eq!(sim.case().run.travel, far);
    assert_eq!(sim.steps_done(), sim.case().steps());
    assert!(sim.is_done());
    assert_eq!(sim.tip_depth(), d);
    // The steered case is in the snapshot, and the restored run goes on.
    let mut restored = Simulation::from_snapshot(&sim.snapshot()).unwrap();
    assert_eq!(restored.case(), sim.case());
    let x = far + 0.5 * d;
    assert_eq!(
        restored.advance_to(x, None).unwrap(),
        sim.advance_to(x, None).unwrap()
    );
}

#[test]
fn advance_to_a_depth_needs_a_vertical_blade_unless_the_depth_stays() {
    let mut c = case();
    c.blade.rake = 60.0;
    let mut sim = Simulation::new(&c).unwrap();
    sim.advance_to(0.2 * c.blade.depth, Some(c.blade.depth))
        .unwrap();
    // Refused, beyond the travel too: the case stays as it was, its
    // travel and its (empty) path.
    let before = sim.case().clone();
    let e = sim
        .advance_to(1.5 * c.run.travel, Some(0.8 * c.blade.depth))
        .unwrap_err();
    assert_eq!(sim.case(), &before);
    let e2 = sim
        .advance_to(0.4 * c.blade.depth, Some(0.8 * c.blade.depth))
        .unwrap_err();
    assert_eq!(sim.case(), &before);
    assert_eq!(e.to_string(), e2.to_string());
    assert!(
        matches!(&e, AdvanceError::Case(k) if k.key == "blade.depth_path"),
        "{e}"
    );
    assert!(e.to_string().contains("vertical"), "{e}");
}

/// Each record reaches `advance_to_with`'s callback when its increment is
/// made: the simulation it sees has just made that increment (and no
/// more), and the records are `advance_to`'s.
#[test]
fn advance_to_with_hands_over_each_record_as_its_increment_is_made() {
    let c = case();
    let x = 7.5 * c.run.increment;
    let mut sim = Simulation::new(&c).unwrap();
    let mut seen = Vec::new();
    let made = sim
        .advance_to_with(x, None, |now, record| {
            assert_eq!(now.steps_done(), record.step);
            seen.push((*record, now.blade_position(), now.profile()));
        })
        .unwrap();
    assert_eq!(made, 8);
    let positions: Vec<f64> = seen.iter().map(|s| s.1).collect();
    assert!(positions.windows(2).all(|w| w[1] > w[0]), "{positions:?}");
    assert!(seen.windows(2).all(|w| w[1].2 != w[0].2));
    let mut other = Simulation::new(&c).unwrap();
    let records = other.advance_to(x, None).unwrap();
    let got: Vec<_> = seen.iter().map(|s| s.0).collect();
    assert_eq!(got, records);
    assert_eq!(rest(sim), rest(other));
}

/// A tip steered from 20 to 0.3 over two increments sits above the dip
/// the first increments left ahead of it: no line from it stays in the
/// soil, and the next increment says so instead of searching the far field
/// for ever (found by fuzzing the C ABI,
/// fuzz/regressions/ffi_calls/tip-steered-above-a-dip).
#[test]
fn a_tip_steered_above_a_dip_ahead_finds_no_mechanism() {
    let mut sim = Simulation::new(&common::original(1.0, 100.0)).unwrap();
    assert_eq!(sim.advance_to(0.3, Some(0.3)).unwrap().len(), 2);
    let e = sim.step().unwrap_err();
    assert!(e.to_string().contains("no admissible"), "{e}");
    assert_eq!(sim.steps_done(), 2);
}
