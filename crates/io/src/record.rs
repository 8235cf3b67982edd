//! A run recorded for its output folder: the history of every increment
//! and evenly spaced surfaces for `frames.csv` and the animation.

use crate::finished::SurfaceFrame;
use soilcut_model::{Simulation, StepError, StepRecord};

/// Surfaces captured during a run for the animation (evenly spaced).
pub const ANIMATION_FRAMES: usize = 120;

/// Runs the remaining increments of `sim`, capturing [`ANIMATION_FRAMES`]
/// evenly spaced surfaces (the first before any increment, the last after
/// all); `on_step` is called after each increment.
pub fn record_run(
    sim: &mut Simulation,
    mut on_step: impl FnMut(),
) -> Result<(Vec<StepRecord>, Vec<SurfaceFrame>), StepError> {
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
    while !sim.is_done() {
        history.push(sim.step()?);
        if next.next_if_eq(&&sim.steps_done()).is_some() {
            frames.push(snapshot(sim));
        }
        on_step();
    }
    Ok((history, frames))
}
