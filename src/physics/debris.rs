//! The energy-limited smallest fragment of a collision (thesis ch. 6).
//!
//! Fragments follow n(s) = C s^{-α} with 3 < α < 4 between s_min and s_max
//! (6.1); the surface created, a fraction η of the kinetic energy, bounds
//! s_min from below. SI units throughout (sizes are radii in m).

use super::PhysicsError;
use std::f64::consts::PI;

pub use super::constants::{AU, G, M_SUN};

/// A material of Table 6.1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DebrisMaterial {
    /// Name.
    pub name: &'static str,
    /// Bulk density ρ, kg m⁻³.
    pub density: f64,
    /// Surface energy γ per unit surface, J m⁻².
    pub surface_energy: f64,
}

/// Table 6.1: silicate, ice, and a typical aggregate (ρ ~ 0.1 g cm⁻³, γ ~ 10⁻⁴–10⁻³ J m⁻²;
/// the geometric middle 3 × 10⁻⁴ J m⁻² is used).
pub const TABLE_6_1: [DebrisMaterial; 3] = [
    DebrisMaterial { name: "silicate", density: 2600.0, surface_energy: 0.05 },
    DebrisMaterial { name: "ice", density: 1000.0, surface_energy: 0.74 },
    DebrisMaterial { name: "aggregate", density: 100.0, surface_energy: 3e-4 },
];

/// Effective surface energy of an aggregate, γ_agg ~ (a/R)² φ^{2/3} γ (App. 6.A),
/// for contact-to-monomer radius ratio `a_over_r` and filling factor φ.
pub fn aggregate_surface_energy(gamma: f64, a_over_r: f64, filling_factor: f64) -> f64 {
    a_over_r * a_over_r * filling_factor.powf(2.0 / 3.0) * gamma
}

fn check_slope(alpha: f64) -> Result<(), PhysicsError> {
    if alpha > 3.0 && alpha < 4.0 {
        Ok(())
    } else {
        Err(PhysicsError::InvalidParameter { name: "alpha", value: alpha, reason: "the slope must satisfy 3 < α < 4" })
    }
}

/// The coefficient C of (6.3), C = 2(4 − α)s₀³ s_max^{α−4}, from M_frag = 2M₀.
pub fn coefficient(alpha: f64, s0: f64, s_max: f64) -> f64 {
    2.0 * (4.0 - alpha) * s0.powi(3) * s_max.powf(alpha - 4.0)
}

/// Fragment mass and surface of (6.2) for s_max ≫ s_min: (M_frag [kg], A_frag [m²]).
pub fn fragment_mass_and_area(alpha: f64, c: f64, density: f64, s_min: f64, s_max: f64) -> (f64, f64) {
    let m = 4.0 * PI * density * c / (3.0 * (4.0 - alpha)) * s_max.powf(4.0 - alpha);
    let a = 4.0 * PI * c / (alpha - 3.0) * s_min.powf(3.0 - alpha);
    (m, a)
}

/// Smallest fragment of two equal colliders of radius s₀ at relative velocity v
/// (general α of (6.2)–(6.3); (6.4) for α = 3.5): η·½μv² = γ(A_frag − 8πs₀²), μ = M₀/2.
pub fn smallest_fragment(
    m: &DebrisMaterial,
    alpha: f64,
    eta: f64,
    v: f64,
    s0: f64,
    s_max: f64,
) -> Result<f64, PhysicsError> {
    check_slope(alpha)?;
    for (name, x) in [("eta", eta), ("v", v), ("s0", s0), ("s_max", s_max)] {
        super::positive(name, x)?;
    }
    let bracket = eta * m.density * s0 * v * v / (3.0 * m.surface_energy) + 8.0;
    let x = (alpha - 3.0) * bracket / (8.0 * (4.0 - alpha) * s0 * s_max.powf(alpha - 4.0));
    let s_min = x.powf(1.0 / (3.0 - alpha));
    if s_min >= s_max {
        return Err(PhysicsError::InvalidParameter {
            name: "s_max",
            value: s_max,
            reason: "s_max ≤ s_min: too little energy for a fragment distribution (mass conservation)",
        });
    }
    Ok(s_min)
}

