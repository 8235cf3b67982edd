//! Studies of many runs (`soilcut-study`) and the analytical baselines.

use crate::case::Case;
use crate::convert::{arrays, from_toml, to_toml};
use crate::errors::{case_error, case_message, detached, python_words};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString, PyTuple};
use pyo3::IntoPyObjectExt;
use soilcut_io::{
    baselines, check_landscape_at, check_landscape_every, far_ties, landscape_at,
    landscape_columns, landscape_map as map_of, landscape_map_columns,
};
use soilcut_model::Simulation;
use soilcut_study::fit::{measured_width, Compare, Fit, FitResult, Method, Test};
use soilcut_study::sample::{Sample, Vary};
use soilcut_study::sweep::{check_keys, Sweep, SweepResult};
use soilcut_study::{no_progress, StudyError};

/// A study's error as Python's: a key's as `soilcut.CaseError`, the rest
/// in the Python arguments' words (`python_words`).
pub fn study_error(py: Python<'_>, e: StudyError) -> PyErr {
    match e {
        StudyError::Case(message) => case_message(py, python_words(&message)),
        StudyError::Key(e) => case_error(py, &e),
        e => PyValueError::new_err(python_words(&e.to_string())),
    }
}

/// One varied key: a spec string as `--vary` takes it (`lo:hi:n`, `lo:hi`,
/// `a,b,c`), a tuple `(lo, hi)` (sampled) or `(lo, hi, n)` (grid), or any
/// other sequence of values.
fn vary(key: &str, spec: &Bound<'_, PyAny>) -> PyResult<Vary> {
    let py = spec.py();
    let made = if let Ok(text) = spec.cast::<PyString>() {
        format!("{key}={text}").parse::<Vary>()
    } else if let Ok(t) = spec.cast::<PyTuple>() {
        let wrong = |what: &str, must: &str| {
            PyValueError::new_err(format!("vary {key}: {what} of (lo, hi, n) must be {must}"))
        };
        let number = |i: usize, what: &str| {
            let item = t.get_item(i)?;
            item.extract::<f64>().map_err(|_| wrong(what, "a number"))
        };
        match t.len() {
            2 => Vary::range(key, number(0, "lo")?, number(1, "hi")?),
            3 => Vary::grid(
                key,
                number(0, "lo")?,
                number(1, "hi")?,
                t.get_item(2)?
                    .extract::<usize>()
                    .map_err(|_| wrong("n", "a whole number >= 1"))?,
            ),
            n => {
                return Err(PyValueError::new_err(format!(
                    "vary {key}: a tuple is (lo, hi) or (lo, hi, n), not {n} items; give a list of values"
                )))
            }
        }
    } else {
        let items = spec.try_iter().map_err(|_| {
            PyValueError::new_err(format!(
                "vary {key}: expected a spec string, a tuple or a sequence of values"
            ))
        })?;
        let values = items
            .map(|item| to_toml(key, &item?))
            .collect::<PyResult<Vec<_>>>()?;
        Vary::list(key, values)
    };
    made.map_err(|e| study_error(py, e))
}

fn sweep_of(
    py: Python<'_>,
    case: &Bound<'_, PyAny>,
    varies: Vec<(String, Bound<'_, PyAny>)>,
    sample: &str,
    seed: u64,
    jobs: usize,
) -> PyResult<Sweep> {
    Ok(Sweep {
        base: Case::extract(case)?.get().base(py)?,
        varies: varies
            .iter()
            .map(|(k, spec)| vary(k, spec))
            .collect::<PyResult<_>>()?,
        sample: Sample::parse(sample, seed).map_err(|e| study_error(py, e))?,
        jobs,
        keep_runs: None,
    })
}

/// The values of every run of a sweep, one list per run.
type Points<'py> = Vec<Vec<Bound<'py, PyAny>>>;

/// The runs of a sweep: the varied keys and one list of values per run.
#[pyfunction]
pub fn sweep_points<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    varies: Vec<(String, Bound<'py, PyAny>)>,
    sample: &str,
    seed: u64,
) -> PyResult<(Vec<String>, Points<'py>)> {
    let sweep = sweep_of(py, case, varies, sample, seed, 1)?;
    let keys = sweep.varies.iter().map(|v| v.key.clone()).collect();
    let points = sweep.points().map_err(|e| study_error(py, e))?;
    let points = points
        .iter()
        .map(|p| p.iter().map(|v| from_toml(py, v)).collect())
        .collect::<PyResult<_>>()?;
    Ok((keys, points))
}

/// The table of `sweep.csv` as columns, in its order: `run` (whole
/// numbers), the varied keys' values, `status`, `error` (NaN where a run
/// did not fail, as pandas reads an empty field), then the figures as
/// float64 arrays ([`SweepResult::figure_columns`], NaN where a run
/// failed).
fn sweep_table<'py>(py: Python<'py>, result: &SweepResult) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let rows = &result.rows;
    out.set_item("run", rows.iter().map(|r| r.run).collect::<Vec<_>>())?;
    for (k, key) in result.keys.iter().enumerate() {
        let values = rows
            .iter()
            .map(|r| from_toml(py, &r.values[k]))
            .collect::<PyResult<Vec<_>>>()?;
        out.set_item(key, values)?;
    }
    let status: Vec<&str> = rows
        .iter()
        .map(|r| if r.outcome.is_ok() { "ok" } else { "failed" })
        .collect();
    out.set_item("status", status)?;
    let errors = rows
        .iter()
        .map(|r| match &r.outcome {
            Ok(_) => f64::NAN.into_py_any(py),
            Err(e) => e.into_py_any(py),
        })
        .collect::<PyResult<Vec<_>>>()?;
    out.set_item("error", errors)?;
    for (name, values) in arrays(py, &result.figure_columns())?.iter() {
        out.set_item(name, values)?;
    }
    Ok(out)
}

