//! soilcut-ffi: the C ABI of soilcut (header `include/soilcut.h`, generated
//! by cbindgen from this crate and checked by `tests/header.rs`).
//!
//! A C or C++ program creates a simulation from a case (TOML text or a
//! file, read by `soilcut-io` exactly as `soilcut run` reads it), steps it
//! and reads each increment's record, its state and its surface. The
//! binding only converts types: every number is the model's, so a C run's
//! history equals `soilcut run`'s `history.csv` bit for bit.
//!
//! Rules of every entry point:
//! * it returns a status (`SOILCUT_OK`, or a negative `SOILCUT_ERR_*`
//!   code), except the few that cannot fail;
//! * a failure's message is kept by the handle and by the calling thread
//!   (`soilcut_last_error`);
//! * no panic crosses the boundary: each call runs under
//!   `std::panic::catch_unwind`;
//! * NULL, misaligned pointers, wrong lengths, NaN and calls out of order
//!   are errors, never undefined behaviour (a dangling pointer, a buffer
//!   shorter than the length given or a freed handle cannot be detected);
//! * a handle is thread-safe: concurrent calls on one handle are
//!   serialised by its lock, and different handles are independent.

mod error;
mod record;

pub use error::{
    SOILCUT_ERR_ARGUMENT, SOILCUT_ERR_INPUT, SOILCUT_ERR_LENGTH, SOILCUT_ERR_NULL,
    SOILCUT_ERR_PANIC, SOILCUT_ERR_STATE, SOILCUT_ERR_STEP, SOILCUT_ERR_TRAVEL, SOILCUT_OK,
};
pub use record::{SoilcutState, SoilcutStep};

use error::{catch, copy_message, fail, guard, step_failure, thread_last_error, Failure};
use soilcut_io::{
    case_from_note, parse_case, read_case, InputError, LoadedCase, Override, HISTORY_HEADER,
};
use soilcut_model::{AdvanceError, ProfilePoint, Simulation, StepRecord};
use std::cell::RefCell;
use std::ffi::{c_char, c_void, CStr, CString};
use std::os::raw::c_int;
use std::path::Path;
use std::sync::{Mutex, OnceLock};

/// A running simulation of one case. Opaque: created by
/// `soilcut_new_from_toml` or `soilcut_new_from_file`, released by
/// `soilcut_free`.
pub struct SoilcutSimulation {
    state: Mutex<State>,
    /// The message of the latest failed call on this handle. Apart from
    /// `state` so that it stays readable after a panic poisoned `state`.
    error: Mutex<String>,
}

struct State {
    sim: Simulation,
    /// The case as read (and as `soilcut_advance_to` steered it), whose
    /// `case.resolved.toml` a snapshot carries so that the Python package
    /// restores it with its case, as it does its own (and the reverse).
    /// None for a snapshot restored without case text.
    loaded: Option<LoadedCase>,
    /// The latest increment's record.
    last: Option<StepRecord>,
    /// The case's accuracy warnings, one per line (as `soilcut run` prints
    /// them on stderr).
    warnings: String,
}

impl SoilcutSimulation {
    fn new((sim, loaded): (Simulation, Option<LoadedCase>)) -> Self {
        let warnings = sim.case().accuracy_warnings().join("\n");
        SoilcutSimulation {
            state: Mutex::new(State {
                sim,
                loaded,
                last: None,
                warnings,
            }),
            error: Mutex::new(String::new()),
        }
    }

    fn error(&self) -> String {
        self.error
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .clone()
    }

    /// Keeps `failure`'s message as the handle's and the thread's last
    /// error; returns its code.
    fn fail(&self, failure: Failure) -> c_int {
        let mut error = self
            .error
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        error.clone_from(&failure.message);
        fail(failure)
    }
}

