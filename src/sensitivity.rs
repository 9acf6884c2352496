//! Sensitivity: how one scalar result X of a scene depends on its
//! parameters. [`what_matters`] ranks every parameter by how much it moves X
//! around the current point (elasticity and range over a factor, a tornado
//! chart); [`curve`] draws X(p) over a parameter's whole range; [`map`]
//! draws X(p₁, p₂) with a colour bar and contours.
//!
//! Every point's value comes from [`value`]: the scene's quick path to the
//! scalar where it has one (the same number without the figures), kept in a
//! per-point cache, so that extending a range, adding points or asking again
//! reuses the work already done. A Monte Carlo scene (one with `runs` and
//! `seed` parameters, whose runs use seeds `seed`, `seed + 1`, …) is
//! computed one seed at a time: a point gets the mean over its seeds (the
//! scene's own mean) and their standard deviation σ, drawn as error bars,
//! and the ranking says when an effect is below that noise. A scalar the
//! scene does not define at a point (no sticking, no planetesimals) is a
//! gap, never a zero.

use crate::figure::{self, Axis, Figure, Heatmap, Scale, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::PhysicsError;
use crate::scene::schema::SpecKind;
use crate::scene::{self, DefaultValue, Progress, SceneError, SceneParams};
use crate::sweep::{Plan, Spacing, Vary};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

/// A sensitivity view as a file remembers it: which result, over which
/// factor, against which parameters. An exported figure of the view carries
/// it in its preset, so that opening the file reopens the view.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct View {
    /// The scalar's key.
    pub output: String,
    /// The factor around each parameter's value of the "what matters" chart.
    pub factor: f64,
    /// The parameter of the curve (the map's horizontal axis); empty for none.
    pub x: String,
    /// The map's second parameter; empty for a curve.
    pub y: String,
    /// The study over whole ranges (Morris or Sobol'), if the view holds one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub whole: Option<WholeRange>,
}

impl Default for View {
    fn default() -> Self {
        View { output: String::new(), factor: 2.0, x: String::new(), y: String::new(), whole: None }
    }
}

/// A global sensitivity study of the view's result over whole parameter
/// ranges: Morris's elementary effects or Sobol' indices, as `grainscope
/// sensitivity` computes them.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WholeRange {
    /// The design: method and size, the factors and their ranges (SI), the seed.
    pub design: crate::global_sensitivity::Design,
    /// Analyse ln X (effects become relative changes).
    #[serde(default)]
    pub log_output: bool,
}

/// A scalar at one point of parameter space.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Value {
    /// The value (for a Monte Carlo scene the mean over its seeds); None
    /// where the scene does not define it (at any of the seeds).
    pub mean: Option<f64>,
    /// The standard deviation over the seeds (Monte Carlo scenes with more
    /// than one run), else None.
    pub sd: Option<f64>,
    /// The number of seeds behind the value (1 for a deterministic scene).
    pub runs: usize,
}

impl Value {
    /// The standard error of the mean, where the value has a spread.
    pub fn error(&self) -> Option<f64> {
        self.sd.map(|s| s / (self.runs as f64).sqrt())
    }
}

/// Points kept in the cache before it starts afresh (each is one number
/// and its parameters as text: some tens of MB at most).
const CACHE_LIMIT: usize = 100_000;

/// The per-point cache: (scalar, parameters) → the scalar there.
fn cache() -> &'static Mutex<HashMap<String, Option<f64>>> {
    static CACHE: OnceLock<Mutex<HashMap<String, Option<f64>>>> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(HashMap::new()))
}

/// Scalar `output` of one computation at `params`, from the cache where it
/// was computed before. Non-finite values count as undefined (what they
/// mean, a bound or no value, is [`raw`]'s).
fn single(params: &SceneParams, output: &str, progress: &Progress) -> Result<Option<f64>, SceneError> {
    Ok(raw(params, output, progress)?.filter(|x| x.is_finite()))
}

/// Scalar `output` at `params` as the scene gives it, non-finite values
/// included (cached).
fn raw(params: &SceneParams, output: &str, progress: &Progress) -> Result<Option<f64>, SceneError> {
    // Debug text of the parameters writes every float exactly: equal text, equal point.
    let key = format!("{output}\u{1f}{params:?}");
    if let Some(v) = cache().lock().ok().and_then(|c| c.get(&key).copied()) {
        return Ok(v);
    }
    let v = scene::scalar(params, output, &progress.quiet_child())?;
    if let Ok(mut c) = cache().lock() {
        if c.len() >= CACHE_LIMIT {
            c.clear();
        }
        c.insert(key, v);
    }
    Ok(v)
}

