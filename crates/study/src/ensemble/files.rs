//! What an ensemble writes: `ensemble.csv`, `summary.json`, every member's
//! run folder and the force envelope picture.

use super::{member_folder, EnsembleResult, Member};
use crate::accuracy::{Spread, WHOLE_RUN, WINDOW_CEILING, WINDOW_FLOOR};
use crate::field;
use serde_json::{json, Value};
use soilcut_io::CsvText;
use soilcut_io::{Columns, OutputError};
use soilcut_plot::Envelope;
use std::path::Path;

/// Where the envelope pictures go in the ensemble's folder.
pub const ENVELOPE: [&str; 2] = ["plots/envelope.png", "plots/envelope.svg"];

/// The accuracy rule in words (docs/model.md §12).
pub fn accuracy_rule() -> String {
    format!(
        "a scheme is accurate on a case when every unit-window ensemble mean of P/(γ0 d²) is \
         within clamp(2 standard errors of the difference of the two ensemble means, {} %, {} %) \
         of the reference grid's ensemble, and the whole-run ensemble mean within {} %",
        WINDOW_FLOOR * 100.0,
        WINDOW_CEILING * 100.0,
        WHOLE_RUN * 100.0
    )
}

fn spread_json(s: &Spread) -> Value {
    json!({
        "mean": s.mean,
        "std": s.std,
        "standard_error": s.standard_error(),
        "min": s.min,
        "max": s.max,
    })
}

impl EnsembleResult {
    /// `ensemble.csv`: one row per unit window k ≤ u/d < k + 1: the
    /// members' window means of P/(γ0 d²), their mean, sample standard
    /// deviation, least and largest, then each member's value (a figure
    /// that does not exist, e.g. the spread of one member, is empty).
    pub fn ensemble_csv(&self) -> String {
        let columns = self.window_columns();
        let mut out = CsvText::named(columns.names());
        for i in 0..columns.len() {
            let row: Vec<String> = columns.iter().map(|(_, v)| field::number(v[i])).collect();
            out.fields(&row);
        }
        out.finish()
    }

    /// The numbers of `ensemble.csv` (NaN where the file is empty).
    pub fn window_columns(&self) -> Columns {
        let mut names: Vec<String> = [
            "u_over_d_from",
            "u_over_d_to",
            "members",
            "mean",
            "std",
            "min",
            "max",
        ]
        .map(String::from)
        .to_vec();
        names.extend(self.members.iter().map(|m| member_folder(m.k)));
        let mut out = Columns::named(names);
        for (w, s) in self.windows.iter().enumerate() {
            let mut row = vec![
                w as f64,
                (w + 1) as f64,
                s.n as f64,
                s.mean,
                s.std,
                s.min,
                s.max,
            ];
            row.extend(self.members.iter().map(|m| m.window_means[w]));
            out.push(&row);
        }
        out
    }

    /// `summary.json`: the perturbation, the spread of the whole-run mean,
    /// of the largest and the first force and of every window mean. The
    /// same on any number of threads (wall times are in [`Self::timing_csv`]).
    pub fn summary_json(&self) -> String {
        let mut text =
            serde_json::to_string_pretty(&self.summary_value()).expect("a summary serialises");
        text.push('\n');
        text
    }

    /// `summary.json` as a JSON value.
    pub fn summary_value(&self) -> Value {
        let p = &self.perturbation;
        let windows: Vec<Value> = self
            .windows
            .iter()
            .enumerate()
            .map(|(w, s)| {
                let mut v = spread_json(s);
                v["u_over_d_from"] = json!(w);
                v["u_over_d_to"] = json!(w + 1);
                v
            })
            .collect();
        json!({
            "name": self.name,
            "title": self.title,
            "members": self.members.len(),
            "perturbation": {
                "key": p.key,
                "base": p.base,
                "rule": p.rule(),
                "k": self.members.iter().map(|m| m.k).collect::<Vec<_>>(),
                "values": self.members.iter().map(|m| m.value).collect::<Vec<_>>(),
                "folders": self.members.iter().map(|m| member_folder(m.k)).collect::<Vec<_>>(),
            },
            "mean_force_norm": spread_json(&self.whole_run),
            "max_force_norm": spread_json(&self.max_force),
            "initial_force_norm": spread_json(&self.initial_force),
            "windows": windows,
            "accuracy_rule": accuracy_rule(),
        })
    }

    /// `timing.csv`: each member's k and the wall time of its simulation, s
    /// (the only figure that changes between identical ensembles).
    pub fn timing_csv(&self) -> String {
        let mut out = CsvText::named(&["k", "folder", "wall_time_s"]);
        for m in &self.members {
            out.fields(&[
                m.k.to_string(),
                member_folder(m.k),
                m.run.wall_time_s.to_string(),
            ]);
        }
        out.finish()
    }

    /// What the envelope picture draws.
    pub fn envelope(&self) -> Envelope {
        let steps = self
            .members
            .iter()
            .map(|m| m.force.len())
            .min()
            .unwrap_or(0);
        let at = |i: usize| -> Spread {
            Spread::of(
                &self
                    .members
                    .iter()
                    .map(|m| m.force[i].1)
                    .collect::<Vec<_>>(),
            )
        };
        let u = |i: usize| self.members[0].force[i].0;
        let spreads: Vec<Spread> = (0..steps).map(at).collect();
        Envelope {
            title: format!("{}: ensemble of {}", self.title, self.members.len()),
            members: self.members.iter().map(|m| m.force.clone()).collect(),
            mean: (0..steps).map(|i| (u(i), spreads[i].mean)).collect(),
            band: (0..steps)
                .map(|i| {
                    (
                        u(i),
                        spreads[i].mean - spreads[i].std,
                        spreads[i].mean + spreads[i].std,
                    )
                })
                .collect(),
            windows: self
                .windows
                .iter()
                .enumerate()
                .map(|(w, s)| (w as f64, (w + 1) as f64, s.mean))
                .collect(),
        }
    }

