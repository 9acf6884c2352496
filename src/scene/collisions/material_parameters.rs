//! Scene "Material parameters" (thesis Figs. 2.7 and 2.8): the best-fit
//! surface energies, yield strengths and relaxation times of the 17
//! experiments against size.

use crate::figure::{Axis, Figure, Fill, Series, Shape, Style};
use crate::physics::contact::Pair;
use crate::physics::experiments::{Bounded, experiments};
use crate::physics::material::{Material, combined_modulus};
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the material-parameters scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// steel, R = 3.18 mm, v_y = 0.3 m/s
    #[param(figure_only, label = "Lifshitz & Kolsky point", default = true)]
    pub lifshitz_kolsky: bool,
    /// Y ~ l^{-1/2} and Y ~ l^{-1}
    #[param(figure_only, label = "power-law guides", default = true)]
    pub guides: bool,
}

/// The points of one panel: values with error bars, and one-sided limits.
#[derive(Default)]
struct Column {
    values: Vec<[f64; 2]>,
    bars: Vec<Series>,
    lower: Vec<[f64; 2]>,
    upper: Vec<[f64; 2]>,
}

impl Column {
    /// Adds a fitted quantity at `x`, divided by `norm`.
    fn add(&mut self, x: f64, b: &Bounded, norm: f64, color: usize) {
        match *b {
            Bounded::Value { best, plus, minus } => {
                self.values.push([x, best / norm]);
                let lo = (best - minus).max(best * 1e-3) / norm;
                self.bars.push(Series::new("", vec![[x, lo], [x, (best + plus) / norm]], Style::Line, color));
            }
            Bounded::Above(v) => self.lower.push([x, v / norm]),
            Bounded::Below(v) => self.upper.push([x, v / norm]),
            Bounded::Fixed(_) | Bounded::Undetermined { .. } => {}
        }
    }
}