/// The first seed and the number of runs of a Monte Carlo scene's
/// parameters; None for a scene without both.
fn seeds(params: &SceneParams) -> Option<(usize, usize)> {
    let mut p = params.clone();
    p.seeds().map(|s| (*s.first, *s.runs))
}

/// Scalar `output` at `params`: cached, through the scene's quick path, and
/// for a Monte Carlo scene seed by seed with the spread over the seeds.
pub fn value(params: &SceneParams, output: &str, progress: &Progress) -> Result<Value, SceneError> {
    match seeds(params) {
        Some((seed, runs)) if runs > 1 => {
            let one: Vec<SceneParams> = (0..runs)
                .map(|k| {
                    let mut p = params.clone();
                    if let Some(s) = p.seeds() {
                        (*s.first, *s.runs) = (seed + k, 1);
                    }
                    p.validate()?;
                    Ok(p)
                })
                .collect::<Result<_, crate::scene::ParamError>>()?;
            let xs: Vec<Option<f64>> =
                one.par_iter().map(|p| single(p, output, progress)).collect::<Result<_, SceneError>>()?;
            let Some(xs) = xs.into_iter().collect::<Option<Vec<f64>>>() else {
                return Ok(Value { mean: None, sd: None, runs });
            };
            // Summed in seed order, as the scene averages its runs.
            let n = xs.len() as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
            Ok(Value { mean: Some(mean), sd: Some(var.sqrt()), runs })
        }
        _ => Ok(Value { mean: single(params, output, progress)?, sd: None, runs: 1 }),
    }
}

/// A point's value, or undefined where its parameters are refused or its
/// computation fails (cancelling still stops the whole).
fn value_or_gap(params: &SceneParams, output: &str, progress: &Progress) -> Result<Value, SceneError> {
    match value(params, output, progress) {
        Err(SceneError::Cancelled) => Err(SceneError::Cancelled),
        Err(_) => Ok(Value { mean: None, sd: None, runs: 1 }),
        Ok(v) => Ok(v),
    }
}

/// The values at many points, in parallel, with progress (each point a
/// unit a browser shares among its workers).
fn values(points: &[SceneParams], output: &str, progress: &Progress) -> Result<Vec<Value>, SceneError> {
    let done = AtomicUsize::new(0);
    let out = progress.units(points, |p| {
        progress.check()?;
        let v = value_or_gap(p, output, progress)?;
        let n = done.fetch_add(1, Ordering::Relaxed) + 1;
        progress.set(n as f64 / points.len().max(1) as f64);
        Ok(v)
    });
    progress.check()?;
    out
}

/// How much one parameter moves a scalar around the current point.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Influence {
    /// The parameter's key.
    pub key: String,
    /// Its label.
    pub label: String,
    /// Its SI unit.
    pub unit: String,
    /// Its current value.
    pub value: f64,
    /// ∂ln X/∂ln p at the current value (central differences of ln X in
    /// ln p); None where X or p is not positive or X is undefined nearby.
    pub elasticity: Option<f64>,
    /// Whether the elasticity agrees within 1 % (or 0.01) between steps of
    /// 1 % and 0.5 % in p: a smooth dependence, not a jump or noise.
    pub converged: bool,
    /// X at p / factor and p × factor (clamped to the parameter's range).
    pub range: [Option<f64>; 2],
    /// σ over the seeds of X at p / factor and p × factor (Monte Carlo).
    pub range_sd: [Option<f64>; 2],
    /// Whether both ends differ from X here by less than twice the standard
    /// error of the difference (Monte Carlo): an effect the seeds cannot
    /// tell from noise.
    pub below_noise: bool,
    /// Why an end of `range` has no value: "" where it has one, else
    /// "> BOUND: WHY" (only a bound is known), "undefined: WHY", or
    /// "refused or failed" (the point could not be computed).
    #[serde(default)]
    pub range_status: [String; 2],
    /// Whether the parameter sets a numerical resolution or sample of the
    /// method (a step, a count, a tolerance, a seed) rather than the physics:
    /// a converged answer does not depend on it, and its row says how far
    /// this one is from converged.
    #[serde(default)]
    pub numerical: bool,
}

