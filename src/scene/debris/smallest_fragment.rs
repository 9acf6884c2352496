//! Scene "Smallest fragment" (thesis Fig. 6.1 top): the energy-limited
//! smallest fragment against collider size.

use super::common::{FragmentParams, materials};
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::debris::{smallest_fragment, splitting_limit};
use crate::scene::controls::LogRange;
use crate::scene::core::{Censored, Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the smallest-fragment scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// Collision parameters.
    #[param(flatten)]
    pub collision: FragmentParams,
    /// start of the collider-size axis
    #[param(figure_only, label = "smallest collider", unit = "m", range(1e-9, 1e6), log, default = 1e-6)]
    pub s0_min: f64,
    /// end of the collider-size axis
    #[param(figure_only, label = "largest collider", unit = "m", range(1e-9, 1e6), log, default = 1e4)]
    pub s0_max: f64,
    /// bodies above this are held by gravity
    #[param(figure_only, label = "self-gravity size", unit = "m", range(1.0, 1e5), log, default = 100.0)]
    pub gravity_size: f64,
}

/// The collider radius whose smallest fragment is `target` (m), by bisection in log s₀.
pub fn collider_for(p: &FragmentParams, material_index: usize, target: f64) -> Option<f64> {
    let m = materials().get(material_index)?;
    let f = |s0: f64| smallest_fragment(m, p.alpha, p.eta, p.velocity, s0, p.s_max(s0)).ok();
    let (mut lo, mut hi) = (1e-9f64, 1e9f64);
    // s_min falls with s₀ where it is defined; find the crossing.
    if f(hi)? > target {
        return None;
    }
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        match f(mid) {
            Some(s) if s <= target => hi = mid,
            _ => lo = mid,
        }
    }
    Some(hi)
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "smallest-fragment",
        title: "Smallest fragment",
        source: "Sect. 6.2; Eqs. 6.1–6.6; Fig. 6.1 (top)",
        explanation: "Fragments follow n(s) = C s^{-α} (6.1) with 3 < α < 4, so the mass sits in the largest \
and the surface in the smallest. Mass conservation, M_frag = 2M₀, fixes C (6.3); if a fraction η of \
the kinetic energy ½μv² (μ = M₀/2) makes the new surface γ(A_frag − 8πs₀²), the smallest fragment \
is bounded: for α = 3.5, s_min = (24γs₀/(ηρs₀v² + 24γ))² / s_max (6.4). Slow collisions can only \
split the colliders, s_min ≈ 5γ/(ηρv²) (6.6, dotted), close to the smallest body that can be split, \
    3γ/(ηρv²) (6.5). Above the mass-conservation line s_min would exceed s_max; beyond ~100 m self-gravity \
holds bodies together (shaded in the thesis, drawn here as limit lines).",
        heavy: false,
    };

    const CENSORED: &'static [Censored] = &[Censored {
        key: "collider_for_1um_silicate",
        above: Some((1e9, "no collider up to 10⁹ m makes silicate fragments as small as 1 µm")),
        undefined: None,
    }];

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let sizes = LogRange::new("s0_min/s0_max", p.s0_min, p.s0_max, 200)?.values();
        let c = &p.collision;
        let mut fig = Figure::new(
            "smallest-fragment",
            "Smallest fragment (Fig. 6.1, top)",
            Axis::log("collider size s₀", "m"),
            Axis::log("smallest fragment s_min", "m"),
        );
        let mut scalars = Vec::new();
        for (i, m) in materials().iter().enumerate() {
            let pts: Vec<[f64; 2]> = sizes
                .iter()
                .filter_map(|&s0| {
                    smallest_fragment(m, c.alpha, c.eta, c.velocity, s0, c.s_max(s0)).ok().map(|s| [s0, s])
                })
                .collect();
            fig = fig.with(Series::new(m.name, pts, Style::Line, i));
            let split = splitting_limit(m, c.eta, c.velocity);
            fig = fig.with(Series::new(
                format!("{} limit (6.6)", m.name),
                vec![[p.s0_min, split], [p.s0_max, split]],
                Style::Dotted,
                i,
            ));
            scalars.push(Scalar {
                key: ["split_silicate", "split_ice", "split_aggregate"][i],
                label: [
                    "splitting limit (6.6), silicate",
                    "splitting limit (6.6), ice",
                    "splitting limit (6.6), aggregate",
                ][i],
                value: split,
                unit: "m",
            });
        }
        fig = fig
            .with(Series::new(
                "mass conservation: s_min = s_max",
                sizes.iter().map(|&s| [s, c.s_max(s)]).collect(),
                Style::Line,
                6,
            ))
            .with(Series::new("self-gravity", vec![[p.gravity_size, 1e-12], [p.gravity_size, 1e6]], Style::Dashed, 6));
        scalars.push(Scalar {
            key: "collider_for_1um_silicate",
            label: "collider making 1 µm silicate fragments",
            // None: not even the largest collider searched (10⁹ m) makes them.
            value: collider_for(c, 0, 1e-6).unwrap_or(f64::INFINITY),
            unit: "m",
        });
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig],
            notes: vec![
                "Points where s_min would exceed s_max (too little energy for a fragment distribution) are not drawn."
                    .into(),
            ],
            extra: crate::scene::core::Extra::None,
        })
    }
}
