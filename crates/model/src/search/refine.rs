//! The sampled scan (`SearchInput::stride` > 1): the scan evaluates every
//! stride-th candidate from the face, then every node within a stride of
//! each sample that is a local minimum of the samples and within `SLACK`
//! of the least. A band's angles are means over its footprint (M10), many
//! nodes wide, so between samples the force is a smooth function of the
//! emergence node or a V whose tip lies where the footprint meets an edge
//! of the soil's state (a softened zone): its least value then lies within
//! a stride of a sample that is a local minimum, and at most the V's slope
//! times half a stride below it (docs/model.md §2.8, (M47)).

use super::block::Block;
use super::input::SearchInput;
use super::line::{Line, Lines};
use super::select::{Best, Choice};
use crate::surface::Surface;
use std::ops::Range;

/// How far above the least sample a local minimum of the samples may lie
/// and still be searched node by node (relative).
pub(super) const SLACK: f64 = 0.02;

/// The candidate of least force (M11, nearest the blade among near-ties)
/// among the samples, the candidates the sampled scan evaluated
/// (reordered here), and every node near their local minima. The scan's
/// `block` holds its prefix sums (extended here) and its running sums at
/// each sample; `windows` and `buffer` (the candidates kept) are scratch.
pub(super) fn refine(
    surface: &Surface,
    input: &SearchInput,
    block: &mut Block,
    samples: &mut [Choice],
    (windows, buffer): (&mut Vec<Range<usize>>, &mut Vec<Choice>),
) -> Option<Choice> {
    samples.sort_by_key(|c| c.node);
    let least = samples.iter().min_by(|a, b| a.force.total_cmp(&b.force))?;
    near_minima(input, samples, least.force, surface.len() - 1, windows);
    let mut best = Best::new(std::mem::take(buffer), true, None, 0.0);
    // Far-field samples (`far_field`) lie on every node already, and may
    // lie beyond the nodes held: the samples are candidates too.
    for c in samples
        .iter()
        .filter(|c| c.force <= least.force * (1.0 + SLACK))
    {
        best.keep(*c);
    }
    for w in windows.iter() {
        evaluate(surface, input, block, w.clone(), &mut best);
    }
    let found = best.select();
    *buffer = best.into_buffer();
    found
}

/// The windows of nodes within a stride of each local minimum of the
/// samples within `SLACK` of the least, merged, before node `end`.
fn near_minima(
    input: &SearchInput,
    samples: &[Choice],
    least: f64,
    end: usize,
    windows: &mut Vec<Range<usize>>,
) {
    let (b, s) = (input.blade, input.stride);
    let bar = least * (1.0 + SLACK);
    windows.clear();
    for (k, c) in samples.iter().enumerate() {
        let lower = |other: Option<&Choice>| {
            other.is_none_or(|o| o.node.abs_diff(c.node) > s || o.force >= c.force)
        };
        let minimum = lower(k.checked_sub(1).map(|i| &samples[i])) && lower(samples.get(k + 1));
        if c.force > bar || !minimum {
            continue;
        }
        let (lo, hi) = (
            (c.node + 1).saturating_sub(s).max(b + 1),
            (c.node + s).min(end),
        );
        match windows.last_mut() {
            Some(w) if w.end >= lo => w.end = w.end.max(hi),
            _ if lo < hi => windows.push(lo..hi),
            _ => {}
        }
    }
}

/// Evaluates every admissible candidate of `window` into `best`, from the
/// running sums at the last sample before it.
fn evaluate(
    surface: &Surface,
    input: &SearchInput,
    block: &mut Block,
    window: Range<usize>,
    best: &mut Best,
) {
    let b = input.blade;
    let at = block
        .checkpoints
        .partition_point(|(j, _)| *j < window.start);
    let (from, mut lines) = match at.checked_sub(1) {
        Some(k) => (block.checkpoints[k].0 + 1, block.checkpoints[k].1),
        None => (b + 1, Lines::new(surface, b, input.depth)),
    };
    block.prefix.cover(surface, b, window.end);
    for j in from..window.end {
        let admitted = lines.advance(surface, j);
        if j < window.start {
            continue;
        }
        let Some(line) = admitted.and_then(|a| Line::alone(j, a, &input.rake)) else {
            continue;
        };
        let band = line.slope.band(&lines, j, input.band_width);
        let angles =
            input
                .laws
                .band_angles(block.prefix.band_angles(surface, &band, input.laws.fresh));
        best.consider(input, &lines, line, angles);
    }
}
