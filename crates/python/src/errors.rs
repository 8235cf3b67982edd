//! Rust errors as the Python package's exceptions (defined in
//! `soilcut/_errors.py`, so that they carry docstrings and attributes).

use crate::step::Step;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use soilcut_io::panic_message;
use soilcut_io::InputError;
use soilcut_model::{AdvanceError, StepError, StepRecord};
use std::any::Any;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// The command line's options that messages of the study and io crates
/// name, and the Python arguments that stand for them (`soilcut.sweep`'s
/// `soilcut.fit`'s and `soilcut.sensitivity`'s keywords, `save`'s folder),
/// longest first.
const ARGUMENTS: [(&str, &str); 21] = [
    (
        "give at least one --free key",
        "give at least one key in free",
    ),
    (
        "give at least one --vary key=SPEC",
        "give at least one key in vary",
    ),
    (
        "give at least one --vary key=lo:hi",
        "give at least one key in vary",
    ),
    ("--method morris", "method=\"morris\""),
    ("--method sobol", "method=\"sobol\""),
    ("--second-order", "second_order=True"),
    ("--dummy's input", "dummy's input"),
    ("--sample lhs:N", "sample=\"lhs:N\""),
    ("e.g. --out out/NAME", "e.g. \"out/NAME\""),
    ("with --set", "with Case.set"),
    ("--objective", "objective"),
    ("--bounds", "bounds"),
    ("--samples", "samples"),
    ("--sample", "sample"),
    ("--free", "free"),
    ("--vary", "vary"),
    ("--method", "method"),
    ("--members", "members"),
    ("--levels", "levels"),
    ("--jobs", "jobs"),
    ("--out", "folder"),
];

/// A message of the study or io crates in the Python arguments' words:
/// they name the command line's options (`--free`, `--sample lhs:N`,
/// `give --bounds key=lo:hi`), which Python takes as keyword arguments.
pub fn python_words(message: &str) -> String {
    let mut text = bounds_hint(message);
    for (option, argument) in ARGUMENTS {
        text = text.replace(option, argument);
    }
    text
}

/// `give --bounds KEY=lo:hi` as Python writes it, `give bounds={"KEY": (lo, hi)}`.
fn bounds_hint(message: &str) -> String {
    let (hint, end) = ("give --bounds ", "=lo:hi");
    let Some(at) = message.find(hint) else {
        return message.to_string();
    };
    let rest = &message[at + hint.len()..];
    let Some(key_end) = rest.find(end) else {
        return message.to_string();
    };
    let key = &rest[..key_end];
    let after = &rest[key_end + end.len()..];
    format!(
        "{}give bounds={{\"{key}\": (lo, hi)}}{after}",
        &message[..at]
    )
}

/// An instance of the package's exception `class`: `class(message, key)`.
fn raise(py: Python<'_>, class: &str, message: String, key: Option<String>) -> PyErr {
    let made = package_class(py, class).and_then(|c| c.call1((message, key)));
    match made {
        Ok(e) => PyErr::from_value(e),
        Err(e) => e,
    }
}

/// The class `name` of `soilcut/_errors.py`.
fn package_class<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("soilcut._errors")?.getattr(name)
}

/// Warns with `soilcut.CaseFormWarning` where the command line prints a
/// notice (`LoadedCase::notices`: a key in an earlier version's form), and
/// with `soilcut.AccuracyWarning` where it warns on stderr
/// (`Case::accuracy_warnings`).
pub fn warn_accuracy(py: Python<'_>, loaded: &soilcut_io::LoadedCase) -> PyResult<()> {
    let notices = loaded
        .notices()
        .iter()
        .map(|m| ("CaseFormWarning", m.clone()));
    let accuracy = loaded.case.accuracy_warnings().into_iter();
    for (class, message) in notices.chain(accuracy.map(|m| ("AccuracyWarning", m))) {
        let class = package_class(py, class)?;
        let message = std::ffi::CString::new(message)?;
        PyErr::warn(py, &class, &message, 1)?;
    }
    Ok(())
}

