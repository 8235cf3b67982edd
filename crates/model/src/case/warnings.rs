//! What is known against the accuracy of a valid case: warnings the front
//! ends print, one sentence each.

use super::Case;

impl Case {
    /// Why the results may be less accurate than they look, one sentence
    /// each (empty when nothing is known against the case): a blade
    /// narrower than a sixth of its depth fails the soil sideways below a
    /// critical depth, which the side crescents do not describe
    /// (docs/model.md §16.4).
    pub fn accuracy_warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
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
