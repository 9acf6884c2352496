//! Static adhesive contact of two elastic spheres: Hertz and JKR theory
//! (thesis Sect. 1.3.3 and 2.2.1) and the closed-form collision estimates of
//! Sect. 2.3.3.

use std::f64::consts::PI;

/// The reduced quantities of a two-body contact. All SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    /// Combined elastic modulus E*, Pa.
    pub modulus: f64,
    /// Reduced radius R (1/R = 1/R₁ + 1/R₂), m.
    pub radius: f64,
    /// Reduced mass m* (1/m* = 1/m₁ + 1/m₂), kg.
    pub mass: f64,
    /// Combined surface energy γ, J/m².
    pub surface_energy: f64,
}

impl Pair {
    /// Hertz contact radius at approach δ: a = (Rδ)^{1/2} (2.4), m.
    pub fn hertz_radius(&self, delta: f64) -> f64 {
        (self.radius * delta.max(0.0)).sqrt()
    }

    /// Hertz force at contact radius a: F = 4E*a³/(3R) (2.5), N.
    pub fn hertz_force(&self, a: f64) -> f64 {
        4.0 * self.modulus * a.powi(3) / (3.0 * self.radius)
    }

    /// JKR approach at contact radius a: δ = a²/R − (2πγa/E*)^{1/2} (2.8), m.
    pub fn jkr_approach(&self, a: f64) -> f64 {
        a * a / self.radius - (2.0 * PI * self.surface_energy * a / self.modulus).sqrt()
    }

    /// JKR force at contact radius a: F = 4E*a³/(3R) − (8πγE*a³)^{1/2} (2.9), N.
    pub fn jkr_force(&self, a: f64) -> f64 {
        self.hertz_force(a) - (8.0 * PI * self.surface_energy * self.modulus * a.powi(3)).sqrt()
    }

    /// JKR equilibrium contact radius a_eq = (9πγR²/(2E*))^{1/3} (2.10), m.
    pub fn jkr_equilibrium_radius(&self) -> f64 {
        (9.0 * PI * self.surface_energy * self.radius.powi(2) / (2.0 * self.modulus)).cbrt()
    }

    /// JKR approach at equilibrium (F = 0), m (negative-free: δ_eq = a_eq²/(3R)).
    pub fn jkr_equilibrium_approach(&self) -> f64 {
        self.jkr_approach(self.jkr_equilibrium_radius())
    }

    /// JKR snap-on contact radius at δ = 0: a = (2πγR²/E*)^{1/3}, m.
    pub fn snap_on_radius(&self) -> f64 {
        (2.0 * PI * self.surface_energy * self.radius.powi(2) / self.modulus).cbrt()
    }

    /// Pull-off force magnitude F_c = (3/2)πγR, N.
    pub fn pull_off_force(&self) -> f64 {
        1.5 * PI * self.surface_energy * self.radius
    }

    /// Elastic force for independent a and δ, F_E = 2E*/(3R) (3aδR − a³) (2.2), N.
    pub fn elastic_force(&self, a: f64, delta: f64) -> f64 {
        2.0 * self.modulus / (3.0 * self.radius) * (3.0 * a * delta * self.radius - a.powi(3))
    }

    /// Elastic energy stored in the contact, U_E (2.3), J.
    pub fn elastic_energy(&self, a: f64, delta: f64) -> f64 {
        let (e, r) = (self.modulus, self.radius);
        e * delta * delta * a - 2.0 * e / (3.0 * r) * delta * a.powi(3) + e * a.powi(5) / (5.0 * r * r)
    }

    /// Surface energy of the contact, U_S = −πa²γ (2.6), J.
    pub fn surface_energy_of(&self, a: f64) -> f64 {
        -PI * a * a * self.surface_energy
    }

    /// Effective surface energy for given a and δ, G_eff = E*(a² − δR)²/(2πaR²) (2.14), J/m².
    pub fn effective_surface_energy(&self, a: f64, delta: f64) -> f64 {
        let u = a * a - delta * self.radius;
        self.modulus * u * u / (2.0 * PI * a * self.radius.powi(2))
    }

    /// Hertz collision time t_H = 2.87 (m*²/(R E*² v))^{1/5} (2.22), s.
    pub fn hertz_time(&self, v: f64) -> f64 {
        2.87 * (self.mass.powi(2) / (self.radius * self.modulus.powi(2) * v)).powf(0.2)
    }

    /// Maximum Hertz approach for impact speed v: δ_m = (15 m* v² / (16 E* R^{1/2}))^{2/5}, m.
    pub fn hertz_max_approach(&self, v: f64) -> f64 {
        (15.0 * self.mass * v * v / (16.0 * self.modulus * self.radius.sqrt())).powf(0.4)
    }

