//! The C ABI called directly, as a C caller would: bad arguments are
//! status codes with messages, never undefined behaviour; the numbers are
//! the model's; handles work on several threads.

use soilcut_ffi::*;
use soilcut_io::{parse_case, HISTORY, HISTORY_HEADER};
use soilcut_model::Simulation;
use std::ffi::{c_char, c_void, CStr, CString};
use std::ptr::{null, null_mut};

const ORIGINAL: &str = include_str!("../../../cases/paper/original.toml");

/// The original case, cut short: `steps` increments of d/500.
fn short(steps: usize) -> String {
    ORIGINAL.replace(
        "travel = 100.0",
        &format!("travel = {}\nincrement = 0.04", steps as f64 * 0.04),
    )
}

/// A handle for `text` with `sets`, or the constructor's code and message.
fn create(text: &str, sets: &[&str]) -> Result<*mut SoilcutSimulation, (i32, String)> {
    let text = CString::new(text).unwrap();
    let sets: Vec<CString> = sets.iter().map(|s| CString::new(*s).unwrap()).collect();
    let pointers: Vec<*const c_char> = sets.iter().map(|s| s.as_ptr()).collect();
    let mut sim = null_mut();
    let code = unsafe {
        soilcut_new_from_toml(text.as_ptr(), pointers.as_ptr(), pointers.len(), &mut sim)
    };
    if code == SOILCUT_OK {
        assert!(!sim.is_null());
        Ok(sim)
    } else {
        assert!(sim.is_null(), "a failed constructor leaves NULL");
        Err((code, last_error(null())))
    }
}

fn last_error(sim: *const SoilcutSimulation) -> String {
    let needed = unsafe { soilcut_last_error(sim, null_mut(), 0) };
    let mut buf = vec![0 as c_char; needed];
    let again = unsafe { soilcut_last_error(sim, buf.as_mut_ptr(), buf.len()) };
    assert_eq!(again, needed);
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_str()
        .unwrap()
        .to_string()
}

fn state(sim: *const SoilcutSimulation) -> SoilcutState {
    let mut out = SoilcutState::default();
    assert_eq!(unsafe { soilcut_state(sim, &mut out) }, SOILCUT_OK);
    out
}

fn step(sim: *mut SoilcutSimulation) -> SoilcutStep {
    let mut record = SoilcutStep::default();
    let code = unsafe { soilcut_step(sim, &mut record) };
    assert_eq!(code, SOILCUT_OK, "{}", last_error(sim));
    record
}

fn steps_to_end(sim: *mut SoilcutSimulation) -> Vec<SoilcutStep> {
    let mut records = Vec::new();
    while state(sim).done == 0 {
        records.push(step(sim));
    }
    records
}

/// A field-by-field bit comparison (-0.0 and NaN would hide from ==).
fn bits(r: &SoilcutStep) -> Vec<u64> {
    let mut v = vec![r.step];
    v.extend(r.values().map(f64::to_bits));
    v
}

struct Free(*mut SoilcutSimulation);
impl Drop for Free {
    fn drop(&mut self) {
        unsafe { soilcut_free(self.0) };
    }
}

