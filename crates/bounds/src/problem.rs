//! The boundary-value problem: a rigid blade face, the ground in front of it
//! as it stands, and the soil below the tip, in plane strain.
//!
//! Coordinates: x horizontal, positive in the cutting direction; y vertical,
//! up. The blade's tip is at A = (x_A, y_A); its face rises from A at the
//! rake α (the face's angle from the horizontal on the soil side, 90°
//! vertical) and leans back along (−cos α, sin α) up to the ground. Soil
//! lies in front of the face (+x); behind it is the cut trench, whose floor
//! is the level of the tip, y = y_A, with no load on it. Below the tip level
//! the soil is continuous under the blade and the trench.
//!
//! Angles are in degrees here; stresses (cohesion c, adhesion a, surcharge q)
//! in force per length²; unit weight γ in force per length³; forces per unit
//! width.

/// Strength and weight of a soil: Mohr–Coulomb with associated flow in the
/// bounds (see the crate documentation for non-associated soil).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Soil {
    /// φ, friction angle, degrees, in [0, 89].
    pub friction_deg: f64,
    /// c, cohesion (stress), ≥ 0.
    pub cohesion: f64,
    /// γ, unit weight (force per length³), ≥ 0.
    pub unit_weight: f64,
}

/// The blade's face: a rigid, straight plate from the tip to the ground.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Face {
    /// x_A, horizontal position of the tip.
    pub tip_x: f64,
    /// y_A, height of the tip (below the ground).
    pub tip_y: f64,
    /// α, rake, degrees, in [30, 90].
    pub rake_deg: f64,
    /// φw, face friction angle, degrees, in [0, 89].
    pub friction_deg: f64,
    /// a, adhesion on the face (stress), ≥ 0.
    pub adhesion: f64,
}

/// The ground in front of the blade: its surface height and its soil,
/// sampled at columns x_i (ascending). Between samples the surface is
/// linear and the soil is that of the nearest sample; beyond the last
/// sample the surface is flat at the last height and the soil the last
/// sample's. The soil of a column applies from the tip level to the surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Ground {
    /// x_i, column positions, ascending.
    pub x: Vec<f64>,
    /// y_i, surface heights, above the tip level.
    pub y: Vec<f64>,
    /// The soil of each column.
    pub soil: Vec<Soil>,
}

/// How far the mesh reaches, in multiples of the face's height h (tip to
/// ground): ahead of the tip, below it and behind it. The truncated
/// boundaries are fixed in the upper bound (rigid soil beyond, kinematically
/// admissible) and free of any condition in the lower bound; the extents
/// must be large enough that enlarging them no longer changes either bound
/// (`crates/bounds/tests/domain.rs` checks the defaults on the checks' problems).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    /// Reach ahead of the tip, multiples of h, in [0.5, 100].
    pub reach: f64,
    /// Depth below the tip, multiples of h, in [0.1, 100].
    pub depth: f64,
    /// Reach behind the tip (under the trench), multiples of h, in [0.1, 100].
    pub back: f64,
}

impl Default for Domain {
    fn default() -> Self {
        Domain {
            reach: 4.0,
            depth: 1.5,
            back: 1.5,
        }
    }
}

/// The whole problem: what is found is the largest horizontal force the
/// face can exert on the soil (the passive, cutting load), per unit width.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// The blade face.
    pub face: Face,
    /// The ground in front of the face.
    pub ground: Ground,
    /// The soil below the tip level (under the ground and the trench).
    pub below: Soil,
    /// q, surcharge on the ground surface (stress, vertical, per unit
    /// horizontal length), ≥ 0. The trench floor carries none.
    pub surcharge: f64,
    /// The mesh's extent.
    pub domain: Domain,
}

/// A problem that cannot be solved as given: the key and its allowed range.
#[derive(Clone, Debug, PartialEq)]
pub struct InputError {
    /// The offending input, e.g. `face.rake_deg` or `ground.y[3]`.
    pub key: String,
    /// What is allowed, e.g. "in [30, 90]".
    pub allowed: String,
    /// The value given.
    pub value: f64,
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {} must be {}", self.key, self.value, self.allowed)
    }
}

impl std::error::Error for InputError {}

fn check(key: &str, value: f64, lo: f64, hi: f64) -> Result<(), InputError> {
    if value.is_finite() && value >= lo && value <= hi {
        return Ok(());
    }
    Err(InputError {
        key: key.to_string(),
        allowed: format!("in [{lo}, {hi}]"),
        value,
    })
}