/// What an end of a parameter's range is, where it has no value.
fn end_status(point: Option<&SceneParams>, output: &str, progress: &Progress) -> String {
    let Some(p) = point else { return "refused or failed".into() };
    // A Monte Carlo end is the mean over seeds, computed seed by seed: one
    // undefined seed leaves it undefined, and the whole runs are not
    // computed again to say more.
    if seeds(p).is_some_and(|(_, runs)| runs > 1) {
        return "undefined at one seed or more".into();
    }
    match raw(p, output, progress) {
        Ok(Some(v)) => match scene::status(p.censored(), output, v) {
            scene::Status::Value => String::new(),
            scene::Status::Above { bound, why } => format!("> {}: {why}", crate::figure::human(bound)),
            scene::Status::Undefined { why } => format!("undefined: {why}"),
        },
        Ok(None) => "undefined".into(),
        Err(_) => "refused or failed".into(),
    }
}

/// What moves a scalar: its value here and every parameter's influence.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Matters {
    /// X at the current point (mean and σ over seeds for Monte Carlo).
    pub here: Value,
    /// The parameters, the largest change of X over the range first.
    pub rows: Vec<Influence>,
}

/// A numeric parameter of a scene, as the sensitivity tools vary it.
#[derive(Debug, Clone)]
pub struct Knob {
    /// Parameter key.
    pub key: &'static str,
    /// Label as shown.
    pub label: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Unit the window shows the value in.
    pub shown_unit: &'static str,
    /// Display value per SI value.
    pub display_scale: f64,
    /// Current value (SI).
    pub value: f64,
    /// Lower end of the documented range (SI).
    pub min: f64,
    /// Upper end of the documented range (SI).
    pub max: f64,
    /// Whether the control is logarithmic.
    pub log: bool,
    /// Whether it sets a numerical resolution or sample of the method
    /// rather than the physics (its spec's `numerical`).
    pub numerical: bool,
}

/// The numeric parameters of `base` that change a result (style-only ones
/// aside); numerical resolutions among them say so.
pub fn knobs(base: &SceneParams) -> Vec<Knob> {
    base.specs()
        .iter()
        .filter(|s| !s.style_only)
        .filter_map(|s| match (&s.kind, base.get(s.key)?) {
            (SpecKind::Number { min, max, log, display_scale }, DefaultValue::Number(value)) => Some(Knob {
                key: s.key,
                label: s.label,
                unit: s.si_unit,
                shown_unit: s.unit,
                display_scale: *display_scale,
                value,
                min: *min,
                max: *max,
                log: *log,
                numerical: s.numerical,
            }),
            _ => None,
        })
        .collect()
}

/// The counts among `base`'s parameters that set a numerical resolution (a
/// number of batches, runs, steps, tracks or grid points; not a seed, which
/// picks a sample and has no scale): "what matters" shows the result at half
/// and twice each, the resolution error, beside the physics.
fn resolution_counts(base: &SceneParams) -> Vec<Knob> {
    base.specs()
        .iter()
        .filter(|s| s.numerical && !s.style_only && !s.figure_only && s.key != "seed")
        .filter_map(|s| match (&s.kind, base.get(s.key)?) {
            (SpecKind::Count { min, max }, DefaultValue::Count(value)) => Some(Knob {
                key: s.key,
                label: s.label,
                unit: s.si_unit,
                shown_unit: s.unit,
                display_scale: 1.0,
                value: value as f64,
                min: *min as f64,
                max: *max as f64,
                log: false,
                numerical: true,
            }),
            _ => None,
        })
        .collect()
}

/// `base` with parameter `key` set to `v`, or None where it is refused.
fn with(base: &SceneParams, key: &str, v: f64) -> Option<SceneParams> {
    let mut p = base.clone();
    p.set_number(key, v).ok().map(|_| p)
}