/// A whole sweep run on `jobs` threads (0: one per core), as the columns
/// of `sweep.csv` (see `sweep_table`).
#[pyfunction]
pub fn sweep_run<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    varies: Vec<(String, Bound<'py, PyAny>)>,
    sample: &str,
    seed: u64,
    jobs: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let sweep = sweep_of(py, case, varies, sample, seed, jobs)?;
    let result = py
        .detach(|| sweep.run(&no_progress))
        .map_err(|e| study_error(py, e))?;
    sweep_table(py, &result)
}

/// One run's values of `keys` as TOML values.
fn toml_values(keys: &[String], values: &[Bound<'_, PyAny>]) -> PyResult<Vec<toml::Value>> {
    keys.iter()
        .zip(values)
        .map(|(k, v)| to_toml(k, v))
        .collect()
}

/// Refuses `keys` that no run of `case` could set (unknown to the case
/// file), with `values` (one run's) as the probe: a sweep given its runs
/// (`samples`) checks them before the first, as a `vary` sweep does.
#[pyfunction]
pub fn sweep_check(
    py: Python<'_>,
    case: &Bound<'_, PyAny>,
    keys: Vec<String>,
    values: Vec<Bound<'_, PyAny>>,
) -> PyResult<()> {
    let values = toml_values(&keys, &values)?;
    let base = Case::extract(case)?.get().base(py)?;
    check_keys(&base, &keys, &values).map_err(|e| study_error(py, e))
}

/// Run `run` (from 1) of `total` of a sweep over `keys`: its row of
/// `sweep.csv` as columns of one value (see `sweep_table`) and its wall
/// time.
#[pyfunction]
pub fn sweep_row<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    keys: Vec<String>,
    values: Vec<Bound<'py, PyAny>>,
    run: usize,
    total: usize,
) -> PyResult<(Bound<'py, PyDict>, f64)> {
    if run == 0 || run > total {
        return Err(PyValueError::new_err(format!(
            "run {run}: runs are numbered from 1 to total = {total}"
        )));
    }
    let values = toml_values(&keys, &values)?;
    let sweep = Sweep {
        base: Case::extract(case)?.get().base(py)?,
        varies: vec![],
        sample: Sample::Grid,
        jobs: 1,
        keep_runs: None,
    };
    let row = py
        .detach(|| sweep.run_point(&keys, run, total, values))
        .map_err(|e| study_error(py, e))?;
    let wall_time_s = row.wall_time_s;
    let result = SweepResult {
        keys,
        rows: vec![row],
    };
    Ok((sweep_table(py, &result)?, wall_time_s))
}