/// The least rake the mesh takes, degrees: its columns parallel to the
/// face would lie too flat below it.
pub const MIN_RAKE: f64 = 30.0;

/// How much steeper than its soil's friction angle a piece of cohesionless
/// surface must be to count as steep (degrees): a slope at its friction
/// angle, to rounding, is at limiting equilibrium and not refused.
pub const STEEP_TOLERANCE: f64 = 1e-3;

/// A piece of the ground's surface steeper than the friction angle of its
/// soil, which has no cohesion and some weight: the ground cannot stand
/// under its own weight. No stress field carries it (there is no lower
/// bound: on a cohesionless surface the stress vanishes, and just below a
/// surface at β the soil must carry the shear of an infinite slope,
/// τ/σ = tan β > tan φ), and a thin block of it slides down at no cost (c = 0
/// dissipates nothing while gravity does work in proportion to the
/// block's velocity: the upper bound is unbounded below).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Steep {
    /// x of the ends of the stretch of steep pieces about the steepest.
    pub x: [f64; 2],
    /// The steepest piece's slope from the horizontal, degrees.
    pub slope_deg: f64,
    /// The least friction angle of the columns at that piece's ends,
    /// degrees.
    pub friction_deg: f64,
}

/// Largest magnitude of any length or stress: keeps the scaled problem's
/// products finite.
const BIG: f64 = 1e20;

impl Soil {
    fn validate(&self, key: &str) -> Result<(), InputError> {
        check(&format!("{key}.friction_deg"), self.friction_deg, 0.0, 89.0)?;
        check(&format!("{key}.cohesion"), self.cohesion, 0.0, BIG)?;
        check(&format!("{key}.unit_weight"), self.unit_weight, 0.0, BIG)
    }
}

impl Problem {
    /// Checks every input against its range, naming the first that is out.
    pub fn validate(&self) -> Result<(), InputError> {
        let f = &self.face;
        check("face.tip_x", f.tip_x, -BIG, BIG)?;
        check("face.tip_y", f.tip_y, -BIG, BIG)?;
        check("face.rake_deg", f.rake_deg, MIN_RAKE, 90.0)?;
        check("face.friction_deg", f.friction_deg, 0.0, 89.0)?;
        check("face.adhesion", f.adhesion, 0.0, BIG)?;
        check("surcharge", self.surcharge, 0.0, BIG)?;
        check("domain.reach", self.domain.reach, 0.5, 100.0)?;
        check("domain.depth", self.domain.depth, 0.0, 100.0)?;
        check("domain.back", self.domain.back, 0.1, 100.0)?;
        self.below.validate("below")?;
        self.validate_ground()
    }

    fn validate_ground(&self) -> Result<(), InputError> {
        let g = &self.ground;
        let n = g.x.len();
        check("ground.x.len()", n as f64, 1.0, 1e9)?;
        if g.y.len() != n || g.soil.len() != n {
            return Err(InputError {
                key: "ground.y.len(), ground.soil.len()".into(),
                allowed: format!("equal to ground.x.len() = {n}"),
                value: g.y.len().min(g.soil.len()) as f64,
            });
        }
        for i in 0..n {
            check(&format!("ground.x[{i}]"), g.x[i], -BIG, BIG)?;
            if i > 0 && g.x[i] <= g.x[i - 1] {
                return Err(InputError {
                    key: format!("ground.x[{i}]"),
                    allowed: format!("greater than ground.x[{}] = {}", i - 1, g.x[i - 1]),
                    value: g.x[i],
                });
            }
            let floor = self.face.tip_y;
            if !(g.y[i].is_finite() && g.y[i] > floor && g.y[i] < BIG) {
                return Err(InputError {
                    key: format!("ground.y[{i}]"),
                    allowed: format!("above the tip level face.tip_y = {floor}"),
                    value: g.y[i],
                });
            }
            g.soil[i].validate(&format!("ground.soil[{i}]"))?;
        }
        Ok(())
    }

    /// The checks' problem: flat ground at y = 0 of one soil (also below
    /// the tip), a vertical face with friction φw and no adhesion, its tip at
    /// (0, −d), the surcharge q, the default domain with the given depth
    /// below the tip (0: soilcut's rigid floor at the tip level).
    pub fn flat(d: f64, soil: Soil, face_friction_deg: f64, surcharge: f64, depth: f64) -> Problem {
        Problem {
            face: Face {
                tip_x: 0.0,
                tip_y: -d,
                rake_deg: 90.0,
                friction_deg: face_friction_deg,
                adhesion: 0.0,
            },
            ground: Ground {
                x: vec![0.0],
                y: vec![0.0],
                soil: vec![soil],
            },
            below: soil,
            surcharge,
            domain: Domain {
                depth,
                ..Domain::default()
            },
        }
    }

