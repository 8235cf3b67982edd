//! The candidate lines (docs/model.md §2.1-2.3, §9.1). Candidate j is the
//! straight line from the blade tip A = (x_b, −d) to surface node j. With
//! r_j = (y_j + d) / (j − b) (rise per node, so that tan β_j = r_j / Δx on
//! the grid, (M2); for a raked blade the grid is sheared and `Rake`
//! converts the slope):
//!
//! * the line stays inside the soil iff no node between lies below it, i.e.
//!   r_j ≤ min over b < i < j of r_i (a running minimum, (M3));
//! * the block weight by the trapezoid rule is
//!   W_j = Δx [ ½ γ_b (y_b + d) + Σ_{b<i<j} γ_i (y_i + d) − r_j Σ_{b<i<j} γ_i (i − b) ],
//!   two running sums, so each candidate costs O(1) (M5);
//! * P_j = W_j · (P/W)(β_j, φ_j) by Eq. (1), plus the loads (M6, M8).

use super::input::SearchInput;
use crate::band::stretch;
use crate::crescent::{blade_force, Fan};
use crate::laws::BandAngles;
use crate::node_grid::face_node::FaceNode;
use crate::node_grid::node_band::Band;
use crate::node_grid::surface::Surface;
use crate::rake::Rake;

/// The lines of one scan: the face, and the running sums of (M5) and the
/// running minimum of (M3) over the nodes scanned so far.
#[derive(Clone, Copy, Debug)]
pub(super) struct Lines {
    /// The face: node b.
    pub(super) face: FaceNode,
    pub(super) d: f64,
    pub(super) dx: f64,
    /// ½ γ_b (y_b + d): the face node's trapezoid share.
    pub(super) base: f64,
    /// Σ γ_i (y_i + d) and Σ γ_i (i − b) over the nodes between b and j.
    pub(super) sum_gh: f64,
    pub(super) sum_gk: f64,
    /// Running minimum of r_i.
    pub(super) r_min: f64,
}

impl Lines {
    /// No node scanned yet, the tip at depth d below the face at node b.
    pub(super) fn new(surface: &Surface, b: usize, d: f64) -> Self {
        let face = FaceNode { node: b };
        Lines {
            face,
            d,
            dx: surface.spacing,
            base: 0.5 * surface.unit_weight[b] * (surface.height[b] + d),
            sum_gh: 0.0,
            sum_gk: 0.0,
            r_min: f64::INFINITY,
        }
    }

    /// Scans node j, the next one: its line's grid slope r_j / Δx (M2) and
    /// weight W_j (M5) if it is admissible (M3), then j joins the sums.
    #[inline]
    pub(super) fn advance(&mut self, surface: &Surface, j: usize) -> Option<(f64, f64)> {
        let k = self.face.spacings(j);
        let rise = surface.height[j] + self.d;
        let mut line = None;
        // r_j ≤ min r_i: the line stays inside the soil (M3).
        if rise <= self.r_min * k {
            // r_j = (y_j + d) / (j − b), the grid slope r_j / Δx (M2).
            let r = rise / k;
            self.r_min = r;
            // W_j = Δx [½ γ_b (y_b + d) + Σ γ_i (y_i + d) − r_j Σ γ_i (i − b)] (M5).
            let weight = self.dx * (self.base + self.sum_gh - r * self.sum_gk);
            line = Some((r / self.dx, weight));
        }
        let g = surface.unit_weight[j] * self.face.node_weight(j);
        self.sum_gh += g * rise;
        self.sum_gk += g * k;
        line
    }
}

/// The slope of a candidate's slip line on the grid and physically.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Slope {
    pub(super) grid: f64,
    pub(super) tan_beta: f64,
}

impl Slope {
    /// The line of slope `grid` on the grid, if its physical angle is
    /// admissible (`Rake::physical`).
    pub(super) fn on_grid(grid: f64, rake: &Rake) -> Option<Self> {
        Some(Slope {
            grid,
            tan_beta: rake.physical(grid)?,
        })
    }

    /// Physical horizontal length of the slip line reaching `spacings`
    /// node spacings ahead of the tip on the grid.
    pub(super) fn length(&self, spacings: f64, dx: f64) -> f64 {
        spacings * dx * stretch(self.grid, self.tan_beta)
    }

    /// The band whose lower boundary is this line to node j.
    pub(super) fn band(&self, lines: &Lines, j: usize, band_width: f64) -> Band {
        Band::new(
            lines.face,
            j,
            (self.grid, self.tan_beta),
            band_width,
            lines.d,
            lines.dx,
        )
    }
}

/// A candidate's slip line: emergence node, slope and block weight.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Line {
    pub(super) node: usize,
    pub(super) slope: Slope,
    pub(super) weight: f64,
    /// The weight the bounds use (`SearchInput::bound_weight`).
    pub(super) floor: f64,
}

impl Line {
    /// The line to node j of a candidate computed on its own, `admitted`
    /// its grid slope and weight (`Lines::advance`), if its physical angle
    /// is admissible; its bounds take the weight itself.
    pub(super) fn alone(j: usize, admitted: (f64, f64), rake: &Rake) -> Option<Self> {
        let (grid, weight) = admitted;
        Some(Line {
            node: j,
            slope: Slope::on_grid(grid, rake)?,
            weight,
            floor: weight,
        })
    }

    /// P_j: Eq. (1) for the band's angles, with the loads, if admissible
    /// (M4, M6, M8); for a blade of finite width, plus its side crescents
    /// per unit width (M42).
    pub(super) fn force(
        &self,
        input: &SearchInput,
        lines: &Lines,
        angles: BandAngles,
    ) -> Option<f64> {
        let t = self.slope.tan_beta;
        let factor = input.laws.factor(angles, t, input.face);
        let spacings = lines.face.spacings(self.node);
        let length = self.slope.length(spacings, lines.dx);
        let fan = Fan {
            rupture: spacings * lines.dx,
            depth: lines.d,
            cot_rake: input.rake.cot,
        };
        let crescents = input.crescents.as_ref();
        blade_force(
            crescents,
            (&input.loads, &factor),
            (self.weight, length, t),
            fan,
        )
    }
}
