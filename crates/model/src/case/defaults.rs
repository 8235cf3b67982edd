//! The defaults of `run.increment`, `run.node_spacing` and
//! `run.vertex_spacing`: each a claim,
//! chosen by the ensemble rule (docs/model.md §9, §12.1) and rechosen
//! whenever the model's numbers change (`docs/studies/ensemble-accuracy/`).
//! They depend on the class of case (issue 28): the model, and whether its
//! soil ever softens, and whether the vertex ground can run it.
//! `default_vertex_spacing`, `default_increment` and `default_node_spacing`
//! are the one place that decides them.

use super::{Case, FaceFrictionRule, Model, Soil, TimeScheme};

/// `run.increment` of the original model (one slip line) when a case does
/// not give it: v0 = d / 250, the coarsest increment the study tries, is
/// accurate by the ensemble rule (docs/model.md §12.1, (M40)) against the
/// reference grid's ensemble at d/2000 on all three original-model cases,
/// whose soil softens, on the reference grid (worst window / tolerance 0.18
/// `cases/paper/original.toml`, 0.13 `cases/tools/tine.toml`, 0.11
/// `cases/tools/dozer.toml`; `docs/studies/ensemble-accuracy/`, rows
/// "defaults"), and on the original case with φr = φp on the coarse grid
/// of `default_node_spacing` (0.085; docs/model.md §9). A slip line has no
/// band width to sample: the search is exhaustive. The refined model's
/// d/1250 cost these cases about 25 times as much for no accuracy the rule
/// asks for.
pub const ORIGINAL_INCREMENTS_PER_DEPTH: f64 = 250.0;

/// `run.increment` of the refined model in soil that never softens, when a
/// case does not give it: v0 = d / 500, with the coarse grid of
/// `COARSE_NODES_PER_DEPTH`, is accurate by the ensemble rule on Fig. 8b
/// (`cases/paper/fig8b.toml`; worst window / tolerance 0.31, against 0.15
/// at d/1250 on the same grid; `docs/studies/ensemble-accuracy/`, row
/// "coarse d/500, h d/25"). The node grid's default of the class, which
/// defaults to the vertex ground (`default_vertex_spacing`).
pub const NON_SOFTENING_INCREMENTS_PER_DEPTH: f64 = 500.0;

/// `run.increment` of the refined model in soil that softens, when a case
/// does not give it: v0 = d / 1250, with the sampled search of
/// `DEFAULT_SAMPLES_PER_BAND` the coarsest of d/1000, d/1250 and d/1500
/// that is accurate by the ensemble rule on Fig. 5, Table 1 S and HS
/// against the reference grid's ensemble at d/2000 with the exhaustive
/// search under the face friction that ships (`mobilised`). Fig. 5 decides
/// it (0.25 of its tolerance at d/1250, 1.10 at d/1000;
/// `docs/studies/ensemble-accuracy/`). The node grid's default of the
/// class, which defaults to the vertex ground.
pub const SOFTENING_INCREMENTS_PER_DEPTH: f64 = 1250.0;

/// `run.increment` on the vertex ground when a case does not give it:
/// v0 = d / 350 with vertices `VERTICES_PER_DEPTH` apart and the midpoint
/// force (`default_time_scheme`) is accurate by the ensemble rule on every
/// paper case of the refined model in softening soil against the
/// reference grid's ensemble at d/2000 (worst window / tolerance: Fig. 5
/// 0.46, Table 1 HS 0.45, Table 1 S 0.12; with vertices d/100 apart 0.90,
/// 0.41, 0.23; `docs/studies/vertex-ground/`, with the flat bands of
/// (M52) and the crowded vertices of (M54)). Of d/250, d/300, d/350, d/400
/// and d/500 it is the coarsest that passes at both vertex spacings: d/250
/// fails Fig. 5 (1.54), d/300 Fig. 5 (1.47, and 1.22 with vertices d/100
/// apart). The explicit rule at d/250
/// passes the paper cases but not Fig. 5 in a bin (1.24) or raked (1.00;
/// docs/model.md §19).
pub const VERTEX_INCREMENTS_PER_DEPTH: f64 = 350.0;

/// Vertex spacings per blade depth of the default vertex ground: h = d/50
/// is accurate on every case of its class, where h = d/25 stands at the
/// edge at the default d/350 with the midpoint force (Table 1 S 0.64, HS
/// 0.79, Fig. 5 0.75) and fails under the explicit rule (Fig. 5 2.20 at
/// d/1250), and d/100 is no more accurate (Fig. 5 0.90 against 0.46 at
/// d/350; `docs/studies/vertex-ground/`).
pub const VERTICES_PER_DEPTH: f64 = 50.0;

