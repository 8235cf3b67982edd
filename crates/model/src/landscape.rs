//! The landscape of minimum effort: the force of every admissible candidate
//! mechanism of one increment, not just the least (paper, "Numerical
//! formulation"; docs/model.md §2.8).
//!
//! The principle of minimum effort picks the least P over the candidates;
//! how flat P is around that minimum says how firmly the band's position is
//! determined. Where many candidates, far apart, lie within a small fraction
//! of the minimum, a small change of the soil moves the band far: the origin
//! of the band jumps and of the sensitivity to the increment that docs/model.md
//! §12 describes, and the reason an exact search must evaluate them
//! all (docs/performance.md).

/// Relative force difference below which two candidates count as equal:
/// among them the node grid's search takes the one nearest the blade
/// (M11), so round-off cannot flip its choice.
pub const TIE_TOLERANCE: f64 = 1e-10;

/// One candidate mechanism: the band whose lower boundary runs from the
/// blade tip to the surface node at (`x_emergence`, `y_emergence`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Emergence point (physical coordinates, case length unit).
    pub x_emergence: f64,
    /// y of the emergence point (0: undisturbed surface).
    pub y_emergence: f64,
    /// β, degrees.
    pub beta_deg: f64,
    /// P: resultant blade force per unit width (Eq. (1) and its loads).
    pub force: f64,
    /// P / (γ0 d²).
    pub force_norm: f64,
    /// The band's friction and dilation angles, degrees.
    pub friction_deg: f64,
    /// The band's dilation angle ψ, degrees.
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

/// The least P / P* in each bin of `bin` (a length) of distance ahead of
/// the blade tip at x = `u`, P* the least force of all: (bin start, least
/// ratio) for every bin that holds a candidate. `candidates` must come
/// nearest first, as `Simulation::landscape` gives them. A map of the
/// landscape over a run stacks these (`soilcut landscape --every`).
pub fn least_by_distance(candidates: &[Candidate], u: f64, bin: f64) -> Vec<(f64, f64)> {
    let least = candidates
        .iter()
        .map(|c| c.force)
        .fold(f64::INFINITY, f64::min);
    let mut bins: Vec<(f64, f64)> = Vec::new();
    for c in candidates {
        let start = ((c.x_emergence - u) / bin).floor() * bin;
        let ratio = c.force / least;
        match bins.last_mut() {
            Some(last) if last.0 == start => last.1 = last.1.min(ratio),
            _ => bins.push((start, ratio)),
        }
    }
    bins
}

#[cfg(test)]
mod tests {
    use super::*;

    fn candidate(x: f64, force: f64) -> Candidate {
        Candidate {
            x_emergence: x,
            y_emergence: 0.0,
            beta_deg: 10.0,
            force,
            force_norm: force,
            friction_deg: 30.0,
            dilation_deg: 0.0,
        }
    }

    #[test]
    fn bins_keep_their_least_ratio() {
        let all = [
            candidate(10.2, 4.0),
            candidate(10.7, 2.0),
            candidate(11.1, 3.0),
            candidate(13.0, 2.2),
        ];
        let bins = least_by_distance(&all, 10.0, 1.0);
        assert_eq!(bins, vec![(0.0, 1.0), (1.0, 1.5), (3.0, 1.1)]);
        assert_eq!(near_minimum(&all, 0.1), 2);
    }
}
