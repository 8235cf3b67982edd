//! The claim on an output folder's name: a lock file `.NAME.lock` beside
//! it, held (an advisory lock of the operating system, `flock` on Unix)
//! while one command writes to `NAME`. The system drops the lock when the
//! process ends, however it ends, so a lock left by a killed command
//! claims nothing.

use std::fs::{self, File, TryLockError};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// A held lock on the name `.NAME.lock` in its folder; the file is
/// removed, then the lock released, on drop.
#[derive(Debug)]
pub struct Lock {
    path: PathBuf,
    _file: File,
}

/// The lock file's name for the output folder `name`.
pub fn lock_name(name: &str) -> String {
    format!(".{name}.lock")
}

impl Lock {
    /// Takes the lock of `name` in `parent`: `None` if another process
    /// (or another claim of this one) holds it. The file records this
    /// process's number, for the message of the one refused.
    pub fn try_take(parent: &Path, name: &str) -> io::Result<Option<Lock>> {
        let path = parent.join(lock_name(name));
        // Bounded: each retry means another process removed the file
        // between our open and our lock, which it does once, on release.
        for _ in 0..64 {
            let mut file = fs::OpenOptions::new()
                .create(true)
                .truncate(false)
                .write(true)
                .open(&path)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(TryLockError::WouldBlock) => return Ok(None),
                Err(TryLockError::Error(e)) => return Err(e),
            }
            if !same_file(&file, &path) {
                continue;
            }
            file.set_len(0)?;
            writeln!(file, "{}", std::process::id())?;
            return Ok(Some(Lock { path, _file: file }));
        }
        Ok(None)
    }

    /// The lock file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

/// The process number a lock file records, if it can be read.
pub fn holder(parent: &Path, name: &str) -> Option<u32> {
    fs::read_to_string(parent.join(lock_name(name)))
        .ok()?
        .trim()
        .parse()
        .ok()
}

/// Whether `path` still names the open `file`: the holder before us
/// removes the file when it lets go, so a lock on the removed one claims
/// nothing.
fn same_file(file: &File, path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (file.metadata(), fs::metadata(path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = (file, path);
        true
    }
}

impl Drop for Lock {
    fn drop(&mut self) {
        // Removed while still held: whoever opens the name next makes a
        // new file, and one who opened the old checks `same_file`.
        let _ = fs::remove_file(&self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_holder_at_a_time_and_nothing_left_after() {
        let tmp = tempfile::tempdir().unwrap();
        let first = Lock::try_take(tmp.path(), "o").unwrap().expect("free");
        assert!(Lock::try_take(tmp.path(), "o").unwrap().is_none());
        assert_eq!(holder(tmp.path(), "o"), Some(std::process::id()));
        assert!(Lock::try_take(tmp.path(), "p").unwrap().is_some());
        drop(first);
        assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 0);
        assert!(Lock::try_take(tmp.path(), "o").unwrap().is_some());
    }
}
