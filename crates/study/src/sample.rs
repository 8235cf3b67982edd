//! Which values a sweep gives its varied keys: `--vary key=SPEC` and
//! `--sample grid|lhs:N`.
//!
//! SPEC is `lo:hi:n` (n evenly spaced values from lo to hi, both included:
//! a grid), `lo:hi` (the interval, for sampling), or a comma-separated
//! list of values (`0.3,0.6`, `full,by-position`), each read like a
//! `--set` value.

use crate::error::StudyError;
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::str::FromStr;

/// The values of one varied key.
#[derive(Clone, Debug, PartialEq)]
pub enum Values {
    /// `lo:hi:n`: n evenly spaced values, lo and hi included.
    Grid {
        /// First value.
        lo: f64,
        /// Last value.
        hi: f64,
        /// Number of values.
        n: usize,
    },
    /// `lo:hi`: the interval, sampled.
    Range {
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
    /// `a,b,c`: these values.
    List(Vec<toml::Value>),
}

/// One `--vary key=SPEC`.
#[derive(Clone, Debug, PartialEq)]
pub struct Vary {
    /// The case-file key.
    pub key: String,
    /// Its values.
    pub values: Values,
}

fn spec_error(text: &str, message: &str) -> StudyError {
    StudyError::Spec(format!("--vary {text}: {message}"))
}

fn finite(text: &str, part: &str) -> Result<f64, StudyError> {
    match part.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(spec_error(
            text,
            &format!("{part:?} is not a finite number (expected lo:hi:n, lo:hi or a,b,c)"),
        )),
    }
}

/// The rules of every spec, whether read from `--vary` text or given as
/// values by a front end (Python's tuples and lists): one function each,
/// so both refuse the same specs with the same words.
impl Vary {
    /// `key` over `n` evenly spaced values from `lo` to `hi`, both
    /// included (`lo:hi:n`).
    pub fn grid(key: &str, lo: f64, hi: f64, n: usize) -> Result<Vary, StudyError> {
        let text = format!("{key}={lo}:{hi}:{n}");
        Vary::check_range(&text, lo, hi)?;
        if n == 0 {
            return Err(spec_error(
                &text,
                "n of lo:hi:n must be a whole number >= 1",
            ));
        }
        if n > 1 && hi == lo {
            return Err(spec_error(&text, "lo:hi:n with n > 1 needs hi > lo"));
        }
        Vary::of(&text, key, Values::Grid { lo, hi, n })
    }

    /// `key` over the interval from `lo` to `hi`, sampled (`lo:hi`).
    pub fn range(key: &str, lo: f64, hi: f64) -> Result<Vary, StudyError> {
        let text = format!("{key}={lo}:{hi}");
        Vary::check_range(&text, lo, hi)?;
        Vary::of(&text, key, Values::Range { lo, hi })
    }

    /// `key` over these values (`a,b,c`).
    pub fn list(key: &str, values: Vec<toml::Value>) -> Result<Vary, StudyError> {
        if values.is_empty() {
            return Err(spec_error(&format!("{key}="), "no values"));
        }
        Vary::of(&format!("{key}=a,b,c"), key, Values::List(values))
    }

    fn check_range(text: &str, lo: f64, hi: f64) -> Result<(), StudyError> {
        for x in [lo, hi] {
            if !x.is_finite() {
                return Err(spec_error(text, &format!("{x} is not a finite number")));
            }
        }
        if hi < lo {
            return Err(spec_error(text, "hi must be >= lo"));
        }
        Ok(())
    }

    fn of(text: &str, key: &str, values: Values) -> Result<Vary, StudyError> {
        if key.is_empty() || key.split('.').any(str::is_empty) {
            return Err(spec_error(text, "expected a non-empty key.path"));
        }
        Ok(Vary {
            key: key.to_string(),
            values,
        })
    }
}

impl FromStr for Vary {
    type Err = StudyError;

