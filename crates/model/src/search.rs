//! The principle of minimum effort: the grid search over candidate emergence
//! nodes for the admissible mechanism of least force (paper, "Numerical
//! formulation"; MODEL.md section 2).
//!
//! Candidate j is the straight line from the blade tip A = (x_b, −d) to
//! surface node j. With r_j = (y_j + d) / (j − b) (rise per node, so that
//! tan β_j = r_j / Δx):
//!
//! * the line stays inside the soil iff no node between lies below it, i.e.
//!   r_j ≤ min over b < i < j of r_i (a running minimum);
//! * the block weight by the trapezoid rule is
//!   W_j = Δx [ ½ γ_b (y_b + d) + Σ_{b<i<j} γ_i (y_i + d) − r_j Σ_{b<i<j} γ_i (i − b) ],
//!   two running sums, so each candidate costs O(1);
//! * P_j = W_j · (P/W)(β_j, φ_j) by Eq. (1), with φ_j and ψ_j the mean of
//!   the node angles over the band's footprint at the surface (the nodes the
//!   band touches, `Band::footprint`; the emergence node alone for a slip
//!   line), from running prefix sums.
//!
//! Stopping rule (why the domain may be finite): along admissible candidates
//! the lines only get lower, so W_j never decreases, and P/W ≥ f_min =
//! sin φ_min / cos(φ_min + φw) for every admissible β. Once W_j f_min exceeds
//! the best force found, no later candidate can win. The scan stops there and
//! grows the domain only if it reaches the end first: growing never changes
//! the result.
//!
//! Ties: candidates whose force is within `TIE_TOLERANCE` (relative) of the
//! minimum count as equal, and the one nearest the blade wins, so round-off
//! cannot flip the choice between near-equal mechanisms.

use crate::band::Band;
use crate::mechanism::ForceFactor;
use crate::surface::Surface;

/// Relative force difference below which two candidates are equal.
pub const TIE_TOLERANCE: f64 = 1e-10;

/// Nodes appended at a time when the scan reaches the end of the domain.
const GROW_NODES_MIN: usize = 256;

/// The chosen mechanism of one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// Emergence node j.
    pub node: usize,
    /// tan β*.
    pub tan_beta: f64,
    /// P*: force per unit width.
    pub force: f64,
    /// W: weight of the block.
    pub weight: f64,
    /// The band's friction and dilation angles (radians).
    pub friction: f64,
    pub dilation: f64,
}

/// The band angles a candidate takes from its footprint (radians).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BandAngles {
    /// Mean of φ(ut_i) over the footprint.
    pub friction: f64,
    /// Mean of ψ(ut_i) over the footprint.
    pub dilation: f64,
    /// Mean of ut_i over the footprint.
    pub shear: f64,
    /// Every node of the footprint is unsheared (ut = 0).
    pub fresh: bool,
}

/// Reusable search state (no allocation per step once warmed up).
#[derive(Clone, Debug, Default)]
pub struct Search {
    /// Admissible candidates of the current step, kept for the tie-break.
    admissible: Vec<Choice>,
    /// Prefix sums from the blade node of φ, ψ and ut.
    prefix: Vec<[f64; 3]>,
    /// Candidate evaluations since creation (for benchmarks).
    pub evaluations: u64,
}

/// What the search needs to know about the soil besides the surface.
pub struct SearchInput<'a, A, F>
where
    A: Fn(BandAngles) -> BandAngles,
    F: Fn(BandAngles, f64) -> ForceFactor,
{
    pub blade: usize,
    pub depth: f64,
    /// dB (0 for the original model's slip line).
    pub band_width: f64,
    /// Lower bound of P/W over every candidate (see the stopping rule).
    pub min_factor: f64,
    /// The band's angles from the footprint means (the band-angle rule).
    pub angles: &'a A,
    /// Eq. (1) for a candidate's band angles at tan β.
    pub factor: &'a F,
    /// Nodes appended when the scan needs more domain.
    pub grow_nodes: usize,
}

impl Search {
    /// The minimum-effort mechanism, or `None` if no admissible candidate
    /// exists within a domain of `max_nodes` nodes.
    pub fn run<A, F>(
        &mut self,
        surface: &mut Surface,
        input: &SearchInput<A, F>,
        max_nodes: usize,
    ) -> Option<Choice>
    where
        A: Fn(BandAngles) -> BandAngles,
        F: Fn(BandAngles, f64) -> ForceFactor,
    {
        self.admissible.clear();
        self.prefix.clear();
        self.prefix.push([0.0; 3]);
        let (b, d, dx) = (input.blade, input.depth, surface.spacing);
        let base = 0.5 * surface.unit_weight[b] * (surface.height[b] + d);
        let (mut sum_gh, mut sum_gk) = (0.0, 0.0);
        let mut r_min = f64::INFINITY;
        let mut best = f64::INFINITY;
        let mut j = b + 1;
        loop {
            // The emergence node always has a neighbour ahead of it.
            if j + 1 >= surface.len() {
                if surface.len() >= max_nodes {
                    break;
                }
                surface.grow(input.grow_nodes.max(GROW_NODES_MIN));
            }
            self.push_prefix(surface, j - 1);
            let k = (j - b) as f64;
            let r = (surface.height[j] + d) / k;
            if r <= r_min {
                r_min = r;
                let weight = dx * (base + sum_gh - r * sum_gk);
                let tan_beta = r / dx;
                self.evaluations += 1;
                let band = Band::new(b, j, tan_beta, input.band_width, d, dx);
                let angles = (input.angles)(self.band_angles(surface, &band));
                if let Some(f) = (input.factor)(angles, tan_beta).at(tan_beta) {
                    let force = weight * f;
                    best = best.min(force);
                    self.admissible.push(Choice {
                        node: j,
                        tan_beta,
                        force,
                        weight,
                        friction: angles.friction,
                        dilation: angles.dilation,
                    });
                }
                if weight * input.min_factor > best * (1.0 + TIE_TOLERANCE) {
                    break;
                }
            }
            let g = surface.unit_weight[j];
            sum_gh += g * (surface.height[j] + d);
            sum_gk += g * k;
            j += 1;
        }
        let threshold = best * (1.0 + TIE_TOLERANCE);
        self.admissible
            .iter()
            .find(|c| c.force <= threshold)
            .copied()
    }

    fn push_prefix(&mut self, surface: &Surface, i: usize) {
        let last = *self.prefix.last().expect("prefix starts with zero");
        self.prefix.push([
            last[0] + surface.friction[i],
            last[1] + surface.dilation[i],
            last[2] + surface.accumulated_shear[i],
        ]);
    }

    /// Mean angles over the band's footprint, nodes j − m ..= j.
    fn band_angles(&mut self, surface: &Surface, band: &Band) -> BandAngles {
        let (b, j) = (band.blade, band.emergence);
        let m = band.footprint(&surface.height);
        if m == 0 {
            return BandAngles {
                friction: surface.friction[j],
                dilation: surface.dilation[j],
                shear: surface.accumulated_shear[j],
                fresh: surface.accumulated_shear[j] == 0.0,
            };
        }
        self.push_prefix(surface, j);
        let hi = self.prefix.pop().expect("just pushed");
        let lo = self.prefix[j - m - b];
        let n = (m + 1) as f64;
        BandAngles {
            friction: (hi[0] - lo[0]) / n,
            dilation: (hi[1] - lo[1]) / n,
            shear: (hi[2] - lo[2]) / n,
            fresh: hi[2] - lo[2] == 0.0,
        }
    }
}
