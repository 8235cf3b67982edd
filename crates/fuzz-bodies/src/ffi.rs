//! The body of the `ffi_calls` target: the fuzzer's bytes as a sequence
//! of C ABI calls (`soilcut-ffi`) with arbitrary arguments, made as a C
//! caller would make them, on two handle slots.
//!
//! What it asserts of every call: no panic escapes (`SOILCUT_ERR_PANIC` is
//! never returned); a failure is one of the documented negative codes with
//! a non-empty one-line message, on the handle and the thread alike; calls
//! out of order (a step after the end, the last step before any, a call on
//! a freed or never-made handle, a read with a misaligned pointer or a
//! wrong length) get the code their documentation names; what a
//! successful read gives (records, state, surface) is finite; a text the
//! Rust reader accepts is accepted by the C constructor and the reverse;
//! a snapshot restores, a changed one does not.
//!
//! Cost: a handle is made only for a case of at most `RUN_NODES` nodes and
//! stepped only within the budget of the other targets (and
//! `RUN_NODES_PER_DEPTH`), for at most [`FFI_STEPS`] increments per input
//! in all (`soilcut_advance_to`'s position is brought within it), and an
//! input makes at most [`FFI_CALLS`] calls.

use crate::{Outcome, BASES, RUN_NODES, RUN_NODES_PER_DEPTH};
use soilcut_ffi::*;
use soilcut_io::{parse_case, LoadedCase, Override};
use soilcut_model::{Case, Simulation, MAGNITUDE};
use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::ptr::{null, null_mut};

/// Increments one input may make, over all its handles.
pub const FFI_STEPS: usize = 6;

/// Calls one input may make (each op is one call, or two with its probe).
pub const FFI_CALLS: usize = 48;

/// Handles an input juggles: two, so that one can be restored from the
/// other's snapshot and freed while the other runs.
const SLOTS: usize = 2;

/// Every status an entry point may return.
const CODES: [c_int; 9] = [
    SOILCUT_OK,
    SOILCUT_ERR_INPUT,
    SOILCUT_ERR_NULL,
    SOILCUT_ERR_LENGTH,
    SOILCUT_ERR_ARGUMENT,
    SOILCUT_ERR_STATE,
    SOILCUT_ERR_STEP,
    SOILCUT_ERR_PANIC,
    SOILCUT_ERR_TRAVEL,
];

/// The numbers a number argument is drawn from (or 8 raw bytes): the
/// special values, and lengths near those of the shipped cases.
const NUMBERS: [f64; 24] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    -1.0,
    -0.0,
    0.0,
    5e-324,
    1e-300,
    0.02,
    0.04,
    0.1,
    0.2,
    0.3,
    0.5,
    1.0,
    2.0,
    10.0,
    15.0,
    20.0,
    40.0,
    1e6,
    1e19,
    1e21,
    f64::MAX,
];