    fn from_str(text: &str) -> Result<Self, StudyError> {
        let (key, spec) = text
            .split_once('=')
            .ok_or_else(|| spec_error(text, "expected key.path=lo:hi:n, lo:hi or a,b,c"))?;
        let (key, spec) = (key.trim(), spec.trim());
        if !spec.contains(':') || spec.contains(',') {
            if spec.split(',').any(|s| s.trim().is_empty()) {
                return Err(spec_error(text, "a list item is empty"));
            }
            let items = spec
                .split(',')
                .map(|s| soilcut_io::parse_value(s.trim()))
                .collect();
            return Vary::list(key, items);
        }
        let parts: Vec<&str> = spec.split(':').collect();
        let lo = finite(text, parts[0])?;
        let hi = finite(text, parts[1])?;
        match parts[2..] {
            [] => Vary::range(key, lo, hi),
            [n] => {
                let n = n
                    .trim()
                    .parse::<usize>()
                    .map_err(|_| spec_error(text, "n of lo:hi:n must be a whole number >= 1"))?;
                Vary::grid(key, lo, hi, n)
            }
            _ => Err(spec_error(text, "expected lo:hi:n or lo:hi")),
        }
    }
}

/// How a sweep chooses its runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sample {
    /// Every combination of the values (`lo:hi:n` and lists).
    Grid,
    /// A Latin-hypercube sample of `runs` points (`lo:hi` and lists).
    Lhs {
        /// Number of points.
        runs: usize,
        /// Seed of the random pairing of strata.
        seed: u64,
    },
}

impl Sample {
    /// `grid` or `lhs:N`, with the seed of `--seed`.
    pub fn parse(text: &str, seed: u64) -> Result<Self, StudyError> {
        match text.trim() {
            "grid" => Ok(Sample::Grid),
            other => other
                .strip_prefix("lhs:")
                .and_then(|n| n.trim().parse::<usize>().ok())
                .filter(|&n| n >= 1)
                .map(|runs| Sample::Lhs { runs, seed })
                .ok_or_else(|| {
                    StudyError::Spec(format!(
                        "--sample {text}: expected grid or lhs:N with N >= 1"
                    ))
                }),
        }
    }
}

/// The most runs a sweep takes: each run's point and row are held until
/// the sweep ends (a few hundred bytes a run, and a run takes at least a
/// millisecond), so 1e5 runs are a day's work on one core; 1e8 (issue 50)
/// took more memory than the machine had before the first run.
pub const MAX_RUNS: usize = 100_000;

/// The runs a sweep's `what` gives, if no more than [`MAX_RUNS`].
fn within_runs(runs: usize, what: &str) -> Result<(), StudyError> {
    if runs <= MAX_RUNS {
        return Ok(());
    }
    Err(StudyError::Spec(format!(
        "{what}: {runs} runs; a sweep takes at most {MAX_RUNS} (1e5 runs): split it or sample \
         it (--sample lhs:N with N <= {MAX_RUNS})"
    )))
}

/// The value of `lo:hi:n` number `i` (from 0): lo and hi exactly at the ends.
fn grid_value(lo: f64, hi: f64, n: usize, i: usize) -> f64 {
    if n == 1 || i == 0 {
        lo
    } else if i == n - 1 {
        hi
    } else {
        lo + (hi - lo) * i as f64 / (n - 1) as f64
    }
}

/// The runs of a sweep: one value per varied key, in the order of `varies`.
/// Grid: every combination, the last key changing fastest. LHS: run i
/// takes, for each key, a uniform point of stratum π(i) of its interval
/// (list items: stratum π(i) of the list's indices), with one seeded random
/// permutation π per key, so that every stratum of every key is sampled
/// exactly once.
pub fn points(varies: &[Vary], sample: Sample) -> Result<Vec<Vec<toml::Value>>, StudyError> {
    if varies.is_empty() {
        return Err(StudyError::Spec(
            "give at least one --vary key=SPEC".to_string(),
        ));
    }
    for (i, v) in varies.iter().enumerate() {
        if varies[..i].iter().any(|w| w.key == v.key) {
            return Err(StudyError::Spec(format!(
                "--vary {}: the key is varied twice",
                v.key
            )));
        }
    }
    match sample {
        Sample::Grid => grid(varies),
        Sample::Lhs { runs, seed } => lhs(varies, runs, seed),
    }
}

