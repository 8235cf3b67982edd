//! Why bytes are not a snapshot this build can restore.

use super::{CRATE_VERSION, FORMAT_VERSION};
use crate::case::CaseError;
use std::fmt;

/// Why bytes are not a snapshot this build can restore.
#[derive(Clone, Debug, PartialEq)]
pub enum SnapshotError {
    /// The bytes do not start with `MAGIC`.
    NotASnapshot,
    /// A snapshot of another format or crate version.
    Version {
        /// Its format version.
        format: u32,
        /// Its crate version (empty if the format is unknown).
        crate_version: String,
    },
    /// The bytes end inside `what`.
    Truncated {
        /// What was being read.
        what: &'static str,
    },
    /// Bytes after the checksum.
    TrailingBytes {
        /// How many.
        count: usize,
    },
    /// The checksum does not match: the bytes were changed.
    Corrupt,
    /// A value out of its range (`what`: which, `message`: why).
    Invalid {
        /// The value.
        what: &'static str,
        /// What is wrong with it.
        message: String,
    },
    /// The case does not validate (`Case::validate`).
    Case(CaseError),
}

impl SnapshotError {
    pub(crate) fn invalid(what: &'static str, message: String) -> Self {
        SnapshotError::Invalid { what, message }
    }
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::NotASnapshot => {
                write!(f, "not a soilcut snapshot (it does not start with the magic bytes)")
            }
            SnapshotError::Version {
                format,
                crate_version,
            } => write!(
                f,
                "a snapshot of another version (format {format}, soilcut {}): this is format {FORMAT_VERSION} of soilcut {CRATE_VERSION}, which restores only its own snapshots",
                if crate_version.is_empty() { "unknown" } else { crate_version }
            ),
            SnapshotError::Truncated { what } => {
                write!(f, "snapshot truncated: it ends inside {what}")
            }
            SnapshotError::TrailingBytes { count } => {
                write!(f, "snapshot has {count} bytes after its end")
            }
            SnapshotError::Corrupt => {
                write!(f, "snapshot corrupt: its checksum does not match its bytes")
            }
            SnapshotError::Invalid { what, message } => {
                write!(f, "snapshot invalid: {what}: {message}")
            }
            SnapshotError::Case(e) => write!(f, "snapshot's case invalid: {e}"),
        }
    }
}

impl std::error::Error for SnapshotError {}
