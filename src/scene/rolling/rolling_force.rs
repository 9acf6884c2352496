//! Scene "Rolling force" (thesis Figs. 3.3, 3.5): the steady rolling force
//! F = M/R from adhesion hysteresis against radius, with the Dominik &
//! Tielens and bulk-loss lines and the measured silica forces.

use super::common::{RollingParams, family};
use crate::figure::{Axis, Figure, Fill, Series, Shape, Style};
use crate::physics::rolling::{bulk_torque, rolling_force, rolling_torque, small_asymmetry_torque};
use crate::scene::controls::LogRange;
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// A measured rolling force with its uncertainty (silica spheres).
struct Measured {
    label: &'static str,
    diameter: f64,
    force: f64,
    error: f64,
}

/// Silica rolling forces of Sect. 3.3.2 (N); Heim et al.'s statistical and
/// systematic errors (0.3 and 1.3 × 10⁻¹⁰ N) are added linearly.
const SILICA: [Measured; 3] = [
    Measured { label: "Heim et al. (1999)", diameter: 1.9e-6, force: 8.5e-10, error: 1.6e-10 },
    Measured { label: "Blum & Wurm (2000)", diameter: 1.9e-6, force: 5.0e-10, error: 2.5e-10 },
    Measured { label: "Gundlach et al. (2011)", diameter: 1.5e-6, force: 12.1e-10, error: 3.6e-10 },
];

