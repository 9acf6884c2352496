//! Scene "Restitution" (thesis Figs. 2.4, 2.5): the coefficient of
//! restitution against velocity and against reduced radius, and the sticking
//! velocity against radius for several relaxation times.

use super::common::CollisionParams;
use crate::figure::{Axis, Figure, Scale, Series, Style, human};
use crate::parallel::prelude::*;
use crate::physics::collision::{
    Options, Restitution as RestitutionAt, Setup, restitution, sticking_search, sticking_search_near,
    sticking_velocity, sticking_velocity_with_yield,
};
use crate::physics::contact::e_independent;
use crate::physics::crack::{CrackLaw, Relation};
use crate::physics::plasticity;
use crate::scene::controls::{LogRange, ParamError};
use crate::scene::core::{
    Censored, Context, Declared, Irregularity, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::schema::ParamSet;
use crate::solver::sampling::{Refined, interpolate, refine};
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Parameters of the restitution scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The collision; its velocity is the fixed velocity of e(R).
    #[param(flatten)]
    pub collision: CollisionParams,
    /// start of e(v)
    #[param(label = "lowest velocity", unit = "m s^-1", shown("m/s", 1.0), range(1e-3, 1e3), log, default = 0.5)]
    pub v_min: f64,
    /// end of e(v)
    #[param(label = "highest velocity", unit = "m s^-1", shown("m/s", 1.0), range(1e-3, 1e3), log, default = 100.0)]
    pub v_max: f64,
    /// points of e(v)
    #[param(figure_only, label = "velocities", range(2.0, 2000.0), default = 200)]
    pub n_velocities: usize,
    /// start of e(R), v_s(R)
    #[param(
        figure_only,
        label = "smallest reduced radius",
        unit = "m",
        shown("µm", 1e6),
        range(1e-8, 1e-2),
        log,
        default = 1e-7
    )]
    pub r_min: f64,
    /// end of e(R), v_s(R)
    #[param(
        figure_only,
        label = "largest reduced radius",
        unit = "m",
        shown("µm", 1e6),
        range(1e-8, 1e-2),
        log,
        default = 1e-4
    )]
    pub r_max: f64,
    /// points of e(R) and v_s(R)
    #[param(figure_only, label = "radii", range(2.0, 200.0), default = 48)]
    pub n_radii: usize,
    /// first v_s(R) curve
    #[param(
        figure_only,
        label = "smallest T_vis",
        unit = "s",
        shown("s", 1.0),
        range(1e-15, 1e-8),
        log,
        default = 1e-13
    )]
    pub t_vis_min: f64,
    /// last v_s(R) curve
    #[param(
        figure_only,
        label = "largest T_vis",
        unit = "s",
        shown("s", 1.0),
        range(1e-15, 1e-8),
        log,
        default = 1e-10
    )]
    pub t_vis_max: f64,
    /// curves of v_s(R)
    #[param(figure_only, label = "T_vis curves", range(1.0, 8.0), default = 4)]
    pub n_t_vis: usize,
}

impl Params {
    fn check_ranges(&self) -> Result<(), ParamError> {
        LogRange::new("v_min/v_max", self.v_min, self.v_max, 2)?;
        LogRange::new("r_min/r_max", self.r_min, self.r_max, 2)?;
        // One T_vis curve is allowed: equal ends.
        if self.t_vis_min != self.t_vis_max {
            LogRange::new("t_vis_min/t_vis_max", self.t_vis_min, self.t_vis_max, 2)?;
        }
        Ok(())
    }

    /// The collision with equal spheres of reduced radius `r` (or a sphere of
    /// radius `r` on a wall).
    fn at_radius(&self, r: f64) -> CollisionParams {
        let mut c = self.collision.clone();
        if c.wall {
            c.radius_1 = r;
        } else {
            c.radius_1 = 2.0 * r;
            c.radius_2 = 2.0 * r;
        }
        c
    }
}

