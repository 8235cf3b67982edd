//! `docs/model.md` names, for each equation, the function that computes it:
//! every `Type::function` it cites is a function of that type in this
//! crate or in the bounds' (`crates/bounds`, which §18 documents), and
//! every other code name it cites (`slide_block`, `TIE_TOLERANCE`, a
//! test's name: any backticked identifier with an underscore) occurs in
//! their sources or this crate's tests. A rename that leaves the document
//! behind fails here.
//!
//! The equation index (§15) runs both ways: every function a row names
//! cites the row's tag, (M17) say, in its doc comment or body, and every
//! file a row names (a path such as `crates/study/src/ensemble.rs`, how the
//! index points at code outside this crate) cites it somewhere. A tag is
//! cited as `M17` with no letter, digit or underscore before it and no
//! digit or letter after it: "(M17)", "(M15, M36)".

use std::fs;
use std::path::{Path, PathBuf};

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// (path, text) of every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<(PathBuf, String)>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = fs::read_to_string(&path).unwrap();
            out.push((path, text));
        }
    }
}

/// Backticked spans of `text`.
fn code_spans(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

fn is_identifier(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_alphabetic())
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Whether `word` occurs in `text` with no identifier character either side.
fn has_word(text: &str, word: &str) -> bool {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        !before.is_some_and(ident) && !after.is_some_and(ident)
    })
}

/// Whether some file defines type `ty` and a function `function`.
fn defines(files: &[(PathBuf, String)], ty: &str, function: &str) -> bool {
    let declared = |text: &str| {
        // A type's methods may live in a file of their own (`impl Wedge`).
        ["struct ", "enum ", "impl "]
            .iter()
            .any(|kind| has_word(text, &format!("{kind}{ty}")))
    };
    files
        .iter()
        .any(|(_, text)| declared(text) && has_word(text, &format!("fn {function}")))
}

#[test]
fn every_function_the_model_document_cites_exists() {
    let doc = fs::read_to_string(crate_dir().join("../../docs/model.md")).unwrap();
    let mut files = Vec::new();
    sources(&crate_dir().join("src"), &mut files);
    sources(&crate_dir().join("tests"), &mut files);
    // §18 documents the rigorous bounds, which live in their own crate.
    sources(&crate_dir().join("../bounds/src"), &mut files);
    let mut cited = 0;
    let mut missing = Vec::new();
    for span in code_spans(&doc) {
        if let Some((ty, function)) = span.split_once("::") {
            if is_identifier(ty) && is_identifier(function) {
                cited += 1;
                if !defines(&files, ty, function) {
                    missing.push(span);
                }
            }
        } else if is_identifier(span) && span.contains('_') {
            cited += 1;
            if !files.iter().any(|(_, text)| has_word(text, span)) {
                missing.push(span);
            }
        }
    }
    assert!(cited > 50, "only {cited} code names found in docs/model.md");
    assert!(missing.is_empty(), "docs/model.md cites {missing:?}");
}

#[test]
fn the_check_rejects_a_renamed_function() {
    let mut files = Vec::new();
    sources(&crate_dir().join("src"), &mut files);
    assert!(defines(&files, "Kinematics", "apply"));
    assert!(!defines(&files, "Kinematics", "apply_all"));
    assert!(!defines(&files, "Kinematic", "apply"));
}

/// One row of the equation index (docs/model.md §15): the tag without its
/// parentheses (`M17`) and the backticked names of its code column.
#[derive(Debug)]
struct IndexRow<'a> {
    tag: &'a str,
    code: Vec<&'a str>,
}

/// The rows of the index, the table under "## 15. Equation index".
fn index_rows(doc: &str) -> Vec<IndexRow<'_>> {
    let start = doc
        .find("## 15. Equation index")
        .expect("docs/model.md has an equation index, §15");
    let section = &doc[start..];
    let section = section[2..]
        .find("\n## ")
        .map_or(section, |end| &section[..end + 2]);
    section
        .lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.trim().trim_matches('|').split('|').collect();
            let tag = cells.first()?.trim();
            let tag = tag.strip_prefix('(')?.strip_suffix(')')?;
            let numbered = tag
                .strip_prefix('M')
                .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
            numbered.then(|| IndexRow {
                tag,
                code: code_spans(cells.last().unwrap_or(&"")),
            })
        })
        .collect()
}