/// Hertz time (2.22) of equal spheres of reduced radius `r` with E* = 10 GPa,
/// ρ = 2000 kg m⁻³ and v = 10 m/s, the typical values of Fig. 2.8(b).
fn typical_hertz_time(r: f64) -> f64 {
    let m = crate::physics::sphere_mass(2000.0, 2.0 * r) / 2.0;
    Pair { modulus: 1e10, radius: r, mass: m, surface_energy: 0.0 }.hertz_time(10.0)
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "material-parameters",
        title: "Material parameters",
        source: "Sect. 2.4.2; Figs. 2.7, 2.8",
        explanation: "The fitted parameters of Table 2.3 against size. Surface energies are normalised to \
the literature value γ_L = 2(γ₁γ₂)^{1/2} of Table 2.2 and mostly lie within a factor of two of it. \
Yield strengths are normalised to Young's modulus of the softer material; most experiments give only \
lower limits (triangles). Against the plastic length scale l = (15m*v²R²/(16E*))^{1/5} (2.33, at half the \
largest velocity) they approach the theoretical strength 0.2E at small l; the guides show the \
Hall–Petch-like Y ~ l^{-1/2} and Y ~ l^{-1}. Relaxation times lie far below the Hertz collision \
time t_H (2.22; E* = 10 GPa, ρ = 2 g/cm³, v = 10 m/s) and grow with the reduced radius.",
        heavy: false,
    };

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let (mut g, mut y, mut l, mut t) = (Column::default(), Column::default(), Column::default(), Column::default());
        let mut within_two = 0;
        for e in experiments() {
            let r_um = e.reduced_radius() * 1e6;
            let gamma_l = e.literature_surface_energy().unwrap_or(f64::NAN);
            let e_soft = e.softer_modulus().unwrap_or(f64::NAN);
            let length = e.plastic_length().unwrap_or(f64::NAN);
            g.add(r_um, &e.gamma, gamma_l, 1);
            y.add(r_um, &e.yield_strength, e_soft, 1);
            l.add(length * 1e6, &e.yield_strength, e_soft, 1);
            t.add(r_um, &e.t_vis, 1.0, 1);
            let ratio = e.gamma.representative() / gamma_l;
            within_two += usize::from((0.5..=2.0).contains(&ratio));
        }
        let radius_axis = || Axis::log("reduced radius R", "µm");
        let mut fig_g =
            Figure::new("surface-energy", "Surface energy (Fig. 2.7a)", radius_axis(), Axis::log("γ / γ_L", ""))
                .with(Series::new("fit", g.values, Style::Points, 1))
                .with(Series::new("γ = γ_L", vec![[0.3, 1.0], [2000.0, 1.0]], Style::Line, 6));
        fig_g.series.extend(g.bars);
        let mut fig_y =
            Figure::new("yield-strength", "Yield strength (Fig. 2.7b)", radius_axis(), Axis::log("Y / E_softer", ""))
                .with(Series::new("fit", y.values, Style::Points, 1))
                .with(Series::new("lower limit", y.lower, Style::LowerLimit, 6))
                .with(Series::new("theoretical 0.2 E", vec![[0.3, 0.2], [2000.0, 0.2]], Style::Dotted, 3));
        fig_y.series.extend(y.bars);

        let mut fig_l = Figure::new(
            "yield-length",
            "Yield strength against length scale (Fig. 2.8a)",
            Axis::log("length scale l (2.33)", "µm"),
            Axis::log("Y / E", ""),
        )
        .with(Series::new("fit", l.values.clone(), Style::Points, 1))
        .with(Series::new("lower limit", l.lower, Style::LowerLimit, 6))
        .with(Series::new("theoretical 0.2 E", vec![[0.01, 0.2], [1e3, 0.2]], Style::Dotted, 3));
        fig_l.series.extend(l.bars);
        if p.guides
            && let Some(&[l0, y0]) = l.values.first()
        {
            let ls = logspace(0.01, 1e3, 20);
            fig_l = fig_l
                .with(Series::new(
                    "Y ∝ l^(−1/2)",
                    ls.iter().map(|&l| [l, y0 * (l / l0).powf(-0.5)]).collect(),
                    Style::Dashed,
                    0,
                ))
                .with(Series::new(
                    "Y ∝ l^(−1)",
                    ls.iter().map(|&l| [l, y0 * (l / l0).powf(-1.0)]).collect(),
                    Style::Dashed,
                    4,
                ));
        }
        let mut lk = None;
        // The point is computed whether or not it is drawn: its scalar is
        // the scene's with either setting.
        if let Some(steel) = Material::named("stainless steel") {
            // Equal steel spheres of radius 3.18 mm that yield at 0.3 m/s: invert (2.28).
            let r: f64 = 3.18e-3;
            let m = crate::physics::sphere_mass(steel.density, r);
            let pair =
                Pair { modulus: combined_modulus(steel, steel), radius: r / 2.0, mass: m / 2.0, surface_energy: 0.0 };
            let v_y: f64 = 0.3;
            let p_y = (v_y * v_y * pair.mass * pair.modulus.powi(4) / (10.2 * pair.radius.powi(3))).powf(0.2);
            let y_lk = p_y / 1.6;
            let l_lk = (15.0 * pair.mass * v_y * v_y * pair.radius.powi(2) / (16.0 * pair.modulus)).powf(0.2);
            if p.lifshitz_kolsky {
                fig_l = fig_l.with(Series::new(
                    "Lifshitz & Kolsky (1964)",
                    vec![[l_lk * 1e6, y_lk / steel.youngs_modulus]],
                    Style::Symbol(Shape::Square, Fill::Filled),
                    0,
                ));
            }
            lk = Some(y_lk);
        }

        let rs = logspace(0.3, 2000.0, 30);
        let mut fig_t =
            Figure::new("relaxation-time", "Relaxation time (Fig. 2.8b)", radius_axis(), Axis::log("T_vis", "s"))
                .with(Series::new("fit", t.values, Style::Points, 1))
                .with(Series::new("upper limit", t.upper, Style::UpperLimit, 6))
                .with(Series::new(
                    "t_H (2.22)",
                    rs.iter().map(|&r| [r, typical_hertz_time(r * 1e-6)]).collect(),
                    Style::Line,
                    6,
                ))
                .with(Series::new(
                    "10⁻³ t_H",
                    rs.iter().map(|&r| [r, 1e-3 * typical_hertz_time(r * 1e-6)]).collect(),
                    Style::Dashed,
                    6,
                ));
        fig_t.series.extend(t.bars);

        let mut scalars = vec![Scalar {
            key: "gamma_within_factor_two",
            label: "experiments with γ within 2× of γ_L",
            value: within_two as f64,
            unit: "",
        }];
        if let Some(y) = lk {
            scalars.push(Scalar {
                key: "lifshitz_kolsky_y",
                label: "Lifshitz & Kolsky yield strength",
                value: y,
                unit: "Pa",
            });
        }
        Ok(SceneOutput { warnings: Vec::new(),
            scalars,
            figures: vec![fig_g, fig_y, fig_l, fig_t],
            notes: vec!["Lower limits (triangles) mark experiments without plastic yield in their velocity range; upper limits (crosses) on T_vis come from the millimetre spheres.".into()],
            extra: crate::scene::core::Extra::None,
        })
    }
}