impl SoilcutSimulation {
    /// Runs `f` on the state, catching a panic (which poisons the lock, so
    /// that every later call fails). Refused inside this handle's
    /// `soilcut_advance_to` callback, whose thread holds the lock.
    fn run<T>(&self, f: impl FnOnce(&mut State) -> Result<T, Failure>) -> Result<T, Failure> {
        catch(|| {
            if in_step(self, |_| ()).is_some() {
                return Err(Failure::new(SOILCUT_ERR_STATE, BUSY));
            }
            let mut state = self.state.lock().map_err(|_| {
                Failure::new(
                    SOILCUT_ERR_PANIC,
                    "an earlier call on this simulation panicked, so its state is unknown: free it",
                )
            })?;
            f(&mut state)
        })
    }
}

/// Why a call on a handle is refused inside its `soilcut_advance_to`'s
/// callback.
const BUSY: &str = "called from soilcut_advance_to's on_step on the same simulation, which is in the middle of advancing: there only soilcut_state, soilcut_last_step and soilcut_last_error may be called on it";

/// The handle whose `soilcut_advance_to` is calling its `on_step` on
/// this thread, and what `soilcut_state` and `soilcut_last_step` report
/// for it meanwhile: the state and record after the increment just made.
struct InStep {
    handle: *const SoilcutSimulation,
    state: SoilcutState,
    record: SoilcutStep,
}

thread_local! {
    static IN_STEP: RefCell<Option<InStep>> = const { RefCell::new(None) };
}

/// `f` of what the callback of `handle`'s advance sees, if this thread is
/// in that callback.
fn in_step<T>(handle: *const SoilcutSimulation, f: impl FnOnce(&InStep) -> T) -> Option<T> {
    IN_STEP.with(|now| {
        let now = now.borrow();
        now.as_ref()
            .filter(|busy| std::ptr::eq(busy.handle, handle))
            .map(f)
    })
}

/// Runs `call` (the caller's callback) with `busy` as this thread's
/// advance in progress; a callback advancing another handle nests.
fn calling_back(busy: InStep, call: impl FnOnce()) {
    let outer = IN_STEP.with(|now| now.replace(Some(busy)));
    call();
    IN_STEP.with(|now| *now.borrow_mut() = outer);
}

/// Writes what the callback in progress on `sim` sees to `out`, if this
/// thread is in it.
///
/// # Safety
/// `out` is NULL or valid for a write.
unsafe fn put_in_step<T>(
    sim: *const SoilcutSimulation,
    (out, name): (*mut T, &str),
    value: impl FnOnce(&InStep) -> T,
) -> Option<c_int> {
    let value = in_step(sim, value)?;
    Some(match writable(out, name) {
        Ok(()) => {
            // SAFETY: checked by `writable`, valid by the caller's contract.
            unsafe { put(out, value) };
            SOILCUT_OK
        }
        // SAFETY: `sim` is the live handle whose advance is in progress.
        Err(failure) => unsafe { &*sim }.fail(failure),
    })
}

/// The handle `sim`, or the thread's failure for a NULL one.
///
/// # Safety
/// `sim` is NULL or a live handle.
unsafe fn handle<'a>(sim: *const SoilcutSimulation) -> Result<&'a SoilcutSimulation, c_int> {
    // SAFETY: NULL or a live handle, by the caller's contract.
    unsafe { sim.as_ref() }.ok_or_else(|| fail(Failure::null("sim")))
}

/// Runs `f` on the state of the handle `sim`; a failure is kept by the
/// handle and the thread.
///
/// # Safety
/// `sim` is NULL or a live handle.
unsafe fn with_handle(
    sim: *const SoilcutSimulation,
    f: impl FnOnce(&mut State) -> Result<(), Failure>,
) -> c_int {
    // SAFETY: by the caller's contract.
    let handle = match unsafe { handle(sim) } {
        Ok(handle) => handle,
        Err(code) => return code,
    };
    match handle.run(f) {
        Ok(()) => SOILCUT_OK,
        Err(failure) => handle.fail(failure),
    }
}

