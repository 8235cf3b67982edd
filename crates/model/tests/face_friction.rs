//! The face friction mobilised with the block's slip along the face
//! (docs/model.md §2.6, (M41)), against an independent brute force on flat
//! ground, and the sign rule it replaces (M9) as `choices.face_friction`.
//!
//! On flat fresh ground the first increment's candidate at angle β has the
//! block W = ½ γ0 d² (cot β + cot α) (the triangle between the face, the
//! line and the surface), the fresh soil's φc and ψc, and
//! P = W sin(β + φ) / cos(β + φ + ω) with ω = m φw + α − 90°. The model's
//! candidates sit on nodes, so its least force is above the continuous
//! minimum by at most what one angle step away from the minimiser costs
//! (first order where the minimum is a kink of the ramp, second order
//! inside it).

use crate::common;

use soilcut_model::{Case, FaceFrictionRule, Model, Simulation, StepRecord};

/// s_m of (M41), written out: the test is independent of the code's constant.
const S_M: f64 = 0.05;

/// The DEM validation's soil (cases/validation/vertical.toml) at d = 20,
/// with `per_depth` increments per depth, on a blade of rake `alpha`.
fn validation(alpha: f64, psi: f64, per_depth: f64, rule: FaceFrictionRule) -> Case {
    let mut case = common::refined("table1-hs", 0.01, per_depth);
    case.model = Model::Refined;
    case.blade.wall_friction = 20.0;
    case.blade.rake = alpha;
    case.soil.friction.initial = 33.7;
    case.soil.friction.peak = 39.5;
    case.soil.friction.residual = 27.8;
    case.soil.dilation.initial = psi;
    case.soil.dilation.peak = 13.0;
    case.soil.dilation.residual = 0.0;
    case.soil.repose = 45.2;
    case.soil.band_width = 10.0;
    case.choices.face_friction = rule;
    case
}

fn first_step(case: &Case) -> StepRecord {
    Simulation::new(case).unwrap().step().unwrap()
}

/// The brute force's view of one candidate on flat ground (angles in degrees).
struct Wedge {
    phi: f64,
    psi: f64,
    phi_w: f64,
    alpha: f64,
    rule: FaceFrictionRule,
}

impl Wedge {
    fn of(case: &Case) -> Self {
        Wedge {
            phi: case.soil.friction.initial.to_radians(),
            psi: case.soil.dilation.initial.to_radians(),
            phi_w: case.blade.wall_friction.to_radians(),
            alpha: case.blade.rake.to_radians(),
            rule: case.choices.face_friction,
        }
    }

    /// Slip up the face per unit of travel: the block's velocity
    /// (1, 0) + s (−cos α, sin α) along β + ψ.
    fn slip(&self, beta: f64) -> f64 {
        let t = (beta + self.psi).tan();
        t / (self.alpha.sin() + t * self.alpha.cos())
    }

    fn mobilisation(&self, beta: f64) -> f64 {
        let s = self.slip(beta);
        match self.rule {
            FaceFrictionRule::Sign if s > 0.0 => 1.0,
            FaceFrictionRule::Sign => -1.0,
            FaceFrictionRule::Mobilised => (s / S_M).clamp(-1.0, 1.0),
        }
    }

    /// P / (γ0 d²) at β, or infinity where not admissible.
    fn force(&self, beta: f64) -> f64 {
        let omega = self.mobilisation(beta) * self.phi_w + self.alpha - std::f64::consts::FRAC_PI_2;
        let denominator = (beta + self.phi + omega).cos();
        if beta <= 0.0 || denominator <= 0.0 || beta + self.phi + omega >= 1.5 {
            return f64::INFINITY;
        }
        let weight = 0.5 * (1.0 / beta.tan() + 1.0 / self.alpha.tan());
        weight * (beta + self.phi).sin() / denominator
    }

    /// The continuous minimum: a scan every 0.001°, refined by golden
    /// sections around the best (the force is unimodal near it: a kink or
    /// a smooth minimum). Returns (β*, P*).
    fn minimum(&self) -> (f64, f64) {
        let step = 0.001f64.to_radians();
        let mut best = (0.0, f64::INFINITY);
        for k in 1..90_000 {
            let beta = k as f64 * step;
            let f = self.force(beta);
            if f < best.1 {
                best = (beta, f);
            }
        }
        let (mut a, mut b) = (best.0 - step, best.0 + step);
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..100 {
            let (x1, x2) = (b - g * (b - a), a + g * (b - a));
            if self.force(x1) < self.force(x2) {
                b = x2;
            } else {
                a = x1;
            }
        }
        // A minimum on the edge of a jump (the sign rule) is the scan's
        // side of it.
        [best.0, a, 0.5 * (a + b), b]
            .into_iter()
            .map(|beta| (beta, self.force(beta)))
            .fold((0.0, f64::INFINITY), |x, y| if y.1 < x.1 { y } else { x })
    }
}

