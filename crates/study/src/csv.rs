//! CSV text written with the `csv` crate: numbers in Rust's shortest
//! round-trip form, text fields quoted when they need it (RFC 4180).

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

/// One record of fields with its line break, written by the `csv`
/// crate: a field is quoted, with quotes doubled, only if it holds a
/// comma, a quote or a line break.
pub fn line<S: AsRef<str>>(fields: &[S]) -> String {
    let mut writer = csv::WriterBuilder::new()
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(Vec::new());
    // Writing to memory cannot fail, and UTF-8 fields give UTF-8 out.
    writer
        .write_record(fields.iter().map(|f| f.as_ref()))
        .expect("a record written to memory");
    let bytes = writer.into_inner().expect("a writer flushed to memory");
    String::from_utf8(bytes).expect("UTF-8 fields")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_when_needed() {
        assert_eq!(line(&["plain", "1.5"]), "plain,1.5\n");
        assert_eq!(line(&["a, b"]), "\"a, b\"\n");
        assert_eq!(line(&["say \"x\"", ""]), "\"say \"\"x\"\"\",\n");
        assert_eq!(value(&toml::Value::Float(30.0)), "30");
        assert_eq!(value(&toml::Value::Float(0.1 + 0.2)), "0.30000000000000004");
        assert_eq!(number(f64::NAN), "");
    }
}
