//! The C ABI links the model and the case and output formats, not the
//! pictures: `soilcut-io` draws only with its feature `pictures`, which the
//! command line, the studies and Python turn on and this crate does not.

use std::process::Command;

#[test]
fn the_c_abi_links_no_plotting_crate() {
    let out = Command::new(env!("CARGO"))
        .args([
            "tree",
            "-p",
            "soilcut-ffi",
            "-e",
            "normal",
            "--prefix",
            "none",
        ])
        .arg("--manifest-path")
        .arg(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml"))
        .output()
        .expect("cargo tree runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let tree = String::from_utf8_lossy(&out.stdout);
    assert!(tree.contains("soilcut-io"), "{tree}");
    for name in ["soilcut-plot ", "plotters", "png ", "gif "] {
        assert!(
            !tree.contains(name),
            "soilcut-ffi depends on {name}:\n{tree}"
        );
    }
}
