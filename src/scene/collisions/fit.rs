//! Scene "Fit measurements" (thesis Sect. 2.4.1): fit γ, T_vis and Y of the
//! restitution model to measured coefficients of restitution.

use super::common::CollisionParams;
use super::common::describe;
use crate::figure::{Axis, Figure, Heatmap, Series, Style};
use crate::physics::collision::{Options, Setup};
use crate::physics::experiments::experiment;
use crate::physics::fit::{Fit as FitResult, FitError, Measurement, Search, fit, model_restitution};
use crate::physics::material::Material;
use crate::scene::controls::{LogRange, ParamError};
use crate::scene::core::{
    Censored, Context, Declared, Irregularity, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use rand::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

/// Parameters of the fit scene. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
#[param(manual_default)]
pub struct Params {
    /// Measurements; empty means the synthetic example.
    #[param(skip)]
    pub data: Vec<Measurement>,
    /// projectile material
    #[param(label = "material 1")]
    pub projectile: Material,
    /// target material
    #[param(label = "material 2")]
    pub target: Material,
    /// projectile hits a flat target
    #[param(label = "sphere on wall")]
    pub wall: bool,
    /// projectile radius
    #[param(label = "radius 1", unit = "m", shown("µm", 1e6), range(2e-8, 2e-2), log)]
    pub radius_1: f64,
    /// target radius (spheres)
    #[param(label = "radius 2", unit = "m", shown("µm", 1e6), range(2e-8, 2e-2), log)]
    pub radius_2: f64,
    /// smallest γ of the grid
    #[param(label = "γ from", unit = "J m^-2", shown("J/m²", 1.0), range(1e-3, 100.0), log)]
    pub gamma_min: f64,
    /// largest γ of the grid
    #[param(label = "γ to", unit = "J m^-2", shown("J/m²", 1.0), range(1e-3, 100.0), log)]
    pub gamma_max: f64,
    /// grid points in γ
    #[param(label = "γ points", range(2.0, 100.0))]
    pub n_gamma: usize,
    /// do not fit γ
    #[param(label = "hold γ fixed")]
    pub fix_gamma: bool,
    /// γ when held fixed
    #[param(label = "fixed γ", unit = "J m^-2", shown("J/m²", 1.0), range(1e-3, 100.0), log)]
    pub gamma: f64,
    /// smallest T_vis of the grid
    #[param(label = "T_vis from", unit = "s", shown("s", 1.0), range(1e-15, 1e-6), log)]
    pub t_vis_min: f64,
    /// largest T_vis of the grid
    #[param(label = "T_vis to", unit = "s", shown("s", 1.0), range(1e-15, 1e-6), log)]
    pub t_vis_max: f64,
    /// grid points in T_vis
    #[param(label = "T_vis points", range(2.0, 100.0))]
    pub n_t_vis: usize,
    /// do not fit T_vis
    #[param(label = "hold T_vis fixed")]
    pub fix_t_vis: bool,
    /// T_vis when held fixed
    #[param(label = "fixed T_vis", unit = "s", shown("s", 1.0), range(1e-15, 1e-6), log)]
    pub t_vis: f64,
    /// smallest Y of the grid
    #[param(label = "Y from", unit = "Pa", shown("MPa", 1e-6), range(1e5, 1e12), log)]
    pub y_min: f64,
    /// largest Y of the grid
    #[param(label = "Y to", unit = "Pa", shown("MPa", 1e-6), range(1e5, 1e12), log)]
    pub y_max: f64,
    /// grid points in Y
    #[param(label = "Y points", range(2.0, 100.0))]
    pub n_y: usize,
    /// do not fit Y
    #[param(label = "hold Y fixed")]
    pub fix_y: bool,
    /// Y when held fixed
    #[param(label = "fixed Y", unit = "Pa", shown("MPa", 1e-6), range(1e5, 1e12), log)]
    pub yield_strength: f64,
    /// integrator tolerance (default 1e-4)
    #[param(quantity = quantities::solver_tolerance)]
    pub rtol: f64,
}

impl Default for Params {
    fn default() -> Self {
        let af = Material::named("AF").cloned().unwrap_or_else(Material::water_ice);
        let mica = Material::named("mica").cloned().unwrap_or_else(Material::water_ice);
        Params {
            data: Vec::new(),
            projectile: af,
            target: mica,
            wall: true,
            radius_1: 2.45e-6,
            radius_2: 2.45e-6,
            gamma_min: 0.02,
            gamma_max: 1.0,
            n_gamma: 16,
            fix_gamma: false,
            gamma: 0.13,
            t_vis_min: 1e-12,
            t_vis_max: 1e-9,
            n_t_vis: 16,
            fix_t_vis: false,
            t_vis: 1e-10,
            y_min: 3e7,
            y_max: 3e10,
            n_y: 16,
            fix_y: false,
            yield_strength: 2e8,
            rtol: 1e-4,
        }
    }
}

impl Params {
    fn searches(&self) -> Result<[Search; 3], ParamError> {
        let check = |name: &str, lo: f64, hi: f64| LogRange::new(name, lo, hi, 2).map(|_| ());
        check("gamma_min/gamma_max", self.gamma_min, self.gamma_max)?;
        check("t_vis_min/t_vis_max", self.t_vis_min, self.t_vis_max)?;
        check("y_min/y_max", self.y_min, self.y_max)?;
        Ok([
            Search {
                min: self.gamma_min,
                max: self.gamma_max,
                points: self.n_gamma,
                fixed: self.fix_gamma.then_some(self.gamma),
            },
            Search {
                min: self.t_vis_min,
                max: self.t_vis_max,
                points: self.n_t_vis,
                fixed: self.fix_t_vis.then_some(self.t_vis),
            },
            Search {
                min: self.y_min,
                max: self.y_max,
                points: self.n_y,
                fixed: self.fix_y.then_some(self.yield_strength),
            },
        ])
    }

    /// The model for given γ, T_vis and Y with this scene's materials and radii.
    pub fn setup(&self, gamma: f64, t_vis: f64, yield_strength: Option<f64>) -> Setup {
        CollisionParams {
            projectile: self.projectile.clone(),
            target: self.target.clone(),
            wall: self.wall,
            radius_1: self.radius_1,
            radius_2: self.radius_2,
            surface_energy: gamma,
            t_vis,
            plasticity: yield_strength.is_some(),
            yield_strength: yield_strength.unwrap_or(1e8),
            ..CollisionParams::default()
        }
        .setup()
    }
}

/// Synthetic measurements: the Wall et al. mica best fit at 20 velocities with
/// Gaussian noise of standard deviation `noise` (fixed seed).
pub fn example_data(noise: f64) -> Result<Vec<Measurement>, SceneError> {
    let e = experiment("wall-mica").ok_or_else(|| ParamError::Inconsistent("example experiment missing".into()))?;
    let setup = e.best_fit_setup().ok_or_else(|| ParamError::Inconsistent("example materials missing".into()))?;
    let velocities = logspace(e.v_min, e.v_max, 20);
    let y = setup.yield_strength.unwrap_or(f64::INFINITY);
    let exact = model_restitution(
        &|g, t, y| {
            Some(Setup {
                pair: crate::physics::contact::Pair { surface_energy: g, ..setup.pair },
                t_vis: t,
                yield_strength: y,
                ..setup
            })
        },
        [setup.pair.surface_energy, setup.t_vis, y],
        &velocities,
        &Options { rtol: 1e-7, ..Options::default() },
    )?;
    let mut rng = rand::rngs::StdRng::seed_from_u64(2015);
    Ok(velocities
        .iter()
        .zip(exact)
        .map(|(&v, e)| {
            // Box–Muller.
            let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
            let z = (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos();
            Measurement { velocity: v, restitution: (e + noise * z).clamp(0.0, 1.2), uncertainty: Some(noise) }
        })
        .collect())
}

/// Runs the fit of the scene (also used by the command line).
pub fn run_fit(p: &Params, data: &[Measurement], progress: &Progress) -> Result<FitResult, SceneError> {
    let searches = p.searches()?;
    let opts = Options { rtol: p.rtol, ..Options::default() };
    let setup_for = |g: f64, t: f64, y: Option<f64>| Some(p.setup(g, t, y));
    let keep_going = |f: f64| {
        progress.set(f);
        !progress.cancelled()
    };
    fit(&setup_for, data, searches, &opts, &keep_going).map_err(|e| match e {
        FitError::Cancelled => SceneError::Cancelled,
        FitError::Physics(p) => SceneError::Physics(p),
        other => SceneError::Param(ParamError::Inconsistent(other.to_string())),
    })
}

fn slice(f: &FitResult, a: usize, b: usize, fixed: usize) -> Heatmap {
    let idx = |p: usize| f.grids[p].iter().position(|&v| v == f.grid_best[p]).unwrap_or(0);
    let k = idx(fixed);
    let (na, nb) = (f.grids[a].len(), f.grids[b].len());
    let mut values = Vec::with_capacity(na * nb);
    for jb in 0..nb {
        for ia in 0..na {
            let mut ix = [0; 3];
            ix[a] = ia;
            ix[b] = jb;
            ix[fixed] = k;
            values.push(f.chi2_at(ix[0], ix[1], ix[2]).max(1e-300).log10());
        }
    }
    Heatmap::new(f.grids[a].clone(), f.grids[b].clone(), values, "log₁₀ χ²", "")
}

/// Why a fitted range has no low end.
const NO_LOW: &str =
    "no low end: the data do not bound it from below within the grid, or it is held fixed or undetermined";

/// Why a fitted range has no high end.
const NO_HIGH: &str =
    "no high end: the data do not bound it from above within the grid, or it is held fixed or undetermined";

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "fit",
        title: "Fit measurements",
        source: "Sect. 2.4.1, Eq. 2.31",
        explanation: "Fits the surface energy γ, the relaxation time T_vis and the yield strength Y to \
measured coefficients of restitution, with E, ν, ρ and the radii fixed by the chosen materials. \
χ² = (1/N) Σ [e_exp(v_n) − e(v_n)]² (2.31) is computed on a logarithmic grid (in parallel); the \
uncertainty of each parameter is the range over which χ² stays below twice its minimum, and the \
best grid point is refined with a Nelder–Mead search. A range that reaches the edge of the grid is a \
one-sided limit (e.g. no plastic yield in the measured range gives Y > …). Any parameter can be held \
fixed. Import measurements from CSV (columns 'velocity [m/s]', 'restitution', optional 'uncertainty') \
with Import data… or by dropping the file on the window; without data the scene fits a synthetic \
example drawn from the Wall et al. mica fit with noise 0.01.",
        heavy: true,
    };

    const CENSORED: &'static [Censored] = &[
        Censored { key: "gamma_low", above: None, undefined: Some(NO_LOW) },
        Censored { key: "gamma_high", above: None, undefined: Some(NO_HIGH) },
        Censored { key: "t_vis_low", above: None, undefined: Some(NO_LOW) },
        Censored { key: "t_vis_high", above: None, undefined: Some(NO_HIGH) },
        Censored { key: "y_low", above: None, undefined: Some(NO_LOW) },
        Censored { key: "y_high", above: None, undefined: Some(NO_HIGH) },
    ];

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "collisions",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a count of the collisions integrated: a whole number",
            resolution: None,
        },
        search("gamma_min"),
        search("gamma_max"),
        search("n_gamma"),
        search("t_vis_min"),
        search("t_vis_max"),
        search("n_t_vis"),
        search("y_min"),
        search("y_max"),
        search("n_y"),
        search("rtol"),
        jumps("gamma", "radius_1"),
        jumps("t_vis", "radius_1"),
        jumps("yield_strength", "radius_1"),
        jumps("gamma_low", "radius_1"),
        jumps("gamma_high", "radius_1"),
        jumps("t_vis_low", "radius_1"),
        jumps("t_vis_high", "radius_1"),
        jumps("y_low", "radius_1"),
        jumps("y_high", "radius_1"),
        jumps("gamma", "radius_2"),
        jumps("t_vis", "radius_2"),
        jumps("yield_strength", "radius_2"),
        jumps("gamma_low", "radius_2"),
        jumps("gamma_high", "radius_2"),
        jumps("t_vis_low", "radius_2"),
        jumps("t_vis_high", "radius_2"),
        jumps("y_low", "radius_2"),
        jumps("y_high", "radius_2"),
    ];

    fn measurements(&mut self) -> Option<&mut Vec<Measurement>> {
        Some(&mut self.data)
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let synthetic = p.data.is_empty();
        let data = if synthetic { example_data(0.01)? } else { p.data.clone() };
        let result = run_fit(p, &data, progress)?;
        output(p, &data, &result)
    }
}

