//! The runs a sensitivity study makes, each described by what it sets, so
//! that any process can make one alone ([`Model::run`]) and hand its row
//! back for the analysis ([`Sensitivity::analyse`](super::Sensitivity)).

use super::tornado::{self, TornadoPoint};
use super::{design, outputs, Method, Model, Sensitivity};
use crate::ensemble::{member_offsets, Perturbation};
use crate::error::StudyError;
use crate::run::{override_of, BaseCase};
use soilcut_io::Override;

/// Which point a run belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Point {
    /// Design point i, from 0, in the design's order.
    Design(usize),
    /// Tornado point i, from 0 ([`tornado::points`]' order).
    Tornado(usize),
}

impl Point {
    /// Its index among the design's points or the tornado's.
    pub fn index(self) -> usize {
        match self {
            Point::Design(i) | Point::Tornado(i) => i,
        }
    }
}

/// One run of a study: member k of a point, and the inputs it sets.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// Its point.
    pub point: Point,
    /// Member k (0 without members).
    pub k: i32,
    /// The inputs and their values: a design point's keys (a test
    /// function's every input, [`DUMMY`](super::DUMMY) too), a tornado
    /// point's one key, or none (the case as it is).
    pub set: Vec<(String, f64)>,
}

/// A made run's row: member k of a point of the design or the tornado,
/// and its outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct RunRow {
    /// The point's index, from 0, among the design's or the tornado's.
    pub point: usize,
    /// Member k (0 without members).
    pub k: i32,
    /// The outputs ([`OUTPUTS`](super::OUTPUTS), then the unit windows', or `f`), or why the run failed.
    pub outcome: Result<Vec<f64>, String>,
    /// Wall time of the simulation, s.
    pub wall_time_s: f64,
}

/// A study's design and its runs, before any is made.
#[derive(Clone, Debug)]
pub struct Plan {
    /// The design in the unit cube, one row per point.
    pub unit: Vec<Vec<f64>>,
    /// The inputs' values of each point.
    pub values: Vec<Vec<f64>>,
    /// The tornado's points (none for a test function).
    pub tornado: Vec<TornadoPoint>,
    /// Every run: the design's, point by point, members in the order of
    /// k, then the tornado's likewise.
    pub runs: Vec<Run>,
    /// The ensembles' rule at the case's own values, if K > 1 (for
    /// summary.json; each point takes it at its own values).
    pub perturbation: Option<String>,
}

impl Plan {
    /// The runs of the design points (the rest are the tornado's).
    pub fn design_runs(&self) -> usize {
        self.runs
            .iter()
            .filter(|r| matches!(r.point, Point::Design(_)))
            .count()
    }
}

impl Sensitivity {
    /// The study's plan, after [`check`](Sensitivity::check): the design
    /// and every run, in the order of samples.csv then tornado.csv.
    pub fn plan(&self) -> Result<Plan, StudyError> {
        self.check()?;
        let (unit, values) = self.design();
        let tornado = match self.model {
            Model::Case(_) => tornado::points(self.ranges.len()),
            Model::Function(_) => Vec::new(),
        };
        let ks = if self.members > 1 {
            member_offsets(self.members)
        } else {
            vec![0]
        };
        // A case's runs set the varied keys; a function reads every input.
        let names: Vec<String> = match self.model {
            Model::Case(_) => self.ranges.iter().map(|r| r.key.clone()).collect(),
            Model::Function(_) => self.keys(),
        };
        let design = values.iter().enumerate().map(|(i, v)| {
            let set: Vec<(String, f64)> = names.iter().cloned().zip(v.iter().copied()).collect();
            (Point::Design(i), set)
        });
        let ends = tornado.iter().enumerate().map(|(i, t)| {
            let set = t.setting(&self.ranges).map(|(key, v)| (key.to_string(), v));
            (Point::Tornado(i), set.into_iter().collect())
        });
        let runs: Vec<Run> = design
            .chain(ends)
            .flat_map(|(point, set)| {
                ks.iter().map(move |&k| Run {
                    point,
                    k,
                    set: set.clone(),
                })
            })
            .collect();
        if let Model::Case(base) = &self.model {
            check_points(base, &runs)?;
        }
        Ok(Plan {
            unit,
            values,
            tornado,
            runs,
            perturbation: self.perturbation()?.map(|p| p.rule()),
        })
    }

