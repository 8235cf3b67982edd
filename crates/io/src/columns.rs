//! The numbers of soilcut's CSV files before they are text: named
//! columns of one length. The files are written from these values, and
//! every front end that hands out numbers (Python's arrays) takes the same
//! values, so a front end's array and the file agree bit for bit without
//! the text being parsed back.

use crate::csv_text::CsvText;
use crate::error::RunFilesError;
use std::path::Path;

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
    /// text reads back to these values exactly.
    pub fn csv(&self) -> String {
        let mut out = CsvText::new(&self.names.join(","));
        let mut row = Vec::with_capacity(self.names.len());
        for i in 0..self.len() {
            row.clear();
            row.extend(self.values.iter().map(|c| c[i]));
            let fields: Vec<&dyn std::fmt::Display> =
                row.iter().map(|x| x as &dyn std::fmt::Display).collect();
            out.row(&fields);
        }
        out.finish()
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
