//! The files of a finished run read back (for `soilcut plot` and
//! `soilcut compare`), and `frames.csv`, the surfaces captured during a run.

use crate::case_file::read_case;
use crate::columns::Columns;
use soilcut_model::{Case, ProfilePoint};
use std::fmt;
use std::path::{Path, PathBuf};

/// Columns of `frames.csv`, in order.
pub const FRAMES_HEADER: &str = "frame,step,u,x,y,accumulated_shear";

/// Rows of one frame in `frames.csv` at most: the surface is thinned to
/// every k-th node to stay under it.
pub const FRAME_ROWS: usize = 400;

/// The ground surface after `step` increments (0: before the first).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFrame {
    /// Increments done.
    pub step: usize,
    /// Blade position: the tip is at (u, −t), t the tip's depth there
    /// (`blade.depth` but on a depth path; the face, at x = u for a
    /// vertical blade, leans back from the tip for an inclined one).
    pub u: f64,
    /// The surface from where the face meets it to the end of the domain.
    pub surface: Vec<ProfilePoint>,
}

/// `frames.csv`: every frame's surface from the face to one blade depth
/// beyond the farthest point that any frame shows visibly moved (by more
/// than 10⁻³ d) and at least two depths ahead of the blade, thinned to at
/// most [`FRAME_ROWS`] rows per frame (every k-th node, the face always kept).
pub fn frames_csv(frames: &[SurfaceFrame], depth: f64) -> String {
    frames_columns(frames, depth).csv()
}

/// The numbers of [`frames_csv`] (columns [`FRAMES_HEADER`]).
pub fn frames_columns(frames: &[SurfaceFrame], depth: f64) -> Columns {
    let mut far: f64 = 0.0;
    for f in frames {
        far = far.max(f.u + depth);
        if let Some(p) = f.surface.iter().rev().find(|p| p.y.abs() > 1e-3 * depth) {
            far = far.max(p.x);
        }
    }
    let end = far + depth;
    let mut out = Columns::new(FRAMES_HEADER);
    for (k, f) in frames.iter().enumerate() {
        let shown = f.surface.iter().take_while(|p| p.x <= end).count();
        let stride = shown.div_ceil(FRAME_ROWS).max(1);
        for p in f.surface[..shown].iter().step_by(stride) {
            out.push(&[k as f64, f.step as f64, f.u, p.x, p.y, p.accumulated_shear]);
        }
    }
    out
}

/// Why the files of a run could not be read.
#[derive(Debug)]
pub struct RunFilesError {
    /// The file that could not be read.
    pub path: PathBuf,
    /// What is wrong with it.
    pub message: String,
}

impl RunFilesError {
    pub(crate) fn new(path: &Path, message: impl ToString) -> Self {
        RunFilesError {
            path: path.to_path_buf(),
            message: crate::error::one_line(&message.to_string()),
        }
    }
}

impl fmt::Display for RunFilesError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for RunFilesError {}

/// A CSV file of numbers with a header line, read by column name.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    path: PathBuf,
    header: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Table {
    /// Reads `path`: a header of column names, then rows of numbers.
    pub fn read(path: &Path) -> Result<Table, RunFilesError> {
        let text = std::fs::read_to_string(path).map_err(|e| RunFilesError::new(path, e))?;
        Table::parse(path, &text)
    }

    /// Parses `text` (`path` names it in errors).
    pub fn parse(path: &Path, text: &str) -> Result<Table, RunFilesError> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let header: Vec<String> = lines
            .next()
            .ok_or_else(|| RunFilesError::new(path, "empty file: expected a header line"))?
            .1
            .split(',')
            .map(|c| c.trim().to_string())
            .collect();
        let mut rows = Vec::new();
        for (i, line) in lines {
            let row = line
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| RunFilesError::new(path, format!("line {}: {e}", i + 1)))?;
            if row.len() != header.len() {
                let message = format!(
                    "line {}: {} values for {} columns",
                    i + 1,
                    row.len(),
                    header.len()
                );
                return Err(RunFilesError::new(path, message));
            }
            rows.push(row);
        }
        Ok(Table {
            path: path.to_path_buf(),
            header,
            rows,
        })
    }

    /// The column names, in order.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether the table has no rows.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The values of column `name`, row by row.
    pub fn column(&self, name: &str) -> Result<Vec<f64>, RunFilesError> {
        let i = self
            .header
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| RunFilesError::new(&self.path, format!("no column `{name}`")))?;
        Ok(self.rows.iter().map(|r| r[i]).collect())
    }

    /// The columns named in `names`, in that order.
    pub fn columns<const N: usize>(
        &self,
        names: [&str; N],
    ) -> Result<[Vec<f64>; N], RunFilesError> {
        let mut out: [Vec<f64>; N] = std::array::from_fn(|_| Vec::new());
        for (slot, name) in out.iter_mut().zip(names) {
            *slot = self.column(name)?;
        }
        Ok(out)
    }

    /// The values of column `name`, or `None` if the table has no such
    /// column (a column added in a later version, absent from older runs).
    pub fn optional_column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.header.iter().position(|h| h == name)?;
        Some(self.rows.iter().map(|r| r[i]).collect())
    }
}

