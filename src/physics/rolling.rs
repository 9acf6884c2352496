//! Rolling friction of adhesive microspheres from adhesion hysteresis
//! (thesis ch. 3): the asymmetric contact of two half-discs, its torque, the
//! critical rolling displacement, the rocking oscillation and the bulk torque.

use super::contact::Pair;
use std::f64::consts::PI;

/// An asymmetric contact: two half-discs of radii a₁ (x > 0) and a₂ (x < 0)
/// sharing the approach δ (3.8). SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfDiscs {
    /// Radius of the half at x > 0, m.
    pub a1: f64,
    /// Radius of the half at x < 0, m.
    pub a2: f64,
    /// Mutual approach, m.
    pub delta: f64,
}

impl HalfDiscs {
    /// The JKR equilibrium contact of `pair` displaced by ξ: a₁ = a_eq − ξ,
    /// a₂ = a_eq + ξ (3.18), δ = δ_eq.
    pub fn displaced(pair: &Pair, xi: f64) -> HalfDiscs {
        let a = pair.jkr_equilibrium_radius();
        HalfDiscs { a1: a - xi, a2: a + xi, delta: pair.jkr_equilibrium_approach() }
    }

    /// Rolling displacement ξ = (a₂ − a₁)/2 (3.9), m.
    pub fn xi(&self) -> f64 {
        0.5 * (self.a2 - self.a1)
    }

    /// Mean radius a = (a₁ + a₂)/2, m.
    pub fn mean_radius(&self) -> f64 {
        0.5 * (self.a1 + self.a2)
    }

    /// Pressure at (x, y) from (3.1) on each half (3.8), Pa; zero outside.
    pub fn pressure(&self, pair: &Pair, x: f64, y: f64) -> f64 {
        let a = if x >= 0.0 { self.a1 } else { self.a2 };
        let r2 = x * x + y * y;
        if r2 >= a * a {
            return 0.0;
        }
        pair.modulus / (PI * pair.radius) * (a * a - 2.0 * r2 + pair.radius * self.delta) / (a * a - r2).sqrt()
    }

    /// Torque of the contact, M = E*/(4R)[(a₁² − δR)² − (a₂² − δR)²] (3.10), N m;
    /// negative when it opposes a positive ξ. The moment ∬ x p dx dy of the
    /// pressure (3.8) evaluates to minus this bracket: (3.10) is the torque
    /// the contact exerts on the sphere, with the sign of (3.11).
    pub fn torque(&self, pair: &Pair) -> f64 {
        let dr = self.delta * pair.radius;
        pair.modulus / (4.0 * pair.radius) * ((self.a1 * self.a1 - dr).powi(2) - (self.a2 * self.a2 - dr).powi(2))
    }

    /// Strain energy release rates (G₁, G₂) of the two halves (3.7), J m⁻².
    pub fn release_rates(&self, pair: &Pair) -> (f64, f64) {
        (pair.effective_surface_energy(self.a1, self.delta), pair.effective_surface_energy(self.a2, self.delta))
    }

    /// Torque from the release rates, M = (R/2)(πa₁G₁ − πa₂G₂) (3.11), N m.
    pub fn torque_from_release_rates(&self, pair: &Pair) -> f64 {
        let (g1, g2) = self.release_rates(pair);
        0.5 * pair.radius * PI * (self.a1 * g1 - self.a2 * g2)
    }

    /// Elastic force of the asymmetric contact, F_E = 2E*a/(3R)(3δR − a² − 3ξ²) (3.12), N.
    pub fn elastic_force(&self, pair: &Pair) -> f64 {
        let (a, xi) = (self.mean_radius(), self.xi());
        2.0 * pair.modulus * a / (3.0 * pair.radius) * (3.0 * self.delta * pair.radius - a * a - 3.0 * xi * xi)
    }

    /// Elastic energy of the asymmetric contact, the mean of (3.21) over both halves (3.24), J.
    pub fn elastic_energy(&self, pair: &Pair) -> f64 {
        0.5 * (pair.elastic_energy(self.a1, self.delta) + pair.elastic_energy(self.a2, self.delta))
    }
}