/// (6.4) as printed (α = 3.5).
pub fn smallest_fragment_64(m: &DebrisMaterial, eta: f64, v: f64, s0: f64, s_max: f64) -> f64 {
    let g = m.surface_energy;
    (24.0 * g * s0 / (eta * m.density * s0 * v * v + 24.0 * g)).powi(2) / s_max
}

/// The smallest body that can be split in half, s₀^split = 3γ/(ηρv²) (6.5), m.
pub fn split_size(m: &DebrisMaterial, eta: f64, v: f64) -> f64 {
    3.0 * m.surface_energy / (eta * m.density * v * v)
}

/// The splitting limit of the smallest fragment, s_min ≈ 5γ/(ηρv²) (6.6), m.
pub fn splitting_limit(m: &DebrisMaterial, eta: f64, v: f64) -> f64 {
    5.0 * m.surface_energy / (eta * m.density * v * v)
}

/// Specific energy to split a body of radius s (6.5), Q = U_K/(2M₀) = 3γ/(8ηρs), J kg⁻¹
/// (the convention v_f² = 8Q*).
pub fn splitting_energy(m: &DebrisMaterial, eta: f64, s: f64) -> f64 {
    3.0 * m.surface_energy / (8.0 * eta * m.density * s)
}

/// A catastrophic-disruption fit Q*_D = Q₀(s/1 cm)^a + Bρ(s/1 cm)^b (cgs, erg g⁻¹).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DisruptionFit {
    /// Label with source.
    pub name: &'static str,
    /// Q₀, erg g⁻¹.
    pub q0: f64,
    /// Strength exponent a.
    pub a: f64,
    /// Gravity coefficient B (cgs).
    pub b_coeff: f64,
    /// Gravity exponent b.
    pub b: f64,
    /// Density, g cm⁻³.
    pub density_cgs: f64,
}

impl DisruptionFit {
    /// Q*_D at radius s (m), J kg⁻¹.
    pub fn q_star(&self, s: f64) -> f64 {
        let r_cm = s * 100.0;
        (self.q0 * r_cm.powf(self.a) + self.b_coeff * self.density_cgs * r_cm.powf(self.b)) * 1e-4
    }
}

/// Benz & Asphaug (1999, Table III) fits at 3 km/s for basalt and ice, the curves
/// of Fig. 6.1 (bottom). The Beitz et al. (2011) aggregate curve is not included:
/// its fit is not given in the thesis.
pub const BENZ_ASPHAUG_3KMS: [DisruptionFit; 2] = [
    DisruptionFit {
        name: "basalt (Benz & Asphaug 1999, 3 km/s)",
        q0: 3.5e7,
        a: -0.38,
        b_coeff: 0.3,
        b: 1.36,
        density_cgs: 2.7,
    },
    DisruptionFit {
        name: "ice (Benz & Asphaug 1999, 3 km/s)",
        q0: 1.6e7,
        a: -0.39,
        b_coeff: 1.2,
        b: 1.26,
        density_cgs: 0.9,
    },
];

/// Blow-out size where β = 1/2 in (6.7): s = 2.3 Q_pr (L/L☉)(M☉/M)(1 g cm⁻³/ρ) µm, m.
pub fn blowout_size(q_pr: f64, luminosity: f64, mass: f64, density: f64) -> f64 {
    2.3e-6 * q_pr * luminosity / mass * (1000.0 / density)
}

/// Relative velocity f·v_K with f = (1.25e² + i²)^{1/2} at orbital radius r (m)
/// around a star of `mass` solar masses, m s⁻¹.
pub fn relative_velocity(e: f64, i: f64, r: f64, mass: f64) -> f64 {
    (1.25 * e * e + i * i).sqrt() * (G * mass * M_SUN / r).sqrt()
}

