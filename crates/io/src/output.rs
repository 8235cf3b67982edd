//! Output files of a run and their atomic placement.
//!
//! Floats are written with Rust's `{}` (shortest round-trip), so the same
//! case gives bit-identical `history.csv` and `profile.csv`.

use crate::baselines::{baselines, Baselines};
use crate::case_file::LoadedCase;
use crate::columns::Columns;
use crate::error::{OutputError, RunFilesError};
use crate::history::history_columns;
use serde::Serialize;
use soilcut_model::summary::{
    sheared_fraction, JUMP_DEPTHS, PEAK_PROMINENCE, SHEARED_REACH_DEPTHS, SHEARED_THRESHOLD,
};
use soilcut_model::{ProfilePoint, StepError, StepRecord, Summary};
use std::fs;
use std::path::{Path, PathBuf};

/// Columns of `profile.csv`, in order.
pub const PROFILE_HEADER: &str = "x,y,accumulated_shear,unit_weight,ridge_height";

/// Everything a finished run writes.
pub struct RunOutput<'a> {
    /// The case as read, for `case.resolved.toml` and the summary.
    pub loaded: &'a LoadedCase,
    /// One record per increment.
    pub history: &'a [StepRecord],
    /// The final surface, from the face on.
    pub profile: &'a [ProfilePoint],
    /// Figures of the run.
    pub summary: &'a Summary,
    /// Candidate mechanisms evaluated (cost measure).
    pub candidate_evaluations: u64,
    /// Time spent in the simulation, seconds.
    pub wall_time_s: f64,
    /// Why the run stopped before its end, if it did: `history` then holds
    /// the increments before the one that failed.
    pub stopped: Option<&'a StepError>,
}

impl RunOutput<'_> {
    /// (file name, contents) of every output file.
    pub fn files(&self) -> Vec<(&'static str, String)> {
        let history = history_columns(self.history);
        self.files_of(
            &history,
            &profile_columns(self.profile),
            &self.summary_doc(),
        )
    }

    /// The numbers of the run's files (with `frames`, the numbers of
    /// `frames.csv`) and the files written from them, each figure computed
    /// once: [`RunOutput::files`], then `frames.csv`.
    pub fn tables_and_files(&self, frames: Columns) -> (RunTables, Vec<(&'static str, String)>) {
        let doc = self.summary_doc();
        let history = history_columns(self.history);
        let profile = profile_columns(self.profile);
        let mut files = self.files_of(&history, &profile, &doc);
        files.push(("frames.csv", frames.csv()));
        let summary = serde_json::to_value(doc).expect("a summary serialises");
        let tables = RunTables {
            history,
            profile,
            frames,
            summary,
        };
        (tables, files)
    }

    fn files_of(
        &self,
        history: &Columns,
        profile: &Columns,
        doc: &SummaryJson<'_>,
    ) -> Vec<(&'static str, String)> {
        let mut summary = serde_json::to_string_pretty(doc).expect("a summary serialises");
        summary.push('\n');
        vec![
            ("history.csv", history.csv()),
            ("profile.csv", profile.csv()),
            ("summary.json", summary),
            ("case.resolved.toml", self.loaded.resolved_toml()),
        ]
    }

    fn summary_doc(&self) -> SummaryJson<'_> {
        let case = &self.loaded.case;
        let s = self.summary;
        SummaryJson {
            name: &case.name,
            title: &case.title,
            model: case.model.name(),
            initial_force_norm: s.initial_force_norm,
            max_force_norm: s.max_force_norm,
            u_over_d_at_max: s.u_over_d_at_max,
            final_force_norm: s.final_force_norm,
            peaks: s
                .peaks
                .iter()
                .map(|p| PeakJson {
                    u_over_d: p.u_over_d,
                    force_norm: p.force_norm,
                })
                .collect(),
            peak_prominence_rule: peak_prominence_rule(),
            mass_drift_rel: s.mass_drift_rel,
            band_jumps: s.band_jumps.len(),
            band_jump_rule: band_jump_rule(),
            sheared_fraction: sheared_fraction(case, self.profile),
            sheared_fraction_rule: sheared_fraction_rule(),
            dilation_area: s.dilation_area,
            simulated_initial_force: self.history.first().map_or(f64::NAN, |r| r.force),
            baselines: baselines(case),
            steps: s.steps,
            candidate_evaluations: self.candidate_evaluations,
            wall_time_s: self.wall_time_s,
            stopped: self.stopped.map(|e| StoppedJson::new(e, case.blade.depth)),
        }
    }
}

