//! Functions of known indices, run in place of a case to check the
//! estimators (the command's hidden `--function`).

use crate::error::StudyError;

/// A test function of the varied inputs, in the order given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Function {
    /// Ishigami & Homma (1990): sin x₁ + a sin² x₂ + b x₃⁴ sin x₁ with
    /// a = 7, b = 0.1, on [−π, π]³: S1 = 0.3139, 0.4424, 0 and
    /// ST = 0.5576, 0.4424, 0.2437.
    Ishigami,
    /// Σ (i + 1) x_i: the coefficients 1, 2, 3, … in the inputs' order.
    Linear,
}

impl Function {
    /// `ishigami` or `linear`.
    pub fn parse(text: &str) -> Result<Function, StudyError> {
        match text {
            "ishigami" => Ok(Function::Ishigami),
            "linear" => Ok(Function::Linear),
            _ => Err(StudyError::Spec(format!(
                "--function {text}: expected ishigami or linear"
            ))),
        }
    }

    /// The inputs it takes (None: any number).
    pub fn inputs(self) -> Option<usize> {
        match self {
            Function::Ishigami => Some(3),
            Function::Linear => None,
        }
    }

    /// Its value at `x`.
    pub fn value(self, x: &[f64]) -> f64 {
        match self {
            Function::Ishigami => {
                let (a, b) = (7.0, 0.1);
                x[0].sin() + a * x[1].sin().powi(2) + b * x[2].powi(4) * x[0].sin()
            }
            Function::Linear => x.iter().enumerate().map(|(i, v)| (i + 1) as f64 * v).sum(),
        }
    }
}