/// s_min/s_blow in a disk, computed from (6.6) with v = f v_K and the β = 1/2
/// blow-out size of (6.7) (Q_pr = 1); independent of ρ and of the stellar mass.
pub fn ratio_to_blowout(gamma: f64, eta: f64, f: f64, r: f64, luminosity: f64) -> f64 {
    // ρ drops out; evaluate with ρ = 1000 kg m⁻³ and M = 1 M☉.
    let m = DebrisMaterial { name: "", density: 1000.0, surface_energy: gamma };
    let v = f * (G * M_SUN / r).sqrt();
    splitting_limit(&m, eta, v) / blowout_size(1.0, luminosity, 1.0, 1000.0)
}

/// (6.8) as printed: 2.4 (a/5 AU)(L/L☉)⁻¹(f/10⁻²)⁻²(η/10⁻²)⁻¹(γ/0.1 J m⁻²).
pub fn ratio_to_blowout_printed(gamma: f64, eta: f64, f: f64, r: f64, luminosity: f64) -> f64 {
    2.4 * (r / (5.0 * AU)) / luminosity / (f / 1e-2).powi(2) / (eta / 1e-2) * (gamma / 0.1)
}

/// Catastrophic fragmentation of unequal colliders (6.10), α = 3.5, s_min ≪ s_max, m.
pub fn smallest_fragment_unequal(m: &DebrisMaterial, eta: f64, v: f64, s_p: f64, s_t: f64, s_max: f64) -> f64 {
    let x =
        6.0 * m.surface_energy * (s_p.powi(3) + s_t.powi(3)).powi(2) / (eta * m.density * v * v * (s_p * s_t).powi(3));
    x * x / s_max
}

/// Erosion by a small projectile (6.11), eroded mass κ m_p, m.
pub fn smallest_fragment_erosion(m: &DebrisMaterial, eta: f64, v: f64, kappa: f64, s_max: f64) -> f64 {
    (6.0 * m.surface_energy * kappa / (eta * m.density * v * v)).powi(2) / s_max
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIL: DebrisMaterial = TABLE_6_1[0];

    #[test]
    fn general_slope_reduces_to_6_4() {
        for (s0, v) in [(1e-3, 20.0), (1.0, 5.0), (1e-5, 100.0)] {
            let s_max = 2f64.powf(-1.0 / 3.0) * s0;
            let a = smallest_fragment(&SIL, 3.5, 1e-2, v, s0, s_max).expect("valid");
            let b = smallest_fragment_64(&SIL, 1e-2, v, s0, s_max);
            assert!((a / b - 1.0).abs() < 1e-12, "{a} vs {b}");
        }
    }

    #[test]
    fn energy_balance_holds_for_any_slope() {
        for alpha in [3.1, 3.5, 3.9] {
            let (s0, v, eta) = (0.05, 30.0, 1e-2);
            let s_max = 2f64.powf(-1.0 / 3.0) * s0;
            let s_min = smallest_fragment(&SIL, alpha, eta, v, s0, s_max).expect("valid");
            let c = coefficient(alpha, s0, s_max);
            let (m_frag, a_frag) = fragment_mass_and_area(alpha, c, SIL.density, s_min, s_max);
            let m0 = 4.0 / 3.0 * PI * SIL.density * s0.powi(3);
            assert!((m_frag / (2.0 * m0) - 1.0).abs() < 1e-12, "mass conservation");
            let lhs = eta * 0.5 * (m0 / 2.0) * v * v;
            let rhs = SIL.surface_energy * (a_frag - 8.0 * PI * s0 * s0);
            assert!((lhs / rhs - 1.0).abs() < 1e-9, "α = {alpha}: {lhs} vs {rhs}");
        }
    }

    #[test]
    fn invalid_slopes_and_slow_collisions_are_errors() {
        for alpha in [3.0, 4.0, 2.5, f64::NAN] {
            assert!(smallest_fragment(&SIL, alpha, 1e-2, 20.0, 1.0, 0.5).is_err());
        }
        // A 1 µm silicate grain at 1 m/s cannot make fragments: s_min would exceed s_max.
        let err = smallest_fragment(&SIL, 3.5, 1e-2, 1.0, 1e-6, 0.79e-6).expect_err("too slow");
        assert!(err.to_string().contains("s_max"));
    }
}
