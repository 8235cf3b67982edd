//! The numbers of soilcut's CSV files before they are text: named
//! columns of one length. The files are written from these values, and
//! every front end that hands out numbers (Python's arrays) takes the same
//! values, so a front end's array and the file agree bit for bit without
//! the text being parsed back.

use crate::csv_text::CsvText;
use crate::error::RunFilesError;
use std::path::{Path, PathBuf};

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

    /// The columns of a CSV text of numbers (`name` names it in errors):
    /// what [`Columns::csv`] wrote reads back to the same columns.
    pub fn parse(name: &str, text: &str) -> Result<Columns, RunFilesError> {
        let table = Table::parse(Path::new(name), text)?;
        let mut out = Columns::named(table.header().to_vec());
        for (slot, name) in out.values.iter_mut().zip(table.header()) {
            *slot = table.column(name)?;
        }
        Ok(out)
    }
}

/// A CSV file of numbers with a header line, read by column name.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    path: PathBuf,
    header: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Table {
    /// Reads `path`: a header of column names, then rows of numbers.
    pub fn read(path: &Path) -> Result<Table, RunFilesError> {
        let text = std::fs::read_to_string(path).map_err(|e| RunFilesError::new(path, e))?;
        Table::parse(path, &text)
    }

    /// Parses `text` (`path` names it in errors).
    pub fn parse(path: &Path, text: &str) -> Result<Table, RunFilesError> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let header: Vec<String> = lines
            .next()
            .ok_or_else(|| RunFilesError::new(path, "empty file: expected a header line"))?
            .1
            .split(',')
            .map(|c| c.trim().to_string())
            .collect();
        let mut rows = Vec::new();
        for (i, line) in lines {
            let row = line
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| RunFilesError::new(path, format!("line {}: {e}", i + 1)))?;
            if row.len() != header.len() {
                let message = format!(
                    "line {}: {} values for {} columns",
                    i + 1,
                    row.len(),
                    header.len()
                );
                return Err(RunFilesError::new(path, message));
            }
            rows.push(row);
        }
        Ok(Table {
            path: path.to_path_buf(),
            header,
            rows,
        })
    }

    /// The column names, in order.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether the table has no rows.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The values of column `name`, row by row.
    pub fn column(&self, name: &str) -> Result<Vec<f64>, RunFilesError> {
        let i = self
            .header
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| RunFilesError::new(&self.path, format!("no column `{name}`")))?;
        Ok(self.rows.iter().map(|r| r[i]).collect())
    }

    /// The columns named in `names`, in that order.
    pub fn columns<const N: usize>(
        &self,
        names: [&str; N],
    ) -> Result<[Vec<f64>; N], RunFilesError> {
        let mut out: [Vec<f64>; N] = std::array::from_fn(|_| Vec::new());
        for (slot, name) in out.iter_mut().zip(names) {
            *slot = self.column(name)?;
        }
        Ok(out)
    }

    /// The values of column `name`, or `None` if the table has no such
    /// column (a column added in a later version, absent from older runs).
    pub fn optional_column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.header.iter().position(|h| h == name)?;
        Some(self.rows.iter().map(|r| r[i]).collect())
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
    fn table_reads_columns_by_name() {
        let t = Table::parse(Path::new("t.csv"), "u,force\n0,1.5\n2, 3e-1\n\n").unwrap();
        assert_eq!(t.len(), 2);
        assert_eq!(t.column("force").unwrap(), vec![1.5, 0.3]);
        assert!(t
            .column("beta")
            .unwrap_err()
            .message
            .contains("no column `beta`"));
        assert_eq!(t.optional_column("u"), Some(vec![0.0, 2.0]));
        assert_eq!(t.optional_column("depth"), None);
    }

    #[test]
    fn table_rejects_ragged_or_bad_rows() {
        let e = Table::parse(Path::new("t.csv"), "u,force\n0\n").unwrap_err();
        assert_eq!(e.message, "line 2: 1 values for 2 columns");
        let e = Table::parse(Path::new("t.csv"), "u,force\n0,x\n").unwrap_err();
        assert!(e.message.starts_with("line 2:"), "{}", e.message);
        assert!(Table::parse(Path::new("t.csv"), "").is_err());
    }
}
