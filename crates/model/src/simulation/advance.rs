//! Position-based steps for controllers (docs/model.md §17): bring the
//! blade to a displacement, and its tip to a depth on the way.
//!
//! The grid is tied to whole increments (h = k v0, and a block moves by
//! v0), so an increment is never shortened: `advance_to(x)` makes the
//! increments up to the first whole increment at or beyond x,
//! `Case::increments_to`, the rule of `run.travel`. The blade stops at most
//! one increment past x and the results stay those of the case.

use super::{Simulation, StepRecord, Until};
use crate::case::{climb, CaseError};
use crate::simulation::StepError;
use std::fmt;

/// Why `advance_to` could not bring the blade to a position.
#[derive(Clone, Debug, PartialEq)]
pub enum AdvanceError {
    /// An argument out of range; nothing was changed.
    Argument {
        /// `x` or `depth`.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy.
        message: String,
    },
    /// The case as steered (its depth path or travel) does not validate;
    /// nothing was changed.
    Case(CaseError),
    /// An increment had no admissible mechanism; the increments before it
    /// were made, and these are their records.
    Step {
        /// The records of the increments made.
        records: Vec<StepRecord>,
        /// Why the next one failed.
        error: StepError,
    },
}

impl fmt::Display for AdvanceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AdvanceError::Argument {
                name,
                value,
                message,
            } => write!(f, "advance_to: {name} = {value}: {message}"),
            AdvanceError::Case(e) => write!(f, "advance_to: {e}"),
            AdvanceError::Step { error, .. } => write!(f, "{error}"),
        }
    }
}

impl std::error::Error for AdvanceError {}

impl Simulation {
    /// Runs the increments that bring the blade to displacement `x` (a
    /// length, measured as `blade_position`) and returns their records:
    /// up to the first whole increment at or beyond x (`Case::increments_to`;
    /// none if the blade is there already). With `depth` (a length, > 0),
    /// the tip goes linearly from its depth now to `depth` at x and stays
    /// there: the case's depth path beyond the blade is replaced by that
    /// segment (vertical blades only, as every depth path; no deeper than
    /// the ground the simulation was set up with, `Case::deepest`). An x
    /// the blade has passed holds `depth` for the next increment, which
    /// takes the tip there (a controller's tick between increments). Beyond
    /// `run.travel`, the travel becomes x. Errors leave the simulation as
    /// it was, except a failed increment (`AdvanceError::Step`).
    pub fn advance_to(
        &mut self,
        x: f64,
        depth: Option<f64>,
    ) -> Result<Vec<StepRecord>, AdvanceError> {
        let mut records = Vec::new();
        match self.advance_to_with(x, depth, |_, record| records.push(*record)) {
            Ok(_) => Ok(records),
            Err(AdvanceError::Step { error, .. }) => Err(AdvanceError::Step { records, error }),
            Err(e) => Err(e),
        }
    }

    /// `advance_to`, handing each increment's record to `on_step` as soon
    /// as the increment is made, with the simulation as it stands after it
    /// (for a caller that reacts while the blade moves: a co-simulation's
    /// time step, a progress display); returns the number of increments
    /// made. A failed increment is `AdvanceError::Step` with no records:
    /// `on_step` has had those of the increments before it.
    pub fn advance_to_with(
        &mut self,
        x: f64,
        depth: Option<f64>,
        mut on_step: impl FnMut(&Simulation, &StepRecord),
    ) -> Result<usize, AdvanceError> {
        let target = self.target(x)?;
        self.steer(x, depth, target - self.done)?;
        self.drive(Until::Increments(target), &mut on_step)
            .map_err(|error| AdvanceError::Step {
                records: Vec::new(),
                error,
            })
    }

    /// The increments done once the blade is at x.
    fn target(&self, x: f64) -> Result<usize, AdvanceError> {
        let argument = |message: String| AdvanceError::Argument {
            name: "x",
            value: x,
            message,
        };
        if !x.is_finite() || x < 0.0 {
            return Err(argument("must be a finite length >= 0".into()));
        }
        let target = self.case.increments_to(x);
        if target < self.done {
            return Err(argument(format!(
                "behind the blade at u = {} ({} increments done; x takes {target}, the first whole increment at or beyond it)",
                self.blade_position(),
                self.done
            )));
        }
        Ok(target)
    }