#[test]
fn records_are_the_models_bit_for_bit() {
    let text = short(30);
    let sim = create(&text, &[]).unwrap();
    let _free = Free(sim);
    let records = steps_to_end(sim);
    let loaded = parse_case(&text, &[]).unwrap();
    let mut model = Simulation::new(&loaded.case).unwrap();
    let expected = model.run_to_end(|_| {}).unwrap();
    assert_eq!(records.len(), 30);
    for (got, want) in records.iter().zip(&expected) {
        assert_eq!(got.step, want.step as u64);
        assert_eq!(got.force.to_bits(), want.force.to_bits());
        assert_eq!(got.force_h.to_bits(), want.force_h.to_bits());
        assert_eq!(got.force_v.to_bits(), want.force_v.to_bits());
        assert_eq!(got.mass.to_bits(), want.mass.to_bits());
        assert_eq!(got.u_over_d.to_bits(), (want.u / 20.0).to_bits());
        // Every field, in history.csv's order.
        let got = bits(got);
        for (i, (name, value)) in HISTORY.iter().enumerate().skip(1) {
            assert_eq!(got[i], value(want).to_bits(), "{name}");
        }
    }
    let mut last = SoilcutStep::default();
    assert_eq!(unsafe { soilcut_last_step(sim, &mut last) }, SOILCUT_OK);
    assert_eq!(bits(&last), bits(records.last().unwrap()));
    let now = state(sim);
    assert_eq!((now.steps_done, now.steps_total, now.done), (30, 30, 1));
    assert_eq!(now.mass.to_bits(), model.mass().to_bits());
    assert_eq!(now.blade_position, model.blade_position());
    assert_eq!(now.initial_mass, model.initial_mass());

    // The surface is the model's profile.
    let mut len = 0;
    assert_eq!(unsafe { soilcut_surface_len(sim, &mut len) }, SOILCUT_OK);
    let profile = model.profile();
    assert_eq!(len, profile.len());
    let (mut x, mut y, mut ut, mut ridge) = (
        vec![0.0; len],
        vec![0.0; len],
        vec![0.0; len],
        vec![0.0; len],
    );
    let code = unsafe {
        soilcut_surface(
            sim,
            x.as_mut_ptr(),
            y.as_mut_ptr(),
            ut.as_mut_ptr(),
            null_mut(),
            ridge.as_mut_ptr(),
            len,
        )
    };
    assert_eq!(code, SOILCUT_OK);
    for (i, p) in profile.iter().enumerate() {
        assert_eq!(
            (x[i], y[i], ut[i], ridge[i]),
            (p.x, p.y, p.accumulated_shear, p.ridge_height)
        );
    }
    assert!(y.iter().any(|&h| h > 0.0), "the pile has grown");
}