/// Whether `text` cites tag `tag` (`M17`): no identifier character before
/// it, no digit or letter after it.
fn cites(text: &str, tag: &str) -> bool {
    text.match_indices(tag).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + tag.len()..].chars().next();
        !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
            && !after.is_some_and(|c| c.is_alphanumeric())
    })
}

/// Every tag `M<n>` cited in `text`, in order, with repeats.
fn tags_cited(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    for (i, _) in text.match_indices('M') {
        let before = text[..i].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let digits = bytes[i + 1..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        let end = i + 1 + digits;
        let after = text[end..].chars().next();
        if digits > 0 && !after.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            found.push(&text[i..end]);
        }
    }
    found
}

/// Byte offset just past the brace that closes the one at `open`, skipping
/// comments, string literals (raw ones too) and character literals, so
/// that a brace in `"{x}"` or `'{'` does not count.
fn matching_brace(text: &str, open: usize) -> Option<usize> {
    let b = text.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let (mut i, mut depth) = (open, 0usize);
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                i += text[i..].find('\n').unwrap_or(text.len() - i);
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let mut nested = 0;
                while i < b.len() {
                    if b[i..].starts_with(b"/*") {
                        nested += 1;
                        i += 2;
                    } else if b[i..].starts_with(b"*/") {
                        nested -= 1;
                        i += 2;
                        if nested == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
                continue;
            }
            b'r' if i == 0 || !ident(b[i - 1]) => {
                // A raw string r"…" or r#"…"# (also after b).
                let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                if b.get(i + 1 + hashes) == Some(&b'"') {
                    let close = format!("\"{}", "#".repeat(hashes));
                    let from = i + 2 + hashes;
                    i = from + text[from..].find(&close)? + close.len();
                    continue;
                }
            }
            b'"' => {
                i += 1;
                while b.get(i)? != &b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'\'' => {
                // A character literal, or else a lifetime (left alone).
                let rest = &text[i + 1..];
                if rest.starts_with('\\') {
                    i += 1 + rest[2..].find('\'')? + 2;
                } else if let Some(c) = rest.chars().next() {
                    if rest[c.len_utf8()..].starts_with('\'') {
                        i += c.len_utf8() + 1;
                    }
                }
            }
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// Offsets of every `fn name` in `text` followed by its parameters or
/// generics (a definition, not a mention).
fn fn_positions(text: &str, name: &str) -> Vec<usize> {
    let pattern = format!("fn {name}");
    text.match_indices(&pattern)
        .filter(|&(i, _)| {
            let before = text[..i].chars().next_back();
            let after = text[i + pattern.len()..].chars().next();
            !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
                && matches!(after, Some('(') | Some('<'))
        })
        .map(|(i, _)| i)
        .collect()
}

/// The text of the function whose `fn` is at `at`: from the doc comments,
/// comments and attributes right above it to the brace that closes its
/// body.
fn function_text(text: &str, at: usize) -> Option<&str> {
    let mut start = text[..at].rfind('\n').map_or(0, |n| n + 1);
    while start > 0 {
        let above = text[..start - 1].rfind('\n').map_or(0, |n| n + 1);
        let line = text[above..start - 1].trim_start();
        if line.starts_with("//") || line.starts_with("#[") {
            start = above;
        } else {
            break;
        }
    }
    let open = at + text[at..].find('{')?;
    Some(&text[start..matching_brace(text, open)?])
}

/// The type an `impl` header (`impl<'a> Trait for Type<'a>`, up to its
/// brace) implements for.
fn impl_self_type(header: &str) -> &str {
    let rest = header.strip_prefix("impl").unwrap_or(header).trim_start();
    let rest = match rest.strip_prefix('<') {
        Some(generic) => {
            let mut depth = 1;
            let end = generic
                .char_indices()
                .find(|&(_, c)| {
                    depth += match c {
                        '<' => 1,
                        '>' => -1,
                        _ => 0,
                    };
                    depth == 0
                })
                .map_or(generic.len(), |(i, _)| i + 1);
            &generic[end..]
        }
        None => rest,
    };
    let rest = rest.rsplit_once(" for ").map_or(rest, |(_, ty)| ty).trim();
    let path = rest.split(['<', ' ', '\n']).next().unwrap_or(rest);
    path.rsplit("::").next().unwrap_or(path)
}

/// (start, end) of the body of every `impl` block of type `ty` in `text`,
/// from its opening brace to just past its closing one.
fn impl_blocks(text: &str, ty: &str) -> Vec<(usize, usize)> {
    let mut blocks = Vec::new();
    for (i, _) in text.match_indices("impl") {
        let line_start = text[..i].rfind('\n').map_or(0, |n| n + 1);
        let Some(brace) = text[i..].find('{').map(|b| i + b) else {
            continue;
        };
        let header = &text[i..brace];
        let starts_a_line = text[line_start..i].trim().is_empty();
        if starts_a_line && header[4..].starts_with([' ', '<']) && impl_self_type(header) == ty {
            if let Some(end) = matching_brace(text, brace) {
                blocks.push((brace, end));
            }
        }
    }
    blocks
}

/// The texts of `Type::function` (or of a free function `function`, any
/// `fn function` at all, when `ty` is `None`) in the files, each with its
/// file.
fn definitions<'a>(
    files: &'a [(PathBuf, String)],
    ty: Option<&str>,
    function: &str,
) -> Vec<(&'a Path, &'a str)> {
    let mut found = Vec::new();
    for (path, text) in files {
        let blocks = match ty {
            Some(ty) => impl_blocks(text, ty),
            None => vec![(0, text.len())],
        };
        for (start, end) in blocks {
            for at in fn_positions(&text[start..end], function) {
                if let Some(f) = function_text(text, start + at) {
                    found.push((path.as_path(), f));
                }
            }
        }
    }
    found
}

/// `path` from the workspace's root, where it is in this crate.
fn shown(path: &Path) -> String {
    path.strip_prefix(crate_dir())
        .map_or(path.to_path_buf(), |p| Path::new("crates/model").join(p))
        .display()
        .to_string()
}

/// What is wrong with the index of `doc` against the crate's `files` and
/// the workspace at `root`: one line per row and name that fails.
fn index_failures(doc: &str, files: &[(PathBuf, String)], root: &Path) -> Vec<String> {
    let mut failures = Vec::new();
    for row in index_rows(doc) {
        let tag = row.tag;
        let mut named = 0;
        for &name in &row.code {
            if name.contains('/') && name.ends_with(".rs") {
                named += 1;
                match fs::read_to_string(root.join(name)) {
                    Err(_) => failures.push(format!("({tag}) `{name}`: no such file")),
                    Ok(text) if !cites(&text, tag) => {
                        failures.push(format!("({tag}) `{name}`: the file does not cite {tag}"))
                    }
                    Ok(_) => {}
                }
                continue;
            }
            let (ty, function) = match name.split_once("::") {
                Some((ty, f)) if is_identifier(ty) && is_identifier(f) => (Some(ty), f),
                None if is_identifier(name) => (None, name),
                _ => continue, // a note such as `per-node-formula`
            };
            named += 1;
            let found = definitions(files, ty, function);
            if found.is_empty() {
                failures.push(format!(
                    "({tag}) `{name}`: no such function in crates/model/src"
                ));
            } else if ty.is_none() && found.len() > 1 {
                let places: Vec<_> = found.iter().map(|(p, _)| shown(p)).collect();
                failures.push(format!(
                    "({tag}) `{name}`: {} functions of that name ({places:?}); name it as Type::{name}",
                    found.len()
                ));
            } else {
                for (path, text) in found {
                    if !cites(text, tag) {
                        failures.push(format!(
                            "({tag}) `{name}` ({}): {tag} is not in its doc comment or body",
                            shown(path)
                        ));
                    }
                }
            }
        }
        if named == 0 {
            failures.push(format!("({tag}): the row names no code"));
        }
    }
    failures
}

#[test]
fn every_function_the_equation_index_names_cites_its_tag() {
    let doc = fs::read_to_string(crate_dir().join("../../docs/model.md")).unwrap();
    let mut files = Vec::new();
    sources(&crate_dir().join("src"), &mut files);
    let rows = index_rows(&doc);
    assert!(rows.len() >= 40, "only {} rows in the index", rows.len());
    let failures = index_failures(&doc, &files, &crate_dir().join("../.."));
    assert!(
        failures.is_empty(),
        "docs/model.md §15, rows whose code does not cite the tag:\n{}",
        failures.join("\n")
    );
}

#[test]
fn every_tag_the_model_document_cites_is_in_the_index() {
    let doc = fs::read_to_string(crate_dir().join("../../docs/model.md")).unwrap();
    let rows = index_rows(&doc);
    // Everything but the index itself (later sections follow it).
    let start = doc.find("## 15. Equation index").unwrap();
    let end = doc[start + 3..]
        .find("\n## ")
        .map_or(doc.len(), |k| start + 3 + k);
    let body = format!("{}{}", &doc[..start], &doc[end..]);
    let mut unknown: Vec<&str> = tags_cited(&doc)
        .into_iter()
        .filter(|t| !rows.iter().any(|r| r.tag == *t))
        .collect();
    unknown.dedup();
    assert!(
        unknown.is_empty(),
        "docs/model.md cites {unknown:?}, not in §15"
    );
    // Each row's equation is stated above the index.
    let unstated: Vec<&str> = rows
        .iter()
        .map(|r| r.tag)
        .filter(|t| !cites(&body, t))
        .collect();
    assert!(
        unstated.is_empty(),
        "§15 lists {unstated:?}, stated nowhere else"
    );
    // Tags are M1, M2, … in order, each once.
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row.tag, format!("M{}", k + 1), "§15, row {}", k + 1);
    }
}

