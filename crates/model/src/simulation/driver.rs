//! The one loop that makes increments (issue 49): every front end (the
//! command line's recording, Python, the studies, the landscape, the
//! bounds' instants, the C ABI) asks the driver to go to a point and
//! observes the increments on the way, in the spirit of argmin's
//! observers: the loop, where it stops and how a failed increment ends it
//! are written once, here.
//!
//! Where to stop is one rule, `Case::increments_to`: the first whole
//! increment at or beyond a blade displacement u, to a relative 1e-9 of u
//! so that u = k v0 computed in floating point lands on increment k.

use super::{Simulation, StepError, StepRecord};

/// Receives each increment as the driver makes it.
pub trait Observer {
    /// Called after each increment with the simulation as the increment
    /// left it and the increment's record.
    fn increment(&mut self, sim: &Simulation, record: &StepRecord);
}

impl<F: FnMut(&Simulation, &StepRecord)> Observer for F {
    fn increment(&mut self, sim: &Simulation, record: &StepRecord) {
        self(sim, record)
    }
}

/// No observer: the increments are made and not looked at.
impl Observer for () {
    fn increment(&mut self, _: &Simulation, _: &StepRecord) {}
}

/// Where the driver stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Until {
    /// The case's travel (`run.travel`).
    End,
    /// After this many increments in all (at most the case's).
    Increments(usize),
    /// The first increment evaluated at u ≥ `at` d, d the case's
    /// `blade.depth` (u = increments × v0; the last increment if `at` lies
    /// beyond it): where `soilcut landscape --at` and `soilcut bounds --at`
    /// look.
    Instant(f64),
}

impl Simulation {
    /// The number of increments done at which `until` is reached.
    pub fn increments_until(&self, until: Until) -> usize {
        let steps = self.case.steps();
        match until {
            Until::End => steps,
            Until::Increments(n) => n.min(steps),
            Until::Instant(at) => self
                .case
                .increments_to(at * self.case.blade.depth)
                .min(steps.saturating_sub(1)),
        }
    }

    /// Makes the increments up to `until`, each handed to `observer`;
    /// returns how many were made. An increment that fails ends the drive
    /// with its error: the increments before it stay made (and were
    /// observed), so a caller keeps what was computed.
    pub fn drive(
        &mut self,
        until: Until,
        observer: &mut impl Observer,
    ) -> Result<usize, StepError> {
        let target = self.increments_until(until);
        let start = self.done;
        while self.done < target {
            let record = self.step()?;
            observer.increment(self, &record);
        }
        Ok(self.done - start)
    }

    /// The increments, counted from the start, at which a quantity sampled
    /// every `every` blade depths of travel is taken, up to `last`
    /// increments done: sample n at the first increment at or beyond
    /// u = n `every` d (`Case::increments_to`), or at the next increment if
    /// the previous sample took that one already (`every` below v0 / d).
    pub fn samples_every(&self, every: f64, last: usize) -> Vec<usize> {
        let d = self.case.blade.depth;
        let mut out: Vec<usize> = Vec::new();
        for i in 0..=last {
            if i >= self.case.increments_to(out.len() as f64 * every * d) {
                out.push(i);
            }
        }
        out
    }
}