/// The largest angle step between the model's chosen candidate and its
/// neighbours, radians, from the landscape of the first increment.
fn angle_step(case: &Case, beta_deg: f64) -> f64 {
    let mut sim = Simulation::new(case).unwrap();
    let mut betas: Vec<f64> = sim
        .landscape()
        .unwrap()
        .iter()
        .map(|c| c.beta_deg)
        .collect();
    betas.sort_by(f64::total_cmp);
    let i = betas
        .iter()
        .position(|&b| (b - beta_deg).abs() < 1e-9)
        .expect("the chosen candidate is in the landscape");
    let below = beta_deg - betas[i.saturating_sub(1)];
    let above = betas[(i + 1).min(betas.len() - 1)] - beta_deg;
    below.max(above).to_radians()
}

/// The model's first force is the brute force's minimum, above it by no
/// more than one angle step away from the minimiser costs.
fn assert_brute_force(case: &Case) -> (StepRecord, Wedge, f64) {
    let got = first_step(case);
    let wedge = Wedge::of(case);
    let (beta, least) = wedge.minimum();
    let step = angle_step(case, got.beta_deg);
    // The force is unimodal about β*, and the grid has a candidate within
    // one step on either side.
    let tolerance = wedge.force(beta - step).min(wedge.force(beta + step)) - least;
    let (rake, rule) = (case.blade.rake, case.choices.face_friction);
    assert!(
        got.force_norm >= least * (1.0 - 1e-12) && got.force_norm <= least + tolerance,
        "α = {rake}, {rule:?}: {} vs brute force {least} at β = {}° (within {tolerance:e})",
        got.force_norm,
        beta.to_degrees()
    );
    assert!(
        (got.beta_deg - beta.to_degrees()).abs() <= 1.5 * step.to_degrees(),
        "α = {rake}, {rule:?}: β* {} vs brute force {}",
        got.beta_deg,
        beta.to_degrees()
    );
    (got, wedge, beta)
}

#[test]
fn vertical_first_increment_is_the_brute_force_minimum() {
    let (got, wedge, beta) = assert_brute_force(&validation(
        90.0,
        -19.7,
        2000.0,
        FaceFrictionRule::Mobilised,
    ));
    // The least force sits where the block slips down the face by s_m:
    // the ramp's lower edge, a kink (β* + ψ = −atan s_m, 16.84°), with the
    // full −φw of a genuinely sinking block.
    assert!(
        (wedge.slip(beta) + S_M).abs() < 1e-6,
        "s* = {}",
        wedge.slip(beta)
    );
    assert!(
        (beta.to_degrees() - 16.838).abs() < 0.01,
        "{}",
        beta.to_degrees()
    );
    let slip = (got.beta_deg + got.dilation_deg).to_radians().tan();
    assert!(slip < -0.99 * S_M, "the chosen block slips: s* = {slip}");
    assert!(
        got.force_norm > 1.47 && got.force_norm < 1.49,
        "{}",
        got.force_norm
    );
    // Sinking: the face friction acts up on the block, down on the blade.
    let omega = (-20f64).to_radians();
    assert!((got.force_v - got.force * omega.sin()).abs() < 1e-12 * got.force);
}

#[test]
fn vertical_first_increment_under_the_sign_rule_is_the_sinking_edge() {
    let case = validation(90.0, -19.7, 2000.0, FaceFrictionRule::Sign);
    let (got, _, beta) = assert_brute_force(&case);
    // The edge of the sinking branch, no slip along the face: β* = −ψ and
    // the sinking block's force there, 1.3429 (issue 20).
    assert!(
        (beta.to_degrees() - 19.7).abs() < 1e-6,
        "{}",
        beta.to_degrees()
    );
    let (b, phi, w) = (
        19.7f64.to_radians(),
        33.7f64.to_radians(),
        20f64.to_radians(),
    );
    let edge = 0.5 / b.tan() * (b + phi).sin() / (b + phi - w).cos();
    assert!(
        (got.force_norm - edge).abs() < 1e-4,
        "{} vs {edge}",
        got.force_norm
    );
    assert!((got.force_norm - 1.343).abs() < 1e-3);
    assert!(got.force_v < 0.0);
}

#[test]
fn raked_first_increment_is_the_brute_force_minimum() {
    for alpha in [45.0, 60.0] {
        let case = validation(alpha, -19.7, 1000.0, FaceFrictionRule::Mobilised);
        let (got, wedge, beta) = assert_brute_force(&case);
        // Here the least force is inside the ramp, a partly mobilised
        // block (m ≈ −0.006 at 45°, −0.50 at 60°), where a raked face's
        // Eq. (1) has its smooth minimum.
        let m = wedge.mobilisation(beta);
        assert!(m.abs() < 0.9, "α = {alpha}: m* = {m}");
        // The recorded components use the chosen mechanism's ω (M12, M41).
        let slip = wedge.slip(got.beta_deg.to_radians());
        let omega =
            (slip / S_M).clamp(-1.0, 1.0) * 20f64.to_radians() + (alpha - 90f64).to_radians();
        let rel = |a: f64, b: f64| (a - b).abs() / got.force;
        assert!(
            rel(got.force_h, got.force * omega.cos()) < 1e-9,
            "α = {alpha}"
        );
        assert!(
            rel(got.force_v, got.force * omega.sin()) < 1e-9,
            "α = {alpha}"
        );
        let sign = assert_brute_force(&validation(alpha, -19.7, 1000.0, FaceFrictionRule::Sign));
        assert!(sign.0.force != got.force);
    }
}

