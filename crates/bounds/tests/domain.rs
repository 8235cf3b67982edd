//! The default domain is large enough: enlarging it changes neither bound
//! by more than 0.5 % on the checks' problems (a rough face, whose
//! mechanism reaches furthest; the smooth one's is Rankine's wedge).

use soilcut_bounds::{bracket, Domain, Problem, Soil};

fn rough(domain: Domain) -> Problem {
    let soil = Soil {
        friction_deg: 35.0,
        cohesion: 0.0,
        unit_weight: 1.0,
    };
    Problem {
        domain,
        ..Problem::flat(1.0, soil, 25.0, 0.0, 0.0)
    }
}

/// Both bounds on the two domains agree within 0.5 % (N = 3).
fn unchanged(a: Domain, b: Domain) {
    let a = bracket(&rough(a), 3).unwrap();
    let b = bracket(&rough(b), 3).unwrap();
    for (x, y) in [
        (a.lower_force(), b.lower_force()),
        (a.upper_force(), b.upper_force()),
    ] {
        assert!((x - y).abs() < 0.005 * x, "{x} vs {y}");
    }
}

#[test]
fn enlarging_the_reach_changes_nothing() {
    let base = Domain {
        depth: 0.0,
        ..Domain::default()
    };
    unchanged(
        base,
        Domain {
            reach: 2.0 * base.reach,
            ..base
        },
    );
}

#[test]
fn enlarging_the_soil_below_the_tip_changes_nothing() {
    let base = Domain::default();
    unchanged(
        base,
        Domain {
            depth: 2.0 * base.depth,
            back: 2.0 * base.back,
            ..base
        },
    );
}
