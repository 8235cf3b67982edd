//! What the vertex ground (docs/model.md §19) does not do yet: the one
//! list, which both refuses such a case on the vertex ground
//! (`Case::validate`, so also a depth path that `advance_to` steers in)
//! and keeps it on the node grid by default (`default_vertex_spacing`).

use super::{BandShearRule, Case, CaseError, UnitWeightRule};

impl Case {
    /// Whether the vertex ground can run this case: a blade vertical or
    /// raked, of finite width or in plane strain, at constant depth or on a depth path (a
    /// vertical one), with or without an end wall (the same), under the default
    /// choices and a sampled search (`run.samples_per_band` > 0); else the first key it cannot take.
    pub fn vertex_ground_supports(&self) -> Result<(), CaseError> {
        let unsupported = |key: &str, why: &str| {
            Err(CaseError::new(
                key,
                format!(
                    "{why}: not supported on the vertex ground (run.vertex_spacing > 0) yet; \
                     run.vertex_spacing = 0 runs it on the node grid"
                ),
            ))
        };
        if self.choices.band_shear != BandShearRule::Full {
            return unsupported("choices.band_shear", "a band shear other than full");
        }
        if self.choices.unit_weight != UnitWeightRule::BandUniform {
            return unsupported(
                "choices.unit_weight",
                "a unit weight rule other than the band's",
            );
        }
        // The vertex ground samples the ground (M49): it has no exhaustive
        // search to fall back on.
        if self.run.samples_per_band == 0.0 {
            return Err(CaseError::new(
                "run.samples_per_band",
                "must be > 0 with run.vertex_spacing > 0 (got 0): 0, the exhaustive search, is the node grid's (run.vertex_spacing = 0); the vertex ground samples K points per band width (8 by default)",
            ));
        }
        Ok(())
    }
}
