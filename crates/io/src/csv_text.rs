//! soilcut's own CSV files, written with the `csv` crate (the crate that
//! reads measured curves): a header, then rows of fields formatted by
//! Rust's `{}` (numbers in their shortest round-trip form), `\n` line
//! ends, a field quoted only if it holds a comma, a quote or a line break.

use std::fmt::Display;

/// A CSV text being written.
pub struct CsvText {
    writer: csv::Writer<Vec<u8>>,
}

impl CsvText {
    /// A text starting with `header`, the column names joined by commas.
    pub fn new(header: &str) -> Self {
        let mut text = CsvText::new_empty();
        text.record(header.split(','));
        text
    }

    fn new_empty() -> Self {
        CsvText {
            writer: csv::WriterBuilder::new()
                .terminator(csv::Terminator::Any(b'\n'))
                .from_writer(Vec::new()),
        }
    }

    /// A text starting with a header of `names`.
    pub fn named<S: AsRef<str>>(names: &[S]) -> Self {
        let mut text = CsvText::new_empty();
        text.fields(names);
        text
    }

    /// Appends one row of fields already formatted.
    pub fn fields<S: AsRef<str>>(&mut self, fields: &[S]) {
        self.record(fields.iter().map(|f| f.as_ref()));
    }

    /// Appends one row.
    pub fn row(&mut self, fields: &[&dyn Display]) {
        self.record(fields.iter().map(|f| f.to_string()));
    }

    fn record<I: IntoIterator<Item = S>, S: AsRef<[u8]>>(&mut self, fields: I) {
        // Writing to memory cannot fail.
        self.writer
            .write_record(fields)
            .expect("a record written to memory");
    }

    /// The text.
    pub fn finish(self) -> String {
        let bytes = self
            .writer
            .into_inner()
            .expect("a writer flushed to memory");
        // Every field came from a Rust string.
        String::from_utf8(bytes).expect("UTF-8 fields")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_as_rust_formats_them() {
        let mut t = CsvText::new("a,b,c");
        t.row(&[&1, &0.1, &"x, y"]);
        t.row(&[&f64::NAN, &1e21, &-0.0]);
        assert_eq!(
            t.finish(),
            "a,b,c\n1,0.1,\"x, y\"\nNaN,1000000000000000000000,-0\n"
        );
    }

    #[test]
    fn fields_are_quoted_only_when_needed() {
        let mut t = CsvText::named(&["plain", "a, b"]);
        t.fields(&["1.5", "say \"x\""]);
        t.fields(&["", ""]);
        assert_eq!(t.finish(), "plain,\"a, b\"\n1.5,\"say \"\"x\"\"\"\n,\n");
    }
}
