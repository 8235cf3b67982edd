//! Convergence with the resolution (docs/model.md §12): one case run on
//! its own ground with the increment v0 and, on the vertex ground, the
//! vertex spacing h halved level after level, together or one of them
//! alone (`Refine`; the node grid's nodes are every v0). Level 0 is the
//! case's own run.
//!
//! Sequential limit analysis of frictional wedges can be chaotic: the
//! sequence of individual bands need not converge, while averaged
//! quantities may. Each level reports both kinds:
//! * averaged: the mean force over each unit window of u/d and over the
//!   whole run, the force envelope (largest force in each window, and their
//!   mean), the band spacing (mean distance between successive band-jump
//!   locations), the final pile (its height, and the RMS difference of its
//!   surface from the finest level's on a common grid);
//! * individual: the largest force, where it occurs, the number of peaks.
//!
//! A quantity is called converged when it changes by less than the
//! tolerance (relative) between the two finest levels.

use crate::error::StudyError;
use crate::field;
use crate::figures::{in_window, mean, unit_windows, window_means};
use crate::fit::interpolate;
use crate::run::{override_of, BaseCase, RunResult};
use crate::Progress;
use rayon::prelude::*;
use soilcut_io::{CsvText, Override};
use soilcut_model::summary::{band_jumps, JUMP_DEPTHS};
use soilcut_model::{Case, Ground};
use soilcut_plot::{draw_panels, Panel, Series};
use std::fmt::Write as _;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

pub mod ensembles;

/// Length ahead of the blade's final position, in depths, over which the
/// final surfaces are compared.
pub const PROFILE_REACH_DEPTHS: f64 = 5.0;
/// Points of the common grid the surfaces are compared on.
pub const PROFILE_POINTS: usize = 501;

/// What a level refines.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Refine {
    /// v0 / 2^k and, on the vertex ground, h / 2^k.
    #[default]
    Both,
    /// v0 / 2^k at the case's h.
    Increment,
    /// The vertex spacing h / 2^k at the case's v0 (the vertex ground only).
    VertexSpacing,
}

/// The resolution a level runs at: v0 and, on the vertex ground, h.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// v0 (length).
    pub increment: f64,
    /// h of the vertex ground (length); `None` on the node grid, whose
    /// nodes are every v0.
    pub vertex_spacing: Option<f64>,
}

impl Resolution {
    /// The resolution `case` runs at.
    pub fn of(case: &Case) -> Self {
        Resolution {
            increment: case.run.increment,
            vertex_spacing: case.run.ground.vertex_spacing(),
        }
    }

    /// The spacing of the ground's points: h, or v0 on the node grid.
    pub fn spacing(&self) -> f64 {
        self.vertex_spacing.unwrap_or(self.increment)
    }

    /// The `--set` overrides that run the case at this resolution.
    pub fn overrides(&self) -> Result<Vec<Override>, StudyError> {
        let set =
            |key, value| override_of(key, &toml::Value::Float(value)).map_err(StudyError::Spec);
        let mut o = vec![set("run.increment", self.increment)?];
        if let Some(h) = self.vertex_spacing {
            o.push(set("run.vertex_spacing", h)?);
        }
        Ok(o)
    }

    /// In words, for errors.
    pub fn describe(&self) -> String {
        match self.vertex_spacing {
            Some(h) => format!("increment {}, vertex spacing {h}", self.increment),
            None => format!("increment {}, node grid", self.increment),
        }
    }
}

impl Refine {
    /// The resolution of level k from the case's: on the node grid only
    /// the increment can be halved.
    pub fn level(self, level: usize, case: Resolution) -> Result<Resolution, StudyError> {
        let f = 2f64.powi(level as i32);
        let (v0, h) = (case.increment, case.vertex_spacing);
        if self == Refine::VertexSpacing && h.is_none() {
            return Err(StudyError::Spec(
                "--refine vertex-spacing: the case runs on the node grid (run.ground = \"nodes\"), whose nodes are every increment; refine the increment".to_string(),
            ));
        }
        Ok(match self {
            Refine::Both => Resolution {
                increment: v0 / f,
                vertex_spacing: h.map(|h| h / f),
            },
            Refine::Increment => Resolution {
                increment: v0 / f,
                vertex_spacing: h,
            },
            Refine::VertexSpacing => Resolution {
                increment: v0,
                vertex_spacing: h.map(|h| h / f),
            },
        })
    }