/// Checks that `p` may be written as a `T`.
fn writable<T>(p: *mut T, name: &str) -> Result<(), Failure> {
    if p.is_null() {
        Err(Failure::null(name))
    } else if !p.is_aligned() {
        Err(Failure::new(
            SOILCUT_ERR_NULL,
            format!("{name} is misaligned"),
        ))
    } else {
        Ok(())
    }
}

/// Writes `value` to `p`, which `writable` has accepted.
///
/// # Safety
/// `p` points to memory valid for a `T`.
unsafe fn put<T>(p: *mut T, value: T) {
    // SAFETY: non-NULL and aligned (checked), valid by the caller's contract.
    unsafe { p.write(value) }
}

/// The NUL-terminated UTF-8 string at `p`.
///
/// # Safety
/// `p` is NULL or a NUL-terminated string.
unsafe fn text<'a>(p: *const c_char, name: &str) -> Result<&'a str, Failure> {
    if p.is_null() {
        return Err(Failure::null(name));
    }
    // SAFETY: a NUL-terminated string, by the caller's contract.
    let bytes = unsafe { CStr::from_ptr(p) };
    bytes
        .to_str()
        .map_err(|e| Failure::new(SOILCUT_ERR_INPUT, format!("{name} is not UTF-8: {e}")))
}

/// The `--set` overrides `sets[0..n]`.
///
/// # Safety
/// `sets` is NULL or valid for `n` pointers, each NULL or a NUL-terminated
/// string.
unsafe fn overrides(sets: *const *const c_char, n: usize) -> Result<Vec<Override>, Failure> {
    if n == 0 {
        return Ok(Vec::new());
    }
    writable(sets.cast_mut(), "sets")?;
    if n > isize::MAX as usize / size_of::<*const c_char>() {
        return Err(Failure::new(
            SOILCUT_ERR_ARGUMENT,
            format!("n_sets = {n} is not the length of an array"),
        ));
    }
    // SAFETY: non-NULL, aligned, `n` pointers by the caller's contract.
    let pointers = unsafe { std::slice::from_raw_parts(sets, n) };
    pointers
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            // SAFETY: NULL or a NUL-terminated string, by the contract.
            let set = unsafe { text(p, &format!("sets[{i}]")) }?;
            set.parse::<Override>().map_err(|e| input(&e))
        })
        .collect()
}

fn input(e: &InputError) -> Failure {
    Failure::new(SOILCUT_ERR_INPUT, e.to_string())
}

/// The simulation of the case `read` reads from the string `arg` (named
/// `name`) with the overrides `sets[0..n_sets]`.
///
/// # Safety
/// As `overrides`, and `arg` is NULL or a NUL-terminated string.
unsafe fn simulation(
    (arg, name): (*const c_char, &str),
    sets: *const *const c_char,
    n_sets: usize,
    read: impl FnOnce(&str, &[Override]) -> Result<LoadedCase, Failure>,
) -> Result<(Simulation, Option<LoadedCase>), Failure> {
    // SAFETY: by the caller's contract.
    let arg = unsafe { text(arg, name) }?;
    // SAFETY: by the caller's contract.
    let overrides = unsafe { overrides(sets, n_sets) }?;
    let loaded = read(arg, &overrides)?;
    let sim = Simulation::start(&loaded.case);
    Ok((sim, Some(loaded)))
}

/// Creates a handle for the simulation `make` sets up and stores it in
/// `*out`.
///
/// # Safety
/// `out` is NULL or valid for a write of a pointer.
unsafe fn create(
    out: *mut *mut SoilcutSimulation,
    make: impl FnOnce() -> Result<(Simulation, Option<LoadedCase>), Failure>,
) -> c_int {
    guard(|| {
        writable(out, "out")?;
        // SAFETY: checked by `writable`; a failure leaves NULL there.
        unsafe { put(out, std::ptr::null_mut()) };
        let sim = make()?;
        let handle = Box::into_raw(Box::new(SoilcutSimulation::new(sim)));
        // SAFETY: as above.
        unsafe { put(out, handle) };
        Ok(())
    })
}

