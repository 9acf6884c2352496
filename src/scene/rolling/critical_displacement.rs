//! Scene "Critical displacement" (thesis Fig. 3.4): the rolling displacement
//! at which a pinned contact starts to roll, against radius.

use super::common::RollingParams;
use super::common::family;
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::rolling::critical_displacement;
use crate::scene::controls::LogRange;
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the critical-displacement scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The contact (default: PSL on silicon, γ = 0.1 J m⁻²).
    #[param(flatten, except("radius"), default = RollingParams::of("PSL", "silicon", true, 12e-6, 0.1))]
    pub contact: RollingParams,
    /// smallest sphere radius
    #[param(
        figure_only,
        label = "smallest radius",
        unit = "m",
        shown("µm", 1e6),
        range(1e-8, 1e-2),
        log,
        default = 1e-6
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
        default = 1e-4
    )]
    pub r_max: f64,
    /// first curve of the family
    #[param(figure_only, label = "smallest Δγ/γ", range(1e-3, 100.0), log, default = 1.0)]
    pub h_min: f64,
    /// last curve of the family
    #[param(figure_only, label = "largest Δγ/γ", range(1e-3, 100.0), log, default = 4.0)]
    pub h_max: f64,
    /// curves in the family
    #[param(figure_only, label = "Δγ/γ curves", range(1, 8), default = 3)]
    pub n_h: usize,
    /// 73–94 nm at 22.5–26.8 µm diameter
    #[param(figure_only, label = "Ding et al. range", default = true)]
    pub ding_data: bool,
}

/// Ding et al.'s range: (diameters [m], ξ_crit [m]).
pub const DING: ((f64, f64), (f64, f64)) = ((22.5e-6, 26.8e-6), (73e-9, 94e-9));

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "critical-displacement",
        title: "Critical displacement",
        source: "Sects. 3.2.3, 3.3.1; Fig. 3.4",
        explanation: "A torque on a sphere in JKR equilibrium first displaces its centre of mass while the \
contact stays pinned: the trailing edge only opens once G₁ − G₂ reaches the adhesion hysteresis \
Δγ = G_op − G_cl. That happens at ξ_crit = (a_eq/12)(Δγ/γ) (3.16), a fixed fraction of the contact \
radius (~ R^{2/3}), not the atomic spacing (~0.3 nm) assumed by Dominik & Tielens. Ding et al. \
    (2007) saw the stiffness of PSL spheres on silicon change after 73–94 nm (diameters 22.5–26.8 µm): \
Δγ/γ ≈ 2.5 in the thesis. The default γ = 0.1 J/m² for PSL contacts follows the thesis's PSL \
case (Sect. 3.3.1).",
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
        let mut fig = Figure::new(
            "critical-displacement",
            "Critical rolling displacement (Fig. 3.4)",
            Axis::log("sphere radius", "µm"),
            Axis::log("ξ_crit", "nm"),
        );
        for (i, h) in family(p.h_min, p.h_max, p.n_h).into_iter().enumerate() {
            let pts = radii.iter().map(|&r| [r * 1e6, critical_displacement(&c.pair(r), h) * 1e9]).collect();
            fig = fig.with(Series::new(format!("Δγ/γ = {}", crate::figure::human(h)), pts, Style::Line, i));
        }
        fig = fig.with(Series::new(
            "ξ = 0.3 nm (Dominik & Tielens)",
            vec![[p.r_min * 1e6, 0.3], [p.r_max * 1e6, 0.3]],
            Style::Dashed,
            6,
        ));
        let ((d0, d1), (x0, x1)) = DING;
        let (r0, r1) = (d0 / 2.0 * 1e6, d1 / 2.0 * 1e6);
        let (y0, y1) = (x0 * 1e9, x1 * 1e9);
        if p.ding_data {
            fig = fig.with(Series::new(
                "Ding et al. (2007) range",
                vec![[r0, y0], [r1, y0], [r1, y1], [r0, y1], [r0, y0]],
                Style::Line,
                3,
            ));
        }
        // The hysteresis that puts ξ_crit at the middle of Ding et al.'s range.
        let mid_r = 0.25 * (d0 + d1);
        let per_unit = critical_displacement(&c.pair(mid_r), 1.0);
        let scalars = vec![
            Scalar {
                key: "a_eq_ding",
                label: "a_eq at d = 24.65 µm",
                value: c.pair(mid_r).jkr_equilibrium_radius(),
                unit: "m",
            },
            Scalar {
                key: "xi_crit_ding_low",
                label: "ξ_crit at d = 22.5 µm, Δγ/γ = 2.5",
                value: critical_displacement(&c.pair(d0 / 2.0), 2.5),
                unit: "m",
            },
            Scalar {
                key: "xi_crit_ding_high",
                label: "ξ_crit at d = 26.8 µm, Δγ/γ = 2.5",
                value: critical_displacement(&c.pair(d1 / 2.0), 2.5),
                unit: "m",
            },
            Scalar {
                key: "hysteresis_ding",
                label: "Δγ/γ for the middle of Ding's range",
                value: 0.5 * (x0 + x1) / per_unit,
                unit: "",
            },
        ];
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
