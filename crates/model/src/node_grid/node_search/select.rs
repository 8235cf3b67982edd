//! Minimum effort and ties (docs/model.md §2.8, §9.1): the increment's mechanism
//! is the admissible candidate of least force, P* = min_j P_j (M11).
//! Candidates whose force is within `TIE_TOLERANCE` (relative) of the
//! minimum count as equal, and the one nearest the blade wins, so round-off
//! cannot flip the choice between near-equal mechanisms.

use super::input::SearchInput;
use super::line::{Line, Lines};
use crate::landscape::TIE_TOLERANCE;
use crate::laws::BandAngles;

/// The chosen mechanism of one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// Emergence node j.
    pub node: usize,
    /// tan β* (physical).
    pub tan_beta: f64,
    /// Slope of the slip line on the grid (= tan β* for a vertical blade;
    /// see `Rake`).
    pub grid_slope: f64,
    /// P*: force per unit width.
    pub force: f64,
    /// W: weight of the block.
    pub weight: f64,
    /// The band's friction and dilation angles (radians).
    pub friction: f64,
    /// Mean of ψ(ut_i) over the footprint, radians.
    pub dilation: f64,
}

/// Told of every admissible candidate a scan evaluates, in the scan's
/// order (nearest the blade first): a landscape's recorder.
pub type Observer<'o> = &'o mut dyn FnMut(&Choice);

/// The best force of one scan and the candidates that reached it.
pub(super) struct Best<'o> {
    /// Best force so far, widened by the tie tolerance: the bar a
    /// candidate must not exceed to be evaluated and kept.
    pub(super) bar: f64,
    /// Whether bounds may reject candidates unevaluated.
    pub(super) prune: bool,
    /// Admissible candidates that were at or below the bar when found,
    /// kept for the tie-break.
    admissible: Vec<Choice>,
    observer: Option<Observer<'o>>,
}

impl<'o> Best<'o> {
    /// No candidate yet; `buffer` is reused for the admissible candidates.
    pub(super) fn new(
        mut buffer: Vec<Choice>,
        prune: bool,
        observer: Option<Observer<'o>>,
    ) -> Self {
        buffer.clear();
        Best {
            bar: f64::INFINITY,
            prune,
            admissible: buffer,
            observer,
        }
    }

    /// The buffer, for the next scan.
    pub(super) fn into_buffer(self) -> Vec<Choice> {
        self.admissible
    }

    /// Lowers the bar to a force found.
    pub(super) fn improve(&mut self, force: f64) {
        self.bar = self.bar.min(force * (1.0 + TIE_TOLERANCE));
    }

    /// No candidate from weight W on can beat the best: W f_min > P_best
    /// (1 + 10⁻¹⁰), the stopping rule (M31).
    pub(super) fn beyond_reach(&self, weight: f64, min_factor: f64) -> bool {
        weight * min_factor > self.bar
    }

    /// Evaluates a candidate in full (Eq. (1)) and keeps it if it can be
    /// the least: the running minimum of P_j (M11).
    pub(super) fn consider(
        &mut self,
        input: &SearchInput,
        lines: &Lines,
        line: Line,
        angles: BandAngles,
    ) {
        let Some(force) = line.force(input, lines, angles) else {
            return;
        };
        let candidate = Choice {
            node: line.node,
            tan_beta: line.slope.tan_beta,
            grid_slope: line.slope.grid,
            force,
            weight: line.weight,
            friction: angles.friction,
            dilation: angles.dilation,
        };
        if let Some(observe) = &mut self.observer {
            observe(&candidate);
        }
        if force > self.bar {
            return;
        }
        self.improve(force);
        self.admissible.push(candidate);
    }

    /// The candidate of least force, P* = min_j P_j (M11), nearest the
    /// blade among near-ties.
    pub(super) fn select(&self) -> Option<Choice> {
        self.admissible
            .iter()
            .filter(|c| c.force <= self.bar)
            .min_by_key(|c| c.node)
            .copied()
    }
}