/// The version of soilcut, a static NUL-terminated string (`"0.1.0"`).
#[no_mangle]
pub extern "C" fn soilcut_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// The columns of `history.csv`, comma-separated, a static NUL-terminated
/// string: the fields of `SoilcutStep` in their order.
#[no_mangle]
pub extern "C" fn soilcut_history_header() -> *const c_char {
    static HEADER: OnceLock<CString> = OnceLock::new();
    HEADER
        .get_or_init(|| CString::new(HISTORY_HEADER).unwrap_or_default())
        .as_ptr()
}

/// Copies the message of the latest failed call into `buf` and returns the
/// bytes it needs, the terminating NUL included (1: no error yet). With
/// `sim` a handle: the latest failure on that handle; with `sim` NULL: the
/// calling thread's latest failure (the only one for a constructor that
/// failed, or a call given a NULL handle). At most `len` bytes are written,
/// always NUL-terminated when `len` > 0; `buf` may be NULL when `len` is
/// 0, to ask for the length. Successful calls leave the message as it was.
/// Never fails.
///
/// # Safety
/// `sim` is NULL or a live handle; `buf` is NULL or valid for writes of
/// `len` bytes.
#[no_mangle]
pub unsafe extern "C" fn soilcut_last_error(
    sim: *const SoilcutSimulation,
    buf: *mut c_char,
    len: usize,
) -> usize {
    let message = catch(|| {
        // SAFETY: NULL or a live handle, by the caller's contract.
        Ok(match unsafe { sim.as_ref() } {
            Some(handle) => handle.error(),
            None => thread_last_error(),
        })
    })
    .unwrap_or_default();
    // SAFETY: by the caller's contract on `buf` and `len`.
    unsafe { copy_message(&message, buf, len) }
}

/// Creates a simulation of the case whose TOML text is `text` (a case
/// file's contents), with `n_sets` overrides `sets[i]` = `"key.path=value"`
/// applied as `soilcut run --set` applies them (`sets` may be NULL when
/// `n_sets` is 0). On success `*out` is the new handle; on failure `*out`
/// is NULL and `soilcut_last_error(NULL, ...)` tells why: a bad key's
/// message starts with the key (`blade.rake: ...`), a syntax error's with
/// its line.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`text`, `out`, `sets` or an
/// element NULL), `SOILCUT_ERR_INPUT` (the case or an override),
/// `SOILCUT_ERR_ARGUMENT` (`n_sets` impossible) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `sets` is NULL or valid for
/// `n_sets` pointers, each NULL or a NUL-terminated string; `out` is NULL
/// or valid for a write of a pointer.
#[no_mangle]
pub unsafe extern "C" fn soilcut_new_from_toml(
    text: *const c_char,
    sets: *const *const c_char,
    n_sets: usize,
    out: *mut *mut SoilcutSimulation,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        create(out, || {
            simulation((text, "text"), sets, n_sets, |text, overrides| {
                parse_case(text, overrides).map_err(|e| input(&e))
            })
        })
    }
}

/// Creates a simulation of the case file at `path` (UTF-8), with overrides
/// as in `soilcut_new_from_toml`. The error message starts with the path,
/// as `soilcut run`'s does: `path/to/case.toml: blade.rake: ...`.
///
/// Returns the codes of `soilcut_new_from_toml` (an unreadable file is
/// `SOILCUT_ERR_INPUT`).
///
/// # Safety
/// As `soilcut_new_from_toml`, with `path` for `text`.
#[no_mangle]
pub unsafe extern "C" fn soilcut_new_from_file(
    path: *const c_char,
    sets: *const *const c_char,
    n_sets: usize,
    out: *mut *mut SoilcutSimulation,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        create(out, || {
            simulation((path, "path"), sets, n_sets, |path, overrides| {
                read_case(Path::new(path), overrides)
                    .map_err(|e| Failure::new(SOILCUT_ERR_INPUT, format!("{path}: {e}")))
            })
        })
    }
}

