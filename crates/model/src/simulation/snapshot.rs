//! Snapshots: a running simulation as bytes and back (docs/model.md §17).
//!
//! A snapshot holds everything that determines the rest of the run: the
//! case (as `advance_to` may have steered it), the surface's nodes and
//! counters, the search's seed (the previous increment's emergence node)
//! and evaluation count, the side heaps and the increments done. What the
//! case determines (the laws, the rake's grid, the node scheme, the face's
//! node, which follows from the increments done) is rebuilt from it; the
//! search's, kinematics' and avalanche's scratch is rebuilt empty, as each
//! increment fills it before use. So a restored simulation continues bit
//! for bit as the original would.
//!
//! Layout, little-endian: the magic `SOILCUT\x01`, the format version
//! (u32), the crate version (length-prefixed UTF-8), the body's length
//! (u64), the body, and a 64-bit checksum of all that precedes it. A
//! snapshot of another format or crate version is refused: the model's
//! numbers may differ between versions, so a state from one is no state of
//! the other.

use super::case_codec::{read_case, write_case};
use super::codec::{checksum, Reader, Writer};
use super::{fresh_angles, Simulation};
use crate::case::CaseError;
use crate::grid::FaceNode;
use crate::laws::Laws;
use crate::search::Search;
use crate::spill::SideHeaps;
use crate::surface::Surface;
use std::fmt;

/// The first bytes of every snapshot.
pub const MAGIC: [u8; 8] = *b"SOILCUT\x01";
/// The layout's version: raised whenever the body changes.
pub const FORMAT_VERSION: u32 = 1;
/// The crate version a snapshot must come from.
pub const CRATE_VERSION: &str = env!("CARGO_PKG_VERSION");

/// Why bytes are not a snapshot this build can restore.
#[derive(Clone, Debug, PartialEq)]
pub enum SnapshotError {
    /// The bytes do not start with `MAGIC`.
    NotASnapshot,
    /// A snapshot of another format or crate version.
    Version {
        /// Its format version.
        format: u32,
        /// Its crate version (empty if the format is unknown).
        crate_version: String,
    },
    /// The bytes end inside `what`.
    Truncated {
        /// What was being read.
        what: &'static str,
    },
    /// Bytes after the checksum.
    TrailingBytes {
        /// How many.
        count: usize,
    },
    /// The checksum does not match: the bytes were changed.
    Corrupt,
    /// A value out of its range (`what`: which, `message`: why).
    Invalid {
        /// The value.
        what: &'static str,
        /// What is wrong with it.
        message: String,
    },
    /// The case does not validate (`Case::validate`).
    Case(CaseError),
}

impl SnapshotError {
    pub(super) fn invalid(what: &'static str, message: String) -> Self {
        SnapshotError::Invalid { what, message }
    }
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::NotASnapshot => {
                write!(f, "not a soilcut snapshot (it does not start with the magic bytes)")
            }
            SnapshotError::Version {
                format,
                crate_version,
            } => write!(
                f,
                "a snapshot of another version (format {format}, soilcut {}): this is format {FORMAT_VERSION} of soilcut {CRATE_VERSION}, which restores only its own snapshots",
                if crate_version.is_empty() { "unknown" } else { crate_version }
            ),
            SnapshotError::Truncated { what } => {
                write!(f, "snapshot truncated: it ends inside {what}")
            }
            SnapshotError::TrailingBytes { count } => {
                write!(f, "snapshot has {count} bytes after its end")
            }
            SnapshotError::Corrupt => {
                write!(f, "snapshot corrupt: its checksum does not match its bytes")
            }
            SnapshotError::Invalid { what, message } => {
                write!(f, "snapshot invalid: {what}: {message}")
            }
            SnapshotError::Case(e) => write!(f, "snapshot's case invalid: {e}"),
        }
    }
}