    /// What level k runs at on `ground`, in words.
    pub fn describe(self, ground: &Ground) -> &'static str {
        match (self, ground.vertex_spacing()) {
            (_, None) => "increment v0/2^k on the node grid (nodes every increment)",
            (Refine::Both, _) => "increment v0/2^k and vertex spacing h/2^k on the vertex ground",
            (Refine::Increment, _) => {
                "increment v0/2^k at the case's vertex spacing h on the vertex ground"
            }
            (Refine::VertexSpacing, _) => {
                "vertex spacing h/2^k at the case's increment v0 on the vertex ground"
            }
        }
    }
}

/// A convergence study to run.
#[derive(Clone, Debug)]
pub struct Converge {
    /// The case and its `--set` overrides.
    pub base: BaseCase,
    /// Number of levels; level k halves the resolution k times (`refine`).
    pub levels: usize,
    /// What each level halves.
    pub refine: Refine,
    /// Relative change between the two finest levels below which a
    /// quantity counts as converged.
    pub tolerance: f64,
    /// Worker threads (0: one per available core).
    pub jobs: usize,
}

/// The figures of one level.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// Level k, from 0 (the case's own increment).
    pub level: usize,
    /// v0 / 2^k, the case's length unit.
    pub increment: f64,
    /// The spacing of the ground's points: the vertex spacing h / 2^k
    /// (or the case's h), or v0 on the node grid; the case's length unit.
    pub spacing: f64,
    /// Increments run.
    pub steps: usize,
    /// Mean P/(γ0 d²) over the whole run.
    pub mean_force_norm: f64,
    /// Mean P/(γ0 d²) over each window k ≤ u/d < k + 1.
    pub window_mean: Vec<f64>,
    /// Largest P/(γ0 d²) in each window (the force envelope).
    pub window_max: Vec<f64>,
    /// Mean of `window_max`.
    pub envelope_mean: f64,
    /// Increments whose emergence point jumped (`summary.json`'s rule).
    pub band_jumps: usize,
    /// Mean distance between successive band-jump locations, / d (NaN
    /// with fewer than two jumps).
    pub band_spacing_d: f64,
    /// Highest point of the final surface, / d.
    pub pile_height_d: f64,
    /// RMS difference of the final surface from the finest level's, / d.
    pub profile_rms_d: f64,
    /// Largest P/(γ0 d²) of the run.
    pub max_force_norm: f64,
    /// u/d where it occurs.
    pub u_over_d_at_max: f64,
    /// Number of distinct force peaks (`summary.json`'s rule).
    pub peaks: usize,
    /// The final surface relative to the blade face, ((x − u)/d, y/d), on
    /// the common grid.
    pub profile: Vec<(f64, f64)>,
    /// (u/d, P/(γ0 d²)) of every increment.
    pub force: Vec<(f64, f64)>,
    /// Wall time of the simulation, s (in `timing.csv` only).
    pub wall_time_s: f64,
}

/// Averaged quantities (the first five) and individual ones, as
/// (name, value of a level, description: a legend's label up to its
/// parenthesis).
type Quantity = (&'static str, fn(&Level) -> f64, &'static str);

/// A quantity's legend label: its description without the parenthesis.
fn label_of(q: &Quantity) -> &'static str {
    q.2.split(" (").next().unwrap_or(q.0)
}

/// Counts (peaks) are written as whole numbers.
fn is_count(q: &Quantity) -> bool {
    q.0 == "peaks"
}