    /// The ensembles' rule at the case's own values, if K > 1: refused
    /// before any run if the case has none.
    fn perturbation(&self) -> Result<Option<Perturbation>, StudyError> {
        match &self.model {
            Model::Case(base) if self.members > 1 => Ok(Some(Perturbation::of(&base.load(&[])?)?)),
            _ => Ok(None),
        }
    }

    /// The design: in the unit cube, and scaled to the keys' ranges
    /// (`dummy` over [0, 1]).
    fn design(&self) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let d = self.keys().len();
        let unit = match self.method {
            Method::Morris { levels } => design::morris(d, self.samples, levels, self.seed),
            Method::Sobol { second_order } => {
                design::saltelli(d, self.samples, second_order, self.seed)
            }
        };
        let scale = |row: &Vec<f64>| {
            row.iter()
                .enumerate()
                .map(|(j, u)| match self.ranges.get(j) {
                    Some(r) => r.lo + (r.hi - r.lo) * u,
                    None => *u,
                })
                .collect()
        };
        let values = unit.iter().map(scale).collect();
        (unit, values)
    }
}

impl Model {
    /// Makes `run`: its outputs ([`OUTPUTS`](super::OUTPUTS), then the
    /// unit windows', or a test function's `f`) or why it failed, and its
    /// wall time (s). A function of the model and the run alone: any
    /// thread or process gives the same row.
    pub fn run(&self, run: &Run) -> RunRow {
        let (outcome, wall_time_s) = match self {
            Model::Function(f) => {
                let x: Vec<f64> = run.set.iter().map(|(_, v)| *v).collect();
                (Ok(vec![f.value(&x)]), 0.0)
            }
            Model::Case(base) => run_member(base, &run.set, run.k),
        };
        RunRow {
            point: run.point.index(),
            k: run.k,
            outcome,
            wall_time_s,
        }
    }
}

/// Refuses, before any run, the first point of the design or the tornado
/// whose values make no valid case (φr > φp where the ranges of both
/// overlap, a band wider than the depth): the ranges' box must hold valid
/// cases only, or the study would stop at that point's run.
fn check_points(base: &BaseCase, runs: &[Run]) -> Result<(), StudyError> {
    let mut last = None;
    for run in runs {
        if last == Some(run.point) {
            continue;
        }
        last = Some(run.point);
        let overrides = overrides_of(&run.set).map_err(StudyError::Spec)?;
        if let Err(e) = base.load(&overrides) {
            let at: Vec<String> = run.set.iter().map(|(k, v)| format!("{k}={v}")).collect();
            return Err(StudyError::Spec(format!(
                "--vary: the point {} of the design is no valid case ({e}): narrow the \
                 ranges so that every combination of them is one",
                at.join(", ")
            )));
        }
    }
    Ok(())
}

/// The overrides that set the keys `set` to their values.
fn overrides_of(set: &[(String, f64)]) -> Result<Vec<Override>, String> {
    set.iter()
        .map(|(key, v)| override_of(key, &toml::Value::Float(*v)))
        .collect()
}

/// Member k of the case with the keys `set` to their values: its outputs
/// and wall time.
fn run_member(base: &BaseCase, set: &[(String, f64)], k: i32) -> (Result<Vec<f64>, String>, f64) {
    let mut overrides = match overrides_of(set) {
        Ok(o) => o,
        Err(e) => return (Err(e), 0.0),
    };
    if k != 0 {
        let member = base
            .load(&overrides)
            .map_err(|e| e.to_string())
            .and_then(|l| Perturbation::of(&l).map_err(|e| e.to_string()))
            .and_then(|p| override_of(&p.key, &toml::Value::Float(p.value(k))));
        match member {
            Ok(o) => overrides.push(o),
            Err(e) => return (Err(e), 0.0),
        }
    }
    match base.run(&overrides) {
        Ok(run) => (Ok(outputs::outputs_of(&run)), run.wall_time_s),
        Err(e) => (Err(e), 0.0),
    }
}
