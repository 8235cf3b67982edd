//! What the simulation asks of the ground it runs on, the node grid
//! (`simulation::node_grid`, docs/model.md §9) or the vertex ground
//! (`vertices::cutting`, §1.2): one question, one method, so that the
//! simulation decides the discretisation once, when it is set up, and
//! never branches on it again.
//!
//! The case, its laws and the count of increments belong to the
//! simulation (`advance_to` steers the case), so each call is given them
//! (`Context`) instead of each ground keeping a copy that could go stale.

use crate::case::Case;
use crate::landscape::Candidate;
use crate::laws::Laws;
use crate::step::{ProfilePoint, StepError, StepRecord};

/// The simulation's state that a ground reads but does not own.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Context<'a> {
    /// The case as it stands (steered by `Simulation::advance_to`).
    pub(crate) case: &'a Case,
    pub(crate) laws: &'a Laws,
    /// Increments done before the one asked for.
    pub(crate) done: usize,
}

/// A ground the simulation can run on.
pub(crate) trait Discretisation {
    /// u: the blade face's x.
    fn blade_position(&self) -> f64;

    /// Weight of soil ahead of the blade (ground that existed at the
    /// start), per blade for a blade of finite width.
    fn mass(&self) -> f64;

    /// Weight of soil spilled into the side heaps so far, per blade.
    fn mass_spilled(&self) -> f64;

    /// Eq. (1) evaluations so far (for benchmarks).
    fn evaluations(&self) -> u64;

    /// y of the floor the ground was set up on (−d of the deepest tip).
    fn floor(&self) -> f64;

    /// The free surface from the face to the end of the ground held.
    fn profile(&self, at: &Context) -> Vec<ProfilePoint>;

    /// The candidates of the next increment, nothing advanced.
    fn landscape(&mut self, at: &Context) -> Result<Vec<Candidate>, StepError>;

    /// Makes the next increment (the caller checks the travel).
    fn step(&mut self, at: &Context) -> Result<StepRecord, StepError>;
}