/// Vertex spacings per blade depth of the default vertex ground under a
/// raked blade: h = d/100. Its ground lies in the sheared coordinates of
/// `Rake`, where the band is thinner by tan β' / tan β (M16), so the
/// vertices must be closer: Fig. 5's soil at α = 60° fails the ensemble
/// rule with vertices d/50 apart at d/350 (1.14 of the tolerance, the 3-4 d
/// window) and d/500 (1.30), and passes with d/100 at d/350 (0.43;
/// `docs/studies/every-class/`).
pub const RAKED_VERTICES_PER_DEPTH: f64 = 100.0;

/// `run.samples_per_band` when a case does not give it: the search's first
/// stage evaluates 8 candidates per band width (`Case::search_stride`,
/// docs/model.md §2.8), its second every node near their local minima.
pub const DEFAULT_SAMPLES_PER_BAND: f64 = 8.0;

/// `run.samples_per_band` on the vertex ground where the soil never
/// softens: 1. Without softening no patch of weak soil localises the
/// least band, the force varies smoothly over a band width, and the second
/// stage narrows the few local minima: Fig. 8b at d/250 with vertices d/25
/// and the midpoint force choosing at the midpoint is accurate by the
/// ensemble rule with K = 1 and K = 2 (0.19 of the tolerance both, at
/// 0.082 s and 0.100 s a run), raked at 60° too (0.14 both;
/// `docs/studies/every-class/`, rows "never softening").
pub const NON_SOFTENING_SAMPLES_PER_BAND: f64 = 1.0;

/// Vertex spacings per blade depth of the default vertex ground of the
/// refined model where the soil never softens: h = d/25, vertical or
/// raked. No softened band localises the mechanism, and a band's strength
/// is a smooth mean over soil that only hardens: Fig. 8b at d/250 with
/// `NON_SOFTENING_SAMPLES_PER_BAND` is accurate by the ensemble rule with
/// vertices d/25 apart (0.19 of the tolerance at 0.082 s a run, against
/// the coarse node grid's 0.31 at 0.093 s), raked at 60° too (0.14, where
/// d/50 is 0.13 at 1.7 times the time; `docs/studies/every-class/`).
pub const NON_SOFTENING_VERTICES_PER_DEPTH: f64 = 25.0;

/// Increments per blade depth on the vertex ground of the refined model
/// where the soil never softens, with the midpoint force: d/250, accurate
/// by the ensemble rule on Fig. 8b (0.19 of the tolerance; 0.42 at d/200,
/// 0.89 at d/150) and raked at 60° (0.14; `docs/studies/every-class/`).
pub const NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH: f64 = 250.0;

/// `run.samples_per_band` when a case does not give it, on its ground:
/// `NON_SOFTENING_SAMPLES_PER_BAND` on the vertex ground where the soil
/// never softens, else `DEFAULT_SAMPLES_PER_BAND`.
pub fn default_samples_per_band(soil: &Soil, on_vertices: bool) -> f64 {
    if on_vertices && !soil.softens() {
        NON_SOFTENING_SAMPLES_PER_BAND
    } else {
        DEFAULT_SAMPLES_PER_BAND
    }
}

/// Node spacings per blade depth of the default coarse grid, used where
/// the soil never softens: h = d / 25 at v0 = d / 500 is accurate by the
/// ensemble rule on Fig. 8b (`docs/studies/ensemble-accuracy/`), and at
/// v0 = d / 250 on the original case with φr = φp (docs/model.md §9).
pub const COARSE_NODES_PER_DEPTH: f64 = 25.0;

/// Increments per blade depth of `run.increment`'s default for the class
/// of case: `ORIGINAL_INCREMENTS_PER_DEPTH` in the original model,
/// `SOFTENING_INCREMENTS_PER_DEPTH` in the refined model where the soil
/// softens, `NON_SOFTENING_INCREMENTS_PER_DEPTH` where it never does.
pub fn default_increments_per_depth(model: Model, soil: &Soil) -> f64 {
    match model {
        Model::Original => ORIGINAL_INCREMENTS_PER_DEPTH,
        Model::Refined if soil.softens() => SOFTENING_INCREMENTS_PER_DEPTH,
        Model::Refined => NON_SOFTENING_INCREMENTS_PER_DEPTH,
    }
}

/// `run.increment` on the vertex ground under the explicit rule (the sign
/// rule of the face friction's, or `run.time_scheme = "explicit"`
/// given) when a case does not give it: v0 = d / 500 is accurate by the
/// ensemble rule on every paper case of the refined model (worst window /
/// tolerance: Fig. 5 0.92, Table 1 HS 0.38, Table 1 S 0.38, Fig. 8b 0.61),
/// d/250 not on Fig. 8b (1.47) and only at the edge on Fig. 5 (0.95;
/// `docs/studies/vertex-ground/`).
pub const VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH: f64 = 500.0;

