//! The output folders this process is writing, for a signal handler:
//! [`abandon_outputs`] removes their staging folders and runs the hooks of
//! folders written in place (a sweep's), so that Ctrl-C or SIGTERM leaves
//! no hidden folder and marks what was kept as stopped.

use std::fs;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;

type Hook = Box<dyn Fn(&str) + Send + Sync>;

enum Entry {
    /// A claimed output folder: its staging folder (none once published),
    /// its lock file and the folders made for it (to remove if empty).
    Claim {
        staging: Option<PathBuf>,
        lock: PathBuf,
        made: Vec<PathBuf>,
    },
    /// Called with the reason the process stops.
    Hook(Hook),
}

static LIVE: Mutex<Vec<(u64, Entry)>> = Mutex::new(Vec::new());
static NEXT: AtomicU64 = AtomicU64::new(0);
static ABANDONED: AtomicBool = AtomicBool::new(false);

/// A registration, removed on drop.
#[must_use]
#[derive(Debug)]
pub struct Registered(u64);

impl Drop for Registered {
    fn drop(&mut self) {
        lock().retain(|(id, _)| *id != self.0);
    }
}

fn lock() -> std::sync::MutexGuard<'static, Vec<(u64, Entry)>> {
    // A panic elsewhere must not keep a signal from cleaning up.
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

fn register(entry: Entry) -> Registered {
    let id = NEXT.fetch_add(1, Ordering::Relaxed);
    lock().push((id, entry));
    Registered(id)
}

/// Registers a claimed output folder (see `Entry::Claim`).
pub(crate) fn claim(staging: Option<PathBuf>, lock: PathBuf, made: Vec<PathBuf>) -> Registered {
    register(Entry::Claim {
        staging,
        lock,
        made,
    })
}

/// Registers `hook`, called by [`abandon_outputs`] with the reason the
/// process stops (`"SIGINT"`): a folder written in place marks itself as
/// stopped there.
pub fn on_abandon(hook: impl Fn(&str) + Send + Sync + 'static) -> Registered {
    register(Entry::Hook(Box::new(hook)))
}

/// Whether [`abandon_outputs`] has run: no new staging folder is made.
pub(crate) fn abandoned() -> bool {
    ABANDONED.load(Ordering::SeqCst)
}

/// For a handler of a signal that ends the process (`reason`, e.g.
/// `"SIGTERM"`): runs every hook, then removes every staging folder and lock file
/// of this process and the folders made for them if empty. The process must
/// end right after: what it was writing is gone.
pub fn abandon_outputs(reason: &str) {
    ABANDONED.store(true, Ordering::SeqCst);
    // Held to the end: nothing registers or writes a hook's files after.
    let live = lock();
    for (_, entry) in live.iter() {
        if let Entry::Hook(hook) = entry {
            hook(reason);
        }
    }
    for (_, entry) in live.iter().rev() {
        if let Entry::Claim {
            staging,
            lock,
            made,
        } = entry
        {
            if let Some(path) = staging {
                remove_staging(path);
            }
            let _ = fs::remove_file(lock);
            for dir in made.iter().rev() {
                let _ = fs::remove_dir(dir);
            }
        }
    }
    std::mem::forget(live);
}

/// Removes a staging folder another thread may be writing into: a file
/// made while it is removed leaves it non-empty, so a few tries.
fn remove_staging(path: &std::path::Path) {
    for _ in 0..8 {
        if fs::remove_dir_all(path).is_ok() || !path.exists() {
            return;
        }
    }
}
