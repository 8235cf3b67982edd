//! One run of a case with overrides: the unit every study is made of.

use soilcut_io::{
    load_case_table, parse_case_table, record_case, run_case, InputError, LoadedCase, Override,
    RecordedRun,
};
use soilcut_model::{ProfilePoint, StepRecord, Summary};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// The case a study starts from: the table of its file (parsed once) and
/// the `--set` overrides given for every run.
#[derive(Clone, Debug)]
pub struct BaseCase {
    table: toml::Table,
    overrides: Vec<Override>,
}

impl BaseCase {
    /// The case file's text and the overrides of every run. Checks that
    /// the case reads (its runs may still fail).
    pub fn new(text: String, overrides: Vec<Override>) -> Result<Self, InputError> {
        BaseCase::from_table(parse_case_table(&text)?, overrides)
    }

    /// [`BaseCase::new`] on the case file's table (a front end that holds
    /// the case as a table already).
    pub fn from_table(table: toml::Table, overrides: Vec<Override>) -> Result<Self, InputError> {
        let base = BaseCase { table, overrides };
        base.load(&[])?;
        Ok(base)
    }

    /// Reads the case file at `path`.
    pub fn read(path: &Path, overrides: Vec<Override>) -> Result<Self, InputError> {
        let text = std::fs::read_to_string(path).map_err(InputError::Read)?;
        BaseCase::new(text, overrides)
    }

    /// This base case with `extra` overrides after its own, for every run.
    pub fn with(&self, extra: &[Override]) -> BaseCase {
        let mut overrides = self.overrides.clone();
        overrides.extend_from_slice(extra);
        BaseCase {
            table: self.table.clone(),
            overrides,
        }
    }

    /// The error of a `key` no run can set, whatever `value` it takes
    /// (`soilcut_io::unknown_key`), or `None`.
    pub fn unknown_key(&self, key: &str, value: &toml::Value) -> Option<InputError> {
        soilcut_io::unknown_key(self.table.clone(), &self.overrides, key, value)
    }

    /// The case with `extra` overrides applied after the base ones.
    pub fn load(&self, extra: &[Override]) -> Result<LoadedCase, InputError> {
        let all: Vec<Override> = self.overrides.iter().chain(extra).cloned().collect();
        load_case_table(self.table.clone(), &all)
    }

    /// Runs the case with `extra` overrides. Every failure (an invalid
    /// combination of keys, no admissible mechanism, even a panic of the
    /// model) is returned as its one-line message.
    pub fn run(&self, extra: &[Override]) -> Result<RunResult, String> {
        let loaded = self.load(extra).map_err(|e| e.to_string())?;
        run_loaded(loaded)
    }

    /// The value of a numeric key of the resolved case (after the base
    /// overrides), e.g. `soil.friction.peak`.
    pub fn number(&self, key: &str) -> Result<f64, String> {
        let loaded = self.load(&[]).map_err(|e| e.to_string())?;
        resolved_number(&loaded, key)
    }
}

/// The value of a numeric key of `loaded`'s resolved case, e.g.
/// `soil.friction.peak`.
pub fn resolved_number(loaded: &LoadedCase, key: &str) -> Result<f64, String> {
    let table = loaded.resolved_table();
    let mut value = None;
    let mut current = Some(&table);
    for part in key.split('.') {
        value = current.and_then(|t| t.get(part));
        current = value.and_then(toml::Value::as_table);
    }
    match value {
        Some(toml::Value::Float(x)) => Ok(*x),
        Some(toml::Value::Integer(i)) => Ok(*i as f64),
        Some(other) => Err(format!("{key}: not a number in the case (got {other})")),
        None => Err(format!(
            "{key}: the resolved case has no such key (give it in the case file or with --set)"
        )),
    }
}

/// Runs a loaded case to its end.
pub fn run_loaded(loaded: LoadedCase) -> Result<RunResult, String> {
    let run = caught(|| Ok(run_case(&loaded, 0, || {})))?;
    if let Some(e) = run.stopped {
        return Err(e.to_string());
    }
    Ok(RunResult {
        loaded,
        history: run.history,
        profile: run.profile,
        summary: run.summary,
        evaluations: run.evaluations,
        wall_time_s: run.wall_time_s,
    })
}

/// Runs a loaded case to its end as `soilcut run` does: every file of its
/// output folder (frames.csv included) and its history.
pub fn run_recorded(loaded: &LoadedCase) -> Result<RecordedRun, String> {
    let run = caught(|| Ok(record_case(loaded, || {})))?;
    match run.stopped {
        Some(e) => Err(e.to_string()),
        None => Ok(run),
    }
}

/// `f`'s result, with a panic of the model turned into its message.
fn caught<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(panic) => Err(format!(
            "the model panicked: {}",
            soilcut_io::panic_message(panic.as_ref())
        )),
    }
}

/// An `Override` setting `key` to `value`, as `--set key=value` would.
pub fn override_of(key: &str, value: &toml::Value) -> Result<Override, String> {
    Override::new(key, value.clone()).map_err(|e| e.to_string())
}

/// Everything a finished run produced.
#[derive(Clone, Debug)]
pub struct RunResult {
    /// The case as run.
    pub loaded: LoadedCase,
    /// One record per increment.
    pub history: Vec<StepRecord>,
    /// The final surface.
    pub profile: Vec<ProfilePoint>,
    /// Figures of the run.
    pub summary: Summary,
    /// Candidate mechanisms evaluated.
    pub evaluations: u64,
    /// Time spent in the simulation (varies between runs).
    pub wall_time_s: f64,
}

impl RunResult {
    /// The usual output files of `soilcut run`.
    pub fn files(&self) -> Vec<(&'static str, String)> {
        soilcut_io::RunOutput {
            loaded: &self.loaded,
            history: &self.history,
            profile: &self.profile,
            summary: &self.summary,
            candidate_evaluations: self.evaluations,
            wall_time_s: self.wall_time_s,
            stopped: None,
        }
        .files()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const REFINED: &str = include_str!("../../io/testdata/refined.toml");

    #[test]
    fn overrides_carry_values_exactly() {
        let base = BaseCase::new(REFINED.to_string(), vec![]).unwrap();
        for x in [3.3123456789012345, 1e-7, 3.5, 0.1 + 0.2, 1e19] {
            let o = override_of("soil.unit_weight", &toml::Value::Float(x)).unwrap();
            assert_eq!(base.load(&[o]).unwrap().case.soil.unit_weight, x);
        }
        let o = override_of(
            "choices.band_shear",
            &toml::Value::String("by-position".into()),
        )
        .unwrap();
        let c = base.load(&[o]).unwrap().case;
        assert_eq!(
            c.choices.band_shear,
            soilcut_model::BandShearRule::ByPosition
        );
    }

    #[test]
    fn numbers_of_the_resolved_case() {
        let set = vec!["soil.friction.peak=36".parse().unwrap()];
        let base = BaseCase::new(REFINED.to_string(), set).unwrap();
        assert_eq!(base.number("soil.friction.peak").unwrap(), 36.0);
        assert_eq!(base.number("soil.repose").unwrap(), 30.0, "a default");
        assert!(base.number("soil.band_width").is_err(), "given as N d50");
        assert!(base.number("soil.friction").is_err(), "a table");
    }

    #[test]
    fn failures_are_messages() {
        let base = BaseCase::new(REFINED.to_string(), vec![]).unwrap();
        let o = "soil.friction.initial=50".parse().unwrap();
        let e = base.run(&[o]).unwrap_err();
        assert!(e.starts_with("soil.friction.initial: "), "{e}");
    }
}
