//! The seed of the best force: the previous increment's emergence node,
//! evaluated on its own before the scan, so that the bounds can reject
//! candidates from the first node on.

use super::angles::footprint_angles;
use super::input::SearchInput;
use super::line::{Line, Lines};
use crate::laws::BandAngles;
use crate::node_grid::surface::Surface;

/// Candidate j computed on its own (its force an upper bound for the
/// scan), if it is admissible: its line, band angles and the running sums
/// before it; `lines` as at the scan's start.
pub(super) fn seed(
    surface: &Surface,
    input: &SearchInput,
    mut lines: Lines,
    j: usize,
) -> Option<(Lines, Line, BandAngles)> {
    let b = lines.face.node;
    if j <= b || j + 1 >= surface.len() {
        return None;
    }
    // The scan's own admissibility test and sums, to the last bit: a seed
    // the scan would reject must not lower the bar.
    for i in b + 1..j {
        lines.advance(surface, i);
    }
    let line = Line::alone(j, lines.advance(surface, j)?, &input.rake)?;
    let band = line.slope.band(&lines, j, input.band_width);
    let m = band.footprint(&surface.height);
    let angles = input.laws.band_angles(footprint_angles(surface, j, m));
    Some((lines, line, angles))
}
