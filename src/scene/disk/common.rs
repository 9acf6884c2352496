//! What the disk scenes (thesis ch. 4) share: the gas disk, the monomers and
//! the semi-analytical growth model.

use crate::physics::aggregate::{R_CRIT, Thresholds, TurbulenceModel};
use crate::physics::constants::{AU, YEAR};
use crate::physics::disk::{GasDisk, Profile};
use crate::physics::growth::{GrowthModel, Porosity, Track};
use crate::physics::monomer::Monomer;
use crate::scene::monomer::{self, RollingEnergyLaw};
use crate::scene::quantities;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};

/// The gas disk's surface density profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum DiskProfile {
    /// The minimum-mass solar nebula (4.1).
    #[default]
    #[choice(key = "mmsn", label = "MMSN (4.1)")]
    Mmsn,
    /// A truncated power law (5.1) of the given mass, R_c and slope.
    #[choice(key = "power-law", label = "truncated power law (5.1)")]
    PowerLaw,
}

/// A gas disk and its dust monomers. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
#[param(manual_default)]
pub struct DiskParams {
    /// surface density profile
    #[param(label = "gas disk")]
    pub profile: DiskProfile,
    /// power-law disk mass
    #[param(quantity = quantities::disk_mass)]
    pub disk_mass: f64,
    /// power-law characteristic radius
    #[param(label = "R_c", unit = "AU", range(5.0, 300.0), log)]
    pub r_c: f64,
    /// power-law slope
    #[param(label = "slope γ", range(0.5, 1.9))]
    pub slope: f64,
    /// halve the temperature
    #[param(label = "cold disk (T/2)")]
    pub cold: bool,
    /// Shakura–Sunyaev α
    #[param(label = "turbulence α", range(1e-6, 1e-1), log)]
    pub alpha: f64,
    /// Σ_d/Σ_g
    #[param(label = "dust-to-gas Z₀", range(1e-4, 0.1), log)]
    pub metallicity: f64,
    /// radius of the monomers
    #[param(label = "monomer radius a₀", unit = "m", shown("µm", 1e6), range(1e-8, 1e-5), log)]
    pub monomer_radius: f64,
    /// ice (1.4 g/cm³, E = 7 GPa) or silicate (2.6 g/cm³, E = 54 GPa)
    #[param(label = "icy monomers")]
    pub icy: bool,
    /// combined surface energy of two icy monomers (2γ_L; Table 2.2: 0.74)
    #[param(label = "surface energy γ (ice)", unit = "J m^-2", shown("J/m²", 1.0), range(0.01, 5.0), log)]
    pub surface_energy_ice: f64,
    /// combined surface energy of two silicate monomers (2γ_L; Table 3.1: 0.05)
    #[param(label = "surface energy γ (silicate)", unit = "J m^-2", shown("J/m²", 1.0), range(0.005, 5.0), log)]
    pub surface_energy_silicate: f64,
    /// calibrated (5.26) ∝ a₀^{5/3}γ^{4/3}; ch. 3 contact 6πγRξ_crit with ξ_crit = (a_eq/12)Δγ/γ; Dominik & Tielens with a fixed ξ_crit, ∝ a₀
    ///
    /// Rolling-energy law: "calibrated" (5.26, default), "contact" (ch. 3, (3.16))
    /// or "dominik-tielens" (fixed ξ_crit).
    #[param(label = "E_roll law")]
    pub rolling_law: RollingEnergyLaw,
    /// adhesion hysteresis of the ch. 3 rolling law (0.35 reproduces (5.26) for ice)
    #[param(quantity = quantities::hysteresis, label = "Δγ/γ (ch. 3 law)")]
    pub hysteresis: f64,
    /// critical rolling displacement of the Dominik & Tielens law (0.3 nm)
    #[param(label = "ξ_crit (D&T law)", unit = "m", shown("nm", 1e9), range(1e-11, 1e-8), log)]
    pub xi_crit: f64,
    /// keep this scene's monomer when another scene's changes (window only)
    #[param(label = "own monomer", style_only)]
    pub own_monomer: bool,
}

impl Default for DiskParams {
    fn default() -> Self {
        let m = monomer::Spec::default();
        DiskParams {
            profile: DiskProfile::Mmsn,
            disk_mass: 0.01,
            r_c: 30.0,
            slope: 1.0,
            cold: false,
            alpha: 1e-3,
            metallicity: 0.01,
            monomer_radius: m.radius,
            icy: m.icy,
            surface_energy_ice: m.surface_energy_ice,
            surface_energy_silicate: m.surface_energy_silicate,
            rolling_law: m.rolling_law,
            hysteresis: m.hysteresis,
            xi_crit: m.xi_crit,
            own_monomer: false,
        }
    }
}

impl DiskParams {
    /// The fragmentation velocity: `given`, or the monomer's (4.12) when `from_monomer`, m s⁻¹.
    pub fn fragmentation_velocity(&self, given: f64, from_monomer: bool) -> f64 {
        if from_monomer { self.monomer().fragmentation_velocity() } else { given }
    }

    /// The combined surface energy of the chosen monomers, J m⁻².
    pub fn surface_energy(&self) -> f64 {
        if self.icy { self.surface_energy_ice } else { self.surface_energy_silicate }
    }

    /// The gas disk.
    pub fn disk(&self) -> GasDisk {
        let profile = match self.profile {
            DiskProfile::PowerLaw => {
                Profile::TruncatedPowerLaw { mass: self.disk_mass, r_c: self.r_c, slope: self.slope }
            }
            DiskProfile::Mmsn => Profile::Mmsn,
        };
        GasDisk { profile, cold: self.cold, alpha: self.alpha, metallicity: self.metallicity }
    }

