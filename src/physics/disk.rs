//! Gas disks: the minimum-mass solar nebula column of ch. 4 (Eqs. 4.1–4.5) and
//! the truncated power law of ch. 5 (Eqs. 5.1–5.5). SI units; radii in m.

pub use super::constants::{AU, G, K_B, M_SUN, YEAR};
use super::tabled;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Mean molecular mass m_g = 3.9 × 10⁻²⁴ g, kg.
pub const M_GAS: f64 = 3.9e-27;
/// Molecular cross section σ_mol = 2 × 10⁻¹⁵ cm², m².
pub const SIGMA_MOL: f64 = 2e-19;

/// The gas surface density profile.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Profile {
    /// Σ = 152 g cm⁻² (R/5 AU)^{-3/2} (4.1).
    Mmsn,
    /// Σ = Σ₀ (R/R_c)^{-γ} exp[−(R/R_c)^{2−γ}] (5.1) for a disk of `mass` (M☉).
    TruncatedPowerLaw {
        /// Disk mass, solar masses.
        mass: f64,
        /// Characteristic radius R_c, AU.
        r_c: f64,
        /// Slope γ (1 or 3/2 in the thesis).
        slope: f64,
    },
}

/// A protoplanetary gas disk around a solar-mass star.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GasDisk {
    /// Surface density profile.
    pub profile: Profile,
    /// Temperatures halved (the cold disks of ch. 5).
    pub cold: bool,
    /// Turbulence strength α.
    pub alpha: f64,
    /// Dust-to-gas ratio of the column Z₀ = Σ_d/Σ_g.
    pub metallicity: f64,
}

impl GasDisk {
    /// The MMSN of ch. 4 with α and Z₀.
    pub fn mmsn(alpha: f64, metallicity: f64) -> GasDisk {
        GasDisk { profile: Profile::Mmsn, cold: false, alpha, metallicity }
    }

    /// Gas surface density Σ_g at radius r, kg m⁻².
    pub fn surface_density(&self, r: f64) -> f64 {
        self.surface_density_and_slope(r).0
    }

    /// Gas surface density Σ_g at radius r (kg m⁻²) and its logarithmic
    /// slope d ln Σ_g/d ln R.
    fn surface_density_and_slope(&self, r: f64) -> (f64, f64) {
        match self.profile {
            Profile::Mmsn => (1520.0 * (r / (5.0 * AU)).powf(-1.5), -1.5),
            Profile::TruncatedPowerLaw { mass, r_c, slope } => {
                let rc = r_c * AU;
                // Σ₀ from M_D = ∫2πrΣ dr = 2πΣ₀R_c²/(2 − γ).
                let sigma0 = mass * M_SUN * (2.0 - slope) / (2.0 * PI * rc * rc);
                let x = r / rc;
                let taper = x.powf(2.0 - slope);
                (sigma0 * x.powf(-slope) * tabled::exp(-taper), -slope - (2.0 - slope) * taper)
            }
        }
    }

    /// Temperature T = 125 K (R/5 AU)^{-1/2} (4.2, 5.2), halved for a cold disk, K.
    pub fn temperature(&self, r: f64) -> f64 {
        let t = 125.0 / (r / (5.0 * AU)).sqrt();
        if self.cold { 0.5 * t } else { t }
    }

    /// Sound speed c_s = (k_B T/m_g)^{1/2} (4.3), m s⁻¹.
    pub fn sound_speed(&self, r: f64) -> f64 {
        (K_B * self.temperature(r) / M_GAS).sqrt()
    }

    /// Kepler frequency Ω = (GM☉/R³)^{1/2} (4.4), s⁻¹.
    pub fn omega(&self, r: f64) -> f64 {
        (G * M_SUN / r.powi(3)).sqrt()
    }

    /// Kepler velocity v_K = RΩ, m s⁻¹.
    pub fn kepler_velocity(&self, r: f64) -> f64 {
        r * self.omega(r)
    }

    /// Gas scale height h_g = c_s/Ω, m.
    pub fn scale_height(&self, r: f64) -> f64 {
        self.sound_speed(r) / self.omega(r)
    }

    /// Midplane gas density ρ_g = Σ_g/((2π)^{1/2} h_g) (4.5), kg m⁻³.
    pub fn midplane_density(&self, r: f64) -> f64 {
        self.surface_density(r) / ((2.0 * PI).sqrt() * self.scale_height(r))
    }