/// The scalar quantities of a level, in the order of the report.
pub const QUANTITIES: [Quantity; 8] = [
    (
        "mean_force_norm",
        |l| l.mean_force_norm,
        "mean force over the run (averaged)",
    ),
    (
        "envelope_mean",
        |l| l.envelope_mean,
        "force envelope: mean of the window maxima (averaged)",
    ),
    (
        "band_spacing_d",
        |l| l.band_spacing_d,
        "band spacing / d (averaged)",
    ),
    (
        "pile_height_d",
        |l| l.pile_height_d,
        "final pile height / d (averaged)",
    ),
    (
        "profile_rms_d",
        |l| l.profile_rms_d,
        "RMS difference of the final surface from the finest level / d",
    ),
    (
        "max_force_norm",
        |l| l.max_force_norm,
        "largest force (individual peak)",
    ),
    (
        "u_over_d_at_max",
        |l| l.u_over_d_at_max,
        "u/d of the largest force (individual peak)",
    ),
    (
        "peaks",
        |l| l.peaks as f64,
        "number of force peaks (individual)",
    ),
];

/// One figure per window of a level.
type PerWindow = fn(&Level) -> &Vec<f64>;

/// A finished convergence study.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvergeResult {
    /// The case's title.
    pub title: String,
    /// d, the reference depth (case length unit).
    pub depth: f64,
    /// The relative change below which a quantity counts as converged.
    pub tolerance: f64,
    /// What each level halved.
    pub refine: Refine,
    /// The case's ground, on which every level runs.
    pub ground: Ground,
    /// Coarsest first.
    pub levels: Vec<Level>,
}

fn level_of(level: usize, run: &RunResult, depth: f64, windows: usize) -> Level {
    let h = &run.history;
    let force: Vec<(f64, f64)> = h.iter().map(|r| (r.u / depth, r.force_norm)).collect();
    let window_mean = window_means(&force, windows);
    let window_max: Vec<f64> = (0..windows)
        .map(|k| in_window(&force, k).into_iter().fold(f64::NAN, f64::max))
        .collect();
    let jumps = band_jumps(h, JUMP_DEPTHS * depth);
    let spacings: Vec<f64> = jumps
        .windows(2)
        .map(|w| (h[w[1]].x_emergence - h[w[0]].x_emergence).abs() / depth)
        .collect();
    let face = run.profile.first().map_or(0.0, |p| p.x);
    let surface: Vec<(f64, f64)> = run
        .profile
        .iter()
        .map(|p| ((p.x - face) / depth, p.y / depth))
        .collect();
    let profile = (0..PROFILE_POINTS)
        .map(|i| {
            let x = PROFILE_REACH_DEPTHS * i as f64 / (PROFILE_POINTS - 1) as f64;
            (x, interpolate(&surface, x))
        })
        .collect();
    let s = &run.summary;
    Level {
        level,
        increment: run.loaded.case.run.increment,
        spacing: Resolution::of(&run.loaded.case).spacing(),
        steps: s.steps,
        mean_force_norm: mean(&force.iter().map(|p| p.1).collect::<Vec<_>>()),
        envelope_mean: mean(&window_max),
        window_mean,
        window_max,
        band_jumps: jumps.len(),
        band_spacing_d: mean(&spacings),
        pile_height_d: surface.iter().map(|p| p.1).fold(f64::NAN, f64::max),
        profile_rms_d: f64::NAN,
        max_force_norm: s.max_force_norm,
        u_over_d_at_max: s.u_over_d_at_max,
        peaks: s.peaks.len(),
        profile,
        force,
        wall_time_s: run.wall_time_s,
    }
}

/// Relative change from `a` to `b`: |b − a| / |b| (NaN if undefined).
pub fn relative_change(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (b - a).abs() / b.abs()
    }
}