/// The fuzzer's bytes, read as arguments; past the end every read is 0.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn u8(&mut self) -> u8 {
        let (&b, rest) = self.0.split_first().unwrap_or((&0, &[]));
        self.0 = rest;
        b
    }

    fn u16(&mut self) -> usize {
        usize::from(self.u8()) | usize::from(self.u8()) << 8
    }

    fn take(&mut self, n: usize) -> &[u8] {
        let (taken, rest) = self.0.split_at(n.min(self.0.len()));
        self.0 = rest;
        taken
    }

    /// A number: from [`NUMBERS`], or (high bit set) 8 raw bytes.
    fn number(&mut self) -> f64 {
        let tag = self.u8();
        if tag & 0x80 == 0 {
            return NUMBERS[usize::from(tag) % NUMBERS.len()];
        }
        let mut raw = [0u8; 8];
        let taken = self.take(8);
        raw[..taken.len()].copy_from_slice(taken);
        f64::from_le_bytes(raw)
    }

    /// A buffer length near `needed`: 0, it, one less, one more, or any
    /// small number.
    fn length(&mut self, needed: usize) -> usize {
        match self.u8() % 5 {
            0 => 0,
            1 => needed,
            2 => needed.saturating_sub(1),
            3 => needed + 1,
            _ => usize::from(self.u8()),
        }
    }

    /// How a pointer argument is given.
    fn pointer(&mut self) -> Pointer {
        match self.u8() % 4 {
            0 => Pointer::Null,
            1 => Pointer::Misaligned,
            _ => Pointer::Valid,
        }
    }

    /// A NUL-terminated string of up to `max` bytes (cut at a NUL).
    fn text(&mut self, max: usize) -> CString {
        let n = self.u16() % (max + 1);
        let bytes = self.take(n);
        let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
        CString::new(&bytes[..end]).expect("cut at the first NUL")
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Pointer {
    Null,
    Misaligned,
    Valid,
}

/// Storage for one `T` written through a pointer given as `Pointer`.
struct Out<T> {
    /// Room for a `T` at offset 0 (aligned) or 1 (misaligned).
    storage: Vec<u64>,
    how: Pointer,
    _t: std::marker::PhantomData<T>,
}

impl<T: Copy> Out<T> {
    fn new(how: Pointer) -> Self {
        Out {
            storage: vec![0; size_of::<T>() / 8 + 2],
            how,
            _t: std::marker::PhantomData,
        }
    }

    fn ptr(&mut self) -> *mut T {
        let base = self.storage.as_mut_ptr().cast::<u8>();
        match self.how {
            Pointer::Null => null_mut(),
            // Offset 1 of a u64 array is misaligned for every T here.
            Pointer::Misaligned => base.wrapping_add(1).cast(),
            Pointer::Valid => base.cast(),
        }
    }

    /// The value written, for a valid pointer.
    fn get(&self) -> Option<T> {
        let valid = self.how == Pointer::Valid;
        // SAFETY: aligned storage of at least size_of::<T>() bytes, and T
        // is plain data for which any bytes the ABI wrote (or zeroes) are
        // a value.
        valid.then(|| unsafe { self.storage.as_ptr().cast::<T>().read() })
    }
}

/// A handle and what the body knows of it.
struct Slot {
    sim: *mut SoilcutSimulation,
    /// Its case's increment rule (`Case::increments_to`): steering never
    /// changes the increment.
    case: Case,
    /// Within the stepping budget.
    steppable: bool,
    /// Whether an increment has been made since it was created.
    has_last: bool,
}

/// The interpreter's state.
struct Calls<'a> {
    input: Bytes<'a>,
    slots: [Option<Slot>; SLOTS],
    /// The latest snapshot taken.
    taken: Option<Vec<u8>>,
    /// Increments left to the input.
    steps_left: usize,
    reached: Outcome,
}

/// Target `ffi_calls`: the bytes as C ABI calls (module documentation).
pub fn ffi_calls(data: &[u8]) -> Outcome {
    let mut calls = Calls {
        input: Bytes(data),
        slots: [None, None],
        taken: None,
        steps_left: FFI_STEPS,
        reached: Outcome::Skipped,
    };
    for _ in 0..FFI_CALLS {
        if calls.input.0.is_empty() {
            break;
        }
        calls.op();
    }
    for i in 0..SLOTS {
        calls.free(i);
    }
    calls.reached
}

