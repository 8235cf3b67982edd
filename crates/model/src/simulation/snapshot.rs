//! Snapshots: a running simulation as bytes and back (docs/model.md §17).
//!
//! A snapshot holds everything that determines the rest of the run: the
//! case (as `advance_to` may have steered it), the surface's nodes and
//! counters, the search's seed (the previous increment's emergence node)
//! and evaluation count, the side heaps, the increments done and the
//! steepest climb the laws were made for (`Body`); the ground as its own
//! type writes it (`GroundBody`: the vertices and the evaluation count, or
//! the node grid's fields).
//! What the case determines (the laws, the rake's grid, the face's node,
//! which follows from the increments done) is rebuilt
//! from it; the search's, kinematics' and avalanche's scratch is rebuilt
//! empty, as each increment fills it before use. So a restored simulation
//! continues bit for bit as the original would.
//!
//! Layout, little-endian: the magic `SOILCUT\x01`, the format version
//! (u32), the crate version (u64 length, UTF-8), the body's length (u64),
//! the body in postcard's format (serde; numbers as their bits), and the
//! CRC-32 (u32) of all that precedes it. A snapshot of another format or
//! crate version is refused: the model's numbers may differ between
//! versions, so a state from one is no state of the other.

mod check;
mod snapshot_error;

pub use snapshot_error::SnapshotError;

use super::{Discretised, Simulation};
use crate::case::{Case, Ground};
use crate::discretisation::Discretisation;
use crate::laws::Laws;
use crate::node_grid::face_node::FaceNode;
use crate::node_grid::node_search::Search;
use crate::node_grid::surface::Surface;
use crate::node_grid::{fresh_angles, NodeGrid};
use crate::side_heaps::SideHeaps;
use crate::vertices::cutting::Cutting;
use crate::vertices::Vertices;
use check::{check_side_heaps, check_state, finite, finite_all, StateCheck};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

/// The first bytes of every snapshot.
pub const MAGIC: [u8; 8] = *b"SOILCUT\x01";
/// The layout's version: raised whenever the body changes.
pub const FORMAT_VERSION: u32 = 10;
/// The crate version a snapshot must come from.
pub const CRATE_VERSION: &str = env!("CARGO_PKG_VERSION");
/// Bytes of the CRC-32 that ends every snapshot.
pub const CHECKSUM_BYTES: usize = 4;

/// The body of a snapshot (docs/model.md §17.1): borrowed from the
/// simulation when written, owned when read. Its fields are the state in
/// the order the layout keeps (postcard writes `nodes`' fields in place,
/// as if they were this struct's); adding one raises `FORMAT_VERSION`.
#[derive(Serialize, Deserialize)]
struct Body<'a> {
    case: Cow<'a, Case>,
    /// The caller's bytes (`snapshot_with_note`).
    note: Cow<'a, [u8]>,
    /// Increments done; the face follows from them.
    done: usize,
    /// The steepest climb the laws' bounds were made for: a steered tip
    /// keeps the bounds of a climb its path no longer holds (the points
    /// ahead of it replaced), and the restored run must scan as far.
    steepest_climb: f64,
    initial_mass: f64,
    /// The side heaps of a blade of finite width, on either ground.
    side: Cow<'a, SideHeaps>,
    /// The ground, of the case's `run.ground`.
    ground: GroundBody<'a>,
}

/// The ground's state in a snapshot, of the kind its case runs on.
#[derive(Serialize, Deserialize)]
enum GroundBody<'a> {
    /// The vertex ground and its evaluations.
    Vertices(Cow<'a, Vertices>, u64),
    /// The node grid.
    Nodes(NodeBody<'a>),
}

/// The node grid's state in a snapshot.
#[derive(Serialize, Deserialize)]
struct NodeBody<'a> {
    /// The surface's floor y, where the undisturbed ground begins, and the
    /// trench's and the appended ground's weights and area.
    floor: f64,
    pristine_from: usize,
    trench_mass: f64,
    appended_mass: f64,
    appended_area: f64,
    /// The node columns y, ut, γ, φ, ψ.
    height: Cow<'a, [f64]>,
    accumulated_shear: Cow<'a, [f64]>,
    unit_weight: Cow<'a, [f64]>,
    friction: Cow<'a, [f64]>,
    dilation: Cow<'a, [f64]>,
    /// The search's seed and its count of evaluations.
    seed: Option<usize>,
    evaluations: u64,
}

impl Simulation {
    /// The simulation's state as bytes (docs/model.md §17):
    /// `Simulation::from_snapshot` restores it, and the restored simulation
    /// continues bit for bit as this one would.
    pub fn snapshot(&self) -> Vec<u8> {
        self.snapshot_with_note(&[])
    }