/// The numbers of a run's files, for front ends that hand out values
/// rather than text: each file is written from these, so they are the
/// file's numbers exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct RunTables {
    /// `history.csv`.
    pub history: Columns,
    /// `profile.csv`.
    pub profile: Columns,
    /// `frames.csv`.
    pub frames: Columns,
    /// `summary.json` (objects' keys sorted; numbers that are not finite
    /// are `null`, as in the file).
    pub summary: serde_json::Value,
}

impl RunTables {
    /// The numbers of a run's files read back from their text (`files`:
    /// (name, contents), as [`RecordedRun::files`](crate::RecordedRun::files)): the same values the
    /// run wrote them from.
    pub fn from_files<S: AsRef<str>>(files: &[(S, String)]) -> Result<RunTables, RunFilesError> {
        let text = |name: &str| {
            files
                .iter()
                .find(|(n, _)| n.as_ref() == name)
                .map(|(_, t)| t.as_str())
                .ok_or_else(|| RunFilesError::new(Path::new(name), "the file is missing"))
        };
        // float_roundtrip (Cargo.toml): the parse gives back the bits written.
        let summary = serde_json::from_str(text("summary.json")?)
            .map_err(|e| RunFilesError::new(Path::new("summary.json"), e))?;
        Ok(RunTables {
            history: Columns::parse("history.csv", text("history.csv")?)?,
            profile: Columns::parse("profile.csv", text("profile.csv")?)?,
            frames: Columns::parse("frames.csv", text("frames.csv")?)?,
            summary,
        })
    }
}

/// The numbers of `profile.csv` (columns [`PROFILE_HEADER`]): one row per
/// node of the surface.
pub fn profile_columns(profile: &[ProfilePoint]) -> Columns {
    let mut out = Columns::new(PROFILE_HEADER);
    for p in profile {
        out.push(&[p.x, p.y, p.accumulated_shear, p.unit_weight, p.ridge_height]);
    }
    out
}

/// The rule by which `summary.json` lists peaks, in words.
pub fn peak_prominence_rule() -> String {
    format!(
        "a peak is an interior local maximum of force_norm whose topographic prominence is at least {PEAK_PROMINENCE} (fraction) of max_force_norm ({}% of the largest force)",
        PEAK_PROMINENCE * 100.0
    )
}

/// The rule by which `summary.json` counts band jumps, in words.
pub fn band_jump_rule() -> String {
    format!(
        "an increment whose emergence point lies more than {JUMP_DEPTHS} d from the previous one"
    )
}

/// The rule of `sheared_fraction`, in words.
pub fn sheared_fraction_rule() -> String {
    format!(
        "fraction of the surface's length within {SHEARED_REACH_DEPTHS} d ahead of the blade's final position whose accumulated shear exceeds {SHEARED_THRESHOLD} ur"
    )
}

#[derive(Serialize)]
struct SummaryJson<'a> {
    name: &'a str,
    title: &'a str,
    model: &'a str,
    initial_force_norm: f64,
    max_force_norm: f64,
    u_over_d_at_max: f64,
    final_force_norm: f64,
    peaks: Vec<PeakJson>,
    peak_prominence_rule: String,
    mass_drift_rel: f64,
    band_jumps: usize,
    band_jump_rule: String,
    sheared_fraction: f64,
    sheared_fraction_rule: String,
    dilation_area: f64,
    simulated_initial_force: f64,
    baselines: Baselines,
    steps: usize,
    candidate_evaluations: u64,
    wall_time_s: f64,
    // Only in the summary of a run that stopped: a finished run's file is
    // as it was before runs could stop and keep their files.
    #[serde(skip_serializing_if = "Option::is_none")]
    stopped: Option<StoppedJson>,
}

/// Where and why a run stopped before its end.
#[derive(Serialize)]
struct StoppedJson {
    /// The increment that failed (from 1); `steps` were made before it.
    increment: usize,
    /// u/d at the start of that increment.
    u_over_d: f64,
    reason: String,
}

