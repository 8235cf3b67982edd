//! Renames that never replace what they must not: a folder is placed at a
//! path only if nothing is there, and `--force`'s swap exchanges two
//! folders in one step, so that no moment leaves the path empty.

use std::io;
use std::path::Path;

/// Renames `from` to `to` only if nothing is at `to` (`AlreadyExists`
/// otherwise). One atomic step on Linux (renameat2 RENAME_NOREPLACE);
/// elsewhere, or on a file system without it, a look then a rename.
pub fn rename_new(from: &Path, to: &Path) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    match renameat2(from, to, libc::RENAME_NOREPLACE) {
        Err(e) if unsupported(&e) => {}
        done => return done,
    }
    if to.symlink_metadata().is_ok() {
        return Err(io::ErrorKind::AlreadyExists.into());
    }
    std::fs::rename(from, to)
}

/// Exchanges the folders `a` and `b` in one step (Linux, renameat2
/// RENAME_EXCHANGE); `Unsupported` where the system or the file system
/// cannot.
pub fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    match renameat2(a, b, libc::RENAME_EXCHANGE) {
        Err(e) if unsupported(&e) => {}
        done => return done,
    }
    let _ = (a, b);
    Err(io::ErrorKind::Unsupported.into())
}

/// EINVAL: the file system has no such rename; ENOSYS: the kernel has not.
#[cfg(target_os = "linux")]
fn unsupported(e: &io::Error) -> bool {
    matches!(e.raw_os_error(), Some(libc::EINVAL | libc::ENOSYS))
}

#[cfg(target_os = "linux")]
fn renameat2(from: &Path, to: &Path, flags: libc::c_uint) -> io::Result<()> {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    let c = |p: &Path| CString::new(p.as_os_str().as_bytes()).map_err(io::Error::other);
    let (from, to) = (c(from)?, c(to)?);
    // SAFETY: both are NUL-terminated paths that live across the call; the
    // call reads them only.
    let r = unsafe {
        libc::renameat2(
            libc::AT_FDCWD,
            from.as_ptr(),
            libc::AT_FDCWD,
            to.as_ptr(),
            flags,
        )
    };
    if r == 0 {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    #[test]
    fn a_new_name_is_never_taken_from_what_is_there() {
        let tmp = tempfile::tempdir().unwrap();
        let (a, b) = (tmp.path().join("a"), tmp.path().join("b"));
        fs::create_dir(&a).unwrap();
        fs::create_dir(&b).unwrap();
        let e = rename_new(&a, &b).unwrap_err();
        assert_eq!(
            e.kind(),
            io::ErrorKind::AlreadyExists,
            "even an empty folder"
        );
        assert!(a.is_dir() && b.is_dir());
        fs::remove_dir(&b).unwrap();
        rename_new(&a, &b).unwrap();
        assert!(!a.exists() && b.is_dir());
    }

    #[test]
    fn an_exchange_swaps_both_or_says_it_cannot() {
        let tmp = tempfile::tempdir().unwrap();
        let (a, b) = (tmp.path().join("a"), tmp.path().join("b"));
        fs::create_dir(&a).unwrap();
        fs::create_dir(&b).unwrap();
        fs::write(a.join("in-a"), "").unwrap();
        match exchange(&a, &b) {
            Ok(()) => assert!(b.join("in-a").is_file() && !a.join("in-a").exists()),
            Err(e) => assert_eq!(e.kind(), io::ErrorKind::Unsupported),
        }
    }
}