/// Results of the three panels, kept so that a change of one parameter
/// recomputes only the panels it touches.
#[derive(Debug, Default, Clone)]
pub struct Cache {
    velocity: Option<(RangeKey, Panel)>,
    radius: Option<(RangeKey, Panel)>,
    sticking: Option<(RangeKey, (f64, f64, usize), Panel)>,
}

/// The inputs of a panel: collision parameters and a (low, high, count) range.
type RangeKey = (CollisionParams, f64, f64, usize);

#[derive(Debug, Clone)]
struct Panel {
    figure: Figure,
    scalars: Vec<Scalar>,
    notes: Vec<String>,
}

/// The collision parameters with the velocity cleared (for cache keys of
/// panels that do not depend on it).
fn without_velocity(c: &CollisionParams) -> CollisionParams {
    CollisionParams { velocity: 0.0, ..c.clone() }
}

/// Runs `f` over `items` in parallel with progress and cancellation.
fn par_map<T: Sync, R: Send>(
    items: &[T],
    progress: &Progress,
    done: &AtomicUsize,
    total: usize,
    f: impl Fn(&T) -> Result<R, SceneError> + Sync + Send,
) -> Result<Vec<R>, SceneError> {
    items
        .par_iter()
        .map(|x| {
            progress.check()?;
            let r = f(x)?;
            let n = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress.set(n as f64 / total as f64);
            Ok(r)
        })
        .collect()
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "restitution",
        title: "Restitution",
        source: "Sects. 2.3.3–2.3.4; Figs. 2.4, 2.5",
        explanation: "The coefficient of restitution e_A = −dδ/dt(t_c)/v (2.23) from the full contact model, \
compared with the elastic JKR limit e_JKR = (1 − (v_c/v)²)^{1/2} (2.24) with \
v_c = (14.18/m*)^{1/2}(γ⁵R⁴/E*²)^{1/6} (2.25), the non-adhesive viscoelastic limit \
e_D, and the 'independent' estimate e_I = (e_JKR² + e_D² − 1)^{1/2} (2.27). e_D is the model's own limit \
γ → 0 (Hertz force plus the bulk force (2.19), the force of Brilliantov et al. 1996), \
e_D = 1 − 5.57 A/t_H + … (Schwager & Pöschel 1998), integrated in full; the printed \
e_D ≈ 1 − 1.92 A/t_H (2.26, dotted) has the same scaling but a loss 2.9 times smaller. \
Plastic yield (Thornton & Ning) gives e_P (2.29) above v_y² = 10.2 R³p_y⁵/(m*E*⁴) (2.28), \
combined as e = (e_A² + e_P² − 1)^{1/2} (2.30). The sticking velocity v_s is the edge between \
sticking and bouncing of the full model, found from a bracket by extrapolating e_A of the slowest \
bounces to zero; viscosity at the crack raises it far above v_c for small grains. Above v_s \
e(v) is drawn through adaptively placed collisions, within 5 × 10⁻⁵ of the model.",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "*",
            parameter: "velocity",
            kind: Irregularity::Ignored,
            why: "the velocity fixes e(R), a figure; the scalars are thresholds of e(v) and do not depend on it",
            resolution: None,
        },
        Declared {
            scalar: "*",
            parameter: "v_min",
            kind: Irregularity::Ignored,
            why: "e_max is the largest e on the velocity grid, which ends at v_max: where e rises towards v_max, the \
                  grid's start moves no scalar",
            resolution: None,
        },
    ];

    const CENSORED: &'static [Censored] = &[
        Censored { key: "v_stick", above: Some((1e4, "no collision bounces up to 10⁴ m/s")), undefined: None },
        Censored { key: "v_y", above: None, undefined: Some("no plastic yield: plasticity is off") },
    ];

    /// Six radii for e(R) and v_s(R) (the costly panels).
    fn coarse(&self) -> Option<Self> {
        Some(Params { n_radii: self.n_radii.min(6), ..self.clone() })
    }

    fn material_changed(&mut self) {
        self.collision.material_changed();
    }

    /// The sticking velocity by its own search (as the e(v) panel finds it),
    /// the two closed-form velocities, and the largest e from the e(v) panel
    /// alone, without the other figures.
    fn scalar(&self, key: &str, progress: &Progress) -> Option<Result<f64, SceneError>> {
        let setup = || self.check_ranges().map(|_| self.collision.setup()).map_err(SceneError::from);
        match key {
            "v_stick" => Some(setup().and_then(|s| {
                progress.check()?;
                let opts = self.collision.options();
                let adhesive = sticking_search(&s, &opts, V_STICK_PRECISION)?.velocity;
                Ok(sticking_velocity_with_yield(&s, &opts, adhesive, V_STICK_PRECISION)?)
            })),
            "v_c" => Some(setup().map(|s| s.pair.jkr_sticking_velocity())),
            // The e(v) panel alone: e(R) and v_s(R) do not enter it.
            "e_max" => Some(setup().and_then(|_| {
                let velocities = logspace(self.v_min, self.v_max, self.n_velocities);
                let done = AtomicUsize::new(0);
                let panel = velocity_panel(self, &velocities, progress, &done, velocities.len() + 20)?;
                Ok(panel.scalars.iter().find(|s| s.key == "e_max").map_or(f64::NAN, |s| s.value))
            })),
            "v_y" => Some(setup().map(|s| s.yield_velocity())),
            _ => None,
        }
    }

    /// Computes the scene, reusing panels of `cache` whose inputs did not change.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let cache: &mut Cache = ctx.caches.get();
        p.check_ranges()?;
        let key_c = without_velocity(&p.collision);
        let velocities = logspace(p.v_min, p.v_max, p.n_velocities);
        let radii = logspace(p.r_min, p.r_max, p.n_radii);
        let t_vis: Vec<f64> = logspace(p.t_vis_min, p.t_vis_max.max(p.t_vis_min * 1.000001), p.n_t_vis.max(2))
            .into_iter()
            .take(p.n_t_vis)
            .collect();
        let key_v: RangeKey = (key_c.clone(), p.v_min, p.v_max, p.n_velocities);
        let key_r: RangeKey = (p.collision.clone(), p.r_min, p.r_max, p.n_radii);
        // The v_s(R) panel draws its own T_vis family: the current T_vis is not
        // among its inputs.
        let key_s: RangeKey = (CollisionParams { t_vis: 0.0, ..key_c.clone() }, p.r_min, p.r_max, p.n_radii);
        let family = (p.t_vis_min, p.t_vis_max, p.n_t_vis);
        let need_v = cache.velocity.as_ref().is_none_or(|(k, _)| *k != key_v);
        let need_r = cache.radius.as_ref().is_none_or(|(k, _)| *k != key_r);
        let need_s = cache.sticking.as_ref().is_none_or(|(k, f, _)| *k != key_s || *f != family);
        // Rough work units: a bisection costs ~20 collisions.
        let total = usize::from(need_v) * (velocities.len() + 20)
            + usize::from(need_r) * radii.len()
            + usize::from(need_s) * radii.len() * t_vis.len() * 20;
        let done = AtomicUsize::new(0);
        let total = total.max(1);

        if need_v {
            let panel = velocity_panel(p, &velocities, progress, &done, total)?;
            cache.velocity = Some((key_v, panel));
        }
        if need_r {
            let panel = radius_panel(p, &radii, progress, &done, total)?;
            cache.radius = Some((key_r, panel));
        }
        if need_s {
            let panel = sticking_panel(p, &radii, &t_vis, progress, &done, total)?;
            cache.sticking = Some((key_s, family, panel));
        }
        let mut out = SceneOutput::default();
        let panels = [
            cache.velocity.as_ref().map(|x| &x.1),
            cache.radius.as_ref().map(|x| &x.1),
            cache.sticking.as_ref().map(|x| &x.2),
        ];
        for panel in panels.into_iter().flatten() {
            out.figures.push(panel.figure.clone());
            out.scalars.extend(panel.scalars.iter().cloned());
            out.notes.extend(panel.notes.iter().cloned());
        }
        out.figures.push(crack_law_figure(&p.collision.crack_law()));
        if p.collision.plasticity {
            out.notes.push("e(R) and the v_s(R) panel use e_A; plasticity enters e(v) and v_s through (2.30).".into());
        }
        Ok(out)
    }
}