/// Releases a handle. NULL is allowed and does nothing; a handle must not
/// be used (or freed) again, nor freed while another thread uses it.
/// Called from the handle's own `soilcut_advance_to` callback it frees
/// nothing and sets the thread's last error.
///
/// # Safety
/// `sim` is NULL or a live handle not in use by another thread.
#[no_mangle]
pub unsafe extern "C" fn soilcut_free(sim: *mut SoilcutSimulation) {
    if sim.is_null() {
        return;
    }
    // Its advance is under way further up this thread's stack.
    if in_step(sim, |_| ()).is_some() {
        fail(Failure::new(
            SOILCUT_ERR_STATE,
            format!("soilcut_free refused: {BUSY}"),
        ));
        return;
    }
    // Dropping plain data does not panic; a panic would be caught all the
    // same.
    let _ = catch(|| {
        // SAFETY: a live handle made by `Box::into_raw`, by the contract.
        drop(unsafe { Box::from_raw(sim) });
        Ok(())
    });
}

/// Copies the case's accuracy warnings (as `soilcut run` prints them on
/// stderr: nodes coarser than the increment in softening soil, a narrow
/// tine), one per line, into `buf` as `soilcut_last_error` copies a
/// message, and stores the bytes needed with the NUL in `*needed` (1: no
/// warning).
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`sim` or `needed`) or
/// `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `buf` is NULL or valid for writes of
/// `len` bytes; `needed` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_warnings(
    sim: *const SoilcutSimulation,
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            writable(needed, "needed")?;
            let n = copy_message(&state.warnings, buf, len);
            put(needed, n);
            Ok(())
        })
    }
}

/// Advances the blade by one increment. With `record` not NULL, the
/// increment's record is copied there (it stays readable by
/// `soilcut_last_step`).
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`sim` NULL, `record`
/// misaligned), `SOILCUT_ERR_TRAVEL` (the case's travel has been reached),
/// `SOILCUT_ERR_STEP` (no admissible mechanism, the simulation
/// unchanged; or a number not finite) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `record` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_step(
    sim: *mut SoilcutSimulation,
    record: *mut SoilcutStep,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            if !record.is_null() {
                writable(record, "record")?;
            }
            let r = state.sim.step().map_err(|e| step_failure(&e))?;
            state.last = Some(r);
            if !record.is_null() {
                put(record, SoilcutStep::new(&r));
            }
            Ok(())
        })
    }
}

/// Copies the latest increment's record into `*record`.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL`, `SOILCUT_ERR_STATE` (no
/// increment yet) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `record` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_last_step(
    sim: *const SoilcutSimulation,
    record: *mut SoilcutStep,
) -> c_int {
    // SAFETY: by the caller's contract.
    if let Some(code) = unsafe { put_in_step(sim, (record, "record"), |busy| busy.record) } {
        return code;
    }
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            writable(record, "record")?;
            let r = state
                .last
                .as_ref()
                .ok_or_else(|| Failure::new(SOILCUT_ERR_STATE, "no increment has been made yet"))?;
            put(record, SoilcutStep::new(r));
            Ok(())
        })
    }
}

/// Copies where the simulation is now (increments done and in all, the
/// blade's position, the tip's depth, the masses) into `*out`.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `out` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_state(
    sim: *const SoilcutSimulation,
    out: *mut SoilcutState,
) -> c_int {
    // SAFETY: by the caller's contract.
    if let Some(code) = unsafe { put_in_step(sim, (out, "out"), |busy| busy.state) } {
        return code;
    }
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            writable(out, "out")?;
            put(out, SoilcutState::new(&state.sim));
            Ok(())
        })
    }
}

/// Stores the number of points of the free surface, from the blade face to
/// the end of the domain, in `*len`: the length `soilcut_surface` needs. It
/// changes as the simulation steps.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `len` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_surface_len(
    sim: *const SoilcutSimulation,
    len: *mut usize,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            writable(len, "len")?;
            put(len, state.sim.profile().len());
            Ok(())
        })
    }
}

