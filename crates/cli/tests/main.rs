//! The crate's integration tests, one module a file of tests/, built as one
//! binary (one link instead of one a file): run one file's tests with
//! `cargo test -p soilcut --test integration FILE::`.

mod analytic;
mod bounds;
mod cli;
mod driver;
mod finite_runs;
mod module_cycles;
mod output_folder;
mod plots;
mod readme;
mod references;
mod sensitivity;
mod study;
mod test_targets;
