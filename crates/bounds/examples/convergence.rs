//! The bracket against the mesh parameter N on the checks' problems: flat
//! ground, tip at depth d = 1, γ = 1, the face at rake RAKE (90: vertical).
//!
//! cargo run --release -p soilcut-bounds --example convergence -- PHI PHI_W C Q DEPTH RAKE [N...]
//!
//! Prints N, triangles, lower, upper, their mean, the half-width relative to
//! the mean, and the wall time of each bound.

use soilcut_bounds::{bracket, Problem, Soil};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("numbers"))
        .collect();
    let (phi, phi_w, c, q) = (args[0], args[1], args[2], args[3]);
    let soil = Soil {
        friction_deg: phi,
        cohesion: c,
        unit_weight: 1.0,
    };
    let mut p = Problem::flat(1.0, soil, phi_w, q, args[4]);
    p.face.rake_deg = args[5];
    println!("N\ttriangles\tlower\tupper\tmean\thalf_width_pct\tlower_s\tupper_s");
    for n in args[6..].iter().map(|&n| n as usize) {
        let b = bracket(&p, n).expect("solved");
        let (lo, up) = (b.lower_force(), b.upper_force());
        let mean = 0.5 * (lo + up);
        println!(
            "{n}\t{}\t{lo:.4}\t{up:.4}\t{mean:.4}\t{:.2}\t{:.2}\t{:.2}",
            b.mesh.triangles.len(),
            50.0 * (up - lo) / mean,
            b.lower_seconds,
            b.upper_seconds
        );
    }
}
