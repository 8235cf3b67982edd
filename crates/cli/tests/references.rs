//! Every file a document or comment names exists in the repository, and
//! nothing points outside it.
//!
//! Scanned: every `*.md`, `*.toml`, `*.rs`, `*.py`, `*.sh` file and the
//! files of `.ci/`, from the repository root down, skipping `target/`,
//! `out/` (generated), `.git/` and other hidden folders. In each, a name
//! is checked when it is
//!
//! 1. a path whose first component is a top-level entry of the repository
//!    (`crates/…`, `cases/…`, `docs/…`, `.ci/…`): it must exist, relative
//!    to the root;
//! 2. a path starting with `../`: resolved from the document's folder (and,
//!    in Rust code, also from its crate's folder, as `CARGO_MANIFEST_DIR`
//!    paths are), it must stay inside the repository and exist;
//! 3. the target of a Markdown link `[text](target)` that is not a URL or
//!    an anchor: resolved from the document's folder, the same;
//! 4. an all-capitals Markdown name without a folder (as `README.md`): it
//!    must exist at the root or in the document's folder;
//! 5. an absolute path ending in `.md`, `.toml`, `.rs`, `.py`, `.sh` or
//!    `.cff`: always an error, it names a document outside the repository.
//!
//! A name ends at the first character that cannot be part of a path; where
//! it runs into a wildcard (`*`, `{`, `<`, `$`: `docs/img/model_*.png`,
//! `cases/paper/{}.toml`, `out/<name>/`) only the part before it is checked,
//! as a prefix of an existing entry. Names starting with `out/` or `target/`
//! are outputs that runs and builds create, so they are not checked (they
//! are not top-level entries of the repository). A trailing `.` or `/`
//! (end of a sentence, a folder) is dropped. `ALLOWED` lists the names
//! that deliberately do not exist (bad inputs in tests).

use std::fs;
use std::path::{Component, Path, PathBuf};

/// A case name that would escape the output folder, refused by the CLI.
const ESCAPE: &str = concat!("..", "/escape");

/// (file, name): names that are meant not to exist.
const ALLOWED: &[(&str, &str)] = &[("crates/cli/tests/cli.rs", ESCAPE)];

/// Extensions of the documents scanned.
const SCANNED: &[&str] = &["md", "toml", "rs", "py", "sh"];

/// Extensions that make an absolute path a document name (rule 5).
const DOCUMENTS: &[&str] = &["md", "toml", "rs", "py", "sh", "cff"];

/// Folders never scanned and never counted as repository entries.
const SKIPPED: &[&str] = &["target", "out", "node_modules", "__pycache__"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

fn skipped(name: &str) -> bool {
    SKIPPED.contains(&name) || (name.starts_with('.') && name != ".ci")
}

fn documents(dir: &Path, found: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            if !skipped(&name) {
                documents(&path, found);
            }
        } else {
            let ext = path.extension().map(|e| e.to_string_lossy().into_owned());
            let in_ci = path.parent().and_then(|p| p.file_name()) == Some(".ci".as_ref());
            if in_ci || ext.is_some_and(|e| SCANNED.contains(&e.as_str())) {
                found.push(path);
            }
        }
    }
}

fn path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '-' | '/')
}

fn wildcard(c: char) -> bool {
    matches!(c, '*' | '{' | '<' | '$')
}

/// A name found in a document: the text, and whether a wildcard follows it.
#[derive(Debug, PartialEq)]
struct Name {
    text: String,
    prefix: bool,
}

/// Maximal runs of path characters, with trailing `.` dropped.
fn names(text: &str) -> Vec<Name> {
    let mut out = Vec::new();
    let mut chars = text.char_indices().peekable();
    while let Some((start, c)) = chars.next() {
        if !path_char(c) {
            continue;
        }
        let mut end = start + c.len_utf8();
        while let Some(&(i, c)) = chars.peek() {
            if !path_char(c) {
                break;
            }
            end = i + c.len_utf8();
            chars.next();
        }
        let prefix = chars.peek().is_some_and(|&(_, c)| wildcard(c));
        let mut name = &text[start..end];
        // The host and path of a URL (after "scheme:").
        if name.starts_with("//") {
            continue;
        }
        if !prefix {
            name = name.trim_end_matches('.');
        }
        if !name.is_empty() {
            out.push(Name {
                text: name.to_string(),
                prefix,
            });
        }
    }
    out
}

