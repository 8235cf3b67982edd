//! `soilcut bounds`: rigorous lower and upper bounds (finite-element limit
//! analysis) on the collapse load of the ground as it stands at one instant
//! of a run, or at instants through it, beside soilcut's own force.

use crate::{load, CaseOutput, Failure, Moment};
use soilcut_bounds::{instant, Instant, InstantError, Options};
use soilcut_io::{
    bounds_columns, bounds_json, bounds_options, field_name, floor_name, strength_name, OutputError,
};
use soilcut_model::Case;
use soilcut_plot::{draw_bounds, draw_panels, BoundsFields, Panel, Series};
use std::path::Path;

pub const EXAMPLES: &str = "\
Examples:
  soilcut bounds cases/paper/original.toml --at 1
      writes out/original-bounds/{bounds.csv,bounds.json,case.resolved.toml}
  soilcut bounds cases/paper/table1-hs.toml --at 2 --mesh 12 --field slope --json
  soilcut bounds cases/paper/fig5.toml --every 0.5 --floor soil --strength davis --field slope";

#[derive(clap::Args)]
pub struct BoundsArgs {
    #[command(flatten)]
    target: CaseOutput,
    #[command(flatten)]
    moment: Moment,
    /// Mesh parameter N: cells along the face near the tip (1 to 64; about
    /// 19 N² triangles on a rigid floor, 58 N² with soil below).
    #[arg(
        long,
        value_name = "N",
        default_value_t = Options::default().mesh as i64,
        allow_negative_numbers = true
    )]
    mesh: i64,
    /// Below the tip level: soilcut's rigid floor, or deformable soil under
    /// the tip and the trench.
    #[arg(long, value_name = "FLOOR", default_value = Options::default().floor.name(), value_parser = ["rigid", "soil"])]
    floor: String,
    /// The soil's strength in the bounds: its own with associated flow, or
    /// Davis's reduced strength from its dilation angle.
    #[arg(long, value_name = "STRENGTH", default_value = Options::default().strength.name(), value_parser = ["associated", "davis"])]
    strength: String,
    /// The strength field: each column its own node's friction angle, or
    /// each column at least as strong as the slope of the surface it stands
    /// at (beyond the paper).
    #[arg(long, value_name = "FIELD", default_value = Options::default().field.name(), value_parser = ["columns", "slope"])]
    field: String,
    /// Print the results as JSON (bounds.json) instead of a table.
    #[arg(long)]
    json: bool,
}

impl BoundsArgs {
    fn options(&self, path: &Path) -> Result<Options, Failure> {
        bounds_options("--", self.mesh, &self.floor, &self.strength, &self.field)
            .map_err(|message| Failure::input(path, message))
    }
}

pub fn bounds(args: BoundsArgs) -> Result<(), Failure> {
    let target = &args.target;
    let path = target.case.as_path();
    let loaded = load(path, &target.set)?;
    let case = &loaded.case;
    args.moment.check(case, path)?;
    let options = args.options(path)?;
    let out = target.out_or(&format!("{}-bounds", case.name));
    let claim = target.claim(&out)?;
    let instants = match (args.moment.at, args.moment.every) {
        (Some(at), _) => instant::at(case, at, options).map(|i| vec![i]),
        (None, every) => instant::every(case, every.unwrap_or(1.0), options),
    }
    .map_err(|e| failure(path, e))?;
    let d = case.blade.depth;
    let json = bounds_json(&instants, d, &options);
    let files = vec![
        ("bounds.csv", bounds_columns(&instants, d).csv()),
        ("bounds.json", json.clone()),
        ("case.resolved.toml", loaded.resolved_toml()),
    ];
    // One instant: its fields; instants through the run: the forces and
    // ratios against u/d.
    claim
        .write_then(&files, |staged| {
            let (file, drawn) = match instants.as_slice() {
                [one] => {
                    let file = staged.join("bounds.png");
                    let drawn = draw_bounds(&fields(one, case), &file);
                    (file, drawn)
                }
                many => {
                    let file = staged.join("bounds_every.png");
                    let title = format!("{}: soilcut beside the bounds", case.title);
                    let drawn = draw_panels(&title, &through_run(many, case), 2, &file);
                    (file, drawn)
                }
            };
            drawn.map_err(|e| OutputError::Io {
                path: file,
                source: std::io::Error::other(e.message),
            })
        })
        .map_err(Failure::output)?;
    if args.json {
        print!("{json}");
    } else {
        print!("{}", table(&instants, d, &options));
        println!("outputs in {}", out.display());
    }
    Ok(())
}

