//! Every shipped case, run in full as shipped, conserves mass (∫γ dA of the
//! ground that existed at the start, with what has spilled around the edges
//! of a blade of finite width) to 1e-9 relative, and holds no number that
//! is not finite in any record or point of its final surface (issue 50).

use soilcut_io::read_case;
use soilcut_model::Simulation;
use std::path::Path;

#[test]
fn every_shipped_case_conserves_mass_and_stays_finite() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
    let mut checked = 0;
    for dir in std::fs::read_dir(&root).unwrap() {
        let dir = dir.unwrap().path();
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        files.sort();
        for file in files {
            let case = read_case(&file, &[]).unwrap().case;
            let mut sim = Simulation::new(&case).unwrap();
            let history = sim.run_to_end(|_| {}).unwrap();
            let name = file.display();
            for r in &history {
                assert_eq!(r.not_finite(), None, "{name}: {r:?}");
            }
            for p in sim.profile() {
                let numbers = [p.x, p.y, p.accumulated_shear, p.unit_weight, p.ridge_height];
                assert!(numbers.iter().all(|v| v.is_finite()), "{name}: {p:?}");
            }
            let met = sim.mass() + sim.mass_spilled();
            let drift = (met - sim.initial_mass()) / sim.initial_mass();
            assert!(
                drift.abs() < 1e-9,
                "{}: mass drift {drift:e}",
                file.display()
            );
            checked += 1;
        }
    }
    assert!(checked >= 5, "only {checked} shipped cases found");
}
