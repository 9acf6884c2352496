//! Parameters shared by the rolling scenes (thesis ch. 3): a sphere on a flat
//! substrate or on an equal sphere.

use crate::physics::contact::Pair;
use crate::physics::material::{Material, combined_modulus};
use crate::scene::controls::Control;
use crate::scene::core::logspace;
use crate::scene::quantities;
use serde::{Deserialize, Serialize};

/// The rolling contact. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RollingParams {
    /// Material of the rolling sphere.
    pub sphere: Material,
    /// Material of the substrate (or of the other sphere).
    pub substrate: Material,
    /// The sphere rests on a flat substrate (true) or on an equal sphere (false).
    pub wall: bool,
    /// Sphere radius, m (default 5 µm; 0.1 µm – 1 mm).
    pub radius: f64,
    /// Combined surface energy γ, J m⁻² (default 0.05 = 2 × 0.025 for PSL).
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

    /// The documented parameters; `with_radius` adds the radius slider.
    pub fn controls(&mut self, d: &Self, with_radius: bool) -> Vec<Control<'_>> {
        let mut c = vec![
            Control::material("sphere", "sphere material", &mut self.sphere)
                .default(d.sphere.name.clone())
                .doc("material of the rolling sphere"),
            Control::material("substrate", "substrate material", &mut self.substrate)
                .default(d.substrate.name.clone())
                .doc("flat substrate or second sphere"),
            Control::toggle("wall", "sphere on flat", &mut self.wall)
                .default(d.wall)
                .doc("on a flat substrate (else on an equal sphere)"),
        ];
        if with_radius {
            c.push(
                Control::number("radius", "sphere radius", &mut self.radius)
                    .default(d.radius)
                    .unit("m")
                    .shown("µm", 1e6)
                    .range(1e-7, 1e-3)
                    .log()
                    .doc("radius of the rolling sphere"),
            );
        }
        c.push(
            quantities::surface_energy(&mut self.surface_energy)
                .default(d.surface_energy)
                .doc("combined surface energy (2γ_L for like materials)"),
        );
        c
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

/// Controls of a radius range (m) and a family of Δγ/γ curves, shared by the
/// rolling scenes: (r_min, r_max) and (h_min, h_max, n_h).
pub fn family_controls<'a>(
    radius: (&'a mut f64, &'a mut f64),
    hysteresis: (&'a mut f64, &'a mut f64, &'a mut usize),
    defaults: ((f64, f64), (f64, f64, usize)),
) -> Vec<Control<'a>> {
    let (dr, dh) = defaults;
    let um = ("µm", 1e6);
    let unit = ("", 1.0);
    vec![
        Control::number("r_min", "smallest radius", radius.0)
            .unit("m")
            .shown(um.0, um.1)
            .range(1e-8, 1e-2)
            .log()
            .default(dr.0)
            .doc("smallest sphere radius"),
        Control::number("r_max", "largest radius", radius.1)
            .unit("m")
            .shown(um.0, um.1)
            .range(1e-8, 1e-2)
            .log()
            .default(dr.1)
            .doc("largest sphere radius"),
        Control::number("h_min", "smallest Δγ/γ", hysteresis.0)
            .shown(unit.0, unit.1)
            .range(1e-3, 100.0)
            .log()
            .default(dh.0)
            .doc("first curve of the family"),
        Control::number("h_max", "largest Δγ/γ", hysteresis.1)
            .shown(unit.0, unit.1)
            .range(1e-3, 100.0)
            .log()
            .default(dh.1)
            .doc("last curve of the family"),
        Control::count("n_h", "Δγ/γ curves", hysteresis.2).range(1.0, 8.0).default(dh.2).doc("curves in the family"),
    ]
}

/// The hysteresis values of the family.
pub fn family(h_min: f64, h_max: f64, n: usize) -> Vec<f64> {
    if n <= 1 { vec![h_min] } else { logspace(h_min, h_max.max(h_min * 1.000001), n) }
}