/// An array of `soilcut_surface`: where, its name, whether it is
/// required, and the value of a point it takes.
type Column<'a> = (*mut f64, &'a str, bool, fn(&ProfilePoint) -> f64);

/// Copies the free surface, from the blade face to the end of the domain,
/// into caller arrays of `len` doubles each (`profile.csv`'s columns): `x`
/// (length, the node's position), `y` (length, the surface height; 0 is
/// the undisturbed ground; the centreline with `blade.width`),
/// `accumulated_shear` (length, ut), `unit_weight` (force/length³, γ) and
/// `ridge_height` (length, the side heaps' crest beside a blade of finite
/// width; 0 in plane strain). `x` and `y` are required; each of the others
/// may be NULL to skip it. `len` must equal `soilcut_surface_len`'s.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`sim`, `x` or `y` NULL, an
/// array misaligned), `SOILCUT_ERR_LENGTH` (`len` is not the surface's;
/// nothing is written) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; each array is NULL or valid for writes
/// of `len` doubles.
#[no_mangle]
pub unsafe extern "C" fn soilcut_surface(
    sim: *const SoilcutSimulation,
    x: *mut f64,
    y: *mut f64,
    accumulated_shear: *mut f64,
    unit_weight: *mut f64,
    ridge_height: *mut f64,
    len: usize,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            let columns: [Column; 5] = [
                (x, "x", true, |p| p.x),
                (y, "y", true, |p| p.y),
                (accumulated_shear, "accumulated_shear", false, |p| {
                    p.accumulated_shear
                }),
                (unit_weight, "unit_weight", false, |p| p.unit_weight),
                (ridge_height, "ridge_height", false, |p| p.ridge_height),
            ];
            for &(p, name, required, _) in &columns {
                if required || !p.is_null() {
                    writable(p, name)?;
                }
            }
            let profile = state.sim.profile();
            if len != profile.len() {
                return Err(Failure::new(
                    SOILCUT_ERR_LENGTH,
                    format!(
                        "len is {len} but the surface has {} points (soilcut_surface_len)",
                        profile.len()
                    ),
                ));
            }
            for (p, _, _, value) in columns {
                if p.is_null() {
                    continue;
                }
                // SAFETY: non-NULL, aligned, `len` doubles by the contract.
                let out = std::slice::from_raw_parts_mut(p, len);
                for (slot, point) in out.iter_mut().zip(&profile) {
                    *slot = value(point);
                }
            }
            Ok(())
        })
    }
}

/// Called by `soilcut_advance_to` with each increment's record, in order,
/// and the caller's `user` pointer, as soon as the increment is made (so a
/// co-simulation sees the force of each increment while the blade moves).
/// The record is valid during the call only. The handle is in the middle
/// of advancing: on it, the callback may call `soilcut_state` and
/// `soilcut_last_step` (which report the increment just made) and
/// `soilcut_last_error`; any other call on it is refused with
/// `SOILCUT_ERR_STATE` (and `soilcut_free` frees nothing). Other handles
/// may be used freely. It must not wait for another thread's call on this
/// handle (which waits for the advance to end), nor unwind (a C++
/// exception) into soilcut.
pub type SoilcutOnStep =
    Option<unsafe extern "C" fn(record: *const SoilcutStep, user: *mut c_void)>;