/// For every positive numeric parameter of `base` (style-only ones aside),
/// how scalar `output` depends on it: the elasticity ∂ln X/∂ln p at the
/// current point and X over the factor `factor` around it; sorted with the
/// largest change of X over the range first. Points run in parallel; 6
/// points per parameter, each through [`value`] (cached, quick path, seed
/// by seed for Monte Carlo).
pub fn what_matters(base: &SceneParams, output: &str, factor: f64, progress: &Progress) -> Result<Matters, SceneError> {
    let factor = if factor.is_finite() && factor > 1.0 { factor } else { 2.0 };
    let here = value(base, output, progress)?;
    let x0 = match here.mean {
        Some(x) => x,
        None => {
            // Undefined here, or no such scalar at all: say which.
            let out = scene::compute(base, progress)?;
            let id = base.info().id;
            let why = if let Some(v) = out.scalar(output) {
                match scene::status(base.censored(), output, v) {
                    scene::Status::Above { bound, why } => format!(
                        "'{output}' is only a bound at the current point of {id} (> {}: {why}): move the point to where it has a value",
                        crate::figure::human(bound)
                    ),
                    scene::Status::Undefined { why } => {
                        format!("'{output}' is undefined at the current point of {id} ({why})")
                    }
                    scene::Status::Value => format!("'{output}' is undefined at the current point of {id}"),
                }
            } else {
                let keys: Vec<&str> = out.scalars.iter().map(|s| s.key).collect();
                format!("no scalar '{output}' in {id} (its scalars: {})", keys.join(", "))
            };
            return Err(PhysicsError::Invalid(why).into());
        }
    };
    let counts = resolution_counts(base);
    let knobs: Vec<Knob> = knobs(base).into_iter().chain(counts.iter().cloned()).filter(|k| k.value > 0.0).collect();
    // Per parameter: ln p ± h and ± h/2 (h = ln 1.01), then p / factor and p × factor.
    // A count (a number of batches, runs, steps) has no elasticity: only its
    // ends, rounded to whole numbers.
    let h = 1.01_f64.ln();
    let offsets = [-h, h, -h / 2.0, h / 2.0, -factor.ln(), factor.ln()];
    let points: Vec<Option<SceneParams>> = knobs
        .iter()
        .flat_map(|k| {
            let count = counts.iter().any(|c| c.key == k.key);
            offsets.iter().enumerate().map(move |(i, o)| {
                let v = (k.value * o.exp()).clamp(k.min, k.max);
                match (count, i) {
                    (false, _) => with(base, k.key, v),
                    (true, 4 | 5) => with(base, k.key, v.round().clamp(k.min, k.max)),
                    (true, _) => None,
                }
            })
        })
        .collect();
    let wanted: Vec<SceneParams> = points.iter().flatten().cloned().collect();
    let mut got = values(&wanted, output, progress)?.into_iter();
    let results: Vec<Value> = points
        .iter()
        .map(|p| match p {
            Some(_) => got.next().unwrap_or(Value { mean: None, sd: None, runs: 1 }),
            None => Value { mean: None, sd: None, runs: 1 },
        })
        .collect();
    let mut rows: Vec<Influence> = knobs
        .iter()
        .enumerate()
        .map(|(k, knob)| {
            let r = &results[k * offsets.len()..(k + 1) * offsets.len()];
            let slope = |lo: Option<f64>, hi: Option<f64>, step: f64| match (lo, hi) {
                (Some(a), Some(b)) if a > 0.0 && b > 0.0 && x0 > 0.0 => Some((b.ln() - a.ln()) / (2.0 * step)),
                _ => None,
            };
            // A parameter at the end of its range moves less than asked: no elasticity there.
            let inside = knob.value * h.exp() <= knob.max && knob.value * (-h).exp() >= knob.min;
            let coarse = slope(r[0].mean, r[1].mean, h).filter(|_| inside);
            let fine = slope(r[2].mean, r[3].mean, h / 2.0).filter(|_| inside);
            let converged = match (coarse, fine) {
                (Some(a), Some(b)) => (a - b).abs() <= 0.01 * b.abs().max(1.0),
                _ => false,
            };
            // Below the noise: each end within 2 standard errors of the difference from X here.
            let below_noise = here.sd.is_some()
                && [&r[4], &r[5]].iter().all(|end| match (end.mean, end.error(), here.error()) {
                    (Some(x), Some(e), Some(e0)) => (x - x0).abs() < 2.0 * e.hypot(e0),
                    _ => false,
                });
            Influence {
                key: knob.key.to_string(),
                label: knob.label.to_string(),
                unit: knob.unit.to_string(),
                value: knob.value,
                elasticity: fine.or(coarse),
                converged,
                range: [r[4].mean, r[5].mean],
                range_sd: [r[4].sd, r[5].sd],
                below_noise,
                range_status: [4, 5].map(|e| {
                    if r[e].mean.is_some() {
                        String::new()
                    } else {
                        end_status(points[k * offsets.len() + e].as_ref(), output, progress)
                    }
                }),
                numerical: knob.numerical,
            }
        })
        .collect();
    let spread = |i: &Influence| {
        let xs: Vec<f64> = [i.range[0], Some(x0), i.range[1]].into_iter().flatten().collect();
        xs.iter().copied().fold(f64::NEG_INFINITY, f64::max) - xs.iter().copied().fold(f64::INFINITY, f64::min)
    };
    // The physics first, then the numerical resolutions, each by its spread.
    rows.sort_by(|a, b| a.numerical.cmp(&b.numerical).then(spread(b).total_cmp(&spread(a))));
    Ok(Matters { here, rows })
}

