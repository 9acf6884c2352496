//! Scene "Stokes number" (thesis Fig. 4.1): Ωt_s against mass for compact
//! grains and porous aggregates, with and without Newton drag.

use super::common::DiskParams;
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::aggregate::{Aggregate, DragRegime, stopping_time};
use crate::physics::constants::AU;
use crate::scene::core::{
    Censored, Context, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the Stokes-number scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// Disk and monomers.
    #[param(flatten)]
    pub disk: DiskParams,
    /// where the particles are
    #[param(quantity = quantities::disk_radius, default = 5.0)]
    pub radius_au: f64,
    /// filling factor of the constant-φ family
    #[param(label = "porous φ", range(1e-6, 1.0), log, default = 1e-4)]
    pub porous_filling: f64,
    /// D_f of the fractal family
    #[param(label = "fractal dimension", range(1.5, 3.0), default = 2.5)]
    pub fractal_dimension: f64,
    /// end of the mass axis
    #[param(quantity = quantities::max_monomers, default = 1e30)]
    pub max_monomers: f64,
}

/// The drag regimes in the order a growing particle meets them: 0 Epstein,
/// 1 Stokes, 2 intermediate, 3 Newton.
fn regime_rank(regime: DragRegime) -> usize {
    match regime {
        DragRegime::Epstein => 0,
        DragRegime::Stokes => 1,
        DragRegime::Intermediate => 2,
        DragRegime::Newton => 3,
    }
}

