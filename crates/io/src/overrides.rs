//! `--set key.path=value`: changes to a case file's table before it is read.

use crate::error::InputError;
use std::str::FromStr;

/// One `key.path=value` override. The value is read as a TOML value
/// (`0.02`, `"refined"`, `{ peak = 36, residual = 30 }`), or else taken as
/// a bare string (`refined`).
#[derive(Clone, Debug, PartialEq)]
pub struct Override {
    text: String,
    key: Vec<String>,
    value: toml::Value,
}

impl FromStr for Override {
    type Err = InputError;

    fn from_str(text: &str) -> Result<Self, InputError> {
        let bad = |message: &str| InputError::Override {
            text: text.to_string(),
            message: message.to_string(),
        };
        let (key, value) = text
            .split_once('=')
            .ok_or_else(|| bad("expected key.path=value"))?;
        let value = value.trim();
        // Read as TOML, a line break would start a second key=value that
        // is dropped: `run.travel=10\nblade.depth=5` set the travel only.
        if value.contains(['\n', '\r']) {
            return Err(bad(
                "the value holds a line break: give one key=value per --set (two keys, two --set)",
            ));
        }
        let depth = nesting(value);
        if depth > MAX_NESTING {
            return Err(bad(&format!(
                "nested {depth} arrays or tables deep: no key takes more than 2 \
                 (blade.depth_path = [[u, d], ...])"
            )));
        }
        if out_of_range(value) {
            return Err(bad(&format!(
                "{value} is out of range for a number (magnitude at most about 1.8e308)"
            )));
        }
        Override::with_text(text, key.trim(), parse_value(value))
    }
}

/// The deepest a `--set` value may nest arrays and tables: no key takes
/// more than two levels, and a parser recursing through a hundred levels
/// overflowed a test thread's stack (found by fuzzing `set_override`).
const MAX_NESTING: usize = 8;

/// How deep `value` nests arrays and tables, outside quoted strings.
fn nesting(value: &str) -> usize {
    let (mut depth, mut deepest, mut quote) = (0usize, 0, None);
    for c in value.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '"' | '\'') => quote = Some(c),
            (None, '[' | '{') => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            (None, ']' | '}') => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

/// A `--set` value: TOML (`0.02`, `"x"`, `{ peak = 36 }`), or else the
/// text as a bare string.
pub fn parse_value(text: &str) -> toml::Value {
    format!("v = {text}")
        .parse::<toml::Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| toml::Value::String(text.to_string()))
}

/// A number too large for a float (`1e400`): TOML refuses it, and taken
/// as a bare string it would be reported as a string where a number is
/// expected.
fn out_of_range(value: &str) -> bool {
    let number = |c: char| c.is_ascii_digit() || "+-.eE_".contains(c);
    value.chars().all(number)
        && value.parse::<f64>().is_ok_and(f64::is_infinite)
        && !matches!(parse_value(value), toml::Value::Float(_))
}

impl Override {
    /// Sets the dotted `key` to `value`, as `--set key=value` would, for a
    /// front end that has the value already (no text to parse).
    pub fn new(key: &str, value: toml::Value) -> Result<Override, InputError> {
        Override::with_text(&format!("{key}={value}"), key, value)
    }

    fn with_text(text: &str, key: &str, value: toml::Value) -> Result<Override, InputError> {
        let key: Vec<String> = key.split('.').map(str::to_string).collect();
        if key.iter().any(|k| k.is_empty()) {
            return Err(InputError::Override {
                text: text.to_string(),
                message: "expected key.path=value with a non-empty key at each level".into(),
            });
        }
        Ok(Override {
            text: text.to_string(),
            key,
            value,
        })
    }

    /// The dotted key.
    pub fn key(&self) -> String {
        self.key.join(".")
    }

