//! The numbers of soilcut's CSV files before they are text: named
//! columns of one length. The files are written from these values, and
//! every front end that hands out numbers (Python's arrays) takes the same
//! values, so a front end's array and the file agree bit for bit without
//! the text being parsed back.

use crate::csv_text::CsvText;
use crate::error::RunFilesError;
use std::path::Path;

/// `x` as Rust's `{}` writes it: a whole number below 1e15 (not −0) by
/// the integer's formatting, which is the same text and far cheaper than
/// the shortest round-trip search.
fn write_number(out: &mut String, x: f64) {
    use std::fmt::Write;
    // Writing to a String cannot fail.
    let written = if x.fract() == 0.0 && x.abs() < 1e15 && !(x == 0.0 && x.is_sign_negative()) {
        write!(out, "{}", x as i64)
    } else {
        write!(out, "{x}")
    };
    written.expect("a number written to a String");
}

/// Named columns of numbers, every column as long as the others.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Columns {
    names: Vec<String>,
    values: Vec<Vec<f64>>,
}

impl Columns {
    /// No rows yet, columns named by `header` (names joined by commas).
    pub fn new(header: &str) -> Self {
        Columns::named(header.split(',').map(str::to_string).collect())
    }

    /// No rows yet, these columns.
    pub fn named(names: Vec<String>) -> Self {
        let values = vec![Vec::new(); names.len()];
        Columns { names, values }
    }

    /// Appends one row, a value per column in order.
    ///
    /// # Panics
    /// If `row` does not have one value per column (a bug of the caller).
    pub fn push(&mut self, row: &[f64]) {
        assert_eq!(row.len(), self.names.len(), "one value per column");
        for (column, &x) in self.values.iter_mut().zip(row) {
            column.push(x);
        }
    }