impl StoppedJson {
    fn new(e: &StepError, depth: f64) -> Self {
        let (increment, u) = match *e {
            StepError::NoAdmissibleMechanism { step, u }
            | StepError::NoMechanismBeforeWall { step, u, .. } => (step, u),
            StepError::TravelReached { steps } => (steps + 1, f64::NAN),
        };
        StoppedJson {
            increment,
            u_over_d: u / depth,
            reason: e.to_string(),
        }
    }
}

#[derive(Serialize)]
struct PeakJson {
    u_over_d: f64,
    force_norm: f64,
}

/// The file by which soilcut knows an output folder as its own: every
/// folder it writes holds it, and `force` replaces no folder without it,
/// so that a mistyped `--out` never deletes the user's files.
pub const OUTPUT_MARKER: &str = ".soilcut";

/// What [`OUTPUT_MARKER`] says to a person who finds it.
fn marker_text() -> String {
    format!(
        "Written by soilcut {}. soilcut's --force (force=True in Python) replaces only folders holding this file.\n",
        env!("CARGO_PKG_VERSION")
    )
}

/// Whether `dir` is free for outputs: absent or an empty folder, or, with
/// `force`, a folder soilcut wrote (holding [`OUTPUT_MARKER`]). Reads only.
pub fn check_output_dir(dir: &Path, force: bool) -> Result<(), OutputError> {
    let err = |make: fn(PathBuf) -> OutputError| Err(make(dir.to_path_buf()));
    if dir.symlink_metadata().is_ok() && !dir.is_dir() {
        err(OutputError::NotAFolder)
    } else if !occupied(dir)? {
        Ok(())
    } else if !force {
        err(OutputError::Exists)
    } else if dir.file_name().is_none() {
        err(OutputError::Unnamed)
    } else if !dir.join(OUTPUT_MARKER).is_file() {
        err(OutputError::NotOurs)
    } else {
        Ok(())
    }
}

fn occupied(dir: &Path) -> Result<bool, OutputError> {
    match fs::read_dir(dir) {
        Ok(mut entries) => Ok(entries.next().is_some()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(false),
        Err(_) => Ok(dir.symlink_metadata().is_ok()),
    }
}

/// Writes `files` into `dir` atomically: into a temporary sibling folder
/// that is renamed into place once complete and removed on any failure.
/// An occupied `dir` is refused unless `force`, which replaces it.
pub fn write_output_dir(
    dir: &Path,
    files: &[(&str, String)],
    force: bool,
) -> Result<(), OutputError> {
    write_output_dir_then(dir, files, force, |_| Ok(()))
}

/// [`write_output_dir`], calling `finish` with the staging folder once
/// `files` are in it and before it is renamed into place, so that files
/// made from them (pictures) appear together with them or not at all.
pub fn write_output_dir_then(
    dir: &Path,
    files: &[(&str, String)],
    force: bool,
    finish: impl FnOnce(&Path) -> Result<(), OutputError>,
) -> Result<(), OutputError> {
    check_output_dir(dir, force)?;
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&parent).map_err(OutputError::io(&parent))?;
    let staging = Staging::create(&parent, dir, "tmp")?;
    let marker = (OUTPUT_MARKER, marker_text());
    for (name, contents) in files.iter().chain([&marker]) {
        let path = staging.path.join(name);
        fs::write(&path, contents).map_err(OutputError::io(&path))?;
    }
    finish(&staging.path)?;
    staging.commit(dir)
}

/// A hidden sibling folder that is removed on drop unless committed.
struct Staging {
    path: PathBuf,
    committed: bool,
}

