//! The files of a finished run read back (for `soilcut plot` and
//! `soilcut compare`), and `frames.csv`, the surfaces captured during a run.

use crate::case_file::read_case;
use crate::columns::Columns;
use crate::error::RunFilesError;
use soilcut_model::{Case, ProfilePoint};
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

/// The files of a finished run: `case.resolved.toml`, `history.csv`,
/// `profile.csv` and, if present, `frames.csv`.
#[derive(Clone, Debug)]
pub struct FinishedRun {
    /// The run's folder.
    pub dir: PathBuf,
    /// The case, from `case.resolved.toml`.
    pub case: Case,
    /// `history.csv`, one row per increment.
    pub history: Columns,
    /// `profile.csv`, the final surface.
    pub profile: Columns,
    /// `frames.csv`, if the run wrote it (`None` for older runs).
    pub frames: Option<Columns>,
}

/// Reads the files of the run in `dir`.
pub fn read_finished_run(dir: &Path) -> Result<FinishedRun, RunFilesError> {
    let case_path = dir.join("case.resolved.toml");
    if !case_path.is_file() {
        return Err(not_a_run(dir));
    }
    let case = read_case(&case_path, &[])
        .map_err(|e| RunFilesError::new(&case_path, e))?
        .case
        .into_case();
    let frames_path = dir.join("frames.csv");
    let frames = if frames_path.exists() {
        Some(Columns::read(&frames_path)?)
    } else {
        None
    };
    Ok(FinishedRun {
        dir: dir.to_path_buf(),
        case,
        history: Columns::read(&dir.join("history.csv"))?,
        profile: Columns::read(&dir.join("profile.csv"))?,
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
        let t = Columns::parse("f.csv", &text).unwrap();
        let last_x = *t.column("x").unwrap().last().unwrap();
        assert!(
            (19.9..=20.0).contains(&last_x),
            "to 1 d beyond 1 d ahead of the face: {last_x}"
        );
    }
}
