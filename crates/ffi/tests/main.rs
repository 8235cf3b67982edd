//! The crate's integration tests, one module a file of tests/, built as one
//! binary (one link instead of one a file): run one file's tests with
//! `cargo test -p soilcut-ffi --test integration FILE::`.

mod abi;
mod dependencies;
mod examples;
mod header;
mod snapshot_case;