    /// Mean thermal speed v_th = (8/π)^{1/2} c_s, m s⁻¹.
    pub fn thermal_speed(&self, r: f64) -> f64 {
        (8.0 / PI).sqrt() * self.sound_speed(r)
    }

    /// Mean free path λ_mfp = m_g/(σ_mol ρ_g) at the midplane, m.
    pub fn mean_free_path(&self, r: f64) -> f64 {
        M_GAS / (SIGMA_MOL * self.midplane_density(r))
    }

    /// Molecular viscosity ν_mol = v_th λ_mfp/2, m² s⁻¹.
    pub fn molecular_viscosity(&self, r: f64) -> f64 {
        0.5 * self.thermal_speed(r) * self.mean_free_path(r)
    }

    /// Turbulence Reynolds number Re_t = αc_s²/(Ων_mol).
    pub fn reynolds(&self, r: f64) -> f64 {
        self.alpha * self.sound_speed(r).powi(2) / (self.omega(r) * self.molecular_viscosity(r))
    }

    /// Turn-over time of the smallest eddies t_η = Re_t^{-1/2}/Ω, s.
    pub fn kolmogorov_time(&self, r: f64) -> f64 {
        self.reynolds(r).powf(-0.5) / self.omega(r)
    }

    /// Pressure-gradient parameter η = −½(c_s/v_K)² ∂ln(ρ_g c_s²)/∂ln R (5.9).
    /// With ρ_g c_s² ∝ Σ_g c_s Ω, T ∝ R^{-1/2} and Ω ∝ R^{-3/2} the slope is
    /// d ln Σ_g/d ln R − 7/4 (−13/4 for the MMSN).
    pub fn eta(&self, r: f64) -> f64 {
        eta_of(self.sound_speed(r), self.kepler_velocity(r), self.surface_density_and_slope(r).1)
    }

    /// Dust surface density Z₀Σ_g, kg m⁻².
    pub fn dust_surface_density(&self, r: f64) -> f64 {
        self.metallicity * self.surface_density(r)
    }
}

/// η (5.9) from the sound speed, the Kepler velocity (m s⁻¹) and
/// d ln Σ_g/d ln R.
fn eta_of(sound_speed: f64, kepler_velocity: f64, sigma_slope: f64) -> f64 {
    -0.5 * (sound_speed / kepler_velocity).powi(2) * (sigma_slope - 1.75)
}

/// Midplane quantities at one radius, computed once for repeated use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Local {
    /// Radius, m.
    pub r: f64,
    /// Temperature, K.
    pub temperature: f64,
    /// Sound speed, m s⁻¹.
    pub sound_speed: f64,
    /// Kepler frequency, s⁻¹.
    pub omega: f64,
    /// Gas scale height, m.
    pub scale_height: f64,
    /// Midplane gas density, kg m⁻³.
    pub density: f64,
    /// Mean thermal speed, m s⁻¹.
    pub thermal_speed: f64,
    /// Mean free path, m.
    pub mean_free_path: f64,
    /// Turbulence Reynolds number.
    pub reynolds: f64,
    /// ηv_K, m s⁻¹.
    pub eta_vk: f64,
    /// Turbulence α.
    pub alpha: f64,
    /// Dust surface density, kg m⁻².
    pub dust_surface_density: f64,
}

