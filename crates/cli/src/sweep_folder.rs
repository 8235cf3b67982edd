//! A sweep's folder, written in place as its runs finish: `sweep.csv`
//! gains each run's row as it finishes (in the order they finish; sorted
//! by run once the sweep ends or stops) and `summary.json` says how many
//! runs finished and whether the sweep is complete. A sweep stopped by an
//! error or a signal (`soilcut_io::on_abandon`) marks itself stopped and
//! keeps what finished; one killed outright keeps its rows too, its
//! summary still saying it is not complete.

use serde::Serialize;
use soilcut_io::{OutputDir, OutputError, Published, Registered};
use soilcut_study::sweep::{SweepResult, SweepRow};
use soilcut_study::StudyError;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// What the folder holds so far.
struct State {
    dir: PathBuf,
    keys: Vec<String>,
    runs: usize,
    rows: Vec<SweepRow>,
    /// Complete or stopped: nothing more is written.
    closed: bool,
    /// The first failure to write a row, reported when the sweep ends.
    error: Option<OutputError>,
}

/// `summary.json` of a sweep.
#[derive(Serialize)]
struct Summary<'a> {
    runs: usize,
    finished: usize,
    failed: usize,
    complete: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    stopped: Option<&'a str>,
}

/// What `summary.json` says of a sweep under way: read after a kill, it
/// is still true.
const UNDER_WAY: &str =
    "the sweep has not finished: it is running, or was killed (sweep.csv holds the runs that finished)";

/// A sweep's folder, published and claimed until dropped.
pub struct SweepFolder {
    state: Arc<Mutex<State>>,
    _published: Published,
    _hook: Registered,
}

impl SweepFolder {
    /// Publishes `claim` with the header of `sweep.csv` and a summary that
    /// says the sweep is under way, for `runs` runs of `keys`.
    pub fn start(claim: OutputDir, keys: Vec<String>, runs: usize) -> Result<Self, OutputError> {
        let header = SweepResult {
            keys: keys.clone(),
            rows: vec![],
        }
        .csv();
        let published = claim.write_then(&[("sweep.csv", header)], |_| Ok(()))?;
        let state = State {
            dir: published.path().to_path_buf(),
            keys,
            runs,
            rows: Vec::new(),
            closed: false,
            error: None,
        };
        state.summary(Some(UNDER_WAY))?;
        let state = Arc::new(Mutex::new(state));
        let shared = Arc::clone(&state);
        let hook = soilcut_io::on_abandon(move |signal| {
            let mut s = shared.lock().unwrap_or_else(|e| e.into_inner());
            let _ = s.close(&format!("interrupted by {signal}"));
        });
        Ok(SweepFolder {
            state,
            _published: published,
            _hook: hook,
        })
    }

    fn state(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Adds a finished run (from a worker thread).
    pub fn add(&self, row: &SweepRow) {
        let mut s = self.state();
        if s.closed {
            return;
        }
        s.rows.push(row.clone());
        if let Err(e) = s.append(row).and_then(|()| s.summary(Some(UNDER_WAY))) {
            s.error.get_or_insert(e);
        }
    }

    /// Marks the sweep stopped by `reason` (an error), keeping what
    /// finished.
    pub fn stop(&self, reason: &str) {
        let _ = self.state().close(&format!("stopped: {reason}"));
    }

    /// The finished sweep's files: `sweep.csv` in the order of the
    /// sample, `timing.csv`, the pictures, then `summary.json` complete.
    pub fn finish(&self, result: &SweepResult) -> Result<(), StudyError> {
        let mut s = self.state();
        if let Some(e) = s.error.take() {
            let _ = s.close(&format!("stopped: {e}"));
            return Err(StudyError::Output(e));
        }
        let dir = s.dir.clone();
        replace(&dir, "sweep.csv", &result.csv())?;
        replace(&dir, "timing.csv", &result.timing_csv())?;
        result.draw(&dir)?;
        s.rows = result.rows.clone();
        s.closed = true;
        Ok(s.summary(None)?)
    }
}

impl State {
    /// Appends `row` to `sweep.csv` (one write: a kill leaves whole rows).
    fn append(&self, row: &SweepRow) -> Result<(), OutputError> {
        let one = SweepResult {
            keys: self.keys.clone(),
            rows: vec![row.clone()],
        }
        .csv();
        let line = one.split_once('\n').map_or("", |(_, rows)| rows);
        let path = self.dir.join("sweep.csv");
        fs::OpenOptions::new()
            .append(true)
            .open(&path)
            .and_then(|mut f| f.write_all(line.as_bytes()))
            .map_err(OutputError::io(path))
    }

    /// Closes the folder as stopped (`why`): `sweep.csv` sorted by run,
    /// the summary saying why. Nothing once complete or closed.
    fn close(&mut self, why: &str) -> Result<(), OutputError> {
        if std::mem::replace(&mut self.closed, true) {
            return Ok(());
        }
        self.rows.sort_by_key(|r| r.run);
        let kept = SweepResult {
            keys: self.keys.clone(),
            rows: self.rows.clone(),
        };
        replace(&self.dir, "sweep.csv", &kept.csv())?;
        let finished = self.rows.len();
        let why = format!("{why} after {finished} of {} runs", self.runs);
        self.summary(Some(&why))?;
        eprintln!(
            "sweep: {why}; the finished runs are kept in {}",
            self.dir.display()
        );
        Ok(())
    }

    /// Writes `summary.json`; `stopped`: why the sweep is not complete.
    fn summary(&self, stopped: Option<&str>) -> Result<(), OutputError> {
        let summary = Summary {
            runs: self.runs,
            finished: self.rows.len(),
            failed: self.rows.iter().filter(|r| r.outcome.is_err()).count(),
            complete: stopped.is_none(),
            stopped,
        };
        let mut text = serde_json::to_string_pretty(&summary).expect("a summary serialises");
        text.push('\n');
        replace(&self.dir, "summary.json", &text)
    }
}

/// Replaces `dir/name` with `contents` in one rename: a reader, or a
/// kill, never meets half a file.
fn replace(dir: &Path, name: &str, contents: &str) -> Result<(), OutputError> {
    let part = dir.join(format!(".{name}.part"));
    let path = dir.join(name);
    fs::write(&part, contents).map_err(OutputError::io(&part))?;
    fs::rename(&part, &path).map_err(OutputError::io(path))
}