#[test]
fn the_history_header_names_the_records_fields() {
    let header = unsafe { CStr::from_ptr(soilcut_history_header()) };
    assert_eq!(header.to_str().unwrap(), HISTORY_HEADER);
    assert_eq!(
        HISTORY_HEADER.split(',').count() * 8,
        size_of::<SoilcutStep>(),
        "one 8-byte field per column"
    );
    let version = unsafe { CStr::from_ptr(soilcut_version()) };
    assert_eq!(version.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
}

#[test]
fn a_bad_case_names_the_key_and_leaves_no_handle() {
    let (code, message) = create(&short(3), &["blade.rake=10"]).unwrap_err();
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(message.starts_with("blade.rake: "), "{message}");
    let (code, message) = create(&short(3).replace("[run]", "[run]\nspeed = 1"), &[]).unwrap_err();
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(message.starts_with("run.speed: unknown key"), "{message}");
    let (_, message) = create("name = = 1", &[]).unwrap_err();
    assert!(message.starts_with("line 1: "), "{message}");
    let (code, message) = create(&short(3), &["no equals sign"]).unwrap_err();
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(message.contains("key.path=value"), "{message}");

    // Not UTF-8.
    let bytes = b"name = \"\xff\"\0";
    let mut sim = null_mut();
    let code = unsafe { soilcut_new_from_toml(bytes.as_ptr().cast(), null(), 0, &mut sim) };
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(last_error(null()).contains("not UTF-8"));
    assert!(sim.is_null());
}

#[test]
fn a_bad_case_file_names_the_path_and_the_key() {
    let file =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/paper/original.toml");
    let path = CString::new(file.to_str().unwrap()).unwrap();
    let set = CString::new("blade.rake=10").unwrap();
    let sets = [set.as_ptr()];
    let mut sim = null_mut();
    let code = unsafe { soilcut_new_from_file(path.as_ptr(), sets.as_ptr(), 1, &mut sim) };
    assert_eq!(code, SOILCUT_ERR_INPUT);
    let message = last_error(null());
    assert!(
        message.starts_with(path.to_str().unwrap()) && message.contains(": blade.rake: "),
        "{message}"
    );
    let travel = CString::new("run.travel=0.04").unwrap();
    let increment = CString::new("run.increment=0.02").unwrap();
    let sets = [travel.as_ptr(), increment.as_ptr()];
    let code = unsafe { soilcut_new_from_file(path.as_ptr(), sets.as_ptr(), 2, &mut sim) };
    assert_eq!(code, SOILCUT_OK);
    assert_eq!(state(sim).steps_total, 2);
    unsafe { soilcut_free(sim) };

    let missing = CString::new("no-such-folder/case.toml").unwrap();
    let code = unsafe { soilcut_new_from_file(missing.as_ptr(), null(), 0, &mut sim) };
    assert_eq!(code, SOILCUT_ERR_INPUT);
    assert!(last_error(null()).contains("cannot read the case file"));
}

#[test]
fn null_pointers_are_errors() {
    let text = CString::new(short(3)).unwrap();
    let mut sim = null_mut();
    unsafe {
        assert_eq!(
            soilcut_new_from_toml(null(), null(), 0, &mut sim),
            SOILCUT_ERR_NULL
        );
        assert_eq!(last_error(null()), "text is NULL");
        assert_eq!(
            soilcut_new_from_toml(text.as_ptr(), null(), 0, null_mut()),
            SOILCUT_ERR_NULL
        );
        assert_eq!(
            soilcut_new_from_toml(text.as_ptr(), null(), 2, &mut sim),
            SOILCUT_ERR_NULL
        );
        assert_eq!(last_error(null()), "sets is NULL");
        let sets = [null::<c_char>()];
        assert_eq!(
            soilcut_new_from_toml(text.as_ptr(), sets.as_ptr(), 1, &mut sim),
            SOILCUT_ERR_NULL
        );
        assert_eq!(last_error(null()), "sets[0] is NULL");
        assert_eq!(
            soilcut_new_from_file(null(), null(), 0, &mut sim),
            SOILCUT_ERR_NULL
        );
        assert_eq!(soilcut_restore(null(), 4, &mut sim), SOILCUT_ERR_NULL);
        assert!(sim.is_null());

        // Every call on a NULL handle.
        let mut record = SoilcutStep::default();
        let mut state = SoilcutState::default();
        let (mut n, mut x) = (0usize, [0.0f64; 1]);
        let mut made = 0u64;
        for code in [
            soilcut_step(null_mut(), &mut record),
            soilcut_last_step(null(), &mut record),
            soilcut_state(null(), &mut state),
            soilcut_surface_len(null(), &mut n),
            soilcut_surface(
                null(),
                x.as_mut_ptr(),
                x.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
                1,
            ),
            soilcut_warnings(null(), null_mut(), 0, &mut n),
            soilcut_snapshot(null(), null_mut(), 0, &mut n),
            soilcut_advance_to(null_mut(), 1.0, f64::NAN, None, null_mut(), &mut made),
        ] {
            assert_eq!(code, SOILCUT_ERR_NULL);
            assert_eq!(last_error(null()), "sim is NULL");
        }
        soilcut_free(null_mut());

        // NULL outputs on a live handle.
        assert_eq!(
            soilcut_new_from_toml(text.as_ptr(), null(), 0, &mut sim),
            SOILCUT_OK
        );
        let _free = Free(sim);
        assert_eq!(soilcut_state(sim, null_mut()), SOILCUT_ERR_NULL);
        assert_eq!(last_error(sim), "out is NULL");
        assert_eq!(soilcut_last_step(sim, null_mut()), SOILCUT_ERR_NULL);
        assert_eq!(soilcut_surface_len(sim, null_mut()), SOILCUT_ERR_NULL);
        assert_eq!(
            soilcut_snapshot(sim, null_mut(), 0, null_mut()),
            SOILCUT_ERR_NULL
        );
        assert_eq!(
            soilcut_snapshot(sim, null_mut(), 10, &mut n),
            SOILCUT_ERR_NULL
        );
        assert_eq!(
            soilcut_warnings(sim, null_mut(), 0, null_mut()),
            SOILCUT_ERR_NULL
        );
        assert_eq!(soilcut_surface_len(sim, &mut n), SOILCUT_OK);
        let mut y = vec![0.0; n];
        assert_eq!(
            soilcut_surface(
                sim,
                null_mut(),
                y.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
                n
            ),
            SOILCUT_ERR_NULL
        );
        assert_eq!(last_error(sim), "x is NULL");
        // A misaligned array is refused too.
        let mut raw = vec![0u8; 8 * n + 8];
        let odd = raw.as_mut_ptr().add(1).cast::<f64>();
        assert_eq!(
            soilcut_surface(
                sim,
                odd,
                y.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
                n
            ),
            SOILCUT_ERR_NULL
        );
        assert_eq!(last_error(sim), "x is misaligned");
        // The record is optional to soilcut_step.
        assert_eq!(soilcut_step(sim, null_mut()), SOILCUT_OK);
        assert_eq!(soilcut_last_step(sim, &mut record), SOILCUT_OK);
        assert_eq!(record.step, 1);
    }
}

#[test]
fn wrong_lengths_are_errors_and_write_nothing() {
    let sim = create(&short(5), &[]).unwrap();
    let _free = Free(sim);
    step(sim);
    let mut n = 0;
    assert_eq!(unsafe { soilcut_surface_len(sim, &mut n) }, SOILCUT_OK);
    for len in [0, n - 1, n + 1] {
        let (mut x, mut y) = (vec![-7.0; n + 1], vec![-7.0; n + 1]);
        let code = unsafe {
            soilcut_surface(
                sim,
                x.as_mut_ptr(),
                y.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
                len,
            )
        };
        assert_eq!(code, SOILCUT_ERR_LENGTH);
        assert_eq!(
            last_error(sim),
            format!("len is {len} but the surface has {n} points (soilcut_surface_len)")
        );
        assert!(x.iter().chain(&y).all(|&v| v == -7.0), "nothing written");
    }

    // A snapshot buffer one byte short.
    let mut needed = 0;
    assert_eq!(
        unsafe { soilcut_snapshot(sim, null_mut(), 0, &mut needed) },
        SOILCUT_OK
    );
    let mut buf = vec![0xAAu8; needed - 1];
    let mut again = 0;
    let code = unsafe { soilcut_snapshot(sim, buf.as_mut_ptr(), buf.len(), &mut again) };
    assert_eq!(code, SOILCUT_ERR_LENGTH);
    assert_eq!(again, needed, "the length needed is told on failure");
    assert!(buf.iter().all(|&b| b == 0xAA));
}

#[test]
fn out_of_order_calls_are_state_errors() {
    let sim = create(&short(2), &[]).unwrap();
    let _free = Free(sim);
    let mut record = SoilcutStep::default();
    assert_eq!(
        unsafe { soilcut_last_step(sim, &mut record) },
        SOILCUT_ERR_STATE
    );
    assert_eq!(last_error(sim), "no increment has been made yet");
    step(sim);
    let second = step(sim);
    assert_eq!(state(sim).done, 1);
    // The model's rule (`StepError::TravelReached`), its own status.
    assert_eq!(
        unsafe { soilcut_step(sim, &mut record) },
        SOILCUT_ERR_TRAVEL
    );
    assert!(
        last_error(sim).starts_with("the case's travel has been reached (2 increments)"),
        "{}",
        last_error(sim)
    );
    assert_eq!(record, SoilcutStep::default(), "nothing written");
    // The thread's message is the same; the state is unchanged.
    assert_eq!(last_error(null()), last_error(sim));
    assert_eq!(state(sim).steps_done, 2);
    assert_eq!(unsafe { soilcut_last_step(sim, &mut record) }, SOILCUT_OK);
    assert_eq!(bits(&record), bits(&second));
}

#[test]
fn nan_and_positions_behind_the_blade_are_argument_errors() {
    let sim = create(&short(20), &[]).unwrap();
    let _free = Free(sim);
    let mut made = 99;
    for x in [f64::NAN, f64::INFINITY, -1.0] {
        let code = unsafe { soilcut_advance_to(sim, x, f64::NAN, None, null_mut(), &mut made) };
        assert_eq!(code, SOILCUT_ERR_ARGUMENT, "x = {x}");
        assert!(last_error(sim).contains("x = "), "{}", last_error(sim));
    }
    assert_eq!(made, 99, "nothing made, nothing written");
    assert_eq!(state(sim).steps_done, 0);
    assert_eq!(
        unsafe { soilcut_advance_to(sim, 0.2, f64::NAN, None, null_mut(), &mut made) },
        SOILCUT_OK
    );
    assert_eq!(made, 5);
    let code = unsafe { soilcut_advance_to(sim, 0.1, f64::NAN, None, null_mut(), &mut made) };
    assert_eq!(code, SOILCUT_ERR_ARGUMENT);
    assert!(
        last_error(sim).contains("behind the blade"),
        "{}",
        last_error(sim)
    );
    for depth in [f64::INFINITY, -3.0, 0.0, 1e9] {
        let code = unsafe { soilcut_advance_to(sim, 0.4, depth, None, null_mut(), &mut made) };
        assert_eq!(code, SOILCUT_ERR_ARGUMENT, "depth = {depth}");
        assert!(last_error(sim).contains("depth = "), "{}", last_error(sim));
    }
    assert_eq!(state(sim).steps_done, 5);
}

/// The records of the case `short(steps)` stepped to its end.
fn stepped(steps: usize) -> Vec<SoilcutStep> {
    let sim = create(&short(steps), &[]).unwrap();
    let _free = Free(sim);
    steps_to_end(sim)
}

unsafe extern "C" fn collect(record: *const SoilcutStep, user: *mut c_void) {
    let records = unsafe { &mut *user.cast::<Vec<SoilcutStep>>() };
    records.push(unsafe { *record });
}

#[test]
fn advance_to_makes_the_increments_of_stepping() {
    let stepped = stepped(20);
    let sim = create(&short(20), &[]).unwrap();
    let _free = Free(sim);
    let mut records: Vec<SoilcutStep> = Vec::new();
    let user = (&mut records as *mut Vec<SoilcutStep>).cast::<c_void>();
    let mut made = 0;
    // 0.3 is 7.5 increments: the blade goes to the 8th, the first whole
    // increment at or beyond it.
    for x in [0.3, 0.3, 0.8] {
        let code = unsafe { soilcut_advance_to(sim, x, f64::NAN, Some(collect), user, &mut made) };
        assert_eq!(code, SOILCUT_OK, "{}", last_error(sim));
    }
    assert_eq!(made, 12);
    assert_eq!(records.len(), 20);
    assert_eq!(state(sim).blade_position, 0.8);
    let got: Vec<_> = records.iter().map(bits).collect();
    let want: Vec<_> = stepped.iter().map(bits).collect();
    assert_eq!(got, want);

    // Beyond the travel, with the tip steered shallower.
    let code = unsafe { soilcut_advance_to(sim, 1.0, 15.0, None, null_mut(), &mut made) };
    assert_eq!(code, SOILCUT_OK, "{}", last_error(sim));
    assert_eq!(made, 5);
    let now = state(sim);
    assert_eq!(
        (now.steps_done, now.steps_total, now.tip_depth),
        (25, 25, 15.0)
    );
}

/// What `during` sees from inside `soilcut_advance_to`'s callback.
struct During {
    sim: *mut SoilcutSimulation,
    /// (record, state then, last step then) per call.
    seen: Vec<(SoilcutStep, SoilcutState, SoilcutStep)>,
    /// Codes of the calls the callback may not make on its handle.
    refused: Vec<i32>,
}

unsafe extern "C" fn during(record: *const SoilcutStep, user: *mut c_void) {
    let during = unsafe { &mut *user.cast::<During>() };
    let sim = during.sim;
    let (mut now, mut last) = (SoilcutState::default(), SoilcutStep::default());
    assert_eq!(unsafe { soilcut_state(sim, &mut now) }, SOILCUT_OK);
    assert_eq!(unsafe { soilcut_last_step(sim, &mut last) }, SOILCUT_OK);
    during.seen.push((unsafe { *record }, now, last));
    let mut needed = 0;
    during.refused.extend([
        unsafe { soilcut_step(sim, null_mut()) },
        unsafe { soilcut_snapshot(sim, null_mut(), 0, &mut needed) },
        unsafe { soilcut_advance_to(sim, 10.0, f64::NAN, None, null_mut(), null_mut()) },
    ]);
    // Refused too: the handle outlives its callback.
    unsafe { soilcut_free(sim) };
}

/// Each record reaches the callback as its increment is made: the state
/// the callback reads has made that increment and no more.
#[test]
fn advance_to_calls_back_as_each_increment_is_made() {
    let stepped = stepped(8);
    let sim = create(&short(8), &[]).unwrap();
    let _free = Free(sim);
    let mut seen = During {
        sim,
        seen: Vec::new(),
        refused: Vec::new(),
    };
    let user = (&mut seen as *mut During).cast::<c_void>();
    let mut made = 0;
    let code = unsafe { soilcut_advance_to(sim, 0.32, f64::NAN, Some(during), user, &mut made) };
    assert_eq!(code, SOILCUT_OK, "{}", last_error(sim));
    assert_eq!((made, seen.seen.len()), (8, 8));
    for ((record, now, last), want) in seen.seen.iter().zip(&stepped) {
        assert_eq!(bits(record), bits(want));
        assert_eq!(bits(last), bits(want));
        assert_eq!(now.steps_done, record.step);
        assert!((now.blade_position - (record.u + 0.04)).abs() < 1e-12);
        assert_eq!(now.mass, record.mass);
    }
    assert!(seen.refused.iter().all(|&c| c == SOILCUT_ERR_STATE));
    assert!(last_error(sim).contains("on_step"), "{}", last_error(sim));
    // After the advance the handle is whole again.
    assert_eq!(state(sim).steps_done, 8);
}

#[test]
fn a_restored_snapshot_continues_bit_for_bit() {
    let sim = create(&short(40), &[]).unwrap();
    let _free = Free(sim);
    for _ in 0..25 {
        step(sim);
    }
    let mut needed = 0;
    assert_eq!(
        unsafe { soilcut_snapshot(sim, null_mut(), 0, &mut needed) },
        SOILCUT_OK
    );
    let mut bytes = vec![0u8; needed + 10];
    let code = unsafe { soilcut_snapshot(sim, bytes.as_mut_ptr(), bytes.len(), &mut needed) };
    assert_eq!(code, SOILCUT_OK);
    bytes.truncate(needed);
    let rest = steps_to_end(sim);

    let mut copy = null_mut();
    assert_eq!(
        unsafe { soilcut_restore(bytes.as_ptr(), bytes.len(), &mut copy) },
        SOILCUT_OK
    );
    let _free_copy = Free(copy);
    assert_eq!(state(copy).steps_done, 25);
    let mut record = SoilcutStep::default();
    assert_eq!(
        unsafe { soilcut_last_step(copy, &mut record) },
        SOILCUT_ERR_STATE
    );
    let again = steps_to_end(copy);
    assert_eq!(
        again.iter().map(bits).collect::<Vec<_>>(),
        rest.iter().map(bits).collect::<Vec<_>>()
    );

    // Changed, cut and foreign bytes are input errors.
    let mut bad = null_mut();
    let mut spoiled = bytes.clone();
    spoiled[needed / 2] ^= 1;
    for (garbage, what) in [
        (&spoiled[..], "corrupt"),
        (&bytes[..needed - 1], ""),
        (&b"not a snapshot at all"[..], "not a soilcut snapshot"),
        (&[][..], ""),
    ] {
        let code = unsafe { soilcut_restore(garbage.as_ptr(), garbage.len(), &mut bad) };
        assert_eq!(code, SOILCUT_ERR_INPUT);
        assert!(last_error(null()).contains(what), "{}", last_error(null()));
        assert!(bad.is_null());
    }
}

#[test]
fn last_error_truncates_to_the_buffer_and_tells_the_length() {
    let (_, message) = create(&short(3), &["blade.rake=10"]).unwrap_err();
    let needed = unsafe { soilcut_last_error(null(), null_mut(), 0) };
    assert_eq!(needed, message.len() + 1);
    let mut buf = [b'x' as c_char; 11];
    let n = unsafe { soilcut_last_error(null(), buf.as_mut_ptr(), buf.len()) };
    assert_eq!(n, needed);
    let cut = unsafe { CStr::from_ptr(buf.as_ptr()) }.to_str().unwrap();
    assert_eq!(cut, &message[..10]);
    // NULL with a length is taken as no buffer.
    assert_eq!(unsafe { soilcut_last_error(null(), null_mut(), 5) }, needed);
}

#[test]
fn warnings_are_the_command_lines() {
    let sim = create(&short(2), &["blade.width=1"]).unwrap();
    let _free = Free(sim);
    let mut needed = 0;
    assert_eq!(
        unsafe { soilcut_warnings(sim, null_mut(), 0, &mut needed) },
        SOILCUT_OK
    );
    let mut buf = vec![0 as c_char; needed];
    assert_eq!(
        unsafe { soilcut_warnings(sim, buf.as_mut_ptr(), buf.len(), &mut needed) },
        SOILCUT_OK
    );
    let text = unsafe { CStr::from_ptr(buf.as_ptr()) }.to_str().unwrap();
    let loaded = parse_case(&short(2), &["blade.width=1".parse().unwrap()]).unwrap();
    let expected = loaded.case.accuracy_warnings();
    assert!(!expected.is_empty());
    assert_eq!(text, expected.join("\n"));

    let plain = create(&short(2), &[]).unwrap();
    let _free_plain = Free(plain);
    assert_eq!(
        unsafe { soilcut_warnings(plain, null_mut(), 0, &mut needed) },
        SOILCUT_OK
    );
    assert_eq!(needed, 1);
}

#[test]
fn arbitrary_text_never_panics() {
    // Bytes a fuzzer might send: every call returns a status.
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let base = short(2);
    for _ in 0..300 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let mut bytes = base.clone().into_bytes();
        let at = (seed % bytes.len() as u64) as usize;
        bytes[at] = (seed >> 32) as u8;
        bytes.retain(|&b| b != 0);
        let text = CString::new(bytes).unwrap();
        let mut sim = null_mut();
        let code = unsafe { soilcut_new_from_toml(text.as_ptr(), null(), 0, &mut sim) };
        assert!(
            [SOILCUT_OK, SOILCUT_ERR_INPUT].contains(&code),
            "{code}: {}",
            last_error(null())
        );
        if code == SOILCUT_OK {
            let mut record = SoilcutStep::default();
            let code = unsafe { soilcut_step(sim, &mut record) };
            assert!([SOILCUT_OK, SOILCUT_ERR_STEP].contains(&code), "{code}");
            unsafe { soilcut_free(sim) };
        }
    }
}