impl GasDisk {
    /// The midplane quantities at radius r.
    pub fn local(&self, r: f64) -> Local {
        // Each quantity as its method computes it, from the others taken once.
        let temperature = self.temperature(r);
        let sound_speed = (K_B * temperature / M_GAS).sqrt();
        let omega = self.omega(r);
        let scale_height = sound_speed / omega;
        let (sigma, sigma_slope) = self.surface_density_and_slope(r);
        let density = sigma / ((2.0 * PI).sqrt() * scale_height);
        let thermal_speed = (8.0 / PI).sqrt() * sound_speed;
        let mean_free_path = M_GAS / (SIGMA_MOL * density);
        let viscosity = 0.5 * thermal_speed * mean_free_path;
        let kepler_velocity = r * omega;
        let eta = eta_of(sound_speed, kepler_velocity, sigma_slope);
        Local {
            r,
            temperature,
            sound_speed,
            omega,
            scale_height,
            density,
            thermal_speed,
            mean_free_path,
            reynolds: self.alpha * sound_speed.powi(2) / (omega * viscosity),
            eta_vk: eta * kepler_velocity,
            alpha: self.alpha,
            dust_surface_density: self.metallicity * sigma,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mmsn_at_5_au_matches_chapter_4() {
        let d = GasDisk::mmsn(1e-3, 1e-2);
        let r = 5.0 * AU;
        assert!((d.sound_speed(r) / 670.0 - 1.0).abs() < 0.02, "c_s = {}", d.sound_speed(r));
        assert!((d.omega(r) / 1.8e-8 - 1.0).abs() < 0.02, "Ω = {}", d.omega(r));
        assert!((d.scale_height(r) / r - 0.05).abs() < 0.002, "h/R = {}", d.scale_height(r) / r);
        assert!((d.mean_free_path(r) / 1.2 - 1.0).abs() < 0.05, "λ = {} m", d.mean_free_path(r));
        assert!((d.eta(r) / 4e-3 - 1.0).abs() < 0.1, "η = {}", d.eta(r));
        assert!(
            (d.eta(r) * d.kepler_velocity(r) / 50.0 - 1.0).abs() < 0.1,
            "ηv_K = {}",
            d.eta(r) * d.kepler_velocity(r)
        );
        // λ ∝ R^{11/4}.
        let ratio = d.mean_free_path(10.0 * AU) / d.mean_free_path(r);
        assert!((ratio / 2f64.powf(11.0 / 4.0) - 1.0).abs() < 1e-9);
    }

    #[test]
    fn truncated_power_law_holds_its_mass() {
        let d = GasDisk {
            profile: Profile::TruncatedPowerLaw { mass: 0.01, r_c: 30.0, slope: 1.0 },
            cold: false,
            alpha: 1e-3,
            metallicity: 0.01,
        };
        let n = 20000;
        let (r0, r1) = (0.01 * AU, 3000.0 * AU);
        let mut m = 0.0;
        for i in 0..n {
            let a = (r0.ln() + (r1 / r0).ln() * i as f64 / n as f64).exp();
            let b = (r0.ln() + (r1 / r0).ln() * (i + 1) as f64 / n as f64).exp();
            let r = (a * b).sqrt();
            m += 2.0 * PI * r * d.surface_density(r) * (b - a);
        }
        assert!((m / (0.01 * M_SUN) - 1.0).abs() < 1e-3, "{}", m / M_SUN);
        let cold = GasDisk { cold: true, ..d };
        assert!((cold.temperature(AU) / d.temperature(AU) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn eta_is_the_pressure_slope_and_local_matches_each_quantity() {
        // η from the analytic slope against a fourth-order central difference
        // of ln(ρ_g c_s²) in ln R, for both profiles, both slopes, warm and cold.
        let disks = [
            GasDisk::mmsn(1e-3, 1e-2),
            GasDisk {
                profile: Profile::TruncatedPowerLaw { mass: 0.1, r_c: 30.0, slope: 1.0 },
                cold: false,
                alpha: 1e-4,
                metallicity: 0.02,
            },
            GasDisk {
                profile: Profile::TruncatedPowerLaw { mass: 0.05, r_c: 100.0, slope: 1.5 },
                cold: true,
                alpha: 1e-3,
                metallicity: 0.01,
            },
        ];
        for d in disks {
            for r_au in [0.5, 3.0, 30.0, 100.0, 300.0] {
                let r = r_au * AU;
                let p = |x: f64| (d.midplane_density(r * x.exp()) * d.sound_speed(r * x.exp()).powi(2)).ln();
                let h = 1e-3;
                let slope = (8.0 * (p(h) - p(-h)) - (p(2.0 * h) - p(-2.0 * h))) / (12.0 * h);
                let numeric = -0.5 * (d.sound_speed(r) / d.kepler_velocity(r)).powi(2) * slope;
                assert!((d.eta(r) / numeric - 1.0).abs() < 1e-8, "{d:?} at {r_au} AU: {} against {numeric}", d.eta(r));
                let l = d.local(r);
                let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-14;
                assert!(close(l.density, d.midplane_density(r)) && close(l.mean_free_path, d.mean_free_path(r)));
                assert!(close(l.reynolds, d.reynolds(r)) && close(l.eta_vk, d.eta(r) * d.kepler_velocity(r)));
                assert!(
                    close(l.dust_surface_density, d.dust_surface_density(r)) && close(l.sound_speed, d.sound_speed(r))
                );
            }
        }
    }
}