impl Converge {
    /// Runs every level in parallel.
    pub fn run(&self, progress: Progress) -> Result<ConvergeResult, StudyError> {
        if self.levels == 0 {
            return Err(StudyError::Spec("--levels must be >= 1".to_string()));
        }
        let loaded = self.base.load(&[])?;
        let case = &loaded.case;
        let depth = case.blade.depth;
        let own = Resolution::of(case);
        // Every level's resolution before any runs: a refinement the
        // ground cannot take is refused at once.
        let resolutions = (0..self.levels)
            .map(|level| self.refine.level(level, own))
            .collect::<Result<Vec<_>, _>>()?;
        let windows = unit_windows(case.run.travel, depth);
        let finished = AtomicUsize::new(0);
        progress(0, self.levels);
        let runs: Vec<Result<Level, StudyError>> = crate::pool(self.jobs)?.install(|| {
            // Finest (slowest) first, so that it starts at once.
            (0..self.levels)
                .rev()
                .collect::<Vec<_>>()
                .into_par_iter()
                .map(|level| {
                    let resolution = resolutions[level];
                    let run = self.base.run(&resolution.overrides()?).map_err(|e| {
                        StudyError::Case(format!("level {level} ({}): {e}", resolution.describe()))
                    })?;
                    let l = level_of(level, &run, depth, windows);
                    progress(finished.fetch_add(1, Ordering::Relaxed) + 1, self.levels);
                    Ok(l)
                })
                .collect()
        });
        let mut levels = runs.into_iter().collect::<Result<Vec<_>, _>>()?;
        levels.reverse();
        let finest = levels.last().expect("one level at least").profile.clone();
        for l in &mut levels {
            let sq: Vec<f64> = l
                .profile
                .iter()
                .zip(&finest)
                .map(|(a, b)| (a.1 - b.1).powi(2))
                .collect();
            l.profile_rms_d = mean(&sq).sqrt();
        }
        Ok(ConvergeResult {
            title: case.title.clone(),
            depth,
            tolerance: self.tolerance,
            refine: self.refine,
            ground: case.run.ground,
            levels,
        })
    }
}

impl ConvergeResult {
    fn windows(&self) -> usize {
        self.levels[0].window_mean.len()
    }

    /// `converge.csv`: one row per level, coarsest first.
    pub fn csv(&self) -> String {
        let mut header: Vec<String> = ["level", "increment", "spacing", "steps", "band_jumps"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        header.extend(QUANTITIES.iter().map(|q| q.0.to_string()));
        for k in 0..self.windows() {
            header.push(format!("window_mean_{k}_{}", k + 1));
        }
        for k in 0..self.windows() {
            header.push(format!("window_max_{k}_{}", k + 1));
        }
        let mut out = CsvText::named(&header);
        for l in &self.levels {
            let mut row = vec![
                l.level.to_string(),
                l.increment.to_string(),
                l.spacing.to_string(),
                l.steps.to_string(),
                l.band_jumps.to_string(),
            ];
            row.extend(QUANTITIES.iter().map(|q| field::number(q.1(l))));
            row.extend(l.window_mean.iter().map(|&x| field::number(x)));
            row.extend(l.window_max.iter().map(|&x| field::number(x)));
            out.fields(&row);
        }
        out.finish()
    }

    /// `timing.csv`: `level,increment,spacing,wall_time_s`.
    pub fn timing_csv(&self) -> String {
        let mut out = CsvText::new("level,increment,spacing,wall_time_s");
        for l in &self.levels {
            out.fields(&[
                l.level.to_string(),
                l.increment.to_string(),
                l.spacing.to_string(),
                l.wall_time_s.to_string(),
            ]);
        }
        out.finish()
    }

    /// Relative change of every quantity from level k − 1 to level k
    /// (k ≥ 1), in the order of [`QUANTITIES`], then the largest change of
    /// the window means and of the window maxima. The profile is compared
    /// as the RMS difference of the two surfaces relative to the pile
    /// height.
    pub fn changes(&self) -> Vec<Vec<f64>> {
        self.levels
            .windows(2)
            .map(|pair| {
                let (a, b) = (&pair[0], &pair[1]);
                let mut row: Vec<f64> = QUANTITIES
                    .iter()
                    .map(|q| match q.0 {
                        "profile_rms_d" => {
                            let sq: Vec<f64> = a
                                .profile
                                .iter()
                                .zip(&b.profile)
                                .map(|(p, q)| (p.1 - q.1).powi(2))
                                .collect();
                            mean(&sq).sqrt() / b.pile_height_d
                        }
                        _ => relative_change(q.1(a), q.1(b)),
                    })
                    .collect();
                let largest = |x: &[f64], y: &[f64]| {
                    x.iter()
                        .zip(y)
                        .map(|(&p, &q)| relative_change(p, q))
                        .fold(0.0, f64::max)
                };
                row.push(largest(&a.window_mean, &b.window_mean));
                row.push(largest(&a.window_max, &b.window_max));
                row
            })
            .collect()
    }

    /// Names of the columns of [`changes`](Self::changes).
    pub fn change_names() -> Vec<&'static str> {
        let mut names: Vec<&str> = QUANTITIES.iter().map(|q| q.0).collect();
        names.extend(["window_mean (largest)", "window_max (largest)"]);
        names
    }