/// `run.increment` when a case does not give it: d over
/// `default_increments_per_depth` on the node grid; on the vertex ground
/// over `ORIGINAL_INCREMENTS_PER_DEPTH` in the original model (the
/// original, tine and dozer cases at d/250 with vertices d/50 and the
/// midpoint force: worst window / tolerance 0.46, 0.34, 0.35 against their
/// reference ensembles, `docs/studies/every-class/`), over
/// `NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH` in the refined model's soil
/// that never softens with the midpoint force, in its softening soil over
/// `VERTEX_INCREMENTS_PER_DEPTH` with the midpoint force, over
/// `VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH` under the explicit rule.
pub fn default_increment(
    model: Model,
    soil: &Soil,
    depth: f64,
    (on_vertices, scheme): (bool, TimeScheme),
) -> f64 {
    match (on_vertices, scheme) {
        (true, _) if model == Model::Original => depth / ORIGINAL_INCREMENTS_PER_DEPTH,
        (true, TimeScheme::MidpointForce) if !soil.softens() => {
            depth / NON_SOFTENING_VERTEX_INCREMENTS_PER_DEPTH
        }
        (true, TimeScheme::MidpointForce) => depth / VERTEX_INCREMENTS_PER_DEPTH,
        (true, TimeScheme::Explicit) => depth / VERTEX_EXPLICIT_INCREMENTS_PER_DEPTH,
        (false, _) => depth / default_increments_per_depth(model, soil),
    }
}

/// `run.vertex_spacing` when a case gives neither it nor
/// `run.node_spacing`: d / `VERTICES_PER_DEPTH` in soil that softens, in
/// either model (d / `RAKED_VERTICES_PER_DEPTH` under a raked blade), as
/// there it is accurate at as few increments as the node grid or fewer
/// and its cost grows as the increments do, not as their square
/// (docs/performance.md; the original model's tine and dozer a third and
/// a half of their node grid's time, its paper case about the same);
/// d / `NON_SOFTENING_VERTICES_PER_DEPTH` in the refined model's soil that
/// never softens, where with the midpoint force choosing at the midpoint
/// (M51a) it is as accurate as the coarse node grid and faster (Fig. 8b:
/// 0.19 of the tolerance at 0.082 s a run against 0.31 at 0.093 s); else
/// 0, the coarse node grid, in the original model's soil that never
/// softens, where the vertex ground is four to eight times slower (the
/// original case with φr = φp: 0.042 s with vertices d/10, 0.078 s with
/// d/25, against 0.010 s on the coarse grid, all accurate; until an
/// increment costs what changed, issue 39). `docs/studies/every-class/`,
/// rows "never softening". Reads the case's model, soil, rake and depth.
pub fn default_vertex_spacing(case: &Case) -> f64 {
    let d = case.blade.depth;
    match (case.model, case.soil.softens()) {
        (Model::Original, false) => 0.0,
        (Model::Refined, false) => d / NON_SOFTENING_VERTICES_PER_DEPTH,
        (_, true) if case.blade.rake == 90.0 => d / VERTICES_PER_DEPTH,
        (_, true) => d / RAKED_VERTICES_PER_DEPTH,
    }
}

/// `run.time_scheme` when a case does not give it: `MidpointForce` on the
/// vertex ground under the mobilised face friction, where it is accurate
/// by the ensemble rule at coarser increments than `Explicit`
/// (`VERTEX_INCREMENTS_PER_DEPTH`); else `Explicit`, the node grid's only
/// scheme and the only one under the sign rule (`Case::validate`).
pub fn default_time_scheme(on_vertices: bool, face_friction: FaceFrictionRule) -> TimeScheme {
    if on_vertices && face_friction == FaceFrictionRule::Mobilised {
        TimeScheme::MidpointForce
    } else {
        TimeScheme::Explicit
    }
}

/// `run.node_spacing` when a case does not give it, for the increment v0:
/// the reference grid (h = v0) where the soil softens, as only there does
/// a coarse grid converge to a limit of its own in the refined model
/// (docs/model.md §9); else the whole number of increments nearest below
/// d / 25 (at least one). It depends on the soil alone: in the original
/// model in soil that never softens, d/25 at d/250 (ten increments a node)
/// is as accurate by the ensemble rule as the reference grid (the original
/// case with φr = φp: 0.085 of the tolerance on either grid against the
/// reference grid's ensemble at d/2000) at a quarter of its time.
pub fn default_node_spacing(soil: &Soil, depth: f64, increment: f64) -> f64 {
    if soil.softens() {
        return increment;
    }
    let per_node = (depth / COARSE_NODES_PER_DEPTH / increment).floor();
    per_node.max(1.0) * increment
}
