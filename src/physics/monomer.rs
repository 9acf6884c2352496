//! The monomers aggregates are built of, and what their contact sets for
//! every larger scale (thesis Sects. 1.2, 3.2, 4.2.3–4.2.4, App. 5.C).
//!
//! Two monomers of radius a₀ touch in a JKR contact of reduced radius
//! R = a₀/2 and reduced mass m₀/2 (ch. 2). That contact sets the energy to
//! break it, E_break ∝ (γ⁵R⁴/E*²)^{1/3} (1.24); the sticking velocity of two
//! monomers (the collision model of ch. 2); and the rolling energy
//! E_roll = 6πγRξ (1.25, 3.14) through the critical displacement ξ. Three
//! laws for ξ are offered:
//! - **calibrated** (5.26), the default: E_roll = (a₀/1 µm)^{5/3} × 1.8 × 10⁻⁷ erg
//!   (ice) or 8.5 × 10⁻⁹ erg (silicate). It is the ch. 3 law calibrated to
//!   Gundlach et al.'s measurement; a surface energy other than the
//!   material's scales it as the ch. 3 law does, E_roll ∝ γ^{4/3} at fixed Δγ/γ;
//! - **contact** (ch. 3): ξ_crit = (a_eq/12)(Δγ/γ) (3.16) with a_eq the JKR
//!   equilibrium radius of the pair, so E_roll ∝ a₀^{5/3};
//! - **Dominik & Tielens** (1995): a fixed ξ_crit (0.3 nm), a size-independent
//!   rolling force and E_roll ∝ a₀.
//!
//! The aggregate thresholds follow: compaction starts at 3bE_roll, the
//! compressive strength is E_roll φ³/a₀³ (4.15) and the fragmentation
//! velocity is v_frag = 20 (E_break/m₀)^{1/2} (4.12), written as the printed
//! 80 m s⁻¹ (a₀/0.1 µm)^{-5/6} for 0.1 µm ice and scaled by E_break/m₀ from
//! there. SI units throughout.

use super::collision::{Options, Setup, sticking_velocity};
use super::contact::Pair;
use super::crack::CrackLaw;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How the rolling energy of two monomers depends on their contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub enum RollingLaw {
    /// Eq. (5.26): the ch. 3 scaling calibrated to Gundlach et al. (2011).
    #[default]
    Calibrated,
    /// Ch. 3: ξ_crit = (a_eq/12)(Δγ/γ) (3.16) with the given Δγ/γ.
    Contact {
        /// Adhesion hysteresis Δγ/γ, dimensionless.
        hysteresis: f64,
    },
    /// Dominik & Tielens (1995): a fixed critical displacement ξ_crit, m.
    DominikTielens {
        /// Critical rolling displacement, m.
        xi: f64,
    },
}

/// Prefactor b of the collisional-compaction threshold 3bE_roll (App. 5.C).
pub const COMPACTION_B: f64 = 0.15;

/// Gundlach et al. (2011): rolling energy 1.8 × 10⁻⁷ erg of ice grains of
/// radius ~1.5 µm, J (Sect. 4.2.4).
pub const GUNDLACH_ROLLING_ENERGY: f64 = 1.8e-14;
/// Radius of Gundlach et al.'s ice grains, m.
pub const GUNDLACH_RADIUS: f64 = 1.5e-6;

/// The monomers aggregates are built of.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Monomer {
    /// Radius a₀, m.
    pub radius: f64,
    /// Material density ρ₀, kg m⁻³ (1400 for ice, 2600 for silicate, as in ch. 4–5).
    pub density: f64,
    /// Icy (true) or silicate monomers: the elastic constants of Tables 2.2 and
    /// 3.1 and the prefactor of (5.26).
    pub icy: bool,
    /// Combined surface energy γ of two monomers in contact (2γ_L), J m⁻².
    #[serde(default = "ice_surface_energy")]
    pub surface_energy: f64,
    /// The rolling-energy law.
    #[serde(default)]
    pub rolling: RollingLaw,
}

fn ice_surface_energy() -> f64 {
    ICE_SURFACE_ENERGY
}

/// Combined surface energy of two ice surfaces, 2 × 0.37 J m⁻² (Table 2.2).
pub const ICE_SURFACE_ENERGY: f64 = 0.74;
/// Combined surface energy of two silicate surfaces, 2 × 0.025 J m⁻² (Table 3.1).
pub const SILICATE_SURFACE_ENERGY: f64 = 0.05;

