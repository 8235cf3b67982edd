//! The crate's integration tests, one module a file of tests/, built as one
//! binary (one link instead of one a file): run one file's tests with
//! `cargo test -p soilcut-model --test integration FILE::`.

mod band_strength;
mod bin;
mod common;
mod controller;
mod depth_path;
mod face_friction;
mod finite_width;
mod first_increment;
mod landscape;
mod magnitude;
mod model_doc;
mod original;
mod rake;
mod random_cases;
mod refined;
mod snapshot;
mod vertex_ground;
mod vertex_robustness;
mod vertices;