    /// Whether each quantity changed by less than the tolerance between the
    /// two finest levels (None with one level or an undefined change).
    pub fn converged(&self) -> Vec<Option<bool>> {
        match self.changes().last() {
            None => vec![None; Self::change_names().len()],
            Some(last) => last
                .iter()
                .map(|&c| (!c.is_nan()).then_some(c < self.tolerance))
                .collect(),
        }
    }

    /// `converge.md`: the tables and the verdicts, readable.
    pub fn markdown(&self) -> String {
        let mut s = String::new();
        let w = &mut s;
        let _ = writeln!(w, "# Convergence with the resolution: {}\n", self.title);
        let _ = writeln!(
            w,
            "Level k runs at {}. Averaged quantities should converge; individual peaks need not (docs/model.md §12). Converged: relative change < {} % between the two finest levels.\n",
            self.refine.describe(&self.ground),
            self.tolerance * 100.0
        );
        self.levels_markdown(w);
        self.windows_markdown(w);
        let (names, changes) = (Self::change_names(), self.changes());
        self.changes_markdown(w, &names, &changes);
        self.verdicts_markdown(w, &names, &changes);
        s
    }

    /// `converge.md`'s table of each level's resolution and quantities.
    fn levels_markdown(&self, w: &mut String) {
        let _ = writeln!(w, "## Per level\n");
        let _ = writeln!(
            w,
            "| level | increment | spacing | steps | band jumps | {} |",
            QUANTITIES.map(|q| q.0).join(" | ")
        );
        let _ = writeln!(w, "|{}", "---|".repeat(5 + QUANTITIES.len()));
        for l in &self.levels {
            let values: Vec<String> = QUANTITIES
                .iter()
                .map(|q| match is_count(q) {
                    true => format!("{}", q.1(l)),
                    false => cell(q.1(l)),
                })
                .collect();
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} |",
                l.level,
                l.increment,
                l.spacing,
                l.steps,
                l.band_jumps,
                values.join(" | ")
            );
        }
    }

    /// `converge.md`'s tables of the window means and the envelope.
    fn windows_markdown(&self, w: &mut String) {
        let tables: [(&str, PerWindow); 2] = [
            ("Mean force P/(γ0 d²)", |l| &l.window_mean),
            ("Force envelope (largest P/(γ0 d²))", |l| &l.window_max),
        ];
        let windows = self.windows();
        let heads: Vec<String> = (0..windows).map(|k| format!("{k}–{}", k + 1)).collect();
        for (title, values) in tables {
            let _ = writeln!(w, "\n{title} in each window of u/d:\n");
            let _ = writeln!(
                w,
                "| level | {} |\n|{}",
                heads.join(" | "),
                "---|".repeat(windows + 1)
            );
            for l in &self.levels {
                let v: Vec<String> = values(l).iter().map(|&x| cell(x)).collect();
                let _ = writeln!(w, "| {} | {} |", l.level, v.join(" | "));
            }
        }
    }

    /// `converge.md`'s table of the relative changes between levels.
    fn changes_markdown(&self, w: &mut String, names: &[&str], changes: &[Vec<f64>]) {
        let _ = writeln!(w, "\n## Relative change from the previous level\n");
        let _ = writeln!(
            w,
            "| quantity | {} |",
            (1..self.levels.len())
                .map(|k| format!("{} → {k}", k - 1))
                .collect::<Vec<_>>()
                .join(" | ")
        );
        let _ = writeln!(w, "|{}", "---|".repeat(self.levels.len()));
        for (i, name) in names.iter().enumerate() {
            let v: Vec<String> = changes.iter().map(|row| cell(row[i])).collect();
            let _ = writeln!(w, "| {name} | {} |", v.join(" | "));
        }
        let _ = writeln!(
            w,
            "\nThe profile row is the RMS difference between the two levels' final surfaces over {PROFILE_REACH_DEPTHS} d ahead of the blade, relative to the finer level's pile height (the per-level table gives each level against the finest). Window rows give the largest change over the windows.\n"
        );
    }

    /// `converge.md`'s verdicts, one line per quantity.
    fn verdicts_markdown(&self, w: &mut String, names: &[&str], changes: &[Vec<f64>]) {
        let _ = writeln!(w, "## Verdict\n");
        for (i, (name, verdict)) in names.iter().zip(self.converged()).enumerate() {
            let text = match verdict {
                Some(true) => "converged",
                Some(false) => "not converged",
                None => "undetermined",
            };
            let series: Vec<f64> = changes.iter().map(|row| row[i]).collect();
            let last = series.last().map_or(String::new(), |c| {
                format!(" ({:.2} % change at the finest step", c * 100.0)
            });
            let shrinking = if series.len() < 2 || last.is_empty() {
                if last.is_empty() {
                    ""
                } else {
                    ")"
                }
            } else if series.windows(2).all(|p| p[1] < p[0]) {
                "; the change shrinks at every level)"
            } else {
                "; the change does not shrink at every level)"
            };
            let _ = writeln!(w, "- {name}: {text}{last}{shrinking}");
        }
    }

    /// `converge.png`: window means and envelope against u/d, the final
    /// surfaces, and the relative changes against the level.
    pub fn draw(&self, path: &Path) -> Result<(), StudyError> {
        let panel = |x_label: &str, y_label: &str, series| Panel {
            x_label: x_label.into(),
            y_label: y_label.into(),
            series,
        };
        let panels = vec![
            panel(
                "u/d (window midpoint)",
                "window mean P/(γ₀d²)",
                self.per_window(|l| &l.window_mean),
            ),
            panel(
                "u/d (window midpoint)",
                "window max P/(γ₀d²) (envelope)",
                self.per_window(|l| &l.window_max),
            ),
            panel(
                "(x − u)/d ahead of the blade",
                "final surface y/d",
                self.per_level(|l| &l.profile),
            ),
            panel(
                "level k (change from level k − 1)",
                "relative change (%)",
                self.change_series(),
            ),
            panel("u/d", "P/(γ₀d²)", self.per_level(|l| &l.force)),
        ];
        draw_panels(
            &format!("Convergence with the resolution: {}", self.title),
            &panels,
            2,
            path,
        )?;
        Ok(())
    }

    /// One line a level of a quantity per unit window, at the windows'
    /// midpoints.
    fn per_window(&self, values: PerWindow) -> Vec<Series> {
        self.levels
            .iter()
            .map(|l| {
                let points = values(l)
                    .iter()
                    .enumerate()
                    .map(|(k, &v)| (k as f64 + 0.5, v))
                    .collect();
                Series::line(&level_label(l), points)
            })
            .collect()
    }

    /// One line a level of one of its curves.
    fn per_level(&self, curve: fn(&Level) -> &Vec<(f64, f64)>) -> Vec<Series> {
        self.levels
            .iter()
            .map(|l| Series::line(&level_label(l), curve(l).clone()))
            .collect()
    }

    /// The relative changes (%) of the averaged quantities against the
    /// level.
    fn change_series(&self) -> Vec<Series> {
        let changes = self.changes();
        [0usize, 1, 2, 3, 5]
            .iter()
            .map(|&i| {
                let points = changes
                    .iter()
                    .enumerate()
                    .map(|(k, row)| ((k + 1) as f64, 100.0 * row[i]))
                    .collect();
                Series::line(label_of(&QUANTITIES[i]), points)
            })
            .collect()
    }
}

/// A level's legend label: its increment and spacing.
fn level_label(l: &Level) -> String {
    format!(
        "level {} (v0 = {}, h = {})",
        l.level, l.increment, l.spacing
    )
}

/// A number of `converge.md`'s tables: four decimals, a dash for none.
fn cell(x: f64) -> String {
    if x.is_nan() {
        "–".to_string()
    } else {
        format!("{x:.4}")
    }
}
