//! The files of a finished fit: `fit.md` (the answer and its intervals
//! first), `fit.csv`, `curves.csv`, `profiles.csv`, `search.csv`,
//! `best.toml`, and the pictures `fit.png`, `profiles.png`, `search.png`.

use super::chaos;
use super::objective::{force_curve, interpolate};
use super::FitResult;
use crate::error::StudyError;
use crate::field;
use soilcut_io::CsvText;
use soilcut_plot::{draw_panels, Panel, Series};
use std::fmt::Write as _;
use std::path::Path;

/// Profiles are drawn up to this Δχ² so that the threshold stays visible.
const PROFILE_CAP: f64 = 40.0;

impl FitResult {
    /// What the profile says of key `j`, in words.
    pub fn verdict(&self, j: usize) -> &'static str {
        match self.profiles.get(j) {
            Some(p) if p.determined => "determined",
            Some(p) if p.bounded => "weakly determined",
            Some(_) => "undetermined",
            None => "not assessed (no profiles)",
        }
    }

    /// The 95 % interval of key `j` in words.
    pub fn interval_text(&self, j: usize) -> String {
        let Some(p) = self.profiles.get(j) else {
            return "–".to_string();
        };
        let free = &self.params[j];
        match (p.lower, p.upper) {
            (Some(a), Some(b)) => format!("{a:.4} to {b:.4}"),
            (None, Some(b)) => format!(
                "≤ {b:.4} (reaches the lower bound {})",
                significant(free.lo)
            ),
            (Some(a), None) => format!(
                "≥ {a:.4} (reaches the upper bound {})",
                significant(free.hi)
            ),
            (None, None) => format!(
                "the whole range {} to {}",
                significant(free.lo),
                significant(free.hi)
            ),
        }
    }

    /// The text files of `soilcut fit` (name, contents): `fit.md` (titled
    /// `title`), `fit.csv`, `curves.csv`, `profiles.csv`, `search.csv` and
    /// the [`best_tomls`](Self::best_tomls).
    pub fn files(&self, title: &str) -> Vec<(String, String)> {
        let mut files = vec![
            ("fit.md".to_string(), self.markdown(title)),
            ("fit.csv".to_string(), self.csv()),
            ("curves.csv".to_string(), self.curves_csv()),
            ("profiles.csv".to_string(), self.profiles_csv()),
            ("search.csv".to_string(), self.search_csv()),
        ];
        files.extend(self.best_tomls());
        files
    }

    /// The files named `best.toml` (the first test's case at the best
    /// values) and `best-<k>.toml` for test k ≥ 2, resolved.
    pub fn best_tomls(&self) -> Vec<(String, String)> {
        self.best_runs
            .iter()
            .enumerate()
            .map(|(k, run)| {
                let name = if k == 0 {
                    "best.toml".to_string()
                } else {
                    format!("best-{}.toml", k + 1)
                };
                (name, run.loaded.resolved_toml())
            })
            .collect()
    }

    /// `fit.csv`: one row per free key: `key,start,lo,hi,best,lower,upper,verdict`
    /// (an interval's end is empty where it reaches the bound).
    pub fn csv(&self) -> String {
        let mut out = CsvText::named(&[
            "key", "start", "lo", "hi", "best", "lower", "upper", "verdict",
        ]);
        for (j, p) in self.params.iter().enumerate() {
            let end = |e: Option<f64>| e.map_or(String::new(), |x| x.to_string());
            let profile = self.profiles.get(j);
            out.fields(&[
                p.key.clone(),
                p.start.to_string(),
                p.lo.to_string(),
                p.hi.to_string(),
                self.best.x[j].to_string(),
                end(profile.and_then(|p| p.lower)),
                end(profile.and_then(|p| p.upper)),
                self.verdict(j).to_string(),
            ]);
        }
        out.finish()
    }

    /// `curves.csv`: for each test and measured point, the measured force,
    /// its weight and the simulated force at the start and at the best
    /// values (empty where the start fails).
    pub fn curves_csv(&self) -> String {
        let mut out = CsvText::named(&["test", "u", "measured", "weight", "start", "fitted"]);
        for (k, t) in self.tests.iter().enumerate() {
            let start = self.start_runs[k].as_ref().map(force_curve);
            let best = force_curve(&self.best_runs[k]);
            for (&(u, p), &w) in t.measured.iter().zip(&t.weights) {
                out.fields(&[
                    t.name.clone(),
                    u.to_string(),
                    p.to_string(),
                    w.to_string(),
                    start
                        .as_ref()
                        .map_or(String::new(), |c| interpolate(c, u).to_string()),
                    interpolate(&best, u).to_string(),
                ]);
            }
        }
        out.finish()
    }

    /// `profiles.csv`: `key,value,delta_chi2,rms`, then the re-optimised
    /// values of every free key (columns named by key).
    pub fn profiles_csv(&self) -> String {
        let mut header = vec![
            "key".to_string(),
            "value".into(),
            "delta_chi2".into(),
            "rms".into(),
        ];
        header.extend(self.params.iter().map(|p| p.key.clone()));
        let mut out = CsvText::named(&header);
        let chi2_min = self.chi2_min();
        for (p, profile) in self.params.iter().zip(&self.profiles) {
            for (v, pt) in &profile.points {
                let mut row = vec![
                    p.key.clone(),
                    v.to_string(),
                    field::number(self.chi2(pt) - chi2_min),
                    field::number(pt.rms),
                ];
                row.extend(pt.x.iter().map(|x| x.to_string()));
                out.fields(&row);
            }
        }
        out.finish()
    }

    /// `search.csv`: one row per generation of the search.
    pub fn search_csv(&self) -> String {
        let mut out = CsvText::named(&[
            "generation",
            "evaluations",
            "best_rms",
            "median_rms",
            "infeasible",
        ]);
        for (g, gen) in self.generations.iter().enumerate() {
            out.fields(&[
                g.to_string(),
                gen.evaluations.to_string(),
                gen.best_rms.to_string(),
                gen.median_rms.to_string(),
                gen.infeasible.to_string(),
            ]);
        }
        out.finish()
    }

    fn chi2(&self, point: &super::problem::Point) -> f64 {
        self.noise.as_ref().map_or(f64::NAN, |n| n.chi2(point))
    }

    fn chi2_min(&self) -> f64 {
        self.chi2(&self.best)
    }

    /// `fit.md`: the answer and its intervals, the pictures, then how it
    /// was found.
    pub fn markdown(&self, title: &str) -> String {
        let mut s = String::new();
        let w = &mut s;
        let _ = writeln!(w, "# Fit: {title}\n");
        let _ = writeln!(
            w,
            "| key | best | 95 % interval | verdict | bounds |\n|---|---|---|---|---|"
        );
        for (j, p) in self.params.iter().enumerate() {
            let _ = writeln!(
                w,
                "| `{}` | {:.4} | {} | {} | {} to {} ({}) |",
                p.key,
                self.best.x[j],
                self.interval_text(j),
                self.verdict(j),
                significant(p.lo),
                significant(p.hi),
                p.rule
            );
        }
        let _ = writeln!(
            w,
            "\nRMS error {:.6} at the best values ({:.6} at the case's own values).",
            self.best.rms, self.start.rms
        );
        self.noise_section(w);
        self.correlation_section(w);
        // profiles.png is drawn only with profiles (`draw`).
        let profiles = match self.profiles.is_empty() {
            true => "",
            false => "![profiles](profiles.png)\n\n",
        };
        let _ = writeln!(
            w,
            "\n![measured and fitted force](fit.png)\n\n{profiles}![search](search.png)\n"
        );
        self.method_section(w);
        s
    }

    fn noise_section(&self, w: &mut String) {
        let Some(noise) = &self.noise else {
            let _ = writeln!(w, "\nNo noise level: the fit is exact or has no more residuals than keys; no intervals.");
            return;
        };
        match self.threshold {
            Some(threshold) => {
                intervals_text(w, threshold);
                self.chaos_text(w);
            }
            None => {
                let _ = writeln!(
                    w,
                    "\nNo intervals: the profiles were not computed (`--profile-points 0`).\n"
                );
            }
        }
        let _ = writeln!(w, "| test | points | noise level σ (from the residuals, at the test's mean weight; χ²'s) | RMS at best |\n|---|---|---|---|");
        for ((t, sigma), run) in self.tests.iter().zip(&noise.sigma).zip(&self.best_runs) {
            let rms = super::objective::sum_of_squares(&t.residuals(self.compare, run))
                / t.weight(self.compare);
            let _ = writeln!(
                w,
                "| {} | {} | {sigma:.6} | {:.6} |",
                t.name,
                t.measured.len(),
                rms.sqrt()
            );
        }
    }

    fn correlation_section(&self, w: &mut String) {
        let Some(c) = &self.correlation else {
            return;
        };
        let _ = writeln!(
            w,
            "\nCorrelation of the keys over the evaluated points within the joint 95 % region (values near ±1 trade off against each other):\n"
        );
        let short: Vec<&str> = self.params.iter().map(|p| p.key.as_str()).collect();
        let _ = writeln!(w, "| | {} |", short.join(" | "));
        let _ = writeln!(w, "|---|{}", "---|".repeat(short.len()));
        for (key, row) in short.iter().zip(c) {
            let cells: Vec<String> = row.iter().map(|r| format!("{r:.2}")).collect();
            let _ = writeln!(w, "| {key} | {} |", cells.join(" | "));
        }
    }

    fn method_section(&self, w: &mut String) {
        let _ = writeln!(
            w,
            "## How it was found\n\nObjective: pooled weighted RMS over {} test(s) of {}.\n",
            self.tests.len(),
            self.compare.describe()
        );
        let (first, last) = (
            &self.generations[0],
            &self.generations[self.generations.len() - 1],
        );
        let _ = writeln!(
            w,
            "{} over the bounds: {} generations, {} runs; best RMS {:.6} in the first generation, {:.6} at the end ({} infeasible points in the first generation, {} in the last). Nelder-Mead polish: RMS {:.6}. Runs in all (search, polish, profiles): {}.",
            self.method.describe(),
            self.generations.len(),
            last.evaluations,
            first.best_rms,
            last.best_rms,
            first.infeasible,
            last.infeasible,
            self.search_rms.min(self.best.rms),
            self.evaluations
        );
    }

    /// Draws `fit.png` (measured and simulated curves, one panel per
    /// test), `profiles.png` (Δχ² of each key) and `search.png` (the
    /// convergence of the search) into `dir`.
    pub fn draw(&self, dir: &Path) -> Result<(), StudyError> {
        draw_panels(
            "Fit: measured and simulated force",
            &self.curve_panels(),
            2,
            &dir.join("fit.png"),
        )?;
        if !self.profiles.is_empty() {
            draw_panels(
                "Profiles: Δχ² with the other keys re-optimised",
                &self.profile_panels(),
                2,
                &dir.join("profiles.png"),
            )?;
        }
        let best: Vec<(f64, f64)> = self
            .generations
            .iter()
            .map(|g| (g.evaluations as f64, g.best_rms))
            .collect();
        let median: Vec<(f64, f64)> = self
            .generations
            .iter()
            .filter(|g| g.median_rms.is_finite())
            .map(|g| (g.evaluations as f64, g.median_rms))
            .collect();
        let panel = Panel {
            x_label: "runs (count)".to_string(),
            y_label: "RMS error of P (γ·length²)".to_string(),
            series: vec![
                Series::line("best so far", best),
                Series::line("median", median),
            ],
        };
        draw_panels(
            &format!("Search: {}", self.method.name()),
            &[panel],
            1,
            &dir.join("search.png"),
        )?;
        Ok(())
    }

    fn curve_panels(&self) -> Vec<Panel> {
        self.tests
            .iter()
            .enumerate()
            .map(|(k, t)| {
                let u_max = t.measured.iter().map(|p| p.0).fold(0.0, f64::max);
                let clip = |c: Vec<(f64, f64)>| c.into_iter().filter(|p| p.0 <= u_max).collect();
                let mut series = vec![Series::points(
                    &format!("measured: {}", t.name),
                    t.measured.clone(),
                )];
                if let Some(run) = &self.start_runs[k] {
                    series.push(Series::line("start", clip(force_curve(run))));
                }
                series.push(Series::line(
                    &format!("fitted, RMS {:.4}", self.best.rms),
                    clip(force_curve(&self.best_runs[k])),
                ));
                Panel {
                    x_label: "u (length)".to_string(),
                    y_label: "P per unit width (γ·length²)".to_string(),
                    series,
                }
            })
            .collect()
    }

    fn profile_panels(&self) -> Vec<Panel> {
        let chi2_min = self.chi2_min();
        let threshold = self.threshold.unwrap_or(f64::NAN).min(PROFILE_CAP);
        self.params
            .iter()
            .zip(&self.profiles)
            .enumerate()
            .map(|(j, (p, profile))| {
                let points: Vec<(f64, f64)> = profile
                    .points
                    .iter()
                    .filter(|(_, pt)| pt.rms.is_finite())
                    .map(|(v, pt)| (*v, (self.chi2(pt) - chi2_min).min(PROFILE_CAP)))
                    .collect();
                Panel {
                    x_label: format!("{} ({})", p.key, self.verdict(j)),
                    y_label: format!("Δχ² (shown up to {PROFILE_CAP})"),
                    series: vec![
                        Series::line("profile", points.clone()),
                        Series::points("", points),
                        Series::line("95 % threshold", vec![(p.lo, threshold), (p.hi, threshold)]),
                        Series::points("best", vec![(self.best.x[j], 0.0)]),
                    ],
                }
            })
            .collect()
    }
}

