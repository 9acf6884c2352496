//! The monomer card: the monomer every aggregate scene shares (radius,
//! material, surface energy, rolling law) and what it sets at every scale.
//! Scenes hold the card's values in their disk parameters
//! ([`DiskParams`](super::disk::common::DiskParams)); the registry reads and
//! writes them by key ([`MONOMER_KEYS`]) so that the window can link the card
//! across scenes and the command line can set it with `--set`. This module
//! imports no scene: the disk parameters build their monomer through it.

use super::controls::DefaultValue;
use super::core::Scalar;
use super::schema::Choice;
use crate::physics::monomer::{ICE_SURFACE_ENERGY, Monomer, RollingLaw, SILICATE_SURFACE_ENERGY};

/// The law of the monomers' rolling energy E_roll.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum RollingEnergyLaw {
    /// The thesis's calibrated law (5.26), ∝ a₀^{5/3}γ^{4/3}.
    #[default]
    #[choice(key = "calibrated", label = "calibrated (5.26)")]
    Calibrated,
    /// The ch. 3 contact, 6πγRξ_crit with ξ_crit from the adhesion hysteresis (3.16).
    #[choice(key = "contact", label = "ch. 3 contact (3.16)")]
    Contact,
    /// Dominik & Tielens with a fixed ξ_crit.
    #[choice(key = "dominik-tielens", label = "Dominik & Tielens")]
    DominikTielens,
}

/// The keys of the monomer card: the parameters every aggregate scene shares.
pub const MONOMER_KEYS: [&str; 7] =
    ["monomer_radius", "icy", "surface_energy_ice", "surface_energy_silicate", "rolling_law", "hysteresis", "xi_crit"];

/// The values of a scene's monomer card, in the order of [`MONOMER_KEYS`].
pub type Card = Vec<DefaultValue>;

/// The card's values, one field per key of [`MONOMER_KEYS`] (in that
/// order; the meaning and default of each is documented on
/// [`DiskParams`](super::disk::common::DiskParams)).
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// `monomer_radius`: a₀, m.
    pub radius: f64,
    /// `icy`: ice rather than silicate.
    pub icy: bool,
    /// `surface_energy_ice`: γ of two icy monomers, J m⁻².
    pub surface_energy_ice: f64,
    /// `surface_energy_silicate`: γ of two silicate monomers, J m⁻².
    pub surface_energy_silicate: f64,
    /// `rolling_law`: the law of E_roll.
    pub rolling_law: RollingEnergyLaw,
    /// `hysteresis`: Δγ/γ of the ch. 3 law.
    pub hysteresis: f64,
    /// `xi_crit`: ξ_crit of the Dominik & Tielens law, m.
    pub xi_crit: f64,
}

impl Default for Spec {
    fn default() -> Self {
        Spec {
            radius: 1e-7,
            icy: true,
            surface_energy_ice: ICE_SURFACE_ENERGY,
            surface_energy_silicate: SILICATE_SURFACE_ENERGY,
            rolling_law: RollingEnergyLaw::Calibrated,
            hysteresis: 0.5,
            xi_crit: 3e-10,
        }
    }
}

impl Spec {
    /// The values of `card` over the defaults; a value of the wrong kind is
    /// left at its default.
    pub fn of_card(card: &Card) -> Spec {
        let mut s = Spec::default();
        for (key, value) in MONOMER_KEYS.iter().zip(card) {
            match (*key, value) {
                ("monomer_radius", DefaultValue::Number(x)) => s.radius = *x,
                ("icy", DefaultValue::Toggle(x)) => s.icy = *x,
                ("surface_energy_ice", DefaultValue::Number(x)) => s.surface_energy_ice = *x,
                ("surface_energy_silicate", DefaultValue::Number(x)) => s.surface_energy_silicate = *x,
                ("rolling_law", DefaultValue::Text(x)) => {
                    if let Some(law) = RollingEnergyLaw::from_key(x) {
                        s.rolling_law = law;
                    }
                }
                ("hysteresis", DefaultValue::Number(x)) => s.hysteresis = *x,
                ("xi_crit", DefaultValue::Number(x)) => s.xi_crit = *x,
                _ => {}
            }
        }
        s
    }

    /// The monomer.
    pub fn monomer(&self) -> Monomer {
        let surface_energy = if self.icy { self.surface_energy_ice } else { self.surface_energy_silicate };
        monomer(self.radius, self.icy, surface_energy, self.rolling_law, self.hysteresis, self.xi_crit)
    }
}

/// The monomer of radius `radius` (m), icy or silicate, with the combined
/// `surface_energy` (J m⁻²) and the rolling law `rolling_law` with its
/// `hysteresis` or `xi_crit`.
pub fn monomer(
    radius: f64,
    icy: bool,
    surface_energy: f64,
    rolling_law: RollingEnergyLaw,
    hysteresis: f64,
    xi_crit: f64,
) -> Monomer {
    let rolling = match rolling_law {
        RollingEnergyLaw::Contact => RollingLaw::Contact { hysteresis },
        RollingEnergyLaw::DominikTielens => RollingLaw::DominikTielens { xi: xi_crit },
        RollingEnergyLaw::Calibrated => RollingLaw::Calibrated,
    };
    Monomer { radius, density: if icy { 1400.0 } else { 2600.0 }, icy, surface_energy, rolling }
}

/// The monomer the card describes.
pub fn monomer_of(card: &Card) -> Monomer {
    Spec::of_card(card).monomer()
}

/// What the monomer sets, as scalars: the rolling energy and force, the
/// critical displacement, the energy to break a contact and the
/// fragmentation velocity of (4.12). With `sticking`, also the sticking
/// velocity of two monomers in the ch. 2 collision model (a few
/// milliseconds), else only the elastic JKR one (2.25).
pub fn scalars(m: &Monomer, sticking: bool) -> Vec<Scalar> {
    let mut s = vec![
        Scalar { key: "monomer_E_roll", label: "monomer: rolling energy E_roll", value: m.rolling_energy(), unit: "J" },
        Scalar { key: "monomer_F_roll", label: "monomer: rolling force F_roll", value: m.rolling_force(), unit: "N" },
        Scalar {
            key: "monomer_xi_crit",
            label: "monomer: critical rolling displacement ξ_crit",
            value: m.rolling_displacement(),
            unit: "m",
        },
        Scalar {
            key: "monomer_E_break",
            label: "monomer: energy to break a contact E_break",
            value: m.break_energy(),
            unit: "J",
        },
        Scalar {
            key: "monomer_v_frag",
            label: "monomer: fragmentation velocity (4.12)",
            value: m.fragmentation_velocity(),
            unit: "m s^-1",
        },
        Scalar {
            key: "monomer_v_stick_jkr",
            label: "monomer: JKR sticking velocity (2.25)",
            value: m.jkr_sticking_velocity(),
            unit: "m s^-1",
        },
    ];
    if sticking && let Ok(v) = m.sticking_velocity(1e-3) {
        s.push(Scalar {
            key: "monomer_v_stick",
            label: "monomer: sticking velocity (ch. 2 model)",
            value: v,
            unit: "m s^-1",
        });
    }
    s
}
