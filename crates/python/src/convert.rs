//! Python values ↔ TOML values (the case file's types), columns of
//! numbers → NumPy arrays, JSON values → Python values.

use crate::errors::key_error;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use soilcut_io::Columns;

/// A Python value as the TOML value of `key`: bool, int, float (NumPy
/// scalars included), str, a list or tuple, a dict with str keys.
pub fn to_toml(key: &str, value: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    let py = value.py();
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return value
            .extract::<i64>()
            .map(toml::Value::Integer)
            .map_err(|_| key_error(py, key, &format!("the integer {value} is out of range")));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(value.extract()?));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        return table(key, dict).map(toml::Value::Table);
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items = value
            .try_iter()?
            .enumerate()
            .map(|(i, item)| to_toml(&format!("{key}[{i}]"), &item?))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(items));
    }
    // NumPy scalars and other numbers: integers first, then floats.
    if value.hasattr("__index__")? {
        if let Ok(i) = value.extract::<i64>() {
            return Ok(toml::Value::Integer(i));
        }
    }
    if value.hasattr("__float__")? {
        if let Ok(x) = value.extract::<f64>() {
            return Ok(toml::Value::Float(x));
        }
    }
    let type_name = value.get_type().name()?;
    Err(key_error(
        py,
        key,
        &format!("a value of type {type_name} cannot be set (expected a number, a string, a bool, a list or a dict)"),
    ))
}

/// A dict of str keys as a TOML table; `prefix` names its keys in errors.
pub fn table(prefix: &str, dict: &Bound<'_, PyDict>) -> PyResult<toml::Table> {
    let mut out = toml::Table::new();
    for (k, v) in dict.iter() {
        let Ok(name) = k.extract::<String>() else {
            let message = format!("the keys of a table must be strings (got {k})");
            return Err(key_error(dict.py(), prefix, &message));
        };
        let path = if prefix.is_empty() {
            name.clone()
        } else {
            format!("{prefix}.{name}")
        };
        out.insert(name, to_toml(&path, &v)?);
    }
    Ok(out)
}

/// A TOML value as a plain Python value (tables as dicts).
pub fn from_toml<'py>(py: Python<'py>, value: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        toml::Value::String(s) => s.into_pyobject(py)?.into_any(),
        toml::Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        toml::Value::Float(x) => x.into_pyobject(py)?.into_any(),
        toml::Value::Boolean(b) => b.into_pyobject(py)?.to_owned().into_any(),
        toml::Value::Datetime(d) => d.to_string().into_pyobject(py)?.into_any(),
        toml::Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(from_toml(py, item)?)?;
            }
            list.into_any()
        }
        toml::Value::Table(t) => dict(py, t)?.into_any(),
    })
}

/// A TOML table as a dict, in the table's order.
pub fn dict<'py>(py: Python<'py>, table: &toml::Table) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (k, v) in table {
        out.set_item(k, from_toml(py, v)?)?;
    }
    Ok(out)
}

/// Columns as a dict of float64 arrays, in order.
pub fn arrays<'py>(py: Python<'py>, columns: &Columns) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (name, values) in columns.iter() {
        out.set_item(name, PyArray1::from_slice(py, values))?;
    }
    Ok(out)
}

/// A JSON value as a plain Python value (objects as dicts, `null` as None).
pub fn json<'py>(py: Python<'py>, value: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            // Neither integer: a float, which serde_json holds as f64.
            _ => n.as_f64().into_pyobject(py)?.into_any(),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(json(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let out = PyDict::new(py);
            for (k, v) in map {
                out.set_item(k, json(py, v)?)?;
            }
            out.into_any()
        }
    })
}
