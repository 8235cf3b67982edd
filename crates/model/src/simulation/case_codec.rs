//! A `Case` in a snapshot: every field, in declaration order.

use super::codec::{Reader, Writer};
use super::snapshot::SnapshotError;
use crate::case::{
    AngleLaw, BandAngleRule, BandShearRule, Bin, Blade, Case, Choices, FaceFrictionRule, Model,
    Run, Soil, UnitWeightRule,
};

pub(super) fn write_case(w: &mut Writer, c: &Case) {
    w.str(&c.name);
    w.str(&c.title);
    w.u8(match c.model {
        Model::Original => 0,
        Model::Refined => 1,
    });
    let b = &c.blade;
    for v in [b.depth, b.wall_friction, b.rake, b.adhesion] {
        w.f64(v);
    }
    w.usize(b.depth_path.len());
    for &[u, d] in &b.depth_path {
        w.f64(u);
        w.f64(d);
    }
    w.option_f64(b.width);
    let s = &c.soil;
    w.f64(s.unit_weight);
    for law in [&s.friction, &s.dilation] {
        for v in [law.initial, law.peak, law.residual] {
            w.f64(v);
        }
    }
    let soil = [
        s.peak_shear,
        s.residual_shear,
        s.repose,
        s.band_width,
        s.cohesion,
        s.surcharge,
    ];
    for v in soil {
        w.f64(v);
    }
    for v in [c.run.travel, c.run.increment, c.run.node_spacing] {
        w.f64(v);
    }
    w.option_f64(c.bin.length);
    let ch = &c.choices;
    w.u8(matches!(ch.band_angles, BandAngleRule::AngleOfMeanShear) as u8);
    w.u8(matches!(ch.band_shear, BandShearRule::ByPosition) as u8);
    w.u8(matches!(ch.unit_weight, UnitWeightRule::PerNodeFormula) as u8);
    w.u8(matches!(ch.face_friction, FaceFrictionRule::Sign) as u8);
}

fn law(r: &mut Reader, what: &'static str) -> Result<AngleLaw, SnapshotError> {
    Ok(AngleLaw {
        initial: r.f64(what)?,
        peak: r.f64(what)?,
        residual: r.f64(what)?,
    })
}

/// One of two values by a flag byte.
fn either<T>(r: &mut Reader, what: &'static str, no: T, yes: T) -> Result<T, SnapshotError> {
    Ok(if r.bool(what)? { yes } else { no })
}

/// The case as written; `Case::validate` is the caller's.
pub(super) fn read_case(r: &mut Reader) -> Result<Case, SnapshotError> {
    let name = r.string("case name")?;
    let title = r.string("case title")?;
    let model = either(r, "model", Model::Original, Model::Refined)?;
    let what = "blade";
    let (depth, wall_friction, rake, adhesion) =
        (r.f64(what)?, r.f64(what)?, r.f64(what)?, r.f64(what)?);
    let points = r.usize("blade.depth_path")?;
    if points.saturating_mul(16) > r.remaining() {
        return Err(SnapshotError::Truncated {
            what: "blade.depth_path",
        });
    }
    let depth_path = (0..points)
        .map(|_| Ok([r.f64("blade.depth_path")?, r.f64("blade.depth_path")?]))
        .collect::<Result<Vec<_>, SnapshotError>>()?;
    let width = r.option_f64("blade.width")?;
    let what = "soil";
    let unit_weight = r.f64(what)?;
    let (friction, dilation) = (law(r, what)?, law(r, what)?);
    let mut v = [0.0; 6];
    for x in &mut v {
        *x = r.f64(what)?;
    }
    let [peak_shear, residual_shear, repose, band_width, cohesion, surcharge] = v;
    let what = "run";
    let run = Run {
        travel: r.f64(what)?,
        increment: r.f64(what)?,
        node_spacing: r.f64(what)?,
    };
    let bin = Bin {
        length: r.option_f64("bin.length")?,
    };
    let what = "choices";
    let choices = Choices {
        band_angles: either(
            r,
            what,
            BandAngleRule::MeanOfAngles,
            BandAngleRule::AngleOfMeanShear,
        )?,
        band_shear: either(r, what, BandShearRule::Full, BandShearRule::ByPosition)?,
        unit_weight: either(
            r,
            what,
            UnitWeightRule::BandUniform,
            UnitWeightRule::PerNodeFormula,
        )?,
        face_friction: either(r, what, FaceFrictionRule::Mobilised, FaceFrictionRule::Sign)?,
    };
    Ok(Case {
        name,
        title,
        model,
        blade: Blade {
            depth,
            wall_friction,
            rake,
            adhesion,
            depth_path,
            width,
        },
        soil: Soil {
            unit_weight,
            friction,
            dilation,
            peak_shear,
            residual_shear,
            repose,
            band_width,
            cohesion,
            surcharge,
        },
        run,
        bin,
        choices,
    })
}