/// The picture of one instant: lengths over d from the tip, the view from
/// half a face height behind the tip to 1.5 d past soilcut's band or two
/// face heights ahead, whichever is further.
fn fields(i: &Instant, case: &Case) -> BoundsFields {
    let (b, r, p) = (&i.bracket, &i.record, &i.problem);
    let d = case.blade.depth;
    let tip = (p.face.tip_x, p.face.tip_y);
    let scaled = |q: [f64; 2]| ((q[0] - tip.0) / d, q[1] / d);
    let h = p.face_height() / d;
    let top = p.ground.y.iter().fold(0.0, |m: f64, &y| m.max(y)) / d;
    let bottom = b.mesh.nodes.iter().fold(0.0, |m: f64, q| m.min(q[1])) / d;
    let reach = ((r.x_emergence - tip.0) / d + 1.5).max(2.0 * h);
    let face_top = p.column_top(tip.0);
    let face_x = tip.0 - (face_top - tip.1) * p.cot_rake();
    BoundsFields {
        title: format!(
            "{}: the bounds' fields at u/d = {:.3} (N = {})",
            case.title,
            r.u / d,
            b.n
        ),
        triangles: b
            .mesh
            .triangles
            .iter()
            .map(|t| t.map(|k| scaled(b.mesh.nodes[k])))
            .collect(),
        shear: b.upper.as_ref().map_or_else(
            |_| vec![f64::NAN; b.mesh.triangles.len()],
            |u| u.shear_rate.clone(),
        ),
        mobilised: b.lower.as_ref().map_or_else(
            |_| vec![f64::NAN; b.mesh.triangles.len()],
            |l| l.mobilised(p, &b.mesh),
        ),
        surface: p
            .ground
            .x
            .iter()
            .zip(&p.ground.y)
            .map(|(&x, &y)| scaled([x, y]))
            .take_while(|q| q.0 <= reach)
            .collect(),
        band: [
            scaled([tip.0, tip.1]),
            scaled([r.x_emergence, r.y_emergence]),
        ],
        face: [scaled([tip.0, tip.1]), scaled([face_x, face_top])],
        x_range: (-0.5 * h, reach),
        y_range: (bottom.max(tip.1 / d - 0.5 * h), top + 0.2 * h),
    }
}

/// The forces over γ0 d² and soilcut's ratios to the bounds against u/d
/// (instants without a bound leave it out).
fn through_run(instants: &[Instant], case: &Case) -> Vec<Panel> {
    let d = case.blade.depth;
    let norm = case.soil.unit_weight * d * d;
    // Missing bounds stay NaN: the line breaks there instead of bridging.
    let curve = |f: &dyn Fn(&Instant) -> f64| -> Vec<(f64, f64)> {
        instants.iter().map(|i| (i.record.u / d, f(i))).collect()
    };
    vec![
        Panel {
            x_label: "u/d (–)".into(),
            y_label: "horizontal force / (γ₀d²) (–)".into(),
            series: vec![
                Series::line("lower bound", curve(&|i| i.bracket.lower_force() / norm)),
                Series::line("upper bound", curve(&|i| i.bracket.upper_force() / norm)),
                Series::points("soilcut", curve(&|i| i.record.force_h / norm)),
            ],
        },
        Panel {
            x_label: "u/d (–)".into(),
            y_label: "soilcut / bound (–)".into(),
            series: vec![
                Series::line("soilcut / lower", curve(&|i| i.ratio_lower())),
                Series::line("soilcut / upper", curve(&|i| i.ratio_upper())),
                Series::line("1", curve(&|_| 1.0)),
            ],
        },
    ]
}

/// Every failure of an instant is the case's or the input's.
fn failure(path: &Path, e: InstantError) -> Failure {
    Failure::input(path, e)
}

/// The table printed on stdout.
fn table(instants: &[Instant], d: f64, options: &Options) -> String {
    let mut out = format!(
        "Limit-analysis bounds on the horizontal force (per unit width), mesh N = {}, floor {}, strength {}, field {}\n\
         {:>8} {:>12} {:>12} {:>12} {:>9} {:>9} {:>8} {:>9} {:>8} {:>8}\n",
        options.mesh,
        floor_name(options.floor),
        strength_name(options.strength),
        field_name(options.field),
        "u/d",
        "lower",
        "upper",
        "soilcut",
        "s/lower",
        "s/upper",
        "±%",
        "triangles",
        "lower s",
        "upper s",
    );
    let mut notes = Vec::new();
    for i in instants {
        let (b, r) = (&i.bracket, &i.record);
        let (lo, up) = (b.lower_force(), b.upper_force());
        out.push_str(&format!(
            "{:>8.3} {:>12.6} {:>12.6} {:>12.6} {:>9.4} {:>9.4} {:>8.2} {:>9} {:>8.2} {:>8.2}\n",
            r.u / d,
            lo,
            up,
            r.force_h,
            i.ratio_lower(),
            i.ratio_upper(),
            100.0 * (up - lo) / (up + lo),
            b.mesh.triangles.len(),
            b.lower_seconds,
            b.upper_seconds,
        ));
        notes.extend(status_notes(i, d));
    }
    for note in notes {
        out.push_str(&note);
    }
    out
}

/// A line for each bound the solver did not find (NaN in the table), or
/// one for both where the ground cannot stand under its own weight.
fn status_notes(i: &Instant, d: f64) -> Vec<String> {
    let u = i.record.u / d;
    let b = &i.bracket;
    if let Some(s) = &b.steep {
        let tip = i.problem.face.tip_x;
        return vec![format!(
            "u/d = {u:.3}: no bounds, the ground cannot stand under its own weight: the surface \
             from x/d = {:.3} to {:.3} ahead of the tip slopes at {:.2}° on soil of φ = {:.2}° \
             without cohesion, so no stress field carries it (no lower bound) and a block of it \
             slides down at no cost (the upper bound is unbounded below); --field slope gives \
             each column at least the slope it stands at\n",
            (s.x[0] - tip) / d,
            (s.x[1] - tip) / d,
            s.slope_deg,
            s.friction_deg,
        )];
    }
    let lower = b.lower.as_ref().err().map(|e| ("lower", e));
    let upper = b.upper.as_ref().err().map(|e| ("upper", e));
    lower
        .into_iter()
        .chain(upper)
        .map(|(which, e)| {
            let why = if e.is_infeasible() {
                ": no stress field on this mesh carries the ground's own weight with its strength (a slope just below its friction angle on a mesh too coarse to show that it holds: a finer --mesh may find one)"
            } else {
                ""
            };
            format!("u/d = {u:.3}: no {which} bound, {e}{why}\n")
        })
        .collect()
}
