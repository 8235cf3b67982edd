//! `[run]`: how far, in what increments, on which ground. The keys as
//! written, the forms of earlier versions read with a notice, and the
//! resolved run written back; the defaults are the model's (`Run::resolve`).

use crate::error::InputError;
use serde::{Deserialize, Serialize};
use soilcut_model::{CaseError, Class, Ground, GroundKind, Run, RunKeys, TimeScheme};

/// `run.ground`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", expecting = "\"vertices\" or \"nodes\"")]
enum GroundName {
    Vertices,
    Nodes,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    expecting = "\"explicit\" or \"midpoint-force\""
)]
enum TimeSchemeName {
    Explicit,
    MidpointForce,
}

impl TimeSchemeName {
    fn of(scheme: TimeScheme) -> Self {
        match scheme {
            TimeScheme::Explicit => TimeSchemeName::Explicit,
            TimeScheme::MidpointForce => TimeSchemeName::MidpointForce,
        }
    }

    fn scheme(self) -> TimeScheme {
        match self {
            TimeSchemeName::Explicit => TimeScheme::Explicit,
            TimeSchemeName::MidpointForce => TimeScheme::MidpointForce,
        }
    }
}

/// `[run]` as written; also its form in `case.resolved.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a table { travel, increment, ground, vertex_spacing, samples_per_band, time_scheme, merge_tolerance }"
)]
pub(super) struct RunFile {
    /// Absent where a tool's motion gives the travel (`[tool]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) travel: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) increment: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ground: Option<GroundName>,
    #[serde(skip_serializing_if = "Option::is_none")]
    vertex_spacing: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    samples_per_band: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    time_scheme: Option<TimeSchemeName>,
    #[serde(skip_serializing_if = "Option::is_none")]
    merge_tolerance: Option<f64>,
    /// The coarse node grid's spacing, gone: read only to say what to
    /// write instead, never written.
    #[serde(default, skip_serializing)]
    node_spacing: Option<f64>,
}

impl RunFile {
    /// The run this file describes for a case of `class`, the resolved
    /// keys written back into it, and the notices of any form of an
    /// earlier version it was read in; `tool_travel` is the travel a
    /// tool's motion gives, which `run.travel` may shorten.
    pub(super) fn resolve(
        &mut self,
        class: Class<'_>,
        tool_travel: Option<f64>,
    ) -> Result<(Run, Vec<String>), InputError> {
        let travel = travel_of(self.travel, tool_travel)?;
        let mut notices = Vec::new();
        if self.ground.is_none() && self.vertex_spacing == Some(0.0) {
            notices.push(
                "run.vertex_spacing = 0 is the old way to choose the node grid: write \
                 run.ground = \"nodes\" instead (this case runs on the node grid)"
                    .to_string(),
            );
            self.read_old_node_grid();
        }
        let run = Run::resolve(&self.keys(travel), class)?;
        if let Some(h) = self.node_spacing.take() {
            notices.push(self.old_node_spacing(h, &run)?);
        }
        self.write(&run);
        Ok((run, notices))
    }

    /// A file of the node grid as earlier versions wrote it
    /// (`run.vertex_spacing = 0`): the keys the vertex ground alone has
    /// now are dropped where they held the node grid's only value.
    fn read_old_node_grid(&mut self) {
        self.ground = Some(GroundName::Nodes);
        self.vertex_spacing = None;
        if self.time_scheme == Some(TimeSchemeName::Explicit) {
            self.time_scheme = None;
        }
        if self.merge_tolerance == Some(0.0) {
            self.merge_tolerance = None;
        }
        if self.samples_per_band == Some(0.0) {
            self.samples_per_band = None;
        }
    }

    /// The notice for an earlier version's `run.node_spacing = h`, which
    /// only a node grid of nodes every increment still runs as written.
    fn old_node_spacing(&self, h: f64, run: &Run) -> Result<String, InputError> {
        let v0 = run.increment;
        if run.ground == Ground::Nodes && (h - v0).abs() <= 1e-9 * v0 {
            return Ok(format!(
                "run.node_spacing = {h} is no longer a key: the node grid has nodes every \
                 run.increment; remove it"
            ));
        }
        Err(CaseError::new(
            "run.node_spacing",
            format!(
                "is no longer a key (got {h}): the node grid (run.ground = \"nodes\") has \
                 nodes every run.increment, and the coarse grid is gone; remove it, and write \
                 run.ground = \"nodes\" to run on the node grid"
            ),
        )
        .into())
    }

    fn keys(&self, travel: f64) -> RunKeys {
        RunKeys {
            travel,
            increment: self.increment,
            ground: self.ground.map(|g| match g {
                GroundName::Vertices => GroundKind::Vertices,
                GroundName::Nodes => GroundKind::Nodes,
            }),
            vertex_spacing: self.vertex_spacing,
            samples_per_band: self.samples_per_band,
            time_scheme: self.time_scheme.map(TimeSchemeName::scheme),
            merge_tolerance: self.merge_tolerance,
        }
    }

    /// Every key of `run` in the file, as `case.resolved.toml` writes it.
    fn write(&mut self, run: &Run) {
        self.increment = Some(run.increment);
        match &run.ground {
            Ground::Vertices(v) => {
                self.ground = Some(GroundName::Vertices);
                self.vertex_spacing = Some(v.spacing);
                self.samples_per_band = Some(v.samples_per_band);
                self.time_scheme = Some(TimeSchemeName::of(v.time_scheme));
                self.merge_tolerance = Some(v.merge_tolerance);
            }
            Ground::Nodes => self.ground = Some(GroundName::Nodes),
        }
    }
}

/// The run's travel: `run.travel`, or the last s of a tool's motion
/// (`tool_travel`), which `run.travel` may shorten but not exceed.
fn travel_of(given: Option<f64>, tool_travel: Option<f64>) -> Result<f64, InputError> {
    match (given, tool_travel) {
        (Some(travel), None) | (None, Some(travel)) => Ok(travel),
        (None, None) => Err(CaseError::new("run.travel", "required key is missing").into()),
        (Some(travel), Some(last)) if travel <= last => Ok(travel),
        (Some(travel), Some(last)) => Err(CaseError::new(
            "run.travel",
            format!(
                "must be at most the last s of tool.motion, {last}, in a case with a tool (got \
                 {travel}): the motion ends there; leave run.travel out to run all of it"
            ),
        )
        .into()),
    }
}