/// The mass in `[lo, hi]` where `past` turns true (false at `lo`, true at
/// `hi`), by bisection in ln m to 10⁻¹² relative.
fn boundary(lo: f64, hi: f64, past: impl Fn(f64) -> bool) -> f64 {
    let (mut a, mut b) = (lo.ln(), hi.ln());
    while b - a > 1e-12 {
        let m = 0.5 * (a + b);
        if past(m.exp()) { b = m } else { a = m }
    }
    b.exp()
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "stokes-number",
        title: "Stokes number",
        source: "Sects. 4.2.1–4.2.2, App. 5.A; Eqs. 4.1–4.10; Fig. 4.1",
        explanation: "The stopping time of a particle of mass m and filling factor φ at the midplane: \
Epstein drag t_s = 3m/(4ρ_g v_th A) for a < 9λ_mfp/4, Stokes drag 4a/(9λ) times that beyond, and for \
particle Reynolds numbers Re_p = 4av_dg/(v_th λ) > 1 the drag coefficient C_D = 24Re^{-3/5} \
    (1 < Re < 800) or 0.44 (4.10), where t_s = 2m/(C_D ρ_g v_dg A) depends on the velocity relative to \
the gas and is found by iteration. Compact grains reach Ωt_s = 1 in the Epstein regime; D_f = 2.5 \
aggregates switch to Stokes drag near Ωt_s ~ 1e-3 and to Newton drag before Ωt_s = 1. Dashed: \
Epstein and Stokes drag only. A is the orientation-averaged projected area of Okuzumi et al. (2009): \
πa² for solid grains, about a third of it for hit-and-stick aggregates of 10⁴ monomers.",
        heavy: false,
    };

    const CENSORED: &'static [Censored] = &[
        Censored {
            key: "compact_st1",
            above: None,
            undefined: Some("compact grains stay below Ωt_s = 1 up to the end of the mass axis"),
        },
        Censored {
            key: "porous_st1",
            above: None,
            undefined: Some("the constant-φ family stays below Ωt_s = 1 up to the end of the mass axis"),
        },
        Censored {
            key: "fractal_stokes_onset",
            above: None,
            undefined: Some("the fractal family stays in Epstein drag up to the end of the mass axis"),
        },
        Censored {
            key: "fractal_re_one",
            above: None,
            undefined: Some("the fractal family stays below Re_p = 1 up to the end of the mass axis"),
        },
        Censored {
            key: "fractal_newton",
            above: None,
            undefined: Some("the fractal family does not reach Newton drag up to the end of the mass axis"),
        },
    ];

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "newton_iterations",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a diagnostic, a whole number of iterations",
            resolution: None,
        },
        Declared {
            scalar: "*",
            parameter: "alpha",
            kind: Irregularity::Ignored,
            why: "α draws only the line Ωt_s = α: stopping times and drag regimes do not depend on it",
            resolution: None,
        },
    ];

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let disk = p.disk.disk();
        let mono = p.disk.monomer();
        let env = disk.local(p.radius_au * AU);
        let m0 = mono.mass();
        let ns = logspace(1.0, p.max_monomers, 241);
        // Filling factor of each family at N monomers.
        let filling_of = |family: usize, n: f64| match family {
            0 => 1.0,
            1 => p.porous_filling,
            _ => n.powf(1.0 - 3.0 / p.fractal_dimension).min(1.0),
        };
        let families = [
            "compact".to_string(),
            format!("constant φ = {}", crate::figure::human(p.porous_filling)),
            format!("fractal, D_f = {}", crate::figure::human(p.fractal_dimension)),
        ];
        // The thesis's colours: compact red, constant φ yellow, fractal green.
        let colours = [0, 3, 2];
        let mut fig = Figure::new(
            "stokes-number",
            "Stokes number (Fig. 4.1)",
            Axis::log("mass m / m₀", ""),
            Axis::log("Ωt_s", ""),
        );
        let mut scalars = Vec::new();
        let mut worst_iterations = 0;
        for (k, name) in families.iter().enumerate() {
            let filling = |n: f64| filling_of(k, n);
            let mut full = Vec::new();
            let mut no_newton = Vec::new();
            // The first grid index of each regime (Stokes, intermediate, Newton).
            let mut first = [None::<usize>; 3];
            for (j, &n) in ns.iter().enumerate() {
                let agg = Aggregate { mass: n * m0, filling: filling(n) };
                let s = stopping_time(&env, &mono, &agg, true);
                worst_iterations = worst_iterations.max(s.iterations);
                let st = s.time * env.omega;
                full.push([n, st]);
                no_newton.push([n, stopping_time(&env, &mono, &agg, false).time * env.omega]);
                let rank = regime_rank(s.regime);
                for (i, slot) in first.iter_mut().enumerate() {
                    if slot.is_none() && rank == i + 1 {
                        *slot = Some(j);
                    }
                }
            }
            // A boundary between grid points, found by bisection in ln m (to
            // 10⁻¹² relative), so that it does not depend on the grid.
            let regime_at = |n: f64| {
                let agg = Aggregate { mass: n * m0, filling: filling(n) };
                regime_rank(stopping_time(&env, &mono, &agg, true).regime)
            };
            let st_at = |n: f64| {
                let agg = Aggregate { mass: n * m0, filling: filling(n) };
                stopping_time(&env, &mono, &agg, true).time * env.omega
            };
            if k == 2 {
                let keys = ["fractal_stokes_onset", "fractal_re_one", "fractal_newton"];
                let labels = [
                    "D_f family: Stokes drag from m/m₀",
                    "D_f family: Re_p > 1 from m/m₀",
                    "D_f family: C_D = 0.44 from m/m₀",
                ];
                for i in 0..3 {
                    let value = match first[i] {
                        Some(0) => ns[0],
                        Some(j) => boundary(ns[j - 1], ns[j], |n| regime_at(n) > i),
                        None => f64::NAN,
                    };
                    scalars.push(Scalar { key: keys[i], label: labels[i], value, unit: "" });
                }
            }
            if k < 2 {
                let value = match full.iter().position(|q| q[1] >= 1.0) {
                    Some(0) => ns[0],
                    Some(j) => boundary(ns[j - 1], ns[j], |n| st_at(n) >= 1.0),
                    None => f64::NAN,
                };
                let (key, label) = if k == 0 {
                    ("compact_st1", "compact: Ωt_s = 1 at m/m₀")
                } else {
                    ("porous_st1", "constant φ: Ωt_s = 1 at m/m₀")
                };
                scalars.push(Scalar { key, label, value, unit: "" });
            }
            fig = fig.with(Series::new(name.clone(), full, Style::Line, colours[k])).with(Series::new(
                format!("{name}, Epstein + Stokes only"),
                no_newton,
                Style::Dashed,
                colours[k],
            ));
        }
        fig = fig.with(Series::new("Ωt_s = 1", vec![[1.0, 1.0], [p.max_monomers, 1.0]], Style::Dashed, 6)).with(
            Series::new(
                format!("Ωt_s = α = {}", crate::figure::human(env.alpha)),
                vec![[1.0, env.alpha], [p.max_monomers, env.alpha]],
                Style::Dashed,
                7,
            ),
        );
        scalars.push(Scalar {
            key: "newton_iterations",
            label: "largest Newton-drag iteration count",
            value: worst_iterations as f64,
            unit: "",
        });
        scalars.push(Scalar {
            key: "mean_free_path",
            label: "mean free path λ_mfp",
            value: env.mean_free_path,
            unit: "m",
        });
        scalars.push(Scalar { key: "monomer_mass", label: "monomer mass m₀", value: m0, unit: "kg" });
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
