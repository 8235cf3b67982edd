//! Output files of a run (placed by `crate::place`).
//!
//! Floats are written with Rust's `{}` (shortest round-trip), so the same
//! case gives bit-identical `history.csv` and `profile.csv`.

use crate::baselines::{baselines, Baselines};
use crate::case_file::LoadedCase;
use crate::columns::Columns;
use crate::error::RunFilesError;
use crate::history::history_columns;
use serde::Serialize;
use soilcut_model::summary::{
    sheared_fraction, JUMP_DEPTHS, PEAK_PROMINENCE, SHEARED_REACH_DEPTHS, SHEARED_THRESHOLD,
};
use soilcut_model::{ProfilePoint, StepError, StepRecord, Summary};
use std::path::Path;

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
            warnings: case.accuracy_warnings(),
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
    /// What is known against the case's accuracy (`Case::accuracy_warnings`),
    /// as the front ends warn of it: in the file too, where no terminal
    /// kept them.
    warnings: Vec<String>,
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
            | StepError::NoMechanismBeforeWall { step, u, .. }
            | StepError::NotFinite { step, u, .. } => (step, u),
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