#[test]
fn every_tag_the_model_code_cites_is_in_the_index() {
    let doc = fs::read_to_string(crate_dir().join("../../docs/model.md")).unwrap();
    let rows = index_rows(&doc);
    let mut files = Vec::new();
    sources(&crate_dir().join("src"), &mut files);
    sources(&crate_dir().join("tests"), &mut files);
    let mut unknown = Vec::new();
    for (path, text) in &files {
        for tag in tags_cited(text) {
            if !rows.iter().any(|r| r.tag == tag) {
                unknown.push(format!("{} cites {tag}", path.display()));
            }
        }
    }
    assert!(
        unknown.is_empty(),
        "tags not in docs/model.md §15: {unknown:?}"
    );
}

#[test]
fn the_index_check_finds_functions_and_rejects_a_missing_tag() {
    let source = r#"
struct Thing;

impl<'a> Thing {
    /// The area (M3): no brace in '{' or "}{" or r"{" counts.
    fn area(&self) -> f64 {
        let s = format!("{}", '}');
        if s.is_empty() { 1.0 } else { 2.0 }
    }

    fn volume(&self) -> f64 {
        // (M33) only
        0.0
    }
}

// (M4) above the function, not next to it

fn free() {}
"#;
    let files = vec![(PathBuf::from("thing.rs"), source.to_string())];
    let area = definitions(&files, Some("Thing"), "area");
    assert_eq!(area.len(), 1);
    assert!(area[0].1.starts_with("    /// The area") && area[0].1.ends_with("    }"));
    assert!(cites(area[0].1, "M3"));
    let volume = definitions(&files, Some("Thing"), "volume");
    assert!(!cites(volume[0].1, "M3") && cites(volume[0].1, "M33"));
    assert!(definitions(&files, Some("Other"), "area").is_empty());
    assert_eq!(definitions(&files, None, "free")[0].1, "fn free() {}");
    let doc = "## 15. Equation index\n\n| eq. | what | paper | code |\n|---|---|---|---|\n\
        | (M3) | area | – | `Thing::area` |\n| (M4) | free | – | `free`, `Thing::gone` |\n";
    let failures = index_failures(doc, &files, Path::new("."));
    assert_eq!(failures.len(), 2, "{failures:?}");
    assert!(failures[0].starts_with("(M4) `free`"), "{failures:?}");
    assert!(failures[1].contains("no such function"), "{failures:?}");
    assert_eq!(
        tags_cited("(M1), M12, (M3, M40) M5a XM6"),
        ["M1", "M12", "M3", "M40"]
    );
}
