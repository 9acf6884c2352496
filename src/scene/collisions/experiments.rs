//! Scene "Experiments" (thesis Sect. 2.4, Figs. 2.6 and 2.11): the best-fit
//! restitution curves of the 17 collision experiments of Table 2.1.

use super::common::describe;
use crate::figure::{Axis, Figure, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::collision::{Options, Outcome, Setup, collide, sticking_velocity};
use crate::physics::experiments::{Experiment, experiment, experiments};
use crate::physics::plasticity::{e_combined, e_plastic};
use crate::scene::core::{Censored, Context, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// The experiments as (key, label) options.
fn options() -> Vec<(&'static str, &'static str)> {
    experiments().iter().map(|e| (e.key.as_str(), e.label.as_str())).collect()
}

/// Parameters of the experiments scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// experiment of Table 2.1
    #[param(label = "experiment", choices = options(), default = "wall-mica".into())]
    pub experiment: String,
    /// also show every experiment as a small plot
    #[param(figure_only, label = "all 17 (Fig. 2.11)", default = true)]
    pub all: bool,
    /// points per curve
    #[param(figure_only, label = "velocities", range(4.0, 400.0), default = 40)]
    pub n_velocities: usize,
    /// relative tolerance of the integrator (default 1e-5)
    #[param(quantity = quantities::solver_tolerance, default = 1e-5)]
    pub rtol: f64,
}

/// The curves of one experiment: (v, e_A, e_P, e, e_JKR combined with e_P).
fn curves(
    e: &Experiment,
    setup: &Setup,
    n: usize,
    opts: &Options,
    progress: &Progress,
) -> Result<Vec<[f64; 5]>, SceneError> {
    let v_y = setup.yield_velocity();
    logspace(e.v_min, e.v_max, n)
        .par_iter()
        .map(|&v| {
            progress.check()?;
            let c = collide(setup, v, opts)?;
            let e_a = if c.outcome == Outcome::Bounce { c.e_adhesive } else { 0.0 };
            let e_p = e_plastic(v, v_y);
            let e_jkr = setup.pair.e_jkr(v);
            let jkr = if e_jkr > 0.0 { e_combined(e_jkr, e_p) } else { 0.0 };
            Ok([v, e_a, e_p, if e_a > 0.0 { e_combined(e_a, e_p) } else { 0.0 }, jkr])
        })
        .collect()
}

fn tabor(e: &Experiment, setup: &Setup) -> f64 {
    let mut pair = setup.pair;
    pair.surface_energy = e.literature_surface_energy().unwrap_or(pair.surface_energy);
    pair.tabor(setup.z0)
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "experiments",
        title: "Experiments",
        source: "Sect. 2.4, App. 2.D; Tables 2.1–2.3, Figs. 2.6, 2.11",
        explanation: "Seventeen published collision experiments (Table 2.1: micrometre spheres on flat \
targets, millimetre spheres on equal spheres) with the best-fit surface energy γ, relaxation time \
T_vis and yield strength Y of Table 2.3. The model restitution e = (e_A² + e_P² − 1)^{1/2} (2.30) \
combines adhesion with viscoelasticity (e_A, from the full contact model) and plastic yield (e_P, \
Thornton & Ning). The dashed curve is elastic JKR theory (2.24) with the same γ and plasticity: \
without viscoelasticity it cannot produce the plateau below unity that the experiments show. The \
Tabor parameter μ (2.11, with the literature γ_L) above each plot checks the JKR limit (μ > 5). \
A yield strength known only as a lower limit (\"> 67 MPa\") means no yield in the measured \
range, so plasticity is off; an upper limit on T_vis is drawn at the limit.",
        heavy: true,
    };

    const CENSORED: &'static [Censored] = &[
        Censored { key: "v_stick", above: Some((1e4, "no collision bounces up to 10⁴ m/s")), undefined: None },
        Censored {
            key: "v_y",
            above: None,
            undefined: Some("no plastic yield: the fit gives Y only as a lower limit"),
        },
        Censored { key: "gamma_L", above: None, undefined: Some("no literature surface energy for these materials") },
    ];

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let e = experiment(&p.experiment).ok_or_else(|| {
            crate::scene::controls::ParamError::Inconsistent(format!("unknown experiment '{}'", p.experiment))
        })?;
        let setup = e
            .best_fit_setup()
            .ok_or_else(|| crate::scene::controls::ParamError::Inconsistent(format!("{}: unknown material", e.key)))?;
        let opts = Options { rtol: p.rtol, ..Options::default() };
        let rows = curves(e, &setup, p.n_velocities, &opts, progress)?;
        let mu = tabor(e, &setup);
        let title = format!("{} (μ = {mu:.1})", e.label);
        let col = |k: usize| rows.iter().map(|r| [r[0], r[k]]).collect::<Vec<_>>();
        let mut main = Figure::new(
            "experiment",
            &title,
            Axis::log("impact velocity v", "m/s"),
            Axis::linear("coefficient of restitution", ""),
        )
        .with(Series::new("e_A adhesion + viscoelasticity", col(1), Style::Dashed, 1))
        .with(Series::new("e combined (2.30)", col(3), Style::Line, 0))
        .with(Series::new("JKR (2.24) + plasticity", col(4), Style::Dashed, 6));
        if setup.yield_strength.is_some() {
            main.series.insert(1, Series::new("e_P plasticity (2.29)", col(2), Style::Dashed, 3));
        }
        let v_s = sticking_velocity(&setup, &opts, 1e-3)?;
        let mut figures = vec![main];
        if p.all {
            let small: Vec<Figure> = experiments()
                .iter()
                .enumerate()
                .map(|(i, x)| {
                    progress.set(i as f64 / experiments().len() as f64);
                    let s = x.best_fit_setup().ok_or_else(|| {
                        crate::scene::controls::ParamError::Inconsistent(format!("{}: unknown material", x.key))
                    })?;
                    let r = curves(x, &s, p.n_velocities.min(30), &opts, progress)?;
                    let fig = Figure::new(
                        &format!("fig-2-11-{}", x.key),
                        &format!("{} (μ = {:.1})", x.label, tabor(x, &s)),
                        Axis::log("v", "m/s"),
                        Axis::linear("e", ""),
                    )
                    .with(Series::new("model", r.iter().map(|q| [q[0], q[3]]).collect(), Style::Line, 0))
                    .with(Series::new(
                        "JKR",
                        r.iter().map(|q| [q[0], q[4]]).collect(),
                        Style::Dashed,
                        6,
                    ));
                    Ok(fig)
                })
                .collect::<Result<_, SceneError>>()?;
            figures.extend(small);
        }
        let scalars = vec![
            Scalar { key: "gamma", label: "surface energy γ (fit)", value: e.gamma.representative(), unit: "J m^-2" },
            Scalar {
                key: "gamma_L",
                label: "literature γ_L = 2(γ₁γ₂)^½",
                value: e.literature_surface_energy().unwrap_or(f64::NAN),
                unit: "J m^-2",
            },
            Scalar { key: "t_vis", label: "relaxation time T_vis (fit)", value: e.t_vis.representative(), unit: "s" },
            Scalar {
                key: "yield_strength",
                label: "yield strength Y (fit or limit)",
                value: e.yield_strength.representative(),
                unit: "Pa",
            },
            Scalar { key: "reduced_radius", label: "reduced radius R", value: e.reduced_radius(), unit: "m" },
            Scalar { key: "tabor", label: "Tabor parameter μ (γ_L)", value: mu, unit: "" },
            Scalar { key: "v_stick", label: "sticking velocity (model)", value: v_s, unit: "m s^-1" },
            Scalar { key: "v_y", label: "yield velocity v_y (2.28)", value: setup.yield_velocity(), unit: "m s^-1" },
        ];
        let notes = vec![
            format!(
                "{} — {} on {}, {} µm diameter, {}, {}–{} m/s.",
                e.reference,
                e.projectile,
                e.target,
                crate::figure::human(e.diameter * 1e6),
                if e.wall { "sphere on flat target" } else { "equal spheres" },
                e.v_min,
                e.v_max
            ),
            format!(
                "Table 2.3: γ = {}, Y = {}, T_vis = {}.",
                describe(&e.gamma, "J/m²", 1.0),
                describe(&e.yield_strength, "MPa", 1e-6),
                describe(&e.t_vis, "s", 1.0)
            ),
            "The measured points are not printed in the thesis; the curves are the published best fits.".into(),
        ];
        Ok(SceneOutput { warnings: Vec::new(), scalars, figures, notes, extra: crate::scene::core::Extra::None })
    }
}