/// Why the fit's results move in steps along the parameters of its search
/// (the continuity audit's finding, declared as the method's nature).
const SEARCH: &str = "the fit evaluates χ² on the grid, refines from the grid's best point and scans each range from \
     there: where χ² has minima of similar depth (or none inside the grid), where the region χ² < 2χ²_min has parts \
     between grid points, and within the integrator's noise of χ² (its tolerance), moving the grid or the tolerance \
     moves the best fit and its ranges in steps: the search's resolution, not the data's";

/// Why the best fit jumps along the spheres' radii (the audit's finding,
/// declared as the nature of a fit): χ² stays continuous, the best fit does not.
const LOWEST_MINIMUM: &str = "the best fit is the lowest of χ²'s minima: where the model is fitted to data it does \
     not describe (radii far from the measured spheres'), two minima of similar depth exchange order as the radius \
     moves, and the best fit and its ranges jump from one to the other while χ²_min itself stays continuous";

/// A jump of the best fit's `scalar` along a radius: [`LOWEST_MINIMUM`].
const fn jumps(scalar: &'static str, parameter: &'static str) -> Declared {
    Declared { scalar, parameter, kind: Irregularity::Step, why: LOWEST_MINIMUM, resolution: None }
}

/// Steps of every result along a parameter of the search: [`SEARCH`].
const fn search(parameter: &'static str) -> Declared {
    Declared { scalar: "*", parameter, kind: Irregularity::Step, why: SEARCH, resolution: None }
}