    /// Sets the key in `table`, creating missing tables on the way. Whether
    /// the key belongs to the schema is checked when the table is read.
    pub fn apply(&self, table: &mut toml::Table) -> Result<(), InputError> {
        let (last, parents) = self.key.split_last().expect("a key has one level at least");
        let mut current = table;
        for (depth, part) in parents.iter().enumerate() {
            let entry = current
                .entry(part.clone())
                .or_insert_with(|| toml::Value::Table(toml::Table::new()));
            current = entry.as_table_mut().ok_or_else(|| {
                InputError::key(
                    &self.key(),
                    format!(
                        "cannot set: {} is not a table",
                        self.key[..=depth].join(".")
                    ),
                )
            })?;
        }
        current.insert(last.clone(), self.value.clone());
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(table: &str, o: &str) -> toml::Table {
        let mut t: toml::Table = table.parse().unwrap();
        o.parse::<Override>().unwrap().apply(&mut t).unwrap();
        t
    }

    #[test]
    fn values_are_toml_or_bare_strings() {
        let t = set("[run]\nincrement = 0.04", "run.increment=0.02");
        assert_eq!(t["run"]["increment"].as_float(), Some(0.02));
        assert_eq!(set("", "model=refined")["model"].as_str(), Some("refined"));
        assert_eq!(
            set("", "model=\"refined\"")["model"].as_str(),
            Some("refined")
        );
        assert_eq!(
            set("", "soil.friction.peak=36")["soil"]["friction"]["peak"].as_integer(),
            Some(36)
        );
        assert!(set("", "x = nan")["x"].as_float().unwrap().is_nan());
    }

    #[test]
    fn numbers_beyond_a_float_are_refused_as_such() {
        let e = "run.increment=1e400".parse::<Override>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "--set run.increment=1e400: 1e400 is out of range for a number (magnitude at most about 1.8e308)"
        );
        assert!("run.increment=-1e400".parse::<Override>().is_err());
        for fine in ["x=1e300", "x=inf", "x=1e-400", "x=e400"] {
            assert!(fine.parse::<Override>().is_ok(), "{fine}");
        }
    }

    #[test]
    fn malformed_overrides_are_refused() {
        assert!("run.increment".parse::<Override>().is_err());
        for two in [
            "run.travel=10\nblade.depth=5",
            "run.travel=10\r\nblade.depth=5",
        ] {
            let e = two.parse::<Override>().unwrap_err();
            assert!(e.to_string().contains("line break"), "{e}");
        }
        assert!("run..increment=1".parse::<Override>().is_err());
        assert!("=1".parse::<Override>().is_err());
        let mut t: toml::Table = "[run]\nincrement = 0.04".parse().unwrap();
        let e = "run.increment.x=1"
            .parse::<Override>()
            .unwrap()
            .apply(&mut t)
            .unwrap_err();
        assert!(
            e.to_string().starts_with("run.increment.x: cannot set"),
            "{e}"
        );
    }

    #[test]
    fn values_nested_deeper_than_any_key_takes_are_refused() {
        let nested = |n: usize| format!("blade.depth_path={}{}", "[".repeat(n), "]".repeat(n));
        assert!(nested(MAX_NESTING).parse::<Override>().is_ok());
        let e = nested(MAX_NESTING + 1).parse::<Override>().unwrap_err();
        assert!(
            e.to_string().contains("nested 9 arrays or tables deep"),
            "{e}"
        );
        // Brackets inside a string are text, not nesting.
        let quoted = format!("name=\"{}\"", "[".repeat(100));
        assert!(quoted.parse::<Override>().is_ok());
    }

    #[test]
    fn control_characters_are_shown_escaped_on_one_line() {
        let e = "run.incr\nement".parse::<Override>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "--set run.incr\\nement: expected key.path=value"
        );
        let mut t = toml::Table::new();
        "a\tb.c=1"
            .parse::<Override>()
            .unwrap()
            .apply(&mut t)
            .unwrap();
        let e = "a\tb.c.d=1"
            .parse::<Override>()
            .unwrap()
            .apply(&mut t)
            .unwrap_err();
        assert!(e.to_string().starts_with("a\\tb.c.d: cannot set"), "{e}");
        assert_eq!(
            crate::parse_case("[\"x\\ny\"]\n", &[]).unwrap_err().to_string(),
            "\"x\\ny\": unknown key (nearest: `run`, `bin`; expected one of: `name`, `title`, `model`, `blade`, `tool`, `soil`, `run`, `bin`, `choices`)"
        );
    }
}