fn grid(varies: &[Vary]) -> Result<Vec<Vec<toml::Value>>, StudyError> {
    // Counted before any axis is made: an axis of 1e8 values alone took
    // gigabytes.
    let mut runs = 1usize;
    for v in varies {
        let n = match &v.values {
            Values::Grid { n, .. } => *n,
            Values::List(items) => items.len(),
            Values::Range { .. } => 1,
        };
        runs = runs.saturating_mul(n);
        within_runs(runs, &format!("--vary {}", v.key))?;
    }
    let mut axes = Vec::with_capacity(varies.len());
    for v in varies {
        axes.push(match &v.values {
            Values::Grid { lo, hi, n } => (0..*n)
                .map(|i| toml::Value::Float(grid_value(*lo, *hi, *n, i)))
                .collect(),
            Values::List(items) => items.clone(),
            Values::Range { .. } => {
                return Err(StudyError::Spec(format!(
                    "--vary {}: lo:hi is for --sample lhs:N; give lo:hi:n for a grid",
                    v.key
                )))
            }
        });
    }
    let total = axes
        .iter()
        .try_fold(1usize, |acc, a: &Vec<toml::Value>| acc.checked_mul(a.len()));
    let total = total.ok_or_else(|| StudyError::Spec("too many combinations".to_string()))?;
    let mut points = Vec::with_capacity(total);
    for mut index in 0..total {
        let mut point = vec![toml::Value::Boolean(false); axes.len()];
        for (slot, axis) in point.iter_mut().zip(&axes).rev() {
            *slot = axis[index % axis.len()].clone();
            index /= axis.len();
        }
        points.push(point);
    }
    Ok(points)
}

