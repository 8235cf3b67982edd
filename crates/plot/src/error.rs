//! The errors of drawing and writing pictures.

use std::fmt;
use std::path::{Path, PathBuf};

/// Why a picture could not be drawn or written.
#[derive(Debug)]
pub struct PlotError {
    /// The file that could not be drawn or written.
    pub path: PathBuf,
    /// What went wrong, on one line.
    pub message: String,
}

impl PlotError {
    pub(crate) fn new(path: &Path, message: impl ToString) -> Self {
        PlotError {
            path: path.to_path_buf(),
            message: message
                .to_string()
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" "),
        }
    }
}

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.message)
    }
}

impl std::error::Error for PlotError {}

/// Errors of drawing, as text (plotters' errors depend on the backend).
pub(crate) type DrawResult = Result<(), String>;

/// Converts any drawing error into the message of a [`DrawResult`].
pub(crate) fn text<E: fmt::Display>(e: E) -> String {
    e.to_string()
}
