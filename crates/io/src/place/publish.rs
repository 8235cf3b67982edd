//! Publishing a claimed output folder: the staging folder renamed to the
//! destination without replacing anything soilcut must not.

use super::debris::hidden_name;
use super::rename::{exchange, rename_new};
use super::{live, OutputDir, Published, OUTPUT_MARKER};
use crate::error::OutputError;
use std::fs;
use std::io;
use std::path::Path;

impl OutputDir {
    /// Writes `files` into the staging folder, calls `finish` with it
    /// (pictures drawn from the files), then publishes it.
    pub fn write_then(
        self,
        files: &[(&str, String)],
        finish: impl FnOnce(&Path) -> Result<(), OutputError>,
    ) -> Result<Published, OutputError> {
        for (name, contents) in files {
            let path = self.staging.join(name);
            fs::write(&path, contents).map_err(OutputError::io(&path))?;
        }
        finish(&self.staging)?;
        self.publish()
    }

    /// Renames the staging folder to the destination: if nothing is there;
    /// over the empty folder that was there at the claim; with `force`,
    /// swapped with soilcut's folder there. Anything else at the
    /// destination (a folder that appeared while the command ran) is left
    /// alone and the outputs are kept beside it
    /// ([`OutputError::Appeared`]).
    pub fn publish(self) -> Result<Published, OutputError> {
        let placed = match self.dir.symlink_metadata() {
            Err(_) => taken(rename_new(&self.staging, &self.dir)),
            Ok(m) if m.is_dir() && self.was_empty => taken(fs::rename(&self.staging, &self.dir)),
            Ok(m) if m.is_dir() && self.force && self.dir.join(OUTPUT_MARKER).is_file() => {
                self.swap()
            }
            Ok(_) => Ok(false),
        };
        match placed.map_err(OutputError::io(&self.dir))? {
            true => Ok(self.published()),
            false => Err(self.keep_beside()),
        }
    }

    /// Replaces soilcut's folder at the destination: one exchange, then
    /// the old folder (now at the staging path) removed; where the system
    /// cannot exchange, the old folder is moved aside (`.NAME.old-PID-N`,
    /// restored by the next command if a kill comes between the renames).
    fn swap(&self) -> io::Result<bool> {
        match exchange(&self.staging, &self.dir) {
            Ok(()) if self.staging.join(OUTPUT_MARKER).is_file() => {
                let _ = fs::remove_dir_all(&self.staging);
                return Ok(true);
            }
            // What was swapped out is not soilcut's (it was replaced
            // after the look): it goes back.
            Ok(()) => return exchange(&self.staging, &self.dir).map(|()| false),
            Err(e) if e.kind() != io::ErrorKind::Unsupported => return Err(e),
            Err(_) => {}
        }
        let aside = self.parent.join(hidden_name(&self.name, "old", 0));
        rename_new(&self.dir, &aside)?;
        if let Err(e) = rename_new(&self.staging, &self.dir) {
            let _ = rename_new(&aside, &self.dir);
            return taken(Err(e));
        }
        let _ = fs::remove_dir_all(&aside);
        Ok(true)
    }

    fn published(mut self) -> Published {
        let lock = self.lock.take().expect("held until published");
        let live = live::claim(None, lock.path().into(), Vec::new());
        self.made.clear();
        Published {
            dir: std::mem::take(&mut self.dir),
            _lock: lock,
            _live: live,
        }
    }

    /// The outputs renamed to `NAME-soilcut-PID` (the first free of
    /// `-N` suffixes) beside a destination taken meanwhile.
    fn keep_beside(self) -> OutputError {
        let base = format!("{}-soilcut-{}", self.name, std::process::id());
        for n in 0..100 {
            let kept = match n {
                0 => self.parent.join(&base),
                n => self.parent.join(format!("{base}-{n}")),
            };
            match rename_new(&self.staging, &kept) {
                Ok(()) => {
                    return OutputError::Appeared {
                        path: self.dir.clone(),
                        kept,
                    }
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
                Err(e) => return OutputError::io(&self.dir)(e),
            }
        }
        OutputError::io(&self.dir)(io::ErrorKind::AlreadyExists.into())
    }
}

/// A rename's outcome: done, or the destination taken (a folder with
/// something in it, or anything where nothing was).
fn taken(r: io::Result<()>) -> io::Result<bool> {
    match r {
        Ok(()) => Ok(true),
        Err(e) if occupied_error(&e) => Ok(false),
        Err(e) => Err(e),
    }
}

/// EEXIST, ENOTEMPTY, ENOTDIR, EISDIR: something is at the destination.
fn occupied_error(e: &io::Error) -> bool {
    use io::ErrorKind::*;
    matches!(
        e.kind(),
        AlreadyExists | DirectoryNotEmpty | NotADirectory | IsADirectory
    )
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if self.lock.is_none() {
            return;
        }
        // Not published: the staging folder (or, after a failed swap,
        // nothing of the user's: `keep_beside` moved ours away) goes.
        if self.staging.join(OUTPUT_MARKER).is_file() {
            let _ = fs::remove_dir_all(&self.staging);
        }
        drop(self.lock.take());
        for dir in self.made.iter().rev() {
            let _ = fs::remove_dir(dir);
        }
    }
}
