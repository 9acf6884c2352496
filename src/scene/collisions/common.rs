//! Parameters shared by the collision scenes: the two bodies, the contact and
//! the numerics.

use crate::figure::{Series, Style};
use crate::physics::collision::{Options, Setup};
use crate::physics::contact::Pair;
use crate::physics::crack::{CrackLaw, Relation};
use crate::physics::experiments::Bounded;
use crate::physics::material::{Bodies, Material, TwoBodies};
use crate::scene::controls::Control;
use crate::scene::quantities;
use serde::{Deserialize, Serialize};

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
    /// Crack-speed relation, a key of [`Relation::CHOICES`] (default "full").
    /// Files written before the choice existed say `low_speed_fit: true`
    /// (the thesis's law) or `false` ((2.16) alone), and keep their law.
    #[serde(alias = "low_speed_fit", deserialize_with = "crack_law_or_legacy_switch")]
    pub crack_law: String,
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
            crack_law: "full".into(),
            plasticity: false,
            yield_strength: 1e8,
            velocity: 8.0,
            rtol: 1e-6,
        }
    }
}

impl CollisionParams {
    /// After a material was picked: γ = 2(γ₁γ₂)^{1/2} of the chosen materials.
    pub fn material_changed(&mut self) {
        self.surface_energy = crate::physics::material::combined_surface_energy(&self.projectile, &self.target);
    }

    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        vec![
            Control::material("projectile", "material 1", &mut self.projectile)
                .default(d.projectile.name.clone())
                .doc("material of sphere 1 (Table 2.2)"),
            Control::material("target", "material 2", &mut self.target)
                .default(d.target.name.clone())
                .doc("material of sphere 2 or of the wall"),
            Control::toggle("wall", "sphere on wall", &mut self.wall)
                .default(d.wall)
                .doc("sphere 1 hits a flat wall of material 2"),
            Control::number("radius_1", "radius 1", &mut self.radius_1)
                .default(d.radius_1)
                .unit("m")
                .shown("µm", 1e6)
                .range(2e-8, 2e-2)
                .log()
                .doc("radius of sphere 1 (default 2 µm)"),
            Control::number("radius_2", "radius 2", &mut self.radius_2)
                .default(d.radius_2)
                .unit("m")
                .shown("µm", 1e6)
                .range(2e-8, 2e-2)
                .log()
                .doc("radius of sphere 2 (default 2 µm; unused for a wall)"),
            quantities::surface_energy(&mut self.surface_energy)
                .default(d.surface_energy)
                .doc("combined surface energy of the contact (2γ_L for like materials; default 0.74)"),
            Control::number("t_vis", "relaxation time T_vis", &mut self.t_vis)
                .default(d.t_vis)
                .unit("s")
                .range(1e-15, 1e-8)
                .log()
                .doc("viscous relaxation time (default 1e-11 s)"),
            quantities::force_range(&mut self.z0)
                .default(d.z0)
                .doc("range of the surface forces, σ₀ = γ/z₀ (default 0.3 nm)"),
            Control::number("k", "modulus ratio k", &mut self.k)
                .default(d.k)
                .range(0.005, 0.3)
                .log()
                .doc("relaxed to instantaneous modulus (default 0.02)"),
            Control::choice("crack_law", "crack law", &mut self.crack_law, Relation::CHOICES.to_vec())
                .default(d.crack_law.clone())
                .doc("crack speed ȧ(β): the exact Dugdale-zone relation of the three-element solid at any k, or the thesis's (2.16) with Greenwood's fits (2.17) (made for k = 0.02; applied for k = 0.018–0.022), or (2.16) alone"),
            Control::toggle("plasticity", "plasticity", &mut self.plasticity)
                .default(d.plasticity)
                .doc("Thornton–Ning plastic yield (2.29)"),
            Control::number("yield_strength", "yield strength Y", &mut self.yield_strength)
                .default(d.yield_strength)
                .unit("Pa")
                .shown("MPa", 1e-6)
                .range(1e5, 1e11)
                .log()
                .doc("yield strength in simple tension (default 100 MPa)"),
            Control::number("velocity", "impact velocity v", &mut self.velocity)
                .default(d.velocity)
                .unit("m s^-1")
                .shown("m/s", 1.0)
                .range(1e-3, 1e3)
                .log()
                .doc("relative velocity at first contact (default 8 m/s)"),
            quantities::solver_tolerance(&mut self.rtol)
                .default(d.rtol)
                .doc("relative tolerance of the integrator (default 1e-6)"),
        ]
    }

    /// The two bodies: sphere 1 against sphere 2 or the wall.
    pub fn bodies(&self) -> TwoBodies {
        let bodies = if self.wall {
            Bodies::Wall { radius: self.radius_1 }
        } else {
            Bodies::Spheres { r1: self.radius_1, r2: self.radius_2 }
        };
        TwoBodies::new(&self.projectile, &self.target, bodies)
    }

    /// Reduced radius R, m.
    pub fn reduced_radius(&self) -> f64 {
        self.bodies().radius
    }

    /// Reduced mass m*, kg.
    pub fn reduced_mass(&self) -> f64 {
        self.bodies().mass
    }

    /// The model setup. The bulk dissipation constant A = T_vis/ν² uses the
    /// mean Poisson ratio of the two materials (exact for like materials).
    pub fn setup(&self) -> Setup {
        let two = self.bodies();
        Setup {
            pair: Pair {
                modulus: two.modulus,
                radius: two.radius,
                mass: two.mass,
                surface_energy: self.surface_energy,
            },
            t_vis: self.t_vis,
            poisson_ratio: two.poisson_ratio,
            z0: self.z0,
            crack: self.crack_law(),
            yield_strength: self.plasticity.then_some(self.yield_strength),
        }
    }

    /// The crack law (the full relation for an unknown key, which validation rejects).
    pub fn crack_law(&self) -> CrackLaw {
        CrackLaw { k: self.k, relation: Relation::from_key(&self.crack_law).unwrap_or_default() }
    }

    /// Integrator options at the chosen tolerance.
    pub fn options(&self) -> Options {
        Options { rtol: self.rtol, ..Options::default() }
    }
}