impl Calls<'_> {
    fn reach(&mut self, outcome: Outcome) {
        self.reached = self.reached.max(outcome);
    }

    /// The slot an op names: `SLOTS` and empty slots give a NULL handle.
    fn slot(&mut self) -> (usize, *mut SoilcutSimulation) {
        let i = usize::from(self.input.u8()) % (SLOTS + 1);
        let sim = self.slots.get(i).and_then(Option::as_ref);
        (i, sim.map_or(null_mut(), |s| s.sim))
    }

    fn op(&mut self) {
        match self.input.u8() % 13 {
            0 => self.new_from_toml(),
            1 => self.new_from_base(),
            2 => self.new_from_file(),
            3 => self.step(),
            4 => self.advance_to(),
            5 => self.last_step(),
            6 => self.state_op(),
            7 => self.surface(),
            8 => self.snapshot(),
            9 => self.restore(),
            10 => self.last_error(),
            11 => self.warnings(),
            _ => {
                let (i, _) = self.slot();
                self.free(i);
            }
        }
    }

    /// Checks `code` is one of `allowed` (never a panic), and a failure's
    /// message; counts a refusal.
    fn expect(
        &mut self,
        code: c_int,
        allowed: &[c_int],
        sim: *const SoilcutSimulation,
        what: &str,
    ) {
        assert_ne!(code, SOILCUT_ERR_PANIC, "{what}: {}", message(sim));
        assert!(CODES.contains(&code), "{what}: unknown code {code}");
        assert!(
            allowed.contains(&code),
            "{what}: code {code}, expected one of {allowed:?}: {}",
            message(sim)
        );
        if code != SOILCUT_OK {
            check_failure(sim, what);
            self.reach(Outcome::Refused);
        }
    }

    fn free(&mut self, i: usize) {
        if let Some(slot) = self.slots.get_mut(i).and_then(Option::take) {
            // SAFETY: a live handle, freed once (the slot is emptied).
            unsafe { soilcut_free(slot.sim) };
        }
    }

    /// Overrides from the input: up to 3 `--set` strings.
    fn sets(&mut self) -> Vec<CString> {
        let n = self.input.u8() % 4;
        (0..n).map(|_| self.input.text(64)).collect()
    }

    fn new_from_toml(&mut self) {
        let text = self.input.text(4096);
        let sets = self.sets();
        self.create(text, sets);
    }

    fn new_from_base(&mut self) {
        let base = BASES[usize::from(self.input.u8()) % BASES.len()];
        let sets = self.sets();
        self.create(CString::new(base).expect("no NUL in a case"), sets);
    }

    /// Makes a handle of `text` with `sets` in a slot, if the Rust reader
    /// finds it within the budget; the C constructor must agree with it.
    fn create(&mut self, text: CString, sets: Vec<CString>) {
        let (i, _) = self.slot();
        let read = read_like_c(&text, &sets);
        if let Ok(loaded) = &read {
            if loaded.case.initial_nodes() > RUN_NODES {
                return;
            }
        }
        self.free(i);
        let pointers: Vec<*const c_char> = sets.iter().map(|s| s.as_ptr()).collect();
        let mut sim = null_mut();
        // SAFETY: NUL-terminated strings, `pointers.len()` of them.
        let code = unsafe {
            soilcut_new_from_toml(text.as_ptr(), pointers.as_ptr(), pointers.len(), &mut sim)
        };
        match read {
            Ok(loaded) => {
                let what = "soilcut_new_from_toml of a case Rust reads";
                self.expect(code, &[SOILCUT_OK], null(), what);
                self.keep(i, sim, loaded.case.into_case());
            }
            Err(e) => {
                let what = format!("soilcut_new_from_toml of a case Rust refuses ({e})");
                self.expect(code, &[SOILCUT_ERR_INPUT], null(), &what);
                assert!(sim.is_null(), "a failed constructor leaves NULL");
            }
        }
    }

    /// Keeps the handle `sim` of `case` in slot `i` (which is empty).
    fn keep(&mut self, i: usize, sim: *mut SoilcutSimulation, case: Case) {
        assert!(!sim.is_null());
        let steppable = steppable(&case);
        if let Some(slot) = self.slots.get_mut(i) {
            *slot = Some(Slot {
                sim,
                case,
                steppable,
                has_last: false,
            });
        } else {
            // SAFETY: the live handle just made; no slot keeps it.
            unsafe { soilcut_free(sim) };
        }
        self.reach(Outcome::Created);
    }

    fn new_from_file(&mut self) {
        let path = CString::new("no-such-dir/case.toml").expect("no NUL");
        let p = if self.input.u8().is_multiple_of(2) {
            null()
        } else {
            path.as_ptr()
        };
        let mut sim = null_mut();
        // SAFETY: NULL or a NUL-terminated string; no overrides.
        let code = unsafe { soilcut_new_from_file(p, null(), 0, &mut sim) };
        let allowed = if p.is_null() {
            SOILCUT_ERR_NULL
        } else {
            SOILCUT_ERR_INPUT
        };
        self.expect(code, &[allowed], null(), "soilcut_new_from_file");
        assert!(sim.is_null());
    }

    /// The state of a live handle, read as a probe (it must succeed).
    fn probe(sim: *mut SoilcutSimulation) -> SoilcutState {
        let mut state = SoilcutState::default();
        // SAFETY: a live handle, a valid out pointer.
        let code = unsafe { soilcut_state(sim, &mut state) };
        assert_eq!(code, SOILCUT_OK, "soilcut_state: {}", message(sim));
        check_state(&state);
        state
    }

    fn step(&mut self) {
        let (i, sim) = self.slot();
        let mut record = Out::<SoilcutStep>::new(self.input.pointer());
        let allowed = if sim.is_null() || record.how == Pointer::Misaligned {
            SOILCUT_ERR_NULL
        } else if Self::probe(sim).done != 0 {
            SOILCUT_ERR_TRAVEL
        } else if self.slots[i].as_ref().is_some_and(|s| s.steppable) && self.steps_left > 0 {
            SOILCUT_OK
        } else {
            return;
        };
        // SAFETY: NULL or a live handle; NULL, misaligned or valid storage.
        let code = unsafe { soilcut_step(sim, record.ptr()) };
        let allowed: &[c_int] = match allowed {
            SOILCUT_OK => &[SOILCUT_OK, SOILCUT_ERR_STEP],
            _ => &[allowed],
        };
        self.expect(code, allowed, sim, "soilcut_step");
        if code == SOILCUT_OK {
            self.steps_left -= 1;
            self.slots[i].as_mut().expect("stepped").has_last = true;
            if let Some(r) = record.get() {
                check_step(&r);
            }
            self.reach(Outcome::Stepped);
        }
    }

    fn last_step(&mut self) {
        let (i, sim) = self.slot();
        let mut record = Out::<SoilcutStep>::new(self.input.pointer());
        let allowed = if sim.is_null() || record.how != Pointer::Valid {
            SOILCUT_ERR_NULL
        } else if self.slots[i].as_ref().is_some_and(|s| s.has_last) {
            SOILCUT_OK
        } else {
            SOILCUT_ERR_STATE
        };
        // SAFETY: NULL or a live handle; NULL, misaligned or valid storage.
        let code = unsafe { soilcut_last_step(sim, record.ptr()) };
        self.expect(code, &[allowed], sim, "soilcut_last_step");
        if let (SOILCUT_OK, Some(r)) = (code, record.get()) {
            check_step(&r);
        }
    }

    fn state_op(&mut self) {
        let (_, sim) = self.slot();
        let mut out = Out::<SoilcutState>::new(self.input.pointer());
        let allowed = if sim.is_null() || out.how != Pointer::Valid {
            SOILCUT_ERR_NULL
        } else {
            SOILCUT_OK
        };
        // SAFETY: NULL or a live handle; NULL, misaligned or valid storage.
        let code = unsafe { soilcut_state(sim, out.ptr()) };
        self.expect(code, &[allowed], sim, "soilcut_state");
        if let (SOILCUT_OK, Some(state)) = (code, out.get()) {
            check_state(&state);
        }
    }

    fn surface(&mut self) {
        let (_, sim) = self.slot();
        let mut n = Out::<usize>::new(self.input.pointer());
        // SAFETY: NULL or a live handle; NULL, misaligned or valid storage.
        let code = unsafe { soilcut_surface_len(sim, n.ptr()) };
        let allowed = if sim.is_null() || n.how != Pointer::Valid {
            SOILCUT_ERR_NULL
        } else {
            SOILCUT_OK
        };
        self.expect(code, &[allowed], sim, "soilcut_surface_len");
        let needed = n.get().unwrap_or(0);
        let len = self.input.length(needed);
        // Which of the five arrays are given (x and y are required).
        let given = self.input.u8();
        let mut columns: Vec<Vec<f64>> = (0..5).map(|_| vec![f64::NAN; len]).collect();
        let pointers: Vec<*mut f64> = columns
            .iter_mut()
            .enumerate()
            .map(|(k, c)| {
                if given & (1 << k) == 0 {
                    null_mut()
                } else {
                    c.as_mut_ptr()
                }
            })
            .collect();
        let allowed = if sim.is_null() || given & 3 != 3 {
            SOILCUT_ERR_NULL
        } else if sim_len_differs(sim, len) {
            SOILCUT_ERR_LENGTH
        } else {
            SOILCUT_OK
        };
        let [x, y, shear, weight, ridge] = pointers[..] else {
            unreachable!("five columns")
        };
        // SAFETY: NULL or a live handle; each array NULL or of `len`
        // doubles.
        let code = unsafe { soilcut_surface(sim, x, y, shear, weight, ridge, len) };
        self.expect(code, &[allowed], sim, "soilcut_surface");
        if code == SOILCUT_OK {
            for (k, column) in columns.iter().enumerate() {
                if given & (1 << k) != 0 {
                    assert!(column.iter().all(|v| v.is_finite()), "surface column {k}");
                }
            }
        }
    }

    fn snapshot(&mut self) {
        let (_, sim) = self.slot();
        let needed_at = self.input.pointer();
        let mut needed = Out::<usize>::new(needed_at);
        let size = if sim.is_null() { 0 } else { snapshot_len(sim) };
        let len = self.input.length(size);
        let with_buf = !self.input.u8().is_multiple_of(4);
        let mut buf = vec![0u8; len];
        let p = if with_buf {
            buf.as_mut_ptr()
        } else {
            null_mut()
        };
        let allowed = if sim.is_null() || needed_at != Pointer::Valid || (!with_buf && len > 0) {
            SOILCUT_ERR_NULL
        } else if with_buf && len < size {
            SOILCUT_ERR_LENGTH
        } else {
            SOILCUT_OK
        };
        // SAFETY: NULL or a live handle; `buf` NULL or of `len` bytes.
        let code = unsafe { soilcut_snapshot(sim, p, len, needed.ptr()) };
        self.expect(code, &[allowed], sim, "soilcut_snapshot");
        if code == SOILCUT_OK && with_buf {
            assert_eq!(needed.get(), Some(size));
            buf.truncate(size);
            self.taken = Some(buf);
        }
    }

    fn restore(&mut self) {
        let (i, _) = self.slot();
        let how = self.input.u8() % 5;
        let mut bytes = self.taken.clone().unwrap_or_default();
        let intact = how == 0 && self.taken.is_some();
        match how {
            1 if !bytes.is_empty() => {
                let at = self.input.u16() % bytes.len();
                bytes[at] ^= self.input.u8() | 1;
            }
            2 => bytes.truncate(self.input.u16()),
            3 => {
                let n = self.input.u16() % 513;
                bytes = self.input.take(n).to_vec();
            }
            _ => {}
        }
        let null_bytes = how == 4;
        let len = if null_bytes {
            1 + usize::from(self.input.u8())
        } else {
            bytes.len()
        };
        let p = if null_bytes { null() } else { bytes.as_ptr() };
        self.free(i);
        let mut sim = null_mut();
        // SAFETY: NULL or `len` readable bytes.
        let code = unsafe { soilcut_restore(p, len, &mut sim) };
        if null_bytes {
            self.expect(code, &[SOILCUT_ERR_NULL], null(), "soilcut_restore of NULL");
            return;
        }
        // What the model makes of the same bytes decides the outcome.
        let model = Simulation::from_snapshot(&bytes);
        let allowed = if model.is_ok() {
            SOILCUT_OK
        } else {
            SOILCUT_ERR_INPUT
        };
        if intact {
            assert_eq!(allowed, SOILCUT_OK, "a snapshot taken does not restore");
        }
        self.expect(code, &[allowed], null(), "soilcut_restore");
        if let Ok(restored) = model {
            let case = restored.case().clone().into_case();
            self.keep(i, sim, case);
            self.reach(Outcome::Restored);
        }
    }

    fn last_error(&mut self) {
        let (_, sim) = self.slot();
        let needed = message(sim).len() + 1;
        let len = self.input.length(needed);
        let mut buf = vec![0x7f as c_char; len];
        let p = if len > 0 || self.input.u8().is_multiple_of(2) {
            buf.as_mut_ptr()
        } else {
            null_mut()
        };
        // SAFETY: NULL or a live handle; `buf` of `len` bytes.
        let got = unsafe { soilcut_last_error(sim, p, len) };
        assert_eq!(got, needed, "soilcut_last_error's length");
        if len > 0 {
            assert!(buf.contains(&0), "soilcut_last_error: not NUL-terminated");
        }
    }

    fn warnings(&mut self) {
        let (_, sim) = self.slot();
        let needed_at = self.input.pointer();
        let mut needed = Out::<usize>::new(needed_at);
        let len = self.input.length(64);
        let mut buf = vec![0 as c_char; len];
        let allowed = if sim.is_null() || needed_at != Pointer::Valid {
            SOILCUT_ERR_NULL
        } else {
            SOILCUT_OK
        };
        // SAFETY: NULL or a live handle; `buf` of `len` bytes.
        let code = unsafe { soilcut_warnings(sim, buf.as_mut_ptr(), len, needed.ptr()) };
        self.expect(code, &[allowed], sim, "soilcut_warnings");
        if code == SOILCUT_OK && len > 0 {
            let n = needed.get().expect("valid");
            assert!(n >= 1 && buf.contains(&0), "soilcut_warnings: {n}");
        }
    }
}

