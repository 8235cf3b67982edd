//! Why a case cannot be run.

use std::fmt;

/// Why a case cannot be run: the offending key (dotted path as in the case
/// file) and what it must satisfy.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseError {
    /// The case-file key, dotted (`soil.friction.peak`).
    pub key: String,
    /// What the value must satisfy, and the value given.
    pub message: String,
}

impl CaseError {
    /// The error for `key` with `message`.
    pub fn new(key: &str, message: impl Into<String>) -> Self {
        CaseError {
            key: key.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for CaseError {}