/// `soilcut.CaseError(message, key)`: the message is the command line's.
pub fn case_error(py: Python<'_>, e: &InputError) -> PyErr {
    let key = match e {
        InputError::Key(k) => Some(k.key.clone()),
        _ => None,
    };
    raise(py, "CaseError", e.to_string(), key)
}

/// `soilcut.CaseError` of the case file at `path`: its message starts
/// with the path.
pub fn case_error_in(py: Python<'_>, path: &Path, e: &InputError) -> PyErr {
    let key = match e {
        InputError::Key(k) => Some(k.key.clone()),
        _ => None,
    };
    raise(py, "CaseError", format!("{}: {e}", path.display()), key)
}

/// `soilcut.CaseError` from a message (errors the study crate reports as text).
pub fn case_message(py: Python<'_>, message: impl Into<String>) -> PyErr {
    raise(py, "CaseError", message.into(), None)
}

/// `soilcut.CaseError` about `key`: the message is `key: message`.
pub fn key_error(py: Python<'_>, key: &str, message: &str) -> PyErr {
    raise(
        py,
        "CaseError",
        format!("{key}: {message}"),
        Some(key.to_string()),
    )
}

/// `soilcut.StepError`: an increment without an admissible mechanism.
pub fn step_error(py: Python<'_>, e: StepError) -> PyErr {
    raise(py, "StepError", e.to_string(), None)
}

/// `soilcut.StepError` with `steps`, the records of the increments made
/// before the one that failed.
fn step_error_after(py: Python<'_>, e: StepError, records: Vec<StepRecord>) -> PyErr {
    let made = package_class(py, "StepError").and_then(|c| {
        let steps: Vec<Step> = records.into_iter().map(Step).collect();
        c.call1((e.to_string(), py.None(), steps))
    });
    match made {
        Ok(e) => PyErr::from_value(e),
        Err(e) => e,
    }
}

/// `soilcut.StepError` of a run that stopped partway, with `steps` and
/// `_records`, the files of the increments made (a `RunRecords`, which
/// `soilcut.run` makes its `result`, marked as stopped).
pub fn stopped_error(
    py: Python<'_>,
    e: StepError,
    records: Vec<StepRecord>,
    run: Py<PyAny>,
) -> PyErr {
    let err = step_error_after(py, e, records);
    let kept = err.value(py).setattr("_records", run);
    match kept {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// `soilcut.SnapshotError`: bytes that are no snapshot this build restores.
pub fn snapshot_error(py: Python<'_>, message: impl Into<String>) -> PyErr {
    raise(py, "SnapshotError", message.into(), None)
}

/// `advance_to`'s errors: a bad argument as `ValueError`, a steered case
/// that does not validate as `soilcut.CaseError` (naming its key), a failed
/// increment as `soilcut.StepError`.
pub fn advance_error(py: Python<'_>, e: AdvanceError) -> PyErr {
    match e {
        AdvanceError::Argument { .. } => PyValueError::new_err(e.to_string()),
        AdvanceError::Case(c) => {
            let message = format!("advance_to: {}", c.message);
            raise(
                py,
                "CaseError",
                format!("{}: {message}", c.key),
                Some(c.key),
            )
        }
        AdvanceError::Step { records, error } => step_error_after(py, error, records),
    }
}

/// A panic of the model (a bug) as a `RuntimeError`, so that it never
/// reaches Python as a `PanicException` (which escapes `except Exception`).
fn panic_error(panic: Box<dyn Any + Send>) -> PyErr {
    let text = panic_message(panic.as_ref());
    PyRuntimeError::new_err(format!("the model panicked (a bug of soilcut): {text}"))
}

/// Runs `f` without the interpreter (other Python threads go on); a step
/// error becomes `soilcut.StepError`, a panic a `RuntimeError`.
pub fn detached<T: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, StepError> + Send,
) -> PyResult<T> {
    detached_map(py, f, step_error)
}

/// `detached` for any error of the model, which `error` converts.
pub fn detached_map<T: Send, E: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, E> + Send,
    error: impl FnOnce(Python<'_>, E) -> PyErr,
) -> PyResult<T> {
    match py.detach(|| catch_unwind(AssertUnwindSafe(f))) {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(e)) => Err(error(py, e)),
        Err(panic) => Err(panic_error(panic)),
    }
}