/// A handle crossing threads, as a C caller may pass it.
#[derive(Clone, Copy)]
struct Shared(*mut SoilcutSimulation);
unsafe impl Send for Shared {}

#[test]
fn two_handles_on_two_threads_at_once() {
    let reference = {
        let sim = create(&short(60), &[]).unwrap();
        let _free = Free(sim);
        steps_to_end(sim).iter().map(bits).collect::<Vec<_>>()
    };
    let handles = [
        create(&short(60), &[]).unwrap(),
        create(&short(60), &[]).unwrap(),
    ]
    .map(Shared);
    let runs: Vec<_> = std::thread::scope(|s| {
        let threads: Vec<_> = handles
            .iter()
            .map(|&h| {
                s.spawn(move || {
                    let h = h;
                    steps_to_end(h.0).iter().map(bits).collect::<Vec<_>>()
                })
            })
            .collect();
        threads.into_iter().map(|t| t.join().unwrap()).collect()
    });
    for run in runs {
        assert_eq!(run, reference);
    }
    for h in handles {
        unsafe { soilcut_free(h.0) };
    }
}

#[test]
fn one_handle_on_two_threads_is_serialised() {
    let sim = Shared(create(&short(60), &[]).unwrap());
    let mut numbers: Vec<u64> = std::thread::scope(|s| {
        let threads: Vec<_> = (0..2)
            .map(|_| {
                s.spawn(move || {
                    let sim = sim;
                    let mut mine = Vec::new();
                    loop {
                        let mut record = SoilcutStep::default();
                        match unsafe { soilcut_step(sim.0, &mut record) } {
                            SOILCUT_OK => mine.push(record.step),
                            SOILCUT_ERR_TRAVEL => return mine,
                            code => panic!("{code}: {}", last_error(sim.0)),
                        }
                        let _ = state(sim.0);
                    }
                })
            })
            .collect();
        threads
            .into_iter()
            .flat_map(|t| t.join().unwrap())
            .collect()
    });
    numbers.sort_unstable();
    assert_eq!(numbers, (1..=60).collect::<Vec<_>>(), "each increment once");
    unsafe { soilcut_free(sim.0) };
}
