//! A run recorded for its output folder: the history of every increment
//! and evenly spaced surfaces for `frames.csv` and the animation.

use crate::case_file::LoadedCase;
use crate::finished::{frames_columns, SurfaceFrame};
use crate::output::{RunOutput, RunTables};
use soilcut_model::{ProfilePoint, Simulation, StepError, StepRecord, Summary, Until};
use std::time::Instant;

/// Surfaces captured during a run for the animation (evenly spaced).
pub const ANIMATION_FRAMES: usize = 120;

/// What one run of a case computed, finished or stopped partway.
#[derive(Clone, Debug)]
pub struct CaseRun {
    /// One record per increment made.
    pub history: Vec<StepRecord>,
    /// Evenly spaced surfaces (the first before any increment, the last
    /// after the last increment made), if any were asked for.
    pub frames: Vec<SurfaceFrame>,
    /// The surface where the run ended.
    pub profile: Vec<ProfilePoint>,
    /// Figures of the run (as in summary.json).
    pub summary: Summary,
    /// Candidate mechanisms evaluated.
    pub evaluations: u64,
    /// Wall time of the increments, s.
    pub wall_time_s: f64,
    /// The failed increment's error, if the run stopped before its end.
    pub stopped: Option<StepError>,
}

/// Runs a loaded case from flat ground to its end: every front end's run
/// of a case (`soilcut run`, Python's `run`, the studies) goes through
/// here, `frames` evenly spaced surfaces captured (0: none); `on_step` is
/// called after each increment.
pub fn run_case(loaded: &LoadedCase, frames: usize, on_step: impl FnMut()) -> CaseRun {
    let mut sim = Simulation::start(&loaded.case);
    run_on(&mut sim, frames, on_step)
}

/// [`run_case`] for the remaining increments of `sim`, a simulation of
/// the case set up by its caller.
fn run_on(sim: &mut Simulation, frames: usize, mut on_step: impl FnMut()) -> CaseRun {
    let start = Instant::now();
    let at = frame_steps(sim.steps_done(), sim.case().steps(), frames);
    let snapshot = |sim: &Simulation| SurfaceFrame {
        step: sim.steps_done(),
        u: sim.blade_position(),
        surface: sim.profile(),
    };
    let mut captured: Vec<SurfaceFrame> = Vec::new();
    if frames > 0 {
        captured.push(snapshot(sim));
    }
    let mut next = at.iter().peekable();
    let mut history = Vec::with_capacity(sim.case().steps() - sim.steps_done());
    let driven = sim.drive(Until::End, &mut |sim: &Simulation, record: &StepRecord| {
        history.push(*record);
        if next.next_if_eq(&&sim.steps_done()).is_some() {
            captured.push(snapshot(sim));
        }
        on_step();
    });
    let stopped = driven.err();
    if stopped.is_some() && captured.last().is_some_and(|f| f.step != sim.steps_done()) {
        captured.push(snapshot(sim));
    }
    let wall_time_s = start.elapsed().as_secs_f64();
    CaseRun {
        summary: Summary::new(sim.case(), &history, sim.initial_mass()),
        history,
        frames: captured,
        profile: sim.profile(),
        evaluations: sim.evaluations(),
        wall_time_s,
        stopped,
    }
}

/// The increments after which the surfaces of a run of `total` increments
/// are captured (`frames` evenly spaced, at least the first and the last),
/// those after increment `done`: the surface at `done` is the first frame.
fn frame_steps(done: usize, total: usize, frames: usize) -> Vec<usize> {
    if frames == 0 {
        return Vec::new();
    }
    let n = frames.min(total + 1).max(2);
    let mut at: Vec<usize> = (0..n)
        .map(|i| (i * total + (n - 1) / 2) / (n - 1))
        .filter(|&step| step > done)
        .collect();
    at.dedup();
    at
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

/// Runs a loaded case to its end with [`run_case`] and returns the files
/// that `soilcut run` writes (every front end writes through here): a run
/// whose increment fails keeps the files of the increments made before
/// it, with the error in `stopped`.
pub fn record_case(loaded: &LoadedCase, on_step: impl FnMut()) -> RecordedRun {
    recorded(loaded, run_case(loaded, ANIMATION_FRAMES, on_step))
}

/// [`record_case`] for the remaining increments of `sim`, a simulation of
/// `loaded` set up by its caller; the error of an increment that fails.
pub fn record_files(
    loaded: &LoadedCase,
    sim: &mut Simulation,
    on_step: impl FnMut(),
) -> Result<RecordedRun, StepError> {
    let run = recorded(loaded, run_on(sim, ANIMATION_FRAMES, on_step));
    match run.stopped {
        Some(e) => Err(e),
        None => Ok(run),
    }
}

/// The files of a run of `loaded`.
fn recorded(loaded: &LoadedCase, run: CaseRun) -> RecordedRun {
    let case = &loaded.case;
    let output = RunOutput {
        loaded,
        history: &run.history,
        profile: &run.profile,
        summary: &run.summary,
        candidate_evaluations: run.evaluations,
        wall_time_s: run.wall_time_s,
        stopped: run.stopped.as_ref(),
    };
    let (tables, files) = output.tables_and_files(frames_columns(&run.frames, case.blade.depth));
    RecordedRun {
        files,
        summary: run.summary,
        history: run.history,
        wall_time_s: run.wall_time_s,
        tables,
        stopped: run.stopped,
    }
}
