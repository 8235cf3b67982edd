//! soilcut held to the DEM. validation/bands.json (written by
//! validation/compare.py from the committed DEM results) holds, for every
//! validation cut, the DEM's seed-mean force over the first depth of travel
//! and the band of soilcut / DEM ratios docs/validation.md reports: the
//! ensemble's ratio ± twice the combined relative spread of soilcut's
//! ensemble and the DEM's seeds. This reruns each case (the unperturbed
//! member), shortened to one depth, and fails when its mean force over
//! [0, 1) d leaves the band, so that a model change that moves soilcut away
//! from the DEM is seen. It also checks that the page quotes the bands.

use soilcut_io::read_case;
use soilcut_model::Simulation;
use std::path::Path;

const CUTS: [&str; 3] = ["vertical", "raked30", "deep"];

#[test]
fn soilcut_stays_in_the_band_the_validation_page_claims_against_the_dem() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let bands: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("validation/bands.json")).unwrap())
            .unwrap();
    let doc = std::fs::read_to_string(root.join("docs/validation.md")).unwrap();
    for name in CUTS {
        let band = &bands[format!("{name}_window_0")];
        let (dem, low, high) = (
            band["dem"].as_f64().unwrap(),
            band["low"].as_f64().unwrap(),
            band["high"].as_f64().unwrap(),
        );
        let file = root.join(format!("cases/validation/{name}.toml"));
        let mut case = read_case(&file, &[]).unwrap().case.into_case();
        case.run.travel = case.blade.depth;
        let history = Simulation::new(&case).unwrap().run_to_end(|_| {}).unwrap();
        let inside: Vec<f64> = history
            .iter()
            .filter(|r| r.u < case.blade.depth)
            .map(|r| r.force_norm)
            .collect();
        let ratio = inside.iter().sum::<f64>() / inside.len() as f64 / dem;
        assert!(
            (low..=high).contains(&ratio),
            "{name}: soilcut / DEM over [0, 1) d is {ratio:.3}, outside the claimed {low:.3}-{high:.3}"
        );
        let quoted = format!("| {name} | {low:.2}-{high:.2} |");
        assert!(
            doc.contains(&quoted),
            "docs/validation.md does not quote the band {quoted:?}"
        );
    }
}