    /// The monomers.
    pub fn monomer(&self) -> Monomer {
        let (law, hysteresis, xi_crit) = (self.rolling_law, self.hysteresis, self.xi_crit);
        monomer::monomer(self.monomer_radius, self.icy, self.surface_energy(), law, hysteresis, xi_crit)
    }
}

/// The semi-analytical growth model. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct GrowthParams {
    /// Disk and monomers.
    #[param(flatten)]
    pub disk: DiskParams,
    /// same-size collisions above it fragment (80 m/s for 0.1 µm ice)
    #[param(quantity = quantities::v_frag, default = 80.0)]
    pub v_frag: f64,
    /// use v_frag = 20 (E_break/m₀)^{1/2} (4.12) of the monomer card instead of the number above
    #[param(label = "v_frag from the monomer", default = false)]
    pub v_frag_from_monomer: bool,
    /// collisions with monomers above it erode (1e4: none)
    #[param(quantity = quantities::v_eros, default = 1e4)]
    pub v_eros: f64,
    /// compact grains bounce above it (1e4: none)
    #[param(label = "bouncing threshold", unit = "m s^-1", shown("m/s", 1.0), range(0.01, 1e4), log, default = 1e4)]
    pub v_bounce: f64,
    /// full turbulence closed form
    #[param(label = "Ormel & Cuzzi form", default = false)]
    pub ormel_cuzzi: bool,
    /// include Re_p > 1 drag
    #[param(label = "Newton drag", default = true)]
    pub newton: bool,
    /// mass growth per step
    #[param(numerical, label = "step Δln m", range(0.01, 1.0), log, default = 0.1)]
    pub dlnm: f64,
}

impl GrowthParams {
    /// The model with a given porosity treatment.
    pub fn model(&self, porosity: Porosity) -> GrowthModel {
        let mut m = GrowthModel::chapter4(porosity);
        m.disk = self.disk.disk();
        m.monomer = self.disk.monomer();
        m.thresholds = Thresholds {
            v_frag: self.disk.fragmentation_velocity(self.v_frag, self.v_frag_from_monomer),
            v_eros: self.v_eros,
            v_bounce: self.v_bounce,
            r_crit: R_CRIT,
        };
        m.turbulence = if self.ormel_cuzzi { TurbulenceModel::OrmelCuzzi } else { TurbulenceModel::Thesis };
        m.newton = self.newton;
        m.dlnm = self.dlnm;
        m.inner_edge = AU;
        m
    }
}

/// The declaration every scene of a local track makes: its step in ln m
/// sets its resolution.
pub const TRACK_STEP: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "dlnm",
    kind: crate::scene::core::Irregularity::Step,
    why: "the track's step in ln m sets its resolution: results move by the discretisation error, in steps \
          where the track gains or loses a point",
    resolution: None,
};

/// Local growth of one aggregate at a fixed radius: the parameters of the
/// porosity-track scene, shared with the timescales scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct TrackParams {
    /// The growth model.
    #[param(flatten, default = GrowthParams { v_frag: 1e4, ..GrowthParams::default() })]
    pub growth: GrowthParams,
    /// where the dust grows
    #[param(quantity = quantities::disk_radius, default = 5.0)]
    pub radius_au: f64,
}

impl TrackParams {
    /// The local track with the given porosity treatment.
    pub fn track(&self, porosity: Porosity) -> Track {
        let mut model = self.growth.model(porosity);
        model.drift = false;
        model.run(self.radius_au * AU, 1e8 * YEAR)
    }
}

/// What the model says of an aggregate of `mass` (kg) and filling factor
/// `filling` at radius `r` (m) of the disk, growing on the time scale
/// `t_grow` (s, infinite when halted): its size, Stokes number, drag regime,
/// drift time and what limits its growth there.
pub fn aggregate_rows(disk: &DiskParams, r: f64, mass: f64, filling: f64, t_grow: f64) -> Vec<(String, String)> {
    use crate::physics::aggregate::{Aggregate, radial_drift, stopping_time};
    use crate::scene::inspect::{row, value};
    let env = disk.disk().local(r);
    let mono = disk.monomer();
    let agg = Aggregate { mass, filling: filling.clamp(1e-12, 1.0) };
    let stop = stopping_time(&env, &mono, &agg, true);
    let st = stop.time * env.omega;
    let t_drift = r / radial_drift(env.eta_vk, st).max(1e-300);
    let a = agg.radius(&mono);
    let limit = if !t_grow.is_finite() {
        "growth halted: collisions fragment, bounce or erode".to_string()
    } else if t_drift < t_grow {
        format!("drift-limited: it drifts in {} times faster than it grows", crate::figure::human(t_grow / t_drift))
    } else {
        format!("growth-limited: it grows {} times faster than it drifts", crate::figure::human(t_drift / t_grow))
    };
    vec![
        row("radius in the disk R", value(r / AU, "AU")),
        row("mass m", value(mass * 1e3, "g")),
        row("filling factor φ", value(agg.filling, "")),
        row("size a", crate::scene::inspect::length(a)),
        row("Stokes number Ωt_s", value(st, "")),
        row("drag regime", format!("{:?} (a/λ_mfp = {})", stop.regime, crate::figure::human(a / env.mean_free_path))),
        row("growth time t_grow", if t_grow.is_finite() { value(t_grow / YEAR, "yr") } else { "∞ (halted)".into() }),
        row("drift time t_drift", value(t_drift / YEAR, "yr")),
        row("what limits growth", limit),
    ]
}