/// The heading of the rows of numerical resolutions in a "what matters" table.
pub const NUMERICAL_HEADING: &str =
    "numerical resolution (a converged answer does not depend on these; their effect is the resolution error)";

/// The "what matters" answer as an aligned text table (the command line's).
pub fn matters_text(m: &Matters, output: &str, factor: f64) -> String {
    let mut t = String::new();
    let here = m.here.mean.map_or("undefined".to_string(), |x| x.to_string());
    let seeds = match (m.here.sd, m.here.runs) {
        (Some(sd), n) => format!(" ± {sd:.3e} (σ over {n} seeds)"),
        _ => String::new(),
    };
    let _ = writeln!(t, "{output} = {here}{seeds}; each parameter divided and multiplied by {factor}");
    let _ =
        writeln!(t, "{:<26} {:>12} {:>11} {:>12} {:>12}", "parameter", "value", "elasticity", "X at p/f", "X at p*f");
    let num = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.5e}"));
    for (i, r) in m.rows.iter().enumerate() {
        if r.numerical && (i == 0 || !m.rows[i - 1].numerical) {
            let _ = writeln!(t, "{NUMERICAL_HEADING}:");
        }
        let e = r.elasticity.map_or("-".to_string(), |e| format!("{e:+.4}{}", if r.converged { "" } else { "?" }));
        let mut noise = if r.below_noise { "  below the noise".to_string() } else { String::new() };
        for (end, why) in ["p/f", "p*f"].iter().zip(&r.range_status) {
            if !why.is_empty() {
                let _ = write!(noise, "  at {end}: {why}");
            }
        }
        let _ = writeln!(
            t,
            "{:<26} {:>12} {:>11} {:>12} {:>12}{noise}",
            r.key,
            format!("{:.4e}", r.value),
            e,
            num(r.range[0]),
            num(r.range[1])
        );
    }
    t.trim_end().to_string()
}

/// The "what matters" answer as a CSV table: a row per parameter, in the
/// chart's order, units in the header.
pub fn matters_csv(m: &Matters, output: &str, factor: f64) -> String {
    let num = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
    let mut t = format!("# {output} = {} (sd {}), factor {factor}\n", num(m.here.mean), num(m.here.sd));
    t.push_str(
        "parameter,unit,value,elasticity,converged,x_at_p_over_factor,x_at_p_times_factor,\
         sd_at_p_over_factor,sd_at_p_times_factor,below_noise,status_at_p_over_factor,status_at_p_times_factor,\
         numerical\n",
    );
    let quoted =
        |s: &str| if s.contains([',', '"']) { format!("\"{}\"", s.replace('"', "\"\"")) } else { s.to_string() };
    for r in &m.rows {
        let _ = writeln!(
            t,
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.key,
            r.unit,
            r.value,
            num(r.elasticity),
            r.converged,
            num(r.range[0]),
            num(r.range[1]),
            num(r.range_sd[0]),
            num(r.range_sd[1]),
            r.below_noise,
            quoted(&r.range_status[0]),
            quoted(&r.range_status[1]),
            r.numerical
        );
    }
    t
}

/// The label and unit of scalar `output` of `base`'s scene (from one whole
/// computation per scene and scalar, then remembered).
fn scalar_meta(base: &SceneParams, output: &str, progress: &Progress) -> Result<(String, String), SceneError> {
    static NAMES: OnceLock<Mutex<HashMap<String, (String, String)>>> = OnceLock::new();
    let names = NAMES.get_or_init(|| Mutex::new(HashMap::new()));
    let key = format!("{}\u{1f}{output}", base.info().id);
    if let Some(found) = names.lock().ok().and_then(|n| n.get(&key).cloned()) {
        return Ok(found);
    }
    let here = scene::compute(base, progress)?;
    let found = here
        .scalars
        .iter()
        .find(|s| s.key == output)
        .map(|s| (s.label.to_string(), s.unit.to_string()))
        .ok_or_else(|| PhysicsError::Invalid(format!("no scalar '{output}' in {}", base.info().id)))?;
    if let Ok(mut n) = names.lock() {
        n.insert(key, found.clone());
    }
    Ok(found)
}

/// The parameter `key` of `base`, with a finite range to draw over.
fn knob(base: &SceneParams, key: &str) -> Result<Knob, SceneError> {
    let k = knobs(base)
        .into_iter()
        .find(|k| k.key == key)
        .ok_or_else(|| PhysicsError::Invalid(format!("no numeric parameter '{key}'")))?;
    if !(k.min.is_finite() && k.max.is_finite()) {
        return Err(PhysicsError::Invalid(format!("'{key}' has no finite range to draw")).into());
    }
    Ok(k)
}

