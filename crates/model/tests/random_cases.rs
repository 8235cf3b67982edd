//! Random valid cases (proptest, from fixed seeds, so the test is the same
//! every time) must run to the end, keep mass, keep every node's state
//! physical, and prune no candidate that would have been the least. A
//! failure is shrunk to its smallest case: every random choice is a
//! fraction in [0, 1) that shrinks towards 0, the low end of each range
//! and no optional load. Two bugs were found this way: a band unit weight
//! driven negative, and a pruning bound that assumed the wrong face
//! friction for raked blades.

use crate::common;

use proptest::collection::vec;
use proptest::test_runner::{Config, RngAlgorithm, TestError, TestRng, TestRunner};
use soilcut_model::accuracy::{agreement, Spread};
use soilcut_model::landscape::TIE_TOLERANCE;
use soilcut_model::{
    AngleLaw, Case, Class, FaceFrictionRule, Ground, Model, Run, RunKeys, Simulation, TimeScheme,
};

/// Fractions in [0, 1) drawn in turn: the random choices of one case.
struct Draws<'a>(std::slice::Iter<'a, f64>);

impl Draws<'_> {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.0.next().copied().expect("enough draws")
    }

    /// True with probability p; false for a fraction shrunk to 0.
    fn chance(&mut self, p: f64) -> bool {
        self.uniform(0.0, 1.0) >= 1.0 - p
    }
}

/// Fractions enough for any case below.
const DRAWS: usize = 40;

/// Runs `check` on `cases` random fraction vectors from the seed `seed`,
/// shrinking a failure towards its smallest case for at most `shrink`
/// further runs.
fn for_random(seed: u8, (cases, shrink): (u32, u32), check: impl Fn(&[f64])) {
    let config = Config {
        cases,
        max_shrink_iters: shrink,
        failure_persistence: None,
        ..Config::default()
    };
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let result = runner.run(&vec(0.0..1.0f64, DRAWS), |draws| {
        check(&draws);
        Ok(())
    });
    if let Err(e) = result {
        match e {
            TestError::Fail(why, draws) => panic!("{why}; smallest case from draws {draws:?}"),
            TestError::Abort(why) => panic!("{why}"),
        }
    }
}

fn random_case(rng: &mut Draws) -> Case {
    let refined = rng.chance(0.6);
    let mut case = if refined {
        common::refined("table1-hs", 1.0, 50.0)
    } else {
        common::original(1.0, 50.0)
    };
    case.run.travel = rng.uniform(1.0, 3.0) * case.blade.depth;
    let initial = rng.uniform(15.0, 35.0);
    let peak = rng.uniform(initial.max(25.0), 42.0);
    let residual = rng.uniform(25.0, peak);
    case.soil.friction = AngleLaw {
        initial: if refined { initial } else { peak },
        peak,
        residual,
    };
    let phi_min = case.soil.friction.min();
    case.blade.rake = if rng.chance(0.5) {
        rng.uniform(35.0, 89.0)
    } else {
        90.0
    };
    case.blade.wall_friction = rng.uniform(0.0, (phi_min - 1.0).min(case.blade.rake - 1.0));
    case.soil.repose = rng.uniform(20.0, (case.blade.rake - 1.0).min(residual));
    if refined {
        case.model = Model::Refined;
        case.soil.dilation = AngleLaw {
            initial: rng.uniform(-10.0, 0.0),
            peak: rng.uniform(0.0, 10.0),
            residual: 0.0,
        };
        case.soil.peak_shear = rng.uniform(0.0, 3.0);
        case.soil.residual_shear = rng.uniform(3.0, 6.0);
        case.soil.band_width = rng.uniform(2.0, 12.0);
    }
    if rng.chance(0.3) {
        case.soil.cohesion = rng.uniform(0.0, 3.0);
    }
    if rng.chance(0.3) {
        case.soil.surcharge = rng.uniform(0.0, 3.0);
    }
    if rng.chance(0.2) && case.blade.rake + phi_min >= 90.0 {
        case.blade.adhesion = rng.uniform(0.0, 2.0);
    }
    if rng.chance(0.25) && case.blade.rake == 90.0 {
        case.blade.depth_path = vec![
            [0.0, rng.uniform(14.0, 18.0)],
            [rng.uniform(5.0, 30.0), 20.0],
        ];
    }
    case
}

/// The strategy's cases, for `for_random`.
fn case_of(draws: &[f64]) -> Case {
    random_case(&mut Draws(draws.iter()))
}

#[test]
fn random_valid_cases_run_and_conserve() {
    for_random(1, (80, 64), |draws| runs_and_conserves(&case_of(draws)));
}