/// The scene's output for a fit already made of `data` (also used by the
/// command line, so that `fit --out` does not fit twice).
pub fn output(p: &Params, data: &[Measurement], result: &FitResult) -> Result<SceneOutput, SceneError> {
    let synthetic = p.data.is_empty();
    let [g, t, y] = result.best;
    let opts = Options { rtol: p.rtol, ..Options::default() };
    let (v_lo, v_hi) = data.iter().fold((f64::INFINITY, 0.0f64), |(a, b), d| (a.min(d.velocity), b.max(d.velocity)));
    let vs = logspace(v_lo * 0.8, v_hi * 1.25, 60);
    let setup_for = |g: f64, t: f64, y: Option<f64>| Some(p.setup(g, t, y));
    let best_curve = model_restitution(&setup_for, result.best, &vs, &opts)?;
    let grid_curve = model_restitution(&setup_for, result.grid_best, &vs, &opts)?;

    let mut fig = Figure::new(
        "fit",
        "Fit to the measurements",
        Axis::log("impact velocity v", "m/s"),
        Axis::linear("coefficient of restitution", ""),
    )
    .with(Series::new("measured", data.iter().map(|d| [d.velocity, d.restitution]).collect(), Style::Points, 1))
    .with(Series::new("best fit", vs.iter().zip(&best_curve).map(|(&v, &e)| [v, e]).collect(), Style::Line, 0))
    .with(Series::new(
        "best grid point",
        vs.iter().zip(&grid_curve).map(|(&v, &e)| [v, e]).collect(),
        Style::Dashed,
        6,
    ));
    for d in data {
        if let Some(s) = d.uncertainty {
            fig.series.push(Series::new(
                "",
                vec![[d.velocity, d.restitution - s], [d.velocity, d.restitution + s]],
                Style::Line,
                1,
            ));
        }
    }
    let names = ["surface energy γ", "relaxation time T_vis", "yield strength Y"];
    let units = ["J/m²", "s", "Pa"];
    let axis = |i: usize| Axis::log(names[i], units[i]);
    let mut figures = vec![fig];
    for (a, b, c, id) in [(0, 1, 2, "chi2-gamma-tvis"), (0, 2, 1, "chi2-gamma-y"), (1, 2, 0, "chi2-tvis-y")] {
        if result.grids[a].len() > 1 && result.grids[b].len() > 1 {
            let mut f = Figure::new(id, &format!("χ² over {} and {}", names[a], names[b]), axis(a), axis(b))
                .with(Series::new("best fit", vec![[result.best[a], result.best[b]]], Style::Marker, 0));
            f.heatmap = Some(slice(result, a, b, c));
            figures.push(f);
        }
    }
    let range = |b: &crate::physics::experiments::Bounded| b.range();
    let scalars = vec![
        Scalar { key: "gamma", label: "best γ", value: g, unit: "J m^-2" },
        Scalar { key: "t_vis", label: "best T_vis", value: t, unit: "s" },
        Scalar { key: "yield_strength", label: "best Y", value: y, unit: "Pa" },
        Scalar { key: "chi2", label: "χ² (2.31) of the best fit", value: result.chi2_min, unit: "" },
        Scalar { key: "gamma_low", label: "γ range, low end", value: range(&result.ranges[0]).0, unit: "J m^-2" },
        Scalar { key: "gamma_high", label: "γ range, high end", value: range(&result.ranges[0]).1, unit: "J m^-2" },
        Scalar { key: "t_vis_low", label: "T_vis range, low end", value: range(&result.ranges[1]).0, unit: "s" },
        Scalar { key: "t_vis_high", label: "T_vis range, high end", value: range(&result.ranges[1]).1, unit: "s" },
        Scalar { key: "y_low", label: "Y range, low end", value: range(&result.ranges[2]).0, unit: "Pa" },
        Scalar { key: "y_high", label: "Y range, high end", value: range(&result.ranges[2]).1, unit: "Pa" },
        Scalar { key: "collisions", label: "collisions integrated", value: result.collisions as f64, unit: "" },
    ];
    let mut notes = vec![format!(
        "γ = {}, T_vis = {}, Y = {} (range where χ² < 2 χ²_min).",
        describe(&result.ranges[0], "J/m²", 1.0),
        describe(&result.ranges[1], "s", 1.0),
        describe(&result.ranges[2], "MPa", 1e-6)
    )];
    if synthetic {
        notes.push("No data imported: fitting a synthetic example (Wall et al. mica best fit, noise 0.01).".into());
    }
    let warnings = result.warning().into_iter().collect();
    Ok(SceneOutput { warnings, scalars, figures, notes, extra: crate::scene::core::Extra::None })
}
