//! Scene "Timescales" (thesis Figs. 4.5, 4.7): growth and drift times of the
//! mass-dominating particle against its mass.

use super::common::TrackParams;
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::constants::YEAR;
use crate::physics::growth::Porosity;
use crate::scene::core::{Context, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the timescale scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The local track.
    #[param(flatten)]
    pub track: TrackParams,
    /// Fig. 4.5 instead of Fig. 4.7
    #[param(label = "collisional compaction only")]
    pub collisional_only: bool,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "timescales",
        title: "Timescales",
        source: "Sects. 4.4.1, 4.5; Figs. 4.5, 4.7",
        explanation: "The growth time t_grow = m/(dm/dt) of the mass-dominating particle from (4.35), \
dm/dt = Σ_d σ_col v_rel/((2π)^{1/2} h_d), against its drift time t_drift = R/|v_drift| (5.8). Brownian \
motion first makes growth slower as particles grow; in the first turbulence regime t_grow stays \
about constant (same-size velocities vanish there and particles sweep up smaller ones: the model \
holds t_grow fixed, as Sect. 4.5 does); beyond t_s = t_η growth speeds up again. Porous aggregates keep \
t_grow << t_drift and outgrow the drift barrier. The dotted line is t_drift/30.",
        heavy: false,
    };

    const DECLARED: &'static [Declared] = &[
        super::common::TRACK_STEP,
        Declared {
            scalar: "*",
            parameter: "ormel_cuzzi",
            kind: Irregularity::Ignored,
            why: "the full closure moves t_grow by up to 8 % where particles are in the intermediate turbulence \
                  regime, but neither scalar: the largest t_grow/t_drift comes later (about 5 × 10⁹ g at the \
                  preset's point), where the two closures give the same velocities, and the drift time does not \
                  depend on velocities between particles",
            resolution: None,
        },
    ];

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let track = p.track.track(if p.collisional_only { Porosity::Collisional } else { Porosity::Full });
        let pts = &track.points;
        let fig = Figure::new(
            "timescales",
            "Growth and drift times of the peak mass (Figs. 4.5, 4.7)",
            Axis::log("mass", "g"),
            Axis::log("time", "yr"),
        )
        .with(Series::new("t_grow", pts.iter().map(|q| [q.mass * 1e3, q.t_grow / YEAR]).collect(), Style::Line, 0))
        .with(Series::new("t_drift", pts.iter().map(|q| [q.mass * 1e3, q.t_drift / YEAR]).collect(), Style::Line, 1))
        .with(Series::new(
            "t_drift / 30",
            pts.iter().map(|q| [q.mass * 1e3, q.t_drift / 30.0 / YEAR]).collect(),
            Style::Dotted,
            1,
        ));
        let worst = pts.iter().filter(|q| q.t_grow.is_finite()).map(|q| q.t_grow / q.t_drift).fold(0.0, f64::max);
        let scalars = vec![
            Scalar { key: "max_tgrow_over_tdrift", label: "largest t_grow / t_drift", value: worst, unit: "" },
            Scalar {
                key: "min_tdrift",
                label: "shortest drift time",
                value: pts.iter().map(|q| q.t_drift).fold(f64::INFINITY, f64::min),
                unit: "s",
            },
        ];
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