/// Runs the increments that bring the blade to displacement `x` (length,
/// measured as `SoilcutState.blade_position`): up to the first whole
/// increment at or beyond x, since an increment is never shortened (the
/// grid moves by whole increments: the rule of `run.travel`, so the blade
/// stops less than one increment past x and the records are the case's
/// own). None if the blade is there already. With `depth` a length (not
/// NaN), the tip goes linearly from its depth now to `depth` at x and
/// stays there (vertical blades only, no deeper than the deepest tip depth
/// of the case); NaN leaves the case's depth (or depth path) as it is.
/// Beyond `run.travel` the travel becomes x.
///
/// `on_step` (may be NULL) is called with each increment's record as the
/// increment is made (`SoilcutOnStep`); `*steps_made` (may be NULL) is
/// the number of increments made, also on `SOILCUT_ERR_STEP`, when the
/// increments before the failed one were made and reported. The last
/// one's record is then `soilcut_last_step`'s.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`sim` NULL, `steps_made`
/// misaligned), `SOILCUT_ERR_ARGUMENT` (x NaN, infinite, negative or
/// behind the blade; depth out of range or not allowed for the case;
/// nothing was changed), `SOILCUT_ERR_STATE` (called from this handle's
/// own `on_step`), `SOILCUT_ERR_STEP` or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `steps_made` is NULL or valid for a
/// write; `on_step` is NULL or a function of that type.
#[no_mangle]
pub unsafe extern "C" fn soilcut_advance_to(
    sim: *mut SoilcutSimulation,
    x: f64,
    depth: f64,
    on_step: SoilcutOnStep,
    user: *mut c_void,
    steps_made: *mut u64,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            if !steps_made.is_null() {
                writable(steps_made, "steps_made")?;
            }
            let depth = (!depth.is_nan()).then_some(depth);
            let mut made = 0;
            let result = advance(state, sim, (x, depth), |record| {
                made += 1;
                if let Some(on_step) = on_step {
                    // SAFETY: a function of this type, by the contract.
                    on_step(record, user);
                }
            });
            // An argument refused made nothing and writes nothing.
            let stepped = result
                .as_ref()
                .map_or_else(|f| f.code == SOILCUT_ERR_STEP, |()| true);
            if stepped && !steps_made.is_null() {
                // SAFETY: checked by `writable` above.
                put(steps_made, made);
            }
            result
        })
    }
}

/// `Simulation::advance_to_with` on the state of `handle`, each record
/// kept as the last and handed to `on_step` as `handle`'s advance in
/// progress; the case as read follows the case as steered.
fn advance(
    state: &mut State,
    handle: *const SoilcutSimulation,
    (x, depth): (f64, Option<f64>),
    mut on_step: impl FnMut(&SoilcutStep),
) -> Result<(), Failure> {
    let State {
        sim, loaded, last, ..
    } = state;
    let result = sim.advance_to_with(x, depth, |now, record| {
        *last = Some(*record);
        let busy = InStep {
            handle,
            state: SoilcutState::new(now),
            record: SoilcutStep::new(record),
        };
        let record = busy.record;
        calling_back(busy, || on_step(&record));
    });
    // The case may be steered even if an increment failed.
    *loaded = loaded.take().map(|l| l.steered(sim.case()));
    match result {
        Ok(_) => Ok(()),
        Err(AdvanceError::Step { error, .. }) => Err(step_failure(&error)),
        Err(e) => Err(Failure::new(SOILCUT_ERR_ARGUMENT, e.to_string())),
    }
}

