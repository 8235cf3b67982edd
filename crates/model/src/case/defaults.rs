//! The defaults of `run.increment` and `run.node_spacing`: each a claim,
//! chosen by the ensemble rule (docs/model.md §9, §12.1) and rechosen
//! whenever the model's numbers change (`docs/studies/ensemble-accuracy/`).

use super::Soil;

/// `run.increment` when a case does not give it: v0 = d / 1250, with the
/// sampled search of `DEFAULT_SAMPLES_PER_BAND` the coarsest of d/1000,
/// d/1250 and d/1500 that is accurate by the ensemble rule (docs/model.md
/// §12.1, (M40)) on every paper case and the tine and dozer of
/// `cases/tools/`, against the reference grid's ensemble at d/2000 with the
/// exhaustive search under the face friction that ships (`mobilised`;
/// `docs/studies/ensemble-accuracy/`); the node spacing defaults to
/// `default_node_spacing`.
pub const DEFAULT_INCREMENTS_PER_DEPTH: f64 = 1250.0;

/// `run.samples_per_band` when a case does not give it: the search's first
/// stage evaluates 8 candidates per band width (`Case::search_stride`,
/// docs/model.md §2.8), its second every node near their local minima.
pub const DEFAULT_SAMPLES_PER_BAND: f64 = 8.0;

/// Node spacings per blade depth of the default coarse grid, used where
/// the soil never softens: h = d / 25 at v0 = d / 1250 is accurate by the
/// ensemble rule on Fig. 8b and the original case
/// (`docs/studies/ensemble-accuracy/`).
pub const COARSE_NODES_PER_DEPTH: f64 = 25.0;

/// `run.node_spacing` when a case does not give it, for the increment v0:
/// the reference grid (h = v0) where the soil softens, as only there does
/// a coarse grid converge to a limit of its own (docs/model.md §9); else
/// the whole number of increments nearest below d / 25 (at least one).
pub fn default_node_spacing(soil: &Soil, depth: f64, increment: f64) -> f64 {
    if soil.softens() {
        return increment;
    }
    let per_node = (depth / COARSE_NODES_PER_DEPTH / increment).floor();
    per_node.max(1.0) * increment
}