    /// The stretch of surface steeper than the friction angle of its
    /// cohesionless, weighing soil (by more than [`STEEP_TOLERANCE`]) about
    /// the piece (between two samples) that exceeds it most; `None` where
    /// every piece can stand.
    pub fn steep(&self) -> Option<Steep> {
        let g = &self.ground;
        let loose = |s: &Soil| s.cohesion == 0.0 && s.unit_weight > 0.0;
        // Each piece's slope, the least φ of its loose ends, and the excess.
        let pieces: Vec<(f64, f64, f64)> = (1..g.x.len())
            .map(|i| {
                let slope = ((g.y[i] - g.y[i - 1]) / (g.x[i] - g.x[i - 1]))
                    .atan()
                    .abs()
                    .to_degrees();
                let phi = [g.soil[i - 1], g.soil[i]]
                    .iter()
                    .filter(|s| loose(s))
                    .map(|s| s.friction_deg)
                    .fold(f64::INFINITY, f64::min);
                (slope, phi, slope - phi)
            })
            .collect();
        let steep = |k: usize| pieces[k].2 > STEEP_TOLERANCE;
        let worst = (0..pieces.len()).filter(|&k| steep(k)).reduce(|a, b| {
            if pieces[b].2 > pieces[a].2 {
                b
            } else {
                a
            }
        })?;
        let (mut first, mut last) = (worst, worst);
        while first > 0 && steep(first - 1) {
            first -= 1;
        }
        while last + 1 < pieces.len() && steep(last + 1) {
            last += 1;
        }
        Some(Steep {
            x: [g.x[first], g.x[last + 1]],
            slope_deg: pieces[worst].0,
            friction_deg: pieces[worst].1,
        })
    }

    /// Surface height at x: linear between samples, flat beyond them.
    pub fn surface(&self, x: f64) -> f64 {
        let (xs, ys) = (&self.ground.x, &self.ground.y);
        let n = xs.len();
        if x <= xs[0] {
            return ys[0];
        }
        if x >= xs[n - 1] {
            return ys[n - 1];
        }
        let i = xs.partition_point(|&xi| xi <= x);
        let t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
        ys[i - 1] + t * (ys[i] - ys[i - 1])
    }

    /// The soil of the column nearest to x (above the tip level).
    pub fn column_soil(&self, x: f64) -> Soil {
        let xs = &self.ground.x;
        let i = xs.partition_point(|&xi| xi <= x);
        let k = if i == 0 {
            0
        } else if i == xs.len() || x - xs[i - 1] <= xs[i] - x {
            i - 1
        } else {
            i
        };
        self.ground.soil[k]
    }

    /// The soil at a point: the column's above the tip level, `below` under it.
    pub fn soil_at(&self, x: f64, y: f64) -> Soil {
        if y < self.face.tip_y {
            self.below
        } else {
            self.column_soil(x)
        }
    }

    /// cot α: a line through the tip-level point (x0, y_A) parallel to the
    /// face is x = x0 − (y − y_A) cot α.
    pub fn cot_rake(&self) -> f64 {
        let a = self.face.rake_deg.to_radians();
        a.cos() / a.sin()
    }

    /// Height where the line parallel to the face through (x0, y_A) meets
    /// the surface: the root of y = s(x0 − (y − y_A) cot α), by bisection
    /// from the tip level (the lowest crossing).
    pub fn column_top(&self, x0: f64) -> f64 {
        let (ya, cot) = (self.face.tip_y, self.cot_rake());
        let gap = |y: f64| self.surface(x0 - (y - ya) * cot) - y;
        if cot == 0.0 {
            return self.surface(x0);
        }
        let mut hi = ya + 1.0;
        let top = self.ground.y.iter().fold(f64::MIN, |m, &y| m.max(y));
        while gap(hi) > 0.0 && hi < top + 1.0 {
            hi = ya + 2.0 * (hi - ya);
        }
        let mut lo = ya;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if gap(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// h, the face's height from the tip to the ground.
    pub fn face_height(&self) -> f64 {
        self.column_top(self.face.tip_x) - self.face.tip_y
    }
}
