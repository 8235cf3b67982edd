//! A run recorded for its output folder: the history of every increment
//! and evenly spaced surfaces for `frames.csv` and the animation.

use crate::case_file::LoadedCase;
use crate::finished::{frames_columns, SurfaceFrame};
use crate::output::{RunOutput, RunTables};
use soilcut_model::{Simulation, StepError, StepRecord, Summary, Until};
use std::time::Instant;

/// Surfaces captured during a run for the animation (evenly spaced).
pub const ANIMATION_FRAMES: usize = 120;

/// Runs the remaining increments of `sim`, capturing [`ANIMATION_FRAMES`]
/// evenly spaced surfaces (the first before any increment, the last after
/// all); `on_step` is called after each increment.
pub fn record_run(
    sim: &mut Simulation,
    on_step: impl FnMut(),
) -> Result<(Vec<StepRecord>, Vec<SurfaceFrame>), StepError> {
    match record_until_stopped(sim, on_step) {
        (history, frames, None) => Ok((history, frames)),
        (_, _, Some(e)) => Err(e),
    }
}

/// [`record_run`], keeping what was computed when an increment fails: the
/// increments before it, the frames captured so far and the surface it
/// stopped at as the last frame, and why.
fn record_until_stopped(
    sim: &mut Simulation,
    mut on_step: impl FnMut(),
) -> (Vec<StepRecord>, Vec<SurfaceFrame>, Option<StepError>) {
    let total = sim.case().steps();
    let n = ANIMATION_FRAMES.min(total + 1).max(2);
    let mut at: Vec<usize> = (0..n)
        .map(|i| (i * total + (n - 1) / 2) / (n - 1))
        .collect();
    at.dedup();
    let snapshot = |sim: &Simulation| SurfaceFrame {
        step: sim.steps_done(),
        u: sim.blade_position(),
        surface: sim.profile(),
    };
    let mut frames = vec![snapshot(sim)];
    let mut history = Vec::with_capacity(total);
    let mut next = at.iter().skip(1).peekable();
    let driven = sim.drive(Until::End, &mut |sim: &Simulation, record: &StepRecord| {
        history.push(*record);
        if next.next_if_eq(&&sim.steps_done()).is_some() {
            frames.push(snapshot(sim));
        }
        on_step();
    });
    match driven {
        Ok(_) => (history, frames, None),
        Err(e) => {
            if frames.last().is_some_and(|f| f.step != sim.steps_done()) {
                frames.push(snapshot(sim));
            }
            (history, frames, Some(e))
        }
    }
}

/// A run's files and summary: a finished run's, or one that stopped
/// partway (`stopped`), whose files hold the increments made before it.
#[derive(Clone, Debug)]
pub struct RecordedRun {
    /// (name, contents): history.csv, profile.csv, summary.json,
    /// case.resolved.toml, frames.csv.
    pub files: Vec<(&'static str, String)>,
    /// The run's summary (as in summary.json).
    pub summary: Summary,
    /// One record per increment (history.csv's rows).
    pub history: Vec<StepRecord>,
    /// Wall time of the increments, s (as in summary.json).
    pub wall_time_s: f64,
    /// The numbers the files were written from.
    pub tables: RunTables,
    /// The failed increment's error, if the run stopped before its end
    /// (summary.json's `stopped` says it too).
    pub stopped: Option<StepError>,
}

/// Runs the remaining increments of `sim` (set up from `loaded`) with
/// [`record_run`], timing them for `summary.json`, and returns the files
/// that `soilcut run` writes (every front end writes through here); the
/// error of an increment that fails.
pub fn record_files(
    loaded: &LoadedCase,
    sim: &mut Simulation,
    on_step: impl FnMut(),
) -> Result<RecordedRun, StepError> {
    let run = record_kept(loaded, sim, on_step);
    match run.stopped {
        Some(e) => Err(e),
        None => Ok(run),
    }
}

/// [`record_files`], but a run whose increment fails keeps the files of
/// the increments made before it, with the error in `stopped`.
pub fn record_kept(
    loaded: &LoadedCase,
    sim: &mut Simulation,
    on_step: impl FnMut(),
) -> RecordedRun {
    let start = Instant::now();
    let (history, frames, stopped) = record_until_stopped(sim, on_step);
    let wall_time_s = start.elapsed().as_secs_f64();
    let case = &loaded.case;
    let summary = Summary::new(case, &history, sim.initial_mass());
    let output = RunOutput {
        loaded,
        history: &history,
        profile: &sim.profile(),
        summary: &summary,
        candidate_evaluations: sim.evaluations(),
        wall_time_s,
        stopped: stopped.as_ref(),
    };
    let (tables, files) = output.tables_and_files(frames_columns(&frames, case.blade.depth));
    RecordedRun {
        files,
        summary,
        history,
        wall_time_s,
        tables,
        stopped,
    }
}
