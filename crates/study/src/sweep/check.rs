//! The keys and values of a sweep checked before any run: what would make
//! every run with them fail alike.

use crate::error::StudyError;
use crate::run::BaseCase;
use soilcut_io::InputError;
use soilcut_model::CaseError;

/// Refuses keys that no run of `base` could set, and values of a type the
/// key does not take (a string where the case has a number), with
/// `values` (a run's) as the probe: a sweep given its runs directly
/// (Python's `samples`) checks them as `Sweep::points` does.
pub fn check_keys(
    base: &BaseCase,
    keys: &[String],
    values: &[toml::Value],
) -> Result<(), StudyError> {
    let resolved = base.load(&[]).ok().map(|l| l.resolved_table());
    for (key, value) in keys.iter().zip(values) {
        if let Some(e) = base.unknown_key(key, value) {
            return Err(StudyError::Key(e));
        }
        let held = resolved.as_ref().and_then(|t| value_at(t, key));
        if let Some(held) = held.filter(|held| !same_kind(held, value)) {
            let message = format!("expected {}, got {}", kind(held), given(value));
            return Err(StudyError::Key(InputError::from(CaseError::new(
                key, message,
            ))));
        }
    }
    Ok(())
}

/// The value of the dotted `key` in `table`.
fn value_at<'a>(table: &'a toml::Table, key: &str) -> Option<&'a toml::Value> {
    let mut parts = key.split('.');
    let mut value = table.get(parts.next()?)?;
    for part in parts {
        value = value.as_table()?.get(part)?;
    }
    Some(value)
}

/// Whether `value` is of the kind of `held`, the case's value (a whole
/// number counts as a number: the case reads either).
fn same_kind(held: &toml::Value, value: &toml::Value) -> bool {
    let number = |v: &toml::Value| v.is_float() || v.is_integer();
    (number(held) && number(value)) || held.type_str() == value.type_str()
}

/// The kind of value a key takes, in words.
fn kind(held: &toml::Value) -> &'static str {
    match held {
        toml::Value::Float(_) | toml::Value::Integer(_) => "a number",
        toml::Value::String(_) => "a string",
        toml::Value::Boolean(_) => "a boolean",
        toml::Value::Array(_) => "a list",
        toml::Value::Table(_) => "a table",
        toml::Value::Datetime(_) => "a date",
    }
}

/// A value given, in words (as the case file's errors say it).
fn given(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => format!("the string {s:?}"),
        toml::Value::Boolean(b) => format!("the boolean {b}"),
        other => format!("{} {other}", kind(other)),
    }
}
