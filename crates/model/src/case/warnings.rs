//! What is known against the accuracy of a valid case: warnings the front
//! ends print, one sentence each.

use super::Case;

impl Case {
    /// Why the results may be less accurate than they look, one sentence
    /// each (empty when nothing is known against the case):
    /// * nodes coarser than the increment where the soil softens converge
    ///   to a limit of their own (docs/model.md §9);
    /// * a blade narrower than a sixth of its depth fails the soil
    ///   sideways below a critical depth, which the side crescents do not
    ///   describe (docs/model.md §16.4).
    pub fn accuracy_warnings(&self) -> Vec<String> {
        let (h, v0) = (self.run.node_spacing, self.run.increment);
        let mut warnings = Vec::new();
        if self.soil.softens() && h > v0 {
            warnings.push(format!(
                "run.node_spacing = {h} is coarser than run.increment = {v0} in soil that \
                 softens: such a grid converges to a limit of its own, 7-22 times the \
                 ensemble rule's tolerance off the reference grid in the unit-window mean \
                 forces of Table 1 S, HS and Fig. 5 (docs/model.md §9, §12.1); leave \
                 run.node_spacing out for the reference grid"
            ));
        }
        if let Some(w) = self.blade.width {
            let d = self.deepest();
            if w < d * crate::crescent::NARROWEST {
                warnings.push(format!(
                    "blade.width = {w} is narrower than 1/6 of the deepest tip depth {d}: \
                     below a critical depth of about 6 widths a narrow tine fails the soil \
                     sideways (Godwin & Spoor 1977), which the side crescents do not \
                     describe, so the force is underestimated there (docs/model.md §16.4)"
                ));
            }
        }
        warnings
    }
}
