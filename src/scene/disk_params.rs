//! Parameters shared by the disk scenes (thesis ch. 4–5): the gas disk and
//! the monomers.

use super::controls::Control;
use crate::physics::aggregate::Monomer;
use crate::physics::disk::{GasDisk, Profile};
use serde::{Deserialize, Serialize};

/// A gas disk and its dust monomers. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DiskParams {
    /// "mmsn" (4.1) or "power-law" (5.1).
    pub profile: String,
    /// Disk mass for the power law, solar masses (default 0.01).
    pub disk_mass: f64,
    /// Characteristic radius R_c for the power law, AU (default 30).
    pub r_c: f64,
    /// Power-law slope γ (default 1).
    pub slope: f64,
    /// Halve the temperature (cold disk).
    pub cold: bool,
    /// Turbulence strength α (default 10⁻³).
    pub alpha: f64,
    /// Dust-to-gas ratio Z₀ (default 0.01).
    pub metallicity: f64,
    /// Monomer radius a₀, m (default 0.1 µm).
    pub monomer_radius: f64,
    /// Icy monomers (ρ₀ = 1.4 g cm⁻³) or silicate (2.6 g cm⁻³).
    pub icy: bool,
}

impl Default for DiskParams {
    fn default() -> Self {
        DiskParams {
            profile: "mmsn".into(),
            disk_mass: 0.01,
            r_c: 30.0,
            slope: 1.0,
            cold: false,
            alpha: 1e-3,
            metallicity: 0.01,
            monomer_radius: 1e-7,
            icy: true,
        }
    }
}

impl DiskParams {
    /// The documented parameters.
    pub fn controls(&mut self) -> Vec<Control<'_>> {
        vec![
            Control::choice(
                "profile",
                "gas disk",
                &mut self.profile,
                vec![("mmsn", "MMSN (4.1)"), ("power-law", "truncated power law (5.1)")],
                "surface density profile",
            ),
            Control::number(
                "disk_mass",
                "disk mass",
                &mut self.disk_mass,
                "M_sun",
                (1e-4, 0.5),
                true,
                ("M_sun", 1.0),
                "power-law disk mass",
            ),
            Control::number(
                "r_c",
                "R_c",
                &mut self.r_c,
                "AU",
                (5.0, 300.0),
                true,
                ("AU", 1.0),
                "power-law characteristic radius",
            ),
            Control::number("slope", "slope γ", &mut self.slope, "", (0.5, 1.9), false, ("", 1.0), "power-law slope"),
            Control::toggle("cold", "cold disk (T/2)", &mut self.cold, "halve the temperature"),
            Control::number(
                "alpha",
                "turbulence α",
                &mut self.alpha,
                "",
                (1e-6, 1e-1),
                true,
                ("", 1.0),
                "Shakura–Sunyaev α",
            ),
            Control::number(
                "metallicity",
                "dust-to-gas Z₀",
                &mut self.metallicity,
                "",
                (1e-4, 0.1),
                true,
                ("", 1.0),
                "Σ_d/Σ_g",
            ),
            Control::number(
                "monomer_radius",
                "monomer radius a₀",
                &mut self.monomer_radius,
                "m",
                (1e-8, 1e-5),
                true,
                ("µm", 1e6),
                "radius of the monomers",
            ),
            Control::toggle("icy", "icy monomers", &mut self.icy, "ice (1.4 g/cm³) or silicate (2.6 g/cm³)"),
        ]
    }

    /// The gas disk.
    pub fn disk(&self) -> GasDisk {
        let profile = if self.profile == "power-law" {
            Profile::TruncatedPowerLaw { mass: self.disk_mass, r_c: self.r_c, slope: self.slope }
        } else {
            Profile::Mmsn
        };
        GasDisk { profile, cold: self.cold, alpha: self.alpha, metallicity: self.metallicity }
    }

    /// The monomers.
    pub fn monomer(&self) -> Monomer {
        Monomer { radius: self.monomer_radius, density: if self.icy { 1400.0 } else { 2600.0 }, icy: self.icy }
    }
}

/// The control of a local scene's disk radius, AU (0.5–300 AU); `meaning`
/// says what sits there.
pub fn radius_control<'a>(value: &'a mut f64, meaning: &'static str) -> Control<'a> {
    Control::number("radius_au", "disk radius", value, "AU", (0.5, 300.0), true, ("AU", 1.0), meaning)
}
