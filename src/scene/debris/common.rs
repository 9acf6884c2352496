//! Parameters shared by the debris-disk scenes (thesis ch. 6).

use crate::physics::debris::{DebrisMaterial, TABLE_6_1};
use crate::scene::controls::Control;
use crate::scene::quantities;
use serde::{Deserialize, Serialize};

/// Collision parameters of the fragment model. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FragmentParams {
    /// Relative velocity, m s⁻¹ (default 20).
    pub velocity: f64,
    /// Fraction η of the kinetic energy that creates surface (default 10⁻²).
    pub eta: f64,
    /// Slope α of the fragment distribution, 3 < α < 4 (default 3.5).
    pub alpha: f64,
    /// Mass fraction of the largest fragment relative to one collider (default 1/2:
    /// s_max = 2^{-1/3} s₀).
    pub largest_fraction: f64,
}

impl Default for FragmentParams {
    fn default() -> Self {
        FragmentParams { velocity: 20.0, eta: 1e-2, alpha: 3.5, largest_fraction: 0.5 }
    }
}

impl FragmentParams {
    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        vec![
            Control::number("velocity", "relative velocity", &mut self.velocity)
                .default(d.velocity)
                .unit("m s^-1")
                .shown("m/s", 1.0)
                .range(1e-2, 1e4)
                .log()
                .doc("collision velocity"),
            quantities::efficiency(&mut self.eta)
                .default(d.eta)
                .doc("fraction of the kinetic energy that makes surface"),
            Control::number("alpha", "slope α", &mut self.alpha)
                .default(d.alpha)
                .range(3.01, 3.99)
                .doc("fragment distribution n(s) ~ s^-α, 3 < α < 4"),
            Control::number("largest_fraction", "largest fragment / collider mass", &mut self.largest_fraction)
                .default(d.largest_fraction)
                .range(1e-3, 1.0)
                .log()
                .doc("s_max = (fraction)^{1/3} s₀ (default 1/2)"),
        ]
    }

    /// Largest fragment of a collider of radius s₀, m.
    pub fn s_max(&self, s0: f64) -> f64 {
        self.largest_fraction.cbrt() * s0
    }
}

/// The materials of Table 6.1.
pub fn materials() -> &'static [DebrisMaterial] {
    &TABLE_6_1
}
