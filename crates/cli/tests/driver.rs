//! One rule for "advance to u" (issue 49): the driver's
//! `Case::increments_to`, which every front end reaches. At a blade
//! displacement that is a whole number of increments in exact arithmetic
//! but not in floating point (k v0 / d times d over v0 lands a few ulps
//! either side of k), the Rust library's `advance_to`, the driver's
//! `Until::Instant`, io's `landscape_at` (Python's `landscape`) and
//! `soilcut landscape --at` all stop at increment k.

use crate::cli::{stdout, Sandbox, REFINED};
use soilcut_io::{landscape_at, parse_case};
use soilcut_model::{Simulation, Until};

/// The two ways a user computes "k increments in depths": k v0 / d and
/// k (v0 / d); some of them are not k v0 / d to the last bit.
fn instants(k: usize, v0: f64, d: f64) -> [f64; 2] {
    [k as f64 * v0 / d, k as f64 * (v0 / d)]
}

#[test]
fn every_front_end_stops_at_the_same_increment_at_a_round_off_boundary() {
    let case = parse_case(REFINED, &[]).unwrap().case;
    let (v0, d) = (case.run.increment, case.blade.depth);
    let mut off_integer = 0;
    for k in 1..case.steps() {
        for at in instants(k, v0, d) {
            off_integer += usize::from(at * d / v0 != k as f64);
            let fresh = || Simulation::new(&case).unwrap();
            assert_eq!(fresh().increments_until(Until::Instant(at)), k, "at {at}");
            let mut sim = fresh();
            sim.advance_to(at * d, None).unwrap();
            assert_eq!(sim.steps_done(), k, "advance_to({})", at * d);
            let mut sim = fresh();
            landscape_at(&mut sim, at).unwrap();
            assert_eq!(sim.steps_done(), k, "landscape_at({at})");
        }
    }
    assert!(off_integer > 10, "the boundary is exercised: {off_integer}");
}

#[test]
fn the_command_line_landscape_stops_where_the_library_does() {
    let sandbox = Sandbox::new(REFINED);
    let case = parse_case(REFINED, &[]).unwrap().case;
    let (v0, d) = (case.run.increment, case.blade.depth);
    // k = 3: 3 × 0.2 / 20 is 0.030000000000000002, and 0.03 × 20 / 0.2
    // is 2.9999999999999996.
    for (i, at) in instants(3, v0, d).into_iter().enumerate() {
        let out = format!("ls{i}");
        let at = format!("{at:?}");
        let o = sandbox.soilcut(&["landscape", "case.toml", "--at", &at, "--out", &out]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(stdout(&o).contains("u/d = 0.030"), "{at}: {}", stdout(&o));
    }
}