/// `n` values over a parameter's whole range, log-spaced where its control
/// is logarithmic.
fn span(k: &Knob, n: usize) -> Vary {
    let spacing = if k.log && k.min > 0.0 { Spacing::Log } else { Spacing::Lin };
    Vary::range(k.key, spacing, k.min, k.max, n.max(2))
}

/// `fig` (whose axes give the scales) with a map of scalar `zs` over the
/// grid `xs` × `ys` (row by row in y; None undefined, left blank): a colour
/// map, log₁₀ where the scalar is positive and spans more than a decade,
/// and contours at the labelled ticks of its range, named by their levels.
/// `names` are the scalar's key (in the contour legend), label (on the
/// colour bar) and unit. The sensitivity maps and the command line's
/// two-parameter sweeps draw their maps here.
pub fn map_figure(
    mut fig: Figure,
    (xs, ys): (&[f64], &[f64]),
    zs: &[Option<f64>],
    names: (&str, &str, &str),
) -> Figure {
    let (key, label, unit) = names;
    let defined: Vec<f64> = zs.iter().flatten().copied().filter(|z| z.is_finite()).collect();
    let (lo, hi) = defined.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &z| (a.min(z), b.max(z)));
    let log = !defined.is_empty() && lo > 0.0 && hi > 10.0 * lo;
    let shown: Vec<f64> = zs.iter().map(|z| z.map_or(f64::NAN, |z| if log { z.log10() } else { z })).collect();
    let colour = if log { format!("log₁₀ {label}") } else { label.to_string() };
    fig.heatmap = Some(Heatmap::new(xs.to_vec(), ys.to_vec(), shown.clone(), &colour, &crate::units::pretty(unit)));
    let scale = if log { Scale::Log } else { Scale::Linear };
    let levels: Vec<f64> = figure::ticks::ticks(lo, hi, scale, 6)
        .into_iter()
        .filter(|t| t.is_major() && t.value > lo && t.value < hi)
        .map(|t| t.value)
        .collect();
    let unit_text = if unit.is_empty() { String::new() } else { format!(" {}", crate::units::pretty(unit)) };
    let list: Vec<String> = levels.iter().map(|&l| figure::human(l)).collect();
    let legend = format!("{key} = {}{unit_text}", list.join(", "));
    let scales = (fig.x.scale, fig.y.scale);
    for level in levels {
        let at = if log { level.log10() } else { level };
        let pts = figure::contour::contour(xs, ys, &shown, at, scales);
        if !pts.is_empty() {
            let name = format!("{key} = {}{unit_text}", figure::human(level));
            let label_at = figure::contour::label_point(&pts, xs, ys, scales);
            fig = fig.with(Series::new(name, pts, Style::Line, 6).keyed(legend.clone()));
            if let Some(p) = label_at {
                fig = fig.label(p, format!("{}{unit_text}", figure::human(level)), None, figure::Anchor::Center);
            }
        }
    }
    fig
}

/// An axis for a parameter.
fn axis_of(k: &Knob, log: bool) -> Axis {
    let unit = crate::units::pretty(k.unit);
    if log { Axis::log(k.label, &unit) } else { Axis::linear(k.label, &unit) }
}

