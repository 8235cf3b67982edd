//! The crate's integration tests, one module a file of tests/, built as one
//! binary (one link instead of one a file): run one file's tests with
//! `cargo test -p soilcut-study --test integration FILE::`.

mod converge;
mod ensemble;
mod fit;
mod sensitivity;
mod sweep;
mod synthetic;
