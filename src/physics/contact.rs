//! Static adhesive contact of two elastic spheres: Hertz and JKR theory
//! (thesis Sect. 1.3.3 and 2.2.1) and the closed-form collision estimates of
//! Sect. 2.3.3.

use crate::solver::{State, dormand_prince_step};
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

    /// Dimensionless damping b = (3/2) A κ^{2/5} v^{1/5} of the non-adhesive
    /// viscoelastic collision, κ = 4E*R^{1/2}/(3m*), for dissipation time A in s
    /// and impact speed v in m/s. It is Brilliantov et al.'s (1996) β v^{1/5} for
    /// the bulk force (2.19), and equals 4.830 A/t_H.
    pub fn viscous_damping(&self, dissipation_time: f64, v: f64) -> f64 {
        let kappa = 4.0 * self.modulus * self.radius.sqrt() / (3.0 * self.mass);
        1.5 * dissipation_time * kappa.powf(0.4) * v.powf(0.2)
    }

    /// Non-adhesive viscoelastic restitution e_D: the limit γ → 0 of the
    /// model's own equations (Hertz force plus the bulk force (2.19)), from
    /// [`viscoelastic_restitution`] of [`Pair::viscous_damping`]. For small
    /// damping it is 1 − 5.571 A/t_H + …, the series of Schwager & Pöschel (1998);
    /// the printed (2.26) is [`Pair::e_viscous_printed`].
    pub fn e_viscous(&self, dissipation_time: f64, v: f64) -> f64 {
        viscoelastic_restitution(self.viscous_damping(dissipation_time, v))
    }

    /// (2.26) as printed, e_D ≈ 1 − 1.92 A/t_H, with A in s; 0 where negative.
    /// It has the model's scaling (A v^{1/5}/R at fixed mass density) but a
    /// loss 1 − e_D 2.90 times smaller than the model's own limit
    /// [`Pair::e_viscous`]: the coefficient of Brilliantov et al. and Schwager &
    /// Pöschel in the thesis's notation is 1.153 × 4.830 = 5.571.
    pub fn e_viscous_printed(&self, dissipation_time: f64, v: f64) -> f64 {
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

/// Restitution of the non-adhesive viscoelastic collision with dimensionless
/// damping b (see [`Pair::viscous_damping`]): the speed at which the scaled
/// approach x returns to zero in x'' = −(x^{3/2} + b x^{1/2} x'), x(0) = 0,
/// x'(0) = 1. The contact ends at zero approach, as in the full model when
/// γ → 0 (the viscous force may pull on the way out). 1 for b = 0; 0 for a
/// non-finite or negative b, or where the spheres creep apart for longer than
/// 50(1 + b) scaled times (b ≳ 10, e < 10⁻⁸).
///
/// Dormand–Prince 5(4) steps under error control (10⁻¹⁰ per step, relative
/// to x + 10⁻³ and to 1 + |x'|): the square roots make the force non-smooth
/// where x = 0, so steps shrink towards both ends of contact and are long in
/// between. The end is the zero of x, found by secant iteration on the length
/// of the last step (x'' vanishes there, so the speed hardly depends on it).
/// Within 5 × 10⁻⁹ of the same integration at tolerance 10⁻¹⁴ for
/// 10⁻⁴ ≤ b ≤ 20, in about 20 µs. The step is the solver's
/// [`dormand_prince_step`]; the loop is written here because it ends on an
/// event (x = 0) that [`crate::solver::dormand_prince`] does not look for.
pub fn viscoelastic_restitution(b: f64) -> f64 {
    if b == 0.0 {
        return 1.0;
    }
    if !(b.is_finite() && b > 0.0) {
        return 0.0;
    }
    viscoelastic_restitution_at(b, VISCOELASTIC_TOLERANCE)
}

/// Error tolerance (per step, on x and x') of [`viscoelastic_restitution`].
const VISCOELASTIC_TOLERANCE: f64 = 1e-10;

/// One Dormand–Prince 5(4) step of x'' = −(x^{3/2} + b x^{1/2} x') from
/// (x, v) with step h: the fifth-order state and the difference to the
/// embedded fourth-order one.
fn dopri_step(b: f64, (x, v): (f64, f64), h: f64) -> ((f64, f64), (f64, f64)) {
    let f = |_: f64, y: &State<2>| {
        let r = y[0].max(0.0).sqrt();
        Some(State::<2>::new(y[1], -(y[0].max(0.0) * r + b * r * y[1])))
    };
    let y = State::<2>::new(x, v);
    match f(0.0, &y).and_then(|k0| dormand_prince_step(&f, 0.0, &y, &k0, h)) {
        Some((yn, _, e)) => ((yn[0], yn[1]), (e[0], e[1])),
        None => ((f64::NAN, f64::NAN), (f64::NAN, f64::NAN)),
    }
}

/// [`viscoelastic_restitution`] at error tolerance `tol` (b > 0).
fn viscoelastic_restitution_at(b: f64, tol: f64) -> f64 {
    let t_max = 50.0 * (1.0 + b);
    let (mut t, mut y, mut h) = (0.0, (0.0_f64, 1.0_f64), 1e-3_f64);
    let mut started = false;
    while t < t_max {
        let (yn, (ex, ev)) = dopri_step(b, y, h);
        let err = (ex / (tol * (1e-3 + y.0.abs().max(yn.0.abs())))).hypot(ev / (tol * (1.0 + y.1.abs())));
        if err.is_nan() || err > 1.0 {
            h *= if err.is_nan() { 0.1 } else { (0.9 * err.powf(-0.2)).clamp(0.1, 0.5) };
            if h < 1e-12 * t_max {
                // No step resolves the motion (a damping beyond floating point).
                return 0.0;
            }
            continue;
        }
        if started && yn.0 <= 0.0 {
            // The approach crosses zero within this step: the step length
            // that ends on x = 0, by secant iteration from (0, x) and (h, x_n).
            let (mut lo, mut hi) = ((0.0, y.0), (h, yn.0));
            let mut end = yn;
            for _ in 0..8 {
                let hs = lo.0 - lo.1 * (hi.0 - lo.0) / (hi.1 - lo.1);
                if !(hs > lo.0 && hs < hi.0) {
                    break;
                }
                end = dopri_step(b, y, hs).0;
                if end.0.abs() <= 1e-14 * (hi.0 - lo.0) {
                    break;
                }
                if end.0 > 0.0 { lo = (hs, end.0) } else { hi = (hs, end.0) }
            }
            return (-end.1).max(0.0);
        }
        started = true;
        t += h;
        y = yn;
        h *= (0.9 * err.max(1e-10).powf(-0.2)).min(5.0);
    }
    0.0
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
    fn viscoelastic_restitution_follows_the_published_series() {
        // Schwager & Pöschel (1998): e = 1 − C1 b + C2 b² − …, with
        // C1 = √π Γ(3/5)/(2^{1/5} 5^{2/5} Γ(21/10)) = 1.153449 and C2 = 3C1²/5.
        let (c1, c2) = (1.153449, 0.6 * 1.153449_f64.powi(2));
        for b in [1e-4, 1e-3, 1e-2] {
            let e = viscoelastic_restitution(b);
            let expect = c1 - c2 * b;
            assert!(((1.0 - e) / b - expect).abs() < 2e-3, "b = {b}: (1 − e)/b = {}", (1.0 - e) / b);
        }
        // The second-order term, with the third (≈ −0.52 b³) as the tolerance.
        let b = 0.02;
        let c2_ours = (viscoelastic_restitution(b) - 1.0 + c1 * b) / (b * b);
        assert!((c2_ours - c2).abs() < 0.6 * b + 0.01, "C2 = {c2_ours}");
        // Exact limits and monotony in the damping.
        assert_eq!(viscoelastic_restitution(0.0), 1.0);
        assert_eq!(viscoelastic_restitution(f64::NAN), 0.0);
        assert_eq!(viscoelastic_restitution(-1.0), 0.0);
        let es: Vec<f64> = [0.01, 0.1, 0.5, 1.0, 2.0, 5.0].iter().map(|&b| viscoelastic_restitution(b)).collect();
        assert!(es.windows(2).all(|w| w[1] < w[0]), "{es:?}");
        assert!(es[5] > 0.0 && es[5] < 0.01, "{es:?}");
    }

    #[test]
    fn viscoelastic_restitution_is_converged_in_its_tolerance() {
        // Against the same integration 10⁴ times tighter, over the damping
        // from the nearly elastic to the nearly stuck.
        for i in 0..=24 {
            let b = 1e-4 * 10f64.powf(i as f64 * 5.3 / 24.0);
            let (e, tight) = (viscoelastic_restitution(b), viscoelastic_restitution_at(b, 1e-14));
            assert!((e - tight).abs() < 1e-8, "b = {b}: {e} against {tight}");
        }
        // A slightly damped collision loses far less than the tolerance of
        // the speed would hide: e is strictly below 1 and monotone.
        assert!(viscoelastic_restitution(1e-6) < 1.0);
        assert!(viscoelastic_restitution(1e-6) > viscoelastic_restitution(2e-6));
        // Dampings beyond any material end with e ≈ 0 instead of a step too
        // small to advance.
        for b in [1e3, 1e10, 1e300, f64::MAX] {
            let e = viscoelastic_restitution(b);
            assert!((0.0..1e-10).contains(&e), "b = {b}: {e}");
        }
    }

    #[test]
    fn printed_viscous_limit_has_the_model_scaling_but_a_smaller_loss() {
        let p = ice();
        let a = 1.6e-10;
        for v in [1.0, 8.0, 100.0] {
            // b = 4.830 A/t_H: the same A v^{1/5} scaling as (2.26).
            let ratio = p.viscous_damping(a, v) * p.hertz_time(v) / a;
            assert!((ratio - 4.830).abs() < 2e-3, "{ratio}");
            let loss_model = 1.0 - p.e_viscous(a, v);
            let loss_printed = 1.0 - p.e_viscous_printed(a, v);
            assert!(loss_model / loss_printed > 2.6 && loss_model / loss_printed < 3.0, "v = {v}");
        }
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