/// Parameters of the rolling-force scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The contact (default: equal silica spheres, Fig. 3.5).
    #[param(flatten, except("radius"), default = RollingParams::of("silicate", "silicate", false, 0.95e-6, 0.05))]
    pub contact: RollingParams,
    /// smallest sphere radius
    #[param(
        figure_only,
        label = "smallest radius",
        unit = "m",
        shown("µm", 1e6),
        range(1e-8, 1e-2),
        log,
        default = 2e-7
    )]
    pub r_min: f64,
    /// largest sphere radius
    #[param(
        figure_only,
        label = "largest radius",
        unit = "m",
        shown("µm", 1e6),
        range(1e-8, 1e-2),
        log,
        default = 2e-5
    )]
    pub r_max: f64,
    /// first curve of the family
    #[param(figure_only, label = "smallest Δγ/γ", range(1e-3, 100.0), log, default = 0.25)]
    pub h_min: f64,
    /// last curve of the family
    #[param(figure_only, label = "largest Δγ/γ", range(1e-3, 100.0), log, default = 3.0)]
    pub h_max: f64,
    /// curves in the family
    #[param(figure_only, label = "Δγ/γ curves", range(1, 8), default = 4)]
    pub n_h: usize,
    /// ξ of the Dominik & Tielens line
    #[param(
        figure_only,
        label = "DT displacement ξ",
        unit = "m",
        shown("nm", 1e9),
        range(1e-11, 1e-8),
        log,
        default = 3e-10
    )]
    pub xi_dt: f64,
    /// bulk loss line (3.22)
    #[param(figure_only, quantity = quantities::quality_factor, default = 100.0)]
    pub q: f64,
    /// Heim, Blum & Wurm, Gundlach
    #[param(figure_only, label = "silica measurements", default = true)]
    pub silica_data: bool,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "rolling-force",
        title: "Rolling force",
        source: "Sects. 3.2.4, 3.3, 3.4; Figs. 3.3, 3.5",
        explanation: "Once rolling, the contact's trailing edge opens at G_op and the leading edge closes \
at G_cl, so (3.11) with a₁ ≈ a₂ ≈ a_eq gives the rolling torque M = (R/2)π a_eq Δγ and the force \
F = M/R (for a pushing force at height R); with a_eq ~ R^{2/3}, F ~ R^{2/3}. The dashed line is \
Dominik & Tielens' M = 6πγRξ with ξ = 0.3 nm (3.14), the dotted one the bulk loss \
M_B = (πU_E/Q)(R/2a) (3.22). The silica data (equal spheres, effective radius R = d/4): Heim et al. \
    (1999), Blum & Wurm (2000), Gundlach et al. (2011); the thesis reads them as Δγ/γ ≈ 0.5. For PSL \
on glass (Sümer & Sitti 2008) the thesis infers Δγ/γ ≈ 3; their measured forces are not printed.",
        heavy: false,
    };

    fn material_changed(&mut self) {
        self.contact.material_changed();
    }

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let radii = LogRange::new("r_min/r_max", p.r_min, p.r_max, 60)?.values();
        let c = &p.contact;
        let x = |r: f64| c.pair(r).radius * 1e6;
        let mut fig = Figure::new(
            "rolling-force",
            "Rolling force (Figs. 3.3, 3.5)",
            Axis::log(if c.wall { "sphere radius R" } else { "effective radius R" }, "µm"),
            Axis::log("rolling force F = M/R", "N"),
        );
        for (i, h) in family(p.h_min, p.h_max, p.n_h).into_iter().enumerate() {
            let pts = radii.iter().map(|&r| {
                let pair = c.pair(r);
                [x(r), rolling_force(&pair, rolling_torque(&pair, h))]
            });
            fig = fig.with(Series::new(format!("Δγ/γ = {}", crate::figure::human(h)), pts.collect(), Style::Line, i));
        }
        let dt = radii.iter().map(|&r| {
            let pair = c.pair(r);
            [x(r), rolling_force(&pair, small_asymmetry_torque(&pair, p.xi_dt))]
        });
        fig = fig.with(Series::new(
            format!("Dominik & Tielens, ξ = {} nm", crate::figure::human(p.xi_dt * 1e9)),
            dt.collect(),
            Style::Dashed,
            6,
        ));
        let bulk = radii.iter().map(|&r| {
            let pair = c.pair(r);
            [x(r), rolling_force(&pair, bulk_torque(&pair, p.q))]
        });
        fig =
            fig.with(Series::new(format!("bulk, Q = {}", crate::figure::human(p.q)), bulk.collect(), Style::Dotted, 7));

        let mut scalars = Vec::new();
        let mut notes = Vec::new();
        if p.silica_data {
            for (k, m) in SILICA.iter().enumerate() {
                let r = m.diameter / 2.0;
                let pair = c.pair(r);
                let xr = pair.radius * 1e6;
                // Measurements in grey, one symbol each (● ▲ ■ as in the
                // thesis), apart from the coloured model family.
                let shape = [Shape::Circle, Shape::TriangleUp, Shape::Square][k % 3];
                fig = fig.with(Series::new(m.label, vec![[xr, m.force]], Style::Symbol(shape, Fill::Filled), 6));
                fig = fig.with(Series::new("", vec![[xr, m.force - m.error], [xr, m.force + m.error]], Style::Line, 6));
                let h = 0.5;
                let model = rolling_force(&pair, rolling_torque(&pair, h));
                let inside = (model - m.force).abs() <= m.error;
                notes.push(format!(
                    "{}: measured ({:.1} ± {:.1})×10⁻¹⁰ N at d = {:.1} µm; Δγ/γ = 0.5 gives {:.2}×10⁻¹⁰ N ({}).",
                    m.label,
                    m.force * 1e10,
                    m.error * 1e10,
                    m.diameter * 1e6,
                    model * 1e10,
                    if inside { "inside the error bar" } else { "outside the error bar" }
                ));
            }
        }
        let pair = c.pair(0.95e-6);
        scalars.push(Scalar {
            key: "force_1_9um_h05",
            label: "F at d = 1.9 µm, Δγ/γ = 0.5",
            value: rolling_force(&pair, rolling_torque(&pair, 0.5)),
            unit: "N",
        });
        let pair = c.pair(p.contact.radius);
        scalars.push(Scalar {
            key: "a_eq",
            label: "a_eq at the set radius",
            value: pair.jkr_equilibrium_radius(),
            unit: "m",
        });
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig],
            notes,
            extra: crate::scene::core::Extra::None,
        })
    }
}
