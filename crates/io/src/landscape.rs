//! `landscape.csv`: every candidate mechanism of one increment.

use crate::columns::Columns;
use crate::csv_text::CsvText;
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

/// One row per landscape and distance bin: u/d of the landscape, the bin's
/// start / d, and the least P / P* of its candidates.
pub fn landscape_map_csv(columns: &[(f64, Vec<(f64, f64)>)]) -> String {
    let mut out = CsvText::new(LANDSCAPE_MAP_HEADER);
    for (u, bins) in columns {
        for (start, ratio) in bins {
            out.row(&[u, start, ratio]);
        }
    }
    out.finish()
}
