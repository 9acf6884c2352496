//! Parameters shared by the debris-disk scenes (thesis ch. 6).

use crate::physics::debris::{DebrisMaterial, TABLE_6_1};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Collision parameters of the fragment model. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct FragmentParams {
    /// collision velocity
    #[param(label = "relative velocity", unit = "m s^-1", shown("m/s", 1.0), range(1e-2, 1e4), log, default = 20.0)]
    pub velocity: f64,
    /// fraction of the kinetic energy that makes surface
    #[param(quantity = quantities::efficiency, default = 1e-2)]
    pub eta: f64,
    /// fragment distribution n(s) ~ s^-α, 3 < α < 4
    #[param(label = "slope α", range(3.01, 3.99), default = 3.5)]
    pub alpha: f64,
    /// s_max = (fraction)^{1/3} s₀ (default 1/2)
    ///
    /// Mass fraction of the largest fragment relative to one collider (default 1/2:
    /// s_max = 2^{-1/3} s₀).
    #[param(label = "largest fragment / collider mass", range(1e-3, 1.0), log, default = 0.5)]
    pub largest_fraction: f64,
}

impl FragmentParams {
    /// Largest fragment of a collider of radius s₀, m.
    pub fn s_max(&self, s0: f64) -> f64 {
        self.largest_fraction.cbrt() * s0
    }
}

/// The materials of Table 6.1.
pub fn materials() -> &'static [DebrisMaterial] {
    &TABLE_6_1
}
