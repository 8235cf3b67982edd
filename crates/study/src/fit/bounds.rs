//! The free keys of a fit and their bounds.

use crate::error::StudyError;
use crate::run::BaseCase;

/// A free parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Free {
    /// The dotted case key.
    pub key: String,
    /// The case's own value.
    pub start: f64,
    /// Lower bound (case units, degrees for angles).
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
    /// How the bounds were chosen, for the report.
    pub rule: String,
}

impl Free {
    /// `x` scaled to the bounds: 0 at `lo`, 1 at `hi`.
    pub fn scaled(&self, x: f64) -> f64 {
        (x - self.lo) / (self.hi - self.lo)
    }

    /// The value at scaled coordinate `z`.
    pub fn value(&self, z: f64) -> f64 {
        self.lo + (self.hi - self.lo) * z
    }

    /// Angles are recovered to 1°, other keys to 10 % (the accuracy the
    /// report compares an interval's width with).
    pub fn is_angle(&self) -> bool {
        is_angle(&self.key)
    }
}

/// Whether a key is an angle in degrees.
pub fn is_angle(key: &str) -> bool {
    key.starts_with("soil.friction.")
        || key.starts_with("soil.dilation.")
        || key == "soil.repose"
        || key == "blade.wall_friction"
        || key == "blade.rake"
}

/// Default bounds of a free key around its start value `x`, and the rule
/// in words:
/// * friction angles (`soil.friction.*`), `soil.repose`,
///   `blade.wall_friction`: x ± 10° within [0°, 90°];
/// * dilation angles (`soil.dilation.*`): x ± 10° within [−45°, 45°];
/// * lengths and other positive sizes (`soil.peak_shear`,
///   `soil.residual_shear`, `soil.d50`, `soil.band_width`,
///   `soil.band_width_d50`, `soil.unit_weight`, `blade.depth`,
///   `blade.width`):
///   0.5 x to 2 x (x must be > 0).
///
/// Any other key needs `--bounds`. [`Free`]s made by [`free_keys`] are
/// further narrowed so that the keys held fixed stay valid
/// ([`ORDERED`]).
pub fn default_bounds(key: &str, x: f64) -> Result<(f64, f64), String> {
    let angle = |lo: f64, hi: f64| Ok(((x - 10.0).max(lo), (x + 10.0).min(hi)));
    match key {
        "soil.friction.initial"
        | "soil.friction.peak"
        | "soil.friction.residual"
        | "soil.repose"
        | "blade.wall_friction" => angle(0.0, 90.0),
        "soil.dilation.initial" | "soil.dilation.peak" | "soil.dilation.residual" => {
            angle(-45.0, 45.0)
        }
        "soil.peak_shear"
        | "soil.residual_shear"
        | "soil.d50"
        | "soil.band_width"
        | "soil.band_width_d50"
        | "soil.unit_weight"
        | "blade.depth"
        | "blade.width" => {
            if x > 0.0 {
                Ok((0.5 * x, 2.0 * x))
            } else {
                Err(format!(
                    "{key}: no default bounds for a start of {x} (give --bounds {key}=lo:hi)"
                ))
            }
        }
        _ => Err(format!(
            "{key}: no default bounds for this key (give --bounds {key}=lo:hi)"
        )),
    }
}

/// Rules of a case between two keys, (smaller, larger): the first may not
/// exceed the second (the case's checks of the soil, docs/model.md §4: φc ≤ φp, φr ≤ φp,
/// up ≤ ur). A proposal that breaks one is an infeasible point of the
/// search; default bounds keep a free key on the valid side of a fixed one.
pub const ORDERED: [(&str, &str); 3] = [
    ("soil.friction.initial", "soil.friction.peak"),
    ("soil.friction.residual", "soil.friction.peak"),
    ("soil.peak_shear", "soil.residual_shear"),
];

/// Default bounds narrowed by the [`ORDERED`] rules against the fixed
/// keys, and the rule in words.
fn narrowed(key: &str, x: f64, base: &BaseCase, free: &[String]) -> Result<Free, String> {
    let (mut lo, mut hi) = default_bounds(key, x)?;
    let mut rule = if is_angle(key) {
        "start ± 10°".to_string()
    } else {
        "start × [0.5, 2]".to_string()
    };
    for (small, large) in ORDERED {
        let fixed = |other: &str| -> Option<f64> {
            (!free.iter().any(|f| f == other))
                .then(|| base.number(other).ok())
                .flatten()
        };
        if key == small {
            if let Some(v) = fixed(large).filter(|&v| v < hi) {
                hi = v;
                rule.push_str(&format!(", ≤ {large} = {v}"));
            }
        } else if key == large {
            if let Some(v) = fixed(small).filter(|&v| v > lo) {
                lo = v;
                rule.push_str(&format!(", ≥ {small} = {v}"));
            }
        }
    }
    Ok(Free {
        key: key.to_string(),
        start: x,
        lo,
        hi,
        rule,
    })
}

