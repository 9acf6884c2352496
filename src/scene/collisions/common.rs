//! Parameters shared by the collision scenes: the two bodies, the contact and
//! the numerics.

use crate::figure::{Series, Style};
use crate::physics::collision::{Options, Setup};
use crate::physics::contact::Pair;
use crate::physics::crack::{CrackLaw, Relation};
use crate::physics::experiments::Bounded;
use crate::physics::material::{Bodies, Material, TwoBodies};
use crate::scene::quantities;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};

/// A head-on collision between a sphere and a sphere or a wall. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct CollisionParams {
    /// material of sphere 1 (Table 2.2)
    #[param(label = "material 1", default = Material::water_ice())]
    pub projectile: Material,
    /// material of sphere 2 or of the wall
    #[param(label = "material 2", default = Material::water_ice())]
    pub target: Material,
    /// sphere 1 hits a flat wall of material 2
    #[param(label = "sphere on wall", default = false)]
    pub wall: bool,
    /// radius of sphere 1
    #[param(label = "radius 1", unit = "m", shown("µm", 1e6), range(2e-8, 2e-2), log, default = 2e-6)]
    pub radius_1: f64,
    /// radius of sphere 2 (unused for a wall)
    #[param(label = "radius 2", unit = "m", shown("µm", 1e6), range(2e-8, 2e-2), log, default = 2e-6)]
    pub radius_2: f64,
    /// combined surface energy of the contact (2γ_L for like materials; default 0.74)
    ///
    /// Combined surface energy γ of the contact, J/m² (default 0.74 = 2 × 0.37 for ice;
    /// 2(γ₁γ₂)^{1/2} for the chosen materials).
    #[param(quantity = quantities::surface_energy, default = 0.74)]
    pub surface_energy: f64,
    /// viscous relaxation time
    #[param(label = "relaxation time T_vis", unit = "s", range(1e-15, 1e-8), log, default = 1e-11)]
    pub t_vis: f64,
    /// range of the surface forces, σ₀ = γ/z₀
    #[param(quantity = quantities::force_range, default = 3e-10)]
    pub z0: f64,
    /// relaxed to instantaneous modulus
    #[param(label = "modulus ratio k", range(0.005, 0.3), log, default = 0.02)]
    pub k: f64,
    /// crack speed ȧ(β): the exact Dugdale-zone relation of the three-element solid at any k, or the thesis's (2.16) with Greenwood's fits (2.17) (made for k = 0.02; applied for k = 0.018–0.022), or (2.16) alone
    ///
    /// Crack-speed relation, a key of [`Relation::CHOICES`].
    /// Files written before the choice existed say `low_speed_fit: true`
    /// (the thesis's law) or `false` ((2.16) alone), and keep their law.
    #[serde(alias = "low_speed_fit", deserialize_with = "crack_law_or_legacy_switch")]
    #[param(label = "crack law")]
    pub crack_law: CrackLawChoice,
    /// Thornton–Ning plastic yield (2.29)
    #[param(label = "plasticity", default = false)]
    pub plasticity: bool,
    /// yield strength in simple tension
    #[param(label = "yield strength Y", unit = "Pa", shown("MPa", 1e-6), range(1e5, 1e11), log, default = 1e8)]
    pub yield_strength: f64,
    /// relative velocity at first contact
    #[param(label = "impact velocity v", unit = "m s^-1", shown("m/s", 1.0), range(1e-3, 1e3), log, default = 8.0)]
    pub velocity: f64,
    /// relative tolerance of the integrator
    ///
    /// Relative tolerance of the integrator (default 1e-6; smaller is more
    /// accurate and slower, see the collision benchmark).
    #[param(quantity = quantities::solver_tolerance, default = 1e-6)]
    pub rtol: f64,
}

impl CollisionParams {
    /// After a material was picked: γ = 2(γ₁γ₂)^{1/2} of the chosen materials.
    pub fn material_changed(&mut self) {
        self.surface_energy = crate::physics::material::combined_surface_energy(&self.projectile, &self.target);
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
        CrackLaw { k: self.k, relation: self.crack_law.relation() }
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
fn crack_law_or_legacy_switch<'de, D: serde::Deserializer<'de>>(d: D) -> Result<CrackLawChoice, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum KeyOrSwitch {
        Switch(bool),
        Key(String),
    }
    Ok(match KeyOrSwitch::deserialize(d)? {
        KeyOrSwitch::Switch(true) => CrackLawChoice::Thesis,
        KeyOrSwitch::Switch(false) => CrackLawChoice::General,
        KeyOrSwitch::Key(k) => CrackLawChoice::from_key(&k).ok_or_else(|| {
            <D::Error as serde::de::Error>::custom(crate::scene::schema::unknown_option(&k, CrackLawChoice::OPTIONS))
        })?,
    })
}

/// The crack-speed relation of a collision, as the schema's choice (files
/// and links keep its key: "full", "thesis", "2.16").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum CrackLawChoice {
    /// [`Relation::Full`].
    #[default]
    #[choice(key = "full", label = "full relation (Dugdale zone, any k)")]
    Full,
    /// [`Relation::Thesis`].
    #[choice(key = "thesis", label = "thesis: (2.16) with (2.17) at k = 0.02")]
    Thesis,
    /// [`Relation::General`].
    #[choice(key = "2.16", label = "(2.16) alone")]
    General,
}

impl CrackLawChoice {
    /// The physics' relation.
    pub fn relation(self) -> Relation {
        match self {
            CrackLawChoice::Full => Relation::Full,
            CrackLawChoice::Thesis => Relation::Thesis,
            CrackLawChoice::General => Relation::General,
        }
    }
}