/// Copies the simulation's state as bytes into `buf` (`soilcut_restore`
/// makes a simulation that continues from them bit for bit as this one
/// would) and stores their length in `*needed`. With `buf` NULL and `len`
/// 0 it only stores the length. The bytes are versioned: they restore only
/// in this version of soilcut. They carry the case's text
/// (`case.resolved.toml`, as steered by `soilcut_advance_to`), as the
/// Python package's snapshots do, so that either restores the other's
/// with its case; a simulation restored from a snapshot without case text
/// makes snapshots without it. The last step's record is not part of
/// them. Each call serialises the state anew (so ask for the length and
/// copy in two calls, or keep a buffer large enough).
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`sim` or `needed` NULL, `buf`
/// NULL with `len` > 0), `SOILCUT_ERR_LENGTH` (`len` < `*needed`: nothing
/// is copied) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `sim` is NULL or a live handle; `buf` is NULL or valid for writes of
/// `len` bytes; `needed` is NULL or valid for a write.
#[no_mangle]
pub unsafe extern "C" fn soilcut_snapshot(
    sim: *const SoilcutSimulation,
    buf: *mut u8,
    len: usize,
    needed: *mut usize,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        with_handle(sim, |state| {
            writable(needed, "needed")?;
            if buf.is_null() && len > 0 {
                return Err(Failure::null("buf"));
            }
            let text = state.loaded.as_ref().map(LoadedCase::resolved_toml);
            let bytes = state
                .sim
                .snapshot_with_note(text.unwrap_or_default().as_bytes());
            put(needed, bytes.len());
            if buf.is_null() {
                return Ok(());
            }
            if len < bytes.len() {
                return Err(Failure::new(
                    SOILCUT_ERR_LENGTH,
                    format!("len is {len} but the snapshot has {} bytes", bytes.len()),
                ));
            }
            // SAFETY: `len` >= the bytes' length writable bytes at `buf`.
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), buf, bytes.len());
            Ok(())
        })
    }
}

/// Creates a simulation from the `len` bytes of a snapshot
/// (`soilcut_snapshot`), stored in `*out` as `soilcut_new_from_toml` does;
/// it has no last step until it steps.
///
/// Returns `SOILCUT_OK`, `SOILCUT_ERR_NULL` (`bytes` NULL with `len` > 0,
/// `out` NULL), `SOILCUT_ERR_INPUT` (not a snapshot, of another version,
/// truncated, corrupt, case text that is not its state's case: the
/// message says which) or `SOILCUT_ERR_PANIC`.
///
/// # Safety
/// `bytes` is NULL or valid for reads of `len` bytes; `out` is NULL or
/// valid for a write of a pointer.
#[no_mangle]
pub unsafe extern "C" fn soilcut_restore(
    bytes: *const u8,
    len: usize,
    out: *mut *mut SoilcutSimulation,
) -> c_int {
    // SAFETY: by the caller's contract.
    unsafe {
        create(out, || {
            let bytes = match len {
                0 => &[][..],
                _ if bytes.is_null() => return Err(Failure::null("bytes")),
                _ if len > isize::MAX as usize => {
                    return Err(Failure::new(
                        SOILCUT_ERR_ARGUMENT,
                        format!("len = {len} is not the length of an array"),
                    ))
                }
                // SAFETY: `len` readable bytes, by the caller's contract.
                _ => std::slice::from_raw_parts(bytes, len),
            };
            let restored = Simulation::from_snapshot_with_note(bytes).and_then(|(sim, note)| {
                let loaded = case_from_note(&note, sim.case())?;
                Ok((sim, loaded))
            });
            restored.map_err(|e| Failure::new(SOILCUT_ERR_INPUT, e.to_string()))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_is_caught_and_reported_on_the_thread() {
        let code = guard(|| panic!("deliberate"));
        assert_eq!(code, SOILCUT_ERR_PANIC);
        let message = thread_last_error();
        assert!(message.contains("deliberate"), "{message}");
        assert!(message.contains("bug of soilcut"), "{message}");
    }

    #[test]
    fn a_panic_on_a_handle_poisons_it_for_every_later_call() {
        let text = include_str!("../../../cases/paper/original.toml");
        let sim = Simulation::start(&parse_case(text, &[]).unwrap().case);
        let handle = Box::into_raw(Box::new(SoilcutSimulation::new((sim, None))));
        unsafe {
            let code = with_handle(handle, |_| panic!("inside the lock"));
            assert_eq!(code, SOILCUT_ERR_PANIC);
            assert!((*handle).error().contains("inside the lock"));
            let mut record = SoilcutStep::default();
            assert_eq!(soilcut_step(handle, &mut record), SOILCUT_ERR_PANIC);
            assert!((*handle).error().contains("earlier call"));
            assert_eq!(record, SoilcutStep::default());
            soilcut_free(handle);
        }
    }
}