    /// `snapshot` with `note`, bytes the caller keeps with the state (the
    /// Python package keeps the case file's text there); the model does
    /// not read them.
    pub fn snapshot_with_note(&self, note: &[u8]) -> Vec<u8> {
        // Plain data into memory: serde's derive has no error to return.
        let body = postcard::to_allocvec(&self.body(note)).expect("a snapshot body serialises");
        let mut out = Vec::with_capacity(body.len() + 64);
        out.extend_from_slice(&MAGIC);
        out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        out.extend_from_slice(&(CRATE_VERSION.len() as u64).to_le_bytes());
        out.extend_from_slice(CRATE_VERSION.as_bytes());
        out.extend_from_slice(&(body.len() as u64).to_le_bytes());
        out.extend_from_slice(&body);
        let sum = crc32fast::hash(&out);
        out.extend_from_slice(&sum.to_le_bytes());
        out
    }

    /// Restores a simulation from `snapshot`'s bytes; an error names what
    /// is wrong (another version, truncated, corrupt, out of range).
    pub fn from_snapshot(bytes: &[u8]) -> Result<Simulation, SnapshotError> {
        Self::from_snapshot_with_note(bytes).map(|(sim, _)| sim)
    }

    /// `from_snapshot`, with the note given to `snapshot_with_note`.
    pub fn from_snapshot_with_note(bytes: &[u8]) -> Result<(Simulation, Vec<u8>), SnapshotError> {
        let body = decode(checked_body(bytes)?)?;
        let note = body.note.to_vec();
        Ok((Self::restore(body)?, note))
    }

    fn body<'a>(&'a self, note: &'a [u8]) -> Body<'a> {
        let (ground, side) = self.ground.body();
        Body {
            case: Cow::Borrowed(&self.case),
            note: Cow::Borrowed(note),
            done: self.done,
            steepest_climb: self.laws.steepest_climb,
            initial_mass: self.initial_mass,
            side: Cow::Borrowed(side),
            ground,
        }
    }

    /// The simulation a decoded body describes, once its numbers are
    /// finite and its state one that runs reach (`check_state`).
    fn restore(b: Body) -> Result<Simulation, SnapshotError> {
        let case = b
            .case
            .into_owned()
            .validated()
            .map_err(SnapshotError::Case)?;
        let initial_mass = finite("initial mass", b.initial_mass)?;
        let laws = laws_for(&case, b.steepest_climb)?;
        let side = side_heaps(&case, b.side.into_owned())?;
        let ground = b.ground.restore(&case, &laws, (b.done, side))?;
        Ok(Simulation {
            laws,
            case,
            ground,
            done: b.done,
            initial_mass,
            failed: None,
        })
    }
}

/// The laws of `case` made for a climb up to `climb`, which is no less
/// than the case's own (a steered run's laws only grow their climb).
fn laws_for(case: &Case, climb: f64) -> Result<Laws, SnapshotError> {
    let mut laws = Laws::new(case);
    let own = laws.steepest_climb;
    if finite("steepest climb", climb)? < own {
        return Err(SnapshotError::invalid(
            "steepest climb",
            format!("{climb} is below the steepest climb of the case's path, {own}"),
        ));
    }
    if climb > own {
        laws.climbing(case, climb);
    }
    Ok(laws)
}

impl Discretised {
    /// The ground's state as a snapshot holds it, and its side heaps.
    fn body(&self) -> (GroundBody<'_>, &SideHeaps) {
        match self {
            Discretised::Nodes(grid) => (GroundBody::Nodes(NodeBody::of(grid)), &grid.side),
            Discretised::Vertices(cutting) => (
                GroundBody::Vertices(Cow::Borrowed(cutting.ground()), cutting.evaluations()),
                cutting.side_heaps(),
            ),
        }
    }
}

impl GroundBody<'_> {
    /// The ground of `case` after `done` increments beside `side`: of the
    /// kind the case's `run.ground` says, and one that runs make.
    fn restore(
        self,
        case: &Case,
        laws: &Laws,
        (done, side): (usize, SideHeaps),
    ) -> Result<Discretised, SnapshotError> {
        match (self, case.run.ground) {
            (GroundBody::Vertices(ground, evaluations), Ground::Vertices(keys)) => {
                let ground = ground.into_owned();
                if let Some(defect) = ground.defect() {
                    return Err(SnapshotError::invalid("vertex ground", defect));
                }
                let cutting = Cutting::resumed(case, keys, (ground, side), evaluations);
                Ok(Discretised::Vertices(Box::new(cutting)))
            }
            (GroundBody::Nodes(nodes), Ground::Nodes) => Ok(Discretised::Nodes(Box::new(
                nodes.restore(case, laws, (done, side))?,
            ))),
            (body, choice) => Err(SnapshotError::invalid(
                "ground",
                format!(
                    "{} where the case's run.ground = \"{}\" says otherwise",
                    match body {
                        GroundBody::Vertices(..) => "vertices",
                        GroundBody::Nodes(_) => "nodes",
                    },
                    choice.name()
                ),
            )),
        }
    }
}

