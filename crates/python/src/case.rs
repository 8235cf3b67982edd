//! The native side of `soilcut.Case`: a case file parsed once into its
//! table and read by `soilcut-io` exactly as the command line reads it;
//! every other call of the extension takes this handle, not text.

use crate::convert::{dict, from_toml, table, to_toml};
use crate::errors::{case_error, case_error_in, case_message};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use soilcut_io::{
    load_case_table, parse_case_bytes, parse_case_table, InputError, LoadedCase, Override,
};
use soilcut_study::BaseCase;
use std::path::{Path, PathBuf};

/// A validated case: the keys given (as a table and as text) and the case
/// they make, every default filled in.
#[pyclass(frozen, module = "soilcut._soilcut", name = "NativeCase")]
pub struct Case {
    /// The case file's text as given, or the table's text after `set_keys`.
    text: String,
    /// The keys given.
    table: toml::Table,
    pub loaded: LoadedCase,
    /// `case.resolved.toml`, kept for equality and hashing.
    resolved: String,
}

impl Case {
    fn of_table(py: Python<'_>, text: String, table: toml::Table) -> PyResult<Case> {
        let loaded = load_case_table(table.clone(), &[]).map_err(|e| case_error(py, &e))?;
        Ok(Case::of_loaded(text, table, loaded))
    }

    fn of_loaded(text: String, table: toml::Table, loaded: LoadedCase) -> Case {
        let resolved = loaded.resolved_toml();
        Case {
            text,
            table,
            loaded,
            resolved,
        }
    }

    /// The case every default filled in: that of `case.resolved.toml`.
    pub fn resolved_of(loaded: &LoadedCase) -> Case {
        let resolved = loaded.resolved_toml();
        Case {
            text: resolved.clone(),
            table: loaded.resolved_table(),
            loaded: loaded.clone(),
            resolved,
        }
    }

    /// The base of a study of this case.
    pub fn base(&self, py: Python<'_>) -> PyResult<BaseCase> {
        BaseCase::from_table(self.table.clone(), vec![]).map_err(|e| case_error(py, &e))
    }

    /// The handle of a `soilcut.Case`, of this class itself, of a case
    /// file's path (`os.PathLike`, or a string that [`names_a_file`]) or of
    /// its text.
    pub fn extract<'py>(case: &Bound<'py, PyAny>) -> PyResult<Bound<'py, Case>> {
        let py = case.py();
        if let Ok(native) = case.cast::<Case>() {
            return Ok(native.clone());
        }
        let path = match case.cast::<PyString>() {
            Ok(text) if !names_a_file(&text.to_cow()?) => {
                return Bound::new(py, Case::from_toml(py, &text.to_cow()?)?);
            }
            Ok(_) => true,
            Err(_) => case.hasattr("__fspath__")?,
        };
        if path {
            return Bound::new(py, Case::from_file(py, case.extract()?)?);
        }
        match case.getattr("_native") {
            Ok(native) => Ok(native.cast_into::<Case>()?),
            Err(_) => Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "expected a soilcut.Case, a case file's path or its text, not {}",
                case.get_type().name()?
            ))),
        }
    }
}

/// Whether a string given where a case is expected is a case file's path,
/// not its text: one line ending in `.toml`, naming a file or without `=`
/// (a case's text has a `key = value` line at least, and no file is named
/// so), so that a mistyped path is reported as a missing file.
fn names_a_file(text: &str) -> bool {
    !text.contains('\n')
        && (text.trim_end().ends_with(".toml") || !text.contains('=') || Path::new(text).is_file())
}

#[pymethods]
impl Case {
    /// The case of a `soilcut.Case`, of a case file's path or of its text
    /// (what every function taking a case accepts).
    #[staticmethod]
    fn of<'py>(case: &Bound<'py, PyAny>) -> PyResult<Bound<'py, Case>> {
        Case::extract(case)
    }

    /// Reads and validates a case file's text.
    #[staticmethod]
    fn from_toml(py: Python<'_>, text: &str) -> PyResult<Case> {
        let table = parse_case_table(text).map_err(|e| case_error(py, &e))?;
        Case::of_table(py, text.to_string(), table)
    }

    /// Reads and validates a case file (TOML, UTF-8): `OSError` (its
    /// subclass for the cause, `FileNotFoundError` …) if it cannot be read,
    /// `soilcut.CaseError` with the path before its message if it is not a
    /// valid case.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<Case> {
        let bytes = std::fs::read(&path)?;
        let named = |e: InputError| case_error_in(py, &path, &e);
        let text = match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(e) => {
                return Err(match parse_case_bytes(e.as_bytes(), &[]) {
                    Err(e) => named(e),
                    Ok(_) => case_message(py, format!("{}: not UTF-8", path.display())),
                })
            }
        };
        let table = parse_case_table(&text).map_err(named)?;
        let loaded = load_case_table(table.clone(), &[]).map_err(named)?;
        Ok(Case::of_loaded(text, table, loaded))
    }

    /// A case from nested dicts shaped like the case file, validated.
    #[staticmethod]
    fn from_dict(py: Python<'_>, d: &Bound<'_, PyDict>) -> PyResult<Case> {
        let table = table("", d)?;
        let text = toml::to_string(&table).map_err(|e| case_message(py, format!("case: {e}")))?;
        Case::of_table(py, text, table)
    }

    /// A new case with each `(key, value)` of `pairs` set as
    /// `--set key=value` sets it, then validated.
    fn set_keys(&self, py: Python<'_>, pairs: Vec<(String, Bound<'_, PyAny>)>) -> PyResult<Case> {
        let mut table = self.table.clone();
        for (key, value) in &pairs {
            let set = Override::new(key, to_toml(key, value)?).map_err(|e| case_error(py, &e))?;
            set.apply(&mut table).map_err(|e| case_error(py, &e))?;
        }
        let text = toml::to_string(&table).map_err(|e| case_message(py, format!("case: {e}")))?;
        Case::of_table(py, text, table)
    }

    /// The case file's text: as given, or rewritten after `set_keys`.
    fn to_toml(&self) -> &str {
        &self.text
    }

    /// The keys given as nested dicts.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        dict(py, &self.table)
    }

    /// The case every default filled in.
    fn resolved(&self) -> Case {
        Case::resolved_of(&self.loaded)
    }

    /// `case.resolved.toml`.
    fn resolved_toml(&self) -> &str {
        &self.resolved
    }

    /// The value of a dotted key of the resolved case, or None.
    fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Option<Bound<'py, PyAny>>> {
        let table = self.loaded.resolved_table();
        let mut parts = key.split('.');
        let mut value = parts.next().and_then(|p| table.get(p));
        for part in parts {
            value = value
                .and_then(toml::Value::as_table)
                .and_then(|t| t.get(part));
        }
        value.map(|v| from_toml(py, v)).transpose()
    }

    /// The case's name, title and model name (`original` or `refined`).
    fn names(&self) -> (&str, &str, &str) {
        let case = &self.loaded.case;
        (&case.name, &case.title, case.model.name())
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<Case>()
            .is_ok_and(|o| o.get().resolved == self.resolved)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        self.resolved.hash(&mut h);
        h.finish()
    }

    /// Pickles as its text (read again when unpickled).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let restore = slf.get_type().getattr("from_toml")?;
        Ok((restore, (slf.get().text.clone(),)))
    }
}
