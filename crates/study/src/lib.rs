//! soilcut-study: studies made of many soilcut runs.
//!
//! * [`sweep`]: every combination (grid) or a seeded Latin-hypercube sample
//!   of case keys, run in parallel, one row of summary figures per run.
//! * [`fit`]: the free case keys that best match one or more measured
//!   force-displacement curves (seeded differential evolution or CMA-ES,
//!   a Nelder-Mead polish), with profile-likelihood intervals and which keys
//!   the curves determine.
//! * [`ensemble`]: one case run with imperceptible perturbations, the
//!   spread of its window means, judged by the rule of [`accuracy`]
//!   (defined in `soilcut-model`).
//! * [`sensitivity`]: Morris screening and Sobol indices of a case's
//!   outputs over ranges of its keys, chaos-aware (ensembles per point).
//! * [`converge`]: one case with the increment halved level after level,
//!   and which averaged quantities converge (docs/model.md §12).
//!
//! A library: no terminal output. Progress is reported through a
//! [`Progress`] callback; results come back as data with methods that
//! render their files. Every result is reproducible: the same inputs and
//! seed give the same files, bit for bit, on any number of threads (wall
//! times go to separate `timing.csv` files).
//!
//! Case keys are changed with the same [`soilcut_io::Override`] mechanism
//! as `--set`, applied to the case file's table before it is resolved, so
//! every key of a case file can be varied or fitted.

#![warn(missing_docs)]

pub mod converge;
pub mod ensemble;
mod error;
pub mod field;
pub mod figures;
pub mod fit;
pub mod run;
pub mod sample;
pub mod sensitivity;
pub mod sweep;

pub use error::StudyError;
pub use run::{BaseCase, RunResult};
/// The ensemble rule (docs/model.md §12.1), defined with the model.
pub use soilcut_model::accuracy;

/// Progress of a study: called with (runs finished, runs in all), once
/// with 0 before the first run and then after each run, from the worker
/// threads.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// A [`Progress`] that ignores everything.
pub fn no_progress(_done: usize, _total: usize) {}

/// A thread pool of `jobs` threads (0: one per available core).
pub(crate) fn pool(jobs: usize) -> Result<rayon::ThreadPool, StudyError> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|e| StudyError::Spec(format!("--jobs {jobs}: cannot start the threads: {e}")))
}
