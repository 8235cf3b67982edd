//! A case that passed [`Case::validate`]: what [`crate::Simulation::start`]
//! takes, so that a case read from a file is checked once on its way in
//! (by whoever read it, who names the keys as the file wrote them) and not
//! again by the simulation.

use super::{Case, CaseError};
use std::ops::Deref;

/// A [`Case`] whose every value is within its allowed range. Read-only:
/// changing a key means validating again ([`ValidCase::into_case`], then
/// [`Case::validated`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ValidCase(Case);

impl Case {
    /// The case, once [`Case::validate`] has accepted it.
    pub fn validated(self) -> Result<ValidCase, CaseError> {
        self.validate()?;
        Ok(ValidCase(self))
    }
}

impl ValidCase {
    /// The case, to be changed (and validated again).
    pub fn into_case(self) -> Case {
        self.0
    }

    /// The case to change in place, for a simulation that steers it: the
    /// caller checks the keys it changed and undoes them if refused
    /// (`Simulation::advance_to`).
    pub(crate) fn edit(&mut self) -> &mut Case {
        &mut self.0
    }
}

impl Deref for ValidCase {
    type Target = Case;

    fn deref(&self) -> &Case {
        &self.0
    }
}