/// Blades that go in and out along random depth paths (each segment may
/// deepen or rise, steeply or not).
#[test]
fn random_depth_paths_run_and_conserve() {
    for_random(2, (40, 64), |draws| {
        let mut rng = Draws(draws.iter());
        let mut case = random_case(&mut rng);
        case.blade.rake = 90.0;
        let points = 2 + rng.uniform(0.0, 3.0) as usize;
        let shallowest = case.soil.band_width.max(case.run.increment) + 1.0;
        let mut u = 0.0;
        case.blade.depth_path = (0..points)
            .map(|_| {
                let point = [u, rng.uniform(shallowest, 20.0)];
                u += rng.uniform(1.0, 30.0);
                point
            })
            .collect();
        runs_and_conserves(&case);
    });
}

/// Runs `case` to the end: positive finite forces, mass kept, every node's
/// state physical, and the pruned search's force that of the unpruned
/// landscape (every seventh increment).
fn runs_and_conserves(case: &Case) {
    // The least, or a near-tie nearer the blade (`search`).
    runs_and_keeps(case, |force, least| {
        force >= least && force <= least * (1.0 + TIE_TOLERANCE)
    });
}

/// Runs `case` to the end: positive finite forces, mass kept, every node's
/// or piece's state physical, and `chosen(force, least)` for the force of
/// every seventh increment against the least of its landscape.
fn runs_and_keeps(case: &Case, chosen: impl Fn(f64, f64) -> bool) {
    let fail = |e: &dyn std::fmt::Display| -> ! { panic!("{e}: {case:?}") };
    let mut sim = Simulation::new(case).unwrap_or_else(|e| fail(&e));
    while !sim.is_done() {
        let least = sim.steps_done().is_multiple_of(7).then(|| {
            let candidates = sim.landscape().unwrap_or_else(|e| fail(&e));
            candidates
                .iter()
                .map(|c| c.force)
                .fold(f64::INFINITY, f64::min)
        });
        let record = sim.step().unwrap_or_else(|e| fail(&e));
        let force = record.force;
        assert!(force.is_finite() && force > 0.0, "{record:?}: {case:?}");
        if let Some(least) = least {
            let step = record.step;
            assert!(
                chosen(force, least),
                "step {step}: {force} vs {least}: {case:?}"
            );
        }
    }
    let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
    assert!(drift.abs() < 1e-9, "mass drift {drift:e}: {case:?}");
    for p in sim.profile() {
        assert!(
            p.unit_weight > 0.3 && p.unit_weight < 3.0,
            "γ {p:?}: {case:?}"
        );
        assert!(p.accumulated_shear >= 0.0, "ut {p:?}");
    }
}

