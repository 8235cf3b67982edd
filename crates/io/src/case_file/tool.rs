//! `[tool]`: a tool of any shape on any motion (docs/model.md §21) as
//! written, and as `case.resolved.toml` writes it back (the pivot filled
//! in). Each shape has its own keys; a key of another shape is refused
//! naming it. The model says which tools its mechanism takes
//! (`Tool::straight_cut`, (M55)).

use crate::error::InputError;
use serde::{Deserialize, Serialize};
use soilcut_model::tool::{Motion, Shape, Tool};
use soilcut_model::{Case, CaseError};

/// `tool.shape`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    expecting = "\"straight\", \"curved\", \"bucket\" or \"points\""
)]
enum ShapeName {
    Straight,
    Curved,
    Bucket,
    Points,
}

impl ShapeName {
    fn word(self) -> &'static str {
        match self {
            ShapeName::Straight => "straight",
            ShapeName::Curved => "curved",
            ShapeName::Bucket => "bucket",
            ShapeName::Points => "points",
        }
    }

    /// The keys of the shape, beside `shape`, `pivot` and `motion`.
    fn keys(self) -> &'static [&'static str] {
        match self {
            ShapeName::Straight => &["rake", "height"],
            ShapeName::Curved => &["edge_angle", "radius", "sweep"],
            ShapeName::Bucket => &["floor", "back_radius", "back_sweep"],
            ShapeName::Points => &["points"],
        }
    }
}

/// `[tool]` as written; also its form in `case.resolved.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a table { shape, rake, height, edge_angle, radius, sweep, floor, back_radius, back_sweep, points, pivot, motion }"
)]
pub(super) struct ToolFile {
    shape: ShapeName,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    rake: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    height: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    edge_angle: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    sweep: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    floor: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    back_radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    back_sweep: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    points: Option<Vec<[f64; 2]>>,
    #[serde(default)]
    pivot: Option<[f64; 2]>,
    motion: Vec<[f64; 4]>,
}

impl ToolFile {
    /// The tool, its defaults written in (a straight face's rake 90°, a
    /// bucket's back wall a semicircle, the pivot at the cutting edge).
    pub(super) fn tool(&mut self) -> Result<Tool, InputError> {
        self.check_keys()?;
        let shape = match self.shape {
            ShapeName::Straight => Shape::Straight {
                rake: *self.rake.get_or_insert(90.0),
                height: required(self.height, "height", self.shape)?,
            },
            ShapeName::Curved => Shape::Curved {
                edge_angle: required(self.edge_angle, "edge_angle", self.shape)?,
                radius: required(self.radius, "radius", self.shape)?,
                sweep: required(self.sweep, "sweep", self.shape)?,
            },
            ShapeName::Bucket => Shape::Bucket {
                floor: required(self.floor, "floor", self.shape)?,
                back_radius: required(self.back_radius, "back_radius", self.shape)?,
                back_sweep: *self.back_sweep.get_or_insert(180.0),
            },
            ShapeName::Points => Shape::Points(
                self.points
                    .clone()
                    .ok_or_else(|| missing("points", self.shape))?,
            ),
        };
        shape.profile()?;
        let pivot = *self.pivot.get_or_insert([0.0, 0.0]);
        if !pivot.iter().all(|c| c.is_finite()) {
            return Err(
                CaseError::new("tool.pivot", format!("must be finite (got {pivot:?})")).into(),
            );
        }
        Ok(Tool {
            shape,
            pivot,
            motion: Motion::new(&self.motion, "tool.motion")?,
        })
    }

    /// The motion of the tool as its blade was steered (M55): a pose where
    /// the steered depth path has a point and at the travel, each the
    /// cutting edge's place plus the pivot's offset, at the tool's rotation.
    pub(super) fn steer(&mut self, case: &Case) {
        let travel = case.run.travel;
        let inner = case.blade.depth_path.iter().map(|p| p[0]);
        let mut at: Vec<f64> = std::iter::once(0.0)
            .chain(inner.filter(|&u| u > 0.0 && u < travel))
            .chain(std::iter::once(travel))
            .collect();
        at.dedup();
        let [dx, dy] = case.blade.pivot;
        self.motion = at
            .into_iter()
            .map(|u| [u, u + dx, -case.tip_depth(u) + dy, case.blade.rotation])
            .collect();
    }

    /// The tool in a few words: its shape, pivot and poses.
    pub(super) fn describe(&self) -> String {
        let last = self.motion.last().map_or(0.0, |row| row[0]);
        format!(
            "tool: a {} profile, pivot {:?}, {} poses over s = 0 to {last}",
            self.shape.word(),
            self.pivot.unwrap_or([0.0, 0.0]),
            self.motion.len()
        )
    }

    /// Refuses a key of another shape, naming it and its shape.
    fn check_keys(&self) -> Result<(), InputError> {
        let given = [
            ("rake", self.rake.is_some()),
            ("height", self.height.is_some()),
            ("edge_angle", self.edge_angle.is_some()),
            ("radius", self.radius.is_some()),
            ("sweep", self.sweep.is_some()),
            ("floor", self.floor.is_some()),
            ("back_radius", self.back_radius.is_some()),
            ("back_sweep", self.back_sweep.is_some()),
            ("points", self.points.is_some()),
        ];
        let own = self.shape.keys();
        match given.iter().find(|(key, is)| *is && !own.contains(key)) {
            Some((key, _)) => Err(CaseError::new(
                &format!("tool.{key}"),
                format!(
                    "is not a key of tool.shape = \"{}\" (its keys: {})",
                    self.shape.word(),
                    own.join(", ")
                ),
            )
            .into()),
            None => Ok(()),
        }
    }
}

fn missing(key: &str, shape: ShapeName) -> InputError {
    CaseError::new(
        &format!("tool.{key}"),
        format!(
            "required key is missing for tool.shape = \"{}\"",
            shape.word()
        ),
    )
    .into()
}

fn required(value: Option<f64>, key: &str, shape: ShapeName) -> Result<f64, InputError> {
    value.ok_or_else(|| missing(key, shape))
}