/// The free keys with their starts (from `base`) and bounds (`bounds`
/// replacing the narrowed defaults).
pub fn free_keys(
    base: &BaseCase,
    free: &[String],
    bounds: &[(String, f64, f64)],
) -> Result<Vec<Free>, StudyError> {
    if free.is_empty() {
        return Err(StudyError::Spec("give at least one --free key".to_string()));
    }
    for (key, ..) in bounds {
        if !free.contains(key) {
            return Err(StudyError::Spec(format!(
                "--bounds {key}: not one of the --free keys"
            )));
        }
    }
    let mut params = Vec::new();
    for (i, key) in free.iter().enumerate() {
        if free[..i].contains(key) {
            return Err(StudyError::Spec(format!("--free {key}: given twice")));
        }
        // A key no run can set, named with the nearest one that can, as
        // a sweep's --vary is (a free key takes numbers).
        if let Some(e) = base.unknown_key(key, &toml::Value::Float(0.0)) {
            return Err(StudyError::Key(e));
        }
        let start = base.number(key).map_err(StudyError::Spec)?;
        let p = match bounds.iter().rev().find(|b| &b.0 == key) {
            Some(&(_, lo, hi)) => Free {
                key: key.clone(),
                start,
                lo,
                hi,
                rule: "--bounds".to_string(),
            },
            None => narrowed(key, start, base, free).map_err(StudyError::Spec)?,
        };
        if p.lo >= p.hi || p.lo.is_nan() || p.hi.is_nan() {
            return Err(StudyError::Spec(format!(
                "{key}: the default bounds are empty ({}); give --bounds {key}=lo:hi",
                p.rule
            )));
        }
        if !(p.lo..=p.hi).contains(&start) {
            return Err(StudyError::Spec(format!(
                "--bounds {key}={}:{}: the start value {start} lies outside",
                p.lo, p.hi
            )));
        }
        params.push(p);
    }
    Ok(params)
}

/// Parses `--bounds key=lo:hi`.
pub fn parse_bounds(text: &str) -> Result<(String, f64, f64), StudyError> {
    let bad = || {
        StudyError::Spec(format!(
            "--bounds {text}: expected key.path=lo:hi with lo < hi"
        ))
    };
    let (key, range) = text.split_once('=').ok_or_else(bad)?;
    let (lo, hi) = range.split_once(':').ok_or_else(bad)?;
    let lo: f64 = lo.trim().parse().map_err(|_| bad())?;
    let hi: f64 = hi.trim().parse().map_err(|_| bad())?;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) || key.trim().is_empty() {
        return Err(bad());
    }
    Ok((key.trim().to_string(), lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    const REFINED: &str = include_str!("../../../io/testdata/refined.toml");

    #[test]
    fn default_bounds_per_key() {
        assert_eq!(default_bounds("soil.friction.peak", 35.0), Ok((25.0, 45.0)));
        assert_eq!(
            default_bounds("soil.friction.initial", 5.0),
            Ok((0.0, 15.0))
        );
        assert_eq!(default_bounds("soil.dilation.peak", 40.0), Ok((30.0, 45.0)));
        assert_eq!(default_bounds("soil.peak_shear", 2.0), Ok((1.0, 4.0)));
        assert!(default_bounds("soil.peak_shear", 0.0).is_err());
        assert!(default_bounds("run.increment", 0.2).is_err());
        assert_eq!(
            parse_bounds("soil.peak_shear=0.5:3").unwrap(),
            ("soil.peak_shear".to_string(), 0.5, 3.0)
        );
        for bad in ["x", "a=1", "a=2:1", "a=x:1", "=1:2"] {
            assert!(parse_bounds(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn fixed_keys_narrow_the_defaults() {
        // φc 20, φp 35, φr 30, up 2, ur 4.
        let base = BaseCase::new(REFINED.to_string(), vec![]).unwrap();
        let keys = |free: &[&str]| {
            let free: Vec<String> = free.iter().map(|s| s.to_string()).collect();
            free_keys(&base, &free, &[]).unwrap()
        };
        let p = keys(&["soil.friction.initial", "soil.peak_shear"]);
        assert_eq!((p[0].lo, p[0].hi), (10.0, 30.0), "φp = 35 is not reached");
        let p = keys(&["soil.friction.peak"]);
        assert_eq!((p[0].lo, p[0].hi), (30.0, 45.0), "φp ≥ φr = 30 (and φc)");
        assert!(
            p[0].rule.contains("soil.friction.residual = 30"),
            "{}",
            p[0].rule
        );
        let p = keys(&["soil.residual_shear"]);
        assert_eq!((p[0].lo, p[0].hi), (2.0, 8.0), "ur ≥ up = 2");
        let p = keys(&["soil.friction.peak", "soil.friction.residual"]);
        assert_eq!(
            (p[0].lo, p[0].hi),
            (25.0, 45.0),
            "both free: no narrowing by φr"
        );
    }
}