    /// JKR sticking velocity v_c = (14.18/m*)^{1/2} (γ⁵R⁴/E*²)^{1/6} (2.25), m/s.
    pub fn jkr_sticking_velocity(&self) -> f64 {
        (14.18 / self.mass).sqrt()
            * (self.surface_energy.powi(5) * self.radius.powi(4) / self.modulus.powi(2)).powf(1.0 / 6.0)
    }

    /// Elastic JKR coefficient of restitution e_JKR = (1 − (v_c/v)²)^{1/2} (2.24); 0 below v_c.
    pub fn e_jkr(&self, v: f64) -> f64 {
        let x = self.jkr_sticking_velocity() / v;
        (1.0 - x * x).max(0.0).sqrt()
    }

    /// Non-adhesive viscoelastic restitution e_D ≈ 1 − 1.92 A/t_H (2.26), with A in s.
    pub fn e_viscous(&self, dissipation_time: f64, v: f64) -> f64 {
        (1.0 - 1.92 * dissipation_time / self.hertz_time(v)).max(0.0)
    }

    /// Tabor parameter μ = (Rγ²/(E*²z₀³))^{1/3} (2.11) for atomic spacing z₀ in m.
    pub fn tabor(&self, z0: f64) -> f64 {
        (self.radius * self.surface_energy.powi(2) / (self.modulus.powi(2) * z0.powi(3))).cbrt()
    }

    /// Energy to break a contact, E_break ~ (γ⁵R⁴/E*²)^{1/3}, J.
    ///
    /// The thesis prints E*³ in (1.24), which is not an energy; E*² is the
    /// dimensionally consistent form, and with it ½m*v_c² of (2.25) equals
    /// 7.09 E_break, so v_stick ∝ R^{-5/6} as the text says.
    pub fn break_energy(&self) -> f64 {
        (self.surface_energy.powi(5) * self.radius.powi(4) / self.modulus.powi(2)).cbrt()
    }

    /// Energy to roll over 90°, E_roll = 6πγRξ (1.25), J, for rolling displacement ξ in m.
    pub fn roll_energy(&self, xi: f64) -> f64 {
        6.0 * PI * self.surface_energy * self.radius * xi
    }
}

/// "Independent" estimate e_I = (e_JKR² + e_D² − 1)^{1/2} (2.27); 0 if the radicand is negative.
pub fn e_independent(e_jkr: f64, e_d: f64) -> f64 {
    (e_jkr * e_jkr + e_d * e_d - 1.0).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ice() -> Pair {
        let m = crate::physics::sphere_mass(1000.0, 2e-6);
        Pair { modulus: 7e9 / (2.0 * 0.9375), radius: 1e-6, mass: m / 2.0, surface_energy: 0.74 }
    }

    #[test]
    fn jkr_curve_passes_through_equilibrium_and_snap_on() {
        let p = ice();
        let a_eq = p.jkr_equilibrium_radius();
        assert!(p.jkr_force(a_eq).abs() < 1e-9 * p.pull_off_force());
        let a0 = p.snap_on_radius();
        assert!(p.jkr_approach(a0).abs() < 1e-12 * a0);
        // On the JKR curve, G_eff equals γ.
        let a = 0.7 * a_eq;
        let g = p.effective_surface_energy(a, p.jkr_approach(a));
        assert!((g / p.surface_energy - 1.0).abs() < 1e-12);
        // The JKR force's minimum along the curve is the pull-off force.
        let fmin = (1..2000).map(|i| p.jkr_force(a_eq * i as f64 / 2000.0)).fold(f64::MAX, f64::min);
        assert!((fmin / -p.pull_off_force() - 1.0).abs() < 1e-4, "{fmin}");
    }

    #[test]
    fn elastic_energy_is_the_potential_of_the_elastic_force() {
        let p = ice();
        let (a, d) = (8e-8, 3e-9);
        let h = 1e-15;
        let num = (p.elastic_energy(a, d + h) - p.elastic_energy(a, d - h)) / (2.0 * h);
        assert!((num / p.elastic_force(a, d) - 1.0).abs() < 1e-6);
        // ∂U_E/∂a = 2πa G_eff (2.12–2.14).
        let ha = 1e-14;
        let da = (p.elastic_energy(a + ha, d) - p.elastic_energy(a - ha, d)) / (2.0 * ha);
        let expect = 2.0 * PI * a * p.effective_surface_energy(a, d);
        assert!((da / expect - 1.0).abs() < 1e-6);
    }

    #[test]
    fn thesis_reference_numbers() {
        let p = ice();
        // v_c = 1.46 m/s, t_H(8 m/s) = 1.4e-8 s, e_JKR(4 m/s) = 0.93 (notes §1).
        assert!((p.jkr_sticking_velocity() - 1.46).abs() < 0.01);
        assert!((p.hertz_time(8.0) / 1.4e-8 - 1.0).abs() < 0.05);
        assert!((p.e_jkr(4.0) - 0.93).abs() < 0.005);
    }
}
