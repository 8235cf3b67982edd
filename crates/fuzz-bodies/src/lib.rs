//! The bodies of soilcut's fuzz targets: each takes the fuzzer's bytes,
//! feeds them to a public reader (or, `ffi_calls`, turns them into C ABI
//! calls) and checks what the project promises of it, panicking on a
//! broken promise (which the fuzzer reports as a crash):
//!
//! * every input is read without a panic;
//! * an input refused gets a one-line, non-empty message, and a key error
//!   names a key;
//! * an input accepted is valid: a case passes `Case::validate`, reads
//!   back from its `case.resolved.toml` to the same case, starts a
//!   [`Simulation`] and (within [`RUN_NODES`]) runs [`RUN_STEPS`]
//!   increments with finite forces and its mass conserved; a measured
//!   curve has finite points and admissible weights, and reads back from
//!   its own CSV.
//!
//! The cargo-fuzz targets in `fuzz/fuzz_targets/` call these functions on
//! nightly; `tests/replay.rs` calls them on every file of the committed
//! corpus (`fuzz/corpus/<target>/`) and of the crashes found
//! (`fuzz/regressions/<target>/`) in the stable test command. A separate
//! crate rather than a feature of `soilcut-io`: the stable workspace build
//! and test use it with no flag, and the readers' public API carries
//! nothing for fuzzing.
//!
//! The C ABI's target, `ffi_calls` (module `ffi`), calls the entry points
//! of `soilcut-ffi` as a C caller would, with arbitrary arguments.

mod ffi;

pub use ffi::{ffi_calls, FFI_CALLS, FFI_STEPS};

use soilcut_io::{
    parse_case, parse_case_bytes, parse_measured_bytes, parse_measured_curve, parse_value,
    InputError, LoadedCase, MeasuredCurve, Override,
};
use soilcut_model::{Model, Simulation, UnitWeightRule};

/// Increments an accepted case runs: enough to move the face, build a
/// band and avalanche, spill at a finite width, on a case whose cost is
/// bounded by [`RUN_NODES`].
pub const RUN_STEPS: usize = 3;

/// The largest case that is stepped, in surface nodes at the start. A
/// step searches the nodes within reach of the blade, so its cost grows
/// with the nodes per blade depth; [`RUN_NODES_PER_DEPTH`] bounds that.
/// The shipped paper cases (6 502 nodes, 500 per depth) are within both.
pub const RUN_NODES: f64 = 20_000.0;

/// The finest grid that is stepped: nodes (or vertices) per deepest tip
/// depth.
pub const RUN_NODES_PER_DEPTH: f64 = 600.0;

/// The largest case a [`Simulation`] is created for, in surface nodes at
/// the start (its memory is linear in them; `Case::validate` allows up to
/// `MAX_NODES`, 5e7, which would take gigabytes and seconds per input).
pub const NEW_NODES: f64 = 1.0e6;

/// The shipped cases `set_override` applies its overrides to, chosen by
/// the input's first byte: each model, a depth path, a finite width.
pub const BASES: [&str; 4] = [
    include_str!("../../io/testdata/original.toml"),
    include_str!("../../io/testdata/refined.toml"),
    include_str!("../../../cases/tools/deepening.toml"),
    include_str!("../../../cases/tools/tine.toml"),
];

/// How far an input got: the replay checks that the corpus reaches every
/// stage, so that no budget or seed change leaves a check unexercised.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Outcome {
    /// Not even given to the reader (an argument that is not UTF-8).
    Skipped,
    /// Refused with a clear error.
    Refused,
    /// Accepted and checked, but beyond [`NEW_NODES`].
    Accepted,
    /// A [`Simulation`] created, but beyond the run's budget.
    Created,
    /// Run for up to [`RUN_STEPS`] increments (or until the model found
    /// no mechanism).
    Stepped,
    /// (`ffi_calls`) A handle restored from a snapshot.
    Restored,
}