/// Torque of a small asymmetry at zero load, M = 6πγRξ (3.14), N m.
pub fn small_asymmetry_torque(pair: &Pair, xi: f64) -> f64 {
    6.0 * PI * pair.surface_energy * pair.radius * xi
}

/// ξ from the release-rate difference, ξ = (a_eq/12)(G₂ − G₁)/γ (3.15), m, with
/// ξ = (a₂ − a₁)/2 as in (3.9) (the thesis writes G₁ − G₂ for the trailing
/// half, whichever side that is). (3.15) sets a₁ = a₂ in (3.11); keeping the
/// (a₁ − a₂)γ term the small-ξ coefficient is 1/10, so (3.15) gives a ξ 17 %
/// smaller than the exact small-asymmetry relation.
pub fn displacement_from_release_rates(pair: &Pair, g_difference: f64) -> f64 {
    pair.jkr_equilibrium_radius() / 12.0 * g_difference / pair.surface_energy
}

/// Critical rolling displacement ξ_crit = (a_eq/12)(Δγ/γ) (3.16), m.
pub fn critical_displacement(pair: &Pair, hysteresis: f64) -> f64 {
    pair.jkr_equilibrium_radius() / 12.0 * hysteresis
}

/// Steady rolling torque with hysteresis Δγ = `hysteresis`·γ near equilibrium:
/// M = (R/2)π a_eq Δγ (3.11 with a₁ ≈ a₂ ≈ a_eq), N m.
pub fn rolling_torque(pair: &Pair, hysteresis: f64) -> f64 {
    0.5 * pair.radius * PI * pair.jkr_equilibrium_radius() * hysteresis * pair.surface_energy
}

/// Rolling force F = M/R for a rolling torque M, N.
pub fn rolling_force(pair: &Pair, torque: f64) -> f64 {
    torque / pair.radius
}

/// Bulk torque for quality factor Q, M_B = (π U_E/Q)(R/(2a)) (3.22) at JKR equilibrium, N m.
pub fn bulk_torque(pair: &Pair, q: f64) -> f64 {
    let a = pair.jkr_equilibrium_radius();
    let u_e = pair.elastic_energy(a, pair.jkr_equilibrium_approach());
    PI * u_e / q * pair.radius / (2.0 * a)
}

/// Rocking frequency of a pinned contact f₀ = (1/2π)(6πγR²/I)^{1/2} (3.20), Hz,
/// for moment of inertia I in kg m².
pub fn rocking_frequency(pair: &Pair, inertia: f64) -> f64 {
    (6.0 * PI * pair.surface_energy * pair.radius.powi(2) / inertia).sqrt() / (2.0 * PI)
}

/// A sphere kicked sideways on its contact (Sect. 3.2.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rocking {
    /// The contact.
    pub pair: Pair,
    /// Moment of inertia I = (2/5)mR² of the rocking sphere, kg m².
    pub inertia: f64,
    /// Adhesion hysteresis Δγ/γ, setting ξ_crit (3.16).
    pub hysteresis: f64,
    /// Quality factor Q of the bulk; the rocking energy e-folds in Q/π periods (3.25).
    /// Infinite for no bulk loss.
    pub q: f64,
    /// Initial rate of ξ (the kick), m s⁻¹.
    pub kick: f64,
}

/// One instant of a rocking run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RockingSample {
    /// Time, s.
    pub t: f64,
    /// Rolling displacement ξ (centre of mass relative to the contact centre), m.
    pub xi: f64,
    /// Rate of the centre of mass, m s⁻¹.
    pub velocity: f64,
    /// Distance the contact has rolled, m.
    pub rolled: f64,
    /// Whether the contact rolls (true) or is pinned (false).
    pub rolling: bool,
    /// Rocking energy (kinetic + stored by the asymmetry), J.
    pub energy: f64,
}

impl Rocking {
    /// Restoring torque of the pinned contact at displacement ξ, from (3.13)
    /// at fixed δ_eq: 6πγRξ[1 + (3/2)(ξ/a_eq)²], N m.
    pub fn pinned_torque(&self, xi: f64) -> f64 {
        let a = self.pair.jkr_equilibrium_radius();
        small_asymmetry_torque(&self.pair, xi) * (1.0 + 1.5 * (xi / a).powi(2))
    }