/// How many random cases `random_cases_with_scaled_lengths_stay_finite`
/// runs: 200 in the suite, `SOILCUT_SCALED_CASES` by hand
/// (`SOILCUT_SCALED_CASES=1000 cargo test -p soilcut-model --release --test
/// integration random_cases::random_cases_with_scaled`).
fn scaled_cases() -> u32 {
    std::env::var("SOILCUT_SCALED_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(200)
}

/// `case` with every length × `s`: the depth and its path, the band width
/// and the shears up and ur; the stresses (cohesion, adhesion, surcharge)
/// × s too, so that the case is the same in units of γ0 d.
fn scaled(mut case: Case, s: f64) -> Case {
    case.blade.depth *= s;
    for point in &mut case.blade.depth_path {
        *point = [point[0] * s, point[1] * s];
    }
    let soil = &mut case.soil;
    soil.band_width *= s;
    soil.peak_shear *= s;
    soil.residual_shear *= s;
    soil.cohesion *= s;
    soil.surcharge *= s;
    case.blade.adhesion *= s;
    case
}

/// Random valid cases with their lengths scaled by 10^(−2 … 2), over a
/// whole or half number of depths (½ to 1½ d, short so that 200 cases
/// take seconds), at a coarse increment (d/50), on the vertex ground
/// (vertices d/25) or the node grid: no record of a finished run holds a
/// number that is not finite, nor its final surface. Issue 50 found 6 of
/// 85 such cases with the mass NaN behind a finished run: where the
/// ground, travel + 8 d, is a whole number of vertex spacings to
/// round-off, it ended in a piece of length 0.
#[test]
fn random_cases_with_scaled_lengths_stay_finite() {
    for_random(9, (scaled_cases(), 0), |draws| {
        let mut rng = Draws(draws.iter());
        let case = random_case(&mut rng);
        let s = 10f64.powf(rng.uniform(-2.0, 2.0));
        let travel = (1.0 + rng.uniform(0.0, 3.0).floor()) / 2.0;
        let on_vertices = rng.chance(0.7);
        let mut case = scaled(case, s);
        let d = case.blade.depth;
        case.run.travel = travel * d;
        case.run.increment = d / 50.0;
        if on_vertices {
            case = common::on_vertices(case, 25.0);
        }
        let mut sim = Simulation::new(&case).unwrap_or_else(|e| panic!("{e}: {case:?}"));
        let history = sim.run_to_end(|_| {});
        let history = history.unwrap_or_else(|e| panic!("{e}: {case:?}"));
        for r in &history {
            assert_eq!(r.not_finite(), None, "{r:?}: {case:?}");
        }
        for p in sim.profile() {
            let numbers = [p.x, p.y, p.accumulated_shear, p.unit_weight];
            assert!(numbers.iter().all(|v| v.is_finite()), "{p:?}: {case:?}");
        }
    });
}

/// The mean P/(γ0 d²) of each unit window of `case` for every member of
/// its ensemble (M39): the band width × (1 + 0.001 k) in the refined
/// model, the wall friction + 0.01° × k in the original, k = −3 … 3.
fn ensemble(case: &Case, windows: usize) -> (Vec<Spread>, Spread) {
    let members: Vec<Vec<f64>> = (-3..=3)
        .map(|k| {
            let mut c = case.clone();
            match c.model {
                Model::Refined => c.soil.band_width *= 1.0 + 0.001 * f64::from(k),
                Model::Original => c.blade.wall_friction += 0.01 * f64::from(k),
            }
            let (history, _) = common::run(&c);
            let mut means = common::window_means(&history, c.blade.depth, windows);
            let all: f64 = history.iter().map(|r| r.force_norm).sum();
            means.push(all / history.len() as f64);
            means
        })
        .collect();
    let spread = |w: usize| Spread::of(&members.iter().map(|m| m[w]).collect::<Vec<_>>());
    ((0..windows).map(spread).collect(), spread(windows))
}

/// `case` on the node grid at `increment`.
fn on_nodes_at(case: &Case, increment: f64) -> Case {
    let mut c = case.clone();
    c.run.increment = increment;
    c.run.ground = Ground::Nodes;
    c
}

/// At the default run of the class of case (`Run::resolve` of a file that
/// gives only the travel) the ensembles of random cases it was not chosen
/// on are accurate by the ensemble rule (M40) against the node grid's
/// ensemble at d/2000, over the first 1.5 depths of travel.
#[test]
fn the_default_grid_is_accurate_on_random_cases() {
    // Three cases as drawn, one whose soil does not soften; an ensemble
    // takes seconds, so a failure is reported as found, not shrunk.
    // Seeds 8, 12 and 14 made vertical at constant depth draw the refined
    // model in softening soil: the vertex ground's class.
    let seeds = [(4, true), (5, true), (6, true), (7, false)];
    let vertical = [(8, true), (12, true), (14, true)];
    for (seed, softens) in seeds.into_iter().chain(vertical) {
        for_random(seed, (1, 0), |draws| {
            let mut case = case_of(draws);
            if !softens {
                case.soil.friction.residual = case.soil.friction.peak;
            }
            if seed >= 8 {
                case.blade.rake = 90.0;
                case.blade.depth_path.clear();
            }
            let d = case.blade.depth;
            case.run.travel = 1.5 * d;
            let keys = RunKeys {
                travel: case.run.travel,
                ..RunKeys::default()
            };
            let class = Class {
                model: case.model,
                soil: &case.soil,
                blade: &case.blade,
                face_friction: case.choices.face_friction,
                in_bin: case.bin.length.is_some(),
            };
            let mut default = case.clone();
            default.run = Run::resolve(&keys, class).unwrap();
            assert_eq!(default.run.ground.name(), "vertices");
            let (windows, whole) = ensemble(&default, 1);
            let (ref_windows, ref_whole) = ensemble(&on_nodes_at(&case, d / 2000.0), 1);
            let a = agreement(&windows, &whole, &ref_windows, &ref_whole);
            assert!(a.accurate(), "{a:?}: {case:?}");
        });
    }
}

/// The same random cases on the vertex ground (docs/model.md §1.2), where it
/// runs: vertical blades at constant depth, vertices d/100 to d/25 apart.
/// Positive finite forces, mass kept, every piece's state physical, and
/// the chosen band never more than the snap's 0.1 % above the least of the
/// first stage's samples (the second stage may go below them); and the
/// same under the midpoint force, its force within half of that least.
#[test]
fn random_cases_on_the_vertex_ground_run_and_conserve() {
    for_random(5, (30, 32), |draws| {
        let mut rng = Draws(draws.iter());
        let mut case = random_case(&mut rng);
        case.blade.rake = 90.0;
        case.blade.depth_path.clear();
        case.blade.adhesion = 0.0;
        let case = common::on_vertices(case, rng.uniform(25.0, 100.0));
        runs_and_keeps(&case, |force, least| force <= least * (1.0 + 1e-3 + 1e-12));
        // The midpoint force moves the soil by the midpoint ψ: mass and
        // state hold as well, and the force stays near the band's at the
        // start (the landscape's least), which it corrects by half an
        // increment of the law (under the sign rule it is refused).
        if case.choices.face_friction == FaceFrictionRule::Mobilised {
            let mut midpoint = case.clone();
            midpoint
                .run
                .vertices_mut()
                .expect("on the vertex ground")
                .time_scheme = TimeScheme::MidpointForce;
            runs_and_keeps(&midpoint, |force, least| {
                (force - least).abs() <= 0.5 * least
            });
        }
    });
}

/// Random straight tools (M55): a straight profile at a random face angle
/// α0, turned by a constant θ about a random pivot, translating along a
/// random motion (a path of poses for a vertical face) is the blade of
/// rake α0 − θ along its edge's depth path; it runs to the end keeping
/// mass to 1e-11, and its `tool_x`, `tool_y`, `tool_rotation` are the pose
/// its motion commands at every increment.
#[test]
fn random_straight_tools_are_their_blades_and_conserve() {
    use soilcut_model::tool::{Motion, Pose, Shape, Tool};
    for_random(3, (20, 16), |draws| {
        let mut rng = Draws(draws.iter());
        let mut case = random_case(&mut rng);
        let (alpha, d) = (case.blade.rake, case.blade.depth);
        let face = if alpha == 90.0 && rng.chance(0.5) {
            90.0
        } else {
            rng.uniform(alpha, 120.0)
        };
        let theta = face - alpha;
        let pivot = [rng.uniform(-2.0, 2.0) * d, rng.uniform(0.0, 4.0) * d];
        let shape = Shape::Straight {
            rake: face,
            height: 3.0 * d,
        };
        let at = |edge: [f64; 2]| {
            // The pivot's place that puts the edge at `edge`.
            let turned = Pose {
                x: 0.0,
                y: 0.0,
                rotation: theta,
            }
            .place(pivot, [0.0, 0.0]);
            [edge[0] - turned[0], edge[1] - turned[1]]
        };
        let travel = case.run.travel;
        let depths: Vec<[f64; 2]> = if alpha == 90.0 && !case.blade.depth_path.is_empty() {
            let mut path = case.blade.depth_path.clone();
            path.insert(0, [0.0, path[0][1]]);
            path.dedup_by(|a, b| a[0] == b[0]);
            path.retain(|p| p[0] < travel);
            path.push([travel, case.tip_depth(travel)]);
            path
        } else {
            vec![[0.0, d], [travel, d]]
        };
        let rows: Vec<[f64; 4]> = depths
            .iter()
            .map(|&[s, depth]| {
                let [x, y] = at([s, -depth]);
                [s, x, y, theta]
            })
            .collect();
        let tool = Tool {
            shape,
            pivot,
            motion: Motion::new(&rows, "tool.motion").unwrap(),
        };
        let cut = tool
            .straight_cut(d)
            .unwrap_or_else(|e| panic!("{e}: {rows:?}"));
        assert!(
            (cut.rake - alpha).abs() < 1e-9 * alpha,
            "{} vs {alpha}",
            cut.rake
        );
        case.blade.rake = cut.rake;
        case.blade.depth_path = cut.depth_path;
        case.blade.pivot = cut.pivot;
        case.blade.rotation = cut.rotation;
        case.run.travel = cut.travel;
        let mut sim = Simulation::new(&case).unwrap_or_else(|e| panic!("{e}: {case:?}"));
        while !sim.is_done() {
            let r = sim.step().unwrap_or_else(|e| panic!("{e}: {case:?}"));
            assert!(r.not_finite().is_none(), "{r:?}");
            let pose = tool.motion.at(r.u);
            let scale = d.max(pose.x.abs());
            assert!((r.tool_x - pose.x).abs() < 1e-9 * scale, "{r:?} {pose:?}");
            assert!((r.tool_y - pose.y).abs() < 1e-9 * scale, "{r:?} {pose:?}");
            assert_eq!(r.tool_rotation, theta);
        }
        let drift = (sim.mass() - sim.initial_mass()) / sim.initial_mass();
        assert!(drift.abs() < 1e-11, "mass drift {drift:e}: {case:?}");
    });
}
