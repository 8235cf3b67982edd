//! The files of a sensitivity study: `indices.csv`, `indices2.csv` (the
//! second-order indices, when asked for), `samples.csv`, `tornado.csv` (a
//! case's), `summary.json`, `sensitivity.md`, `timing.csv`.

use super::analysis::{Indices, OutputIndices};
use super::plan::RunRow;
use super::runs::SensitivityResult;
use super::{bootstrap, outputs, sobol, Method};
use crate::field::number;
use soilcut_io::CsvText;

impl SensitivityResult {
    /// `indices.csv`: Sobol `output,key,S1,S1_low,S1_high,ST,ST_low,ST_high`;
    /// Morris `output,key,mu_star,mu_star_low,mu_star_high,sigma,mu`.
    /// Empty fields for an output that does not vary or that a run does
    /// not have; no rows if a run failed.
    pub fn indices_csv(&self) -> String {
        let header = match self.study.method {
            Method::Sobol { .. } => "output,key,S1,S1_low,S1_high,ST,ST_low,ST_high",
            Method::Morris { .. } => "output,key,mu_star,mu_star_low,mu_star_high,sigma,mu",
        };
        let mut out = CsvText::new(header);
        for o in self.analysis.as_deref().unwrap_or(&[]) {
            for (j, key) in self.keys.iter().enumerate() {
                let mut fields = vec![o.name.clone(), key.clone()];
                fields.extend(
                    index_fields(self.study.method, &o.indices, j)
                        .iter()
                        .map(|&x| number(x)),
                );
                out.fields(&fields);
            }
        }
        out.finish()
    }

    /// `indices2.csv`: `output,key,key2,S2,S2_low,S2_high`, a row per pair
    /// of inputs (key before key2 in the inputs' order) of every output;
    /// empty fields for an output without indices; no rows if a run failed.
    pub fn indices2_csv(&self) -> String {
        let mut out = CsvText::new("output,key,key2,S2,S2_low,S2_high");
        for o in self.analysis.as_deref().unwrap_or(&[]) {
            let found = match &o.indices {
                Indices::Sobol(Some(all)) => all.pairs.as_slice(),
                _ => &[],
            };
            for (p, (j, k)) in sobol::pairs(self.keys.len()).enumerate() {
                let s2 = found.get(p).map(|p| p.s2);
                let numbers = s2.map_or([f64::NAN; 3], |i| [i.value, i.low, i.high]);
                let mut fields = vec![o.name.clone(), self.keys[j].clone(), self.keys[k].clone()];
                fields.extend(numbers.iter().map(|&x| number(x)));
                out.fields(&fields);
            }
        }
        out.finish()
    }

    /// `samples.csv`: `run,point,k`, the inputs' values, `status,error`,
    /// the outputs: every run, in the design's order.
    pub fn samples_csv(&self) -> String {
        let mut header: Vec<String> = ["run", "point", "k"].map(String::from).to_vec();
        header.extend(self.keys.iter().cloned());
        header.extend(["status".to_string(), "error".to_string()]);
        header.extend(self.outputs.iter().cloned());
        let mut out = CsvText::named(&header);
        for (i, row) in self.runs.iter().enumerate() {
            let mut fields = vec![
                (i + 1).to_string(),
                (row.point + 1).to_string(),
                row.k.to_string(),
            ];
            fields.extend(self.values[row.point].iter().map(|x| x.to_string()));
            fields.extend(self.outcome_fields(row));
            out.fields(&fields);
        }
        out.finish()
    }

    /// `tornado.csv`: `run,key,end,value,k,status,error`, the outputs:
    /// every run of the tornado, the case's (key and value empty, end
    /// `case`) first, then each key's at `lo` and `hi`; `run` goes on from
    /// samples.csv's.
    pub fn tornado_csv(&self) -> String {
        let mut header: Vec<String> = ["run", "key", "end", "value", "k", "status", "error"]
            .map(String::from)
            .to_vec();
        header.extend(self.outputs.iter().cloned());
        let mut out = CsvText::named(&header);
        for (i, row) in self.tornado_runs.iter().enumerate() {
            let point = &self.tornado[row.point];
            let (key, value) = match point.setting(&self.study.ranges) {
                Some((key, value)) => (key.to_string(), value.to_string()),
                None => (String::new(), String::new()),
            };
            let mut fields = vec![
                (self.runs.len() + i + 1).to_string(),
                key,
                point.end.name().to_string(),
                value,
                row.k.to_string(),
            ];
            fields.extend(self.outcome_fields(row));
            out.fields(&fields);
        }
        out.finish()
    }

