//! Parameters shared by the rolling scenes (thesis ch. 3): a sphere on a flat
//! substrate or on an equal sphere.

use crate::physics::contact::Pair;
use crate::physics::material::{Material, combined_modulus};
use crate::scene::core::logspace;
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// The rolling contact. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
#[param(manual_default)]
pub struct RollingParams {
    /// material of the rolling sphere
    #[param(label = "sphere material")]
    pub sphere: Material,
    /// flat substrate or second sphere
    #[param(label = "substrate material")]
    pub substrate: Material,
    /// on a flat substrate (else on an equal sphere)
    #[param(label = "sphere on flat")]
    pub wall: bool,
    /// radius of the rolling sphere
    #[param(label = "sphere radius", unit = "m", shown("µm", 1e6), range(1e-7, 1e-3), log)]
    pub radius: f64,
    /// combined surface energy (2γ_L for like materials)
    #[param(quantity = quantities::surface_energy)]
    pub surface_energy: f64,
}

impl Default for RollingParams {
    fn default() -> Self {
        let psl = Material::named("PSL").cloned().unwrap_or_else(Material::water_ice);
        RollingParams { sphere: psl.clone(), substrate: psl, wall: true, radius: 5e-6, surface_energy: 0.05 }
    }
}

impl RollingParams {
    /// A preset contact.
    pub fn of(sphere: &str, substrate: &str, wall: bool, radius: f64, surface_energy: f64) -> Self {
        let d = RollingParams::default();
        RollingParams {
            sphere: Material::named(sphere).cloned().unwrap_or(d.sphere),
            substrate: Material::named(substrate).cloned().unwrap_or(d.substrate),
            wall,
            radius,
            surface_energy,
        }
    }

    /// After a material changed: γ = 2(γ₁γ₂)^{1/2} of the chosen materials.
    pub fn material_changed(&mut self) {
        self.surface_energy = crate::physics::material::combined_surface_energy(&self.sphere, &self.substrate);
    }

    /// Mass of the sphere of radius `r`, kg.
    pub fn sphere_mass(&self, r: f64) -> f64 {
        crate::physics::sphere_mass(self.sphere.density, r)
    }

    /// The contact of a sphere of radius `r`: R = r on a flat, r/2 on an equal sphere.
    pub fn pair(&self, r: f64) -> Pair {
        let m = self.sphere_mass(r);
        let (radius, mass) = if self.wall { (r, m) } else { (r / 2.0, m / 2.0) };
        Pair {
            modulus: combined_modulus(&self.sphere, &self.substrate),
            radius,
            mass,
            surface_energy: self.surface_energy,
        }
    }

    /// Moment of inertia (2/5)mr² of the sphere, kg m² (as in (3.17)).
    pub fn inertia(&self, r: f64) -> f64 {
        0.4 * self.sphere_mass(r) * r * r
    }
}

/// The hysteresis values of the family.
pub fn family(h_min: f64, h_max: f64, n: usize) -> Vec<f64> {
    if n <= 1 { vec![h_min] } else { logspace(h_min, h_max.max(h_min * 1.000001), n) }
}
