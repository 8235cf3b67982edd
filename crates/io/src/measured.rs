//! Measured force-displacement curves, as spreadsheets export them: CSV
//! with the columns `u` and `force` and optionally `weight` (in any order,
//! among others that are ignored; names ignore case), one point a row.
//!
//! Read with the `csv` crate: fields may be quoted, the delimiter is `,`,
//! `;` or a tab (whichever the header line holds most of, outside quotes),
//! a leading byte-order mark is dropped, blank lines and lines starting
//! with `#` are skipped. With `;` as the delimiter a number may use a
//! decimal comma (`1,5`), as spreadsheets in such locales write it.

use crate::error::InputError;
use std::path::Path;

/// A measured curve: points (u, force) in the file's order and the weight
/// of each (1 where the file has no `weight` column).
#[derive(Clone, Debug, PartialEq)]
pub struct MeasuredCurve {
    /// (u, force) per row, in the file's units.
    pub points: Vec<(f64, f64)>,
    /// The weight of each point, ≥ 0.
    pub weights: Vec<f64>,
}

/// Reads a measured curve: (u, force) per row, in the file's order.
pub fn read_measured(path: &Path) -> Result<Vec<(f64, f64)>, InputError> {
    Ok(read_measured_curve(path)?.points)
}

/// Reads a measured curve with its weights.
pub fn read_measured_curve(path: &Path) -> Result<MeasuredCurve, InputError> {
    let bytes = std::fs::read(path).map_err(InputError::ReadMeasured)?;
    parse_measured_bytes(&bytes)
}

/// [`read_measured_curve`] on the bytes of the file, as read from disk:
/// text that is not UTF-8 is a syntax error naming its line.
pub fn parse_measured_bytes(bytes: &[u8]) -> Result<MeasuredCurve, InputError> {
    parse_measured_curve(crate::error::utf8(bytes)?)
}

/// [`read_measured`] on the text of the file.
pub fn parse_measured(text: &str) -> Result<Vec<(f64, f64)>, InputError> {
    Ok(parse_measured_curve(text)?.points)
}

/// [`read_measured_curve`] on the text of the file. Every value must be a
/// finite number, every weight ≥ 0 with at least one > 0; at least two
/// points are needed. Errors name the line and the column.
pub fn parse_measured_curve(text: &str) -> Result<MeasuredCurve, InputError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let (header_line, header) = header_of(text)?;
    let delimiter = delimiter_of(header);
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(delimiter)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(text.as_bytes());
    let names: Vec<String> = reader
        .headers()
        .map_err(|e| syntax(header_line, e.to_string()))?
        .iter()
        .map(str::to_lowercase)
        .collect();
    let layout = Layout::of(names, header_line, delimiter)?;
    let mut curve = MeasuredCurve {
        points: Vec::new(),
        weights: Vec::new(),
    };
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(header_line, |p| p.line() as usize);
            syntax(line, e.to_string())
        })?;
        let (point, weight) = layout.row(&record)?;
        curve.points.push(point);
        curve.weights.push(weight);
    }
    enough(curve, header_line)
}

fn syntax(line: usize, message: String) -> InputError {
    InputError::Syntax { line, message }
}

/// The header: the first line that is neither blank nor a `#` comment,
/// with its number (from 1).
fn header_of(text: &str) -> Result<(usize, &str), InputError> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .find(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .ok_or_else(|| {
            syntax(
                1,
                "empty file: expected a header with the columns u,force".into(),
            )
        })
}

/// Where the columns a curve reads are, by the header's (lower-case)
/// names.
struct Layout {
    names: Vec<String>,
    delimiter: u8,
    u: usize,
    force: usize,
    weight: Option<usize>,
}

impl Layout {
    fn of(names: Vec<String>, header_line: usize, delimiter: u8) -> Result<Self, InputError> {
        let column = |name: &str| names.iter().position(|n| n == name);
        let missing = |name: &str| {
            syntax(
                header_line,
                format!("the header has no column {name:?} (expected the columns u,force)"),
            )
        };
        let u = column("u").ok_or_else(|| missing("u"))?;
        let force = column("force").ok_or_else(|| missing("force"))?;
        let weight = column("weight");
        Ok(Layout {
            names,
            delimiter,
            u,
            force,
            weight,
        })
    }

