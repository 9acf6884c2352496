//! Numerical integrators shared by the physical models.

mod roots;
mod rosenbrock;

pub use roots::{Root, illinois};
pub use rosenbrock::{Matrix, Rosenbrock4, SolverError, SolverStats, State, StiffSystem};