    /// Brings the case to the advance to x: its travel to x at least and,
    /// with `depth`, the tip going linearly from its depth now to `depth`
    /// at x (`todo` increments get it there). Edits the case in place, so
    /// that a tick costs what it changes and not the length of the path
    /// steered so far (a clone and a full check of the case at every tick,
    /// and then at every tick past the travel, made a long steered
    /// session's ticks grow with it); an error leaves the case as it was.
    fn steer(&mut self, x: f64, depth: Option<f64>, todo: usize) -> Result<(), AdvanceError> {
        let new_points = match depth {
            Some(depth) => self.steered_points(x, depth, todo)?,
            None => None,
        };
        let travel = self.case.run.travel;
        if new_points.is_none() && x <= travel {
            return Ok(());
        }
        let from = self.read_to();
        let path = &mut self.case.edit().blade.depth_path;
        let kept = path.partition_point(|p| p[0] < from);
        let ahead = match new_points {
            // What the increments made have read stays as run; the tip is
            // pinned where they left it, so that the ones to come start from it.
            Some(points) => {
                let ahead = path.split_off(kept);
                path.extend(points);
                ahead
            }
            None => Vec::new(),
        };
        self.case.edit().run.travel = travel.max(x);
        // The rest of the case is as it was checked; the rules that read
        // the path beyond its points read its deepest point, which stays
        // within the ground's floor, the depth the case was checked for.
        let floor = -self.ground.get().floor();
        let checked = match new_points {
            Some(_) => self.case.validate_depth_points(kept),
            None => Ok(()),
        }
        .and_then(|()| {
            if x > travel {
                self.case.validate_longer_travel(floor)
            } else {
                Ok(())
            }
        });
        if let Err(e) = checked {
            let path = &mut self.case.edit().blade.depth_path;
            if new_points.is_some() {
                path.truncate(kept);
                path.extend(ahead);
            }
            self.case.edit().run.travel = travel;
            return Err(AdvanceError::Case(e));
        }
        // The stopping bound and the face's least mobilisation hold for the
        // climbs the laws were made for: a tip pulled up faster than any
        // before needs laws made for it (a new fastest climb: rare).
        if let Some([from, to]) = new_points {
            let climb = climb(from, to);
            if climb > self.laws.steepest_climb {
                self.laws.climbing(&self.case, climb);
            }
        }
        Ok(())
    }

    /// The two points of the depth path that take the tip from its depth
    /// now to `depth` at x over `todo` increments (at the end of the next
    /// one where `todo` is 0); `None` where the case holds the tip at
    /// `depth` with no path (nor a vertical blade).
    fn steered_points(
        &self,
        x: f64,
        depth: f64,
        todo: usize,
    ) -> Result<Option<[[f64; 2]; 2]>, AdvanceError> {
        let argument = |message: String| AdvanceError::Argument {
            name: "depth",
            value: depth,
            message,
        };
        let floor = -self.ground.get().floor();
        // A depth path's rule (`Case::validate`): deeper than an increment
        // and the band.
        let least = self.case.run.increment.max(self.case.soil.band_width);
        if !(depth.is_finite() && depth > least && depth <= floor) {
            return Err(argument(format!(
                "must be in ({least}, {floor}]: deeper than run.increment and the band width, and no deeper than the ground the simulation holds, down to the deepest tip depth of its case (give the case a blade.depth_path reaching the deepest depth to steer to)"
            )));
        }
        if self.case.blade.depth_path.is_empty() && depth == self.case.blade.depth {
            return Ok(None);
        }
        // A position the blade has passed needs no increment: the command
        // holds until the next increment takes it (a controller ticks
        // between increments), the path's point at that increment's end; a
        // later command replaces it before the increment is made.
        let v0 = self.case.run.increment;
        let last = self.done + todo.max(1) - 1;
        let reach = if todo == 0 { f64::INFINITY } else { x };
        let from = self.read_to();
        Ok(Some([
            [from, self.case.tip_depth(from)],
            [reach.min(last as f64 * v0 + v0), depth],
        ]))
    }

    /// The furthest along the depth path the increments made so far have
    /// read it: increment j + 1 reads the tip at u_j = j v0 and at
    /// u_j + v0 (both grounds hold the face at exactly j v0), and the two
    /// differ in the last bit. New points go from there on, so that every
    /// depth a made increment read stays on the path as it read it, and
    /// the steered case runs as the steered session did, bit for bit.
    fn read_to(&self) -> f64 {
        let u = self.blade_position();
        match self.done {
            0 => u,
            n => u.max((n - 1) as f64 * self.case.run.increment + self.case.run.increment),
        }
    }
}
