//! Placing a command's output folder so that no race deletes or replaces
//! what the command did not write:
//!
//! * claimed when the command starts ([`OutputDir::claim`]): the lock of
//!   its name (`.NAME.lock`, held to the end; a second command is refused),
//!   its destination checked (free, or with `force` soilcut's own), and a
//!   hidden staging folder `.NAME.tmp-PID-N` made beside it;
//! * published by a rename that takes the name only if it is free, or
//!   replaces an empty folder that was there at the claim, or (with
//!   `force`) swaps in one step with a folder that holds soilcut's marker:
//!   a folder that appeared at the name meanwhile is left alone, and the
//!   outputs are kept beside it under a name the error gives;
//! * cleaned when a command ends before publishing (its staging folder
//!   removed), on Ctrl-C or SIGTERM ([`abandon_outputs`], from the command
//!   line's handler) and, after a kill, by the next command into the same
//!   folder (`debris`).

mod claim;
mod debris;
mod live;
mod lock;
mod publish;
mod rename;

pub use live::{abandon_outputs, on_abandon, Registered};

use crate::error::OutputError;
use lock::Lock;
use std::fs;
use std::io;
use std::path::{Component, Path, PathBuf};

/// The file by which soilcut knows an output folder as its own: every
/// folder it writes holds it, and `force` replaces no folder without it,
/// so that a mistyped `--out` never deletes the user's files.
pub const OUTPUT_MARKER: &str = ".soilcut";

/// The longest output folder name, bytes: 255 (the usual file system's
/// limit) less the 18 that the hidden folder beside it adds (`.`,
/// `.old-`, a process number of up to 7 digits, `-`, up to 4 digits).
pub const MAX_NAME_BYTES: usize = 237;

/// What [`OUTPUT_MARKER`] says to a person who finds it.
fn marker_text() -> String {
    format!(
        "Written by soilcut {}. soilcut's --force (force=True in Python) replaces only folders holding this file.\n",
        env!("CARGO_PKG_VERSION")
    )
}

/// Whether `dir` is free for outputs: absent or an empty folder, or, with
/// `force`, a folder soilcut wrote (holding [`OUTPUT_MARKER`]). Reads only.
pub fn check_output_dir(dir: &Path, force: bool) -> Result<(), OutputError> {
    let err = |make: fn(PathBuf) -> OutputError| Err(make(dir.to_path_buf()));
    if dir.symlink_metadata().is_ok() && !dir.is_dir() {
        err(OutputError::NotAFolder)
    } else if !occupied(dir)? {
        Ok(())
    } else if !force {
        err(OutputError::Exists)
    } else if name_of(dir).is_none() {
        err(OutputError::Unnamed)
    } else if !dir.join(OUTPUT_MARKER).is_file() {
        err(OutputError::NotOurs)
    } else {
        Ok(())
    }
}

fn occupied(dir: &Path) -> Result<bool, OutputError> {
    match fs::read_dir(dir) {
        Ok(mut entries) => Ok(entries.next().is_some()),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(false),
        Err(_) => Ok(dir.symlink_metadata().is_ok()),
    }
}

/// The folder's name: its last component, if that is a name (not `.`,
/// `..` or `/`; `X/.` is `X`).
fn name_of(dir: &Path) -> Option<String> {
    match dir.components().next_back()? {
        Component::Normal(name) => Some(name.to_string_lossy().into_owned()),
        _ => None,
    }
}

/// Writes `files` into `dir` atomically: claimed, staged and published
/// ([`OutputDir`]); an occupied `dir` is refused unless `force`, which
/// replaces it if soilcut wrote it.
pub fn write_output_dir(
    dir: &Path,
    files: &[(&str, String)],
    force: bool,
) -> Result<(), OutputError> {
    write_output_dir_then(dir, files, force, |_| Ok(()))
}

/// [`write_output_dir`], calling `finish` with the staging folder once
/// `files` are in it and before it is published, so that files made from
/// them (pictures) appear together with them or not at all.
pub fn write_output_dir_then(
    dir: &Path,
    files: &[(&str, String)],
    force: bool,
    finish: impl FnOnce(&Path) -> Result<(), OutputError>,
) -> Result<(), OutputError> {
    OutputDir::claim(dir, force)?
        .write_then(files, finish)
        .map(drop)
}

/// An output folder claimed by this process: its name locked, its staging
/// folder made. Dropped unpublished, it removes what it made.
#[derive(Debug)]
pub struct OutputDir {
    dir: PathBuf,
    parent: PathBuf,
    name: String,
    force: bool,
    /// `dir` was an empty folder at the claim: the rename may replace it.
    was_empty: bool,
    staging: PathBuf,
    lock: Option<Lock>,
    made: Vec<PathBuf>,
    _live: Registered,
}

/// A published output folder, its name still locked until dropped: a
/// folder written in place (a sweep's) stays claimed while it is written.
#[derive(Debug)]
pub struct Published {
    dir: PathBuf,
    _lock: Lock,
    _live: Registered,
}

impl Published {
    /// The folder.
    pub fn path(&self) -> &Path {
        &self.dir
    }
}

#[cfg(test)]
mod tests;
