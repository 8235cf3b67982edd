//! What an interrupted command leaves beside its output folder, and its
//! cleaning by the next command into the same folder. A command writes
//! into `.NAME.tmp-PID-N` (its staging folder) and, where the system
//! cannot swap two folders in one step, moves a replaced folder aside to
//! `.NAME.old-PID-N` for a moment. Either is soilcut's own by its name and
//! its marker file; it is left over when the lock of `NAME` is free (no
//! command writes to `NAME`) and the process PID is not running.

use super::lock::Lock;
use super::rename::rename_new;
use super::OUTPUT_MARKER;
use std::fs;
use std::path::Path;

/// A hidden folder of a command: `.NAME.TAG-PID-N`.
#[derive(Debug, PartialEq)]
pub struct Hidden<'a> {
    /// The output folder's name.
    pub name: &'a str,
    /// `tmp` (staging) or `old` (replaced, moved aside).
    pub tag: &'a str,
    /// The process that made it.
    pub pid: u32,
}

/// The name of a hidden folder of this process for `name`.
pub fn hidden_name(name: &str, tag: &str, attempt: u32) -> String {
    format!(".{name}.{tag}-{}-{attempt}", std::process::id())
}

/// `file` as a hidden folder's name, if it is one.
pub fn parse(file: &str) -> Option<Hidden<'_>> {
    let rest = file.strip_prefix('.')?;
    let (name, tail) = rest.rsplit_once('.')?;
    let (tag, numbers) = tail.split_once('-')?;
    let (pid, attempt) = numbers.split_once('-')?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let known = matches!(tag, "tmp" | "old");
    if !(known && !name.is_empty() && digits(pid) && digits(attempt)) {
        return None;
    }
    Some(Hidden {
        name,
        tag,
        pid: pid.parse().ok()?,
    })
}

/// Whether process `pid` may be running. Where this cannot be known (no
/// `/proc`), every process is taken to run: nothing is cleaned.
fn may_run(pid: u32) -> bool {
    let proc = Path::new("/proc");
    !proc.join("self").exists() || proc.join(pid.to_string()).exists()
}

/// Cleans what interrupted commands left in `parent`: each left-over
/// staging folder is removed; a folder moved aside is put back if its
/// name is free, else removed (the new one had taken its place). `held`
/// is the name whose lock the caller holds. Best effort: what cannot be
/// cleaned stays, for a later command.
pub fn clean(parent: &Path, held: &str) {
    let Ok(entries) = fs::read_dir(parent) else {
        return;
    };
    let mut found: Vec<String> = entries
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|f| parse(f).is_some_and(|h| h.pid != std::process::id() && !may_run(h.pid)))
        .collect();
    // Moved-aside folders first: one may be restored before its staging
    // folder is looked at.
    found.sort_by_key(|f| parse(f).map(|h| h.tag != "old"));
    for file in &found {
        let Some(h) = parse(file) else { continue };
        // A name another command holds is its to clean.
        let lock = if h.name == held {
            None
        } else {
            match Lock::try_take(parent, h.name) {
                Ok(Some(lock)) => Some(lock),
                _ => continue,
            }
        };
        clean_one(parent, file, &h);
        drop(lock);
    }
}

fn clean_one(parent: &Path, file: &str, h: &Hidden<'_>) {
    let path = parent.join(file);
    if !path.is_dir() || path.symlink_metadata().is_ok_and(|m| m.is_symlink()) {
        return;
    }
    if !path.join(OUTPUT_MARKER).is_file() {
        // Made but not yet marked: removed only if empty.
        let _ = fs::remove_dir(&path);
        return;
    }
    if h.tag == "old" && rename_new(&path, &parent.join(h.name)).is_ok() {
        return;
    }
    let _ = fs::remove_dir_all(&path);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_soilcuts_names_are_hidden_folders() {
        assert_eq!(
            parse(".out.v2.tmp-123-0"),
            Some(Hidden {
                name: "out.v2",
                tag: "tmp",
                pid: 123
            })
        );
        for other in [
            ".out.tmp-1",
            ".out.tmp-x-0",
            "out.tmp-1-0",
            ".out.new-1-0",
            "..tmp-1-0",
        ] {
            assert_eq!(parse(other), None, "{other}");
        }
    }

    #[test]
    fn left_overs_are_cleaned_and_others_kept() {
        let tmp = tempfile::tempdir().unwrap();
        let dead = 4_194_999; // above Linux's largest process number
        let make = |name: &str, marked: bool| {
            let dir = tmp.path().join(name);
            fs::create_dir(&dir).unwrap();
            if marked {
                fs::write(dir.join(OUTPUT_MARKER), "").unwrap();
            }
        };
        make(&format!(".a.tmp-{dead}-0"), true);
        make(&format!(".b.old-{dead}-0"), true);
        make(&format!(".c.tmp-{dead}-0"), false);
        make(&format!(".d.tmp-{dead}-0"), false);
        fs::write(tmp.path().join(format!(".d.tmp-{dead}-0/mine")), "").unwrap();
        make(&format!(".e.tmp-{}-0", std::process::id()), true);
        let held = Lock::try_take(tmp.path(), "f").unwrap().unwrap();
        make(&format!(".f.tmp-{dead}-0"), true);
        clean(tmp.path(), "g");
        let mut left: Vec<String> = fs::read_dir(tmp.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        left.sort();
        let pid = std::process::id();
        let expected = [
            format!(".d.tmp-{dead}-0"),
            format!(".e.tmp-{pid}-0"),
            ".f.lock".to_string(),
            format!(".f.tmp-{dead}-0"),
            "b".to_string(),
        ];
        assert_eq!(left, expected, "unmarked but not empty, alive, held: kept");
        drop(held);
    }
}