/// Largest interpolation error of e(v) between adaptive samples: a sample is
/// added wherever the curve through its neighbours misses the model by more.
const E_TOLERANCE: f64 = 5e-5;
/// Relative precision of the sticking velocity of the e(v) panel: fine
/// enough that e just above v_s (where e ∝ (v − v_s)^{1/2}) stays within the
/// tolerance at the velocity grid.
const V_STICK_PRECISION: f64 = 1e-6;
/// Relative precision of the sticking velocities of the v_s(R) panel (a
/// fraction of a pixel on its log axis).
const STICKING_PANEL_PRECISION: f64 = 1e-3;
/// The loosest solver tolerance the v_s(R) panel integrates with (the
/// solver tolerance of the scene where that is looser): against rtol = 10⁻⁶
/// it moves v_s by at most 4.3 × 10⁻⁵ for R = 0.01–1000 µm, T_vis =
/// 10⁻¹⁴–10⁻⁹ s and γ = 0.1–2 J/m², over 20 times below
/// [`STICKING_PANEL_PRECISION`], at a third of the steps.
const STICKING_PANEL_RTOL: f64 = 1e-4;
/// Samples of the first e(v) round, log-spaced over the velocity range.
const COARSE_VELOCITIES: usize = 9;

/// e_A(v) over the velocity range: zero up to v_s, and above it a curve of
/// adaptive samples (e_A² against ln v, cubic between samples, refined by
/// [`refine`] to [`E_TOLERANCE`]), read at `velocities`.
/// Far fewer collisions than velocities where e(v) is smooth; every velocity
/// is computed directly when the curve would need more samples than that.
fn adaptive_restitution(
    setup: &Setup,
    opts: &Options,
    velocities: &[f64],
    progress: &Progress,
    done: &AtomicUsize,
    total: usize,
) -> Result<(Vec<f64>, f64), SceneError> {
    let e_of = |v: &f64| -> Result<f64, SceneError> { Ok(restitution(setup, *v, opts)?.e_adhesive) };
    let (v_lo, v_hi) = (velocities[0], velocities[velocities.len() - 1]);
    let coarse = logspace(v_lo, v_hi, COARSE_VELOCITIES);
    // The search for v_s is sequential: run it beside the first round.
    let (search, first) = crate::parallel::join(
        || sticking_search(setup, opts, V_STICK_PRECISION),
        || par_map(&coarse, progress, done, total, e_of),
    );
    let (search, first) = (search?, first?);
    progress.check()?;
    let [stick, bounce] = search.bracket;
    let v_s = search.velocity;
    let direct = |progress: &Progress| par_map(velocities, progress, done, total, e_of);
    if v_s >= v_hi {
        // The search found no bounce below v_hi: the range sticks, unless a
        // collision of the first round bounced (a window of bouncing between
        // the search's doublings), and then every velocity is computed.
        if first.iter().any(|&e| e > 0.0) {
            return Ok((direct(progress)?, v_s));
        }
        return Ok((vec![0.0; velocities.len()], v_s));
    }
    if coarse.iter().zip(&first).any(|(&v, &e)| v > bounce && e == 0.0) {
        // Something sticks above v_s: e(v) is not one smooth branch.
        return Ok((direct(progress)?, v_s));
    }
    // Samples of e_A² against ln v from v_s (or the start of the range) up.
    let start = v_lo.max(bounce);
    let mut samples: Vec<[f64; 2]> = coarse
        .iter()
        .zip(&first)
        .chain(search.bounces.iter().map(|b| (&b[0], &b[1])))
        .filter(|&(&v, &e)| v >= start && v <= v_hi && e > 0.0)
        .map(|(&v, &e)| [v.ln(), e * e])
        .collect();
    if v_lo < bounce && !samples.iter().any(|s| s[0] == bounce.ln()) {
        samples.push([bounce.ln(), 0.0]);
    }
    if v_lo >= bounce && !samples.iter().any(|s| s[0] == v_lo.ln()) {
        // The range starts above v_s with a collision that did not bounce
        // (e(v) is not monotonic here): no curve to interpolate.
        return Ok((direct(progress)?, v_s));
    }
    let budget = velocities.len().min(velocities.iter().filter(|&&v| v > stick).count() + 2);
    let miss = |_: f64, predicted: f64, sampled: f64| (predicted.max(0.0).sqrt() - sampled.sqrt()).abs() / E_TOLERANCE;
    let refined = refine(samples, 1e-9, budget.max(COARSE_VELOCITIES + 2), miss, |xs: &[f64]| {
        let vs: Vec<f64> = xs.iter().map(|x| x.exp()).collect();
        let e = par_map(&vs, progress, done, total, e_of)?;
        Ok::<_, SceneError>(e.iter().map(|e| e * e).collect())
    })?;
    let samples = match refined {
        Refined::Converged(s) => s,
        Refined::Budget(_) => return Ok((direct(progress)?, v_s)),
    };
    let e = velocities
        .iter()
        .map(|&v| if v <= stick { 0.0 } else { interpolate(&samples, v.ln()).max(0.0).sqrt().min(1.0) })
        .collect();
    Ok((e, v_s))
}

