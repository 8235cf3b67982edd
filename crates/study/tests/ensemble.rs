//! Ensembles on a short, coarse case: the perturbation, the spread and
//! determinism.

use soilcut_study::ensemble::{member_offsets, Ensemble, EnsembleResult};
use soilcut_study::{no_progress, BaseCase};

const REFINED: &str = include_str!("../../io/testdata/refined.toml");
const ORIGINAL: &str = include_str!("../../io/testdata/original.toml");

fn ensemble(text: &str, set: &[&str], members: usize, jobs: usize) -> Ensemble {
    let set = set.iter().map(|s| s.parse().unwrap()).collect();
    Ensemble {
        base: BaseCase::new(text.to_string(), set).unwrap(),
        members,
        jobs,
    }
}

fn short(members: usize, jobs: usize) -> EnsembleResult {
    ensemble(
        REFINED,
        &["run.travel=40", "run.increment=0.5"],
        members,
        jobs,
    )
    .run(&no_progress)
    .unwrap()
}

fn file<'a>(files: &'a [(&str, String)], name: &str) -> &'a str {
    &files.iter().find(|f| f.0 == name).unwrap().1
}

#[test]
fn members_are_k_minus_3_to_3_with_d50_scaled() {
    assert_eq!(member_offsets(7), [-3, -2, -1, 0, 1, 2, 3]);
    assert_eq!(member_offsets(4), [-2, -1, 0, 1]);
    let r = short(7, 2);
    assert_eq!(r.perturbation.key, "soil.d50");
    for m in &r.members {
        let expected = 0.6 * (1.0 + 0.001 * f64::from(m.k));
        let resolved = file(&m.run.files, "case.resolved.toml");
        assert!(
            resolved.contains(&format!("d50 = {expected}")),
            "k = {}: {resolved}",
            m.k
        );
        let band = m.loaded.case.soil.band_width;
        assert!((band - 7.0 * expected).abs() < 1e-12, "dB = 7 d50");
    }
}

#[test]
fn member_zero_is_the_case_itself_bit_for_bit() {
    let r = short(3, 1);
    let zero = r.members.iter().find(|m| m.k == 0).unwrap();
    let base = BaseCase::new(
        REFINED.to_string(),
        vec![
            "run.travel=40".parse().unwrap(),
            "run.increment=0.5".parse().unwrap(),
        ],
    )
    .unwrap();
    let alone = base.run(&[]).unwrap();
    assert_eq!(zero.run.history, alone.history);
    assert_eq!(
        file(&zero.run.files, "history.csv"),
        file(&alone.files(), "history.csv")
    );
}

#[test]
fn spreads_are_those_of_the_members_window_means() {
    let r = short(5, 2);
    assert_eq!(r.windows.len(), 2, "travel 2 d: two unit windows");
    for (w, s) in r.windows.iter().enumerate() {
        // Window means recomputed from each member's history.
        let means: Vec<f64> = r
            .members
            .iter()
            .map(|m| {
                let f: Vec<f64> = m
                    .run
                    .history
                    .iter()
                    .filter(|h| (h.u / 20.0).floor() as usize == w)
                    .map(|h| h.force_norm)
                    .collect();
                f.iter().sum::<f64>() / f.len() as f64
            })
            .collect();
        let mean = means.iter().sum::<f64>() / 5.0;
        let var = means.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 4.0;
        assert!((s.mean - mean).abs() < 1e-12 * mean);
        assert!((s.std - var.sqrt()).abs() < 1e-9 * mean);
        let lo = means.iter().copied().fold(f64::INFINITY, f64::min);
        assert_eq!(s.min, lo);
        assert!(s.min <= s.mean && s.mean <= s.max);
    }
    // The perturbation is imperceptible but not nothing: the members differ.
    assert!(r.windows.iter().any(|s| s.std > 0.0));
    assert!(r.whole_run.std < 0.05 * r.whole_run.mean);
    assert_eq!(r.initial_force.n, 5);
}

