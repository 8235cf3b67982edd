//! soilcut-bounds: rigorous lower and upper bounds on the force a rigid
//! blade needs to cut the ground in front of it, by finite-element limit
//! analysis (FELA) in plane strain, as second-order-cone programs solved by
//! an interior-point method (`clarabel`). A pure library: no files, no
//! terminal.
//!
//! The [`Problem`] is the ground as it stands (surface, per-column friction,
//! cohesion and unit weight), a rigid face with friction φw and adhesion a,
//! a surcharge q, and the soil below the tip. Both bounds find the largest
//! horizontal force P_h the face can exert on the soil:
//!
//! - [`lower`]: a statically admissible stress field (equilibrium, stress
//!   discontinuities at every edge, Mohr–Coulomb yield as a cone) proves
//!   that the soil carries P_h^L without collapse: P_h^L ≤ P_h.
//! - [`upper`]: a kinematically admissible velocity field (the face at unit
//!   horizontal velocity) whose dissipation, net of the power of gravity and
//!   surcharge, is P_h^U ≥ P_h.
//!
//! The theorems hold for a perfectly plastic soil with associated flow
//! (dilation ψ = φ) and an associated face interface: for a soil with
//! ψ < φ the bracket bounds the associated soil of the same strength.
//!
//! ```
//! use soilcut_bounds::{Problem, Soil};
//! let sand = Soil { friction_deg: 30.0, cohesion: 0.0, unit_weight: 1.0 };
//! let p = Problem::flat(1.0, sand, 0.0, 0.0, 0.0);
//! let b = soilcut_bounds::bracket(&p, 2).unwrap();
//! // Rankine: ½ Kp γ d² = 1.5 (Kp = 3).
//! assert!(b.lower_force() <= 1.5 + 1e-6 && 1.5 <= b.upper_force() + 1e-6);
//! ```

#![warn(missing_docs)]

mod bracket;
pub mod conic;
mod edges;
pub mod instant;
pub mod lower;
pub mod mesh;
pub mod problem;
mod quadratic;
pub mod scale;
pub mod strength;
pub mod upper;

pub use bracket::{bracket, Bracket, MAX_MESH};
pub use conic::SolveError;
pub use instant::{Floor, Instant, InstantError, Options, DEFAULT_MESH};
pub use lower::LowerBound;
pub use mesh::{Mesh, Side};
pub use problem::{Domain, Face, Ground, InputError, Problem, Soil, Steep};
pub use strength::{Field, Strength};
pub use upper::UpperBound;