fn velocity_panel(
    p: &Params,
    velocities: &[f64],
    progress: &Progress,
    done: &AtomicUsize,
    total: usize,
) -> Result<Panel, SceneError> {
    let setup = p.collision.setup();
    let opts = p.collision.options();
    let (e_adhesive, v_adhesive) = adaptive_restitution(&setup, &opts, velocities, progress, done, total)?;
    progress.check()?;
    // With plastic yield the first bounce can lie above the adhesive v_s.
    let v_s = sticking_velocity_with_yield(&setup, &opts, v_adhesive, V_STICK_PRECISION)?;
    let v_y = setup.yield_velocity();
    let results: Vec<RestitutionAt> = velocities
        .iter()
        .zip(&e_adhesive)
        .map(|(&v, &e_a)| {
            let e_p = plasticity::e_plastic(v, v_y);
            let e = if e_a > 0.0 { plasticity::e_combined(e_a, e_p) } else { 0.0 };
            RestitutionAt { velocity: v, e_adhesive: e_a, e_plastic: e_p, e }
        })
        .collect();
    progress.check()?;
    let pair = setup.pair;
    let a = setup.dissipation_time();
    // e_D at each velocity, drawn itself and inside e_I.
    let e_d: Vec<f64> = velocities.iter().map(|&v| pair.e_viscous(a, v)).collect();
    let mut fig = Figure::new(
        "restitution-velocity",
        "Restitution against velocity",
        Axis::log("impact velocity v", "m/s"),
        Axis::linear("coefficient of restitution", ""),
    )
    .with(Series::new("e (model)", results.iter().map(|r| [r.velocity, r.e]).collect(), Style::Line, 0))
    .with(Series::new("e_JKR (2.24)", velocities.iter().map(|&v| [v, pair.e_jkr(v)]).collect(), Style::Dashed, 1))
    .with(Series::new(
        "e_D (γ → 0 limit)",
        velocities.iter().zip(&e_d).map(|(&v, &e)| [v, e]).collect(),
        Style::Dashed,
        2,
    ))
    .with(Series::new(
        "(2.26) as printed",
        velocities.iter().map(|&v| [v, pair.e_viscous_printed(a, v)]).collect(),
        Style::Dotted,
        2,
    ))
    .with(Series::new(
        "e_I (2.27)",
        velocities.iter().zip(&e_d).map(|(&v, &e)| [v, e_independent(pair.e_jkr(v), e)]).collect(),
        Style::Dashed,
        3,
    ));
    if p.collision.plasticity {
        fig = fig.with(Series::new(
            "e_P (2.29)",
            velocities.iter().map(|&v| [v, plasticity::e_plastic(v, v_y)]).collect(),
            Style::Dashed,
            4,
        ));
    }
    fig = fig.with(Series::new("sticking velocity v_s", vec![[v_s, 0.0], [v_s, 1.0]], Style::Dashed, 6));
    let e_max = results.iter().map(|r| r.e).fold(0.0, f64::max);
    let mut notes = Vec::new();
    if v_s.is_infinite() {
        notes.push(if v_adhesive.is_finite() {
            format!(
                "With plastic yield the spheres stick at every velocity up to 10⁴ m/s (without it they bounce above {} m/s): v_s is a lower bound.",
                human(v_adhesive)
            )
        } else {
            "The spheres stick at every velocity up to 10⁴ m/s: v_s is a lower bound.".to_string()
        });
    } else if v_s > v_adhesive * (1.0 + 1e-3) {
        notes.push(format!(
            "Plastic yield moves the first bounce from {} m/s (adhesion and viscosity alone) to v_s = {} m/s.",
            human(v_adhesive),
            human(v_s)
        ));
    }
    Ok(Panel {
        notes,
        figure: fig,
        scalars: vec![
            Scalar { key: "v_stick", label: "sticking velocity v_s (model)", value: v_s, unit: "m s^-1" },
            Scalar {
                key: "v_c",
                label: "JKR sticking velocity v_c (2.25)",
                value: pair.jkr_sticking_velocity(),
                unit: "m s^-1",
            },
            Scalar { key: "v_y", label: "yield velocity v_y (2.28)", value: v_y, unit: "m s^-1" },
            Scalar { key: "e_max", label: "largest e on the velocity grid", value: e_max, unit: "" },
        ],
    })
}

