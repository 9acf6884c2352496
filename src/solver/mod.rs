//! Numerical integrators, root finders and samplers shared by the physical models.

mod explicit;
mod roots;
mod rosenbrock;
pub mod sampling;

pub use explicit::{dormand_prince, dormand_prince_step};
pub use roots::{Root, illinois};
pub use rosenbrock::{ClockInstant, LogClock, Matrix, Rosenbrock4, SolverError, SolverStats, State, StiffSystem};
