//! Physical constants, SI.

/// Gravitational constant, m³ kg⁻¹ s⁻².
pub const G: f64 = 6.674_30e-11;
/// Solar mass, kg.
pub const M_SUN: f64 = 1.988_47e30;
/// Astronomical unit, m.
pub const AU: f64 = 1.495_978_707e11;
/// Boltzmann constant, J K⁻¹.
pub const K_B: f64 = 1.380_649e-23;
/// One year, s.
pub const YEAR: f64 = 3.156e7;