/// Around the no-slip point the forces of neighbouring candidates change by
/// small steps under (M41); the sign rule jumps from the sinking to the
/// rising force there.
#[test]
fn the_force_is_continuous_in_beta() {
    let largest_jump = |rule| {
        let mut sim = Simulation::new(&validation(90.0, -19.7, 200.0, rule)).unwrap();
        let mut candidates = sim.landscape().unwrap();
        candidates.sort_by(|a, b| a.beta_deg.total_cmp(&b.beta_deg));
        candidates
            .windows(2)
            .filter(|w| w[0].beta_deg > 10.0 && w[1].beta_deg < 30.0)
            .map(|w| (w[1].force / w[0].force - 1.0).abs())
            .fold(0.0, f64::max)
    };
    let mobilised = largest_jump(FaceFrictionRule::Mobilised);
    let sign = largest_jump(FaceFrictionRule::Sign);
    assert!(mobilised < 0.05, "{mobilised}");
    assert!(sign > 1.0, "the sign rule jumps: {sign}");
}

/// The first force as ψc moves across the range where sinking and partly
/// mobilised blocks compete with the rising one changes by small steps;
/// the step bound is 1.5 times the largest step of the brute force, which
/// has its steepest stretch just before the rising wedge takes over
/// (ψc ≈ −6.5°).
#[test]
fn the_first_force_is_continuous_in_the_dilation() {
    let psis: Vec<f64> = (0..=96).map(|k| -24.0 + 0.25 * k as f64).collect();
    let forces: Vec<f64> = psis
        .iter()
        .map(|&psi| {
            first_step(&validation(90.0, psi, 200.0, FaceFrictionRule::Mobilised)).force_norm
        })
        .collect();
    let brute: Vec<f64> = psis
        .iter()
        .map(|&psi| {
            Wedge::of(&validation(90.0, psi, 200.0, FaceFrictionRule::Mobilised))
                .minimum()
                .1
        })
        .collect();
    let steps = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[1] - w[0]).abs())
            .fold(0.0, f64::max)
    };
    let bound = 1.5 * steps(&brute);
    assert!(bound < 0.2, "{bound}");
    assert!(steps(&forces) <= bound, "{} > {bound}", steps(&forces));
    for (f, b) in forces.iter().zip(&brute) {
        assert!(*f >= b * (1.0 - 1e-12) && *f < b * 1.002, "{f} vs {b}");
    }
}

/// The paper's cases start on rising blocks that slip: their first
/// increments do not depend on the rule, to the bit.
#[test]
fn paper_first_increments_do_not_depend_on_the_rule() {
    let mut cases: Vec<Case> = ["fig5", "table1-hs", "table1-s", "fig8b"]
        .iter()
        .map(|name| common::refined(name, 0.01, 500.0))
        .collect();
    cases.push(common::original(0.01, 500.0));
    for mut case in cases {
        case.choices.face_friction = FaceFrictionRule::Mobilised;
        let mobilised = first_step(&case);
        case.choices.face_friction = FaceFrictionRule::Sign;
        let sign = first_step(&case);
        assert_eq!(mobilised, sign, "{}", case.name);
    }
}

/// The search's bounds hold for every ω a partly mobilised block may have
/// (M41): through a run in compacting soil, on vertical and raked blades
/// and with cohesion and a surcharge, every tenth increment's least force
/// is the least of its landscape (every candidate, nothing pruned).
#[test]
fn pruning_never_changes_the_least_force() {
    let mut cases = Vec::new();
    for alpha in [90.0, 60.0, 45.0, 30.0] {
        let mut case = validation(alpha, -19.7, 50.0, FaceFrictionRule::Mobilised);
        case.run.travel = 1.5 * case.blade.depth;
        cases.push(case.clone());
        case.soil.cohesion = 0.05 * case.blade.depth;
        case.soil.surcharge = 0.1 * case.blade.depth;
        cases.push(case);
    }
    let mut fig5 = common::refined("fig5", 1.5, 50.0);
    fig5.blade.depth_path = vec![[0.0, 20.0], [10.0, 16.0], [20.0, 16.0], [25.0, 20.0]];
    cases.push(fig5);
    for case in cases {
        let mut sim = Simulation::new(&case).unwrap();
        let mut checked = 0;
        while !sim.is_done() {
            let least = sim.steps_done().is_multiple_of(10).then(|| {
                sim.landscape()
                    .unwrap()
                    .iter()
                    .map(|c| c.force)
                    .fold(f64::INFINITY, f64::min)
            });
            let record = sim.step().unwrap();
            if let Some(least) = least {
                assert_eq!(
                    record.force, least,
                    "α = {}, step {}",
                    case.blade.rake, record.step
                );
                checked += 1;
            }
        }
        assert!(checked >= 7);
    }
}
