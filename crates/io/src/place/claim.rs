//! [`OutputDir::claim`]: the checks and the making of a claim, before the
//! command runs.

use super::debris::{clean, hidden_name};
use super::lock::{holder, Lock};
use super::{live, marker_text, name_of, OutputDir, MAX_NAME_BYTES, OUTPUT_MARKER};
use crate::error::OutputError;
use std::fs;
use std::path::{Path, PathBuf};

impl OutputDir {
    /// Claims `dir` for this process's outputs: refused (before anything
    /// runs) if it has no name or too long a name, if a file stands where
    /// a folder must, if another command holds it, if it is occupied
    /// (without `force`, or with it by a folder soilcut did not write) or
    /// if no folder can be made there. Cleans what interrupted commands
    /// left beside it.
    pub fn claim(dir: &Path, force: bool) -> Result<OutputDir, OutputError> {
        let dir: PathBuf = dir.components().collect();
        let name = name_of(&dir).ok_or_else(|| OutputError::Unnamed(dir.clone()))?;
        if name.len() > MAX_NAME_BYTES {
            return Err(OutputError::NameTooLong(dir, name.len()));
        }
        if live::abandoned() {
            return Err(unusable(&dir)(std::io::ErrorKind::Interrupted.into()));
        }
        let parent = match dir.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let mut made = Made(make_folders(&parent, &dir)?);
        let lock = Lock::try_take(&parent, &name)
            .map_err(unusable(&dir))?
            .ok_or_else(|| OutputError::Busy(dir.clone(), holder(&parent, &name)))?;
        if !within_ours(&parent) {
            clean(&parent, &name);
        }
        super::check_output_dir(&dir, force)?;
        let was_empty = fs::read_dir(&dir).is_ok_and(|mut e| e.next().is_none());
        let staging = make_staging(&parent, &name).map_err(unusable(&dir))?;
        let made = std::mem::take(&mut made.0);
        let registered = live::claim(Some(staging.clone()), lock.path().into(), made.clone());
        Ok(OutputDir {
            dir,
            parent,
            name,
            force,
            was_empty,
            staging,
            lock: Some(lock),
            made,
            _live: registered,
        })
    }

    /// The staging folder, where the outputs are written before they are
    /// published.
    pub fn staging(&self) -> &Path {
        &self.staging
    }
}

/// An [`OutputError::Unusable`] of `dir`.
fn unusable(dir: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
    move |source| OutputError::Unusable {
        path: dir.to_path_buf(),
        source,
    }
}

/// Folders made for a claim, removed (if still empty) unless taken.
struct Made(Vec<PathBuf>);

impl Drop for Made {
    fn drop(&mut self) {
        for dir in self.0.iter().rev() {
            let _ = fs::remove_dir(dir);
        }
    }
}

/// Makes `parent` and the folders above it that are missing; the folders
/// made, outermost first. A file where a folder must be is named as such.
fn make_folders(parent: &Path, dir: &Path) -> Result<Vec<PathBuf>, OutputError> {
    let mut missing = Vec::new();
    let mut at = Some(parent);
    while let Some(p) = at.filter(|p| !p.as_os_str().is_empty()) {
        match p.symlink_metadata() {
            Ok(_) if p.is_dir() => break,
            Ok(_) => return Err(OutputError::NotAFolder(p.to_path_buf())),
            Err(_) => missing.push(p.to_path_buf()),
        }
        at = p.parent();
    }
    missing.reverse();
    let mut made = Made(Vec::new());
    for p in missing {
        match fs::create_dir(&p) {
            Ok(()) => made.0.push(p),
            // Another command (or a sweep's other run) made it meanwhile:
            // not ours to remove.
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && p.is_dir() => {}
            Err(e) => return Err(unusable(dir)(e)),
        }
    }
    Ok(std::mem::take(&mut made.0))
}

/// Whether `parent` is, or is in, a folder soilcut writes (a staging
/// folder, or a sweep's `runs/`): soilcut's own, no debris to look for.
fn within_ours(parent: &Path) -> bool {
    [Some(parent), parent.parent()]
        .into_iter()
        .flatten()
        .any(|p| p.join(OUTPUT_MARKER).is_file())
}

/// Makes `.NAME.tmp-PID-N` in `parent` with its marker, the first N free.
fn make_staging(parent: &Path, name: &str) -> std::io::Result<PathBuf> {
    for attempt in 0..1000 {
        let path = parent.join(hidden_name(name, "tmp", attempt));
        match fs::create_dir(&path) {
            Ok(()) => {
                let marked = fs::write(path.join(OUTPUT_MARKER), marker_text());
                return match marked {
                    Ok(()) => Ok(path),
                    Err(e) => {
                        let _ = fs::remove_dir(&path);
                        Err(e)
                    }
                };
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
            Err(e) => return Err(e),
        }
    }
    Err(std::io::ErrorKind::AlreadyExists.into())
}