    /// The column names, in order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The values of column `name`, row by row.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        let i = self.names.iter().position(|n| n == name)?;
        Some(&self.values[i])
    }

    /// (name, values) of every column, in order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &[f64])> {
        self.names
            .iter()
            .map(String::as_str)
            .zip(self.values.iter().map(Vec::as_slice))
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.values.first().map_or(0, Vec::len)
    }

    /// Whether there are no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The CSV text: the header, then one line per row, every number in
    /// Rust's shortest round-trip form (`1` for 1.0, `NaN`), so that the
    /// text reads back to these values exactly. A number never needs
    /// quoting, so the rows are written directly (`write_number`), and a
    /// value equal to the one above it in its column (the frame, step and
    /// u of `frames.csv`'s rows) is copied, not formatted again.
    pub fn csv(&self) -> String {
        let mut out = CsvText::new(&self.names.join(",")).finish();
        let mut above: Vec<(u64, String)> = vec![(0, String::new()); self.values.len()];
        for i in 0..self.len() {
            for (j, column) in self.values.iter().enumerate() {
                if j > 0 {
                    out.push(',');
                }
                let (bits, text) = &mut above[j];
                let x = column[i];
                if i == 0 || x.to_bits() != *bits {
                    *bits = x.to_bits();
                    text.clear();
                    write_number(text, x);
                }
                out.push_str(text);
            }
            out.push('\n');
        }
        out
    }

    /// Reads the CSV file of numbers at `path` (as [`Columns::parse`]).
    pub fn read(path: &Path) -> Result<Columns, RunFilesError> {
        let text = std::fs::read_to_string(path).map_err(|e| RunFilesError::new(path, e))?;
        Columns::parse(path, &text)
    }

    /// The columns of a CSV text of numbers with a header line (`path`
    /// names it in errors), read with the `csv` crate: blank lines are
    /// skipped and fields trimmed. What [`Columns::csv`] wrote reads back
    /// to the same columns.
    pub fn parse(path: impl AsRef<Path>, text: &str) -> Result<Columns, RunFilesError> {
        let path = path.as_ref();
        // The line of the record that starts at `byte` (the csv crate's
        // count skips blank lines, and its position is before them).
        let line_at = |byte: u64| {
            let (before, after) = text.as_bytes().split_at(byte as usize);
            let breaks = |bytes: &[u8]| bytes.iter().filter(|&&b| b == b'\n').count();
            let blank = after.iter().take_while(|b| b.is_ascii_whitespace()).count();
            breaks(before) + breaks(&after[..blank]) + 1
        };
        let fail = |line: usize, message: String| {
            RunFilesError::new(path, format!("line {line}: {message}"))
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .flexible(true)
            .from_reader(text.as_bytes());
        let names: Vec<String> = reader
            .headers()
            .map_err(|e| fail(1, e.to_string()))?
            .iter()
            .map(str::to_string)
            .collect();
        if names.is_empty() {
            return Err(RunFilesError::new(
                path,
                "empty file: expected a header line",
            ));
        }
        let mut out = Columns::named(names);
        for record in reader.records() {
            let record = record
                .map_err(|e| fail(e.position().map_or(0, |p| line_at(p.byte())), e.to_string()))?;
            // Counted only for an error: a scan of the text before it.
            let line = || record.position().map_or(0, |p| line_at(p.byte()));
            if record.len() != out.names.len() {
                let message = format!("{} values for {} columns", record.len(), out.names.len());
                return Err(fail(line(), message));
            }
            for (column, field) in out.values.iter_mut().zip(&record) {
                column.push(field.parse().map_err(|e| fail(line(), format!("{e}")))?);
            }
        }
        Ok(out)
    }

    /// The columns named in `names`, in that order; the message names a
    /// missing one.
    pub fn columns<const N: usize>(&self, names: [&str; N]) -> Result<[&[f64]; N], String> {
        let mut out: [&[f64]; N] = [&[]; N];
        for (slot, name) in out.iter_mut().zip(names) {
            *slot = self
                .column(name)
                .ok_or_else(|| format!("no column `{name}`"))?;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_reads_back_to_the_same_bits() {
        let mut c = Columns::new("step,u,force");
        c.push(&[1.0, 0.1 + 0.2, 1e-300]);
        c.push(&[2.0, -0.0, 123456.789e10]);
        let text = c.csv();
        assert!(
            text.starts_with("step,u,force\n1,0.30000000000000004,"),
            "{text}"
        );
        let back = Columns::parse("t.csv", &text).unwrap();
        for ((n, a), (m, b)) in c.iter().zip(back.iter()) {
            assert_eq!(n, m);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(a), bits(b), "{n}");
        }
        assert_eq!(back.len(), 2);
        assert_eq!(back.column("u"), Some(&[0.1 + 0.2, -0.0][..]));
        assert_eq!(back.column("v"), None);
    }

    /// The text as the `csv` crate writes each number's `{}`: the
    /// yardstick `csv` must equal byte for byte.
    fn plain_csv(c: &Columns) -> String {
        let mut out = CsvText::new(&c.names.join(","));
        for i in 0..c.len() {
            let row: Vec<f64> = c.values.iter().map(|v| v[i]).collect();
            let fields: Vec<&dyn std::fmt::Display> =
                row.iter().map(|x| x as &dyn std::fmt::Display).collect();
            out.row(&fields);
        }
        out.finish()
    }

    #[test]
    fn text_is_rusts_formatting_of_every_number() {
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1e15,
            -1e15,
            999_999_999_999_999.0,
            1e16,
            2f64.powi(53),
            1e21,
            1e-300,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
        ];
        let mut c = Columns::new("a,b,c");
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for i in 0..4000 {
            let r = next();
            let x = match i % 4 {
                0 => f64::from_bits(r),
                1 => (r % 2_000_001) as f64 - 1e6,
                2 => special[(r % special.len() as u64) as usize],
                _ => (r % 1000) as f64 / 8.0,
            };
            // Repeats down a column, as frames.csv's frame and u.
            let repeat = if i % 3 == 0 { x } else { 0.25 };
            c.push(&[x, repeat, -x]);
        }
        assert_eq!(c.csv(), plain_csv(&c));
    }

    #[test]
    #[should_panic(expected = "one value per column")]
    fn a_short_row_is_a_bug() {
        Columns::new("a,b").push(&[1.0]);
    }

    #[test]
    fn a_file_reads_by_column_name() {
        let t = Columns::parse("t.csv", "u,force\n0,1.5\n\n2, 3e-1\n\n").unwrap();
        assert_eq!(t.len(), 2);
        assert_eq!(t.column("force"), Some(&[1.5, 0.3][..]));
        let [u, force] = t.columns(["u", "force"]).unwrap();
        assert_eq!((u, force), (&[0.0, 2.0][..], &[1.5, 0.3][..]));
        assert_eq!(t.columns(["u", "beta"]).unwrap_err(), "no column `beta`");
        assert_eq!(t.column("depth"), None);
    }

    #[test]
    fn ragged_or_bad_rows_are_refused_at_their_line() {
        let e = Columns::parse("t.csv", "u,force\n0\n").unwrap_err();
        assert_eq!(e.message, "line 2: 1 values for 2 columns");
        let e = Columns::parse("t.csv", "u,force\n\n0,x\n").unwrap_err();
        assert!(e.message.starts_with("line 3:"), "{}", e.message);
        let e = Columns::parse("t.csv", "").unwrap_err();
        assert_eq!(e.message, "empty file: expected a header line");
    }
}