impl Monomer {
    /// 0.1 µm water-ice monomers of ch. 4 with the calibrated rolling law.
    pub fn ice() -> Monomer {
        Monomer {
            radius: 1e-7,
            density: 1400.0,
            icy: true,
            surface_energy: ICE_SURFACE_ENERGY,
            rolling: RollingLaw::Calibrated,
        }
    }

    /// Monomer mass m₀, kg.
    pub fn mass(&self) -> f64 {
        4.0 / 3.0 * PI * self.density * self.radius.powi(3)
    }

    /// Young's modulus and Poisson ratio: water ice (7 GPa, 0.25, Table 2.2)
    /// or silicate (54 GPa, 0.17, Table 3.1).
    pub fn elastic_constants(&self) -> (f64, f64) {
        if self.icy { (7e9, 0.25) } else { (54e9, 0.17) }
    }

    /// The material's own combined surface energy (Tables 2.2, 3.1), J m⁻².
    pub fn material_surface_energy(&self) -> f64 {
        if self.icy { ICE_SURFACE_ENERGY } else { SILICATE_SURFACE_ENERGY }
    }

    /// The contact of two monomers: E*, R = a₀/2, m* = m₀/2 and γ.
    pub fn pair(&self) -> Pair {
        let (e, nu) = self.elastic_constants();
        Pair {
            modulus: e / (2.0 * (1.0 - nu * nu)),
            radius: self.radius / 2.0,
            mass: self.mass() / 2.0,
            surface_energy: self.surface_energy,
        }
    }

    /// Rolling energy of (5.26) at the material's surface energy, J.
    pub fn calibrated_rolling_energy(&self) -> f64 {
        let e1 = if self.icy { 1.8e-14 } else { 8.5e-16 };
        e1 * (self.radius / 1e-6).powf(5.0 / 3.0)
    }

    /// The critical rolling displacement ξ_crit of the chosen law, m.
    pub fn rolling_displacement(&self) -> f64 {
        let pair = self.pair();
        match self.rolling {
            RollingLaw::Calibrated => self.rolling_energy() / (6.0 * PI * pair.surface_energy * pair.radius),
            RollingLaw::Contact { hysteresis } => pair.jkr_equilibrium_radius() / 12.0 * hysteresis,
            RollingLaw::DominikTielens { xi } => xi,
        }
    }

    /// Rolling energy E_roll of two monomers under the chosen law, J.
    pub fn rolling_energy(&self) -> f64 {
        match self.rolling {
            RollingLaw::Calibrated => {
                let g = self.surface_energy / self.material_surface_energy();
                // Exactly (5.26) at the material's surface energy.
                if g == 1.0 {
                    self.calibrated_rolling_energy()
                } else {
                    self.calibrated_rolling_energy() * g.powf(4.0 / 3.0)
                }
            }
            RollingLaw::Contact { .. } | RollingLaw::DominikTielens { .. } => {
                self.pair().roll_energy(self.rolling_displacement())
            }
        }
    }

    /// Impact energy above which a collision compacts, 3bE_roll (b = 0.15), J.
    pub fn compaction_energy(&self) -> f64 {
        3.0 * COMPACTION_B * self.rolling_energy()
    }

    /// Rolling force F_roll = E_roll/R = 6πγξ_crit (3.14 with F = M/R), N.
    pub fn rolling_force(&self) -> f64 {
        self.rolling_energy() / self.pair().radius
    }

    /// Energy to break the contact of two monomers, E_break (1.24), J.
    pub fn break_energy(&self) -> f64 {
        self.pair().break_energy()
    }

    /// The Δγ/γ for which the ch. 3 law gives the rolling energy of (5.26)
    /// (the same at every radius, both laws scaling as a₀^{5/3}).
    pub fn hysteresis_of_calibration(&self) -> f64 {
        let pair = self.pair();
        self.rolling_energy() / pair.roll_energy(pair.jkr_equilibrium_radius() / 12.0)
    }

    /// Catastrophic fragmentation velocity v_frag = 20 (E_break/m₀)^{1/2}
    /// (4.12), m s⁻¹, normalised to the printed 80 m s⁻¹ for 0.1 µm ice at
    /// γ = 0.74 J m⁻²: 80 (a₀/0.1 µm)^{-5/6} for ice at its own γ.
    pub fn fragmentation_velocity(&self) -> f64 {
        let reference = Monomer::ice();
        if self.icy && self.surface_energy == ICE_SURFACE_ENERGY && self.density == reference.density {
            // The printed power law itself, exact for the published numbers.
            80.0 * (self.radius / 1e-7).powf(-5.0 / 6.0)
        } else {
            let per_mass = |m: &Monomer| m.break_energy() / m.mass();
            80.0 * (per_mass(self) / per_mass(&reference)).sqrt()
        }
    }

