//! What the disk scenes (thesis ch. 4) share: the gas disk, the monomers and
//! the semi-analytical growth model.

use crate::physics::aggregate::{R_CRIT, Thresholds, TurbulenceModel};
use crate::physics::constants::{AU, YEAR};
use crate::physics::disk::{GasDisk, Profile};
use crate::physics::growth::{GrowthModel, Porosity, Track};
use crate::physics::monomer::Monomer;
use crate::scene::controls::Control;
use crate::scene::monomer::{self, ROLLING_LAWS};
use crate::scene::quantities;
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
    /// Combined surface energy γ of two icy monomers, J m⁻² (default 0.74 = 2 × 0.37, Table 2.2).
    pub surface_energy_ice: f64,
    /// Combined surface energy γ of two silicate monomers, J m⁻² (default 0.05 = 2 × 0.025, Table 3.1).
    pub surface_energy_silicate: f64,
    /// Rolling-energy law: "calibrated" (5.26, default), "contact" (ch. 3, (3.16))
    /// or "dominik-tielens" (fixed ξ_crit).
    pub rolling_law: String,
    /// Adhesion hysteresis Δγ/γ of the ch. 3 law (default 0.5).
    pub hysteresis: f64,
    /// Critical rolling displacement of the Dominik & Tielens law, m (default 0.3 nm).
    pub xi_crit: f64,
    /// Keep this scene's monomer instead of sharing the explorer's (window only).
    pub own_monomer: bool,
}

impl Default for DiskParams {
    fn default() -> Self {
        let m = monomer::Spec::default();
        DiskParams {
            profile: "mmsn".into(),
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
    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        vec![
            Control::choice("profile", "gas disk", &mut self.profile, vec![("mmsn", "MMSN (4.1)"), ("power-law", "truncated power law (5.1)")]).default(d.profile.clone()).doc("surface density profile"),
            quantities::disk_mass(&mut self.disk_mass).default(d.disk_mass).doc("power-law disk mass"),
            Control::number("r_c", "R_c", &mut self.r_c).default(d.r_c).unit("AU").range(5.0, 300.0).log().doc("power-law characteristic radius"),
            Control::number("slope", "slope γ", &mut self.slope).default(d.slope).range(0.5, 1.9).doc("power-law slope"),
            Control::toggle("cold", "cold disk (T/2)", &mut self.cold).default(d.cold).doc("halve the temperature"),
            Control::number("alpha", "turbulence α", &mut self.alpha).default(d.alpha).range(1e-6, 1e-1).log().doc("Shakura–Sunyaev α"),
            Control::number("metallicity", "dust-to-gas Z₀", &mut self.metallicity).default(d.metallicity).range(1e-4, 0.1).log().doc("Σ_d/Σ_g"),
            Control::number("monomer_radius", "monomer radius a₀", &mut self.monomer_radius).default(d.monomer_radius).unit("m").shown("µm", 1e6).range(1e-8, 1e-5).log().doc("radius of the monomers"),
            Control::toggle("icy", "icy monomers", &mut self.icy).default(d.icy).doc("ice (1.4 g/cm³, E = 7 GPa) or silicate (2.6 g/cm³, E = 54 GPa)"),
            Control::number("surface_energy_ice", "surface energy γ (ice)", &mut self.surface_energy_ice).default(d.surface_energy_ice).unit("J m^-2").shown("J/m²", 1.0).range(0.01, 5.0).log().doc("combined surface energy of two icy monomers (2γ_L; Table 2.2: 0.74)"),
            Control::number("surface_energy_silicate", "surface energy γ (silicate)", &mut self.surface_energy_silicate).default(d.surface_energy_silicate).unit("J m^-2").shown("J/m²", 1.0).range(0.005, 5.0).log().doc("combined surface energy of two silicate monomers (2γ_L; Table 3.1: 0.05)"),
            Control::choice("rolling_law", "E_roll law", &mut self.rolling_law, ROLLING_LAWS.to_vec()).default(d.rolling_law.clone()).doc("calibrated (5.26) ∝ a₀^{5/3}γ^{4/3}; ch. 3 contact 6πγRξ_crit with ξ_crit = (a_eq/12)Δγ/γ; Dominik & Tielens with a fixed ξ_crit, ∝ a₀"),
            quantities::hysteresis(&mut self.hysteresis).labelled("Δγ/γ (ch. 3 law)").default(d.hysteresis).doc("adhesion hysteresis of the ch. 3 rolling law (0.35 reproduces (5.26) for ice)"),
            Control::number("xi_crit", "ξ_crit (D&T law)", &mut self.xi_crit).default(d.xi_crit).unit("m").shown("nm", 1e9).range(1e-11, 1e-8).log().doc("critical rolling displacement of the Dominik & Tielens law (0.3 nm)"),
            Control::toggle("own_monomer", "own monomer", &mut self.own_monomer).default(d.own_monomer).style_only().doc("keep this scene's monomer when another scene's changes (window only)"),
        ]
    }

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
        let profile = if self.profile == "power-law" {
            Profile::TruncatedPowerLaw { mass: self.disk_mass, r_c: self.r_c, slope: self.slope }
        } else {
            Profile::Mmsn
        };
        GasDisk { profile, cold: self.cold, alpha: self.alpha, metallicity: self.metallicity }
    }