/// The files of a finished run: `case.resolved.toml`, `history.csv`,
/// `profile.csv` and, if present, `frames.csv`.
#[derive(Clone, Debug)]
pub struct FinishedRun {
    /// The run's folder.
    pub dir: PathBuf,
    /// The case, from `case.resolved.toml`.
    pub case: Case,
    /// `history.csv`, one row per increment.
    pub history: Table,
    /// `profile.csv`, the final surface.
    pub profile: Table,
    /// `frames.csv`, if the run wrote it (`None` for older runs).
    pub frames: Option<Table>,
}

/// Reads the files of the run in `dir`.
pub fn read_finished_run(dir: &Path) -> Result<FinishedRun, RunFilesError> {
    let case_path = dir.join("case.resolved.toml");
    if !case_path.is_file() {
        return Err(not_a_run(dir));
    }
    let case = read_case(&case_path, &[])
        .map_err(|e| RunFilesError::new(&case_path, e))?
        .case;
    let frames_path = dir.join("frames.csv");
    let frames = if frames_path.exists() {
        Some(Table::read(&frames_path)?)
    } else {
        None
    };
    Ok(FinishedRun {
        dir: dir.to_path_buf(),
        case,
        history: Table::read(&dir.join("history.csv"))?,
        profile: Table::read(&dir.join("profile.csv"))?,
        frames,
    })
}

/// A folder without the files of a run: say what it is not and what a run
/// folder is, rather than that one file of it is missing.
fn not_a_run(dir: &Path) -> RunFilesError {
    let what = if dir.is_dir() {
        "not a run folder"
    } else {
        "no such folder"
    };
    let ensemble = if dir.join("ensemble.csv").is_file() {
        " (an ensemble's members are its k-3 ... k+3 folders)"
    } else {
        ""
    };
    RunFilesError::new(
        dir,
        format!("{what}: a run folder is one `soilcut run` wrote, with case.resolved.toml, history.csv and profile.csv{ensemble}"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_reads_columns_by_name() {
        let t = Table::parse(Path::new("t.csv"), "u,force\n0,1.5\n2, 3e-1\n\n").unwrap();
        assert_eq!(t.len(), 2);
        assert_eq!(t.column("force").unwrap(), vec![1.5, 0.3]);
        assert!(t
            .column("beta")
            .unwrap_err()
            .message
            .contains("no column `beta`"));
        assert_eq!(t.optional_column("u"), Some(vec![0.0, 2.0]));
        assert_eq!(t.optional_column("depth"), None);
    }

    #[test]
    fn table_rejects_ragged_or_bad_rows() {
        let e = Table::parse(Path::new("t.csv"), "u,force\n0\n").unwrap_err();
        assert_eq!(e.message, "line 2: 1 values for 2 columns");
        let e = Table::parse(Path::new("t.csv"), "u,force\n0,x\n").unwrap_err();
        assert!(e.message.starts_with("line 2:"), "{}", e.message);
        assert!(Table::parse(Path::new("t.csv"), "").is_err());
    }

    #[test]
    fn frames_are_trimmed_and_thinned() {
        let point = |x: f64, y: f64| ProfilePoint {
            x,
            y,
            accumulated_shear: 0.0,
            unit_weight: 1.0,
            ridge_height: 0.0,
        };
        let surface: Vec<ProfilePoint> = (0..5000)
            .map(|i| point(i as f64 * 0.01, if i < 100 { 0.5 } else { 0.0 }))
            .collect();
        let frames = vec![SurfaceFrame {
            step: 3,
            u: 0.0,
            surface,
        }];
        let text = frames_csv(&frames, 10.0);
        let rows: Vec<&str> = text.lines().skip(1).collect();
        assert!(rows.len() <= FRAME_ROWS, "{}", rows.len());
        assert_eq!(rows[0], "0,3,0,0,0.5,0");
        let t = Table::parse(Path::new("f.csv"), &text).unwrap();
        let last_x = *t.column("x").unwrap().last().unwrap();
        assert!(
            (19.9..=20.0).contains(&last_x),
            "to 1 d beyond 1 d ahead of the face: {last_x}"
        );
    }
}
