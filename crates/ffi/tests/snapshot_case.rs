//! A snapshot made through the C ABI carries the case's text, as the
//! Python package's do (`snapshot_with_note` with `case.resolved.toml`),
//! so that each restores the other's with its case.

use soilcut_ffi::*;
use soilcut_io::{parse_case, LoadedCase};
use soilcut_model::Simulation;
use std::ffi::{c_char, CStr, CString};
use std::ptr::{null, null_mut};

const ORIGINAL: &str = include_str!("../../../cases/paper/original.toml");

/// The original case, cut to 0.48 of travel (6 increments at its default
/// d/250).
fn loaded() -> LoadedCase {
    parse_case(&ORIGINAL.replace("travel = 100.0", "travel = 0.48"), &[]).unwrap()
}

fn last_error() -> String {
    let mut buf = vec![0 as c_char; 512];
    unsafe { soilcut_last_error(null(), buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

fn snapshot(sim: *const SoilcutSimulation) -> Vec<u8> {
    let mut needed = 0;
    assert_eq!(
        unsafe { soilcut_snapshot(sim, null_mut(), 0, &mut needed) },
        SOILCUT_OK
    );
    let mut bytes = vec![0; needed];
    let code = unsafe { soilcut_snapshot(sim, bytes.as_mut_ptr(), needed, &mut needed) };
    assert_eq!(code, SOILCUT_OK);
    bytes
}

fn restore(bytes: &[u8]) -> Result<*mut SoilcutSimulation, (i32, String)> {
    let mut sim = null_mut();
    match unsafe { soilcut_restore(bytes.as_ptr(), bytes.len(), &mut sim) } {
        SOILCUT_OK => Ok(sim),
        code => Err((code, last_error())),
    }
}

#[test]
fn a_c_snapshot_carries_the_case_as_steered() {
    let text = CString::new(loaded().resolved_toml()).unwrap();
    let mut sim = null_mut();
    let code = unsafe { soilcut_new_from_toml(text.as_ptr(), null(), 0, &mut sim) };
    assert_eq!(code, SOILCUT_OK);
    // Steered shallower and beyond the travel: the depth path and the
    // travel the note must carry are no longer the file's.
    let code = unsafe { soilcut_advance_to(sim, 0.6, 15.0, None, null_mut(), null_mut()) };
    assert_eq!(code, SOILCUT_OK);
    let bytes = snapshot(sim);
    unsafe { soilcut_free(sim) };
    let (restored, note) = Simulation::from_snapshot_with_note(&bytes).unwrap();
    let note = String::from_utf8(note).unwrap();
    let case = parse_case(&note, &[]).unwrap().case;
    assert_eq!(&case, restored.case());
    assert_eq!(case.run.travel, 0.6);
    assert_eq!(case.blade.depth_path.last(), Some(&[0.6, 15.0]));
    assert_eq!(note, loaded().steered(&case).resolved_toml());
}

#[test]
fn a_python_style_snapshot_restores_through_c_with_its_case() {
    let loaded = loaded();
    let mut sim = Simulation::new(&loaded.case).unwrap();
    for _ in 0..5 {
        sim.step().unwrap();
    }
    // What the Python package writes (crates/python/src/simulation.rs).
    let text = loaded.resolved_toml();
    let python = sim.snapshot_with_note(text.as_bytes());
    let handle = restore(&python).unwrap();
    // The C ABI's snapshot of it is the Python one, case text included.
    assert_eq!(snapshot(handle), python);
    unsafe { soilcut_free(handle) };

    // Without case text (a snapshot of the model's own): restored, and
    // its snapshots have none either.
    let bare = sim.snapshot();
    let handle = restore(&bare).unwrap();
    assert_eq!(snapshot(handle), bare);
    unsafe { soilcut_free(handle) };

    // Case text that is not the state's case is refused.
    let other = text.replace("name = \"original\"", "name = \"other\"");
    assert_ne!(other, text);
    let (code, message) = restore(&sim.snapshot_with_note(other.as_bytes())).unwrap_err();
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(message.contains("not the case of its state"), "{message}");
    let (code, message) = restore(&sim.snapshot_with_note(b"\xff")).unwrap_err();
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(message.contains("not UTF-8"), "{message}");
}