    /// `status,error` and the outputs of a run.
    fn outcome_fields(&self, row: &RunRow) -> Vec<String> {
        match &row.outcome {
            Ok(v) => {
                let outputs = v.iter().map(|&x| number(x));
                ["ok".to_string(), String::new()]
                    .into_iter()
                    .chain(outputs)
                    .collect()
            }
            Err(e) => {
                let outputs = self.outputs.iter().map(|_| String::new());
                ["failed".to_string(), e.clone()]
                    .into_iter()
                    .chain(outputs)
                    .collect()
            }
        }
    }

    /// `timing.csv`: `run,wall_time_s`, samples.csv's runs then
    /// tornado.csv's (the only file that changes between identical
    /// studies).
    pub fn timing_csv(&self) -> String {
        let mut out = CsvText::new("run,wall_time_s");
        for (i, row) in self.runs.iter().chain(&self.tornado_runs).enumerate() {
            out.fields(&[(i + 1).to_string(), row.wall_time_s.to_string()]);
        }
        out.finish()
    }

    /// `summary.json`: the study, whether it is complete, each output's
    /// unit, chaos share and the runs that lack it.
    pub fn summary_json(&self) -> String {
        let s = &self.study;
        let (method, levels, second_order) = match s.method {
            Method::Sobol { second_order } => ("sobol", None, second_order),
            Method::Morris { levels } => ("morris", Some(levels), false),
        };
        let ranges: Vec<serde_json::Value> = s
            .ranges
            .iter()
            .map(|r| serde_json::json!({"key": r.key, "lo": r.lo, "hi": r.hi}))
            .collect();
        let outputs: Vec<serde_json::Value> = self
            .analysis
            .as_deref()
            .unwrap_or(&[])
            .iter()
            .map(|o| {
                let undefined = match o.indices {
                    Indices::Undefined { runs } => runs,
                    _ => 0,
                };
                serde_json::json!({
                    "output": o.name, "unit": outputs::unit_of(&o.name),
                    "chaos_share": o.chaos_share, "undefined_runs": undefined,
                })
            })
            .collect();
        let all = self.runs.iter().chain(&self.tornado_runs);
        let failed = all.filter(|r| r.outcome.is_err()).count();
        let json = serde_json::json!({
            "method": method, "levels": levels, "second_order": second_order, "samples": s.samples, "members": s.members,
            "perturbation": self.perturbation, "seed": s.seed, "dummy": s.dummy,
            "keys": ranges, "design_points": self.design.len(), "runs": self.runs.len(),
            "tornado_points": self.tornado.len(), "tornado_runs": self.tornado_runs.len(),
            "failed": failed, "complete": self.analysis.is_ok(),
            "stopped": self.analysis.as_ref().err(),
            "bootstrap": {"resamples": bootstrap::RESAMPLES, "confidence": 0.95, "interval": "normal"},
            "outputs": outputs,
        });
        let mut text = serde_json::to_string_pretty(&json).expect("a summary serialises");
        text.push('\n');
        text
    }

    /// The files, name and contents (timing.csv last; tornado.csv for a
    /// case only).
    pub fn files(&self) -> Vec<(&'static str, String)> {
        let mut files = vec![("indices.csv", self.indices_csv())];
        if let Method::Sobol { second_order: true } = self.study.method {
            files.push(("indices2.csv", self.indices2_csv()));
        }
        files.push(("samples.csv", self.samples_csv()));
        if !self.tornado.is_empty() {
            files.push(("tornado.csv", self.tornado_csv()));
        }
        files.extend([
            ("summary.json", self.summary_json()),
            ("sensitivity.md", self.markdown()),
            ("timing.csv", self.timing_csv()),
        ]);
        files
    }
}

/// The numbers of input `j`'s row of `indices.csv` (NaN: empty).
fn index_fields(method: Method, indices: &Indices, j: usize) -> Vec<f64> {
    match indices {
        Indices::Undefined { .. } => match method {
            Method::Sobol { .. } => vec![f64::NAN; 6],
            Method::Morris { .. } => vec![f64::NAN; 5],
        },
        Indices::Sobol(Some(all)) => {
            let i = &all.inputs[j];
            vec![
                i.s1.value, i.s1.low, i.s1.high, i.st.value, i.st.low, i.st.high,
            ]
        }
        Indices::Sobol(None) => vec![f64::NAN; 6],
        Indices::Morris(all) => {
            let i = &all[j];
            vec![
                i.mu_star.value,
                i.mu_star.low,
                i.mu_star.high,
                i.sigma,
                i.mu,
            ]
        }
    }
}