    /// A data row's point (u, force) and weight (1 without the column).
    fn row(&self, record: &csv::StringRecord) -> Result<((f64, f64), f64), InputError> {
        let line = record.position().map_or(0, |p| p.line() as usize);
        if record.len() != self.names.len() {
            return Err(syntax(
                line,
                format!(
                    "{} fields, the header has {}",
                    record.len(),
                    self.names.len()
                ),
            ));
        }
        let number = |col: usize| {
            let field = &record[col];
            parse_number(field, self.delimiter).ok_or_else(|| {
                syntax(
                    line,
                    format!(
                        "column {} ({}): {field:?} is not a finite number",
                        col + 1,
                        self.names[col]
                    ),
                )
            })
        };
        let point = (number(self.u)?, number(self.force)?);
        let weight = match self.weight {
            Some(col) => number(col)?,
            None => 1.0,
        };
        if weight < 0.0 {
            return Err(syntax(
                line,
                format!(
                    "column {} (weight): {weight} is negative",
                    self.weight.unwrap_or(0) + 1
                ),
            ));
        }
        Ok((point, weight))
    }
}

/// The curve if it can be fitted: two points or more, a weight > 0.
fn enough(curve: MeasuredCurve, header_line: usize) -> Result<MeasuredCurve, InputError> {
    if curve.points.len() < 2 {
        return Err(syntax(
            header_line,
            format!("{} data rows: a curve needs at least 2", curve.points.len()),
        ));
    }
    if curve.weights.iter().all(|&w| w == 0.0) {
        return Err(syntax(header_line, "every weight is 0".into()));
    }
    Ok(curve)
}

/// The delimiter of a header line: `;`, tab or `,`, whichever occurs most
/// outside quotes (`,` on a tie or when none does).
fn delimiter_of(header: &str) -> u8 {
    let mut counts = [0usize; 3];
    let mut quoted = false;
    for c in header.chars() {
        match c {
            '"' => quoted = !quoted,
            ';' if !quoted => counts[0] += 1,
            '\t' if !quoted => counts[1] += 1,
            ',' if !quoted => counts[2] += 1,
            _ => {}
        }
    }
    let best = (0..3).max_by_key(|&i| (counts[i], i)).unwrap_or(2);
    [b';', b'\t', b','][best]
}

/// A finite number; with `;` as the delimiter a single decimal comma is
/// read as a point.
fn parse_number(field: &str, delimiter: u8) -> Option<f64> {
    let parsed = field.parse::<f64>().ok().or_else(|| {
        (delimiter == b';' && field.matches(',').count() == 1 && !field.contains('.'))
            .then(|| field.replace(',', ".").parse::<f64>().ok())
            .flatten()
    });
    parsed.filter(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error_of(text: &str) -> (usize, String) {
        match parse_measured(text) {
            Err(InputError::Syntax { line, message }) => (line, message),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn columns_by_name() {
        let text = "# lab test 3\nforce, u ,t\n1.5,0,9\n\n2.5,0.25,9\n";
        assert_eq!(parse_measured(text).unwrap(), vec![(0.0, 1.5), (0.25, 2.5)]);
    }

    #[test]
    fn files_as_spreadsheets_write_them() {
        let want = vec![(0.0, 1.5), (0.25, 2.5)];
        let quoted = "\u{feff}\"time, s\",\"U\",\"Force\"\n\"0\",0,1.5\n\"1, 2\",0.25,\"2.5\"\n";
        assert_eq!(parse_measured(quoted).unwrap(), want);
        let semicolons = "u;force;note\n0;1,5;a, b\n0,25;2,5;c\n";
        assert_eq!(parse_measured(semicolons).unwrap(), want);
        let tabs = "u\tforce\n0\t1.5\n0.25\t2.5\n";
        assert_eq!(parse_measured(tabs).unwrap(), want);
        let weighted = parse_measured_curve("u,force,weight\n0,1.5,2\n0.25,2.5,0\n").unwrap();
        assert_eq!(weighted.points, want);
        assert_eq!(weighted.weights, vec![2.0, 0.0]);
        assert_eq!(parse_measured_curve(tabs).unwrap().weights, vec![1.0, 1.0]);
    }

    #[test]
    fn errors_name_the_line_and_column() {
        assert_eq!(error_of("u,f\n0,1\n1,2\n").0, 1);
        let (line, message) = error_of("u,force\n0,1\n1,x\n");
        assert_eq!(line, 3);
        assert!(message.contains("column 2 (force)"), "{message}");
        assert_eq!(error_of("u,force\n0,1\n1,inf\n").0, 3);
        assert_eq!(error_of("# note\n\nu,force\n0,1\n1\n").0, 5);
        assert_eq!(error_of("u,force\n0,1\n").0, 1);
        assert_eq!(error_of("").0, 1);
        assert_eq!(error_of("u,force,weight\n0,1,1\n1,2,-1\n").0, 3);
        assert_eq!(error_of("u,force,weight\n0,1,0\n1,2,0\n").0, 1);
        match parse_measured_bytes(b"u,force\n0,1\n1,\xff\n") {
            Err(InputError::Syntax { line, message }) => {
                assert_eq!(line, 3);
                assert!(message.contains("0xff at column 3"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        let (line, message) = error_of("u,force\n0,1\n\"1,2\n");
        assert!(line >= 3, "{line}: {message}");
    }
}