/// A calibration as `soilcut fit` makes it: the best values, their
/// intervals and verdicts, the RMS errors, and the files `soilcut fit`
/// writes (`fit.md`, `fit.csv`, `curves.csv`, `profiles.csv`, `search.csv`,
/// `best.toml`).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    measured: Vec<(f64, f64)>,
    width: Option<f64>,
    free: Vec<String>,
    bounds: Vec<(String, f64, f64)>,
    objective: &str,
    method: &str,
    budget: (usize, usize, u64, usize),
    seed: u64,
    jobs: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let case = Case::extract(case)?;
    let case = case.get();
    let title = case.loaded.case.title.clone();
    let w = measured_width(width, &case.loaded.case, "width").map_err(|e| study_error(py, e))?;
    let compare: Compare = objective.parse().map_err(|e| study_error(py, e))?;
    let method: Method = method.parse().map_err(|e| study_error(py, e))?;
    let (evaluations, population, polish_iterations, profile_grid) = budget;
    let weights = vec![1.0; measured.len()];
    let fit = Fit {
        tests: vec![Test::per_width(
            "measured",
            case.base(py)?,
            &measured,
            weights,
            w,
        )],
        free,
        bounds,
        compare,
        method,
        evaluations,
        population,
        seed,
        polish_iterations,
        profile_grid,
        jobs,
    };
    let r = py
        .detach(|| fit.run(&no_progress))
        .map_err(|e| study_error(py, e))?;
    fit_dict(py, &r, &title)
}

/// The dict `fit` returns: per key its best value, interval and verdict,
/// the RMS errors, and the files by name.
fn fit_dict<'py>(py: Python<'py>, r: &FitResult, title: &str) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let (best, intervals, verdicts) = (PyDict::new(py), PyDict::new(py), PyDict::new(py));
    for (j, p) in r.params.iter().enumerate() {
        best.set_item(&p.key, r.best.x[j])?;
        intervals.set_item(&p.key, r.interval_text(j))?;
        verdicts.set_item(&p.key, r.verdict(j))?;
    }
    out.set_item("best", best)?;
    out.set_item("intervals", intervals)?;
    out.set_item("verdicts", verdicts)?;
    out.set_item("best_rms", r.best.rms)?;
    out.set_item("start_rms", r.start.rms)?;
    let files = PyDict::new(py);
    for (name, text) in r.files(title) {
        files.set_item(name, text)?;
    }
    out.set_item("files", files)?;
    Ok(out)
}

/// The analytical baselines of the case's initial flat ground, as
/// `soilcut analytic` prints them and `summary.json` holds them
/// (`soilcut_io::baselines`): `rankine`, `coulomb` and `fee`, each a dict
/// (or None where no wedge is admissible), in the library's order.
#[pyfunction]
pub fn analytic<'py>(py: Python<'py>, case: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let case = Case::extract(case)?.get().loaded.case.clone();
    let text = serde_json::to_string(&baselines(&case)).expect("baselines serialise");
    // Python's json keeps the fields' order and reads every float back
    // exactly (serde_json writes the shortest round-trip form).
    let out = PyModule::import(py, "json")?
        .call_method1("loads", (text,))?
        .cast_into::<PyDict>()?;
    if case.blade.width.is_some() && !out.contains("mckyes_ali")? {
        // summary.json leaves out a blade's baseline without an admissible
        // wedge; Python has said None there.
        out.set_item("mckyes_ali", py.None())?;
    }
    Ok(out)
}

/// The map of `soilcut landscape --every`: landscapes at u/d = 0, `every`,
/// 2 `every`, … binned by distance ahead of the tip, as
/// `(landscape_map.csv's columns, how many hold a far tie)`.
#[pyfunction]
pub fn landscape_map<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    every: f64,
) -> PyResult<(Bound<'py, PyDict>, usize)> {
    let native = Case::extract(case)?;
    let case = &native.get().loaded.case;
    check_landscape_every(case, "every", every).map_err(PyValueError::new_err)?;
    let mut sim = Simulation::start(case);
    let columns = detached(py, || map_of(&mut sim, every))?;
    Ok((
        arrays(py, &landscape_map_columns(&columns))?,
        far_ties(&columns),
    ))
}

/// The landscape of `soilcut landscape --at`: every candidate mechanism at
/// the first increment evaluated at u ≥ `at`·d, as `(u, landscape.csv's
/// columns)`.
#[pyfunction]
pub fn landscape<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    at: f64,
) -> PyResult<(f64, Bound<'py, PyDict>)> {
    let native = Case::extract(case)?;
    let case = &native.get().loaded.case;
    check_landscape_at(case, "at", at).map_err(PyValueError::new_err)?;
    let mut sim = Simulation::start(case);
    let candidates = detached(py, || landscape_at(&mut sim, at))?;
    let u = sim.blade_position();
    Ok((
        u,
        arrays(py, &landscape_columns(&candidates, u, case.blade.depth))?,
    ))
}
