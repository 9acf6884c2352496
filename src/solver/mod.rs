//! Numerical integrators, root finders and samplers shared by the physical models.

mod roots;
mod rosenbrock;
pub mod sampling;

pub use roots::{Root, illinois};
pub use rosenbrock::{ClockInstant, LogClock, Matrix, Rosenbrock4, SolverError, SolverStats, State, StiffSystem};
