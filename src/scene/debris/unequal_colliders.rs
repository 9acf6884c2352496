//! Scene "Unequal colliders" (thesis Fig. 6.3, App. 6.B): the smallest
//! fragment of a body s₀ hit by colliders of other sizes.

use crate::figure::{Axis, Figure, Series, Style};
use crate::scene::core::{Context, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the unequal-collider scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// mass ratio above which collisions erode
    #[param(label = "erosive mass ratio", range(1.0, 1e6), log, default = 100.0)]
    pub erosive_ratio: f64,
    /// eroded mass / projectile mass
    #[param(label = "smallest κ", range(0.01, 100.0), log, default = 1.0)]
    pub kappa_min: f64,
    /// eroded mass / projectile mass
    #[param(figure_only, label = "largest κ", range(0.01, 100.0), log, default = 10.0)]
    pub kappa_max: f64,
    /// curves of the erosion family
    #[param(figure_only, label = "κ curves", range(1.0, 6.0), default = 3)]
    pub n_kappa: usize,
}

/// s_min(s_x)/s_min(s₀, s₀) for size ratio x = s_x/s₀ in the catastrophic regime.
pub fn normalised_catastrophic(x: f64) -> f64 {
    let q = (1.0 + x.powi(3)).powi(2) / (4.0 * x.powi(3));
    // The largest fragment is half the heavier collider: s_max ∝ max(1, x).
    q * q / x.max(1.0)
}

/// s_min/s_min(equal) in the erosive regime: (κ/4)².
pub fn normalised_erosion(kappa: f64) -> f64 {
    (kappa / 4.0).powi(2)
}

/// The mass ratio in `[lo, hi]` whose catastrophic s_min is smallest, and
/// that s_min normalised: golden-section search in ln(ratio) to 10⁻¹²
/// (the normalised s_min falls with the ratio up to its minimum, then rises,
/// so the search converges to the minimum or to the end `hi` before it).
pub fn best_catastrophic(lo: f64, hi: f64) -> (f64, f64) {
    let f = |u: f64| normalised_catastrophic(u.exp().cbrt());
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    while b - a > 1e-12 {
        if fc < fd {
            (b, d, fd) = (d, c, fc);
            c = b - g * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    // The ends, where the minimum lies outside.
    [(a + b) / 2.0, hi.ln(), lo.ln()]
        .into_iter()
        .map(|u| (u.exp(), f(u)))
        .min_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap_or((1.0, 1.0))
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "unequal-colliders",
        title: "Unequal colliders",
        source: "App. 6.B; Eqs. 6.9–6.11; Fig. 6.3",
        explanation: "A body of size s₀ meets colliders s_x. With μ from (6.9) and s_min << s_max, catastrophic \
fragmentation gives s_min = [6γ(s_p³ + s_t³)²/(ηρv²(s_p s_t)³)]² / s_max (6.10); when the mass ratio \
exceeds 10² the collision only erodes a mass κ m_p, s_min = (6γκ/(ηρv²))² / s_max (6.11). The largest \
fragment is half the heavier collider's mass up to a mass ratio 10², and half of m₀ in the erosive \
regime. Normalised to the equal-size collision, near-equal masses make the smallest fragments among \
catastrophic collisions; in the erosive regime the value depends on κ alone (κ²/16).",
        heavy: false,
    };

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let ratios = logspace(1e-3, 1e9, 241);
        let x_of = |ratio: f64| ratio.cbrt();
        let cat: Vec<[f64; 2]> =
            ratios.iter().filter(|&&r| r <= p.erosive_ratio).map(|&r| [r, normalised_catastrophic(x_of(r))]).collect();
        let mut fig = Figure::new(
            "unequal-colliders",
            "Smallest fragment of unequal collisions (Fig. 6.3)",
            Axis::log("mass ratio m_x / m₀", ""),
            Axis::log("s_min / s_min(equal)", ""),
        )
        .with(Series::new("catastrophic (6.10)", cat, Style::Line, 0))
        .with(Series::new(
            "erosive above",
            vec![[p.erosive_ratio, 1e-3], [p.erosive_ratio, 1e6]],
            Style::Dashed,
            6,
        ));
        let kappas = if p.n_kappa <= 1 {
            vec![p.kappa_min]
        } else {
            logspace(p.kappa_min, p.kappa_max.max(p.kappa_min * 1.000001), p.n_kappa)
        };
        for (i, k) in kappas.iter().enumerate() {
            let v = normalised_erosion(*k);
            fig = fig.with(Series::new(
                format!("erosion (6.11), κ = {}", crate::figure::human(*k)),
                vec![[p.erosive_ratio, v], [1e9, v]],
                Style::Line,
                1 + i,
            ));
        }
        let (best_ratio, best) = best_catastrophic(ratios[0], p.erosive_ratio.max(ratios[0]));
        let scalars = vec![
            crate::scene::core::Scalar {
                key: "best_mass_ratio",
                label: "catastrophic mass ratio with the smallest s_min",
                value: best_ratio,
                unit: "",
            },
            crate::scene::core::Scalar {
                key: "best_normalised",
                label: "its s_min / s_min(equal)",
                value: best,
                unit: "",
            },
            crate::scene::core::Scalar {
                key: "erosion_kappa_min",
                label: "erosive s_min / s_min(equal) at the smallest κ",
                value: normalised_erosion(p.kappa_min),
                unit: "",
            },
        ];
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
