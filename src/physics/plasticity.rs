//! Plastic deformation in the Thornton & Ning (1998) model (thesis Sect. 2.3.4).

use super::contact::Pair;

/// Yield velocity v_y = (10.2 R³ p_y⁵ / (m* E*⁴))^{1/2} with p_y = 1.6 Y (2.28), m/s.
/// `yield_strength` Y is in Pa.
pub fn yield_velocity(pair: &Pair, yield_strength: f64) -> f64 {
    let py = 1.6 * yield_strength;
    (10.2 * pair.radius.powi(3) * py.powi(5) / (pair.mass * pair.modulus.powi(4))).sqrt()
}

/// Plastic coefficient of restitution e_P (2.29) for impact speed v and yield velocity v_y.
pub fn e_plastic(v: f64, v_yield: f64) -> f64 {
    let x = v_yield / v;
    if x > 1.0 {
        return 1.0;
    }
    let c = (6.0 * 3f64.sqrt() / 5.0).sqrt();
    c * (1.0 - x * x / 6.0).sqrt() * (x / (x + 2.0 * (1.2 - 0.2 * x * x).sqrt())).powf(0.25)
}

/// Combined restitution e = (e_A² + e_P² − 1)^{1/2} (2.30); 0 when the radicand is negative.
pub fn e_combined(e_adhesive: f64, e_plastic: f64) -> f64 {
    (e_adhesive * e_adhesive + e_plastic * e_plastic - 1.0).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn e_plastic_is_continuous_at_the_yield_velocity() {
        let vy = 3.0;
        let below = e_plastic(vy * (1.0 - 1e-9), vy);
        let above = e_plastic(vy * (1.0 + 1e-9), vy);
        assert_eq!(below, 1.0);
        assert!((above - 1.0).abs() < 1e-6, "{above}");
    }

    #[test]
    fn e_plastic_falls_as_quarter_power_at_high_speed() {
        let vy = 1.0;
        let r = e_plastic(1e6, vy) / e_plastic(1e8, vy);
        assert!((r / 100f64.powf(0.25) - 1.0).abs() < 1e-3, "{r}");
        assert!(e_plastic(10.0, vy) < 1.0);
    }
}