impl SensitivityResult {
    /// `sensitivity.md`: a table per output, its chaos share beside it.
    pub fn markdown(&self) -> String {
        let mut md = String::from("# Sensitivity\n\n");
        let analysis = match &self.analysis {
            Ok(a) => a,
            Err(e) => return md + &format!("Not complete: {e}. samples.csv has every run.\n"),
        };
        md += &format!(
            "{} design points × {} member(s) = {} runs, seed {}; intervals: 95 %, bootstrap of {} resamples.\n",
            self.design.len(),
            self.study.members,
            self.runs.len(),
            self.study.seed,
            bootstrap::RESAMPLES
        );
        if !self.tornado.is_empty() {
            md += &format!(
                "The tornado: {} points (the case, each key at lo and hi) × {} member(s) = {} runs.\n",
                self.tornado.len(),
                self.study.members,
                self.tornado_runs.len()
            );
        }
        for o in analysis {
            md += &self.output_table(o);
        }
        md
    }

    fn output_table(&self, o: &OutputIndices) -> String {
        let share = o
            .chaos_share
            .map_or("not measured (one member a point)".to_string(), |c| {
                format!("{c:.4}")
            });
        let unit = outputs::unit_of(&o.name);
        let mut md = format!("\n## {} ({unit})\n\n", o.name);
        if let Indices::Undefined { runs } = o.indices {
            return md
                + &format!(
                "Not defined in {runs} of {} runs (see the guide's output table): no indices.\n",
                self.runs.len()
            );
        }
        md += &format!("Chaos share: {share}.\n\n");
        let method = self.study.method;
        let head = match method {
            Method::Sobol { .. } => {
                "| key | S1 | S1 95 % | ST | ST 95 % |\n|---|---|---|---|---|\n"
            }
            Method::Morris { .. } => "| key | μ* | μ* 95 % | σ | μ |\n|---|---|---|---|---|\n",
        };
        md += head;
        for (j, key) in self.keys.iter().enumerate() {
            let f = index_fields(method, &o.indices, j);
            let n = |x: f64| {
                if x.is_finite() {
                    format!("{x:.4}")
                } else {
                    "–".into()
                }
            };
            let cells = match method {
                Method::Sobol { .. } => [
                    n(f[0]),
                    format!("{} to {}", n(f[1]), n(f[2])),
                    n(f[3]),
                    format!("{} to {}", n(f[4]), n(f[5])),
                ],
                Method::Morris { .. } => [
                    n(f[0]),
                    format!("{} to {}", n(f[1]), n(f[2])),
                    n(f[3]),
                    n(f[4]),
                ],
            };
            md += &format!("| {key} | {} |\n", cells.join(" | "));
        }
        md + &self.pairs_table(o) + &self.tornado_table(o)
    }

    /// Output `o`'s second-order indices, if the study has them.
    fn pairs_table(&self, o: &OutputIndices) -> String {
        let Indices::Sobol(Some(all)) = &o.indices else {
            return String::new();
        };
        if all.pairs.is_empty() {
            return String::new();
        }
        let mut md = String::from("\n| keys | S2 | S2 95 % |\n|---|---|---|\n");
        for p in &all.pairs {
            let i = p.s2;
            md += &format!(
                "| {} × {} | {:.4} | {:.4} to {:.4} |\n",
                self.keys[p.j], self.keys[p.k], i.value, i.low, i.high
            );
        }
        md
    }

    /// Output `o`'s tornado in words: the case's value, each key's at its
    /// ends, widest range first (none for a test function).
    fn tornado_table(&self, o: &OutputIndices) -> String {
        let Some(ranges) = self.tornado_ranges(&o.name) else {
            return String::new();
        };
        let n = |x: f64| {
            if x.is_finite() {
                format!("{x:.4}")
            } else {
                "–".into()
            }
        };
        let mut md = format!(
            "\nTornado, the others at the case's values (the case: {}):\n\n| key | lo | at lo | hi | at hi |\n|---|---|---|---|---|\n",
            n(ranges.case)
        );
        for &(j, at_lo, at_hi) in &ranges.keys {
            let r = &self.study.ranges[j];
            md += &format!(
                "| {} | {} | {} | {} | {} |\n",
                r.key,
                r.lo,
                n(at_lo),
                r.hi,
                n(at_hi)
            );
        }
        md
    }
}
