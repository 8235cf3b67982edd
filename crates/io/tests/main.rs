//! The crate's integration tests, one module a file of tests/, built as one
//! binary (one link instead of one a file): run one file's tests with
//! `cargo test -p soilcut-io --test integration FILE::`.

mod golden;
mod mechanism_columns;
mod shipped_cases;
mod snapshots;
mod tables;
mod tools;
mod validation;
