//! Measured force-displacement curves: CSV with the columns `u` and
//! `force` (in any order, among others that are ignored), one point a row.

use crate::error::InputError;
use std::path::Path;

/// Reads a measured curve: (u, force) per row, in the file's order.
pub fn read_measured(path: &Path) -> Result<Vec<(f64, f64)>, InputError> {
    let text = std::fs::read_to_string(path).map_err(InputError::Read)?;
    parse_measured(&text)
}

/// [`read_measured`] on the text of the file. Blank lines and lines
/// starting with `#` are skipped; every value must be a finite number;
/// at least two points are needed.
pub fn parse_measured(text: &str) -> Result<Vec<(f64, f64)>, InputError> {
    let syntax = |line: usize, message: String| InputError::Syntax { line, message };
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (header_line, header) = rows.next().ok_or_else(|| {
        syntax(
            1,
            "empty file: expected a header with the columns u,force".into(),
        )
    })?;
    let names: Vec<&str> = header
        .split(',')
        .map(|s| s.trim().trim_matches('"'))
        .collect();
    let column = |name: &str| {
        names.iter().position(|n| *n == name).ok_or_else(|| {
            syntax(
                header_line,
                format!("the header has no column {name:?} (expected the columns u,force)"),
            )
        })
    };
    let (u_col, force_col) = (column("u")?, column("force")?);
    let mut points = Vec::new();
    for (line, row) in rows {
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            return Err(syntax(
                line,
                format!("{} fields, the header has {}", fields.len(), names.len()),
            ));
        }
        let number = |col: usize| match fields[col].parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(syntax(
                line,
                format!("{}: {:?} is not a finite number", names[col], fields[col]),
            )),
        };
        points.push((number(u_col)?, number(force_col)?));
    }
    if points.len() < 2 {
        return Err(syntax(
            header_line,
            format!("{} data rows: a curve needs at least 2", points.len()),
        ));
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_of(text: &str) -> usize {
        match parse_measured(text) {
            Err(InputError::Syntax { line, .. }) => line,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn columns_by_name() {
        let text = "# lab test 3\nforce, u ,t\n1.5,0,9\n\n2.5,0.25,9\n";
        assert_eq!(parse_measured(text).unwrap(), vec![(0.0, 1.5), (0.25, 2.5)]);
    }

    #[test]
    fn errors_name_the_line() {
        assert_eq!(line_of("u,f\n0,1\n1,2\n"), 1);
        assert_eq!(line_of("u,force\n0,1\n1,x\n"), 3);
        assert_eq!(line_of("u,force\n0,1\n1,inf\n"), 3);
        assert_eq!(line_of("u,force\n0,1\n1\n"), 3);
        assert_eq!(line_of("u,force\n0,1\n"), 1);
        assert_eq!(line_of(""), 1);
    }
}
