//! Greenwood's (2004) law for a viscoelastic crack at the contact edge
//! (thesis Eqs. 2.15–2.17).
//!
//! The crack speed is written ȧ = C g(β) with C = E*γ/(σ₀² T_vis) and
//! β = G_eff/γ. `g` is positive for β < 1 (a growing contact), negative for
//! β > 1 (a shrinking one), and diverges at β → k and β → 1/k, so the physical
//! domain is k < β < 1/k.

/// Crack-speed law of a three-element viscoelastic solid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrackLaw {
    /// Ratio of relaxed to instantaneous modulus k (dimensionless, 0 < k < 0.5).
    pub k: f64,
    /// Use Greenwood's low-speed fits (2.17) for 0.29 < β < 3.7. They were
    /// made for k = 0.02 and join the general law (2.16) within ~1 % there;
    /// for other k they would not, and a jump in the crack speed traps the
    /// contact on it, so they are applied only for 0.018 ≤ k ≤ 0.022.
    pub low_speed_fit: bool,
}

impl CrackLaw {
    /// Lower end of the domain of `g`: β = k.
    pub fn beta_min(&self) -> f64 {
        self.k
    }

    /// Upper end of the domain of `g`: β = 1/k.
    pub fn beta_max(&self) -> f64 {
        1.0 / self.k
    }

    /// The dimensionless crack speed g(β) = σ₀²T_vis ȧ/(E*γ) and its derivative
    /// dg/dβ; `None` outside k < β < 1/k.
    pub fn speed(&self, beta: f64) -> Option<(f64, f64)> {
        let k = self.k;
        if !(beta > k && beta < 1.0 / k) {
            return None;
        }
        let fit = self.low_speed_fit && (0.018..=0.022).contains(&k);
        if beta == 1.0 && fit {
            return Some((0.0, self.speed(1.0 - 1e-9).map_or(0.0, |s| s.1)));
        }
        if fit && beta > 0.29 && beta < 1.0 {
            let x = 1.0 / beta - 1.0;
            let p = x.powf(0.116);
            let g = (0.1035 * x + 0.3421) * x * p;
            let dgdx = 0.1035 * x * p + (0.1035 * x + 0.3421) * 1.116 * p;
            return Some((g, -dgdx / (beta * beta)));
        }
        if fit && beta > 1.0 && beta < 3.7 {
            let x = beta - 1.0;
            let p = x.powf(0.1403);
            let g = -(0.2112 * x + 0.3939) * x * p;
            let dgdx = -(0.2112 * x * p + (0.2112 * x + 0.3939) * 1.1403 * p);
            return Some((g, dgdx));
        }
        if (beta - 1.0).abs() < BRIDGE {
            return Some(self.bridge(beta));
        }
        self.general(beta)
    }

    /// Greenwood's general law (2.16), valid away from β = 1.
    fn general(&self, beta: f64) -> Option<(f64, f64)> {
        let k = self.k;
        if beta < 1.0 {
            let l = ((1.0 - k) / (1.0 - beta)).ln();
            let g = 0.15 / (beta * l);
            let dg = -0.15 * (l + beta / (1.0 - beta)) / (beta * l).powi(2);
            Some((g, dg))
        } else {
            let m = ((1.0 - k) / (1.0 - 1.0 / beta)).ln();
            let g = -0.24 * beta / m;
            let dg = -0.24 * (m + 1.0 / (beta - 1.0)) / (m * m);
            Some((g, dg))
        }
    }

    /// Near β = 1 the general law has an infinite slope (and is inaccurate:
    /// Greenwood gives the low-speed fits for that reason), which makes the
    /// quasi-static limit needlessly stiff. Within |β − 1| < `BRIDGE` it is
    /// replaced by the quadratic in u = 1 − β through g(1 ± BRIDGE) and 0 at
    /// β = 1, which keeps the sign of ȧ equal to that of 1 − β.
    fn bridge(&self, beta: f64) -> (f64, f64) {
        let e = BRIDGE;
        let g_minus = self.general(1.0 - e).map_or(0.0, |g| g.0);
        let g_plus = self.general(1.0 + e).map_or(0.0, |g| g.0);
        let s = (g_minus - g_plus) / (2.0 * e);
        let c = (g_minus + g_plus) / (2.0 * e * e);
        let u = 1.0 - beta;
        (s * u + c * u * u, -(s + 2.0 * c * u))
    }
}

/// Half-width of the window around β = 1 where the general law is bridged.
const BRIDGE: f64 = 0.01;

#[cfg(test)]
mod tests {
    use super::*;

    const LAW: CrackLaw = CrackLaw { k: 0.02, low_speed_fit: true };

    #[test]
    fn sign_and_divergence() {
        assert!(LAW.speed(0.5).expect("in domain").0 > 0.0);
        assert!(LAW.speed(2.0).expect("in domain").0 < 0.0);
        assert!(LAW.speed(0.02 * 1.0001).expect("in domain").0 > 1e4);
        assert!(LAW.speed(49.99).expect("in domain").0 < -1e4);
        assert!(LAW.speed(0.02).is_none() && LAW.speed(50.0).is_none() && LAW.speed(f64::NAN).is_none());
    }

    #[test]
    fn derivative_matches_finite_differences() {
        for law in [LAW, CrackLaw { k: 0.02, low_speed_fit: false }, CrackLaw { k: 0.1, low_speed_fit: false }] {
            for &b in &[0.03, 0.1, 0.5, 0.9, 1.1, 2.0, 5.0, 9.0] {
                if b >= law.beta_max() || b <= law.beta_min() {
                    continue;
                }
                let h = 1e-7 * b;
                let num = (law.speed(b + h).expect("in").0 - law.speed(b - h).expect("in").0) / (2.0 * h);
                let ana = law.speed(b).expect("in").1;
                assert!((num - ana).abs() <= 1e-5 * ana.abs().max(1e-3), "{law:?} β={b}: {num} vs {ana}");
            }
        }
    }

    #[test]
    fn bridge_keeps_the_sign_and_joins_the_general_law() {
        let law = CrackLaw { k: 0.05, low_speed_fit: false };
        assert_eq!(law.speed(1.0).expect("in").0, 0.0);
        for i in 1..100 {
            let u = 0.0101 * i as f64 / 100.0;
            assert!(law.speed(1.0 - u).expect("in").0 > 0.0);
            assert!(law.speed(1.0 + u).expect("in").0 < 0.0);
        }
        for b in [0.99, 1.01] {
            let inside = law.speed(b + (1.0 - b) * 1e-9).expect("in").0;
            let outside = law.speed(b - (1.0 - b) * 1e-9).expect("in").0;
            assert!((inside - outside).abs() < 1e-6, "{b}: {inside} vs {outside}");
        }
    }

    #[test]
    fn low_speed_fits_join_the_general_law() {
        // At the ends of the fit ranges the two forms agree to about 1 %.
        let fit = |b: f64| LAW.speed(b).expect("in").0;
        let general = |b: f64| CrackLaw { k: 0.02, low_speed_fit: false }.speed(b).expect("in").0;
        assert!((fit(0.2901) / general(0.2901) - 1.0).abs() < 0.02);
        assert!((fit(3.699) / general(3.699) - 1.0).abs() < 0.02);
    }
}