    /// Energy stored by the asymmetry, ∫M dξ/R, J.
    pub fn stored_energy(&self, xi: f64) -> f64 {
        let a = self.pair.jkr_equilibrium_radius();
        let k = 6.0 * PI * self.pair.surface_energy;
        k * (0.5 * xi * xi + 0.375 * xi.powi(4) / (a * a))
    }

    /// Kinetic energy of the rocking sphere at centre-of-mass rate v, J.
    pub fn kinetic_energy(&self, v: f64) -> f64 {
        0.5 * self.inertia * (v / self.pair.radius).powi(2)
    }

    /// Rocking frequency f₀ (3.20), Hz.
    pub fn frequency(&self) -> f64 {
        rocking_frequency(&self.pair, self.inertia)
    }

    /// The kick that makes a pinned, undamped contact rock to amplitude `amplitude` (m).
    pub fn kick_for_amplitude(pair: &Pair, inertia: f64, amplitude: f64) -> f64 {
        let r = Rocking { pair: *pair, inertia, hysteresis: f64::INFINITY, q: f64::INFINITY, kick: 0.0 };
        let e = r.stored_energy(amplitude);
        (2.0 * e / inertia).sqrt() * pair.radius
    }

    /// Integrates the motion for `periods` rocking periods with `steps_per_period`
    /// classical Runge–Kutta steps, switching between the pinned contact
    /// (restoring torque) and rolling (constant opposing torque (3.11) while
    /// |ξ| = ξ_crit) at the crossings, located to the step's linear interpolation.
    pub fn run(&self, periods: f64, steps_per_period: usize) -> Vec<RockingSample> {
        let f0 = self.frequency();
        let dt = 1.0 / (f0 * steps_per_period as f64);
        let n = (periods * steps_per_period as f64).ceil() as usize;
        let xi_crit = critical_displacement(&self.pair, self.hysteresis);
        let m_roll = rolling_torque(&self.pair, self.hysteresis);
        // ξ'' = (R²/I)·(torque) in terms of the centre of mass: I θ'' = M with θ = ξ/R.
        let gain = self.pair.radius.powi(2) / self.inertia;
        let damping = if self.q.is_finite() { 2.0 * PI * f0 / (2.0 * self.q) } else { 0.0 };
        let (mut t, mut xi, mut v, mut rolled, mut rolling) = (0.0, 0.0, self.kick, 0.0, false);
        let sample = |t: f64, xi: f64, v: f64, rolled: f64, rolling: bool| RockingSample {
            t,
            xi,
            velocity: v,
            rolled,
            rolling,
            energy: self.kinetic_energy(v) + self.stored_energy(xi),
        };
        let mut out = Vec::with_capacity(n + 1);
        out.push(sample(t, xi, v, rolled, rolling));
        for _ in 0..n {
            if rolling {
                // ξ stays at ±ξ_crit; the sphere decelerates under the rolling torque.
                let dir = v.signum();
                let accel = -gain * m_roll * dir / self.pair.radius - damping * v;
                let v_new = v + accel * dt;
                if v_new * v <= 0.0 {
                    // Comes to rest within the step: the contact pins again.
                    let f = v / (v - v_new);
                    rolled += v * f * dt * 0.5;
                    t += f * dt;
                    v = 0.0;
                    rolling = false;
                } else {
                    rolled += 0.5 * (v + v_new) * dt;
                    v = v_new;
                    t += dt;
                }
            } else {
                let acc = |x: f64, u: f64| -gain * self.pinned_torque(x) / self.pair.radius - damping * u;
                let (k1x, k1v) = (v, acc(xi, v));
                let (k2x, k2v) = (v + 0.5 * dt * k1v, acc(xi + 0.5 * dt * k1x, v + 0.5 * dt * k1v));
                let (k3x, k3v) = (v + 0.5 * dt * k2v, acc(xi + 0.5 * dt * k2x, v + 0.5 * dt * k2v));
                let (k4x, k4v) = (v + dt * k3v, acc(xi + dt * k3x, v + dt * k3v));
                let xi_new = xi + dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
                let v_new = v + dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
                if xi_new.abs() >= xi_crit && xi.abs() < xi_crit {
                    // The trailing edge reaches G_op: true rolling starts.
                    let f = (xi_crit - xi.abs()) / (xi_new.abs() - xi.abs());
                    t += f * dt;
                    v += f * (v_new - v);
                    xi = xi_crit * xi_new.signum();
                    rolling = true;
                } else {
                    xi = xi_new;
                    v = v_new;
                    t += dt;
                }
            }
            out.push(sample(t, xi, v, rolled, rolling));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn psl_on_flat() -> Pair {
        // A 5 µm PSL sphere on PSL (Fig. 3.2), γ = 2 × 0.025 J/m².
        let e = 3.4e9 / (2.0 * (1.0 - 0.33f64.powi(2)));
        Pair { modulus: e, radius: 5e-6, mass: 1026.0 * 4.0 / 3.0 * PI * 125e-18, surface_energy: 0.05 }
    }

    #[test]
    fn torque_forms_agree() {
        let p = psl_on_flat();
        let a = p.jkr_equilibrium_radius();
        let c = HalfDiscs { a1: 0.93 * a, a2: 1.05 * a, delta: 0.9 * p.jkr_equilibrium_approach() };
        let m = c.torque(&p);
        assert!((c.torque_from_release_rates(&p) / m - 1.0).abs() < 1e-10);
        // (3.13): M = ξ[−F_E + 4E*a³/(3R)], with the sign convention of (3.10).
        let m13 = -c.xi() * (-c.elastic_force(&p) + 4.0 * p.modulus * c.mean_radius().powi(3) / (3.0 * p.radius));
        assert!((m13 / m - 1.0).abs() < 1e-10, "{m13} vs {m}");
    }

    #[test]
    fn torque_integral_matches_the_closed_form() {
        let p = psl_on_flat();
        let c = HalfDiscs::displaced(&p, 0.1 * p.jkr_equilibrium_radius());
        // ∬ x p dx dy in polar coordinates; the edge singularity is integrable (r = a sin² u substitution).
        let half = |a: f64, sign: f64| {
            let n = 4000;
            let mut sum = 0.0;
            for i in 0..n {
                let u = (i as f64 + 0.5) / n as f64 * PI / 2.0;
                let r = a * u.sin();
                let dr = a * u.cos() * PI / 2.0 / n as f64;
                // ∫ over the half: ∫ x dφ = 2r (φ ∈ ±π/2 for x > 0).
                let p_r =
                    p.modulus / (PI * p.radius) * (a * a - 2.0 * r * r + p.radius * c.delta) / (a * a - r * r).sqrt();
                sum += sign * 2.0 * r * r * p_r * dr;
            }
            sum
        };
        let numeric = half(c.a1, 1.0) + half(c.a2, -1.0);
        // (3.10) is minus the first moment of the pressure (see `torque`).
        assert!((-numeric / c.torque(&p) - 1.0).abs() < 1e-3, "{numeric} vs {}", c.torque(&p));
    }

    #[test]
    fn small_asymmetry_gives_dominik_tielens() {
        let p = psl_on_flat();
        for frac in [1e-4, 1e-3, 1e-2] {
            let xi = frac * p.jkr_equilibrium_radius();
            let m = -HalfDiscs::displaced(&p, xi).torque(&p);
            assert!((m / small_asymmetry_torque(&p, xi) - 1.0).abs() < 2.0 * frac * frac + 1e-9, "{frac}");
        }
        // (3.15) inverts (3.11) with a₁ = a₂: 10/12 of the exact small-ξ value.
        let xi = 1e-3 * p.jkr_equilibrium_radius();
        let (g1, g2) = HalfDiscs::displaced(&p, xi).release_rates(&p);
        let ratio = displacement_from_release_rates(&p, g2 - g1) / xi;
        assert!((ratio - 10.0 / 12.0).abs() < 1e-2, "{ratio}");
    }

    #[test]
    fn steady_rolling_torque_equals_the_pinned_torque_at_the_critical_displacement() {
        let p = psl_on_flat();
        let h = 3.0;
        let xi = critical_displacement(&p, h);
        assert!((small_asymmetry_torque(&p, xi) / rolling_torque(&p, h) - 1.0).abs() < 1e-12);
    }
}
