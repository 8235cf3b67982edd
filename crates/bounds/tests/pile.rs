//! A pile against the face steeper than its soil's friction angle: the
//! ground cannot stand, which the bracket reports without a solve, and the
//! strength field `Field::Slope` that makes it stand.

use soilcut_bounds::{bracket, Field, Ground, Problem, Soil, SolveError};

/// Flat ground at y = 0 over a tip at depth 1, vertical smooth face, a pile
/// against the face 0.3 high falling at 30° to the flat ground, every
/// column of soil (φ, c), γ = 1; the same soil below the tip.
fn piled(phi: f64, c: f64) -> Problem {
    let soil = Soil {
        friction_deg: phi,
        cohesion: c,
        unit_weight: 1.0,
    };
    let mut p = Problem::flat(1.0, soil, 0.0, 0.0, 0.0);
    let run = 0.3 / 30f64.to_radians().tan();
    let x: Vec<f64> = (0..=12).map(|i| run * i as f64 / 8.0).collect();
    let y = x
        .iter()
        .map(|&x| (0.3 - x * 30f64.to_radians().tan()).max(0.0))
        .collect();
    p.ground = Ground {
        soil: vec![soil; x.len()],
        x,
        y,
    };
    p
}

#[test]
fn a_loose_pile_steeper_than_its_soil_cannot_stand_and_is_not_solved() {
    let p = piled(20.0, 0.0);
    let steep = p.steep().expect("30° on φ = 20° without cohesion");
    assert!((steep.slope_deg - 30.0).abs() < 1e-9);
    assert_eq!(steep.friction_deg, 20.0);
    // The whole face of the pile, from the face to its toe.
    assert_eq!(steep.x[0], 0.0);
    assert!((steep.x[1] - 0.3 / 30f64.to_radians().tan()).abs() < 1e-9);
    let b = bracket(&p, 3).unwrap();
    assert_eq!(b.steep, Some(steep));
    for bound in [b.lower.as_ref().err(), b.upper.as_ref().err()] {
        let e = bound.expect("no bound");
        assert!(e.is_steep() && !e.is_infeasible(), "{e}");
        assert_eq!(e.status, SolveError::STEEP);
        assert!(e.to_string().contains("cannot stand under its own weight"));
    }
    assert!(b.lower_force().is_nan() && b.upper_force().is_nan());
}

#[test]
fn a_pile_that_can_stand_is_solved() {
    // Cohesion holds a short slope steeper than φ; φ above the slope holds any.
    for p in [piled(20.0, 0.5), piled(35.0, 0.0)] {
        assert_eq!(p.steep(), None);
        let b = bracket(&p, 3).unwrap();
        assert_eq!(b.steep, None);
        let (lower, upper) = (b.lower_force(), b.upper_force());
        assert!(
            lower > 0.0 && lower <= upper * (1.0 + 1e-5),
            "{lower} {upper}"
        );
    }
}

/// The slope field lifts φ to the slope (plus its margin) where it is
/// weaker, nowhere else: the loose pile then stands and is bracketed, and
/// on a cohesive pile that stood already both bounds rise.
#[test]
fn the_slope_field_makes_the_pile_stand_and_strengthens_it() {
    let mut loose = piled(20.0, 0.0);
    Field::Slope.apply(&mut loose.ground);
    let phi: Vec<f64> = loose.ground.soil.iter().map(|s| s.friction_deg).collect();
    // Columns 0 to 8 stand on the pile (8 at its toe), 9 on are flat.
    let toe = 8;
    for (i, &f) in phi.iter().enumerate() {
        let expected = if i <= toe {
            30.0 + soilcut_bounds::strength::SLOPE_MARGIN
        } else {
            20.0
        };
        assert!((f - expected).abs() < 1e-9, "column {i}: {f}");
    }
    assert_eq!(loose.steep(), None);
    let b = bracket(&loose, 3).unwrap();
    let (lower, upper) = (b.lower_force(), b.upper_force());
    assert!(
        lower > 0.0 && lower <= upper * (1.0 + 1e-5),
        "{:?} {:?}",
        b.lower,
        b.upper
    );

    let own = piled(20.0, 0.5);
    let mut lifted = own.clone();
    Field::Slope.apply(&mut lifted.ground);
    let (a, b) = (bracket(&own, 3).unwrap(), bracket(&lifted, 3).unwrap());
    assert!(
        b.lower_force() > a.lower_force(),
        "{} {}",
        a.lower_force(),
        b.lower_force()
    );
    assert!(
        b.upper_force() > a.upper_force(),
        "{} {}",
        a.upper_force(),
        b.upper_force()
    );
    // On flat ground the field changes nothing.
    let flat = Problem::flat(1.0, own.below, 0.0, 0.0, 0.0);
    let mut same = flat.clone();
    Field::Slope.apply(&mut same.ground);
    assert_eq!(same, flat);
}
