//! Status codes, the last error's message, and the guard every entry point
//! runs in: a panic is caught here and never unwinds into the caller.

use soilcut_model::StepError;
use std::any::Any;
use std::cell::RefCell;
use std::ffi::c_char;
use std::os::raw::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Success.
pub const SOILCUT_OK: c_int = 0;
/// Bad input: the case text or file (unreadable, not UTF-8, not TOML, a key
/// missing, unknown or out of range: the message names the key), a bad
/// override, or snapshot bytes that are not a snapshot of this version.
pub const SOILCUT_ERR_INPUT: c_int = -1;
/// A pointer argument that must not be NULL was NULL (or was misaligned).
pub const SOILCUT_ERR_NULL: c_int = -2;
/// A caller-provided array's length is not the one required (the message
/// gives the length needed).
pub const SOILCUT_ERR_LENGTH: c_int = -3;
/// A numeric argument out of its range: NaN or infinite, or a position
/// behind the blade.
pub const SOILCUT_ERR_ARGUMENT: c_int = -4;
/// The call is not allowed in the simulation's present state: the last
/// step's record before any step, a call on a handle from its own
/// `soilcut_advance_to` callback (other than `soilcut_state`,
/// `soilcut_last_step`, `soilcut_last_error`).
pub const SOILCUT_ERR_STATE: c_int = -5;
/// The increment has no admissible mechanism, or made a number that is not
/// finite (the model's step errors; the message says which and why). The
/// simulation is unchanged by the first; after the second every step
/// gives it again.
pub const SOILCUT_ERR_STEP: c_int = -6;
/// soilcut panicked (a bug of soilcut): the panic was caught at the
/// boundary. A handle whose call panicked is unusable afterwards; every
/// later call on it but soilcut_last_error and soilcut_free returns this
/// code.
pub const SOILCUT_ERR_PANIC: c_int = -7;
/// A step after the case's travel has been reached (`run.travel`; the
/// caller's mistake, the model's step error `TravelReached`): nothing is
/// changed. `soilcut_advance_to` goes beyond the travel.
pub const SOILCUT_ERR_TRAVEL: c_int = -8;

/// The model's step error as a status: a step past the travel is the
/// caller's, any other the soil's (no admissible mechanism).
pub(crate) fn step_failure(e: &StepError) -> Failure {
    let code = match e {
        StepError::TravelReached { .. } => SOILCUT_ERR_TRAVEL,
        _ => SOILCUT_ERR_STEP,
    };
    Failure::new(code, e.to_string())
}

/// A failed call: its status code and message.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Failure {
    pub code: c_int,
    pub message: String,
}

impl Failure {
    pub fn new(code: c_int, message: impl Into<String>) -> Self {
        Failure {
            code,
            message: message.into(),
        }
    }

    pub fn null(name: &str) -> Self {
        Failure::new(SOILCUT_ERR_NULL, format!("{name} is NULL"))
    }

    /// A panic's payload as a failure.
    pub fn panicked(payload: &(dyn Any + Send)) -> Self {
        let text = soilcut_io::panic_message(payload);
        Failure::new(
            SOILCUT_ERR_PANIC,
            format!("soilcut panicked (a bug of soilcut): {text}"),
        )
    }
}

thread_local! {
    /// The message of the calling thread's latest failed call.
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Records `failure` as the calling thread's last error; returns its code.
pub(crate) fn fail(failure: Failure) -> c_int {
    LAST_ERROR.with(|last| *last.borrow_mut() = failure.message);
    failure.code
}

/// The calling thread's last error message.
pub(crate) fn thread_last_error() -> String {
    LAST_ERROR.with(|last| last.borrow().clone())
}

/// Runs `f`, catching a panic; a failure is recorded as the thread's last
/// error and its code returned.
pub(crate) fn guard(f: impl FnOnce() -> Result<(), Failure>) -> c_int {
    match catch(f) {
        Ok(()) => SOILCUT_OK,
        Err(failure) => fail(failure),
    }
}

/// Runs `f`, turning a panic into a [`Failure`].
pub(crate) fn catch<T>(f: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    // The closure's captures are not used again after a panic except
    // through the poisoned mutex of a handle, which the callers check.
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|payload| Err(Failure::panicked(&*payload)))
}

/// Copies `message` into `buf` (at most `len` bytes, always NUL-terminated
/// when `len` > 0) and returns the bytes needed with the NUL.
///
/// # Safety
/// `buf` is NULL or valid for writes of `len` bytes.
pub(crate) unsafe fn copy_message(message: &str, buf: *mut c_char, len: usize) -> usize {
    // An interior NUL (never written by soilcut) would cut the message short.
    let bytes = message.as_bytes();
    let needed = bytes.len() + 1;
    if !buf.is_null() && len > 0 {
        let mut n = bytes.len().min(len - 1);
        // A cut message stays UTF-8: whole characters only.
        while !message.is_char_boundary(n) {
            n -= 1;
        }
        // SAFETY: the caller guarantees `len` writable bytes at `buf`;
        // n + 1 <= len.
        unsafe {
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), buf.cast::<u8>(), n);
            *buf.add(n) = 0;
        }
    }
    needed
}