fn radius_panel(
    p: &Params,
    radii: &[f64],
    progress: &Progress,
    done: &AtomicUsize,
    total: usize,
) -> Result<Panel, SceneError> {
    let v = p.collision.velocity;
    let rows = par_map(radii, progress, done, total, |&r| {
        let c = p.at_radius(r);
        let setup = c.setup();
        let res = restitution(&setup, v, &c.options())?;
        let pair = setup.pair;
        Ok([
            r,
            res.e_adhesive,
            e_independent(pair.e_jkr(v), pair.e_viscous(setup.dissipation_time(), v)),
            pair.e_jkr(v),
        ])
    })?;
    let title = format!("Restitution against reduced radius at v = {} m/s", human(v));
    let fig = Figure::new(
        "restitution-radius",
        &title,
        Axis::log("reduced radius R", "µm"),
        Axis::linear("coefficient of restitution", ""),
    )
    .with(Series::new("e_A (model)", rows.iter().map(|r| [r[0] * 1e6, r[1]]).collect(), Style::Line, 0))
    .with(Series::new("e_I (2.27)", rows.iter().map(|r| [r[0] * 1e6, r[2]]).collect(), Style::Dashed, 3))
    .with(Series::new("e_JKR (2.24)", rows.iter().map(|r| [r[0] * 1e6, r[3]]).collect(), Style::Dashed, 1));
    Ok(Panel { figure: fig, scalars: Vec::new(), notes: Vec::new() })
}

