//! Parameters shared by the collision scenes: the two bodies, the contact and
//! the numerics.

use super::controls::Control;
use crate::physics::collision::{Options, Setup};
use crate::physics::contact::Pair;
use crate::physics::crack::CrackLaw;
use crate::physics::material::{Material, combined_modulus};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A head-on collision between a sphere and a sphere or a wall. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CollisionParams {
    /// Material of sphere 1 (the projectile).
    pub projectile: Material,
    /// Material of sphere 2 or of the wall.
    pub target: Material,
    /// Sphere 1 hits a flat wall (R₂ → ∞, m₂ → ∞) instead of sphere 2.
    pub wall: bool,
    /// Radius of sphere 1, m (default 2 µm; 20 nm – 2 cm).
    pub radius_1: f64,
    /// Radius of sphere 2, m (default 2 µm; 20 nm – 2 cm; ignored for a wall).
    pub radius_2: f64,
    /// Combined surface energy γ of the contact, J/m² (default 0.74 = 2 × 0.37 for ice;
    /// 2(γ₁γ₂)^{1/2} for the chosen materials).
    pub surface_energy: f64,
    /// Viscous relaxation time T_vis, s (default 1e-11; 1e-15 – 1e-8).
    pub t_vis: f64,
    /// Range of the surface forces z₀, m (σ₀ = γ/z₀; default 0.3 nm).
    pub z0: f64,
    /// Relaxed-to-instantaneous modulus ratio k (default 0.02).
    pub k: f64,
    /// Use Greenwood's low-speed crack fits (2.17), which were made for k = 0.02.
    pub low_speed_fit: bool,
    /// Include Thornton–Ning plasticity.
    pub plasticity: bool,
    /// Yield strength Y, Pa (default 1e8; used when `plasticity` is on).
    pub yield_strength: f64,
    /// Impact velocity, m/s (default 8; 1e-3 – 1e3).
    pub velocity: f64,
    /// Relative tolerance of the integrator (default 1e-6; smaller is more
    /// accurate and slower, see the collision benchmark).
    pub rtol: f64,
}

impl Default for CollisionParams {
    fn default() -> Self {
        CollisionParams {
            projectile: Material::water_ice(),
            target: Material::water_ice(),
            wall: false,
            radius_1: 2e-6,
            radius_2: 2e-6,
            surface_energy: 0.74,
            t_vis: 1e-11,
            z0: 3e-10,
            k: 0.02,
            low_speed_fit: true,
            plasticity: false,
            yield_strength: 1e8,
            velocity: 8.0,
            rtol: 1e-6,
        }
    }
}

impl CollisionParams {
    /// The documented parameters.
    pub fn controls(&mut self) -> Vec<Control<'_>> {
        vec![
            Control::material("projectile", "material 1", &mut self.projectile, "material of sphere 1 (Table 2.2)"),
            Control::material("target", "material 2", &mut self.target, "material of sphere 2 or of the wall"),
            Control::toggle("wall", "sphere on wall", &mut self.wall, "sphere 1 hits a flat wall of material 2"),
            Control::number(
                "radius_1",
                "radius 1",
                &mut self.radius_1,
                "m",
                (2e-8, 2e-2),
                true,
                ("µm", 1e6),
                "radius of sphere 1 (default 2 µm)",
            ),
            Control::number(
                "radius_2",
                "radius 2",
                &mut self.radius_2,
                "m",
                (2e-8, 2e-2),
                true,
                ("µm", 1e6),
                "radius of sphere 2 (default 2 µm; unused for a wall)",
            ),
            Control::number(
                "surface_energy",
                "surface energy γ",
                &mut self.surface_energy,
                "J m^-2",
                (1e-3, 10.0),
                true,
                ("J/m²", 1.0),
                "combined surface energy of the contact (2γ_L for like materials; default 0.74)",
            ),
            Control::number(
                "t_vis",
                "relaxation time T_vis",
                &mut self.t_vis,
                "s",
                (1e-15, 1e-8),
                true,
                ("s", 1.0),
                "viscous relaxation time (default 1e-11 s)",
            ),
            Control::number(
                "z0",
                "force range z₀",
                &mut self.z0,
                "m",
                (1e-10, 1e-9),
                false,
                ("nm", 1e9),
                "range of the surface forces, σ₀ = γ/z₀ (default 0.3 nm)",
            ),
            Control::number(
                "k",
                "modulus ratio k",
                &mut self.k,
                "",
                (0.005, 0.3),
                true,
                ("", 1.0),
                "relaxed to instantaneous modulus (default 0.02)",
            ),
            Control::toggle(
                "low_speed_fit",
                "low-speed crack fit",
                &mut self.low_speed_fit,
                "use Greenwood's fits (2.17) near β = 1 (made for k = 0.02; applied for k = 0.018–0.022)",
            ),
            Control::toggle("plasticity", "plasticity", &mut self.plasticity, "Thornton–Ning plastic yield (2.29)"),
            Control::number(
                "yield_strength",
                "yield strength Y",
                &mut self.yield_strength,
                "Pa",
                (1e5, 1e11),
                true,
                ("MPa", 1e-6),
                "yield strength in simple tension (default 100 MPa)",
            ),
            Control::number(
                "velocity",
                "impact velocity v",
                &mut self.velocity,
                "m s^-1",
                (1e-3, 1e3),
                true,
                ("m/s", 1.0),
                "relative velocity at first contact (default 8 m/s)",
            ),
            Control::number(
                "rtol",
                "solver tolerance",
                &mut self.rtol,
                "",
                (1e-12, 1e-3),
                true,
                ("", 1.0),
                "relative tolerance of the integrator (default 1e-6)",
            ),
        ]
    }

    /// Reduced radius R, m.
    pub fn reduced_radius(&self) -> f64 {
        if self.wall { self.radius_1 } else { 1.0 / (1.0 / self.radius_1 + 1.0 / self.radius_2) }
    }

    /// Reduced mass m*, kg.
    pub fn reduced_mass(&self) -> f64 {
        let m1 = self.projectile.density * 4.0 / 3.0 * PI * self.radius_1.powi(3);
        if self.wall {
            m1
        } else {
            let m2 = self.target.density * 4.0 / 3.0 * PI * self.radius_2.powi(3);
            m1 * m2 / (m1 + m2)
        }
    }

    /// The model setup. The bulk dissipation constant A = T_vis/ν² uses the
    /// mean Poisson ratio of the two materials (exact for like materials).
    pub fn setup(&self) -> Setup {
        Setup {
            pair: Pair {
                modulus: combined_modulus(&self.projectile, &self.target),
                radius: self.reduced_radius(),
                mass: self.reduced_mass(),
                surface_energy: self.surface_energy,
            },
            t_vis: self.t_vis,
            poisson_ratio: 0.5 * (self.projectile.poisson_ratio + self.target.poisson_ratio),
            z0: self.z0,
            crack: CrackLaw { k: self.k, low_speed_fit: self.low_speed_fit },
            yield_strength: self.plasticity.then_some(self.yield_strength),
        }
    }

    /// Integrator options at the chosen tolerance.
    pub fn options(&self) -> Options {
        Options { rtol: self.rtol, ..Options::default() }
    }
}
