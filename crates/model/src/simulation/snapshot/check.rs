//! The invariants a restored state must keep: every increment keeps them
//! and the model indexes by them, so a state that breaks one would not
//! continue as any run does.

use super::SnapshotError;
use crate::case::Case;
use crate::side_heaps::SideHeaps;

pub(super) fn finite(what: &'static str, v: f64) -> Result<f64, SnapshotError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(SnapshotError::invalid(what, format!("{v} is not finite")))
    }
}

pub(super) fn finite_all(what: &'static str, v: Vec<f64>) -> Result<Vec<f64>, SnapshotError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(SnapshotError::invalid(what, format!("{x} is not finite"))),
        None => Ok(v),
    }
}

/// What `check_state` looks at.
pub(super) struct StateCheck<'a> {
    pub(super) case: &'a Case,
    /// Nodes of the surface.
    pub(super) n: usize,
    /// Lengths of the other node columns.
    pub(super) lengths: [usize; 4],
    pub(super) face: usize,
    pub(super) floor: f64,
    pub(super) pristine_from: usize,
    pub(super) seed: Option<usize>,
    pub(super) side: &'a SideHeaps,
    pub(super) unit_weight: &'a [f64],
}

/// The invariants every increment keeps, which the model indexes by: a
/// state that breaks one would not continue as any run does.
pub(super) fn check_state(c: &StateCheck) -> Result<(), SnapshotError> {
    check_nodes(c)?;
    check_ground(c)?;
    check_side_heaps_within(c)
}

/// The node columns: of one length, from the face to the end wall at
/// most, undisturbed from a node among them.
fn check_nodes(c: &StateCheck) -> Result<(), SnapshotError> {
    let n = c.n;
    if c.lengths.iter().any(|&l| l != n) {
        return Err(SnapshotError::invalid(
            "surface",
            format!(
                "node columns of different lengths ({n} and {:?})",
                c.lengths
            ),
        ));
    }
    // Every increment leaves a node ahead of its emergence node, which is
    // ahead of the face.
    if n < c.face + 2 {
        return Err(SnapshotError::invalid(
            "increments done",
            format!(
                "the face at node {} needs at least {} nodes (got {n})",
                c.face,
                c.face + 2
            ),
        ));
    }
    if let Some(wall) = c.case.wall_node() {
        if n > wall + 1 {
            return Err(SnapshotError::invalid(
                "surface",
                format!("{n} nodes reach beyond the end wall's node {wall}"),
            ));
        }
    }
    if c.pristine_from > n {
        return Err(SnapshotError::invalid(
            "surface",
            format!("undisturbed from node {} of {n}", c.pristine_from),
        ));
    }
    Ok(())
}

/// The floor below the deepest tip, unit weights > 0, the search's seed
/// among the nodes.
fn check_ground(c: &StateCheck) -> Result<(), SnapshotError> {
    let n = c.n;
    if !(c.floor < 0.0 && -c.floor >= c.case.deepest()) {
        return Err(SnapshotError::invalid(
            "surface floor",
            format!(
                "y = {} must lie at or below the deepest tip depth {}",
                c.floor,
                c.case.deepest()
            ),
        ));
    }
    if c.unit_weight.iter().any(|&g| g <= 0.0) {
        return Err(SnapshotError::invalid(
            "unit weights",
            "must be > 0".to_string(),
        ));
    }
    if let Some(j) = c.seed.filter(|&j| j >= n) {
        return Err(SnapshotError::invalid(
            "search seed",
            format!("node {j} of {n}"),
        ));
    }
    Ok(())
}

/// The side heaps: columns of one length, and none without a blade width;
/// on the node grid within the surface.
pub(super) fn check_side_heaps(case: &Case, side: &SideHeaps) -> Result<(), SnapshotError> {
    let m = side.area.len();
    if side.height.len() != m || side.unit_weight.len() != m {
        return Err(SnapshotError::invalid(
            "side heaps",
            format!(
                "columns of {m}, {} and {} nodes",
                side.height.len(),
                side.unit_weight.len()
            ),
        ));
    }
    if case.blade.width.is_none() && (m > 0 || side.spilled != 0.0) {
        return Err(SnapshotError::invalid(
            "side heaps",
            "a blade without blade.width has none".to_string(),
        ));
    }
    Ok(())
}

/// The node grid's side heaps lie within its surface.
fn check_side_heaps_within(c: &StateCheck) -> Result<(), SnapshotError> {
    let (m, n) = (c.side.area.len(), c.n);
    if m > n {
        return Err(SnapshotError::invalid(
            "side heaps",
            format!("columns of {m} nodes for a surface of {n}"),
        ));
    }
    Ok(())
}