/// `x` to 4 significant digits, without trailing zeros: a bound such as
/// 40.8 − 10 reads 30.8, not 30.799999999999997.
fn significant(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return x.to_string();
    }
    let decimals = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

impl FitResult {
    /// The chaos's share of the threshold: the best values' members.
    fn chaos_text(&self, w: &mut String) {
        let Some(chaos) = &self.chaos else {
            let _ = writeln!(w, "The chaos's share could not be measured (a member of the best values did not run); the threshold is the bootstrap's alone.\n");
            return;
        };
        let (Some(noise), best) = (&self.noise, &self.best) else {
            return;
        };
        let above: Vec<String> = chaos
            .chi2
            .iter()
            .map(|c| delta_text(c - noise.chi2(best)))
            .collect();
        let _ = writeln!(
            w,
            "The model is chaotic: the best values' own ensemble members (k = {} of the ensembles' rule, docs/guide/ensembles.md) fit the curves with Δχ² = {} from the best point by chance alone, so the threshold is at least the spread of χ² over the best point and its members, {} ({}).\n",
            chaos::MEMBERS.map(|k| k.to_string()).join(", "),
            above.join(", "),
            delta_text(chaos.threshold),
            if self.threshold.is_some_and(|t| t <= chaos.threshold) {
                "the chaos sets it"
            } else {
                "the bootstrap's is larger"
            }
        );
    }
}