/// Reference curves of Hertz and JKR theory for one pair, in display units
/// (nm, µN): a(δ) and F(δ), up to contact radius `a_max`.
pub fn reference_curves(pair: &Pair, a_max: f64) -> [Series; 4] {
    let n = 200;
    let mut hertz_a = Vec::new();
    let mut hertz_f = Vec::new();
    let mut jkr_a = Vec::new();
    let mut jkr_f = Vec::new();
    for i in 0..=n {
        let a = a_max * i as f64 / n as f64;
        let d_h = a * a / pair.radius;
        hertz_a.push([d_h * 1e9, a * 1e9]);
        hertz_f.push([d_h * 1e9, pair.hertz_force(a) * 1e6]);
        if i > 0 {
            let d = pair.jkr_approach(a);
            jkr_a.push([d * 1e9, a * 1e9]);
            jkr_f.push([d * 1e9, pair.jkr_force(a) * 1e6]);
        }
    }
    [
        Series::new("Hertz", hertz_a, Style::Dashed, 6),
        Series::new("JKR", jkr_a, Style::Dashed, 1),
        Series::new("Hertz", hertz_f, Style::Dashed, 6),
        Series::new("JKR", jkr_f, Style::Dashed, 1),
    ]
}

/// A fitted value as text, e.g. "0.13 (+0.02 −0.02) J/m²" or "> 67 MPa".
pub fn describe(b: &Bounded, unit: &str, scale: f64) -> String {
    use crate::figure::human as t;
    match *b {
        Bounded::Value { best, plus, minus } => {
            format!("{} (+{} −{}) {unit}", t(best * scale), t(plus * scale), t(minus * scale))
        }
        Bounded::Above(x) => format!("> {} {unit}", t(x * scale)),
        Bounded::Below(x) => format!("< {} {unit}", t(x * scale)),
        Bounded::Fixed(x) => format!("{} {unit} (held fixed)", t(x * scale)),
        Bounded::Undetermined { best } => format!("undetermined (best point {} {unit})", t(best * scale)),
    }
}

/// Reads `crack_law`: a key, or the switch `low_speed_fit` of older files
/// (true: the thesis's law; false: (2.16) alone).
fn crack_law_or_legacy_switch<'de, D: serde::Deserializer<'de>>(d: D) -> Result<String, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum KeyOrSwitch {
        Switch(bool),
        Key(String),
    }
    Ok(match KeyOrSwitch::deserialize(d)? {
        KeyOrSwitch::Switch(true) => Relation::Thesis.key().into(),
        KeyOrSwitch::Switch(false) => Relation::General.key().into(),
        KeyOrSwitch::Key(k) => k,
    })
}
