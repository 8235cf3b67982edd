//! The fields of the studies' CSV files: numbers in Rust's shortest
//! round-trip form, a figure that does not exist empty. The files are
//! written by `soilcut_io::CsvText`, the one CSV writer of soilcut.

/// A case value as a CSV field: numbers as written by Rust's `{}`,
/// strings as themselves, anything else as TOML.
pub fn value(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => x.to_string(),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// A number as a CSV field; NaN (a figure that does not exist) as empty.
pub fn number(x: f64) -> String {
    if x.is_nan() {
        String::new()
    } else {
        x.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_as_rust_formats_them_and_nan_empty() {
        assert_eq!(value(&toml::Value::Float(30.0)), "30");
        assert_eq!(value(&toml::Value::Float(0.1 + 0.2)), "0.30000000000000004");
        assert_eq!(number(f64::NAN), "");
    }
}
