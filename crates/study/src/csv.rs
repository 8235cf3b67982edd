//! CSV text: numbers in Rust's shortest round-trip form, text fields quoted
//! when they need it (RFC 4180).

/// `text` as one CSV field: quoted, with quotes doubled, if it holds a
/// comma, a quote or a line break.
pub fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// A case value as a CSV field: numbers as written by Rust's `{}`,
/// strings as themselves, anything else as TOML.
pub fn value(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => x.to_string(),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::String(s) => field(s),
        other => field(&other.to_string()),
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

/// Joins fields into one line with its line break.
pub fn line(fields: &[String]) -> String {
    let mut out = fields.join(",");
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_when_needed() {
        assert_eq!(field("plain"), "plain");
        assert_eq!(field("a, b"), "\"a, b\"");
        assert_eq!(field("say \"x\""), "\"say \"\"x\"\"\"");
        assert_eq!(value(&toml::Value::Float(30.0)), "30");
        assert_eq!(value(&toml::Value::Float(0.1 + 0.2)), "0.30000000000000004");
        assert_eq!(number(f64::NAN), "");
    }
}
