//! Candidates on undisturbed ground, in closed form (see `search`): beyond
//! the last disturbed node the surface is flat, fresh and of unit weight
//! γ0, so a candidate's weight is a function of its distance alone and its
//! band has the fresh soil's angles.

use crate::band::stretch;
use crate::mechanism::ForceFactor;
use crate::rake::Rake;
use crate::search::{BandAngles, Scan, SearchInput, Slope};
use crate::surface::Surface;

/// Candidates on undisturbed flat ground (y = 0, unit weight γ0) from
/// n_s = j0 − b on: with the running sums S over the nodes before j0 and
/// the face's offset δ' = δ/Δx (node b + k is k − δ' spacings ahead),
/// W(n) = Δx [base + S_gh + γ0 d (n − n_s)
///            − (d/(n − δ')) (S_gk + γ0 Σ_{k=n_s}^{n−1} (k − δ'))].
pub(crate) struct FarField {
    d: f64,
    dx: f64,
    offset: f64,
    base: f64,
    sum_gh: f64,
    sum_gk: f64,
    gamma: f64,
    start: usize,
}

impl FarField {
    pub(crate) fn new(scan: &Scan, gamma: f64, start: usize) -> Self {
        FarField {
            d: scan.d,
            dx: scan.dx,
            offset: scan.offset,
            base: scan.base,
            sum_gh: scan.sum_gh,
            sum_gk: scan.sum_gk,
            gamma,
            start,
        }
    }

    pub(crate) fn weight(&self, n: usize) -> f64 {
        let s = self.start;
        let ahead = (n - s) as f64;
        let triangle = ((n * (n - 1) - s * (s - 1)) / 2) as f64 - self.offset * ahead;
        let r = self.d / self.spacings(n);
        self.dx
            * (self.base + self.sum_gh + self.gamma * self.d * ahead
                - r * (self.sum_gk + self.gamma * triangle))
    }

    /// Spacings from the face to node b + n.
    pub(crate) fn spacings(&self, n: usize) -> f64 {
        n as f64 - self.offset
    }

    pub(crate) fn slope(&self, n: usize, rake: &Rake) -> Option<Slope> {
        let grid = (self.d / self.spacings(n)) / self.dx;
        Some(Slope {
            grid,
            tan_beta: rake.physical(grid)?,
        })
    }

    /// First n ≥ n_s whose line passes below every node before it.
    pub(crate) fn first_admissible(&self, r_min: f64) -> usize {
        let admissible = |n: usize| self.d <= r_min * self.spacings(n);
        let mut n = if r_min.is_finite() {
            ((self.d / r_min + self.offset).ceil() as usize).max(self.start)
        } else {
            self.start
        };
        while n > self.start && admissible(n - 1) {
            n -= 1;
        }
        while !admissible(n) {
            n += 1;
        }
        n
    }
}

/// Whether candidate j and everything beyond lies on undisturbed flat ground
/// with a footprint (and its secant window) that does not reach disturbed
/// nodes.
pub(crate) fn far_field_from<A, F>(surface: &Surface, input: &SearchInput<A, F>, j: usize) -> bool
where
    A: Fn(BandAngles) -> BandAngles,
    F: Fn(BandAngles, f64) -> ForceFactor,
{
    let undisturbed = surface.pristine_from;
    if j < undisturbed {
        return false;
    }
    let dx = surface.spacing;
    let spacings = (j - input.blade) as f64 - surface.offset_of(input.blade);
    // The footprint below is at least dB / (tan β Δx) + 2 with
    // 1 / tan β = Δx (x_j − x_b) / d − cot α (`Rake`): a test without
    // a square root for the many nodes that fail it.
    let (least, cut) = (
        input.band_width * spacings / input.depth,
        input.band_width * input.rake.cot / dx,
    );
    let ahead = (j - undisturbed) as f64;
    if ahead <= least - cut + 2.0 - 1e-9 * (least + cut + 2.0) {
        return false;
    }
    let grid = (input.depth / spacings) / dx;
    let Some(tan_beta) = input.rake.physical(grid) else {
        return false;
    };
    let thickness = input.band_width * (1.0 + tan_beta * tan_beta).sqrt() * stretch(grid, tan_beta);
    let footprint = thickness / grid / dx + 2.0;
    (j - undisturbed) as f64 > footprint
}
