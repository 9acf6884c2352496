//! The collision experiments of Table 2.1 with the best fits of Table 2.3
//! (thesis Sect. 2.4, App. 2.D), loaded from `assets/experiments.ron`.

use super::collision::Setup;
use super::contact::Pair;
use super::crack::CrackLaw;
use super::material::{Bodies, Material, TwoBodies, combined_surface_energy};
use serde::{Deserialize, Serialize};
use std::sync::OnceLock;

/// A fitted quantity: a value with asymmetric uncertainty, or a one-sided limit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Bounded {
    /// Best value with the distances to the upper and lower ends of its range.
    Value {
        /// Best fit.
        best: f64,
        /// Upper end minus best.
        plus: f64,
        /// Best minus lower end.
        minus: f64,
    },
    /// Only a lower limit is known ("> x").
    Above(f64),
    /// Only an upper limit is known ("< x").
    Below(f64),
    /// Held fixed at this value, not fitted.
    Fixed(f64),
    /// The data do not determine a range (no more measurements than free
    /// parameters, or an exact fit that leaves χ² < 2 χ²_min empty): the best
    /// point found, which is not a measurement.
    Undetermined {
        /// Best point found.
        best: f64,
    },
}

impl Bounded {
    /// The value to draw a model curve with: the best value, or the limit itself.
    pub fn representative(&self) -> f64 {
        match *self {
            Bounded::Value { best, .. } | Bounded::Undetermined { best } => best,
            Bounded::Above(x) | Bounded::Below(x) | Bounded::Fixed(x) => x,
        }
    }

    /// Lower and upper end of the allowed range (infinite on the open side;
    /// NaN for a fixed or undetermined quantity, which has no measured range).
    pub fn range(&self) -> (f64, f64) {
        match *self {
            Bounded::Value { best, plus, minus } => (best - minus, best + plus),
            Bounded::Above(x) => (x, f64::INFINITY),
            Bounded::Below(x) => (0.0, x),
            Bounded::Fixed(_) | Bounded::Undetermined { .. } => (f64::NAN, f64::NAN),
        }
    }

    /// Whether `x` lies in the range.
    pub fn contains(&self, x: f64) -> bool {
        let (lo, hi) = self.range();
        x >= lo && x <= hi
    }
}

/// One experiment of Table 2.1 with its fit of Table 2.3. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Experiment {
    /// Short identifier, e.g. "wall-mica".
    pub key: String,
    /// Name as in Table 2.3.
    pub label: String,
    /// Publication.
    pub reference: String,
    /// Projectile material (Table 2.2 name).
    pub projectile: String,
    /// Target material (Table 2.2 name).
    pub target: String,
    /// Projectile diameter, m.
    pub diameter: f64,
    /// Sphere on a flat target (true) or two equal spheres (false).
    pub wall: bool,
    /// Lowest velocity examined, m s⁻¹.
    pub v_min: f64,
    /// Highest velocity examined, m s⁻¹.
    pub v_max: f64,
    /// Combined surface energy γ, J m⁻².
    pub gamma: Bounded,
    /// Yield strength Y, Pa.
    pub yield_strength: Bounded,
    /// Viscous relaxation time T_vis, s.
    pub t_vis: Bounded,
}

impl Experiment {
    /// The two materials (looked up in Table 2.2).
    pub fn materials(&self) -> Option<(&'static Material, &'static Material)> {
        Some((Material::named(&self.projectile)?, Material::named(&self.target)?))
    }

    /// Reduced radius R, m.
    pub fn reduced_radius(&self) -> f64 {
        let r = self.diameter / 2.0;
        if self.wall { r } else { r / 2.0 }
    }

    /// Literature surface energy γ_L = 2(γ₁γ₂)^{1/2} of Table 2.2, J m⁻².
    pub fn literature_surface_energy(&self) -> Option<f64> {
        let (a, b) = self.materials()?;
        Some(combined_surface_energy(a, b))
    }

    /// Young's modulus of the softer material, Pa.
    pub fn softer_modulus(&self) -> Option<f64> {
        let (a, b) = self.materials()?;
        Some(a.youngs_modulus.min(b.youngs_modulus))
    }

    /// The model setup for given γ (J m⁻²), T_vis (s) and Y (Pa, `None` for
    /// no plasticity); z₀ = 0.3 nm and k = 0.02 as in the thesis.
    pub fn setup(&self, gamma: f64, t_vis: f64, yield_strength: Option<f64>) -> Option<Setup> {
        let (a, b) = self.materials()?;
        let radius = self.diameter / 2.0;
        let bodies = if self.wall { Bodies::Wall { radius } } else { Bodies::Twins { radius } };
        let two = TwoBodies::new(a, b, bodies);
        Some(Setup {
            pair: Pair { modulus: two.modulus, radius: two.radius, mass: two.mass, surface_energy: gamma },
            t_vis,
            poisson_ratio: two.poisson_ratio,
            z0: 3e-10,
            crack: CrackLaw::thesis(0.02),
            yield_strength,
        })
    }

    /// The setup of the best fit of Table 2.3. A yield strength known only
    /// as a lower limit means no plastic yield in the velocity range, so
    /// plasticity is off; an upper limit on T_vis is used as its value.
    pub fn best_fit_setup(&self) -> Option<Setup> {
        let y = match self.yield_strength {
            Bounded::Value { best, .. } => Some(best),
            _ => None,
        };
        self.setup(self.gamma.representative(), self.t_vis.representative(), y)
    }

    /// The length scale of plastic deformation, l = (15m*v²R²/(16E*))^{1/5}
    /// (2.33) at half the largest velocity, m.
    pub fn plastic_length(&self) -> Option<f64> {
        let s = self.best_fit_setup()?;
        let v = 0.5 * self.v_max;
        Some((15.0 * s.pair.mass * v * v * s.pair.radius.powi(2) / (16.0 * s.pair.modulus)).powf(0.2))
    }
}

static EXPERIMENTS: OnceLock<Vec<Experiment>> = OnceLock::new();

/// The 17 experiments, ordered as Table 2.3 (largest reduced radius first).
pub fn experiments() -> &'static [Experiment] {
    EXPERIMENTS.get_or_init(|| {
        // Compiled into the binary; a malformed asset is caught by the tests.
        ron::from_str(include_str!("../../assets/experiments.ron")).unwrap_or_default()
    })
}

/// Looks an experiment up by key.
pub fn experiment(key: &str) -> Option<&'static Experiment> {
    experiments().iter().find(|e| e.key == key)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_complete_and_consistent() {
        let table: Vec<Experiment> =
            ron::from_str(include_str!("../../assets/experiments.ron")).expect("experiments.ron parses");
        assert_eq!(table.len(), 17);
        for e in &table {
            assert!(e.materials().is_some(), "{}: unknown material", e.key);
            assert!(e.v_min < e.v_max && e.diameter > 0.0, "{}", e.key);
            assert!(e.best_fit_setup().expect("setup").validate().is_ok(), "{}", e.key);
        }
        // Ordered from largest to smallest reduced radius, as Table 2.3.
        assert!(table.windows(2).all(|w| w[0].reduced_radius() >= w[1].reduced_radius()));
        // Only Wall et al.'s mica and silicon have a measured yield strength.
        let finite: Vec<&str> = table
            .iter()
            .filter(|e| matches!(e.yield_strength, Bounded::Value { .. }))
            .map(|e| e.key.as_str())
            .collect();
        assert_eq!(finite, ["wall-mica", "wall-silicon"]);
    }
}