impl<'a> NodeBody<'a> {
    fn of(grid: &'a NodeGrid) -> Self {
        let s = &grid.surface;
        NodeBody {
            floor: s.floor,
            pristine_from: s.pristine_from,
            trench_mass: s.trench_mass,
            appended_mass: s.appended_mass,
            appended_area: s.appended_area,
            height: Cow::Borrowed(&s.height),
            accumulated_shear: Cow::Borrowed(&s.accumulated_shear),
            unit_weight: Cow::Borrowed(&s.unit_weight),
            friction: Cow::Borrowed(&s.friction),
            dilation: Cow::Borrowed(&s.dilation),
            seed: grid.search.previous(),
            evaluations: grid.search.evaluations,
        }
    }

    /// The node grid of `case` after `done` increments beside `side`, once
    /// the numbers are finite and the state one that runs reach
    /// (`check_state`).
    fn restore(
        self,
        case: &Case,
        laws: &Laws,
        (done, side): (usize, SideHeaps),
    ) -> Result<NodeGrid, SnapshotError> {
        let floor = finite("surface floor", self.floor)?;
        let column = |what, v: Cow<[f64]>| finite_all(what, v.into_owned());
        let height = column("surface heights", self.height)?;
        let accumulated_shear = column("accumulated shear", self.accumulated_shear)?;
        let unit_weight = column("unit weights", self.unit_weight)?;
        let friction = column("friction angles", self.friction)?;
        let dilation = column("dilation angles", self.dilation)?;
        // The face follows from the increments done: one node each.
        let face = FaceNode { node: done };
        check_state(&StateCheck {
            case,
            n: height.len(),
            lengths: [&accumulated_shear, &unit_weight, &friction, &dilation].map(Vec::len),
            face: face.node,
            floor,
            pristine_from: self.pristine_from,
            seed: self.seed,
            side: &side,
            unit_weight: &unit_weight,
        })?;
        let mut s = Surface::flat(
            case.run.increment,
            -floor,
            case.soil.unit_weight,
            fresh_angles(laws),
            0,
        );
        s.face = face;
        s.pristine_from = self.pristine_from;
        s.trench_mass = finite("trench mass", self.trench_mass)?;
        s.appended_mass = finite("appended mass", self.appended_mass)?;
        s.appended_area = finite("appended area", self.appended_area)?;
        s.height = height;
        s.accumulated_shear = accumulated_shear;
        s.unit_weight = unit_weight;
        s.friction = friction;
        s.dilation = dilation;
        let mut grid = NodeGrid::on(case, s);
        grid.search = Search::resumed(self.seed, self.evaluations);
        grid.side = side;
        Ok(grid)
    }
}

/// The side heaps of a restored snapshot, once their numbers are finite
/// and their columns of one length, and none without a blade width.
fn side_heaps(case: &Case, side: SideHeaps) -> Result<SideHeaps, SnapshotError> {
    let side = SideHeaps {
        spilled: finite("mass spilled", side.spilled)?,
        area: finite_all("side heaps", side.area)?,
        height: finite_all("side heaps", side.height)?,
        unit_weight: finite_all("side heaps", side.unit_weight)?,
    };
    check_side_heaps(case, &side)?;
    Ok(side)
}

/// The body from its postcard bytes, all of them.
fn decode(bytes: &[u8]) -> Result<Body<'static>, SnapshotError> {
    match postcard::take_from_bytes::<Body>(bytes) {
        Ok((body, [])) => Ok(body),
        Ok((_, rest)) => Err(SnapshotError::invalid(
            "body",
            format!("{} bytes left over after the state", rest.len()),
        )),
        Err(postcard::Error::DeserializeUnexpectedEnd) => {
            Err(SnapshotError::Truncated { what: "the body" })
        }
        Err(e) => Err(SnapshotError::invalid("body", e.to_string())),
    }
}

