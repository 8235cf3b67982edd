//! Errors of reading a case, of writing outputs and of reading a run's
//! files back. Every message is one line.

use soilcut_model::CaseError;
use std::fmt;
use std::path::{Path, PathBuf};

/// Why a case could not be read: always the user's input, never a bug.
#[derive(Debug)]
pub enum InputError {
    /// The case file could not be read at all.
    Read(std::io::Error),
    /// A measured curve's file could not be read at all.
    ReadMeasured(std::io::Error),
    /// The file is not valid TOML.
    Syntax {
        /// Line of the error, from 1.
        line: usize,
        /// The parser's message.
        message: String,
    },
    /// A key is missing, unknown, of the wrong type or out of range.
    Key(CaseError),
    /// A `--set` argument is not `key.path=value`.
    Override {
        /// The argument as given.
        text: String,
        /// What is wrong with it.
        message: String,
    },
}

impl InputError {
    pub(crate) fn key(key: &str, message: impl Into<String>) -> Self {
        InputError::Key(CaseError::new(&visible(key), one_line(&message.into())))
    }
}

impl From<CaseError> for InputError {
    fn from(e: CaseError) -> Self {
        InputError::key(&e.key, e.message)
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::Read(e) => {
                write!(f, "cannot read the case file: {}", one_line(&e.to_string()))
            }
            InputError::ReadMeasured(e) => write!(
                f,
                "cannot read the measured curve: {}",
                one_line(&e.to_string())
            ),
            InputError::Syntax { line, message } => write!(f, "line {line}: {message}"),
            InputError::Key(e) => write!(f, "{e}"),
            InputError::Override { text, message } => {
                write!(f, "--set {}: {message}", visible(text))
            }
        }
    }
}

impl std::error::Error for InputError {}

/// Why the outputs could not be written.
#[derive(Debug)]
pub enum OutputError {
    /// The output folder exists, is not empty, and `force` was not given.
    Exists(PathBuf),
    /// A path without a folder name (`.`, `..`, `/`): no output folder
    /// can be placed there.
    Unnamed(PathBuf),
    /// The folder's name is longer than
    /// [`MAX_NAME_BYTES`](crate::MAX_NAME_BYTES) (its length, bytes).
    NameTooLong(PathBuf, usize),
    /// Another command (its process number, if known) is writing to it.
    Busy(PathBuf, Option<u32>),
    /// No output folder can be made there (nothing was run).
    Unusable {
        /// The output folder.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// Something appeared at the output folder's path while the command
    /// ran: it was left alone and the outputs were placed at `kept`.
    Appeared {
        /// The output folder.
        path: PathBuf,
        /// Where the outputs are.
        kept: PathBuf,
    },
    /// The path exists and is not a folder (a file): never replaced.
    NotAFolder(PathBuf),
    /// `force` was given, but the folder holds no
    /// [`OUTPUT_MARKER`](crate::OUTPUT_MARKER): soilcut did not write it.
    NotOurs(PathBuf),
    /// A file system operation failed.
    Io {
        /// The path the operation was on.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
}

impl OutputError {
    /// A closure turning an I/O error on `path` into an [`OutputError::Io`].
    pub fn io(path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> Self {
        let path = path.into();
        move |source| OutputError::Io { path, source }
    }

    /// The path the error is about.
    pub fn path(&self) -> &std::path::Path {
        match self {
            OutputError::Exists(path)
            | OutputError::Unnamed(path)
            | OutputError::NotAFolder(path)
            | OutputError::NotOurs(path)
            | OutputError::NameTooLong(path, _)
            | OutputError::Busy(path, _)
            | OutputError::Unusable { path, .. }
            | OutputError::Appeared { path, .. }
            | OutputError::Io { path, .. } => path,
        }
    }
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OutputError::Exists(_) => write!(
                f,
                "output folder exists and is not empty; use --force to replace it or choose another --out"
            ),
            OutputError::Unnamed(_) => write!(
                f,
                "a folder given without a name (such as . or ..) cannot hold soilcut's outputs; give a new folder's name, e.g. --out out/NAME"
            ),
            OutputError::NameTooLong(_, n) => write!(
                f,
                "the folder's name is {n} bytes; soilcut's output folders' names are at most {} bytes (255, the file system's limit, less what its hidden working folder beside it adds): choose a shorter --out",
                crate::MAX_NAME_BYTES
            ),
            OutputError::Busy(_, pid) => write!(
                f,
                "another soilcut{} is writing this output folder; wait for it to end or choose another --out",
                pid.map_or(String::new(), |p| format!(" (process {p})"))
            ),
            OutputError::Unusable { source, .. } => write!(
                f,
                "{}: soilcut cannot make its output folder here; choose another --out",
                one_line(&source.to_string())
            ),
            OutputError::Appeared { kept, .. } => write!(
                f,
                "a folder or file appeared here while soilcut ran; it was left alone, and the outputs are in {}",
                kept.display()
            ),
            OutputError::NotAFolder(_) => write!(
                f,
                "exists and is not a folder (a file); soilcut writes its outputs into a folder and never replaces a file: choose another --out"
            ),
            OutputError::NotOurs(_) => write!(
                f,
                "output folder exists and soilcut did not write it (it holds no {} file); --force replaces only soilcut's own output folders: choose another --out",
                crate::OUTPUT_MARKER
            ),
            OutputError::Io { source, .. } => write!(f, "{}", one_line(&source.to_string())),
        }
    }
}

impl std::error::Error for OutputError {}

/// Why the files of a run could not be read.
#[derive(Debug)]
pub struct RunFilesError {
    /// The file that could not be read.
    pub path: PathBuf,
    /// What is wrong with it.
    pub message: String,
}

impl RunFilesError {
    pub(crate) fn new(path: &Path, message: impl ToString) -> Self {
        RunFilesError {
            path: path.to_path_buf(),
            message: one_line(&message.to_string()),
        }
    }
}

impl fmt::Display for RunFilesError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for RunFilesError {}

/// Text the user gave (a `--set` argument, a key), with its control
/// characters escaped (`\n`, `\t`, `\u{1b}`): the message stays one line
/// and shows what was given, where collapsing would hide it. Found by
/// fuzzing (docs/fuzzing.md): an argument with a line break broke the
/// message in two.
pub fn visible(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_debug().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// Collapses line breaks, so that every error prints as one line.
pub(crate) fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The bytes of a file as text. A file that is not UTF-8 (a spreadsheet's
/// Latin-1 export, a binary file given by mistake) is refused at the line
/// of its first invalid byte, rather than as an unreadable file.
pub(crate) fn utf8(bytes: &[u8]) -> Result<&str, InputError> {
    std::str::from_utf8(bytes).map_err(|e| {
        let valid = &bytes[..e.valid_up_to()];
        let line = valid.iter().filter(|&&b| b == b'\n').count() + 1;
        let column = valid.len() - valid.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1) + 1;
        InputError::Syntax {
            line,
            message: format!(
                "byte 0x{:02x} at column {column} is not UTF-8 text: save the file as UTF-8",
                bytes[e.valid_up_to()]
            ),
        }
    })
}
