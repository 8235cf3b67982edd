//! `include/soilcut.h` is what cbindgen generates from the crate now: a
//! changed entry point without a regenerated header fails here.
//!
//! After changing the entry points, rewrite the header with
//! SOILCUT_BLESS=1 cargo test -p soilcut-ffi --test integration header::

use std::path::Path;

fn generated() -> String {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut out);
    String::from_utf8(out).expect("the header is UTF-8")
}

#[test]
fn the_committed_header_is_current() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/soilcut.h");
    let header = generated();
    if std::env::var_os("SOILCUT_BLESS").is_some() {
        std::fs::write(&path, &header).expect("write include/soilcut.h");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == header,
        "{} is not what cbindgen generates from crates/ffi/src; regenerate it with\n    SOILCUT_BLESS=1 cargo test -p soilcut-ffi --test integration header::",
        path.display()
    );
}

#[test]
fn no_rust_type_appears_in_the_header() {
    let header = generated();
    // The handle is opaque: declared, never defined.
    assert!(
        header.contains("typedef struct SoilcutSimulation SoilcutSimulation;"),
        "{header}"
    );
    // Rust's own type names, as whole words outside the comments.
    let rust = [
        "Simulation",
        "StepRecord",
        "State",
        "Mutex",
        "Vec",
        "Option",
        "String",
        "str",
        "Box",
        "usize",
        "isize",
        "f64",
        "u64",
        "c_int",
        "c_char",
    ];
    for line in header.lines() {
        let code = line.trim_start();
        if code.starts_with("/*") || code.starts_with('*') || code.starts_with("//") {
            continue;
        }
        for word in code.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
            assert!(!rust.contains(&word), "{word:?} in the header: {line}");
        }
    }
    for c in [
        "int soilcut_step(",
        "typedef struct SoilcutStep {",
        "#define SOILCUT_ERR_PANIC -7",
    ] {
        assert!(header.contains(c), "{c:?} missing from\n{header}");
    }
}
