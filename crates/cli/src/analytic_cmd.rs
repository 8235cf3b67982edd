//! `soilcut analytic`: the analytical baselines of a case's initial flat
//! ground, as a table on stdout.

use soilcut_io::{baselines, Baselines, NormalisedBaseline};
use soilcut_model::Case;

pub const EXAMPLES: &str = "\
Examples:
  soilcut analytic cases/paper/fig5.toml
  soilcut analytic cases/tools/inclined.toml --set soil.cohesion=5
  soilcut analytic cases/tools/tine.toml";

/// The table `soilcut analytic` prints.
pub fn report(case: &Case) -> String {
    let all = baselines(case);
    let mut out = format!(
        "Analytic baselines for the initial flat ground of {} (forces per unit width)\n\
         d = {}, γ0 = {}, φ = {}° (at zero shear), φw = {}°, α = {}°, c = {}, a = {}, q = {}\n\n\
         {:<32} {:>12} {:>12} {:>12} {:>12} {:>10}\n",
        case.name,
        case.blade.depth,
        case.soil.unit_weight,
        case.soil.friction.initial,
        case.blade.wall_friction,
        case.blade.rake,
        case.soil.cohesion,
        case.blade.adhesion,
        case.soil.surcharge,
        "method",
        "P",
        "P/(γ0 d²)",
        "horizontal",
        "vertical",
        "β* (°)",
    );
    let mut row = |name: &str, b: Option<NormalisedBaseline>| match b {
        Some(b) => out.push_str(&format!(
            "{:<32} {:>12.6} {:>12.6} {:>12.6} {:>12.6} {:>10.3}\n",
            name, b.force, b.force_norm, b.force_h, b.force_v, b.failure_angle_deg
        )),
        None => out.push_str(&format!("{name:<32} no admissible wedge\n")),
    };
    row("Rankine (smooth vertical wall)", Some(all.rankine));
    row("Coulomb (trial wedge, c=a=q=0)", all.coulomb);
    row("FEE (Reece; McKyes' factors)", all.fee);
    if let Some(f) = all.fee.and_then(|b| b.factors) {
        out.push_str(&format!(
            "\nFEE factors at β*: Nγ = {:.6}, Nc = {:.6}, Na = {:.6}, Nq = {:.6}\n",
            f.n_gamma, f.n_c, f.n_a, f.n_q
        ));
    }
    if let Some(w) = case.blade.width {
        out.push_str(&narrow_report(&all, w, case.blade.depth));
    }
    out.push_str(
        "\nvertical: the soil's force on the blade, positive upward; Rankine ignores φw, α and a.\n",
    );
    out
}

/// McKyes & Ali's blade of width w (M46), per blade, beside plane strain
/// times w.
fn narrow_report(all: &Baselines, w: f64, depth: f64) -> String {
    let Some(n) = all.mckyes_ali else {
        return format!("\nMcKyes-Ali (w = {w}): no admissible wedge\n");
    };
    let b = n.baseline;
    let mut out = format!(
        "\nBlade of width w = {w} (w/d = {:.4}), forces per blade:\n\
         {:<32} {:>12} {:>12} {:>12} {:>12} {:>10}\n\
         {:<32} {:>12.6} {:>12.6} {:>12.6} {:>12.6} {:>10.3}\n",
        w / depth,
        "method",
        "P",
        "P/(γ0 d² w)",
        "horizontal",
        "vertical",
        "β* (°)",
        "McKyes-Ali (centre + crescents)",
        b.force,
        b.force_norm,
        b.force_h,
        b.force_v,
        b.failure_angle_deg
    );
    if let Some(plane) = all.fee {
        out.push_str(&format!(
            "{:<32} {:>12.6} {:>12.6}\n",
            "FEE × w (plane strain)",
            plane.force * w,
            plane.force_norm
        ));
    }
    out.push_str(&format!(
        "rupture distance r = {:.6} ({:.4} d), crescent half-angle ρ = {:.3}°\n",
        n.rupture,
        n.rupture / depth,
        n.crescent_angle_deg
    ));
    if let Some(f) = b.factors {
        out.push_str(&format!(
            "factors at β*: Nγ3 = {:.6}, Nc3 = {:.6}, Na3 = {:.6}, Nq3 = {:.6}\n",
            f.n_gamma, f.n_c, f.n_a, f.n_q
        ));
    }
    if w < depth * soilcut_model::crescent::NARROWEST {
        out.push_str("w/d < 1/6: below the critical depth the soil fails sideways, which this wedge does not describe (docs/model.md §16.4)\n");
    }
    out
}
