//! Every shipped case, run in full as shipped, conserves mass (∫γ dA of the
//! ground that existed at the start, with the soil spilled beside a blade
//! of finite width) to 1e-9 relative.

use soilcut_io::read_case;
use soilcut_model::Simulation;
use std::path::Path;

#[test]
fn every_shipped_case_conserves_mass() {
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
            sim.run_to_end(|_| {}).unwrap();
            // A blade of finite width spills soil into side heaps (docs/model.md §16.5).
            let held = sim.mass() + sim.mass_spilled();
            let drift = (held - sim.initial_mass()) / sim.initial_mass();
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
