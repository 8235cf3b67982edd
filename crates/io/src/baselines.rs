//! The analytical baselines of a case's initial flat ground, normalised by
//! the case's force scale: `summary.json`'s `baselines`, the table of
//! `soilcut analytic` and Python's `soilcut.analytic` are all this.

use serde::Serialize;
use soilcut_model::analytic::{Baseline, Wedge};
use soilcut_model::Case;

/// The baselines of a case (docs/model.md's analytic solutions).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Baselines {
    /// Rankine's passive pressure on a smooth vertical wall.
    pub rankine: NormalisedBaseline,
    /// Coulomb's trial wedge with c = a = q = 0 (`None`: no admissible
    /// wedge).
    pub coulomb: Option<NormalisedBaseline>,
    /// Reece's Fundamental Earthmoving Equation with McKyes' factors.
    pub fee: Option<NormalisedBaseline>,
    /// McKyes & Ali for a blade of finite width (per blade; `None` in plane
    /// strain or where no wedge is admissible).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mckyes_ali: Option<NarrowBaseline>,
}

/// One baseline, its force also normalised.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct NormalisedBaseline {
    /// P, per unit width (per blade for McKyes & Ali).
    pub force: f64,
    /// P/(γ0 d²) (P/(γ0 d² w) per blade).
    pub force_norm: f64,
    /// Horizontal (draft) component.
    pub force_h: f64,
    /// Vertical component, positive upward.
    pub force_v: f64,
    /// β* of the least force, degrees.
    pub failure_angle_deg: f64,
    /// The factors at β*, for the FEE and McKyes & Ali.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub factors: Option<BaselineFactors>,
}

/// The FEE's factors (Nγ, Nc, Na, Nq) at β*.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BaselineFactors {
    /// Nγ.
    pub n_gamma: f64,
    /// Nc.
    pub n_c: f64,
    /// Na.
    pub n_a: f64,
    /// Nq.
    pub n_q: f64,
}

/// McKyes & Ali's least force per blade (M46), normalised by γ0 d² w.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct NarrowBaseline {
    /// The force per blade.
    #[serde(flatten)]
    pub baseline: NormalisedBaseline,
    /// The rupture distance ahead of the blade (length).
    pub rupture: f64,
    /// The crescents' half-angle, degrees.
    pub crescent_angle_deg: f64,
}

impl NormalisedBaseline {
    fn new(b: Baseline, norm: f64) -> Self {
        NormalisedBaseline {
            force: b.force,
            force_norm: b.force / norm,
            force_h: b.force_h,
            force_v: b.force_v,
            failure_angle_deg: b.failure_angle.to_degrees(),
            factors: b.factors.map(|f| BaselineFactors {
                n_gamma: f.n_gamma,
                n_c: f.n_c,
                n_a: f.n_a,
                n_q: f.n_q,
            }),
        }
    }
}

/// The baselines of `case`'s initial flat ground, normalised by
/// [`Case::force_scale`] (times the width for McKyes & Ali).
pub fn baselines(case: &Case) -> Baselines {
    let wedge = Wedge::of_case(case);
    let norm = case.force_scale();
    let plane = |b: Baseline| NormalisedBaseline::new(b, norm);
    let narrow = case.blade.width.and_then(|w| {
        let n = wedge.mckyes_ali(w)?;
        Some(NarrowBaseline {
            baseline: NormalisedBaseline::new(n.baseline, norm * w),
            rupture: n.rupture,
            crescent_angle_deg: n.crescent_angle.to_degrees(),
        })
    });
    Baselines {
        rankine: plane(wedge.rankine()),
        coulomb: wedge.coulomb().map(plane),
        fee: wedge.fee().map(plane),
        mckyes_ali: narrow,
    }
}
