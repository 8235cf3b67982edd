//! Records the commit the binary is built from, for `soilcut --version`.
//!
//! `SOILCUT_COMMIT` is the first 12 hex digits of `git rev-parse HEAD` when
//! this crate sits at `crates/cli` of a git work tree (a clone or a
//! worktree), else the environment variable `SOILCUT_COMMIT` if set (for
//! builds from a source archive), else `unknown`. Without git the build
//! still succeeds. The script reruns when HEAD moves: a commit, a checkout
//! or a fetch into the branch.

use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-env-changed=SOILCUT_COMMIT");
    let manifest = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let commit = git_commit(&manifest)
        .or_else(|| std::env::var("SOILCUT_COMMIT").ok())
        .unwrap_or_else(|| "unknown".to_string());
    println!("cargo:rustc-env=SOILCUT_COMMIT={commit}");
}

/// Runs git in `dir`; its trimmed stdout if it succeeded.
fn git(dir: &Path, args: &[&str]) -> Option<String> {
    let output = Command::new("git")
        .args(args)
        .current_dir(dir)
        .output()
        .ok()?;
    let text = String::from_utf8(output.stdout).ok()?;
    (output.status.success() && !text.trim().is_empty()).then(|| text.trim().to_string())
}

/// The commit of the work tree holding this crate, and the files whose
/// change means HEAD moved (printed as rerun-if-changed).
fn git_commit(manifest: &Path) -> Option<String> {
    // Only our own repository: a source archive unpacked inside some other
    // git work tree must not report that tree's commit.
    let top = PathBuf::from(git(manifest, &["rev-parse", "--show-toplevel"])?);
    let ours = top.join("crates/cli").canonicalize().ok()? == manifest.canonicalize().ok()?;
    if !ours {
        return None;
    }
    let commit = git(manifest, &["rev-parse", "--verify", "HEAD"])?;
    watch_head(manifest);
    Some(commit.chars().take(12).collect())
}

/// rerun-if-changed on HEAD, on the branch's ref (loose or packed), so a
/// new commit rebuilds the version string without rebuilding on every run.
fn watch_head(manifest: &Path) {
    let absolute = |p: String| {
        let p = PathBuf::from(p);
        if p.is_absolute() {
            p
        } else {
            manifest.join(p)
        }
    };
    let Some(git_dir) = git(manifest, &["rev-parse", "--git-dir"]).map(absolute) else {
        return;
    };
    let common = git(manifest, &["rev-parse", "--git-common-dir"])
        .map(absolute)
        .unwrap_or_else(|| git_dir.clone());
    let mut watched = vec![git_dir.join("HEAD"), common.join("packed-refs")];
    if let Some(branch) = git(manifest, &["symbolic-ref", "-q", "HEAD"]) {
        let loose = common.join(&branch);
        // A packed ref has no file yet; its folder changes when one appears.
        watched.push(if loose.exists() {
            loose
        } else {
            loose.parent().map(Path::to_path_buf).unwrap_or(common)
        });
    }
    for path in watched.into_iter().filter(|p| p.exists()) {
        println!("cargo:rerun-if-changed={}", path.display());
    }
}