/// Targets of Markdown links `](target)`.
fn link_targets(text: &str) -> Vec<String> {
    text.split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .map(|t| t.split('#').next().unwrap_or("").trim().to_string())
        .filter(|t| !t.is_empty() && !t.contains("://") && !t.starts_with("mailto:"))
        .collect()
}

/// `base` joined with `rel`, `..` and `.` resolved; `None` if it leaves `root`.
fn resolve(root: &Path, base: &Path, rel: &str) -> Option<PathBuf> {
    let mut path = base.to_path_buf();
    for part in Path::new(rel).components() {
        match part {
            Component::ParentDir => {
                path.pop();
            }
            Component::Normal(p) => path.push(p),
            _ => {}
        }
        if !path.starts_with(root) {
            return None;
        }
    }
    path.starts_with(root).then_some(path)
}

/// Whether `path` exists, or (for a prefix) some entry of its folder
/// starts with its last component.
fn exists(path: &Path, prefix: bool) -> bool {
    if !prefix || path.exists() {
        return path.exists();
    }
    let (Some(dir), Some(stem)) = (path.parent(), path.file_name()) else {
        return false;
    };
    let stem = stem.to_string_lossy();
    fs::read_dir(dir).is_ok_and(|entries| {
        entries
            .filter_map(Result::ok)
            .any(|e| e.file_name().to_string_lossy().starts_with(stem.as_ref()))
    })
}

fn all_capitals_markdown(name: &str) -> bool {
    name.strip_suffix(".md").is_some_and(|stem| {
        stem.starts_with(|c: char| c.is_ascii_uppercase())
            && stem
                .chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_' || c == '-')
    })
}

/// The problems with one name in a document in folder `dir`; `../` paths
/// are resolved from each of `bases`.
fn check_name(
    root: &Path,
    top: &[String],
    dir: &Path,
    bases: &[PathBuf],
    name: &Name,
) -> Option<String> {
    let text = name.text.as_str();
    let path_text = if name.prefix {
        text
    } else {
        text.trim_end_matches('/')
    };
    if let Some(rest) = text.strip_prefix('/') {
        let ext = Path::new(rest).extension().map(|e| e.to_string_lossy());
        let document = ext.is_some_and(|e| DOCUMENTS.contains(&e.as_ref()));
        return (document && !name.prefix).then(|| format!("{text}: outside the repository"));
    }
    if text.starts_with("../") {
        let resolved: Vec<PathBuf> = bases
            .iter()
            .filter_map(|base| resolve(root, base, path_text))
            .collect();
        return if resolved.is_empty() {
            Some(format!("{text}: outside the repository"))
        } else if resolved.iter().any(|p| exists(p, name.prefix)) {
            None
        } else {
            Some(format!("{text}: no such file"))
        };
    }
    let first = text.split('/').next().unwrap_or("");
    if text.contains('/') && top.iter().any(|t| t == first) {
        let found = resolve(root, root, path_text).is_some_and(|p| exists(&p, name.prefix));
        return (!found).then(|| format!("{text}: no such file in the repository"));
    }
    if !text.contains('/') && all_capitals_markdown(text) {
        let found = root.join(text).exists() || dir.join(text).exists();
        return (!found).then(|| format!("{text}: not at the root nor beside the document"));
    }
    None
}

/// The problems of one document (`rel` its path from the root).
fn check_document(root: &Path, top: &[String], rel: &str, text: &str) -> Vec<String> {
    let dir = root.join(rel).parent().unwrap().to_path_buf();
    let mut bases = vec![dir.clone()];
    if rel.ends_with(".rs") {
        let crate_dir = dir.ancestors().find(|d| d.join("Cargo.toml").exists());
        bases.extend(crate_dir.map(Path::to_path_buf));
    }
    let allowed = |name: &str| ALLOWED.contains(&(rel, name));
    let mut problems: Vec<String> = names(text)
        .iter()
        .filter(|n| !allowed(&n.text))
        .filter_map(|n| check_name(root, top, &dir, &bases, n))
        .collect();
    if rel.ends_with(".md") {
        // `(../../`start_depth`)` was a link the guide's conversion broke.
        let climbs = |n: &&Name| n.text.split('/').all(|c| c == ".." || c.is_empty());
        for name in names(text)
            .iter()
            .filter(|n| n.text.starts_with(".."))
            .filter(climbs)
        {
            problems.push(format!("{}: climbs folders but names none", name.text));
        }
        for target in link_targets(text) {
            match resolve(root, &dir, &target) {
                None => problems.push(format!("link {target}: outside the repository")),
                Some(p) if !p.exists() => problems.push(format!("link {target}: no such file")),
                Some(_) => {}
            }
        }
    }
    problems
        .into_iter()
        .map(|p| format!("{rel}: {p}"))
        .collect()
}