impl std::error::Error for SnapshotError {}

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
        let mut w = Writer::default();
        w.0.extend_from_slice(&MAGIC);
        w.u32(FORMAT_VERSION);
        w.str(CRATE_VERSION);
        // The body's length, patched in once the body is written (no copy
        // of a body the size of the domain).
        let at = w.0.len();
        w.u64(0);
        write_case(&mut w, &self.case);
        w.bytes(note);
        self.write_state(&mut w);
        let length = (w.0.len() - at - 8) as u64;
        w.0[at..at + 8].copy_from_slice(&length.to_le_bytes());
        let sum = checksum(&w.0);
        w.u64(sum);
        w.0
    }

    /// Restores a simulation from `snapshot`'s bytes; an error names what
    /// is wrong (another version, truncated, corrupt, out of range).
    pub fn from_snapshot(bytes: &[u8]) -> Result<Simulation, SnapshotError> {
        Self::from_snapshot_with_note(bytes).map(|(sim, _)| sim)
    }

    /// `from_snapshot`, with the note given to `snapshot_with_note`.
    pub fn from_snapshot_with_note(bytes: &[u8]) -> Result<(Simulation, Vec<u8>), SnapshotError> {
        let body = checked_body(bytes)?;
        let mut r = Reader::new(body);
        let case = read_case(&mut r)?;
        case.validate().map_err(SnapshotError::Case)?;
        let note = r.bytes("note")?.to_vec();
        let sim = Self::read_state(&mut r, case)?;
        match r.remaining() {
            0 => Ok((sim, note)),
            count => Err(SnapshotError::invalid(
                "body",
                format!("{count} bytes left over after the state"),
            )),
        }
    }

    fn write_state(&self, w: &mut Writer) {
        w.usize(self.done);
        w.f64(self.initial_mass);
        let s = &self.surface;
        w.f64(s.floor);
        w.usize(s.pristine_from);
        w.f64(s.trench_mass);
        w.f64(s.appended_mass);
        w.f64(s.appended_area);
        for v in [
            &s.height,
            &s.accumulated_shear,
            &s.unit_weight,
            &s.friction,
            &s.dilation,
        ] {
            w.f64s(v);
        }
        let previous = self.search.previous();
        w.u8(previous.is_some() as u8);
        w.usize(previous.unwrap_or(0));
        w.u64(self.search.evaluations);
        let side = &self.side;
        w.f64(side.spilled);
        for v in [&side.area, &side.height, &side.unit_weight] {
            w.f64s(v);
        }
    }

    fn read_state(r: &mut Reader, case: crate::case::Case) -> Result<Simulation, SnapshotError> {
        let done = r.usize("increments done")?;
        let initial_mass = finite("initial mass", r.f64("initial mass")?)?;
        let floor = finite("surface floor", r.f64("surface floor")?)?;
        let pristine_from = r.usize("surface")?;
        let trench_mass = finite("trench mass", r.f64("surface")?)?;
        let appended_mass = finite("appended mass", r.f64("surface")?)?;
        let appended_area = finite("appended area", r.f64("surface")?)?;
        let mut column = |what| r.f64s(what).and_then(|v| finite_all(what, v));
        let height = column("surface heights")?;
        let accumulated_shear = column("accumulated shear")?;
        let unit_weight = column("unit weights")?;
        let friction = column("friction angles")?;
        let dilation = column("dilation angles")?;
        let previous = r.bool("search seed")?;
        let seed = r.usize("search seed")?;
        let evaluations = r.u64("evaluations")?;
        let mut side = SideHeaps::default();
        side.spilled = finite("mass spilled", r.f64("side heaps")?)?;
        side.area = finite_all("side heaps", r.f64s("side heaps")?)?;
        side.height = finite_all("side heaps", r.f64s("side heaps")?)?;
        side.unit_weight = finite_all("side heaps", r.f64s("side heaps")?)?;
        let k = case.increments_per_node();
        // The face follows from the increments done (`Scheme::face_after`).
        let face = FaceNode {
            node: done / k,
            offset: (done % k) as f64 / k as f64,
        };
        check_state(&StateCheck {
            case: &case,
            n: height.len(),
            lengths: [&accumulated_shear, &unit_weight, &friction, &dilation].map(Vec::len),
            face: face.node,
            floor,
            pristine_from,
            seed: previous.then_some(seed),
            side: &side,
            unit_weight: &unit_weight,
        })?;
        let laws = Laws::new(&case);
        let mut s = Surface::flat(
            Self::scheme(&case),
            -floor,
            case.soil.unit_weight,
            fresh_angles(&laws),
            0,
        );
        s.face = face;
        s.pristine_from = pristine_from;
        s.trench_mass = trench_mass;
        s.appended_mass = appended_mass;
        s.appended_area = appended_area;
        s.height = height;
        s.accumulated_shear = accumulated_shear;
        s.unit_weight = unit_weight;
        s.friction = friction;
        s.dilation = dilation;
        let mut sim = Simulation::assemble(case, laws, s, initial_mass);
        sim.search = Search::resumed(previous.then_some(seed), evaluations);
        sim.side = side;
        sim.done = done;
        Ok(sim)
    }
}

