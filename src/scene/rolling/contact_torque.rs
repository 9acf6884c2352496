//! Scene "Contact under torque" (thesis Figs. 3.1, 3.2): the asymmetric
//! pressure distribution of a contact made of two half-discs, its torque
//! contributions, and a side view.

use super::common::RollingParams;
use crate::figure::{Axis, Figure, Fill, Heatmap, Series, Shape, Style};
use crate::physics::rolling::{HalfDiscs, small_asymmetry_torque};
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the contact-under-torque scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The contact (default: a 5 µm PSL sphere on PSL, Fig. 3.2).
    #[param(flatten)]
    pub contact: RollingParams,
    /// rolling displacement relative to a_eq
    #[param(label = "asymmetry ξ/a", range(0.0, 0.5), default = 0.1)]
    pub xi_over_a: f64,
    /// resolution of the maps
    #[param(figure_only, label = "map cells", range(11.0, 301.0), default = 81)]
    pub cells: usize,
}

/// Clips the colour range of a map to ± the 90th percentile of |value| (the
/// pressure is singular at the contact edge).
fn clip(values: &mut [f64]) {
    let mut mags: Vec<f64> = values.iter().filter(|v| **v != 0.0).map(|v| v.abs()).collect();
    if mags.is_empty() {
        return;
    }
    crate::sorting::sort_by_key(&mut mags, |m| *m);
    let c = mags[(mags.len() * 9) / 10];
    for v in values.iter_mut() {
        *v = v.clamp(-c, c);
    }
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "contact-torque",
        title: "Contact under torque",
        source: "Sects. 3.2.1–3.2.2; Figs. 3.1, 3.2",
        explanation: "Under a torque the contact becomes asymmetric. Following Dominik & Tielens it is \
modelled as two half-discs of radii a₁ (x > 0) and a₂ (x < 0) sharing one approach δ (3.8), each \
with the pressure (3.1). The centre of mass (+) and the centre of the contact (star) are offset by \
ξ = (a₂ − a₁)/2 (3.9). The torque is M = E*/(4R)[(a₁² − δR)² − (a₂² − δR)²] (3.10) = \
    (R/2)(πa₁G₁ − πa₂G₂) (3.11) with the strain energy release rates G = E*(a² − δR)²/(2πaR²) (3.7); it \
comes mostly from the crack edges far from the y-axis. For a small asymmetry at zero load \
M = 6πγRξ (3.14), Dominik & Tielens' result.",
        heavy: false,
    };

    fn material_changed(&mut self) {
        self.contact.material_changed();
    }

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let pair = p.contact.pair(p.contact.radius);
        let a_eq = pair.jkr_equilibrium_radius();
        let xi = p.xi_over_a * a_eq;
        let c = HalfDiscs::displaced(&pair, xi);
        let half = 1.15 * c.a1.max(c.a2);
        let n = p.cells;
        let centres: Vec<f64> = (0..n).map(|i| -half + 2.0 * half * (i as f64 + 0.5) / n as f64).collect();
        let mut pressure = Vec::with_capacity(n * n);
        let mut moment = Vec::with_capacity(n * n);
        for &y in &centres {
            for &x in &centres {
                let pr = c.pressure(&pair, x, y);
                pressure.push(pr * 1e-6);
                moment.push(x * pr);
            }
        }
        clip(&mut pressure);
        clip(&mut moment);
        let nm: Vec<f64> = centres.iter().map(|v| v * 1e9).collect();
        let markers = |fig: Figure| {
            fig.with(Series::new("centre of mass", vec![[0.0, 0.0]], Style::Symbol(Shape::Plus, Fill::Filled), 1))
                .with(Series::new("centre of contact", vec![[-xi * 1e9, 0.0]], Style::Marker, 3))
        };
        let mut fig_p = markers(
            Figure::new(
                "pressure-map",
                "Pressure p(x, y) (Fig. 3.2A)",
                Axis::linear("x (rolling direction)", "nm"),
                Axis::linear("y", "nm"),
            )
            .square(),
        );
        fig_p.heatmap = Some(Heatmap::new(nm.clone(), nm.clone(), pressure, "pressure (clipped)", "MPa"));
        let mut fig_m = markers(
            Figure::new(
                "torque-map",
                "Torque contributions x·p (Fig. 3.2B)",
                Axis::linear("x (rolling direction)", "nm"),
                Axis::linear("y", "nm"),
            )
            .square(),
        );
        fig_m.heatmap = Some(Heatmap::new(nm.clone(), nm, moment, "x·p (clipped)", "N/m"));

        // Side view near the contact: sphere surface above the flat, exaggerated vertically.
        let r = pair.radius;
        let xs: Vec<f64> = (0..=200).map(|i| -2.0 * half + 4.0 * half * i as f64 / 200.0).collect();
        let surface: Vec<[f64; 2]> = xs
            .iter()
            .map(|&x| {
                let a = if x >= 0.0 { c.a1 } else { c.a2 };
                let z = if x.abs() <= a { 0.0 } else { (x * x - a * a) / (2.0 * r) };
                [x * 1e9, z * 1e9]
            })
            .collect();
        let fig_s = Figure::new(
            "side-view",
            "Side view (Fig. 3.1B; vertical scale exaggerated)",
            Axis::linear("x", "nm"),
            Axis::linear("height above the substrate", "nm"),
        )
        .with(Series::new("sphere surface", surface, Style::Line, 1))
        .with(Series::new("substrate", vec![[xs[0] * 1e9, 0.0], [xs[200] * 1e9, 0.0]], Style::Line, 6))
        .with(Series::new("contact (a₂ | a₁)", vec![[-c.a2 * 1e9, 0.0], [c.a1 * 1e9, 0.0]], Style::Line, 0))
        .with(Series::new("centre of mass", vec![[0.0, 0.0]], Style::Symbol(Shape::Plus, Fill::Filled), 1))
        .with(Series::new("centre of contact", vec![[-xi * 1e9, 0.0]], Style::Marker, 3));

        let (g1, g2) = c.release_rates(&pair);
        let scalars = vec![
            Scalar { key: "a_eq", label: "JKR equilibrium radius a_eq", value: a_eq, unit: "m" },
            Scalar { key: "a1", label: "half-disc radius a₁ (x > 0)", value: c.a1, unit: "m" },
            Scalar { key: "a2", label: "half-disc radius a₂ (x < 0)", value: c.a2, unit: "m" },
            Scalar { key: "xi", label: "rolling displacement ξ", value: xi, unit: "m" },
            Scalar { key: "torque", label: "torque M (3.10), magnitude", value: c.torque(&pair).abs(), unit: "N m" },
            Scalar {
                key: "torque_small",
                label: "6πγRξ (3.14)",
                value: small_asymmetry_torque(&pair, xi),
                unit: "N m",
            },
            Scalar {
                key: "elastic_force",
                label: "elastic force F_E (3.12)",
                value: c.elastic_force(&pair),
                unit: "N",
            },
            Scalar { key: "g1", label: "release rate G₁", value: g1, unit: "J m^-2" },
            Scalar { key: "g2", label: "release rate G₂", value: g2, unit: "J m^-2" },
            Scalar { key: "tabor", label: "Tabor parameter μ (z₀ = 0.3 nm)", value: pair.tabor(3e-10), unit: "" },
        ];
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_p, fig_m, fig_s],
            notes: vec![
                "The maps clip the colour scale at the 90th percentile: the pressure is singular at the contact edge."
                    .into(),
            ],
            extra: crate::scene::core::Extra::None,
        })
    }
}