fn top_level(root: &Path) -> Vec<String> {
    fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !SKIPPED.contains(&n.as_str()) && n != ".git")
        .collect()
}

#[test]
fn every_named_file_exists_in_the_repository() {
    let root = root();
    let top = top_level(&root);
    let mut docs = Vec::new();
    documents(&root, &mut docs);
    assert!(docs.len() > 50, "only {} documents found", docs.len());
    let mut problems = Vec::new();
    for doc in &docs {
        let rel = doc
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .into_owned();
        let text = fs::read_to_string(doc).unwrap();
        problems.extend(check_document(&root, &top, &rel, &text));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The checker itself, on made-up documents: it must catch what it is for.
/// (Names are assembled from pieces so that this file passes its own scan.)
#[test]
fn the_checker_catches_missing_and_outside_names() {
    let root = root();
    let top = top_level(&root);
    let check = |rel: &str, text: &str| check_document(&root, &top, rel, text);
    let outside = ["see ", "..", "/shared"].concat();
    assert_eq!(check("README.md", &outside).len(), 1, "{outside}");
    let deep_outside = ["see ", "..", "/..", "/shared/x"].concat();
    assert_eq!(check("docs/model.md", &deep_outside).len(), 1);
    let missing = ["cites ", "do", "cs/no-such-page.md."].concat();
    assert_eq!(check("docs/model.md", &missing).len(), 1);
    let capitals = ["per ", "MODEL", ".md section 2"].concat();
    assert_eq!(check("cases/paper/fig5.toml", &capitals).len(), 1);
    let absolute = ["/", "work", "/notes", ".md"].concat();
    assert_eq!(check("crates/model/src/lib.rs", &absolute).len(), 1);
    let link = ["[model](", "img/none", ".png)"].concat();
    assert_eq!(check("docs/model.md", &link).len(), 1);
    let from_crate = ["join(\"", "..", "/", "..", "/nothing\")"].concat();
    assert_eq!(check("crates/io/tests/golden.rs", &from_crate).len(), 1);
    let climbs = ["start (", "..", "/", "..", "/`start_depth`)"].concat();
    assert_eq!(check("docs/guide/gym.md", &climbs).len(), 1, "{climbs}");
    // What exists passes; outputs and wildcards are not flagged.
    let fine = [
        "`docs/model.md` §2, crates/model/src/node_grid/node_search.rs, cases/tools/, ",
        "docs/img/model_*.png, cases/paper/{}.toml, out/<name>/history.csv, ",
        "out/original/plots/force.png, [the model](model.md#2), README.md, ",
        "[up](",
        "..",
        "/",
        "cases/paper/",
        "fig5.toml), https://docs.rs/x/y.md",
    ]
    .concat();
    assert_eq!(check("docs/model.md", &fine), Vec::<String>::new());
    let from_crate = [
        "join(\"",
        "..",
        "/",
        "..",
        "/",
        "cases/paper/",
        "fig5.toml\")",
    ]
    .concat();
    assert_eq!(
        check("crates/io/tests/golden.rs", &from_crate),
        Vec::<String>::new()
    );
}

/// Curves the studies' scripts make with `synthetic_curve.py` are named
/// synthetic, and no document's data is named measured: none was measured
/// (`docs/studies/calibration.md`).
#[test]
fn synthetic_curves_are_named_synthetic() {
    let studies = root().join("docs/studies");
    let not_measured = |name: &str| assert!(!name.ends_with(".measured.csv"), "{name}");
    let mut made = 0;
    for entry in fs::read_dir(&studies).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        not_measured(&name);
        if !name.ends_with(".sh") {
            continue;
        }
        for line in fs::read_to_string(&path).unwrap().lines() {
            let mut words = line.split_whitespace();
            if words.any(|w| w.ends_with("synthetic_curve.py\"")) {
                let written = words.nth(1).unwrap_or_default();
                assert!(written.ends_with(".synthetic.csv\""), "{name}: {line}");
                made += 1;
            }
        }
    }
    assert!(made >= 2, "{made} curves made");
    for entry in fs::read_dir(studies.join("calibration-cases")).unwrap() {
        not_measured(&entry.unwrap().file_name().to_string_lossy());
    }
}