/// A first guess of v_s at the next radius, `radii[vs.len()]`, from the
/// sticking velocities `vs` of the radii before it on the same curve: the
/// straight line in log–log through the last two, or from the last one with
/// the slope of the JKR v_c (2.25); `None` for the first radius or after a
/// radius where v_s lies outside the searched range.
fn sticking_guess(radii: &[f64], vs: &[f64]) -> Option<f64> {
    let j = vs.len();
    let finite = |v: &f64| v.is_finite() && *v > 0.0;
    let last = *vs.get(j.checked_sub(1)?).filter(|v| finite(v))?;
    let ln_r = |k: usize| radii[k].ln();
    let slope = match j.checked_sub(2).and_then(|k| vs.get(k).filter(|v| finite(v)).map(|v| (k, *v))) {
        Some((k, before)) => (last / before).ln() / (ln_r(j - 1) - ln_r(k)),
        None => -5.0 / 6.0,
    };
    let guess = (last.ln() + slope * (ln_r(j) - ln_r(j - 1))).exp();
    (guess.is_finite() && guess > 0.0).then_some(guess)
}

fn sticking_panel(
    p: &Params,
    radii: &[f64],
    t_vis: &[f64],
    progress: &Progress,
    done: &AtomicUsize,
    total: usize,
) -> Result<Panel, SceneError> {
    // Each T_vis curve walks the radii in order (the curves in parallel):
    // v_s at one radius, extrapolated along the curve, is the first guess at
    // the next (at the default size 1052 collisions instead of 1889 from v_c).
    let failed = std::sync::Mutex::new(Vec::<String>::new());
    let curves: Vec<Vec<f64>> = t_vis
        .par_iter()
        .map(|&tv| -> Result<Vec<f64>, SceneError> {
            let mut vs: Vec<f64> = Vec::with_capacity(radii.len());
            for &r in radii {
                progress.check()?;
                let mut c = p.at_radius(r);
                c.t_vis = tv;
                let setup = c.setup();
                let opts = Options { rtol: c.options().rtol.max(STICKING_PANEL_RTOL), ..c.options() };
                let found = match sticking_guess(radii, &vs) {
                    Some(guess) => {
                        sticking_search_near(&setup, &opts, STICKING_PANEL_PRECISION, guess).map(|s| s.velocity)
                    }
                    None => sticking_velocity(&setup, &opts, STICKING_PANEL_PRECISION),
                };
                // A search whose collision the integrator cannot follow (the
                // fastest, smallest grains at large k) leaves a gap that a
                // note names; it does not take the other curves with it.
                let v = match found {
                    Ok(v) => v,
                    Err(e) => {
                        failed.lock().unwrap_or_else(|p| p.into_inner()).push(format!(
                            "T_vis = {} s, R = {} µm: {e} (not drawn).",
                            human(tv),
                            human(r * 1e6)
                        ));
                        f64::NAN
                    }
                };
                vs.push(v);
                let n = done.fetch_add(20, Ordering::Relaxed) + 20;
                progress.set(n as f64 / total as f64);
            }
            Ok(vs)
        })
        .collect::<Result<_, _>>()?;
    let vs: Vec<f64> = curves.concat();
    let mut fig = Figure::new(
        "sticking-velocity",
        "Sticking velocity against reduced radius",
        Axis::log("reduced radius R", "µm"),
        Axis::log("sticking velocity", "m/s"),
    )
    // T_vis is the colour, on a colour bar: the palette colours of the
    // panels above mean e_I, e_JKR and e_D.
    .family("relaxation time T_vis", "s", Scale::Log);
    for (i, tv) in t_vis.iter().enumerate() {
        let pts = radii
            .iter()
            .enumerate()
            .map(|(j, &r)| [r * 1e6, vs[i * radii.len() + j]])
            .filter(|p| !p[1].is_nan())
            .collect();
        fig = fig.with(Series::new(format!("T_vis = {} s", human(*tv)), pts, Style::Line, i % 6).at(*tv));
    }
    let jkr = radii.iter().map(|&r| [r * 1e6, p.at_radius(r).setup().pair.jkr_sticking_velocity()]).collect();
    fig = fig.with(Series::new("JKR v_c (2.25)", jkr, Style::Dashed, 6));
    let mut notes = Vec::new();
    for (i, tv) in t_vis.iter().enumerate() {
        let stuck = vs[i * radii.len()..(i + 1) * radii.len()].iter().filter(|v| v.is_infinite()).count();
        if stuck > 0 {
            notes.push(format!(
                "T_vis = {} s: at {stuck} of {} radii the spheres stick even at 10⁴ m/s (not drawn).",
                human(*tv),
                radii.len()
            ));
        }
    }
    let mut failed = failed.into_inner().unwrap_or_else(|p| p.into_inner());
    failed.sort();
    notes.extend(failed);
    Ok(Panel { figure: fig, scalars: Vec::new(), notes })
}