/// Scalar `output` against parameter `key` over its whole documented range
/// (`n` points, log-spaced where the control is logarithmic), as a figure:
/// the curve (broken where the scalar is undefined), error bars of ±σ over
/// the seeds for a Monte Carlo scene, and the current value marked.
pub fn curve(base: &SceneParams, output: &str, key: &str, n: usize, progress: &Progress) -> Result<Figure, SceneError> {
    let k = knob(base, key)?;
    let vary = span(&k, n);
    let (xs, log) = (vary.values(), vary.log_axis());
    let points: Vec<SceneParams> = xs.iter().filter_map(|&x| with(base, key, x)).collect();
    if points.len() != xs.len() {
        return Err(PhysicsError::Invalid(format!("'{key}' refuses values inside its own range")).into());
    }
    let ys = values(&points, output, progress)?;
    let here = value(base, output, progress)?;
    let (y_label, y_unit) = scalar_meta(base, output, progress)?;
    let positive = ys.iter().filter_map(|v| v.mean).all(|y| y > 0.0) && here.mean.is_none_or(|y| y > 0.0);
    let y_unit = crate::units::pretty(&y_unit);
    let y_axis = if positive { Axis::log(&y_label, &y_unit) } else { Axis::linear(&y_label, &y_unit) };
    let mut fig = Figure::new("sensitivity", &format!("{y_label} against {}", k.label), axis_of(&k, log), y_axis);
    let mut pieces: Vec<Vec<[f64; 2]>> = vec![Vec::new()];
    for (x, y) in xs.iter().zip(&ys) {
        match y.mean {
            Some(y) => pieces.last_mut().into_iter().for_each(|p| p.push([*x, y])),
            None if pieces.last().is_some_and(|p| !p.is_empty()) => pieces.push(Vec::new()),
            None => {}
        }
    }
    let name = match here.runs {
        1 => output.to_string(),
        runs => format!("{output} (mean of {runs} seeds)"),
    };
    for (j, piece) in pieces.into_iter().filter(|p| !p.is_empty()).enumerate() {
        let style = if piece.len() == 1 { Style::Points } else { Style::Line };
        fig = fig.with(Series::new(if j == 0 { name.as_str() } else { "" }, piece, style, 0));
    }
    let bars = error_bars(xs.iter().zip(&ys).map(|(&x, v)| (x, *v)), positive);
    if !bars.is_empty() {
        fig = fig.with(Series::new("±σ over the seeds", bars, Style::Line, 0));
    }
    if let Some(y0) = here.mean {
        fig = fig.with(Series::new("current value", vec![[k.value, y0]], Style::Marker, 1));
    }
    Ok(fig)
}

/// Vertical bars of ±σ at each point with a spread, as line pieces
/// separated by breaks (on a log axis the lower end stays positive).
fn error_bars(points: impl Iterator<Item = (f64, Value)>, log: bool) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for (x, v) in points {
        if let (Some(m), Some(s)) = (v.mean, v.sd) {
            let lo = if log && m - s <= 0.0 { m * 1e-3 } else { m - s };
            out.extend([[x, lo], [x, m + s], [f64::NAN, f64::NAN]]);
        }
    }
    out
}

