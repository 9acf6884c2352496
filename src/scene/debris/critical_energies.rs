//! Scene "Critical energies" (thesis Fig. 6.1 bottom): the specific energy to
//! split a body against size, beside catastrophic-disruption fits.

use super::common::materials;
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::debris::{BENZ_ASPHAUG_3KMS, splitting_energy};
use crate::scene::controls::LogRange;
use crate::scene::core::{Context, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the critical-energies scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// dotted curves
    #[param(figure_only, label = "low efficiency η", range(1e-6, 1.0), log, default = 1e-3)]
    pub eta_low: f64,
    /// dashed curves
    #[param(label = "high efficiency η", range(1e-6, 1.0), log, default = 1.0)]
    pub eta_high: f64,
    /// start of the size axis
    #[param(figure_only, label = "smallest size", unit = "m", range(1e-9, 1e6), log, default = 1e-6)]
    pub s_min: f64,
    /// end of the size axis
    #[param(figure_only, label = "largest size", unit = "m", range(1e-9, 1e7), log, default = 1e5)]
    pub s_max: f64,
    /// Benz & Asphaug (1999), 3 km/s
    #[param(figure_only, label = "disruption fits", default = true)]
    pub disruption_fits: bool,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "critical-energies",
        title: "Critical energies",
        source: "Sect. 6.2; Fig. 6.1 (bottom)",
        explanation: "The specific energy to split a body of radius s in two, Q = 3γ/(8ηρs) from (6.5) with \
the convention v_f² = 8Q*, for a low η (dashed; 1e-3 in the thesis) and a high η (solid; 1), against catastrophic-disruption \
thresholds Q*_D = Q₀(s/1 cm)^a + Bρ(s/1 cm)^b with a strength regime (small sizes) and a gravity regime \
    (large sizes). Shown: Benz & Asphaug (1999) basalt and ice at 3 km/s (their Table III). Not shown: the \
Beitz et al. (2011) aggregate curve, whose fit is not given in the thesis. Destroying a body takes \
far more energy than splitting it.",
        heavy: false,
    };

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let sizes = LogRange::new("s_min/s_max", p.s_min, p.s_max, 120)?.values();
        let mut fig = Figure::new(
            "critical-energies",
            "Critical energies (Fig. 6.1, bottom)",
            Axis::log("size s", "m"),
            Axis::log("specific energy Q", "J/kg"),
        );
        for (i, m) in materials().iter().enumerate() {
            // As in the thesis: the low efficiency dotted, the high one dashed,
            // the disruption fits solid.
            for (eta, style, tag) in [(p.eta_low, Style::Dotted, "η low"), (p.eta_high, Style::Dashed, "η high")] {
                let pts = sizes.iter().map(|&s| [s, splitting_energy(m, eta, s)]).collect();
                fig = fig.with(Series::new(
                    format!("split {}, {tag} = {}", m.name, crate::figure::human(eta)),
                    pts,
                    style,
                    i,
                ));
            }
        }
        if p.disruption_fits {
            for (k, fit) in BENZ_ASPHAUG_3KMS.iter().enumerate() {
                fig = fig.with(Series::new(
                    fit.name,
                    sizes.iter().map(|&s| [s, fit.q_star(s)]).collect(),
                    Style::Line,
                    4 + k,
                ));
            }
        }
        let silicate = &materials()[0];
        let q_split = splitting_energy(silicate, p.eta_high, 1.0);
        let q_basalt = BENZ_ASPHAUG_3KMS[0].q_star(1.0);
        let scalars = vec![
            crate::scene::core::Scalar {
                key: "q_split_1m",
                label: "splitting energy, 1 m silicate, high η",
                value: q_split,
                unit: "J kg^-1",
            },
            crate::scene::core::Scalar {
                key: "q_basalt_1m",
                label: "basalt Q*_D at 1 m (Benz & Asphaug)",
                value: q_basalt,
                unit: "J kg^-1",
            },
            crate::scene::core::Scalar {
                key: "disruption_over_split",
                label: "Q*_D / splitting energy at 1 m",
                value: q_basalt / q_split,
                unit: "",
            },
        ];
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