impl Staging {
    fn create(parent: &Path, dir: &Path, tag: &str) -> Result<Self, OutputError> {
        let base = dir
            .file_name()
            .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
        let pid = std::process::id();
        let mut attempt = 0u32;
        loop {
            let path = parent.join(format!(".{base}.{tag}-{pid}-{attempt}"));
            match fs::create_dir(&path) {
                Ok(()) => {
                    return Ok(Staging {
                        path,
                        committed: false,
                    })
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && attempt < 1000 => {
                    attempt += 1;
                }
                Err(e) => return Err(OutputError::io(path)(e)),
            }
        }
    }

    /// Renames the staged folder to `dir`, moving an existing `dir` aside
    /// first and deleting it only once the new one is in place.
    fn commit(mut self, dir: &Path) -> Result<(), OutputError> {
        let old = if dir.symlink_metadata().is_ok() {
            let parent = self.path.parent().expect("staging has a parent");
            let aside = Staging::create(parent, dir, "old")?;
            fs::remove_dir(&aside.path).map_err(OutputError::io(&aside.path))?;
            fs::rename(dir, &aside.path).map_err(OutputError::io(dir))?;
            Some(aside)
        } else {
            None
        };
        if let Err(e) = fs::rename(&self.path, dir) {
            if let Some(mut aside) = old {
                // Put the previous outputs back (or keep them aside if that
                // fails too); the new ones are dropped.
                aside.committed = fs::rename(&aside.path, dir).is_err();
            }
            return Err(OutputError::io(dir)(e));
        }
        self.committed = true;
        // `old` (the replaced outputs) is removed by its drop.
        drop(old);
        Ok(())
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        if !self.committed {
            let _ = if self.path.is_dir() {
                fs::remove_dir_all(&self.path)
            } else {
                fs::remove_file(&self.path)
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files() -> Vec<(&'static str, String)> {
        vec![("a.txt", "new".to_string())]
    }

    #[test]
    fn writes_and_refuses_to_overwrite() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("nested/out");
        write_output_dir(&dir, &files(), false).unwrap();
        assert_eq!(fs::read_to_string(dir.join("a.txt")).unwrap(), "new");
        let e = write_output_dir(&dir, &files(), false).unwrap_err();
        assert!(matches!(e, OutputError::Exists(_)));
        fs::write(dir.join("stale.txt"), "x").unwrap();
        write_output_dir(&dir, &files(), true).unwrap();
        assert!(!dir.join("stale.txt").exists(), "force replaces the folder");
        let leftovers: Vec<_> = fs::read_dir(dir.parent().unwrap()).unwrap().collect();
        assert_eq!(leftovers.len(), 1, "no staging folders left behind");
    }

    #[test]
    fn force_replaces_only_what_soilcut_wrote() {
        let tmp = tempfile::tempdir().unwrap();
        let file = tmp.path().join("notes.txt");
        fs::write(&file, "mine").unwrap();
        let foreign = tmp.path().join("mine");
        fs::create_dir(&foreign).unwrap();
        fs::write(foreign.join("notes.txt"), "mine").unwrap();
        for force in [false, true] {
            let e = write_output_dir(&file, &files(), force).unwrap_err();
            assert!(matches!(e, OutputError::NotAFolder(_)), "{e:?}");
            assert!(e.to_string().contains("not a folder"), "{e}");
        }
        let e = write_output_dir(&foreign, &files(), true).unwrap_err();
        assert!(matches!(e, OutputError::NotOurs(_)), "{e:?}");
        assert_eq!(fs::read_to_string(&file).unwrap(), "mine");
        assert_eq!(
            fs::read_to_string(foreign.join("notes.txt")).unwrap(),
            "mine"
        );
        let ours = tmp.path().join("ours");
        write_output_dir(&ours, &files(), false).unwrap();
        assert!(ours.join(OUTPUT_MARKER).is_file());
        write_output_dir(&ours, &files(), true).unwrap();
    }

    #[test]
    fn force_refuses_unnamed_folders() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("a");
        write_output_dir(&dir, &files(), false).unwrap();
        for unnamed in [dir.join(".."), PathBuf::from("/")] {
            let e = check_output_dir(&unnamed, true).unwrap_err();
            assert!(matches!(e, OutputError::Unnamed(_)), "{unnamed:?}");
        }
        assert!(check_output_dir(&dir.join("."), true).is_ok(), "a/. is a");
    }

    #[test]
    fn empty_folder_is_used() {
        let tmp = tempfile::tempdir().unwrap();
        write_output_dir(tmp.path(), &files(), false).unwrap();
        assert!(tmp.path().join("a.txt").exists());
    }

    #[test]
    fn failure_leaves_nothing() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("out");
        let bad = vec![
            ("a.txt", "x".to_string()),
            ("no/such/b.txt", "y".to_string()),
        ];
        assert!(matches!(
            write_output_dir(&dir, &bad, false),
            Err(OutputError::Io { .. })
        ));
        assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 0);
    }
}
