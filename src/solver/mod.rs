//! Numerical integrators shared by the physical models.

mod rosenbrock;

pub use rosenbrock::{Matrix, Rosenbrock4, SolverError, SolverStats, State, StiffSystem};