/// A Δχ² for `fit.md`: two decimals, or three significant digits where
/// it is huge (a fit that is exact to round-off has a tiny noise level).
fn delta_text(x: f64) -> String {
    if x.abs() < 1e6 {
        format!("{x:.2}")
    } else {
        format!("{x:.2e}")
    }
}

/// How `fit.md`'s intervals were found, with their threshold of Δχ².
fn intervals_text(w: &mut String, threshold: f64) {
    let _ = writeln!(
        w,
        "\nIntervals by profile likelihood: χ² = Σ_t S_t/(w̄_t σ_t²) with each test's noise level σ_t (at its mean weight w̄_t) estimated from the residuals at the best values; for each key the profile of χ² across its bounds, the other keys re-optimised. The 95 % interval spans the key's values over every evaluated point with Δχ² ≤ {}: the threshold, calibrated for the roughness of the objective by a wild bootstrap (replicate curves made of the best fit's curve plus its residuals with random signs, and how far the evaluated points and short refits undercut each replicate's truth), at least the χ²ₚ 95 % quantile of a smooth model with p free keys and at least the chaos's share below: the intervals are the projections of the joint 95 % region. A key is **determined** when its interval ends inside its bounds and lies within ± 1° (angles) or ± 10 % (other keys) of the best value, **weakly determined** when it ends inside its bounds but is wider, **undetermined** when it reaches a bound: the curves do not fix it within its bounds.\n",
        delta_text(threshold)
    );
}

#[cfg(test)]
mod tests {
    use super::significant;

    #[test]
    fn bounds_read_to_four_significant_digits() {
        assert_eq!(significant(40.8 - 10.0), "30.8");
        assert_eq!(significant(0.96 * 0.5), "0.48");
        assert_eq!(significant(-12.345678), "-12.35");
        assert_eq!(significant(1234567.0), "1234567");
        assert_eq!(significant(0.000123456), "0.0001235");
        assert_eq!(significant(90.0), "90");
        assert_eq!(significant(0.0), "0");
    }
}