#[test]
fn the_same_on_any_number_of_threads() {
    let (a, b) = (short(4, 1), short(4, 2));
    assert_eq!(a.ensemble_csv(), b.ensemble_csv());
    assert_eq!(a.summary_json(), b.summary_json());
    for (x, y) in a.members.iter().zip(&b.members) {
        assert_eq!(x.run.history, y.run.history);
    }
    assert_eq!(a.envelope(), b.envelope());
}

#[test]
fn the_original_model_perturbs_the_wall_friction() {
    let r = ensemble(ORIGINAL, &["run.travel=20", "run.increment=0.5"], 3, 2)
        .run(&no_progress)
        .unwrap();
    assert_eq!(r.perturbation.key, "blade.wall_friction");
    let phi_w: Vec<f64> = r
        .members
        .iter()
        .map(|m| m.loaded.case.blade.wall_friction)
        .collect();
    let base = r.perturbation.base;
    assert_eq!(phi_w, [base - 0.01, base, base + 0.01]);
}

#[test]
fn one_member_is_refused_naming_the_option() {
    let e = ensemble(REFINED, &[], 1, 1).run(&no_progress).unwrap_err();
    assert!(e.to_string().contains("--ensemble 1"), "{e}");
}

#[test]
fn a_member_that_fails_is_named() {
    // φw + 0.01° × k reaches the soil's friction: member k = +1 is invalid.
    let set = [
        "run.travel=20",
        "run.increment=0.5",
        "blade.wall_friction=29.995",
    ];
    let e = ensemble(ORIGINAL, &set, 3, 1)
        .run(&no_progress)
        .unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("member k = 1") && text.contains("blade.wall_friction"),
        "{text}"
    );
}

#[test]
fn the_folder_holds_every_member_and_the_spread() {
    let r = short(3, 2);
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ens");
    r.write(&out, false, false).unwrap();
    for name in ["ensemble.csv", "summary.json", "timing.csv"] {
        assert!(out.join(name).is_file(), "{name}");
    }
    for k in ["k-1", "k+0", "k+1"] {
        let h = std::fs::read_to_string(out.join(k).join("history.csv")).unwrap();
        assert!(h.starts_with("step,u,"), "{k}");
    }
    let csv = std::fs::read_to_string(out.join("ensemble.csv")).unwrap();
    assert!(csv.starts_with("u_over_d_from,u_over_d_to,members,mean,std,min,max,k-1,k+0,k+1\n"));
    assert_eq!(csv.lines().count(), 3);
    assert!(r.write(&out, false, false).is_err(), "an occupied folder");
}

#[test]
fn converging_ensembles_are_judged_against_the_finest_level() {
    use soilcut_study::converge::ensembles::EnsembleConverge;
    use soilcut_study::converge::Refine;
    let set = ["run.travel=40", "run.increment=1"]
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    let study = EnsembleConverge {
        base: BaseCase::new(REFINED.to_string(), set).unwrap(),
        levels: 2,
        refine: Refine::Both,
        members: 3,
        jobs: 2,
    };
    let r = study.run(&no_progress).unwrap();
    let increments: Vec<f64> = r.levels.iter().map(|l| l.increment).collect();
    assert_eq!(increments, [1.0, 0.5]);
    let agreements = r.agreements();
    // The finest level against itself: no deviation, accurate.
    let finest = agreements.last().unwrap();
    assert!(finest.accurate());
    assert!(finest.windows.iter().all(|v| v.deviation == 0.0));
    // The coarse level's deviation is its mean's from the finest's.
    let (coarse, fine) = (&r.levels[0].ensemble, &r.levels[1].ensemble);
    let expected = (coarse.whole_run.mean - fine.whole_run.mean) / fine.whole_run.mean;
    assert!((agreements[0].whole_run.deviation - expected).abs() < 1e-15);
    // converge.csv: one row per level and window, plus the whole run.
    let csv = r.csv();
    assert_eq!(csv.lines().count(), 1 + 2 * (2 + 1));
    assert!(csv.lines().nth(3).unwrap().starts_with("0,1,0.4,all,3,"));
    assert!(r.markdown().contains("| 1 | 0.5 | 0.2 |"));
}
