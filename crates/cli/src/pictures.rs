//! The pictures of finished runs: their files read with `soilcut-io`,
//! drawn with `soilcut-plot`.

use soilcut_io::{read_finished_run, FinishedRun, RunFilesError, Table};
use soilcut_plot::{Frame, Increment, Measured, PlotError, RunData, SurfacePoint};
use std::path::{Path, PathBuf};

/// Where a run's pictures go, relative to its output folder.
pub const PLOTS_DIR: &str = "plots";
pub const ANIMATION: &str = "animation.gif";

/// A failure: reading the run's files (bad input) or drawing (I/O).
pub enum PictureError {
    Read(RunFilesError),
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

/// Overlays the force and β* curves of the runs in `dirs` (and a measured
/// curve, columns `u,force`) into `out`.
pub fn compare(dirs: &[PathBuf], measured: Option<&Path>, out: &Path) -> Result<(), PictureError> {
    let runs = dirs
        .iter()
        .map(|d| read_finished_run(d).and_then(|r| run_data(&r)))
        .collect::<Result<Vec<_>, _>>()?;
    let measured = match measured {
        Some(path) => Some(Measured {
            label: format!(
                "measured ({})",
                path.file_name().unwrap_or_default().to_string_lossy()
            ),
            points: soilcut_io::read_measured(path).map_err(|e| RunFilesError {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?,
        }),
        None => None,
    };
    soilcut_plot::draw_compare(&runs, measured.as_ref(), out)?;
    Ok(())
}

/// The columns of `table` named in `names`, in that order.
fn columns<const N: usize>(
    table: &Table,
    names: [&str; N],
) -> Result<[Vec<f64>; N], RunFilesError> {
    let mut out: [Vec<f64>; N] = std::array::from_fn(|_| Vec::new());
    for (slot, name) in out.iter_mut().zip(names) {
        *slot = table.column(name)?;
    }
    Ok(out)
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

/// What the pictures need of a finished run.
pub fn run_data(run: &FinishedRun) -> Result<RunData, RunFilesError> {
    let [step, u, force, beta, xe, ye] = columns(
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
    let history = (0..step.len())
        .map(|i| Increment {
            step: step[i] as usize,
            u: u[i],
            force_norm: force[i],
            beta_deg: beta[i],
            x_emergence: xe[i],
            y_emergence: ye[i],
        })
        .collect();
    let [x, y, shear] = columns(&run.profile, ["x", "y", "accumulated_shear"])?;
    let mut frames: Vec<Frame> = Vec::new();
    if let Some(table) = &run.frames {
        let [id, step, u, x, y, shear] =
            columns(table, ["frame", "step", "u", "x", "y", "accumulated_shear"])?;
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
    }
    let case = &run.case;
    Ok(RunData {
        title: case.title.clone(),
        depth: case.blade.depth,
        rake: case.blade.rake,
        unit_weight: case.soil.unit_weight,
        band_width: case.soil.band_width,
        history,
        profile: surface(&x, &y, &shear),
        frames,
    })
}