/// Scalar `output` over parameters `key_x` and `key_y` across both whole
/// ranges (`n` × `n` points, log-spaced where the controls are
/// logarithmic), as a map: a colour map (log₁₀ X where X is positive
/// throughout and spans more than a decade), labelled contours, undefined
/// points left blank, and the current point marked.
pub fn map(
    base: &SceneParams,
    output: &str,
    key_x: &str,
    key_y: &str,
    n: usize,
    progress: &Progress,
) -> Result<Figure, SceneError> {
    if key_x == key_y {
        return Err(PhysicsError::Invalid("a map needs two different parameters".into()).into());
    }
    let (kx, ky) = (knob(base, key_x)?, knob(base, key_y)?);
    let (vx, vy) = (span(&kx, n), span(&ky, n));
    let (xs, ys) = (vx.values(), vy.values());
    let (log_x, log_y) = (vx.log_axis(), vy.log_axis());
    // The plan's last parameter runs fastest: x, row by row in y, as a heatmap wants.
    let plan = Plan::new(base.clone(), vec![vy, vx]).map_err(|e| PhysicsError::Invalid(e.to_string()))?;
    let points: Vec<SceneParams> = (0..plan.len()).map(|i| plan.params_at(i)).collect::<Result<_, _>>()?;
    let zs: Vec<Option<f64>> = values(&points, output, progress)?.iter().map(|v| v.mean).collect();
    let (label, unit) = scalar_meta(base, output, progress)?;
    let fig = Figure::new(
        "sensitivity-map",
        &format!("{label} over {} and {}", kx.label, ky.label),
        axis_of(&kx, log_x),
        axis_of(&ky, log_y),
    );
    let fig = map_figure(fig, (&xs, &ys), &zs, (output, &label, &unit));
    Ok(fig.with(Series::new("current point", vec![[kx.value, ky.value]], Style::Marker, 1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn what_matters_finds_the_jkr_exponents() {
        // v_c = (14.18/m*)^{1/2} (γ⁵R⁴/E*²)^{1/6} (2.25): ∂ln v_c/∂ln γ = 5/6,
        // and the relaxation time does not enter.
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let m = what_matters(&base, "v_c", 2.0, &Progress::default()).expect("computes");
        let v_c = m.here.mean.expect("defined");
        assert!(v_c > 0.0 && m.here.sd.is_none());
        let row = |k: &str| m.rows.iter().find(|r| r.key == k).expect(k).clone();
        let gamma = row("surface_energy");
        assert!(gamma.converged && !gamma.below_noise);
        assert!((gamma.elasticity.expect("defined") - 5.0 / 6.0).abs() < 1e-6, "{gamma:?}");
        // Over a factor 2: v_c × 2^{±5/6}.
        let [lo, hi] = gamma.range;
        assert!((lo.expect("low") / v_c - 2f64.powf(-5.0 / 6.0)).abs() < 1e-9);
        assert!((hi.expect("high") / v_c - 2f64.powf(5.0 / 6.0)).abs() < 1e-9);
        assert_eq!(row("t_vis").elasticity, Some(0.0));
        // Sorted by the change over the range: a parameter v_c ignores comes last.
        let at = |k: &str| m.rows.iter().position(|r| r.key == k);
        assert!(at("surface_energy") < at("t_vis"));
        let e = what_matters(&base, "no_such_scalar", 2.0, &Progress::default()).unwrap_err();
        assert!(e.to_string().contains("no scalar 'no_such_scalar'") && e.to_string().contains("v_c"), "{e}");
    }

    #[test]
    fn a_curve_spans_the_range_and_marks_the_current_value() {
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let fig = curve(&base, "v_c", "surface_energy", 20, &Progress::default()).expect("computes");
        let line = &fig.series[0];
        assert_eq!(line.points.len(), 20);
        // v_c ∝ γ^{5/6} along the whole range.
        let [a, b] = [line.points[0], line.points[19]];
        assert!(((b[1] / a[1]).ln() / (b[0] / a[0]).ln() - 5.0 / 6.0).abs() < 1e-9);
        let marker = fig.series.last().expect("marker");
        assert_eq!(marker.points[0][0], 0.74);
        assert!(curve(&base, "v_c", "projectile", 20, &Progress::default()).is_err());
    }

    #[test]
    fn the_quick_path_gives_the_scenes_own_sticking_velocity() {
        // The restitution scene's quick path to v_s must equal the full
        // computation's, bit for bit, away from the defaults too.
        for (gamma, radius) in [(0.74, 2e-6), (0.2, 0.6e-6), (1.5, 20e-6)] {
            let mut p = SceneParams::default_for("restitution").expect("scene");
            p.set("surface_energy", &gamma.to_string()).expect("γ");
            p.set("radius_1", &radius.to_string()).expect("R1");
            p.set("radius_2", &radius.to_string()).expect("R2");
            let full = scene::compute(&p, &Progress::default()).expect("computes");
            for key in ["v_stick", "v_c", "v_y", "e_max"] {
                let quick = scene::scalar(&p, key, &Progress::default()).expect("computes");
                assert_eq!(quick.map(f64::to_bits), full.scalar(key).map(f64::to_bits), "{key} at γ = {gamma}");
            }
        }
    }

    #[test]
    fn a_map_follows_the_jkr_law_in_both_parameters() {
        // v_c ∝ γ^{5/6} R^{2/3} / m*^{1/2}, m* ∝ R³: along radius at fixed γ, v_c ∝ R^{-5/6}.
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let fig = map(&base, "v_c", "surface_energy", "radius_1", 8, &Progress::default()).expect("computes");
        let heat = fig.heatmap.as_ref().expect("a colour map");
        assert_eq!((heat.x.len(), heat.y.len(), heat.values.len()), (8, 8, 64));
        assert!(heat.label.starts_with("log₁₀"));
        // Along x (γ) in the first row: log10 v_c rises by 5/6 per decade of γ.
        let slope = (heat.values[7] - heat.values[0]) / (heat.x[7] / heat.x[0]).log10();
        assert!((slope - 5.0 / 6.0).abs() < 1e-9, "{slope}");
        assert!(fig.series.iter().any(|s| s.name.starts_with("v_c = ")), "labelled contours");
        assert!(map(&base, "v_c", "surface_energy", "surface_energy", 8, &Progress::default()).is_err());
    }

    #[test]
    fn a_monte_carlo_point_is_the_mean_over_its_seeds_with_their_spread() {
        let mut p = SceneParams::default_for("kernel-tests").expect("scene");
        p.set("runs", "3").expect("runs");
        let full = scene::compute(&p, &Progress::default()).expect("computes");
        let key = "events";
        let v = value(&p, key, &Progress::default()).expect("computes");
        assert_eq!(v.runs, 3);
        let mean = v.mean.expect("defined");
        assert!((mean - full.scalar(key).expect("scalar")).abs() <= 1e-12 * mean.abs(), "{v:?}");
        assert!(v.sd.is_some_and(|s| s >= 0.0));
    }
}