fn lhs(varies: &[Vary], runs: usize, seed: u64) -> Result<Vec<Vec<toml::Value>>, StudyError> {
    within_runs(runs, &format!("--sample lhs:{runs}"))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut points = vec![Vec::with_capacity(varies.len()); runs];
    for v in varies {
        let mut strata: Vec<usize> = (0..runs).collect();
        strata.shuffle(&mut rng);
        for (point, stratum) in points.iter_mut().zip(strata) {
            let t = (stratum as f64 + rng.random::<f64>()) / runs as f64;
            point.push(match &v.values {
                Values::Range { lo, hi } => toml::Value::Float((lo + (hi - lo) * t).min(*hi)),
                Values::List(items) => {
                    items[(stratum * items.len() / runs).min(items.len() - 1)].clone()
                }
                Values::Grid { .. } => {
                    return Err(StudyError::Spec(format!(
                        "--vary {}: lo:hi:n is for a grid; give lo:hi with --sample lhs:N",
                        v.key
                    )))
                }
            });
        }
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vary(text: &str) -> Vary {
        text.parse().unwrap()
    }

    fn float(v: &toml::Value) -> f64 {
        v.as_float().unwrap()
    }

    #[test]
    fn specs_are_read() {
        assert_eq!(
            vary("soil.friction.peak=30:45:7").values,
            Values::Grid {
                lo: 30.0,
                hi: 45.0,
                n: 7
            }
        );
        assert_eq!(vary("a.b=-1:2").values, Values::Range { lo: -1.0, hi: 2.0 });
        let Values::List(items) = vary("choices.band_shear=full,by-position").values else {
            panic!()
        };
        assert_eq!(items[1].as_str(), Some("by-position"));
        let Values::List(items) = vary("soil.d50=0.3, 0.6").values else {
            panic!()
        };
        assert_eq!(items[1].as_float(), Some(0.6));
        for bad in [
            "x",
            "=1:2",
            "a..b=1",
            "a=2:1",
            "a=1:2:0",
            "a=1:2:x",
            "a=1:2:3:4",
            "a=1,",
            "a=x:2",
            "a=1:1:3",
            "a=nan:2",
        ] {
            assert!(bad.parse::<Vary>().is_err(), "{bad}");
        }
        // Values given directly obey the same rules as the text.
        assert_eq!(Vary::grid("a", 30.0, 45.0, 7).unwrap(), vary("a=30:45:7"));
        assert_eq!(Vary::range("a", -1.0, 2.0).unwrap(), vary("a=-1:2"));
        for bad in [
            Vary::grid("a", 2.0, 1.0, 3),
            Vary::grid("a", 1.0, 2.0, 0),
            Vary::grid("a", 1.0, 1.0, 3),
            Vary::range("a", f64::NAN, 2.0),
            Vary::range("a..b", 1.0, 2.0),
            Vary::list("a", vec![]),
        ] {
            assert!(bad.is_err(), "{bad:?}");
        }
    }

    #[test]
    fn grid_count_is_the_product_and_last_key_is_fastest() {
        let varies = [vary("a=30:45:7"), vary("b=0.3,0.6"), vary("c=1:3:3")];
        let p = points(&varies, Sample::Grid).unwrap();
        assert_eq!(p.len(), 7 * 2 * 3);
        assert_eq!(float(&p[0][0]), 30.0);
        assert_eq!(float(&p[p.len() - 1][0]), 45.0);
        assert_eq!(float(&p[1][2]), 2.0);
        assert_eq!(float(&p[3][1]), 0.6);
        assert_eq!(float(&p[6][0]), 32.5);
        let mut seen: Vec<String> = p.iter().map(|q| format!("{q:?}")).collect();
        seen.sort();
        seen.dedup();
        assert_eq!(seen.len(), p.len(), "every combination once");
    }

    #[test]
    fn lhs_samples_every_stratum_of_every_key_once() {
        let varies = [vary("a=30:45"), vary("b=-2:0.5"), vary("c=x,y,z,w")];
        let runs = 40;
        let p = points(&varies, Sample::Lhs { runs, seed: 7 }).unwrap();
        assert_eq!(p.len(), runs);
        for (k, (lo, hi)) in [(0usize, (30.0, 45.0)), (1, (-2.0, 0.5))] {
            let mut strata: Vec<usize> = p
                .iter()
                .map(|q| {
                    let x = float(&q[k]);
                    assert!((lo..=hi).contains(&x));
                    ((x - lo) / (hi - lo) * runs as f64).floor() as usize
                })
                .collect();
            strata.sort();
            assert_eq!(strata, (0..runs).collect::<Vec<_>>(), "key {k}");
        }
        for item in ["x", "y", "z", "w"] {
            let count = p.iter().filter(|q| q[2].as_str() == Some(item)).count();
            assert_eq!(count, runs / 4, "{item}");
        }
        let again = points(&varies, Sample::Lhs { runs, seed: 7 }).unwrap();
        assert_eq!(p, again, "same seed, same sample");
        let other = points(&varies, Sample::Lhs { runs, seed: 8 }).unwrap();
        assert_ne!(p, other);
    }

    #[test]
    fn specs_must_fit_the_sampling() {
        assert!(points(&[vary("a=1:2")], Sample::Grid).is_err());
        assert!(points(&[vary("a=1:2:3")], Sample::Lhs { runs: 3, seed: 0 }).is_err());
        assert!(points(&[vary("a=1,2"), vary("a=3,4")], Sample::Grid).is_err());
        assert!(points(&[], Sample::Grid).is_err());
        assert_eq!(
            Sample::parse("lhs:12", 3).unwrap(),
            Sample::Lhs { runs: 12, seed: 3 }
        );
        assert!(Sample::parse("lhs:0", 3).is_err());
        assert!(Sample::parse("random", 3).is_err());
    }
}