/// Target `case_toml`: any bytes as a case file.
pub fn case_toml(data: &[u8]) -> Outcome {
    match parse_case_bytes(data, &[]) {
        Ok(loaded) => {
            let text = std::str::from_utf8(data).expect("accepted bytes are text");
            let again = parse_case(text, &[]).expect("text accepted as bytes is accepted");
            assert_eq!(again, loaded, "bytes and text read differently");
            check_accepted(&loaded)
        }
        Err(e) => check_refused(&e),
    }
}

/// Target `set_override`: `--set` arguments applied to a shipped case.
/// The first byte picks the case from [`BASES`]; the rest are arguments
/// separated by NUL bytes (which no command-line argument can hold).
/// Arguments that are not UTF-8 never reach the reader (the command line
/// refuses them), so neither do they here.
pub fn set_override(data: &[u8]) -> Outcome {
    let Some((&pick, rest)) = data.split_first() else {
        return Outcome::Skipped;
    };
    let base = BASES[pick as usize % BASES.len()];
    let mut overrides = Vec::new();
    for arg in rest.split(|&b| b == 0) {
        let Ok(text) = std::str::from_utf8(arg) else {
            return Outcome::Skipped;
        };
        match text.parse::<Override>() {
            Ok(o) => {
                check_override(text, &o);
                overrides.push(o);
            }
            Err(e) => {
                check_refused(&e);
                assert!(
                    matches!(e, InputError::Override { .. }),
                    "{text:?}: not an override error: {e:?}"
                );
                return Outcome::Refused;
            }
        }
    }
    match parse_case(base, &overrides) {
        Ok(loaded) => check_accepted(&loaded),
        Err(e) => {
            check_refused(&e);
            assert!(
                !matches!(e, InputError::Syntax { .. }),
                "a shipped case with overrides has no syntax error: {e:?}"
            );
            Outcome::Refused
        }
    }
}

/// Target `measured_csv`: any bytes as a measured force-displacement curve.
pub fn measured_csv(data: &[u8]) -> Outcome {
    match parse_measured_bytes(data) {
        Ok(curve) => {
            check_curve(&curve);
            let text = std::str::from_utf8(data).expect("accepted bytes are text");
            let again = parse_measured_curve(text).expect("text accepted as bytes is accepted");
            assert_eq!(again, curve, "bytes and text read differently");
            Outcome::Accepted
        }
        Err(e) => check_refused(&e),
    }
}

/// An accepted case is valid, reads back from its resolved file to the
/// same case, starts and, within the budget, runs conserving mass.
pub fn check_accepted(loaded: &LoadedCase) -> Outcome {
    let case = &loaded.case;
    if let Err(e) = case.validate() {
        panic!("accepted case fails Case::validate: {e}");
    }
    let resolved = loaded.resolved_toml();
    let again = match parse_case(&resolved, &[]) {
        Ok(again) => again,
        Err(e) => panic!("case.resolved.toml is refused: {e}\n{resolved}"),
    };
    assert_eq!(
        &again.case, case,
        "case.resolved.toml reads back differently\n{resolved}"
    );
    assert_eq!(
        again.resolved_toml(),
        resolved,
        "case.resolved.toml is not a fixed point"
    );
    // Warnings are printed by every front end: they must format.
    for w in case.accuracy_warnings() {
        assert!(!w.is_empty());
    }
    let nodes = case.initial_nodes();
    if nodes > NEW_NODES {
        return Outcome::Accepted;
    }
    let mut sim = match Simulation::new(case) {
        Ok(sim) => sim,
        Err(e) => panic!("accepted case refused by Simulation::new: {e}"),
    };
    let initial = sim.initial_mass();
    assert!(
        initial.is_finite() && initial > 0.0,
        "initial mass {initial}"
    );
    if nodes > RUN_NODES || case.deepest() / case.run.spacing() > RUN_NODES_PER_DEPTH {
        return Outcome::Created;
    }
    // The paper's unit weight node by node drifts the mass by design
    // (README, `choices.unit_weight`; docs/model.md §14): it is there for
    // comparison. Every other case keeps it exact.
    let conserves_mass =
        case.model == Model::Original || case.choices.unit_weight != UnitWeightRule::PerNodeFormula;
    for _ in 0..RUN_STEPS.min(case.steps()) {
        let record = match sim.step() {
            Ok(record) => record,
            Err(e) => {
                // No mechanism is the model's answer, not a bug: its
                // message must still say so.
                assert!(!e.to_string().is_empty());
                return Outcome::Stepped;
            }
        };
        for (what, v) in [
            ("force", record.force),
            ("force_h", record.force_h),
            ("force_v", record.force_v),
            ("depth", record.depth),
            ("mass", record.mass),
        ] {
            assert!(v.is_finite(), "step {}: {what} = {v}", record.step);
        }
        assert!(
            record.force >= 0.0,
            "step {}: force {}",
            record.step,
            record.force
        );
        if !conserves_mass {
            continue;
        }
        let met = sim.mass() + sim.mass_spilled();
        let drift = (met - initial) / initial;
        assert!(
            drift.abs() < 1e-9,
            "step {}: mass drift {drift:e} (mass {}, spilled {}, initial {initial})",
            record.step,
            sim.mass(),
            sim.mass_spilled()
        );
    }
    Outcome::Stepped
}

