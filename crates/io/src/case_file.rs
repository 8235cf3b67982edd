//! Case files: TOML in, a resolved and validated [`Case`] out.
//!
//! The key names are the public interface (see README.md). Unknown keys are
//! an error; keys of the refined model are an error in an original case.
//! Range checks are [`Case::validate`]'s; this module only checks what the
//! model never sees (the case name, `soil.d50`, `soil.band_width_d50`).

use crate::error::InputError;
use crate::overrides::Override;
use run::RunFile;
use serde::{Deserialize, Serialize};
use soilcut_model::tool::StraightCut;
use soilcut_model::{
    AngleLaw, BandAngleRule, BandShearRule, BandStrengthRule, Bin, Blade, Case, CaseError, Choices,
    Class, FaceFrictionRule, Model, SnapshotError, Soil, UnitWeightRule, ValidCase,
};
use std::path::Path;
use tool::ToolFile;

mod run;
mod tool;

const REFINED_ONLY: &str = "applies to model = \"refined\" only";
const REFINED_REQUIRED: &str = "required for model = \"refined\"";

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"original\" or \"refined\"")]
enum ModelName {
    Original,
    Refined,
}

/// The case file as written; also the form of `case.resolved.toml`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a case table")]
struct CaseFile {
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    title: Option<String>,
    model: ModelName,
    blade: BladeFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    tool: Option<ToolFile>,
    soil: SoilFile,
    run: RunFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    bin: Option<BinFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    choices: Option<ChoicesFile>,
}

/// `[bin]`: the soil bin's end wall (none: unbounded ground).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table { length }")]
struct BinFile {
    length: f64,
}

/// `[choices]`: variants of the open choices (docs/model.md §14); all but
/// `face_friction` are the refined model's only, and absent from an
/// original case.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a table { band_angles, band_shear, unit_weight, face_friction, band_strength }"
)]
struct ChoicesFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band_angles: Option<BandAnglesName>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band_shear: Option<BandShearName>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    unit_weight: Option<UnitWeightName>,
    #[serde(default)]
    face_friction: FaceFrictionName,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band_strength: Option<BandStrengthName>,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    expecting = "\"mean-of-angles\" or \"angle-of-mean-shear\""
)]
enum BandAnglesName {
    #[default]
    MeanOfAngles,
    AngleOfMeanShear,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    expecting = "\"footprint\", \"crossed-columns\" or \"crossed-columns-unfloored\""
)]
enum BandStrengthName {
    #[default]
    Footprint,
    CrossedColumns,
    CrossedColumnsUnfloored,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", expecting = "\"full\" or \"by-position\"")]
enum BandShearName {
    #[default]
    Full,
    ByPosition,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    expecting = "\"band-uniform\" or \"per-node-formula\""
)]
enum UnitWeightName {
    #[default]
    BandUniform,
    PerNodeFormula,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", expecting = "\"mobilised\" or \"sign\"")]
enum FaceFrictionName {
    #[default]
    Mobilised,
    Sign,
}

impl ChoicesFile {
    /// The original model's choices: `face_friction` only.
    fn original(&self) -> Result<Choices, InputError> {
        refined_only(self.band_angles.is_some(), "choices.band_angles")?;
        refined_only(self.band_shear.is_some(), "choices.band_shear")?;
        refined_only(self.unit_weight.is_some(), "choices.unit_weight")?;
        refined_only(self.band_strength.is_some(), "choices.band_strength")?;
        Ok(Choices {
            face_friction: self.face_friction(),
            ..Choices::default()
        })
    }

    /// The refined model's choices, every default filled in.
    fn refined(&mut self) -> Choices {
        Choices {
            band_angles: match *self.band_angles.get_or_insert_default() {
                BandAnglesName::MeanOfAngles => BandAngleRule::MeanOfAngles,
                BandAnglesName::AngleOfMeanShear => BandAngleRule::AngleOfMeanShear,
            },
            band_shear: match *self.band_shear.get_or_insert_default() {
                BandShearName::Full => BandShearRule::Full,
                BandShearName::ByPosition => BandShearRule::ByPosition,
            },
            unit_weight: match *self.unit_weight.get_or_insert_default() {
                UnitWeightName::BandUniform => UnitWeightRule::BandUniform,
                UnitWeightName::PerNodeFormula => UnitWeightRule::PerNodeFormula,
            },
            face_friction: self.face_friction(),
            band_strength: match *self.band_strength.get_or_insert_default() {
                BandStrengthName::Footprint => BandStrengthRule::Footprint,
                BandStrengthName::CrossedColumns => BandStrengthRule::CrossedColumns,
                BandStrengthName::CrossedColumnsUnfloored => {
                    BandStrengthRule::CrossedColumnsUnfloored
                }
            },
        }
    }

    fn face_friction(&self) -> FaceFrictionRule {
        match self.face_friction {
            FaceFrictionName::Mobilised => FaceFrictionRule::Mobilised,
            FaceFrictionName::Sign => FaceFrictionRule::Sign,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a table { depth, wall_friction, rake, adhesion, depth_path, width }"
)]
struct BladeFile {
    depth: f64,
    wall_friction: f64,
    #[serde(default)]
    rake: Option<f64>,
    #[serde(default)]
    adhesion: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    depth_path: Option<Vec<[f64; 2]>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    width: Option<f64>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table of soil properties")]
struct SoilFile {
    unit_weight: f64,
    friction: FrictionFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    dilation: Option<AngleFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    peak_shear: Option<f64>,
    residual_shear: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    repose: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    d50: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band_width: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band_width_d50: Option<f64>,
    #[serde(default)]
    cohesion: Option<f64>,
    #[serde(default)]
    surcharge: Option<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table { initial, peak, residual }")]
struct FrictionFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    initial: Option<f64>,
    peak: f64,
    /// Left out: the peak (a soil that never softens); written back.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    residual: Option<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table { initial, peak, residual }")]
struct AngleFile {
    initial: f64,
    peak: f64,
    /// Left out: the peak (a soil that never softens); written back.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    residual: Option<f64>,
}

/// A case read from a file: the model's [`Case`] and its resolved file form.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedCase {
    /// The case as the model takes it, every default filled in, validated
    /// once here with the keys named as the file wrote them.
    pub case: ValidCase,
    resolved: CaseFile,
    /// What the file wrote in the form of an earlier version, and what to
    /// write instead: one line each, for the front ends to show.
    notices: Vec<String>,
}

impl LoadedCase {
    /// The case as a running simulation has steered it
    /// (`Simulation::advance_to`): `case`, the case of a simulation started
    /// from this one, with its depth path and travel in both forms.
    pub fn steered(&self, case: &ValidCase) -> LoadedCase {
        let mut loaded = self.clone();
        let path = &case.blade.depth_path;
        loaded.case = case.clone();
        // A steered tool moves as its blade was steered (M55).
        match loaded.resolved.tool.as_mut() {
            Some(tool) => tool.steer(case),
            None => loaded.resolved.blade.depth_path = (!path.is_empty()).then(|| path.clone()),
        }
        loaded.resolved.run.travel = Some(case.run.travel);
        loaded
    }