/// The crack law at the scene's k (Greenwood's Fig. 6 form): β = G_eff/γ
/// against the scaled crack speed v* = σ₀²T_vis|ȧ|/(E*γ), opening (β > 1)
/// and healing (β < 1), for the full relation, (2.16) and the fits (2.17)
/// (made for k = 0.02); the collisions use the one chosen in the
/// parameters.
pub fn crack_law_figure(law: &CrackLaw) -> Figure {
    let k = law.k;
    let (v_lo, v_hi) = (1e-4, 1e4);
    // β from ln(β − k) − ln(1 − β) = z, and the same for 1/β: both ends
    // of each branch are reached evenly.
    let zs: Vec<f64> = (0..=600).map(|i| -14.0 + 24.0 * i as f64 / 600.0).collect();
    let healing: Vec<f64> = zs.iter().map(|z| (k + z.exp()) / (1.0 + z.exp())).collect();
    let opening: Vec<f64> = healing.iter().map(|b| 1.0 / b).collect();
    let curve = |g: &dyn Fn(f64) -> Option<f64>, betas: &[f64]| -> Vec<[f64; 2]> {
        let mut pts: Vec<[f64; 2]> =
            betas.iter().filter_map(|&b| g(b).map(|v| [v.abs(), b])).filter(|p| p[0] >= v_lo && p[0] <= v_hi).collect();
        crate::sorting::sort_by_key(&mut pts, |a| a[0]);
        pts
    };
    let full = CrackLaw::full(k).resolve();
    let full_g = |b: f64| full.speed(b).map(|s| s.0);
    let general = CrackLaw { k, relation: Relation::General };
    let general_g = |b: f64| general.general(b).map(|s| s.0);
    let fit_g = |b: f64| CrackLaw::low_speed_fit(b);
    let title = format!("Crack law at k = {}", human(k));
    const FITS: &str = "(2.17), fits for k = 0.02";
    Figure::new("crack-law", &title, Axis::log("crack speed v* = σ₀²T_vis|ȧ|/(E*γ)", ""), Axis::log("β = G_eff/γ", ""))
        .with(Series::new("full relation, opening", curve(&full_g, &opening), Style::Line, 0).keyed("full relation"))
        .with(Series::new("full relation, healing", curve(&full_g, &healing), Style::Line, 0).keyed("full relation"))
        .with(Series::new("(2.16), opening", curve(&general_g, &opening), Style::Dashed, 1).keyed("(2.16)"))
        .with(Series::new("(2.16), healing", curve(&general_g, &healing), Style::Dashed, 1).keyed("(2.16)"))
        .with(Series::new("(2.17), opening", curve(&fit_g, &opening), Style::Dotted, 2).keyed(FITS))
        .with(Series::new("(2.17), healing", curve(&fit_g, &healing), Style::Dotted, 2).keyed(FITS))
}