    /// Writes the ensemble's folder `dir`: `ensemble.csv`, `summary.json`,
    /// `timing.csv`,
    /// each member's run folder (`k-3` … `k+3`, as `soilcut run` writes it)
    /// and, with `pictures`, the members' pictures and
    /// `plots/envelope.{png,svg}`; all of it appears together or not at all.
    pub fn write(&self, dir: &Path, force: bool, pictures: bool) -> Result<(), OutputError> {
        self.write_into(soilcut_io::OutputDir::claim(dir, force)?, pictures)
            .map(drop)
    }

    /// [`EnsembleResult::write`] into a folder claimed before the members ran.
    pub fn write_into(
        &self,
        dir: soilcut_io::OutputDir,
        pictures: bool,
    ) -> Result<soilcut_io::Published, OutputError> {
        let files = [
            ("ensemble.csv", self.ensemble_csv()),
            ("summary.json", self.summary_json()),
            ("timing.csv", self.timing_csv()),
        ];
        dir.write_then(&files, |staged| {
            for m in &self.members {
                write_member(staged, m, pictures)?;
            }
            if pictures {
                self.draw_envelope(staged)?;
            }
            Ok(())
        })
    }

    fn draw_envelope(&self, dir: &Path) -> Result<(), OutputError> {
        let plots = dir.join("plots");
        std::fs::create_dir_all(&plots).map_err(OutputError::io(&plots))?;
        let envelope = self.envelope();
        for name in ENVELOPE {
            let path = dir.join(name);
            soilcut_plot::draw_envelope(&envelope, &path).map_err(|e| OutputError::Io {
                path: e.path,
                source: std::io::Error::other(e.message),
            })?;
        }
        Ok(())
    }
}

fn write_member(dir: &Path, m: &Member, pictures: bool) -> Result<(), OutputError> {
    soilcut_io::write_run_dir(&dir.join(member_folder(m.k)), &m.run.files, false, pictures)
}

/// The spreads an ensemble's folder records: what the accuracy rule needs
/// to judge one ensemble against another without rerunning either.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedSpread {
    /// The case's title.
    pub title: String,
    /// Each unit window's spread (`ensemble.csv`).
    pub windows: Vec<Spread>,
    /// The whole-run mean's spread (`summary.json`).
    pub whole_run: Spread,
}

impl RecordedSpread {
    /// Reads `dir/ensemble.csv` and `dir/summary.json`.
    pub fn read(dir: &Path) -> Result<RecordedSpread, soilcut_io::RunFilesError> {
        let csv = dir.join("ensemble.csv");
        if !csv.exists() {
            return Err(not_an_ensemble(dir));
        }
        let table = Columns::read(&csv)?;
        let [n, mean, std, min, max] = table
            .columns(["members", "mean", "std", "min", "max"])
            .map_err(|message| soilcut_io::RunFilesError { path: csv, message })?;
        let windows = (0..table.len())
            .map(|i| Spread {
                n: n[i] as usize,
                mean: mean[i],
                std: std[i],
                min: min[i],
                max: max[i],
            })
            .collect();
        let path = dir.join("summary.json");
        let bad = |message: String| soilcut_io::RunFilesError {
            path: path.clone(),
            message,
        };
        let text = std::fs::read_to_string(&path).map_err(|e| bad(e.to_string()))?;
        let json: Value = serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
        let number = |v: &Value, key: &str| {
            v[key]
                .as_f64()
                .ok_or_else(|| bad(format!("mean_force_norm.{key}: expected a number")))
        };
        let whole = &json["mean_force_norm"];
        let whole_run = Spread {
            n: json["members"]
                .as_u64()
                .ok_or_else(|| bad("members: expected a whole number".into()))?
                as usize,
            mean: number(whole, "mean")?,
            std: number(whole, "std")?,
            min: number(whole, "min")?,
            max: number(whole, "max")?,
        };
        Ok(RecordedSpread {
            title: json["title"].as_str().unwrap_or_default().to_string(),
            windows,
            whole_run,
        })
    }

    /// This ensemble judged against `reference` by the rule.
    pub fn agreement(&self, reference: &RecordedSpread) -> crate::accuracy::Agreement {
        crate::accuracy::agreement(
            &self.windows,
            &self.whole_run,
            &reference.windows,
            &reference.whole_run,
        )
    }
}

/// Why `dir`, which holds no `ensemble.csv`, is not an ensemble folder.
fn not_an_ensemble(dir: &Path) -> soilcut_io::RunFilesError {
    let what = if !dir.is_dir() {
        "no such folder"
    } else if dir.join("history.csv").exists() {
        "a run folder, not an ensemble folder (no ensemble.csv)"
    } else {
        "not an ensemble folder (no ensemble.csv)"
    };
    soilcut_io::RunFilesError {
        path: dir.to_path_buf(),
        message: format!("{what}: give folders written by `soilcut run CASE --ensemble N`"),
    }
}
