//! The physical models. Nothing here knows about the window: every function
//! takes and returns plain numbers in SI units.

pub mod aggregate;
pub mod batches;
pub mod coagulation;
pub mod collision;
mod column_row;
pub mod constants;
pub mod contact;
pub mod crack;
pub mod debris;
pub mod disk;
pub mod equations;
pub mod experiments;
pub mod fdlibm;
pub mod fit;
pub mod growth;
pub mod material;
pub mod monomer;
pub mod monte_carlo;
pub mod plasticity;
pub mod rolling;
pub mod tabled;
mod wide;

/// Error for physically meaningless input to a model function.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PhysicsError {
    /// A parameter is non-finite or outside its valid range.
    #[error("{name} = {value:e} is invalid: {reason}")]
    InvalidParameter {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A run configuration is inconsistent.
    #[error("{0}")]
    Invalid(String),
    /// The integrator failed. (Not a `source`: the message already says why,
    /// and error chains would print it twice.)
    #[error("integration failed: {0}")]
    Solver(crate::solver::SolverError),
}

impl From<crate::solver::SolverError> for PhysicsError {
    fn from(e: crate::solver::SolverError) -> Self {
        PhysicsError::Solver(e)
    }
}

/// Mass of a homogeneous sphere, m = (4/3)πρr³, kg (density in kg m⁻³, radius in m).
pub fn sphere_mass(density: f64, radius: f64) -> f64 {
    density * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3)
}

/// Returns `Ok(value)` if `value` is finite and strictly positive.
pub fn positive(name: &'static str, value: f64) -> Result<f64, PhysicsError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(PhysicsError::InvalidParameter { name, value, reason: "must be finite and > 0" })
    }
}
