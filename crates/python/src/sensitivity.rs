//! `soilcut.sensitivity`: the sensitivity study of `soilcut-study` as a
//! native handle (its runs, the whole study on threads, the analysis of
//! rows made elsewhere) and one run alone, which Python's executors make
//! in any process.

use crate::case::Case;
use crate::study::study_error;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use soilcut_study::no_progress;
use soilcut_study::sensitivity::{
    Method, Model, Plan, Point, Range, Run, RunRow, Sensitivity, SensitivityResult,
};
use std::path::PathBuf;

/// A run as Python hands it to a worker: `(tornado, point, k, set)`, the
/// point's index among the design's (tornado False) or the tornado's.
type RunTuple = (bool, usize, i32, Vec<(String, f64)>);

/// A run's row as a worker hands it back: `(point, k, outputs, error,
/// wall_time_s)`, outputs None where the run failed and error None where
/// it did not.
type RowTuple = (usize, i32, Option<Vec<f64>>, Option<String>, f64);

/// A checked study and its plan (the extension's side of
/// `soilcut.sensitivity`).
#[pyclass(frozen, module = "soilcut._soilcut")]
pub struct SensitivityStudy {
    study: Sensitivity,
    plan: Plan,
}

/// One varied key: `"lo:hi"` as `--vary` takes it, or a pair `(lo, hi)`.
fn range(key: &str, spec: &Bound<'_, PyAny>) -> PyResult<Range> {
    let py = spec.py();
    let made = if let Ok(text) = spec.cast::<PyString>() {
        Range::parse(&format!("{key}={text}"))
    } else if let Ok((lo, hi)) = spec.extract::<(f64, f64)>() {
        Range::new(key, lo, hi)
    } else {
        return Err(PyValueError::new_err(format!(
            "vary {key}: expected a range (lo, hi) or \"lo:hi\""
        )));
    };
    made.map_err(|e| study_error(py, e))
}

#[pymethods]
impl SensitivityStudy {
    /// The study of `case` over `vary` (key → range), checked and planned:
    /// `samples` None takes the method's default.
    #[new]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        case: &Bound<'_, PyAny>,
        vary: Vec<(String, Bound<'_, PyAny>)>,
        method: &str,
        samples: Option<usize>,
        levels: usize,
        second_order: bool,
        members: usize,
        dummy: bool,
        seed: u64,
        jobs: usize,
    ) -> PyResult<Self> {
        let method = Method::named(method, levels, second_order).map_err(|e| study_error(py, e))?;
        let study = Sensitivity {
            model: Model::Case(Case::extract(case)?.get().base(py)?),
            ranges: vary
                .iter()
                .map(|(key, spec)| range(key, spec))
                .collect::<PyResult<_>>()?,
            method,
            samples: samples.unwrap_or(method.default_samples()),
            members,
            dummy,
            seed,
            jobs,
        };
        let plan = study.plan().map_err(|e| study_error(py, e))?;
        Ok(SensitivityStudy { study, plan })
    }

    /// Every run, in the order of samples.csv then tornado.csv.
    fn runs(&self) -> Vec<RunTuple> {
        self.plan.runs.iter().map(run_tuple).collect()
    }

    /// The whole study on the study's `jobs` threads, as `soilcut
    /// sensitivity` makes it: see `analyse` for what it returns.
    #[pyo3(signature = (pictures=None))]
    fn run<'py>(&self, py: Python<'py>, pictures: Option<PathBuf>) -> PyResult<Bound<'py, PyDict>> {
        let result = py
            .detach(|| self.study.run(&no_progress))
            .map_err(|e| study_error(py, e))?;
        finished(py, &result, pictures)
    }

    /// The study from the rows of its runs, in the order of `runs`: a dict
    /// of `files` (name → text, as `soilcut sensitivity` writes them) and
    /// `pictures` (the paths drawn into the folder `pictures`, if given).
    #[pyo3(signature = (rows, pictures=None))]
    fn analyse<'py>(
        &self,
        py: Python<'py>,
        rows: Vec<RowTuple>,
        pictures: Option<PathBuf>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let rows = rows.into_iter().map(run_row).collect();
        let result = py
            .detach(|| self.study.analyse(self.plan.clone(), rows))
            .map_err(|e| study_error(py, e))?;
        finished(py, &result, pictures)
    }
}

/// The files of `result` and the pictures drawn into `folder`, if given.
fn finished<'py>(
    py: Python<'py>,
    result: &SensitivityResult,
    folder: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let drawn = match folder {
        Some(dir) => py
            .detach(|| {
                std::fs::create_dir_all(&dir)
                    .map_err(|e| format!("{}: {e}", dir.display()))
                    .and_then(|()| result.draw(&dir).map_err(|e| e.to_string()))
            })
            .map_err(|e| PyValueError::new_err(format!("pictures {e}")))?,
        None => Vec::new(),
    };
    let files = PyDict::new(py);
    for (name, text) in result.files() {
        files.set_item(name, text)?;
    }
    let out = PyDict::new(py);
    out.set_item("files", files)?;
    out.set_item("pictures", drawn)?;
    Ok(out)
}

fn run_tuple(run: &Run) -> RunTuple {
    let tornado = matches!(run.point, Point::Tornado(_));
    (tornado, run.point.index(), run.k, run.set.clone())
}

fn run_row((point, k, outputs, error, wall_time_s): RowTuple) -> RunRow {
    RunRow {
        point,
        k,
        outcome: outputs.ok_or_else(|| error.unwrap_or_default()),
        wall_time_s,
    }
}

/// One run of a sensitivity study of `case` (from `SensitivityStudy.runs`),
/// without the interpreter: its row for `SensitivityStudy.analyse`. The
/// same in any process.
#[pyfunction]
pub fn sensitivity_run(
    py: Python<'_>,
    case: &Bound<'_, PyAny>,
    run: RunTuple,
) -> PyResult<RowTuple> {
    let (tornado, i, k, set) = run;
    let point = if tornado {
        Point::Tornado(i)
    } else {
        Point::Design(i)
    };
    let model = Model::Case(Case::extract(case)?.get().base(py)?);
    let row = py.detach(|| model.run(&Run { point, k, set }));
    let (outputs, error) = match row.outcome {
        Ok(v) => (Some(v), None),
        Err(e) => (None, Some(e)),
    };
    Ok((row.point, row.k, outputs, error, row.wall_time_s))
}