/// The header's fields in order; a short input names what it ends inside.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Cursor<'a> {
    fn remaining(&self) -> usize {
        self.bytes.len() - self.at
    }

    fn take(&mut self, n: usize, what: &'static str) -> Result<&'a [u8], SnapshotError> {
        if self.remaining() < n {
            return Err(SnapshotError::Truncated { what });
        }
        self.at += n;
        Ok(&self.bytes[self.at - n..self.at])
    }

    fn array<const N: usize>(&mut self, what: &'static str) -> Result<[u8; N], SnapshotError> {
        let mut out = [0; N];
        out.copy_from_slice(self.take(N, what)?);
        Ok(out)
    }

    /// Bytes behind a u64 length, checked against the bytes left before
    /// anything is read (a corrupt length must not reach past the end).
    fn counted(&mut self, what: &'static str) -> Result<&'a [u8], SnapshotError> {
        let n = u64::from_le_bytes(self.array(what)?);
        match usize::try_from(n) {
            Ok(n) if n <= self.remaining() => self.take(n, what),
            _ => Err(SnapshotError::Truncated { what }),
        }
    }
}

/// The header checked (magic, versions, length, checksum); the body.
fn checked_body(bytes: &[u8]) -> Result<&[u8], SnapshotError> {
    if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
        return Err(SnapshotError::NotASnapshot);
    }
    let mut r = Cursor {
        bytes,
        at: MAGIC.len(),
    };
    let format = u32::from_le_bytes(r.array("the format version")?);
    if format != FORMAT_VERSION {
        return Err(SnapshotError::Version {
            format,
            crate_version: String::new(),
        });
    }
    let version = std::str::from_utf8(r.counted("the crate version")?)
        .map_err(|_| SnapshotError::invalid("the crate version", "not UTF-8 text".to_string()))?;
    if version != CRATE_VERSION {
        // Escaped: the bytes of a snapshot from elsewhere may hold control
        // characters, a NUL among them, which the C ABI's message would
        // end at (found by fuzzing ffi_calls).
        return Err(SnapshotError::Version {
            format,
            crate_version: version.escape_debug().to_string(),
        });
    }
    let body = r.counted("the body")?;
    let end = r.at;
    let sum = u32::from_le_bytes(r.array("the checksum")?);
    if r.remaining() > 0 {
        return Err(SnapshotError::TrailingBytes {
            count: r.remaining(),
        });
    }
    if crc32fast::hash(&bytes[..end]) != sum {
        return Err(SnapshotError::Corrupt);
    }
    Ok(body)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sim() -> Simulation {
        let mut sim = Simulation::new(&crate::common::original(0.5, 40.0)).unwrap();
        for _ in 0..4 {
            sim.step().unwrap();
        }
        sim
    }

    /// The error of restoring `sim` after `spoil` (a state no run reaches,
    /// under a valid checksum).
    fn restored(spoil: impl FnOnce(&mut Simulation)) -> SnapshotError {
        let mut s = sim();
        spoil(&mut s);
        Simulation::from_snapshot(&s.snapshot()).unwrap_err()
    }

    /// The node grid `sim` runs on.
    fn nodes(sim: &mut Simulation) -> &mut NodeGrid {
        match &mut sim.ground {
            Discretised::Nodes(grid) => grid,
            Discretised::Vertices(_) => panic!("a case on the node grid"),
        }
    }

    fn about(e: SnapshotError) -> &'static str {
        match e {
            SnapshotError::Invalid { what, .. } => what,
            SnapshotError::Case(_) => "case",
            other => panic!("{other}"),
        }
    }

    #[test]
    fn states_no_run_reaches_are_refused_by_name() {
        let e = restored(|s| nodes(s).surface.height.truncate(3));
        assert_eq!(about(e), "surface");
        let e = restored(|s| nodes(s).surface.friction.push(0.5));
        assert_eq!(about(e), "surface");
        let e = restored(|s| s.done = 10_000);
        assert_eq!(about(e), "increments done");
        let e = restored(|s| nodes(s).surface.height[3] = f64::NAN);
        assert_eq!(about(e), "surface heights");
        let e = restored(|s| nodes(s).surface.unit_weight[5] = 0.0);
        assert_eq!(about(e), "unit weights");
        let e = restored(|s| nodes(s).surface.floor = -1.0);
        assert_eq!(about(e), "surface floor");
        let e = restored(|s| nodes(s).search = Search::resumed(Some(1 << 40), 0));
        assert_eq!(about(e), "search seed");
        let e = restored(|s| nodes(s).side.area = vec![0.0; 3]);
        assert_eq!(about(e), "side heaps");
        let e = restored(|s| s.case.edit().soil.unit_weight = -1.0);
        assert_eq!(about(e), "case");
        // Bounds made for less than the case's own climb would not bound.
        let e = restored(|s| s.laws.steepest_climb = -0.5);
        assert_eq!(about(e), "steepest climb");
        let e = restored(|s| s.laws.steepest_climb = f64::NAN);
        assert_eq!(about(e), "steepest climb");
    }
}
