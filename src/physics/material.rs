//! Material properties (Table 2.2 of the thesis), loaded from `assets/materials.ron`.

use serde::{Deserialize, Serialize};
use std::sync::OnceLock;

/// Elastic and adhesive properties of one material.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Display name, e.g. "water ice".
    pub name: String,
    /// Group heading of Table 2.2 (metals/minerals, polymers, others).
    #[serde(default)]
    pub group: String,
    /// Young's modulus E, Pa.
    pub youngs_modulus: f64,
    /// Poisson ratio ν, dimensionless (0 ≤ ν < 0.5).
    pub poisson_ratio: f64,
    /// Density ρ, kg m⁻³.
    pub density: f64,
    /// Surface free energy γ_L of one surface, J/m².
    pub surface_energy: f64,
}

impl Material {
    /// Bulk sound speed (E/ρ)^{1/2}, m/s (the c_s column of Table 2.2).
    pub fn sound_speed(&self) -> f64 {
        (self.youngs_modulus / self.density).sqrt()
    }

    /// Looks a material up by name (case-insensitive).
    pub fn named(name: &str) -> Option<&'static Material> {
        materials().iter().find(|m| m.name.eq_ignore_ascii_case(name))
    }

    /// Water ice of Table 2.2: E = 7 GPa, ν = 0.25, ρ = 1000 kg m⁻³, γ_L = 0.37 J/m².
    pub fn water_ice() -> Material {
        Material {
            name: "water ice".into(),
            group: "Others".into(),
            youngs_modulus: 7e9,
            poisson_ratio: 0.25,
            density: 1000.0,
            surface_energy: 0.37,
        }
    }
}

/// Combined elastic modulus E* of two materials: 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂, Pa.
pub fn combined_modulus(a: &Material, b: &Material) -> f64 {
    1.0 / ((1.0 - a.poisson_ratio.powi(2)) / a.youngs_modulus + (1.0 - b.poisson_ratio.powi(2)) / b.youngs_modulus)
}

/// The bodies of a head-on collision, by geometry. SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bodies {
    /// Sphere 1 of radius `radius` on a flat wall (R₂ → ∞, m₂ → ∞).
    Wall {
        /// Radius of sphere 1, m.
        radius: f64,
    },
    /// Two spheres of radii `r1` and `r2`.
    Spheres {
        /// Radius of sphere 1, m.
        r1: f64,
        /// Radius of sphere 2, m.
        r2: f64,
    },
    /// Two identical spheres of radius `radius` (the sphere–sphere experiments).
    Twins {
        /// Radius of either sphere, m.
        radius: f64,
    },
}

/// The reduced properties of two bodies in contact: the one place the
/// two-sphere set-up of ch. 2 is written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBodies {
    /// Combined modulus E* (defined with (2.1)), Pa.
    pub modulus: f64,
    /// Reduced radius R = R₁R₂/(R₁ + R₂), m.
    pub radius: f64,
    /// Reduced mass m* = m₁m₂/(m₁ + m₂), kg.
    pub mass: f64,
    /// Mean Poisson ratio of the two materials (for A = T_vis/ν², exact for like materials).
    pub poisson_ratio: f64,
}

impl TwoBodies {
    /// Sphere 1 of material `a` against body 2 of material `b`.
    pub fn new(a: &Material, b: &Material, bodies: Bodies) -> TwoBodies {
        let (radius, mass) = match bodies {
            Bodies::Wall { radius } => (radius, super::sphere_mass(a.density, radius)),
            Bodies::Spheres { r1, r2 } => {
                let (m1, m2) = (super::sphere_mass(a.density, r1), super::sphere_mass(b.density, r2));
                (1.0 / (1.0 / r1 + 1.0 / r2), m1 * m2 / (m1 + m2))
            }
            Bodies::Twins { radius } => (radius / 2.0, super::sphere_mass(a.density, radius) / 2.0),
        };
        TwoBodies {
            modulus: combined_modulus(a, b),
            radius,
            mass,
            poisson_ratio: 0.5 * (a.poisson_ratio + b.poisson_ratio),
        }
    }
}

/// Combined surface energy of a contact, γ = 2 (γ₁γ₂)^{1/2}, J/m² (twice γ_L for like materials).
pub fn combined_surface_energy(a: &Material, b: &Material) -> f64 {
    2.0 * (a.surface_energy * b.surface_energy).sqrt()
}

static MATERIALS: OnceLock<Vec<Material>> = OnceLock::new();

/// The materials of Table 2.2, in the order of `assets/materials.ron`.
pub fn materials() -> &'static [Material] {
    MATERIALS.get_or_init(|| {
        // The table is compiled into the binary; a malformed asset is a build
        // defect caught by the test suite, so fall back to ice alone here.
        ron::from_str(include_str!("../../assets/materials.ron")).unwrap_or_else(|_| vec![Material::water_ice()])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_parses_completely() {
        let table: Vec<Material> =
            ron::from_str(include_str!("../../assets/materials.ron")).expect("materials.ron parses");
        assert_eq!(table.len(), 17);
        assert_eq!(materials().len(), 17);
    }

    #[test]
    fn sound_speeds_match_table() {
        // c_s column of Table 2.2.
        let cases = [("water ice", 2645.0), ("PSL", 1820.0), ("silicon", 8789.0), ("copper", 3813.0)];
        for (name, cs) in cases {
            let m = Material::named(name).expect(name);
            assert!((m.sound_speed() / cs - 1.0).abs() < 0.005, "{name}: {}", m.sound_speed());
        }
    }

    #[test]
    fn like_materials_double_the_surface_energy() {
        let ice = Material::water_ice();
        assert!((combined_surface_energy(&ice, &ice) - 0.74).abs() < 1e-12);
        let e = combined_modulus(&ice, &ice);
        assert!((e - 7e9 / (2.0 * 0.9375)).abs() < 1.0);
    }
}
