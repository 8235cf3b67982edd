//! `history.csv`'s columns, named once in the model's
//! `StepRecord::COLUMNS`: the file is written from this list, and the C
//! ABI's record and Python's `Step` take their fields from it.

use crate::columns::Columns;
use soilcut_model::StepRecord;

/// A column of `history.csv`: its name and a record's value in it.
pub type HistoryColumn = soilcut_model::step::Column;

/// The columns of `history.csv`, in order (the model's
/// `StepRecord::COLUMNS`, which its finiteness check reads too).
pub const HISTORY: [HistoryColumn; 24] = StepRecord::COLUMNS;

/// Columns of `history.csv`, in order: the names of [`HISTORY`] joined by
/// commas (at compile time).
pub const HISTORY_HEADER: &str = match std::str::from_utf8(&HEADER_BYTES) {
    Ok(header) => header,
    Err(_) => panic!("the column names are UTF-8"),
};

const HEADER_BYTES: [u8; header_len()] = header_bytes();

const fn header_len() -> usize {
    let mut len = HISTORY.len() - 1;
    let mut i = 0;
    while i < HISTORY.len() {
        len += HISTORY[i].0.len();
        i += 1;
    }
    len
}

const fn header_bytes() -> [u8; header_len()] {
    let mut out = [b','; header_len()];
    let (mut at, mut i) = (0, 0);
    while i < HISTORY.len() {
        let name = HISTORY[i].0.as_bytes();
        let mut j = 0;
        while j < name.len() {
            out[at] = name[j];
            at += 1;
            j += 1;
        }
        at += 1;
        i += 1;
    }
    out
}

/// The value of the column `name` of [`HISTORY`] for `record`, if there
/// is such a column.
pub fn history_value(record: &StepRecord, name: &str) -> Option<f64> {
    let (_, value) = HISTORY.iter().find(|(n, _)| *n == name)?;
    Some(value(record))
}

/// The numbers of `history.csv` (columns [`HISTORY_HEADER`]): one row
/// per increment.
pub fn history_columns(history: &[StepRecord]) -> Columns {
    let mut out = Columns::new(HISTORY_HEADER);
    let mut row = [0.0; HISTORY.len()];
    for r in history {
        for (slot, (_, value)) in row.iter_mut().zip(&HISTORY) {
            *slot = value(r);
        }
        out.push(&row);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_is_the_names_in_order() {
        let names: Vec<&str> = HISTORY.iter().map(|(n, _)| *n).collect();
        assert_eq!(HISTORY_HEADER, names.join(","));
        assert!(HISTORY_HEADER.starts_with("step,u,u_over_d,force,"));
    }
}