/// What `soilcut_new_from_toml` reads from `text` and `sets`, by the Rust
/// reader.
fn read_like_c(text: &CStr, sets: &[CString]) -> Result<LoadedCase, String> {
    let text = text.to_str().map_err(|e| e.to_string())?;
    let overrides = sets
        .iter()
        .map(|s| {
            let s = s.to_str().map_err(|e| e.to_string())?;
            s.parse::<Override>().map_err(|e| e.to_string())
        })
        .collect::<Result<Vec<_>, _>>()?;
    parse_case(text, &overrides).map_err(|e| e.to_string())
}

/// Within the stepping budget of the other targets.
fn steppable(case: &Case) -> bool {
    case.initial_nodes() <= RUN_NODES && case.deepest() / case.run.spacing() <= RUN_NODES_PER_DEPTH
}

/// The calling thread's (sim NULL) or the handle's last message.
fn message(sim: *const SoilcutSimulation) -> String {
    // SAFETY: NULL or a live handle; a buffer asked for its length.
    let needed = unsafe { soilcut_last_error(sim, null_mut(), 0) };
    let mut buf = vec![0 as c_char; needed];
    // SAFETY: as above, `needed` bytes.
    unsafe { soilcut_last_error(sim, buf.as_mut_ptr(), needed) };
    // SAFETY: NUL-terminated by soilcut_last_error.
    let text = unsafe { CStr::from_ptr(buf.as_ptr()) };
    text.to_string_lossy().into_owned()
}

