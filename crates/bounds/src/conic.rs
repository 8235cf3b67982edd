//! A second-order-cone program assembled row by row and solved by the
//! interior-point method of `clarabel` (Goulart & Chen 2024):
//!
//! ```text
//! minimise cᵀx  subject to  A x + s = b,  s ∈ {0}ᵐ¹ × ℝ₊ᵐ² × Q³ × … × Q³
//! ```
//!
//! with Q³ = {(t, u, v) : √(u² + v²) ≤ t} the Lorentz cone.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
};

/// An affine expression Σ aᵢ xᵢ + constant.
#[derive(Clone, Debug, Default)]
pub struct Affine {
    /// (variable, coefficient) pairs; repeats add up.
    pub terms: Vec<(usize, f64)>,
    /// The constant.
    pub constant: f64,
}

impl Affine {
    /// Σ aᵢ xᵢ.
    pub fn of(terms: Vec<(usize, f64)>) -> Affine {
        Affine {
            terms,
            constant: 0.0,
        }
    }

    /// Adds a constant.
    pub fn plus(mut self, constant: f64) -> Affine {
        self.constant += constant;
        self
    }
}

/// Rows of one kind: s = b − A x, A's entries as (row, column, value).
#[derive(Default)]
struct Rows {
    entries: Vec<(usize, usize, f64)>,
    b: Vec<f64>,
}

impl Rows {
    /// A row whose slack is the affine expression e: A = −terms, b = constant.
    fn push(&mut self, e: &Affine) {
        let row = self.b.len();
        self.entries
            .extend(e.terms.iter().map(|&(j, a)| (row, j, -a)));
        self.b.push(e.constant);
    }
}

/// The program under assembly.
#[derive(Default)]
pub struct Program {
    vars: usize,
    cost: Vec<f64>,
    zero: Rows,
    nonneg: Rows,
    cones: Rows,
}

/// The solver's answer.
#[derive(Clone, Debug)]
pub struct Solution {
    /// The minimiser.
    pub x: Vec<f64>,
    /// cᵀx at the minimiser.
    pub objective: f64,
    /// Interior-point iterations.
    pub iterations: u32,
}

/// The solver did not reach an optimum.
#[derive(Clone, Debug, PartialEq)]
pub struct SolveError {
    /// clarabel's status, e.g. "PrimalInfeasible".
    pub status: String,
}

impl std::fmt::Display for SolveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.is_steep() {
            return write!(
                f,
                "not sought: the ground cannot stand under its own weight"
            );
        }
        write!(f, "the conic solver stopped with status {}", self.status)
    }
}

impl std::error::Error for SolveError {}

impl SolveError {
    /// Whether the program has no solution (rather than the solver failing
    /// to find one): for a lower bound, no field on the mesh carries the
    /// ground's own weight.
    pub fn is_infeasible(&self) -> bool {
        self.status.contains("Infeasible")
    }

    /// The status of a bound not sought because the ground cannot stand
    /// under its own weight ([`crate::Steep`]).
    pub const STEEP: &'static str = "SteepGround";

    /// A bound not sought because the ground cannot stand.
    pub fn steep() -> SolveError {
        SolveError {
            status: Self::STEEP.into(),
        }
    }

    /// Whether the bound was not sought because the ground cannot stand.
    pub fn is_steep(&self) -> bool {
        self.status == Self::STEEP
    }
}

impl Program {
    /// n new variables; returns the first one's index.
    pub fn variables(&mut self, n: usize) -> usize {
        self.vars += n;
        self.cost.resize(self.vars, 0.0);
        self.vars - n
    }

    /// Adds a to variable j's cost.
    pub fn cost(&mut self, j: usize, a: f64) {
        self.cost[j] += a;
    }

    /// e = 0.
    pub fn zero(&mut self, e: &Affine) {
        self.zero.push(e);
    }

    /// e ≥ 0.
    pub fn nonnegative(&mut self, e: &Affine) {
        self.nonneg.push(e);
    }

    /// √(u² + v²) ≤ t.
    pub fn cone(&mut self, t: &Affine, u: &Affine, v: &Affine) {
        for e in [t, u, v] {
            self.cones.push(e);
        }
    }

    /// Number of variables and of constraint rows.
    pub fn size(&self) -> (usize, usize) {
        let rows = self.zero.b.len() + self.nonneg.b.len() + self.cones.b.len();
        (self.vars, rows)
    }

    /// Minimises the cost.
    pub fn solve(&self) -> Result<Solution, SolveError> {
        let (n, m) = self.size();
        let (mut i, mut j, mut v, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut offset = 0;
        for rows in [&self.zero, &self.nonneg, &self.cones] {
            for &(r, c, a) in &rows.entries {
                i.push(offset + r);
                j.push(c);
                v.push(a);
            }
            b.extend_from_slice(&rows.b);
            offset += rows.b.len();
        }
        let a = CscMatrix::new_from_triplets(m, n, i, j, v);
        let p = CscMatrix::zeros((n, n));
        let mut cones = Vec::new();
        if !self.zero.b.is_empty() {
            cones.push(SupportedConeT::ZeroConeT(self.zero.b.len()));
        }
        if !self.nonneg.b.is_empty() {
            cones.push(SupportedConeT::NonnegativeConeT(self.nonneg.b.len()));
        }
        cones.extend((0..self.cones.b.len() / 3).map(|_| SupportedConeT::SecondOrderConeT(3)));
        let settings = DefaultSettingsBuilder::default()
            .verbose(false)
            .max_iter(400)
            .build()
            .map_err(|e| SolveError {
                status: format!("{e:?}"),
            })?;
        let mut solver =
            DefaultSolver::new(&p, &self.cost, &a, &b, &cones, settings).map_err(|e| {
                SolveError {
                    status: format!("{e:?}"),
                }
            })?;
        solver.solve();
        let s = &solver.solution;
        match s.status {
            SolverStatus::Solved | SolverStatus::AlmostSolved => Ok(Solution {
                x: s.x.clone(),
                objective: s.obj_val,
                iterations: s.iterations,
            }),
            other => Err(SolveError {
                status: format!("{other:?}"),
            }),
        }
    }
}
