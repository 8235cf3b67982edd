//! Shared case builders for the model's integration tests.
#![allow(dead_code)]

use soilcut_model::{AngleLaw, Blade, Case, Ground, Model, Run, Soil, TimeScheme, VertexGround};

/// The paper's original-model case (docs/model.md §13), shortened to
/// `travel_depths` depths at increment d / `per_depth`.
pub fn original(travel_depths: f64, per_depth: f64) -> Case {
    let d = 20.0;
    Case {
        name: "original".into(),
        title: "Original model".into(),
        model: Model::Original,
        blade: Blade {
            depth: d,
            wall_friction: 10.0,
            rake: 90.0,
            adhesion: 0.0,
            depth_path: Vec::new(),
            width: None,
            pivot: [0.0, 0.0],
            rotation: 0.0,
        },
        soil: Soil {
            unit_weight: 1.0,
            friction: AngleLaw {
                initial: 35.0,
                peak: 35.0,
                residual: 30.0,
            },
            dilation: AngleLaw::constant(0.0),
            peak_shear: 0.0,
            residual_shear: 4.0,
            repose: 30.0,
            band_width: 0.0,
            cohesion: 0.0,
            surcharge: 0.0,
        },
        run: Run {
            travel: travel_depths * d,
            increment: d / per_depth,
            ground: Ground::Nodes,
        },
        bin: Default::default(),
        choices: Default::default(),
    }
}

/// `case` on the vertex ground (docs/model.md §1.2), vertices d/`per_depth`
/// apart, with the sampled search's default K (it has no exhaustive one).
/// The time scheme is the explicit one.
pub fn on_vertices(mut case: Case, per_depth: f64) -> Case {
    case.run.ground = Ground::Vertices(VertexGround {
        spacing: case.blade.depth / per_depth,
        samples_per_band: soilcut_model::DEFAULT_SAMPLES_PER_BAND,
        time_scheme: TimeScheme::Explicit,
        merge_tolerance: 0.0,
    });
    case
}

/// `case` on the vertex ground at its defaults: d/350
/// (`VERTEX_INCREMENTS_PER_DEPTH`), vertices d/50, the midpoint force.
pub fn at_vertex_defaults(mut case: Case) -> Case {
    case.run.increment = case.blade.depth / soilcut_model::VERTEX_INCREMENTS_PER_DEPTH;
    let mut case = on_vertices(case, soilcut_model::VERTICES_PER_DEPTH);
    if let Some(v) = case.run.vertices_mut() {
        v.time_scheme = TimeScheme::MidpointForce;
    }
    case
}

/// Coulomb's passive coefficient with wall friction (angles in degrees).
pub fn coulomb_kp(phi: f64, phi_w: f64) -> f64 {
    let (p, w) = (phi.to_radians(), phi_w.to_radians());
    let root = ((p + w).sin() * p.sin() / w.cos()).sqrt();
    p.cos().powi(2) / (w.cos() * (1.0 - root).powi(2))
}

/// The paper's refined cases (docs/model.md §13): "fig5", "table1-hs",
/// "table1-s" and, scaled to d = 20, "fig8b" (hardening only), shortened
/// to `travel_depths` at increment d / `per_depth`.
pub fn refined(which: &str, travel_depths: f64, per_depth: f64) -> Case {
    let law = |initial, peak, residual| AngleLaw {
        initial,
        peak,
        residual,
    };
    let mut case = original(travel_depths, per_depth);
    case.model = Model::Refined;
    let (friction, dilation, up, n) = match which {
        "fig5" => (law(20.0, 40.0, 30.0), law(-5.0, 10.0, 0.0), 2.0, 15.0),
        "table1-hs" => (law(20.0, 35.0, 30.0), law(-5.0, 5.0, 0.0), 2.0, 7.0),
        "table1-s" => (law(35.0, 35.0, 30.0), law(0.0, 5.0, 0.0), 0.0, 7.0),
        // d = 25.4, up = 0.6, dB = 20 d50 = 3.0 in the paper: here × 20/25.4.
        "fig8b" => (
            law(20.0, 33.0, 33.0),
            law(-5.0, 0.0, 0.0),
            0.6 * 20.0 / 25.4,
            5.0 * 20.0 / 25.4,
        ),
        other => panic!("no case {other}"),
    };
    case.name = which.into();
    case.soil.friction = friction;
    case.soil.dilation = dilation;
    case.soil.peak_shear = up;
    case.soil.band_width = n * 0.6;
    case
}

/// Runs a case to the end.
pub fn run(case: &Case) -> (Vec<soilcut_model::StepRecord>, soilcut_model::Simulation) {
    let mut sim = soilcut_model::Simulation::new(case).expect("valid case");
    let history = sim.run_to_end(|_| {}).expect("admissible mechanism");
    (history, sim)
}

/// Mean P/(γ0 d²) over each unit of u/d, for the first `windows` units.
pub fn window_means(history: &[soilcut_model::StepRecord], d: f64, windows: usize) -> Vec<f64> {
    (0..windows)
        .map(|k| {
            let window: Vec<f64> = history
                .iter()
                .filter(|r| (r.u / d).floor() as usize == k)
                .map(|r| r.force_norm)
                .collect();
            window.iter().sum::<f64>() / window.len() as f64
        })
        .collect()
}

/// Over the increments checked (every `every`-th): how many, how many
/// above the landscape's least force by more than the tie tolerance, and
/// the largest relative excess. Fails if a force is below the least.
pub fn least_force_excess(case: &Case, every: usize) -> (usize, usize, f64) {
    let mut sim = soilcut_model::Simulation::new(case).expect("a valid case");
    let (mut checked, mut above, mut largest) = (0, 0, 0.0f64);
    while !sim.is_done() {
        let least = sim.steps_done().is_multiple_of(every).then(|| {
            let candidates = sim.landscape().expect("a mechanism");
            candidates
                .iter()
                .map(|c| c.force)
                .fold(f64::INFINITY, f64::min)
        });
        let record = sim.step().expect("a mechanism");
        let Some(least) = least else { continue };
        let e = record.force / least - 1.0;
        assert!(
            e >= -soilcut_model::landscape::TIE_TOLERANCE,
            "step {}: {e:e} below the least",
            record.step
        );
        checked += 1;
        above += usize::from(e > soilcut_model::landscape::TIE_TOLERANCE);
        largest = largest.max(e);
    }
    (checked, above, largest)
}