/// A failure's message is one non-empty line, the handle's and the
/// thread's alike.
fn check_failure(sim: *const SoilcutSimulation, what: &str) {
    let thread = message(null());
    assert!(!thread.trim().is_empty(), "{what}: empty message");
    assert!(
        !thread.contains('\n'),
        "{what}: message of more lines: {thread:?}"
    );
    if !sim.is_null() {
        assert_eq!(message(sim), thread, "{what}: the handle's message");
    }
}

fn check_step(r: &SoilcutStep) {
    if let Some(wrong) = step_wrong(r) {
        panic!("{wrong}");
    }
}

/// What is wrong with a record, if anything: a number not finite, a
/// step before the first, a negative force.
fn step_wrong(r: &SoilcutStep) -> Option<String> {
    let values = r.values();
    let right = values.iter().all(|v| v.is_finite()) && r.step >= 1 && r.force >= 0.0;
    (!right).then(|| format!("record {r:?}"))
}

fn check_state(s: &SoilcutState) {
    let values = [
        s.blade_position,
        s.tip_depth,
        s.mass,
        s.mass_spilled,
        s.initial_mass,
    ];
    assert!(values.iter().all(|v| v.is_finite()), "state {s:?}");
    assert!(s.steps_done <= s.steps_total && (s.done == 0) == (s.steps_done < s.steps_total));
}

