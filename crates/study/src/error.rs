//! Errors of a study. Every message is one line.

use soilcut_io::{InputError, OutputError};
use std::fmt;

/// Why a study could not be carried out. A run that fails inside a sweep
/// is not an error of the sweep: it is a row with its message.
#[derive(Debug)]
pub enum StudyError {
    /// A bad study argument (`--vary`, `--free`, `--bounds`, `--sample`,
    /// measured data), named in the message.
    Spec(String),
    /// A key of a study argument that the case file cannot hold (an
    /// unknown `--vary` key), named with the nearest it can.
    Key(InputError),
    /// The base case cannot be read, or cannot be run where the study
    /// needs it (the start of a fit, a level of a convergence study).
    Case(String),
    /// The outputs cannot be written.
    Output(OutputError),
    /// A picture cannot be drawn or written.
    Plot(String),
}

impl From<InputError> for StudyError {
    fn from(e: InputError) -> Self {
        StudyError::Case(e.to_string())
    }
}

impl From<soilcut_plot::PlotError> for StudyError {
    fn from(e: soilcut_plot::PlotError) -> Self {
        StudyError::Plot(e.to_string())
    }
}

impl From<OutputError> for StudyError {
    fn from(e: OutputError) -> Self {
        StudyError::Output(e)
    }
}

impl fmt::Display for StudyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StudyError::Spec(m) | StudyError::Case(m) | StudyError::Plot(m) => f.write_str(m),
            StudyError::Key(e) => write!(f, "{e}"),
            StudyError::Output(e) => write!(f, "{}: {e}", e.path().display()),
        }
    }
}

impl std::error::Error for StudyError {}
