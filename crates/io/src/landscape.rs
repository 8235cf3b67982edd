//! `landscape.csv`: every candidate mechanism of one increment.

use crate::columns::Columns;
use soilcut_model::landscape::least_by_distance;
use soilcut_model::{Candidate, Case, Simulation, StepError, Until};

/// Columns of `landscape.csv`, in order.
pub const LANDSCAPE_HEADER: &str = "x_emergence,distance_over_d,y_emergence,beta_deg,force,force_norm,force_over_least,friction_deg,dilation_deg";

/// Checks the moment of a landscape, `at` = u/d (`name`: how the caller's
/// user gave it, e.g. `--at`): a number from 0 to run.travel / blade.depth.
pub fn check_landscape_at(case: &Case, name: &str, at: f64) -> Result<(), String> {
    let last = case.run.travel / case.blade.depth;
    check_moment(name, at, "from 0 to", last, (0.0..=last).contains(&at))
}

/// Checks the spacing of a map of landscapes, `every` = Δu/d (`name` as in
/// [`check_landscape_at`]): above 0, at most run.travel / blade.depth.
pub fn check_landscape_every(case: &Case, name: &str, every: f64) -> Result<(), String> {
    let last = case.run.travel / case.blade.depth;
    check_moment(
        name,
        every,
        "above 0, at most",
        last,
        every > 0.0 && every <= last,
    )
}

fn check_moment(name: &str, value: f64, range: &str, last: f64, ok: bool) -> Result<(), String> {
    if value.is_finite() && ok {
        return Ok(());
    }
    Err(format!(
        "{name} must be a number {range} run.travel / blade.depth = {last} (got {value})"
    ))
}

/// Steps `sim` to the first increment evaluated at u ≥ `at`·d (u = steps ×
/// v0; the last increment if `at` lies beyond it) and returns every
/// candidate mechanism there: the landscape of `soilcut landscape --at`.
pub fn landscape_at(sim: &mut Simulation, at: f64) -> Result<Vec<Candidate>, StepError> {
    sim.drive(Until::Instant(at), &mut ())?;
    sim.landscape()
}

/// One row per candidate, nearest the blade first; `u` is the face's
/// position and `depth` the case's d (distance_over_d = (x − u) / d).
pub fn landscape_csv(candidates: &[Candidate], u: f64, depth: f64) -> String {
    landscape_columns(candidates, u, depth).csv()
}

/// The numbers of [`landscape_csv`] (columns [`LANDSCAPE_HEADER`]).
pub fn landscape_columns(candidates: &[Candidate], u: f64, depth: f64) -> Columns {
    let least = candidates
        .iter()
        .map(|c| c.force)
        .fold(f64::INFINITY, f64::min);
    let mut out = Columns::new(LANDSCAPE_HEADER);
    for c in candidates {
        out.push(&[
            c.x_emergence,
            (c.x_emergence - u) / depth,
            c.y_emergence,
            c.beta_deg,
            c.force,
            c.force_norm,
            c.force / least,
            c.friction_deg,
            c.dilation_deg,
        ]);
    }
    out
}

/// Columns of `landscape_map.csv`, in order.
pub const LANDSCAPE_MAP_HEADER: &str = "u_over_d,distance_over_d,force_over_least";

/// Width of the landscape map's distance bins, in blade depths.
pub const MAP_BIN: f64 = 0.05;

/// One landscape of the map: its u/d and, for each bin of `MAP_BIN` d
/// ahead of the tip that holds a candidate, (the bin's start / d, the
/// least P / P* of its candidates).
pub type MapColumn = (f64, Vec<(f64, f64)>);

/// The landscapes of `soilcut landscape --every`: at u/d = 0, `every`,
/// 2 `every`, … (each at the first increment at or beyond, through the
/// end of the travel), binned by distance ahead of the tip.
pub fn landscape_map(sim: &mut Simulation, every: f64) -> Result<Vec<MapColumn>, StepError> {
    let d = sim.case().blade.depth;
    let mut columns: Vec<MapColumn> = Vec::new();
    for at in sim.samples_every(every, sim.case().steps()) {
        sim.drive(Until::Increments(at), &mut ())?;
        let u = sim.blade_position();
        let candidates = sim.landscape()?;
        let bins = least_by_distance(&candidates, u, MAP_BIN * d);
        columns.push((u / d, bins.iter().map(|&(s, r)| (s / d, r)).collect()));
    }
    Ok(columns)
}

/// How many landscapes of the map hold a far tie: a bin more than 1 d from
/// the least one whose least force comes within 1 % of it, the band
/// jumps of docs/model.md §12.
pub fn far_ties(columns: &[MapColumn]) -> usize {
    let far = |bins: &[(f64, f64)]| {
        bins.iter().find(|b| b.1 == 1.0).is_some_and(|least| {
            bins.iter()
                .any(|b| b.1 <= 1.01 && (b.0 - least.0).abs() > 1.0)
        })
    };
    columns.iter().filter(|c| far(&c.1)).count()
}

/// The numbers of `landscape_map.csv` (columns [`LANDSCAPE_MAP_HEADER`]):
/// one row per landscape and distance bin.
pub fn landscape_map_columns(columns: &[MapColumn]) -> Columns {
    let mut out = Columns::new(LANDSCAPE_MAP_HEADER);
    for (u, bins) in columns {
        for &(start, ratio) in bins {
            out.push(&[*u, start, ratio]);
        }
    }
    out
}

/// `landscape_map.csv`: one row per landscape and distance bin, u/d of the
/// landscape, the bin's start / d, and the least P / P* of its candidates.
pub fn landscape_map_csv(columns: &[MapColumn]) -> String {
    landscape_map_columns(columns).csv()
}