/// Whether `len` is not the surface length of the live handle `sim`.
fn sim_len_differs(sim: *mut SoilcutSimulation, len: usize) -> bool {
    let mut n = 0;
    // SAFETY: a live handle, a valid out pointer.
    let code = unsafe { soilcut_surface_len(sim, &mut n) };
    assert_eq!(code, SOILCUT_OK);
    n != len
}

/// The snapshot length of the live handle `sim`.
fn snapshot_len(sim: *mut SoilcutSimulation) -> usize {
    let mut n = 0;
    // SAFETY: a live handle, a length query.
    let code = unsafe { soilcut_snapshot(sim, null_mut(), 0, &mut n) };
    assert_eq!(code, SOILCUT_OK, "{}", message(sim));
    n
}

/// What `soilcut_advance_to`'s callback saw: the records, and what went
/// wrong (a panic cannot unwind out of an `extern "C"` function).
struct Seen {
    sim: *mut SoilcutSimulation,
    records: Vec<SoilcutStep>,
    /// Whether to call back into the handle from the callback.
    reenter: bool,
    wrong: Vec<String>,
}

unsafe extern "C" fn on_step(record: *const SoilcutStep, user: *mut c_void) {
    // SAFETY: the `Seen` the body passed, and the record during the call.
    let (seen, record) = unsafe { (&mut *user.cast::<Seen>(), *record) };
    seen.wrong.extend(step_wrong(&record));
    if seen.reenter {
        let mut state = SoilcutState::default();
        // SAFETY: the live handle being advanced, a valid out pointer.
        let code = unsafe { soilcut_state(seen.sim, &mut state) };
        if code != SOILCUT_OK || state.steps_done != record.step {
            seen.wrong
                .push(format!("state in the callback: {code}, {state:?}"));
        }
        // SAFETY: the live handle being advanced; NULL record.
        let code = unsafe { soilcut_step(seen.sim, null_mut()) };
        if code != SOILCUT_ERR_STATE || message(seen.sim).is_empty() {
            seen.wrong.push(format!("step in the callback: {code}"));
        }
    }
    seen.records.push(record);
}

