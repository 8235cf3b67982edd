//! The landscape of minimum effort: the force of every admissible candidate
//! mechanism of one increment, not just the least (paper, "Numerical
//! formulation"; MODEL.md section 2).
//!
//! The principle of minimum effort picks the least P over the candidates;
//! how flat P is around that minimum says how firmly the band's position is
//! determined. Where many candidates, far apart, lie within a small fraction
//! of the minimum, a small change of the soil moves the band far: the origin
//! of the band jumps and of the sensitivity to the increment that MODEL.md
//! section 7 describes, and the reason an exact search must evaluate them
//! all (docs/performance.md).

/// One candidate mechanism: the band whose lower boundary runs from the
/// blade tip to the surface node at (`x_emergence`, `y_emergence`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Emergence point (physical coordinates, case length unit).
    pub x_emergence: f64,
    pub y_emergence: f64,
    /// β, degrees.
    pub beta_deg: f64,
    /// P: resultant blade force per unit width (Eq. (1) and its loads).
    pub force: f64,
    /// P / (γ0 d²).
    pub force_norm: f64,
    /// The band's friction and dilation angles, degrees.
    pub friction_deg: f64,
    pub dilation_deg: f64,
}

/// How many candidates lie within `fraction` of the least force
/// (P ≤ (1 + fraction) P*), the least one included.
pub fn near_minimum(candidates: &[Candidate], fraction: f64) -> usize {
    let least = candidates
        .iter()
        .map(|c| c.force)
        .fold(f64::INFINITY, f64::min);
    candidates
        .iter()
        .filter(|c| c.force <= least * (1.0 + fraction))
        .count()
}
