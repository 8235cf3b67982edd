//! The principle of minimum effort: the grid search over candidate emergence
//! nodes for the admissible mechanism of least force (paper, "Numerical
//! formulation"; docs/model.md §2, §9.1).
//!
//! Candidate j is the straight line from the blade tip to surface node j
//! (`line`: its angle (M2), admissibility (M3) and weight (M5) from running
//! sums); its force is P_j = W_j · (P/W)(β_j, φ_j) by Eq. (1), with φ_j and
//! ψ_j the means of the node angles over the band's footprint (`angles`,
//! (M10)). The least force wins, nearest the blade among near-ties
//! (`select`, (M11)).
//!
//! Stopping rule (why the domain may be finite, (M31)): along admissible
//! candidates the lines only get lower, so W_j never decreases, and
//! P/W ≥ f_min, its value at β → 0 for the least friction angle and the
//! lesser of the face frictions the block may have (P/W grows with β and φ
//! while the rake exceeds the wall friction, which the case validation
//! ensures). Once W_j f_min exceeds the best force found, no later
//! candidate can win. The scan stops there and grows the domain only if it
//! reaches the end first: growing never changes the result.
//!
//! Speed without changing the result: the best force starts from the
//! previous increment's emergence node, evaluated first (`seed`); a
//! candidate is evaluated in full only if a lower bound of its force can
//! beat the best so far (`bounds`); the scan takes blocks of nodes in
//! three passes (`block`); beyond the last disturbed node the candidates
//! have a closed form and are handled in blocks (`far_field`, (M32)).

mod angles;
mod block;
pub(crate) mod bounds;
mod far_field;
mod input;
mod line;
mod seed;
mod select;

pub use crate::laws::BandAngles;
pub use input::SearchInput;
pub use select::{Choice, Observer};

use crate::node_grid::surface::Surface;
use block::{Block, BlockEnd};
use bounds::LeastFriction;
use far_field::FarField;
use line::Lines;
use select::Best;

/// Nodes appended at a time when the scan reaches the end of the domain.
const GROW_NODES_MIN: usize = 256;

/// Reusable search state (no allocation per step once warmed up).
#[derive(Clone, Debug, Default)]
pub struct Search {
    /// The admissible candidates of a scan, reused (`Best`).
    admissible: Vec<Choice>,
    /// Emergence node of the previous increment (seeds the best force).
    previous: Option<usize>,
    /// The block of nodes being scanned.
    block: Block,
    /// Candidates evaluated in full since creation (for benchmarks).
    pub evaluations: u64,
}

impl Search {
    /// A search resumed from a snapshot: seeded from node `previous`,
    /// with `evaluations` already counted.
    pub fn resumed(previous: Option<usize>, evaluations: u64) -> Self {
        Search {
            previous,
            evaluations,
            ..Search::default()
        }
    }

    /// The previous increment's emergence node, which seeds the next scan.
    pub fn previous(&self) -> Option<usize> {
        self.previous
    }

    /// The minimum-effort mechanism, P* = min_j P_j (M11), or `None` if no
    /// admissible candidate exists within a domain of `max_nodes` nodes.
    pub fn run(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput,
        max_nodes: usize,
    ) -> Option<Choice> {
        let mut found = self.scan(surface, input, max_nodes, true, None);
        if found.is_none() {
            // None may be true (an end wall leaves no room); that a bound
            // rejected every admissible candidate is proven not to happen:
            // if it ever does, tests fail here and a user's run still gets
            // the true minimum.
            found = self.scan(surface, input, max_nodes, false, None);
            debug_assert!(
                found.is_none(),
                "a bound rejected every admissible candidate"
            );
        }
        self.previous = found.map(|c| c.node);
        found
    }

    /// `run` without pruning, handing every admissible candidate up to the
    /// stopping bound to `observe` as it is evaluated (a landscape); the
    /// search is left as it was (the next `run` is seeded from the same
    /// node, and `evaluations` counts increments only).
    pub fn survey(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput,
        max_nodes: usize,
        observe: Observer,
    ) -> Option<Choice> {
        let evaluations = self.evaluations;
        let found = self.scan(surface, input, max_nodes, false, Some(observe));
        self.evaluations = evaluations;
        found
    }

    /// The outward scan over candidates j = b + 1, b + 2, … (M2, M3, M5);
    /// with `prune` false, no candidate is rejected unevaluated except
    /// beyond the stopping bound.
    fn scan(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput,
        max_nodes: usize,
        prune: bool,
        observer: Option<Observer>,
    ) -> Option<Choice> {
        let b = input.blade;
        let mut best = Best::new(std::mem::take(&mut self.admissible), prune, observer);
        self.block.start_scan();
        let mut lines = Lines::new(surface, b, input.depth);
        let previous = self.previous.filter(|_| prune);
        if let Some((at, line, angles)) =
            previous.and_then(|j| seed::seed(surface, input, lines, j))
        {
            if let Some(force) = line.force(input, &at, angles) {
                best.improve(force);
            }
        }
        let mut least = LeastFriction::new(surface.friction[b], input);
        let mut j = b + 1;
        // A block ends before the domain grows or the far field starts, and
        // both happen only once the block is settled and the scan goes on:
        // where the scan node by node would have done them (the profile
        // holds every node the domain grew by).
        loop {
            let end = self
                .block
                .weigh(surface, input, &mut lines, &mut least, &best, j);
            self.evaluations += self.block.footprints(surface, input, &lines, &best);
            if self.block.settle(input, &lines, &mut best) {
                break;
            }
            match end {
                BlockEnd::Next(next) => j = next,
                BlockEnd::End(_) if surface.len() >= max_nodes => break,
                BlockEnd::End(next) => {
                    surface.grow(input.grow_nodes.max(GROW_NODES_MIN));
                    j = next;
                }
                BlockEnd::FarField(j0) => {
                    let far = FarField::new(&lines, surface.ground_unit_weight, j0 - b);
                    self.evaluations += far.scan(input, &lines, &mut best, max_nodes);
                    break;
                }
            }
        }
        let choice = best.select();
        self.admissible = best.into_buffer();
        choice
    }
}