impl Calls<'_> {
    fn advance_to(&mut self) {
        let (i, sim) = self.slot();
        let (mut x, depth) = (self.input.number(), self.input.number());
        let flags = self.input.u8();
        let made_at = match flags & 3 {
            0 => Pointer::Null,
            1 => Pointer::Misaligned,
            _ => Pointer::Valid,
        };
        let mut made = Out::<u64>::new(made_at);
        let mut seen = Seen {
            sim,
            records: Vec::new(),
            reenter: flags & 8 != 0,
            wrong: Vec::new(),
        };
        let callback: SoilcutOnStep = if flags & 4 != 0 { Some(on_step) } else { None };
        let mut before = 0;
        let allowed: &[c_int] = if sim.is_null() || made_at == Pointer::Misaligned {
            &[SOILCUT_ERR_NULL]
        } else {
            let slot = self.slots[i].as_ref().expect("a live handle");
            let left = if slot.steppable { self.steps_left } else { 0 };
            before = Self::probe(sim).steps_done;
            match within(slot, before as usize, x, left) {
                Some(near) => {
                    x = near;
                    &[SOILCUT_OK, SOILCUT_ERR_ARGUMENT, SOILCUT_ERR_STEP]
                }
                None => &[SOILCUT_ERR_ARGUMENT],
            }
        };
        let user = (&mut seen as *mut Seen).cast::<c_void>();
        // SAFETY: NULL or a live handle; `made` NULL, misaligned or valid;
        // `on_step` of the type, `user` the `Seen` it reads.
        let code = unsafe { soilcut_advance_to(sim, x, depth, callback, user, made.ptr()) };
        self.expect(code, allowed, sim, "soilcut_advance_to");
        assert!(seen.wrong.is_empty(), "callback: {:?}", seen.wrong);
        if !matches!(code, SOILCUT_OK | SOILCUT_ERR_STEP) {
            return;
        }
        let count = Self::probe(sim).steps_done - before;
        if let Some(m) = made.get() {
            assert_eq!(m, count, "steps_made and the steps done");
        }
        if callback.is_some() {
            assert_eq!(
                seen.records.len() as u64,
                count,
                "callbacks and the steps done"
            );
        }
        self.steps_left = self.steps_left.saturating_sub(count as usize);
        if count > 0 {
            self.slots[i].as_mut().expect("advanced").has_last = true;
            self.reach(Outcome::Stepped);
        }
    }
}

/// The position to advance the handle of `slot`, `done` increments in, to
/// for `x` within `left` increments: x itself if it takes no more (or if
/// no position does: NaN, infinite, negative, behind the blade, beyond
/// the largest travel, each refused before any increment), else the
/// farthest position within `left`. None: x is refused.
fn within(slot: &Slot, done: usize, x: f64, left: usize) -> Option<f64> {
    if !(0.0..=MAGNITUDE[1]).contains(&x) {
        return None;
    }
    let target = slot.case.increments_to(x);
    if target < done {
        return None;
    }
    if target - done <= left {
        return Some(x);
    }
    Some((done + left) as f64 * slot.case.run.increment)
}
