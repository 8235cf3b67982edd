//! The scan in blocks (speed without changing the result): the scan takes
//! `BLOCK` nodes at a time in three passes: the running sums and each
//! line's weight and first bound (`Block::weigh`); the footprints and the
//! second bound of the lines that passed (`Block::footprints`); Eq. (1)
//! for those left, in order, up to the stopping rule (`Block::settle`).
//! The first two passes use the best force at the block's start, which the
//! third only lowers, so they reject no line that the scan node by node
//! would have kept; they hold no branch on their bounds (which lines pass
//! is data), so the processor overlaps candidates.

use super::angles::Prefix;
use super::bounds::LeastFriction;
use super::far_field::far_field_from;
use super::input::SearchInput;
use super::line::{Line, Lines, Slope};
use super::select::Best;
use crate::force_bounds::may_win;
use crate::laws::BandAngles;
use crate::node_grid::surface::Surface;

/// Nodes scanned per block.
const BLOCK: usize = 128;

/// Where a block of the scan ended.
pub(super) enum BlockEnd {
    /// After `BLOCK` nodes: the next block starts at this node.
    Next(usize),
    /// At a node with no neighbour ahead: the end of the domain, which may
    /// grow (the scan goes on from this node).
    End(usize),
    /// At the first node of the far field (`far_field`).
    FarField(usize),
}

/// One block of the scan, reused from step to step.
#[derive(Clone, Debug, Default)]
pub(super) struct Block {
    /// Its first node.
    start: usize,
    /// W_j of each node from `start` as the bounds take it
    /// (`SearchInput::bound_weight`), −∞ where the line is not admissible.
    weight: Vec<f64>,
    /// The lines of the first pass; the first `near` passed its bound.
    passed: Vec<Line>,
    near: usize,
    /// The lines that passed the second pass's bound, with their band angles.
    kept: Vec<(Line, BandAngles)>,
    /// The band angles' prefix sums over the nodes scanned.
    pub(super) prefix: Prefix,
}

impl Block {
    /// Readies the prefix sums for a scan from the blade node.
    pub(super) fn start_scan(&mut self) {
        self.prefix.start();
    }

    /// First pass over a block of up to `BLOCK` nodes from j: the running
    /// sums, each node's line (admissible or not, and W_j) and the lines
    /// that pass the bound before the footprint (with the best force at the
    /// block's start). Stops before a node where the scan must first do
    /// something else (`BlockEnd`).
    pub(super) fn weigh(
        &mut self,
        surface: &Surface,
        input: &SearchInput,
        lines: &mut Lines,
        least: &mut LeastFriction,
        best: &Best,
        mut j: usize,
    ) -> BlockEnd {
        self.start = j;
        self.weight.clear();
        self.passed.resize(BLOCK, Line::default());
        let mut near = 0;
        let limit = j + BLOCK;
        let end = loop {
            if j >= limit {
                break BlockEnd::Next(j);
            }
            if far_field_from(surface, input, lines, j) {
                break BlockEnd::FarField(j);
            }
            // The emergence node always has a neighbour ahead of it.
            if j + 1 >= surface.len() {
                break BlockEnd::End(j);
            }
            self.prefix.push(surface, j - 1);
            least.include(surface, j, input);
            let admitted = lines.advance(surface, j);
            let rupture = lines.face.spacings(j) * lines.dx;
            let floor = admitted.map(|(_, weight)| input.bound_weight(weight, rupture));
            // Inadmissible lines never stop the scan.
            self.weight.push(floor.unwrap_or(f64::NEG_INFINITY));
            let line = admitted.and_then(|(grid, weight)| {
                let slope = Slope::on_grid(grid, &input.rake)?;
                Some(Line {
                    node: j,
                    slope,
                    weight,
                    floor: floor.unwrap_or(weight),
                })
            });
            if let Some(line) = line {
                self.passed[near] = line;
                // Kept without a branch: which lines pass is data.
                let t = line.slope.tan_beta;
                let pass =
                    !best.prune || least.lower.can_beat(line.floor, t, best.bar, &input.face);
                near += usize::from(pass);
            }
            j += 1;
        };
        self.near = near;
        end
    }

    /// Second pass: the footprint and band angles (M10) of each line kept
    /// by the first, and the bound after the footprint (with the best force
    /// at the block's start); keeps those that pass, in order. Returns the
    /// number of lines it evaluated.
    pub(super) fn footprints(
        &mut self,
        surface: &Surface,
        input: &SearchInput,
        lines: &Lines,
        best: &Best,
    ) -> u64 {
        let near = self.near;
        self.kept.resize(near, (Line::default(), input.laws.fresh));
        let mut kept = 0;
        for i in 0..near {
            let line = self.passed[i];
            let band = line.slope.band(lines, line.node, input.band_width);
            let angles =
                input
                    .laws
                    .band_angles(self.prefix.band_angles(surface, &band, input.laws.fresh));
            let lower = (line.floor, line.slope.tan_beta);
            let may_win = may_win((input.laws, &input.face), lower, &angles, best.bar);
            self.kept[kept] = (line, angles);
            kept += usize::from(angles.fresh | !best.prune | may_win);
        }
        self.kept.truncate(kept);
        near as u64
    }

    /// Third pass: Eq. (1) for the lines kept, in order, with the best force
    /// as it improves, up to the node where the stopping rule (M31) ends
    /// the scan (W_j f_min above the best force then); returns whether it
    /// did. The bounds of the first two passes used the best force at the
    /// block's start, no lower than the best force now: they rejected only
    /// lines that could not beat it.
    pub(super) fn settle(&self, input: &SearchInput, lines: &Lines, best: &mut Best) -> bool {
        let min_factor = input.laws.min_factor;
        let mut stop = self.first_stop(0, best, min_factor);
        for &(line, angles) in &self.kept {
            let i = line.node - self.start;
            if i > stop {
                return true;
            }
            let bar = best.bar;
            best.consider(input, lines, line, angles);
            if best.bar != bar {
                stop = self.first_stop(i, best, min_factor);
            }
        }
        stop < self.weight.len()
    }

    /// The first node from block index `from` at which the stopping rule
    /// ends the scan (as an index; the block's length if none).
    fn first_stop(&self, from: usize, best: &Best, min_factor: f64) -> usize {
        self.weight[from..]
            .iter()
            .position(|&w| best.beyond_reach(w, min_factor))
            .map_or(self.weight.len(), |k| from + k)
    }
}
