//! `docs/model.md` names, for each equation, the function that computes it:
//! every `Type::function` it cites is a function of that type in this
//! crate, and every other code name it cites (`slide_block`,
//! `TIE_TOLERANCE`, a test's name: any backticked identifier with an
//! underscore) occurs in this crate's source or tests. A rename that
//! leaves the document behind fails here.

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
        ["struct ", "enum "]
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