    /// Elastic JKR sticking velocity of two monomers, v_c of (2.25), m s⁻¹.
    pub fn jkr_sticking_velocity(&self) -> f64 {
        self.pair().jkr_sticking_velocity()
    }

    /// Sticking velocity of two monomers in the viscoelastic collision model
    /// of ch. 2 (the reference set's T_vis = 10⁻¹¹ s, z₀ = 0.3 nm, k = 0.02),
    /// to relative precision `rel`, m s⁻¹.
    pub fn sticking_velocity(&self, rel: f64) -> Result<f64, super::PhysicsError> {
        let (_, nu) = self.elastic_constants();
        let setup = Setup {
            pair: self.pair(),
            t_vis: 1e-11,
            poisson_ratio: nu,
            z0: 3e-10,
            crack: CrackLaw::thesis(0.02),
            yield_strength: None,
        };
        sticking_velocity(&setup, &Options::default(), rel)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slope(law: RollingLaw) -> f64 {
        let at = |a: f64| Monomer { radius: a, rolling: law, ..Monomer::ice() }.rolling_energy();
        (at(1e-6) / at(1e-7)).log10()
    }

    #[test]
    fn the_three_laws_scale_as_published() {
        assert!((slope(RollingLaw::Calibrated) - 5.0 / 3.0).abs() < 1e-12);
        assert!((slope(RollingLaw::Contact { hysteresis: 0.5 }) - 5.0 / 3.0).abs() < 1e-12);
        assert!((slope(RollingLaw::DominikTielens { xi: 3e-10 }) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn calibrated_law_is_eq_5_26_and_the_contact_law_meets_it() {
        let m = Monomer::ice();
        // 3.9 × 10⁻⁹ erg for 0.1 µm ice (Sect. 4.2.4: "4 × 10⁻⁹ erg").
        assert!((m.rolling_energy() / 3.878e-16 - 1.0).abs() < 1e-3, "{}", m.rolling_energy());
        let h = m.hysteresis_of_calibration();
        assert!(h > 0.3 && h < 0.4, "{h}");
        for a in [1e-8, 1e-7, 1.5e-6] {
            let cal = Monomer { radius: a, ..m };
            let contact = Monomer { rolling: RollingLaw::Contact { hysteresis: h }, ..cal };
            assert!((contact.rolling_energy() / cal.rolling_energy() - 1.0).abs() < 1e-12);
        }
        // The surface energy enters the calibrated law as γ^{4/3}.
        let doubled = Monomer { surface_energy: 2.0 * ICE_SURFACE_ENERGY, ..m };
        assert!((doubled.rolling_energy() / m.rolling_energy() - 2f64.powf(4.0 / 3.0)).abs() < 1e-12);
    }

    #[test]
    fn fragmentation_velocity_follows_eq_4_12() {
        let m = Monomer::ice();
        assert_eq!(m.fragmentation_velocity(), 80.0);
        let big = Monomer { radius: 1e-6, ..m };
        assert!((big.fragmentation_velocity() - 80.0 * 10f64.powf(-5.0 / 6.0)).abs() < 1e-9);
        // Scaled through E_break/m₀, the same power law: γ nudged by 1e-9.
        let nudged = Monomer { radius: 1e-6, surface_energy: ICE_SURFACE_ENERGY * (1.0 + 1e-9), ..m };
        assert!((nudged.fragmentation_velocity() / big.fragmentation_velocity() - 1.0).abs() < 1e-8);
        // v ∝ γ^{5/6}.
        let strong = Monomer { surface_energy: 2.0 * ICE_SURFACE_ENERGY, ..m };
        assert!((strong.fragmentation_velocity() / 80.0 - 2f64.powf(5.0 / 6.0)).abs() < 1e-9);
    }

    #[test]
    fn viscous_losses_raise_the_sticking_velocity_above_jkr() {
        // Micron monomers: finite, above the elastic JKR value.
        let m = Monomer { radius: 2e-6, ..Monomer::ice() };
        let v = m.sticking_velocity(1e-3).expect("sticking velocity");
        assert!(v > m.jkr_sticking_velocity() && v < 100.0, "{v} vs {}", m.jkr_sticking_velocity());
        // 0.1 µm monomers with the reference T_vis stick at every speed the
        // search covers: the bulk loss A/t_H exceeds the rebound.
        let small = Monomer::ice().sticking_velocity(1e-3).expect("sticking velocity");
        assert!(small > 1e3, "{small}");
    }
}
