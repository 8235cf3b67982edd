//! The pictures of finished runs: their files read back and drawn with
//! `soilcut-plot`. Every front end writes a run's folder through
//! [`write_run_dir`], so the folders are identical.

use crate::columns::Columns;
use crate::error::{OutputError, RunFilesError};
use crate::finished::{read_finished_run, FinishedRun};
use crate::place::{OutputDir, Published};
use soilcut_plot::{Frame, Increment, Measured, PlotError, RunData, SurfacePoint};
use std::path::{Path, PathBuf};

/// Where a run's pictures go, relative to its output folder.
pub const PLOTS_DIR: &str = "plots";
pub const ANIMATION: &str = "animation.gif";

/// A failure: reading the run's files (bad input) or drawing (I/O).
#[derive(Debug)]
pub enum PictureError {
    /// The run's files could not be read.
    Read(RunFilesError),
    /// A picture could not be drawn or written.
    Draw(PlotError),
}

impl From<RunFilesError> for PictureError {
    fn from(e: RunFilesError) -> Self {
        PictureError::Read(e)
    }
}

impl From<PlotError> for PictureError {
    fn from(e: PlotError) -> Self {
        PictureError::Draw(e)
    }
}

/// Reads the run in `dir` and draws its pictures into `dir/plots` and, if
/// it has `frames.csv`, `dir/animation.gif`. Returns the files written.
pub fn draw_run_dir(dir: &Path) -> Result<Vec<PathBuf>, PictureError> {
    let run = run_data(&read_finished_run(dir)?)?;
    let mut written = soilcut_plot::draw_run(&run, &dir.join(PLOTS_DIR))?;
    if !run.frames.is_empty() {
        let path = dir.join(ANIMATION);
        soilcut_plot::draw_animation(&run, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// Writes a run's output folder: `files` and, if `pictures`, the pictures
/// drawn from them (placed together, atomically, by [`OutputDir`]).
pub fn write_run_dir(
    out: &Path,
    files: &[(&str, String)],
    force: bool,
    pictures: bool,
) -> Result<(), OutputError> {
    write_run_into(OutputDir::claim(out, force)?, files, pictures).map(drop)
}

/// [`write_run_dir`] into a folder claimed before the run.
pub fn write_run_into(
    out: OutputDir,
    files: &[(&str, String)],
    pictures: bool,
) -> Result<Published, OutputError> {
    out.write_then(files, |staged| {
        if pictures {
            draw_run_dir(staged).map_err(|e| {
                let message = match e {
                    PictureError::Read(e) => e.to_string(),
                    PictureError::Draw(e) => e.message,
                };
                OutputError::Io {
                    path: staged.to_path_buf(),
                    source: std::io::Error::other(message),
                }
            })?;
        }
        Ok(())
    })
}

/// Overlays the force and β* curves of the runs in `dirs` (and a measured
/// curve, columns `u,force`) into `out`. The legend names each run by its
/// case title, or by its folder where titles are equal.
pub fn compare(dirs: &[PathBuf], measured: Option<&Path>, out: &Path) -> Result<(), PictureError> {
    let mut runs = dirs
        .iter()
        .map(|d| read_finished_run(d).and_then(|r| run_data(&r)))
        .collect::<Result<Vec<_>, _>>()?;
    label_by_folder(&mut runs, dirs);
    let measured = match measured {
        Some(path) => Some(Measured {
            label: format!(
                "measured ({})",
                path.file_name().unwrap_or_default().to_string_lossy()
            ),
            points: crate::measured::read_measured(path).map_err(|e| RunFilesError {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?,
        }),
        None => None,
    };
    soilcut_plot::draw_compare(&runs, measured.as_ref(), out)?;
    Ok(())
}

/// Where two runs share a title, each run's legend entry becomes its
/// folder, shortened to the last components that tell it from the others
/// (`out/original`, `/home/me/out/fine`: `original`, `fine`), so that runs
/// of one case can be told apart without paths as long as the picture.
fn label_by_folder(runs: &mut [RunData], dirs: &[PathBuf]) {
    let titles: Vec<String> = runs.iter().map(|r| r.title.clone()).collect();
    let shared: Vec<bool> = titles
        .iter()
        .map(|t| titles.iter().filter(|u| *u == t).count() > 1)
        .collect();
    let folders: Vec<&PathBuf> = dirs
        .iter()
        .zip(&shared)
        .filter(|(_, s)| **s)
        .map(|(d, _)| d)
        .collect();
    for ((run, dir), shared) in runs.iter_mut().zip(dirs).zip(shared) {
        if shared {
            run.title = short_folder(dir, &folders);
        }
    }
}

/// The last components of `dir`, as few as tell it from the other
/// `folders` (all of it if none do: the same folder given twice).
fn short_folder(dir: &Path, folders: &[&PathBuf]) -> String {
    let tail = |d: &Path, n: usize| -> Vec<String> {
        let parts: Vec<String> = d
            .components()
            .filter(|c| matches!(c, std::path::Component::Normal(_)))
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        parts[parts.len().saturating_sub(n)..].to_vec()
    };
    let depth = dir.components().count().max(1);
    let n = (1..=depth)
        .find(|&n| {
            let mine = tail(dir, n);
            folders
                .iter()
                .filter(|f| f.as_path() != dir)
                .all(|f| tail(f, n) != mine)
        })
        .unwrap_or(depth);
    match tail(dir, n).join("/") {
        label if label.is_empty() => dir.display().to_string(),
        label => label,
    }
}

fn surface(x: &[f64], y: &[f64], shear: &[f64]) -> Vec<SurfacePoint> {
    (0..x.len())
        .map(|i| SurfacePoint {
            x: x[i],
            y: y[i],
            accumulated_shear: shear[i],
        })
        .collect()
}

/// The columns `names` of a finished run's file `name`, or an error
/// naming the file and the missing column.
fn columns<'a, const N: usize>(
    run: &FinishedRun,
    name: &str,
    file: &'a Columns,
    names: [&str; N],
) -> Result<[&'a [f64]; N], RunFilesError> {
    file.columns(names)
        .map_err(|message| RunFilesError::new(&run.dir.join(name), message))
}

/// The surfaces of `frames.csv`, one frame per run of equal `frame`.
fn frames(run: &FinishedRun, table: &Columns) -> Result<Vec<Frame>, RunFilesError> {
    let [id, step, u, x, y, shear] = columns(
        run,
        "frames.csv",
        table,
        ["frame", "step", "u", "x", "y", "accumulated_shear"],
    )?;
    let mut frames = Vec::new();
    let mut start = 0;
    for end in 1..=id.len() {
        if end == id.len() || id[end] != id[start] {
            frames.push(Frame {
                step: step[start] as usize,
                u: u[start],
                surface: surface(&x[start..end], &y[start..end], &shear[start..end]),
            });
            start = end;
        }
    }
    Ok(frames)
}

/// What the pictures need of a finished run.
pub fn run_data(run: &FinishedRun) -> Result<RunData, RunFilesError> {
    let [step, u, force, beta, xe, ye] = columns(
        run,
        "history.csv",
        &run.history,
        [
            "step",
            "u",
            "force_norm",
            "beta_deg",
            "x_emergence",
            "y_emergence",
        ],
    )?;
    // Runs from before depth paths have no `depth` column: the tip was at
    // blade.depth throughout.
    let depth = match run.history.column("depth") {
        Some(depth) => depth.to_vec(),
        None => vec![run.case.blade.depth; step.len()],
    };
    let history = (0..step.len())
        .map(|i| Increment {
            step: step[i] as usize,
            u: u[i],
            force_norm: force[i],
            beta_deg: beta[i],
            x_emergence: xe[i],
            y_emergence: ye[i],
            depth: depth[i],
        })
        .collect();
    let [x, y, shear] = columns(
        run,
        "profile.csv",
        &run.profile,
        ["x", "y", "accumulated_shear"],
    )?;
    let frames = match &run.frames {
        Some(table) => frames(run, table)?,
        None => Vec::new(),
    };
    // Runs from before finite widths have no side heaps.
    let ridges = match run.profile.column("ridge_height") {
        Some(h) if h.iter().any(|&v| v > 0.0) => x.iter().copied().zip(h.iter().copied()).collect(),
        _ => Vec::new(),
    };
    let case = &run.case;
    Ok(RunData {
        title: case.title.clone(),
        depth: case.blade.depth,
        rake: case.blade.rake,
        unit_weight: case.soil.unit_weight,
        band_width: case.soil.band_width,
        history,
        profile: surface(x, y, shear),
        frames,
        ridges,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    #[test]
    fn folders_are_named_by_as_few_last_components_as_tell_them_apart() {
        let labels = |dirs: &[&str]| -> Vec<String> {
            let dirs: Vec<PathBuf> = dirs.iter().map(PathBuf::from).collect();
            let folders: Vec<&PathBuf> = dirs.iter().collect();
            dirs.iter().map(|d| short_folder(d, &folders)).collect()
        };
        assert_eq!(
            labels(&["out/original", "/home/me/out/fine/"]),
            ["original", "fine"]
        );
        assert_eq!(labels(&["/a/x/k-1", "/a/y/k-1"]), ["x/k-1", "y/k-1"]);
        assert_eq!(labels(&["out/a", "./out/a"]), ["out/a", "out/a"]);
        assert_eq!(labels(&["."]), ["."]);
    }

    /// A finished run of `cases/paper/original.toml` (d = 20) with two
    /// increments, `history` its history.csv.
    fn finished(history: &str) -> (tempfile::TempDir, FinishedRun) {
        let tmp = tempfile::tempdir().unwrap();
        let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/paper/original.toml");
        fs::copy(case, tmp.path().join("case.resolved.toml")).unwrap();
        fs::write(tmp.path().join("history.csv"), history).unwrap();
        fs::write(
            tmp.path().join("profile.csv"),
            "x,y,accumulated_shear,unit_weight\n0.04,0,0,1\n",
        )
        .unwrap();
        let run = read_finished_run(tmp.path()).unwrap();
        (tmp, run)
    }

    const OLD: &str = "step,u,u_over_d,force,force_norm,force_h,force_v,beta_deg,\
        x_emergence,mass,y_emergence,friction_deg,slip,dilation_deg,dilation_area";

    #[test]
    fn the_depth_column_is_read_and_older_runs_are_at_blade_depth() {
        let (_tmp, run) = finished(&format!(
            "{OLD},depth\n1,0,0,1,1,1,0,20,50,1,0,35,0.1,0,0,10\n\
             2,0.04,0.002,1,1,1,0,20,50,1,0,35,0.1,0,0,10.01\n"
        ));
        let data = run_data(&run).unwrap();
        let depths: Vec<f64> = data.history.iter().map(|h| h.depth).collect();
        assert_eq!(depths, [10.0, 10.01]);
        assert_eq!(data.depth, 20.0, "the reference depth");

        let (_tmp, run) = finished(&format!(
            "{OLD}\n1,0,0,1,1,1,0,20,50,1,0,35,0.1,0,0\n\
             2,0.04,0.002,1,1,1,0,20,50,1,0,35,0.1,0,0\n"
        ));
        let data = run_data(&run).unwrap();
        let depths: Vec<f64> = data.history.iter().map(|h| h.depth).collect();
        assert_eq!(depths, [20.0, 20.0], "blade.depth without the column");
    }
}
