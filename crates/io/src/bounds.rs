//! `bounds.csv` and `bounds.json`: soilcut's force beside the rigorous
//! bounds of the ground as it stood, one row per instant.

use crate::columns::Columns;
use serde_json::json;
use soilcut_bounds::{Field, Floor, Instant, Options, SolveError, Strength, MAX_MESH};

/// Columns of `bounds.csv`, in order.
pub const BOUNDS_HEADER: &str = "u,u_over_d,depth,face_height,soilcut,lower,upper,soilcut_over_lower,soilcut_over_upper,half_width,mesh,triangles,lower_seconds,upper_seconds,soilcut_force,beta_deg,friction_deg";

/// One row per instant; `depth` is the case's d (u_over_d = u / d).
pub fn bounds_columns(instants: &[Instant], depth: f64) -> Columns {
    let mut columns = Columns::new(BOUNDS_HEADER);
    for i in instants {
        let (r, b) = (&i.record, &i.bracket);
        let (lo, up) = (b.lower_force(), b.upper_force());
        columns.push(&[
            r.u,
            r.u / depth,
            r.depth,
            i.problem.face_height(),
            r.force_h,
            lo,
            up,
            i.ratio_lower(),
            i.ratio_upper(),
            (up - lo) / (up + lo),
            b.n as f64,
            b.mesh.triangles.len() as f64,
            b.lower_seconds,
            b.upper_seconds,
            r.force,
            r.beta_deg,
            r.friction_deg,
        ]);
    }
    columns
}

/// The instants as JSON: the options, then one object per instant with the
/// columns of `bounds.csv` (NaN as null) and each bound's solver status.
pub fn bounds_json(instants: &[Instant], depth: f64, options: &Options) -> String {
    let columns = bounds_columns(instants, depth);
    let rows: Vec<serde_json::Value> = (0..columns.len())
        .map(|k| {
            let mut row: serde_json::Map<String, serde_json::Value> = columns
                .iter()
                .map(|(name, values)| (name.to_string(), json!(values[k])))
                .collect();
            let b = &instants[k].bracket;
            row.insert("lower_status".into(), json!(status(&b.lower)));
            row.insert("upper_status".into(), json!(status(&b.upper)));
            serde_json::Value::Object(row)
        })
        .collect();
    let value = json!({
        "mesh": options.mesh,
        "floor": floor_name(options.floor),
        "strength": strength_name(options.strength),
        "field": field_name(options.field),
        "instants": rows,
    });
    let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
    text.push('\n');
    text
}

/// "Solved", or the solver's status where a bound was not found (NaN in
/// the columns).
fn status<T>(bound: &Result<T, SolveError>) -> String {
    match bound {
        Ok(_) => "Solved".into(),
        Err(e) => e.status.clone(),
    }
}

/// The options of a bounds command from its arguments, checked; `prefix`
/// is how the caller's user names them (`--` on the command line): a bad
/// one is named with its allowed values.
pub fn bounds_options(
    prefix: &str,
    mesh: i64,
    floor: &str,
    strength: &str,
    field: &str,
) -> Result<Options, String> {
    let Some(mesh) = usize::try_from(mesh)
        .ok()
        .filter(|n| (1..=MAX_MESH).contains(n))
    else {
        return Err(format!(
            "{prefix}mesh must be an integer from 1 to {MAX_MESH} (got {mesh})"
        ));
    };
    let floor = match floor {
        "rigid" => Floor::Rigid,
        "soil" => Floor::Soil,
        other => return Err(format!("{prefix}floor must be rigid or soil (got {other})")),
    };
    let strength = match strength {
        "associated" => Strength::Associated,
        "davis" => Strength::Davis,
        other => {
            return Err(format!(
                "{prefix}strength must be associated or davis (got {other})"
            ))
        }
    };
    let field = match field {
        "columns" => Field::Columns,
        "slope" => Field::Slope,
        other => {
            return Err(format!(
                "{prefix}field must be columns or slope (got {other})"
            ))
        }
    };
    Ok(Options {
        mesh,
        floor,
        strength,
        field,
    })
}

/// The name of a floor, as `--floor` takes it.
pub fn floor_name(floor: Floor) -> &'static str {
    match floor {
        Floor::Rigid => "rigid",
        Floor::Soil => "soil",
    }
}

/// The name of a strength, as `--strength` takes it.
pub fn strength_name(strength: Strength) -> &'static str {
    match strength {
        Strength::Associated => "associated",
        Strength::Davis => "davis",
    }
}

/// The name of a strength field, as `--field` takes it.
pub fn field_name(field: Field) -> &'static str {
    match field {
        Field::Columns => "columns",
        Field::Slope => "slope",
    }
}
