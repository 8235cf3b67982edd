//! No module cycles: within each crate of the workspace, no two source files
//! import each other, directly or through others. A file's imports are its
//! `use` paths that start at `crate::`, `super::` or `self::`, each taken
//! to the longest module path that is a file of the crate; a parent's
//! `mod child;` and its re-exports (`pub use child::X`) are the module
//! tree, not imports. Two files that need each other want one concept or a
//! third file (errors and shared types belong in leaf modules).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// A module's path within its crate (`["search", "block"]`; empty: the
/// crate root).
type Module = Vec<String>;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("a source folder") {
        let path = entry.expect("an entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn module_of(src: &Path, file: &Path) -> Module {
    let rel = file
        .strip_prefix(src)
        .expect("under src")
        .with_extension("");
    let mut parts: Module = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("lib" | "main" | "mod")
    ) {
        parts.pop();
    }
    parts
}

/// The paths `text` imports: its `use` declarations (those that begin a
/// line, after a visibility), whitespace removed, and every `crate::a::b`
/// written inline in code, each with whether it stands in the file's
/// inline `mod tests`, whose `super` is the file itself.
fn uses(text: &str) -> Vec<(bool, String)> {
    let mut out = Vec::new();
    let mut open: Option<String> = None;
    let mut in_tests = false;
    for line in text.lines() {
        let line = line.trim();
        in_tests |= matches!(line, "mod tests {" | "pub(crate) mod tests {");
        let current = match open.take() {
            Some(started) => started + line,
            None => {
                let declaration = ["use ", "pub use ", "pub(crate) use ", "pub(super) use "]
                    .iter()
                    .find_map(|v| line.strip_prefix(v));
                match declaration {
                    Some(rest) => rest.to_string(),
                    None => {
                        out.extend(inline_paths(line).map(|p| (in_tests, p)));
                        continue;
                    }
                }
            }
        };
        match current.find(';') {
            Some(end) => out.push((in_tests, current[..end].split_whitespace().collect())),
            None => open = Some(current),
        }
    }
    out
}

/// The `crate::a::b` paths written in a line of code (not a comment).
fn inline_paths(line: &str) -> impl Iterator<Item = String> + '_ {
    let code = if line.starts_with("//") { "" } else { line };
    code.match_indices("crate::").filter_map(move |(at, _)| {
        let before = code[..at].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            return None;
        }
        let path: String = code[at..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
            .collect();
        Some(path.trim_end_matches(':').to_string())
    })
}

/// The full paths of a use tree: `a::{b, c::{d, e}}` is `a::b`, `a::c::d`,
/// `a::c::e` (without whitespace).
fn expand(tree: &str) -> Vec<String> {
    let Some(open) = tree.find('{') else {
        return vec![tree.to_string()];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let (mut depth, mut from, mut out) = (0, 0, Vec::new());
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.extend(
                    expand(&inner[from..i])
                        .into_iter()
                        .map(|t| format!("{prefix}{t}")),
                );
                from = i + 1;
            }
            _ => {}
        }
    }
    out.extend(
        expand(&inner[from..])
            .into_iter()
            .map(|t| format!("{prefix}{t}")),
    );
    out
}

/// The module paths a `use` names from `from`: every path of it that
/// starts at `crate`, `super` or `self`, resolved against the tree.
fn targets(from: &Module, declaration: &str) -> Vec<Module> {
    let mut out = Vec::new();
    for path in expand(declaration) {
        let mut segments = path.split("::");
        let mut base: Module = match segments.next() {
            Some("crate") => Vec::new(),
            Some("self") => from.clone(),
            Some("super") => from[..from.len().saturating_sub(1)].to_vec(),
            _ => continue,
        };
        for segment in segments {
            match segment {
                "super" => {
                    base.pop();
                }
                "self" | "*" | "" => {}
                s => base.push(s.split(" as ").next().unwrap_or(s).to_string()),
            }
        }
        out.push(base);
    }
    out
}

/// The file-level import graph of one crate.
fn graph(src: &Path) -> BTreeMap<Module, BTreeSet<Module>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let modules: BTreeMap<Module, PathBuf> = files
        .iter()
        .map(|f| (module_of(src, f), f.clone()))
        .collect();
    let mut edges = BTreeMap::new();
    for (module, file) in &modules {
        let text = fs::read_to_string(file).expect("a source file");
        let mut to = BTreeSet::new();
        for (in_tests, declaration) in uses(&text) {
            let mut from = module.clone();
            if in_tests {
                from.push("tests".to_string());
            }
            for mut target in targets(&from, &declaration) {
                while !target.is_empty() && !modules.contains_key(&target) {
                    target.pop();
                }
                if modules.contains_key(&target) && &target != module {
                    to.insert(target);
                }
            }
        }
        edges.insert(module.clone(), to);
    }
    edges
}

/// A cycle through `start`, if one exists (depth-first search).
fn cycle_through(
    edges: &BTreeMap<Module, BTreeSet<Module>>,
    start: &Module,
) -> Option<Vec<Module>> {
    let mut stack = vec![(start.clone(), vec![start.clone()])];
    let mut seen = BTreeSet::new();
    while let Some((at, path)) = stack.pop() {
        for next in &edges[&at] {
            if next == start {
                return Some(path);
            }
            if seen.insert(next.clone()) {
                let mut longer = path.clone();
                longer.push(next.clone());
                stack.push((next.clone(), longer));
            }
        }
    }
    None
}

fn name(m: &Module) -> String {
    if m.is_empty() {
        "lib".to_string()
    } else {
        m.join("/")
    }
}

#[test]
fn no_crate_has_a_module_cycle() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut found = Vec::new();
    for entry in fs::read_dir(&crates).expect("crates/") {
        let src = entry.expect("an entry").path().join("src");
        if !src.is_dir() {
            continue;
        }
        let edges = graph(&src);
        for module in edges.keys() {
            if let Some(cycle) = cycle_through(&edges, module) {
                let names: Vec<String> = cycle.iter().map(name).collect();
                found.push(format!("{}: {}", src.display(), names.join(" -> ")));
            }
        }
    }
    assert!(found.is_empty(), "module cycles:\n{}", found.join("\n"));
}

/// The test sees a cycle where there is one.
#[test]
fn a_cycle_is_seen() {
    let dir = std::env::temp_dir().join(format!("soilcut-cycles-{}", std::process::id()));
    let src = dir.join("src");
    fs::create_dir_all(src.join("a")).unwrap();
    fs::write(src.join("lib.rs"), "mod a;\nmod b;\n").unwrap();
    fs::write(src.join("a.rs"), "mod c;\nuse crate::{b::{B, f}, a::c};\n").unwrap();
    fs::write(src.join("a/c.rs"), "use super::super::b::B;\n").unwrap();
    fs::write(
        src.join("b.rs"),
        "fn f() { crate::a::c::g() }\n#[cfg(test)]\nmod tests {\n    use super::*;\n}\n",
    )
    .unwrap();
    let edges = graph(&src);
    let a = vec!["a".to_string()];
    let b = vec!["b".to_string()];
    let c = vec!["a".to_string(), "c".to_string()];
    assert_eq!(edges[&a], BTreeSet::from([b.clone(), c.clone()]));
    assert_eq!(edges[&c], BTreeSet::from([b.clone()]));
    assert!(cycle_through(&edges, &b).is_some());
    assert!(cycle_through(&edges, &a).is_none());
    fs::remove_dir_all(&dir).unwrap();
}