    /// `soilcut check`'s line for a case with a tool: the tool and the
    /// blade it is (M55); None for a case without one.
    pub fn tool_line(&self) -> Option<String> {
        let tool = self.resolved.tool.as_ref()?;
        let blade = &self.case.blade;
        let path = if blade.depth_path.is_empty() {
            "at constant depth"
        } else {
            "along its cutting edge's depth path"
        };
        Some(format!(
            "{}: the blade of rake {}° {path} (docs/model.md §21, (M55))",
            tool.describe(),
            blade.rake
        ))
    }

    /// The notices of keys written in the form of an earlier version,
    /// one line each (the command line prints them on stderr, Python warns
    /// with them).
    pub fn notices(&self) -> &[String] {
        &self.notices
    }

    /// The table of `case.resolved.toml` (without its comment line).
    pub fn resolved_table(&self) -> toml::Table {
        toml::Table::try_from(&self.resolved).expect("a case serialises to TOML")
    }

    /// `case.resolved.toml`: every default filled in, only the keys valid
    /// for the case's model. Reading it back gives the same [`Case`].
    pub fn resolved_toml(&self) -> String {
        let body = toml::to_string(&self.resolved).expect("a case serialises to TOML");
        format!(
            "# soilcut {} case, resolved: every default filled in.\n{body}",
            env!("CARGO_PKG_VERSION")
        )
    }
}

/// The case a snapshot's note holds: the note
/// `Simulation::snapshot_with_note` keeps is the case's `resolved_toml`
/// (as the C ABI and the Python package write it), or empty for a
/// simulation known only by its state (None). `case` is the restored
/// simulation's: the text must read back to it.
pub fn case_from_note(note: &[u8], case: &Case) -> Result<Option<LoadedCase>, SnapshotError> {
    if note.is_empty() {
        return Ok(None);
    }
    let invalid = |message: String| SnapshotError::Invalid {
        what: "its case text",
        message,
    };
    // The note is under the checksum: only bytes made by hand get here.
    let text = std::str::from_utf8(note).map_err(|e| invalid(format!("not UTF-8: {e}")))?;
    let loaded = parse_case(text, &[]).map_err(|e| invalid(e.to_string()))?;
    if *loaded.case != *case {
        return Err(invalid("not the case of its state".into()));
    }
    Ok(Some(loaded))
}

/// Reads, overrides, resolves and validates a case file.
pub fn read_case(path: &Path, overrides: &[Override]) -> Result<LoadedCase, InputError> {
    let bytes = std::fs::read(path).map_err(InputError::Read)?;
    parse_case_bytes(&bytes, overrides)
}

/// [`read_case`] on the bytes of a case file, as read from disk: text that
/// is not UTF-8 is a syntax error naming its line.
pub fn parse_case_bytes(bytes: &[u8], overrides: &[Override]) -> Result<LoadedCase, InputError> {
    parse_case(crate::error::utf8(bytes)?, overrides)
}

/// [`read_case`] on the text of a case file.
pub fn parse_case(text: &str, overrides: &[Override]) -> Result<LoadedCase, InputError> {
    load_case_table(parse_case_table(text)?, overrides)
}

/// The table of a case file's text, not yet read as a case: a syntax
/// error names its line.
pub fn parse_case_table(text: &str) -> Result<toml::Table, InputError> {
    text.parse().map_err(|e: toml::de::Error| syntax(text, &e))
}

/// [`read_case`] on a case file's table (from [`parse_case_table`]).
pub fn load_case_table(
    mut table: toml::Table,
    overrides: &[Override],
) -> Result<LoadedCase, InputError> {
    for o in overrides {
        o.apply(&mut table)?;
    }
    let file: CaseFile = serde_path_to_error::deserialize(table).map_err(|e| schema_error(&e))?;
    resolve(file)
}

fn syntax(text: &str, e: &toml::de::Error) -> InputError {
    let line = e.span().map_or(1, |s| {
        text[..s.start.min(text.len())].matches('\n').count() + 1
    });
    InputError::Syntax {
        line,
        message: crate::error::one_line(e.message()),
    }
}

/// The error of a dotted `key` that no case file can hold, whatever its
/// value: a key the schema does not know (naming the nearest it does), or
/// one below a key that is not a table. `None` for a key the case may
/// hold; its value is checked when a case is read. A study asks before its
/// runs, which would each fail alike.
pub fn unknown_key(
    mut table: toml::Table,
    overrides: &[Override],
    key: &str,
    value: &toml::Value,
) -> Option<InputError> {
    let probe = match Override::new(key, value.clone()) {
        Ok(probe) => probe,
        Err(e) => return Some(e),
    };
    for o in overrides.iter().chain([&probe]) {
        if let Err(e) = o.apply(&mut table) {
            return Some(e);
        }
    }
    match serde_path_to_error::deserialize::<_, CaseFile>(table) {
        Err(e) if quoted_after(e.inner().message(), "unknown field `").is_some() => {
            Some(schema_error(&e))
        }
        _ => None,
    }
}

/// Names the dotted key of a schema error, including the missing or unknown
/// key itself (serde reports those at the enclosing table).
fn schema_error(e: &serde_path_to_error::Error<toml::de::Error>) -> InputError {
    let path = e.path().to_string();
    let message = e.inner().message();
    // The path ends with the field itself where serde had reached it.
    let child = |field: &str| {
        let written = toml_key(field);
        if path == "." || path == field {
            written
        } else if let Some(parent) = path.strip_suffix(&format!(".{field}")) {
            format!("{parent}.{written}")
        } else {
            format!("{path}.{written}")
        }
    };
    if let Some(field) = quoted_after(message, "missing field `") {
        return InputError::key(&child(field), "required key is missing");
    }
    if let Some(field) = quoted_after(message, "unknown field `") {
        let expected = message.split_once(", expected ").map_or("", |(_, e)| e);
        let key = child(field);
        let parent = key.rsplit_once('.').map_or("", |(parent, _)| parent);
        let hint = match expected {
            "" => String::new(),
            e => format!(
                " (nearest: {}; expected {})",
                nearest(parent, field, e),
                e.replace("one of ", "one of: ")
            ),
        };
        return InputError::key(&key, format!("unknown key{hint}"));
    }
    let key = if path == "." { "case" } else { &path };
    InputError::key(
        key,
        plain_type_error(message).unwrap_or_else(|| message.into()),
    )
}

/// serde's `invalid type: string "abc", expected f64` in the words of the
/// case file: `expected a number, got the string "abc"` (Rust's type names
/// mean nothing to a user who wrote TOML).
fn plain_type_error(message: &str) -> Option<String> {
    let (got, expected) = message
        .strip_prefix("invalid type: ")?
        .rsplit_once(", expected ")?;
    let expected = match expected {
        "f64" | "f32" => "a number",
        "u8" | "u16" | "u32" | "u64" | "usize" | "i32" | "i64" => "a whole number",
        "a boolean" => "true or false",
        "a sequence" => "an array",
        other => other,
    };
    let (kind, value) = got.split_once(' ').unwrap_or((got, ""));
    let kind = match kind {
        "sequence" => "an array".to_string(),
        "map" => "a table".to_string(),
        "integer" => "the whole number".to_string(),
        "floating" => "the number".to_string(),
        other => format!("the {other}"),
    };
    let value = value.trim_start_matches("point ").replace('`', "");
    Some(
        format!("expected {expected}, got {kind} {value}")
            .trim_end()
            .to_string(),
    )
}

/// The keys of serde's `expected` list (`` one of `a`, `b` `` or `` `a` ``)
/// fewest edits from the unknown `field`, dotted below `parent`: what a
/// misspelling meant.
fn nearest(parent: &str, field: &str, expected: &str) -> String {
    let keys: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
    let least = keys.iter().map(|k| edits(field, k)).min().unwrap_or(0);
    keys.iter()
        .filter(|k| edits(field, k) == least)
        .map(|k| match parent {
            "" => format!("`{k}`"),
            p => format!("`{p}.{k}`"),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The Levenshtein distance between `a` and `b`, in characters.
fn edits(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substituted = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substituted.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

/// A key as it is written in TOML: bare if it can be, else quoted, so
/// that an empty key or one with spaces is still named (found by fuzzing,
/// docs/fuzzing.md: `"" = 1` was reported as ": unknown key").
fn toml_key(key: &str) -> String {
    let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
    if !key.is_empty() && key.chars().all(bare) {
        key.to_string()
    } else {
        format!("{key:?}")
    }
}

fn quoted_after<'a>(message: &'a str, prefix: &str) -> Option<&'a str> {
    let rest = message.strip_prefix(prefix)?;
    rest.split_once('`').map(|(field, _)| field)
}

fn refined_only(present: bool, key: &str) -> Result<(), InputError> {
    if present {
        Err(InputError::key(key, REFINED_ONLY))
    } else {
        Ok(())
    }
}

fn required<T>(value: Option<T>, key: &str) -> Result<T, InputError> {
    value.ok_or_else(|| InputError::key(key, REFINED_REQUIRED))
}

fn check_name(name: &str) -> Result<(), InputError> {
    let allowed = |c: char| c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-');
    if name.is_empty() || !name.chars().all(allowed) || name.chars().all(|c| c == '.') {
        return Err(InputError::key(
            "name",
            format!("must be non-empty, of the characters A-Z a-z 0-9 . _ - only, and not only dots (got {name:?}); it names the output folder"),
        ));
    }
    Ok(())
}

/// Most characters of a case's title: it heads every picture, whose
/// drawing took seconds for a title of 1e5 characters (issue 50).
const MAX_TITLE: usize = 200;

/// The title (given as `key`, `title` or the `name` it defaults to) within
/// [`MAX_TITLE`] characters.
fn check_title(title: &str, key: &str) -> Result<(), InputError> {
    let n = title.chars().count();
    if n <= MAX_TITLE {
        return Ok(());
    }
    Err(InputError::key(
        key,
        format!("the title is at most {MAX_TITLE} characters, as it heads every picture (got {n})"),
    ))
}

/// A positive, finite number the model never sees (so it cannot check it).
fn positive(value: f64, key: &str) -> Result<(), InputError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(InputError::key(
            key,
            format!("must be a finite number > 0 (got {value})"),
        ))
    }
}

/// A length the model never sees, in the model's range of lengths
/// ([`soilcut_model::MAGNITUDE`]): d50 only scales a band width given as
/// N·d50, so 1e300 was taken where the band width was a length.
fn length(value: f64, key: &str) -> Result<(), InputError> {
    let [least, greatest] = soilcut_model::MAGNITUDE;
    if (least..=greatest).contains(&value) {
        return Ok(());
    }
    Err(InputError::key(
        key,
        format!("must be a length in [{least:e}, {greatest:e}] (got {value})"),
    ))
}

/// `blade.depth_path` as written: an empty list is refused rather than
/// read as no path (a list meant to hold points).
fn depth_path(path: Option<&Vec<[f64; 2]>>) -> Result<Vec<[f64; 2]>, InputError> {
    match path {
        Some(points) if points.is_empty() => Err(InputError::key(
            "blade.depth_path",
            "give at least one point [u, d] (leave the key out for the constant depth blade.depth)",
        )),
        given => Ok(given.cloned().unwrap_or_default()),
    }
}

/// The refined model's own keys: (friction.initial, dilation, peak_shear,
/// band width). Fills in the resolved file in place.
fn resolve_refined(soil: &mut SoilFile) -> Result<(f64, AngleLaw, f64, f64), InputError> {
    let initial = required(soil.friction.initial, "soil.friction.initial")?;
    let dilation = required(soil.dilation, "soil.dilation")?;
    let peak_shear = required(soil.peak_shear, "soil.peak_shear")?;
    let d50 = required(soil.d50, "soil.d50")?;
    length(d50, "soil.d50")?;
    let band_width = match (soil.band_width, soil.band_width_d50) {
        (Some(width), None) => width,
        (None, Some(n)) => {
            positive(n, "soil.band_width_d50")?;
            n * d50
        }
        (Some(_), Some(_)) => {
            return Err(InputError::key(
                "soil.band_width",
                "give exactly one of soil.band_width (a length) and soil.band_width_d50 (N, dB = N·d50), not both",
            ))
        }
        (None, None) => {
            return Err(InputError::key(
                "soil.band_width",
                format!("{REFINED_REQUIRED}: give soil.band_width (a length) or soil.band_width_d50 (N, dB = N·d50)"),
            ))
        }
    };
    let dilation = AngleLaw {
        initial: dilation.initial,
        peak: dilation.peak,
        residual: dilation.residual.unwrap_or(dilation.peak),
    };
    if let Some(d) = soil.dilation.as_mut() {
        d.residual = Some(dilation.residual);
    }
    Ok((initial, dilation, peak_shear, band_width))
}

/// The case a case file describes, its defaults written into `file` (the
/// resolved file), validated.
fn resolve(mut file: CaseFile) -> Result<LoadedCase, InputError> {
    check_name(&file.name)?;
    let key = if file.title.is_some() {
        "title"
    } else {
        "name"
    };
    let title = file.title.get_or_insert_with(|| file.name.clone()).clone();
    check_title(&title, key)?;
    let adhesion = *file.blade.adhesion.get_or_insert(0.0);
    let depth = file.blade.depth;
    let by_tool = blade_motion(&mut file)?;
    let tool_travel = by_tool.as_ref().map(|cut| cut.travel);
    let (rake, depth_path, pivot, rotation) = match by_tool {
        Some(cut) => (cut.rake, cut.depth_path, cut.pivot, cut.rotation),
        None => (
            *file.blade.rake.get_or_insert(90.0),
            depth_path(file.blade.depth_path.as_ref())?,
            [0.0, 0.0],
            0.0,
        ),
    };
    let model = match file.model {
        ModelName::Original => Model::Original,
        ModelName::Refined => Model::Refined,
    };
    let soil = resolve_soil(&mut file.soil, model)?;
    let choices_file = file.choices.get_or_insert_with(ChoicesFile::default);
    let choices = match model {
        Model::Original => choices_file.original()?,
        Model::Refined => choices_file.refined(),
    };
    let blade = Blade {
        depth,
        wall_friction: file.blade.wall_friction,
        rake,
        adhesion,
        depth_path,
        width: file.blade.width,
        pivot,
        rotation,
    };
    let class = Class {
        model,
        soil: &soil,
        blade: &blade,
        face_friction: choices.face_friction,
        in_bin: file.bin.is_some(),
    };
    let (run, notices) = file.run.resolve(class, tool_travel)?;
    let case = Case {
        name: file.name.clone(),
        title,
        model,
        blade,
        soil,
        run,
        bin: Bin {
            length: file.bin.map(|b| b.length),
        },
        choices,
    };
    let case = case.validated().map_err(|e| key_as_written(e, &file))?;
    Ok(LoadedCase {
        case,
        resolved: file,
        notices,
    })
}

/// The blade's rake, depth path and travel as a tool gives them: none
/// where the case has no tool (`blade.rake` and `blade.depth_path` then
/// give them), else the tool's (M55).
fn blade_motion(file: &mut CaseFile) -> Result<Option<StraightCut>, InputError> {
    let Some(tool_file) = file.tool.as_mut() else {
        return Ok(None);
    };
    for (key, given) in [
        ("blade.rake", file.blade.rake.is_some()),
        ("blade.depth_path", file.blade.depth_path.is_some()),
    ] {
        if given {
            return Err(CaseError::new(
                key,
                "is given by the tool in a case with [tool] (its profile and tool.motion): remove it",
            )
            .into());
        }
    }
    Ok(Some(tool_file.tool()?.straight_cut(file.blade.depth)?))
}

/// The soil of a case file, its defaults written into `soil`: the repose
/// angle the residual friction, no cohesion or surcharge; the original
/// model's initial friction its peak, without dilation or a band.
fn resolve_soil(soil: &mut SoilFile, model: Model) -> Result<Soil, InputError> {
    let residual = *soil.friction.residual.get_or_insert(soil.friction.peak);
    let repose = *soil.repose.get_or_insert(residual);
    let cohesion = *soil.cohesion.get_or_insert(0.0);
    let surcharge = *soil.surcharge.get_or_insert(0.0);
    let (initial, dilation, peak_shear, band_width) = match model {
        Model::Original => {
            refined_only(soil.friction.initial.is_some(), "soil.friction.initial")?;
            refined_only(soil.dilation.is_some(), "soil.dilation")?;
            refined_only(soil.peak_shear.is_some(), "soil.peak_shear")?;
            refined_only(soil.d50.is_some(), "soil.d50")?;
            refined_only(soil.band_width.is_some(), "soil.band_width")?;
            refined_only(soil.band_width_d50.is_some(), "soil.band_width_d50")?;
            (soil.friction.peak, AngleLaw::constant(0.0), 0.0, 0.0)
        }
        Model::Refined => resolve_refined(soil)?,
    };
    Ok(Soil {
        unit_weight: soil.unit_weight,
        friction: AngleLaw {
            initial,
            peak: soil.friction.peak,
            residual,
        },
        dilation,
        peak_shear,
        residual_shear: soil.residual_shear,
        repose,
        band_width,
        cohesion,
        surcharge,
    })
}

/// Names a validation error by the key the user wrote: the original model's
/// initial friction is its peak, and a band width may be given as N·d50.
fn key_as_written(e: CaseError, file: &CaseFile) -> InputError {
    match (e.key.as_str(), file.model) {
        ("soil.friction.initial", ModelName::Original) => {
            InputError::key("soil.friction.peak", e.message)
        }
        ("soil.band_width", _) if file.soil.band_width_d50.is_some() => InputError::key(
            "soil.band_width_d50",
            format!("band width dB = N·d50: {}", e.message),
        ),
        _ => e.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use soilcut_model::{TimeScheme, VertexGround};

    const ORIGINAL: &str = include_str!("../testdata/original.toml");
    const REFINED: &str = include_str!("../testdata/refined.toml");

    fn key_error(text: &str, overrides: &[&str]) -> CaseError {
        let overrides: Vec<Override> = overrides.iter().map(|s| s.parse().unwrap()).collect();
        match parse_case(text, &overrides) {
            Err(InputError::Key(e)) => e,
            other => panic!("expected a key error, got {other:?}"),
        }
    }

    #[test]
    fn a_value_of_the_wrong_type_is_named_in_the_case_files_words() {
        for (set, said) in [
            (
                "run.increment=abc",
                "expected a number, got the string \"abc\"",
            ),
            (
                "run.increment=true",
                "expected a number, got the boolean true",
            ),
            (
                "blade.depth_path=3",
                "expected an array, got the whole number 3",
            ),
            ("name=3.5", "expected a string, got the number 3.5"),
        ] {
            let e = key_error(ORIGINAL, &[set]);
            assert_eq!(e.message, said, "{set}");
            assert!(!e.message.contains("f64"), "{set}");
        }
    }

    #[test]
    fn choices_default_to_model_md_and_can_be_varied() {
        let loaded = parse_case(REFINED, &[]).unwrap();
        assert_eq!(loaded.case.choices, Choices::default());
        assert!(loaded.resolved_toml().contains("[choices]"));
        let set: Vec<Override> = [
            "choices.band_shear=by-position",
            "choices.unit_weight=per-node-formula",
        ]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
        let varied = parse_case(REFINED, &set).unwrap().case.choices;
        assert_eq!(varied.band_shear, BandShearRule::ByPosition);
        assert_eq!(varied.unit_weight, UnitWeightRule::PerNodeFormula);
        assert_eq!(varied.band_angles, BandAngleRule::MeanOfAngles);
        let e = key_error(REFINED, &["choices.band_angles=median"]);
        assert_eq!(e.key, "choices.band_angles");
        // The band's strength (M53): refined only, two words.
        assert_eq!(varied.band_strength, BandStrengthRule::Footprint);
        let crossed = ["choices.band_strength=crossed-columns".parse().unwrap()];
        let loaded = parse_case(REFINED, &crossed).unwrap();
        assert_eq!(
            loaded.case.choices.band_strength,
            BandStrengthRule::CrossedColumns
        );
        assert_eq!(
            parse_case(&loaded.resolved_toml(), &[]).unwrap().case,
            loaded.case
        );
        let unfloored = ["choices.band_strength=crossed-columns-unfloored"
            .parse()
            .unwrap()];
        assert_eq!(
            parse_case(REFINED, &unfloored)
                .unwrap()
                .case
                .choices
                .band_strength,
            BandStrengthRule::CrossedColumnsUnfloored
        );
        for (text, set) in [
            (REFINED, "choices.band_strength=widest"),
            (ORIGINAL, "choices.band_strength=footprint"),
        ] {
            assert_eq!(key_error(text, &[set]).key, "choices.band_strength");
        }
        assert_eq!(
            key_error(ORIGINAL, &["choices.band_shear=full"]).key,
            "choices.band_shear"
        );
        assert_eq!(varied.face_friction, FaceFrictionRule::Mobilised);
        let sign = ["choices.face_friction=sign".parse().unwrap()];
        for text in [ORIGINAL, REFINED] {
            let loaded = parse_case(text, &sign).unwrap();
            assert_eq!(loaded.case.choices.face_friction, FaceFrictionRule::Sign);
            let again = parse_case(&loaded.resolved_toml(), &[]).unwrap();
            assert_eq!(again.case, loaded.case);
        }
        let original = parse_case(ORIGINAL, &[]).unwrap().resolved_toml();
        assert!(
            original.contains("face_friction = \"mobilised\""),
            "{original}"
        );
        assert!(!original.contains("band_shear"), "{original}");
        let e = key_error(REFINED, &["choices.face_friction=none"]);
        assert_eq!(e.key, "choices.face_friction");
        assert!(e.message.contains("`mobilised` or `sign`"), "{}", e.message);
    }

    #[test]
    fn bin_length_is_read_validated_and_written_back() {
        let loaded = parse_case(ORIGINAL, &[]).unwrap();
        assert_eq!(loaded.case.bin.length, None);
        assert!(!loaded.resolved_toml().contains("[bin]"));
        let set: Vec<Override> = vec!["bin.length=120".parse().unwrap()];
        let walled = parse_case(ORIGINAL, &set).unwrap();
        assert_eq!(walled.case.bin.length, Some(120.0));
        let again = parse_case(&walled.resolved_toml(), &[]).unwrap();
        assert_eq!(again.case, walled.case);
        assert_eq!(key_error(ORIGINAL, &["bin.length=10"]).key, "bin.length");
        assert_eq!(key_error(ORIGINAL, &["bin.width=10"]).key, "bin.width");
    }

    #[test]
    fn original_resolves_defaults() {
        let c = parse_case(ORIGINAL, &[]).unwrap().case;
        assert_eq!(c.title, "base");
        assert_eq!(c.soil.repose, 30.0);
        assert_eq!(c.soil.friction.initial, 35.0);
        assert_eq!(c.soil.dilation, AngleLaw::constant(0.0));
        assert_eq!((c.soil.peak_shear, c.soil.band_width), (0.0, 0.0));
    }

    #[test]
    fn refined_band_width_from_d50() {
        let c = parse_case(REFINED, &[]).unwrap().case;
        assert_eq!(c.model, Model::Refined);
        assert_eq!(c.soil.band_width, 7.0 * 0.6);
        assert_eq!(c.soil.friction.initial, 20.0);
        assert_eq!(c.soil.dilation.initial, -5.0);
    }

    /// `text` without its `increment` line.
    fn without_increment(text: &str) -> String {
        text.lines()
            .filter(|l| !l.starts_with("increment"))
            .map(|l| format!("{l}\n"))
            .collect()
    }

    fn loaded(text: &str, overrides: &[&str]) -> LoadedCase {
        let overrides: Vec<Override> = overrides.iter().map(|s| s.parse().unwrap()).collect();
        parse_case(text, &overrides).unwrap()
    }

    /// (d, v0, the vertex ground's keys) `text` resolves to with
    /// `overrides`, checked to be written into the resolved file, which
    /// reads back to the same case.
    fn resolved_ground(text: &str, overrides: &[&str]) -> (f64, f64, Option<VertexGround>) {
        let loaded = loaded(text, overrides);
        let run = &loaded.case.run;
        let resolved = loaded.resolved_toml();
        let ground = format!("ground = \"{}\"", run.ground.name());
        let mut lines = vec![format!("increment = {:?}", run.increment), ground];
        if let Some(v) = run.vertices() {
            lines.push(format!("vertex_spacing = {:?}", v.spacing));
            lines.push(format!("samples_per_band = {:?}", v.samples_per_band));
            lines.push(format!("time_scheme = \"{}\"", v.time_scheme.name()));
            lines.push(format!("merge_tolerance = {:?}", v.merge_tolerance));
        }
        for line in lines {
            assert!(resolved.contains(&line), "{line} not in {resolved}");
        }
        assert!(!resolved.contains("node_spacing"), "{resolved}");
        assert_eq!(parse_case(&resolved, &[]).unwrap().case, loaded.case);
        (
            loaded.case.blade.depth,
            run.increment,
            run.vertices().copied(),
        )
    }

    /// The vertex spacing of `ground`, panicking on the node grid.
    fn spacing(ground: Option<VertexGround>) -> f64 {
        ground.expect("on the vertex ground").spacing
    }

    #[test]
    fn increment_and_ground_default_by_the_class_of_case() {
        let original = without_increment(ORIGINAL);
        let refined = without_increment(REFINED);
        // The original model: d/250 on the vertex ground, vertices d/50
        // apart in softening soil, d/25 where it never softens (the coarse
        // node grid's class before issue 49).
        let (d, v0, v) = resolved_ground(&original, &[]);
        assert_eq!((v0, spacing(v)), (d / 250.0, d / 50.0));
        let (d, v0, v) = resolved_ground(&original, &["soil.friction.residual=35"]);
        assert_eq!((v0, spacing(v)), (d / 250.0, d / 25.0));
        // The refined model in softening soil: d/350, vertices d/50 (d/100
        // raked), 8 samples; on the node grid d/1250.
        let (d, v0, v) = resolved_ground(&refined, &[]);
        assert_eq!((v0, spacing(v)), (d / 350.0, d / 50.0));
        assert_eq!(v.unwrap().samples_per_band, 8.0);
        let (d, v0, v) = resolved_ground(&refined, &["blade.rake=70"]);
        assert_eq!((v0, spacing(v)), (d / 350.0, d / 100.0));
        let (d, v0, v) = resolved_ground(&refined, &["run.ground=\"nodes\""]);
        assert_eq!((v0, v), (d / 1250.0, None));
        // Soil that never softens: d/250 on vertices d/25, 1 sample; on
        // the node grid d/500.
        let never = "soil.friction.residual=35";
        let (d, v0, v) = resolved_ground(&refined, &[never]);
        assert_eq!((v0, spacing(v)), (d / 250.0, d / 25.0));
        assert_eq!(v.unwrap().samples_per_band, 1.0);
        let (d, v0, _) = resolved_ground(&refined, &[never, "run.ground=\"nodes\""]);
        assert_eq!(v0, d / 500.0);
        // An increment given keeps the class's spacing.
        let (d, v0, v) = resolved_ground(&refined, &["run.increment=0.02"]);
        assert_eq!((v0, spacing(v)), (0.02, d / 50.0));
    }

    #[test]
    fn a_key_of_the_other_ground_is_refused_naming_it() {
        let nodes = "run.ground=\"nodes\"";
        for key in [
            "run.vertex_spacing=0.4",
            "run.samples_per_band=8",
            "run.time_scheme=\"explicit\"",
            "run.merge_tolerance=0",
        ] {
            let e = key_error(REFINED, &[nodes, key]);
            assert_eq!(e.key, key.split('=').next().unwrap(), "{e}");
            assert!(e.message.contains("run.ground = \"vertices\""), "{e}");
        }
        // The coarse grid's key names what to write instead.
        for set in [
            &["run.node_spacing=0.4"][..],
            &[nodes, "run.node_spacing=0.4"],
        ] {
            let e = key_error(REFINED, set);
            assert_eq!(e.key, "run.node_spacing", "{e}");
            assert!(e.message.contains("remove it"), "{e}");
        }
        let e = key_error(REFINED, &["run.ground=\"grid\""]);
        assert_eq!(e.key, "run.ground", "{e}");
        assert!(e.message.contains("`vertices` or `nodes`"), "{e}");
        let e = key_error(
            REFINED,
            &["run.ground=\"vertices\"", "run.vertex_spacing=0"],
        );
        assert_eq!(e.key, "run.vertex_spacing", "{e}");
    }

    #[test]
    fn an_old_node_grid_file_runs_on_the_node_grid_with_a_notice() {
        // As earlier versions wrote a node-grid case: vertex_spacing = 0 and
        // the node grid's only values of the vertex ground's keys.
        let old = [
            "run.vertex_spacing=0",
            "run.node_spacing=0.2",
            "run.time_scheme=\"explicit\"",
            "run.merge_tolerance=0",
            "run.samples_per_band=0",
        ];
        let from_old = loaded(REFINED, &old);
        let new = loaded(REFINED, &["run.ground=\"nodes\""]);
        assert_eq!(from_old.case, new.case);
        assert!(new.notices().is_empty());
        let notices = from_old.notices();
        assert_eq!(notices.len(), 2, "{notices:?}");
        assert!(
            notices[0].contains("write run.ground = \"nodes\""),
            "{notices:?}"
        );
        assert!(notices[1].contains("run.node_spacing"), "{notices:?}");
        assert_eq!(from_old.resolved_toml(), new.resolved_toml());
        // The sampled search of the node grid is gone: named.
        let e = key_error(REFINED, &["run.vertex_spacing=0", "run.samples_per_band=8"]);
        assert_eq!(e.key, "run.samples_per_band", "{e}");
    }

    #[test]
    fn the_time_scheme_defaults_by_the_face_friction() {
        let refined = without_increment(REFINED);
        let scheme = |o: &[&str]| resolved_ground(&refined, o).2.unwrap().time_scheme;
        assert_eq!(scheme(&[]), TimeScheme::MidpointForce);
        assert_eq!(
            scheme(&["run.time_scheme=\"explicit\""]),
            TimeScheme::Explicit
        );
        // Explicit takes its own default increment, d/500, as does the
        // sign rule of the face friction, which has no midpoint force.
        let (d, v0, _) = resolved_ground(&refined, &["run.time_scheme=\"explicit\""]);
        assert_eq!(v0, d / 500.0);
        let sign = ["choices.face_friction=\"sign\""];
        assert_eq!(scheme(&sign), TimeScheme::Explicit);
        assert_eq!(resolved_ground(&refined, &sign).1, 20.0 / 500.0);
        let e = key_error(&refined, &[sign[0], "run.time_scheme=\"midpoint-force\""]);
        assert_eq!(e.key, "run.time_scheme");
        assert!(e.message.contains("needs choices.face_friction"), "{e}");
    }

    #[test]
    fn merge_tolerance_defaults_to_none_and_refuses_its_range() {
        let refined = without_increment(REFINED);
        let v = resolved_ground(&refined, &[]).2.unwrap();
        assert_eq!(v.merge_tolerance, 0.0);
        for bad in ["0.5", "-0.01", "nan"] {
            let e = key_error(&refined, &[&format!("run.merge_tolerance={bad}")]);
            assert_eq!(e.key, "run.merge_tolerance", "{bad}");
        }
        let e = key_error(&refined, &["run.merge_tolerance=0.5"]);
        assert!(e.message.contains("[0, 0.1]"), "{e}");
    }

    #[test]
    fn samples_per_band_refuses_a_negative_count() {
        let every = resolved_ground(ORIGINAL, &["run.samples_per_band=0"]).2;
        assert_eq!(every.unwrap().samples_per_band, 0.0);
        for bad in ["-1", "nan", "inf"] {
            let e = key_error(ORIGINAL, &[&format!("run.samples_per_band={bad}")]);
            assert_eq!(e.key, "run.samples_per_band", "{bad}");
        }
    }

    #[test]
    fn resolved_round_trip_is_identical() {
        for text in [ORIGINAL, REFINED] {
            let loaded = parse_case(text, &[]).unwrap();
            let again = parse_case(&loaded.resolved_toml(), &[]).unwrap();
            assert_eq!(again.case, loaded.case);
            assert_eq!(again.resolved_toml(), loaded.resolved_toml());
        }
    }

    #[test]
    fn a_steered_case_reads_back_as_steered() {
        let loaded = parse_case(ORIGINAL, &[]).unwrap();
        let mut case = loaded.case.clone().into_case();
        case.blade.depth_path = vec![[0.0, 20.0], [31.5, 12.25]];
        case.run.travel = 123.5;
        let steered = loaded.steered(&case.clone().validated().unwrap());
        assert_eq!(steered.case.blade.depth_path, case.blade.depth_path);
        let again = parse_case(&steered.resolved_toml(), &[]).unwrap();
        assert_eq!(again.case, steered.case);
    }

    #[test]
    fn resolved_original_has_no_refined_keys() {
        let text = parse_case(ORIGINAL, &[]).unwrap().resolved_toml();
        for key in ["initial", "dilation", "peak_shear", "d50", "band_width"] {
            assert!(!text.contains(key), "{key} in\n{text}");
        }
        assert!(
            text.contains("repose = 30.0") && text.contains("title = \"base\""),
            "{text}"
        );
    }

    #[test]
    fn missing_and_unknown_keys_are_named() {
        let e = key_error(&ORIGINAL.replace("depth = 20.0\n", ""), &[]);
        assert_eq!(e.key, "blade.depth");
        let e = key_error(&ORIGINAL.replace("[run]", "[run]\nspeed = 1"), &[]);
        assert_eq!(e.key, "run.speed");
        assert!(e.message.starts_with("unknown key"), "{e}");
        let e = key_error(ORIGINAL, &["soil.friction.pk=3"]);
        assert_eq!(e.key, "soil.friction.pk");
        assert!(e.message.contains("(nearest: `soil.friction.peak`;"), "{e}");
        let e = key_error(ORIGINAL, &["colour=1"]);
        assert_eq!(e.key, "colour");
        let e = key_error(&ORIGINAL.replace("name = \"base\"\n", ""), &[]);
        assert_eq!(e.key, "name");
        // Keys that cannot be written bare are named as TOML quotes them.
        assert_eq!(key_error(&format!("\"\" = 1\n{ORIGINAL}"), &[]).key, "\"\"");
        let e = key_error(&ORIGINAL.replace("[run]", "[run]\n\"a b\" = 1"), &[]);
        assert_eq!(e.key, "run.\"a b\"");
    }

    #[test]
    fn a_key_no_value_can_set_is_told_from_a_bad_value() {
        let table = parse_case_table(ORIGINAL).unwrap();
        let unknown = |key: &str, value: toml::Value| {
            unknown_key(table.clone(), &[], key, &value).map(|e| e.to_string())
        };
        let e = unknown("soil.frict", 30.into()).unwrap();
        assert!(
            e.starts_with("soil.frict: unknown key (nearest: `soil.friction`;"),
            "{e}"
        );
        let e = unknown("soil.frict.peak", 30.into()).unwrap();
        assert!(e.starts_with("soil.frict: unknown key"), "{e}");
        assert!(unknown("run.increment.x", 1.into()).is_some());
        // A known key with a bad value is the run's error, not the key's.
        assert_eq!(unknown("soil.friction.peak", 95.into()), None);
        assert_eq!(unknown("blade.depth", "deep".into()), None);
        // The base overrides come first: a key they make a number has no children.
        let base = ["run.travel=1".parse().unwrap()];
        assert!(unknown_key(table.clone(), &base, "run.travel.x", &1.into()).is_some());
    }

    #[test]
    fn wrong_types_are_named() {
        let e = key_error(ORIGINAL, &["blade.depth=\"deep\""]);
        assert_eq!(e.key, "blade.depth");
        let e = key_error(ORIGINAL, &["model=fancy"]);
        assert_eq!(e.key, "model");
    }

    #[test]
    fn refined_keys_in_original_case() {
        for (set, key) in [
            ("soil.friction.initial=30", "soil.friction.initial"),
            ("soil.peak_shear=1", "soil.peak_shear"),
            ("soil.d50=0.6", "soil.d50"),
            ("soil.band_width=9", "soil.band_width"),
            ("soil.band_width_d50=9", "soil.band_width_d50"),
            (
                "soil.dilation={initial=0,peak=0,residual=0}",
                "soil.dilation",
            ),
        ] {
            let e = key_error(ORIGINAL, &[set]);
            assert_eq!(e.key, key);
            assert!(e.message.contains("refined"), "{e}");
        }
    }

    #[test]
    fn refined_requirements() {
        let e = key_error(REFINED, &["soil.band_width=9"]);
        assert!(e.to_string().contains("soil.band_width_d50"), "{e}");
        let e = key_error(&REFINED.replace("band_width_d50 = 7\n", ""), &[]);
        assert_eq!(e.key, "soil.band_width");
        let e = key_error(&REFINED.replace("d50 = 0.6\n", ""), &[]);
        assert_eq!(e.key, "soil.d50");
        let e = key_error(&REFINED.replace("peak_shear = 2\n", ""), &[]);
        assert_eq!(e.key, "soil.peak_shear");
        let e = key_error(REFINED, &["soil.friction={peak=40,residual=30}"]);
        assert_eq!(e.key, "soil.friction.initial");
        let e = key_error(REFINED, &["soil.d50=-0.6", "soil.band_width_d50=-15"]);
        assert_eq!(e.key, "soil.d50");
        let e = key_error(REFINED, &["soil.band_width_d50=40"]);
        assert_eq!(
            e.key, "soil.band_width_d50",
            "dB = 24 > d is named as written"
        );
    }

    #[test]
    fn a_soil_without_residual_values_never_softens() {
        let hardening = REFINED
            .replace("peak = 35, residual = 30 }", "peak = 35 }")
            .replace("peak = 5, residual = 0 }", "peak = 5 }");
        let left_out = loaded(&hardening, &[]);
        let given = loaded(
            REFINED,
            &["soil.friction.residual=35", "soil.dilation.residual=5"],
        );
        assert_eq!(left_out.case.soil, given.case.soil);
        assert_eq!(left_out.case.soil.repose, 35.0, "the repose follows φr");
        let text = left_out.resolved_toml();
        assert_eq!(loaded(&text, &[]).case, left_out.case, "written back");
        assert!(text.contains("residual = 35.0"), "{text}");
        let e = key_error(&hardening, &["soil.friction.initial=36"]);
        assert_eq!(e.key, "soil.friction.initial", "φc <= φp = φr still");
    }

    #[test]
    fn original_friction_errors_name_the_peak() {
        let e = key_error(ORIGINAL, &["soil.friction.peak=95"]);
        assert_eq!(e.key, "soil.friction.peak");
    }

    #[test]
    fn names_are_restricted() {
        for bad in ["", "..", "a/b", "a b", "ü"] {
            let e = key_error(ORIGINAL, &[&format!("name={bad:?}")]);
            assert_eq!(e.key, "name", "{bad:?}");
        }
        assert!(parse_case(ORIGINAL, &["name=\"a-1_b.c\"".parse().unwrap()]).is_ok());
    }

    #[test]
    fn text_that_is_not_utf8_is_refused_at_its_line() {
        let mut bytes = ORIGINAL.as_bytes().to_vec();
        let at = ORIGINAL.find("travel").unwrap();
        bytes[at + 2] = 0xe9; // a Latin-1 é
        match parse_case_bytes(&bytes, &[]) {
            Err(InputError::Syntax { line, message }) => {
                assert_eq!(line, 14);
                assert!(message.starts_with("byte 0xe9 at column 3 "), "{message}");
            }
            other => panic!("{other:?}"),
        }
        let text = parse_case_bytes(ORIGINAL.as_bytes(), &[]).unwrap();
        assert_eq!(text, parse_case(ORIGINAL, &[]).unwrap());
    }

    #[test]
    fn syntax_errors_give_the_line() {
        let text = ORIGINAL.replace("travel = 20.0", "travel = = 20.0");
        match parse_case(&text, &[]) {
            Err(InputError::Syntax { line, .. }) => assert_eq!(line, 14),
            other => panic!("{other:?}"),
        }
    }
}