/// The header checked (magic, versions, length, checksum); the body.
fn checked_body(bytes: &[u8]) -> Result<&[u8], SnapshotError> {
    if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
        return Err(SnapshotError::NotASnapshot);
    }
    let mut r = Reader::new(&bytes[MAGIC.len()..]);
    let format = r.u32("the format version")?;
    if format != FORMAT_VERSION {
        return Err(SnapshotError::Version {
            format,
            crate_version: String::new(),
        });
    }
    let version = r.string("the crate version")?;
    if version != CRATE_VERSION {
        return Err(SnapshotError::Version {
            format,
            crate_version: version,
        });
    }
    let body = r.bytes("the body")?;
    let end = bytes.len() - r.remaining();
    let sum = r.u64("the checksum")?;
    if r.remaining() > 0 {
        return Err(SnapshotError::TrailingBytes {
            count: r.remaining(),
        });
    }
    if checksum(&bytes[..end]) != sum {
        return Err(SnapshotError::Corrupt);
    }
    Ok(body)
}

fn finite(what: &'static str, v: f64) -> Result<f64, SnapshotError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(SnapshotError::invalid(what, format!("{v} is not finite")))
    }
}

fn finite_all(what: &'static str, v: Vec<f64>) -> Result<Vec<f64>, SnapshotError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(SnapshotError::invalid(what, format!("{x} is not finite"))),
        None => Ok(v),
    }
}

/// What `check_state` looks at.
struct StateCheck<'a> {
    case: &'a crate::case::Case,
    /// Nodes of the surface.
    n: usize,
    /// Lengths of the other node columns.
    lengths: [usize; 4],
    face: usize,
    floor: f64,
    pristine_from: usize,
    seed: Option<usize>,
    side: &'a SideHeaps,
    unit_weight: &'a [f64],
}

/// The invariants every increment keeps, which the model indexes by: a
/// state that breaks one would not continue as any run does.
fn check_state(c: &StateCheck) -> Result<(), SnapshotError> {
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
    let side = c.side;
    let m = side.area.len();
    if side.height.len() != m || side.unit_weight.len() != m || m > n {
        return Err(SnapshotError::invalid(
            "side heaps",
            format!(
                "columns of {m}, {} and {} nodes for a surface of {n}",
                side.height.len(),
                side.unit_weight.len()
            ),
        ));
    }
    if c.case.blade.width.is_none() && (m > 0 || side.spilled != 0.0) {
        return Err(SnapshotError::invalid(
            "side heaps",
            "a blade without blade.width has none".to_string(),
        ));
    }
    Ok(())
}

#[cfg(test)]
#[path = "../../tests/common.rs"]
mod common;

#[cfg(test)]
mod tests {
    use super::*;

    fn sim() -> Simulation {
        let mut sim = Simulation::new(&super::common::original(0.5, 40.0)).unwrap();
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

    fn about(e: SnapshotError) -> &'static str {
        match e {
            SnapshotError::Invalid { what, .. } => what,
            SnapshotError::Case(_) => "case",
            other => panic!("{other}"),
        }
    }

    #[test]
    fn states_no_run_reaches_are_refused_by_name() {
        let e = restored(|s| s.surface.height.truncate(3));
        assert_eq!(about(e), "surface");
        let e = restored(|s| s.surface.friction.push(0.5));
        assert_eq!(about(e), "surface");
        let e = restored(|s| s.done = 10_000);
        assert_eq!(about(e), "increments done");
        let e = restored(|s| s.surface.height[3] = f64::NAN);
        assert_eq!(about(e), "surface heights");
        let e = restored(|s| s.surface.unit_weight[5] = 0.0);
        assert_eq!(about(e), "unit weights");
        let e = restored(|s| s.surface.floor = -1.0);
        assert_eq!(about(e), "surface floor");
        let e = restored(|s| s.search = Search::resumed(Some(1 << 40), 0));
        assert_eq!(about(e), "search seed");
        let e = restored(|s| s.side.area = vec![0.0; 3]);
        assert_eq!(about(e), "side heaps");
        let e = restored(|s| s.case.soil.unit_weight = -1.0);
        assert_eq!(about(e), "case");
    }
}