/// A refused input's message is one non-empty line; a key error names a
/// key and says what is wrong with it.
pub fn check_refused(e: &InputError) -> Outcome {
    let message = e.to_string();
    assert!(!message.trim().is_empty(), "empty message: {e:?}");
    assert!(
        !message.contains('\n'),
        "message of more than one line: {message:?}"
    );
    match e {
        InputError::Key(k) => {
            assert!(
                !k.key.trim().is_empty(),
                "key error names no key: {message:?}"
            );
            assert!(
                !k.message.trim().is_empty(),
                "key error says nothing: {message:?}"
            );
        }
        InputError::Syntax { line, message } => {
            assert!(*line >= 1, "line {line}");
            assert!(!message.trim().is_empty(), "syntax error says nothing");
        }
        InputError::Override { message, .. } => {
            assert!(!message.trim().is_empty(), "override error says nothing")
        }
        InputError::Read(_) | InputError::ReadMeasured(_) => panic!("no file is read: {e:?}"),
    }
    Outcome::Refused
}

/// A parsed `--set` keeps the key as written and sets exactly that key.
fn check_override(text: &str, o: &Override) {
    let (key, value) = text.split_once('=').expect("an accepted override has =");
    assert_eq!(o.key(), key.trim(), "{text:?}");
    let mut table = toml::Table::new();
    if let Err(e) = o.apply(&mut table) {
        panic!("{text:?} cannot be set on an empty table: {e}");
    }
    let parts: Vec<&str> = key.trim().split('.').collect();
    let (last, parents) = parts.split_last().expect("one level at least");
    let mut at = &table;
    for p in parents {
        at = at[*p].as_table().expect("parents are created as tables");
    }
    // Debug rather than ==: a NaN value equals itself only so.
    assert_eq!(
        format!("{:?}", at[*last]),
        format!("{:?}", parse_value(value.trim())),
        "{text:?}"
    );
}

/// An accepted curve holds what `parse_measured_curve` promises, and
/// written back as CSV reads the same.
fn check_curve(curve: &MeasuredCurve) {
    assert!(curve.points.len() >= 2, "{} points", curve.points.len());
    assert_eq!(curve.points.len(), curve.weights.len());
    for &(u, f) in &curve.points {
        assert!(u.is_finite() && f.is_finite(), "point ({u}, {f})");
    }
    assert!(curve.weights.iter().all(|w| w.is_finite() && *w >= 0.0));
    assert!(curve.weights.iter().any(|&w| w > 0.0));
    let mut csv = String::from("u,force,weight\n");
    for (&(u, f), w) in curve.points.iter().zip(&curve.weights) {
        csv.push_str(&format!("{u:?},{f:?},{w:?}\n"));
    }
    let again = parse_measured_curve(&csv).expect("a curve written back is read");
    // Debug: -0.0 and 0.0 are == but written differently.
    assert_eq!(format!("{again:?}"), format!("{curve:?}"), "{csv}");
}