    /// The monomers.
    pub fn monomer(&self) -> Monomer {
        let (law, hysteresis, xi_crit) = (self.rolling_law.as_str(), self.hysteresis, self.xi_crit);
        monomer::monomer(self.monomer_radius, self.icy, self.surface_energy(), law, hysteresis, xi_crit)
    }
}

/// The control of a local scene's disk radius, AU (0.5–300 AU); `meaning`
/// says what sits there.
pub fn radius_control<'a>(value: &'a mut f64, meaning: &'static str) -> Control<'a> {
    Control::number("radius_au", "disk radius", value).unit("AU").range(0.5, 300.0).log().doc(meaning)
}

/// The semi-analytical growth model. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GrowthParams {
    /// Disk and monomers.
    pub disk: DiskParams,
    /// Fragmentation velocity, m s⁻¹ (default: (4.12) for ice, 10 for compact tracks).
    pub v_frag: f64,
    /// Use the monomer's v_frag (4.12) instead of `v_frag`.
    pub v_frag_from_monomer: bool,
    /// Erosion threshold, m s⁻¹ (default 10⁴: no erosion).
    pub v_eros: f64,
    /// Bouncing threshold of compact grains, m s⁻¹ (default 10⁴: none).
    pub v_bounce: f64,
    /// Use the full Ormel & Cuzzi turbulence form.
    pub ormel_cuzzi: bool,
    /// Include Newton drag.
    pub newton: bool,
    /// Growth per step, Δln m (default 0.1).
    pub dlnm: f64,
}

impl Default for GrowthParams {
    fn default() -> Self {
        GrowthParams {
            disk: DiskParams::default(),
            v_frag: 80.0,
            v_frag_from_monomer: false,
            v_eros: 1e4,
            v_bounce: 1e4,
            ormel_cuzzi: false,
            newton: true,
            dlnm: 0.1,
        }
    }
}

impl GrowthParams {
    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        let mut c = self.disk.controls(&d.disk);
        let v = ("m/s", 1.0);
        c.push(
            quantities::v_frag(&mut self.v_frag)
                .default(d.v_frag)
                .doc("same-size collisions above it fragment (80 m/s for 0.1 µm ice)"),
        );
        c.push(
            Control::toggle("v_frag_from_monomer", "v_frag from the monomer", &mut self.v_frag_from_monomer)
                .default(d.v_frag_from_monomer)
                .doc("use v_frag = 20 (E_break/m₀)^{1/2} (4.12) of the monomer card instead of the number above"),
        );
        c.push(
            quantities::v_eros(&mut self.v_eros)
                .default(d.v_eros)
                .doc("collisions with monomers above it erode (1e4: none)"),
        );
        c.push(
            Control::number("v_bounce", "bouncing threshold", &mut self.v_bounce)
                .default(d.v_bounce)
                .unit("m s^-1")
                .shown(v.0, v.1)
                .range(0.01, 1e4)
                .log()
                .doc("compact grains bounce above it (1e4: none)"),
        );
        c.push(
            Control::toggle("ormel_cuzzi", "Ormel & Cuzzi form", &mut self.ormel_cuzzi)
                .default(d.ormel_cuzzi)
                .doc("full turbulence closed form"),
        );
        c.push(
            Control::toggle("newton", "Newton drag", &mut self.newton).default(d.newton).doc("include Re_p > 1 drag"),
        );
        c.push(
            Control::number("dlnm", "step Δln m", &mut self.dlnm)
                .default(d.dlnm)
                .range(0.01, 1.0)
                .log()
                .doc("mass growth per step"),
        );
        c
    }

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

/// Local growth of one aggregate at a fixed radius: the parameters of the
/// porosity-track scene, shared with the timescales scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TrackParams {
    /// The growth model.
    pub growth: GrowthParams,
    /// Radius, AU (default 5).
    pub radius_au: f64,
}

impl Default for TrackParams {
    fn default() -> Self {
        TrackParams { growth: GrowthParams { v_frag: 1e4, ..GrowthParams::default() }, radius_au: 5.0 }
    }
}

impl TrackParams {
    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        let mut c = self.growth.controls(&d.growth);
        c.push(radius_control(&mut self.radius_au, "where the dust grows").default(d.radius_au));
        c
    }

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
