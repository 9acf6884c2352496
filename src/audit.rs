//! The continuity audit: does a scene answer everywhere a user can set it,
//! and does every answer change smoothly where the physics is smooth?
//!
//! [`audit`] sweeps every parameter of a preset's scene over its documented
//! range, one at a time around the preset's point: numbers on a grid
//! (logarithmic where the control is), counts from their smallest value up
//! to the preset's, every other option of a switch or a choice. For every
//! scalar it reports
//! - **errors**: the computation fails at a valid value;
//! - **undefined** values: non-finite where the scene declares no meaning
//!   ([`crate::scene::Scene::CENSORED`]);
//! - **missing** values: reported at some values, absent at others;
//! - **steps**: a change between grid neighbours that stands out from its
//!   neighbours' changes (more than [`TREND`] times their median, and more
//!   than [`RELEVANT`] of the value) and that stays as the interval is
//!   bisected [`Options::refine`] times, all in one half of the last
//!   bracket ([`ONE_SIDED`]) — a jump, not a steep slope or a pole;
//! - **ignored** parameters: ones that change the figures but no scalar
//!   (declared where the parameter's spec says `figure_only`: an axis
//!   range, a curve's resolution, an overlay), and parameters so declared
//!   that do move a scalar.
//!
//! A finding the scene declares as physics ([`crate::scene::Scene::DECLARED`]:
//! a threshold such as sticking, a regime boundary, a parameter that only
//! shapes a figure) is listed with its reason; any other fails the audit.
//! A parameter that changes nothing at all here (e.g. a yield strength with
//! plasticity off) is listed as inert.
//!
//! Scenes of random runs (Monte Carlo) change their random path with every
//! parameter, so their scalars are noisy at every scale: a step there must
//! also exceed [`NOISE`] times the spread of the scalar over independent
//! seeds, at the preset's point and at both ends of the step's bracket.

use crate::scene::schema::Spec;
use crate::scene::schema::{SpecKind, Value};
use crate::scene::spec::short;
use crate::scene::{self, Declared, Irregularity, Progress, SceneError, SceneParams};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};
use std::hash::{Hash, Hasher};

/// A change between grid neighbours is a step candidate when it exceeds this
/// many times the median change of its neighbours.
pub const TREND: f64 = 2.0;

/// Changes below this fraction of the value are never steps (solver
/// tolerances, rounding).
pub const RELEVANT: f64 = 1e-3;

/// A bisected change counts as a jump when it keeps at least this fraction
/// of the grid change it came from (a smooth change halves with every
/// bisection).
pub const KEEPS: f64 = 0.5;

/// A jump sits in one half of its last bracket: that half carries at least
/// this share of the bracket's change (a smooth change splits about evenly,
/// even next to a pole, where the nearer half carries about two thirds).
pub const ONE_SIDED: f64 = 0.9;

/// A step declared as the model's resolution
/// ([`crate::scene::Declared::resolution`]) must shrink below this fraction
/// of its size at four times the resolution (a step of one batch in N shrinks
/// about fourfold; a switch of the physics keeps its size), or below its
/// square at sixteen times (a quantity that a coarse setting does not yet
/// resolve, such as a quantile over a few dozen batches, shrinks from some
/// count on; a switch of the physics keeps its size at every count).
pub const RESOLVED: f64 = 0.5;

/// How much of a resolution step is left at four and sixteen times the
/// resolution (the second only where the first is not below [`RESOLVED`]).
#[derive(Debug, Clone, Copy)]
struct Finer {
    four: f64,
    sixteen: Option<f64>,
}

/// For a scene of random runs: a step must also exceed this many standard
/// deviations of the scalar over independent seeds, at the preset's point
/// and at both ends of the step's last bracket.
pub const NOISE: f64 = 4.0;

/// Independent seeds (sets of the scene's runs) that estimate a scalar's
/// scatter.
const SEEDS: usize = 4;

/// Why an ignored parameter declared `figure_only` in its spec is no defect.
pub const FIGURE_ONLY: &str = "it sets only what a figure shows (its spec says so)";

/// How finely to look.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Grid points along each numeric parameter's range.
    pub points: usize,
    /// Bisections of each step candidate's interval.
    pub refine: usize,
    /// Only these parameters (keys); every parameter when empty.
    pub only: Vec<String>,
    /// Numbers swept no higher than these values (keys and SI values): the
    /// resolution parameters a coarse setting lowered ([`ceilings`]), whose
    /// range beyond it costs more than the audited point itself.
    pub ceilings: Vec<(String, f64)>,
}

/// The numeric parameters that `coarse` sets below `full` (a resolution such
/// as the groups per decade of a Monte Carlo run), each with its coarse
/// value: the audit of a coarse setting sweeps them from their smallest
/// value up to there, as it sweeps counts up to the preset's.
pub fn ceilings(full: &SceneParams, coarse: &SceneParams) -> Vec<(String, f64)> {
    coarse
        .specs()
        .iter()
        .filter_map(|s| match (coarse.get(s.key)?, full.get(s.key)?) {
            (Value::Number(c), Value::Number(f)) if c < f => Some((s.key.to_string(), c)),
            _ => None,
        })
        .collect()
}

impl Default for Options {
    fn default() -> Self {
        Options { points: 24, refine: 10, only: Vec::new(), ceilings: Vec::new() }
    }
}

/// One finding of the audit.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Finding {
    /// What was found.
    pub kind: Irregularity,
    /// The parameter along which it was found.
    pub parameter: &'static str,
    /// The scalar it concerns; empty for a finding about the parameter
    /// itself (an error, an ignored parameter).
    pub scalar: String,
    /// Where: the parameter's values (SI), one value or a bracket.
    pub at: Vec<f64>,
    /// What was seen, in words and numbers.
    pub detail: String,
    /// The scene's reason, where it declares the finding as physics.
    pub declared: Option<&'static str>,
}

/// The audit of one preset.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Report {
    /// The scene's identifier.
    pub scene: &'static str,
    /// Parameters swept.
    pub parameters: usize,
    /// Computations made.
    pub computations: usize,
    /// Points the scene's own checks refused (a combination outside what
    /// the scene accepts, e.g. a range end past the other end).
    pub refused: usize,
    /// Every finding, declared ones included.
    pub findings: Vec<Finding>,
    /// Parameters that change nothing at all at this point.
    pub inert: Vec<&'static str>,
}

impl Report {
    /// The findings the scene does not declare: what fails the audit.
    pub fn failures(&self) -> impl Iterator<Item = &Finding> {
        self.findings.iter().filter(|f| f.declared.is_none())
    }

    /// The report as text, a line per finding.
    pub fn text(&self) -> String {
        let mut s = format!(
            "{}: {} parameters, {} computations, {} refused points\n",
            self.scene, self.parameters, self.computations, self.refused
        );
        for f in &self.findings {
            let what = if f.scalar.is_empty() {
                f.parameter.to_string()
            } else {
                format!("{} along {}", f.scalar, f.parameter)
            };
            match f.declared {
                None => s += &format!("  FAIL {:<9} {what}: {}\n", f.kind.word(), f.detail),
                Some(why) => s += &format!("  ok   {:<9} {what}: {} (declared: {why})\n", f.kind.word(), f.detail),
            }
        }
        if !self.inert.is_empty() {
            s += &format!("  inert here: {}\n", self.inert.join(", "));
        }
        s
    }
}

/// What one computation gave.
#[derive(Debug, Clone)]
enum Point {
    /// The scene refused the combination.
    Refused,
    /// The computation failed.
    Failed(String),
    /// The scalars (key, value, unit) and a fingerprint of the figures.
    Done { scalars: Vec<(&'static str, f64, &'static str)>, figures: u64 },
}

impl Point {
    fn scalar(&self, key: &str) -> Option<f64> {
        match self {
            Point::Done { scalars, .. } => scalars.iter().find(|s| s.0 == key).map(|s| s.1),
            _ => None,
        }
    }
}

/// A fingerprint of a scene's figures: every number they draw.
fn fingerprint(figures: &[crate::figure::Figure]) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for f in figures {
        f.id.hash(&mut h);
        for s in &f.series {
            s.points.len().hash(&mut h);
            for p in &s.points {
                p[0].to_bits().hash(&mut h);
                p[1].to_bits().hash(&mut h);
            }
        }
        if let Some(m) = &f.heatmap {
            for v in m.x.iter().chain(&m.y).chain(&m.values) {
                v.to_bits().hash(&mut h);
            }
        }
    }
    h.finish()
}

/// Computes `params`.
fn compute(params: &SceneParams, progress: &Progress) -> Result<Point, SceneError> {
    if params.validate().is_err() {
        return Ok(Point::Refused);
    }
    match scene::compute(params, &progress.quiet_child()) {
        Ok(out) => Ok(Point::Done {
            scalars: out.scalars.iter().map(|s| (s.key, s.value, s.unit)).collect(),
            figures: fingerprint(&out.figures),
        }),
        Err(SceneError::Cancelled) => Err(SceneError::Cancelled),
        Err(SceneError::Param(_)) => Ok(Point::Refused),
        Err(SceneError::Physics(e)) => Ok(Point::Failed(e.to_string())),
    }
}

/// How a parameter is swept.
#[derive(Debug, Clone)]
enum Sweep {
    /// A number over `[min, max]`, on a grid in `u` (ln x where `log`).
    Number { log: bool },
    /// A count: whole numbers.
    Count,
    /// A switch or a choice: its other options.
    Options,
}

/// A parameter and the points along it.
struct Line {
    key: &'static str,
    spec: &'static Spec,
    sweep: Sweep,
    /// Grid coordinate (for numbers: x or ln x), the value set, the result.
    points: Vec<(f64, Value, Point)>,
}

/// `base` with parameter `key` set to `value`, or None where it is refused.
fn with(base: &SceneParams, key: &str, value: &Value) -> Option<SceneParams> {
    let mut p = base.clone();
    p.set_value(key, value).ok().map(|_| p)
}

/// A parameter, how it is swept, and its grid: (u, value) per point.
type Planned = (&'static Spec, Sweep, Vec<(f64, Value)>);

/// A confirmed step: the candidate and its narrowed bracket, (u, y) at each end.
type Bracket = (Candidate, (f64, f64), (f64, f64));

/// The values along each parameter of `base`: (key, sweep, [(u, value)]).
fn plan(base: &SceneParams, options: &Options) -> Vec<Planned> {
    let n = options.points.max(3);
    base.specs()
        .iter()
        .filter(|s| !s.style_only)
        .filter(|s| options.only.is_empty() || options.only.iter().any(|k| k == s.key))
        .filter_map(|s| {
            let here = base.get(s.key)?;
            match (&s.kind, here) {
                (SpecKind::Number { min, max, log, .. }, Value::Number(_)) => {
                    let ceiling = options.ceilings.iter().find(|(k, _)| k == s.key).map(|c| c.1);
                    let max = &ceiling.map_or(*max, |c| c.min(*max));
                    let (a, b) = if *log { (min.ln(), max.ln()) } else { (*min, *max) };
                    if !(a.is_finite() && b.is_finite() && b > a) {
                        return None;
                    }
                    let values = (0..n)
                        .map(|i| {
                            let u = a + (b - a) * i as f64 / (n - 1) as f64;
                            let x = if *log { u.exp() } else { u };
                            (u, Value::Number(x.clamp(*min, *max)))
                        })
                        .collect();
                    Some((s, Sweep::Number { log: *log }, values))
                }
                (SpecKind::Count { min, max }, Value::Count(here)) => {
                    // From the smallest count up to the preset's (no dearer
                    // than the preset), or a few above the smallest.
                    let top = if here > *min { here } else { (*min * 4).max(*min + 3).min(*max) };
                    let mut counts: BTreeSet<usize> = BTreeSet::new();
                    for i in 0..6 {
                        let f = i as f64 / 5.0;
                        let c = (*min.max(&1) as f64).powf(1.0 - f) * (top as f64).powf(f);
                        counts.insert((c.round() as usize).clamp(*min, top));
                    }
                    counts.insert(*min);
                    counts.remove(&here);
                    Some((s, Sweep::Count, counts.into_iter().map(|c| (c as f64, Value::Count(c))).collect()))
                }
                (SpecKind::Toggle, Value::Toggle(on)) => Some((s, Sweep::Options, vec![(0.0, Value::Toggle(!on))])),
                (SpecKind::Choice { options }, Value::Text(here)) => Some((
                    s,
                    Sweep::Options,
                    options
                        .iter()
                        .filter(|(k, _)| *k != here)
                        .enumerate()
                        .map(|(i, (k, _))| (i as f64, Value::Text(k.to_string())))
                        .collect(),
                )),
                _ => None,
            }
        })
        .collect()
}

/// Audits the scene of `base` (see the module's documentation).
pub fn audit(base: &SceneParams, options: &Options, progress: &Progress) -> Result<Report, SceneError> {
    base.validate()?;
    if let Some(k) = options.only.iter().find(|k| base.spec(k).is_none()) {
        return Err(crate::scene::ParamError::unknown(k, &base.keys()).into());
    }
    let declared = base.declared();
    let censored = base.censored();
    // The preset's own point: its error, if any, is the audit's.
    let out = scene::compute(base, &progress.quiet_child())?;
    let base_keys: Vec<&'static str> = out.scalars.iter().map(|s| s.key).collect();
    let here = Point::Done {
        scalars: out.scalars.iter().map(|s| (s.key, s.value, s.unit)).collect(),
        figures: fingerprint(&out.figures),
    };
    let noise = spread(base, &base_keys, progress)?;

    // Every point of every line, computed in parallel.
    let planned = plan(base, options);
    let flat: Vec<(usize, f64, Value)> = planned
        .iter()
        .enumerate()
        .flat_map(|(i, (_, _, values))| values.iter().map(move |(u, v)| (i, *u, v.clone())))
        .collect();
    let done: Vec<Point> = flat
        .par_iter()
        .map(|(i, _, v)| match with(base, planned[*i].0.key, v) {
            Some(p) => compute(&p, progress),
            None => Ok(Point::Refused),
        })
        .collect::<Result<_, _>>()?;
    let mut lines: Vec<Line> = planned
        .iter()
        .map(|(spec, sweep, _)| Line { key: spec.key, spec, sweep: sweep.clone(), points: Vec::new() })
        .collect();
    for ((i, u, v), point) in flat.into_iter().zip(done) {
        lines[i].points.push((u, v, point));
    }

    let mut report = Report {
        scene: base.info().id,
        parameters: lines.len(),
        computations: 1 + lines.iter().map(|l| l.points.len()).sum::<usize>(),
        refused: lines.iter().flat_map(|l| &l.points).filter(|p| matches!(p.2, Point::Refused)).count(),
        findings: Vec::new(),
        inert: Vec::new(),
    };
    let mut candidates = Vec::new();
    for line in &lines {
        let shown = |v: &Value| format!("{} = {}", line.key, line.spec.display(v));
        let si = |v: &Value| match v {
            Value::Number(x) => vec![*x],
            Value::Count(c) => vec![*c as f64],
            _ => Vec::new(),
        };
        let mut push = |kind, scalar: &str, at: Vec<f64>, detail: String| {
            let d = Declared::find(declared, kind, if scalar.is_empty() { "*" } else { scalar }, line.key);
            report.findings.push(Finding {
                kind,
                parameter: line.key,
                scalar: scalar.to_string(),
                at,
                detail,
                declared: d
                    .map(|d| d.why)
                    .or((kind == Irregularity::Ignored && line.spec.figure_only).then_some(FIGURE_ONLY)),
            });
        };

        // Failures.
        let failed: Vec<(&Value, &String)> = line
            .points
            .iter()
            .filter_map(|(_, v, p)| if let Point::Failed(e) = p { Some((v, e)) } else { None })
            .collect();
        if let Some((v, e)) = failed.first() {
            push(
                Irregularity::Error,
                "",
                si(v),
                format!("fails at {} of {} points, first at {}: {e}", failed.len(), line.points.len(), shown(v)),
            );
        }

        // Missing and undefined values.
        let mut keys: BTreeSet<&'static str> = base_keys.iter().copied().collect();
        for (_, _, p) in &line.points {
            if let Point::Done { scalars, .. } = p {
                keys.extend(scalars.iter().map(|s| s.0));
            }
        }
        let done: Vec<&(f64, Value, Point)> =
            line.points.iter().filter(|(_, _, p)| matches!(p, Point::Done { .. })).collect();
        for key in &keys {
            let absent: Vec<&Value> = done.iter().filter(|(_, _, p)| p.scalar(key).is_none()).map(|t| &t.1).collect();
            if let Some(v) = absent.first().filter(|_| absent.len() < done.len() || base_keys.contains(key)) {
                push(
                    Irregularity::Missing,
                    key,
                    si(v),
                    format!("absent at {} of {} points, first at {}", absent.len(), done.len(), shown(v)),
                );
            }
            let undefined: Vec<(&Value, f64)> = done
                .iter()
                .filter_map(|(_, v, p)| p.scalar(key).filter(|x| !meant(censored, key, *x)).map(|x| (v, x)))
                .collect();
            if let Some((v, x)) = undefined.first() {
                push(
                    Irregularity::Undefined,
                    key,
                    si(v),
                    format!(
                        "{x} at {} of {} points, first at {}, with no stated meaning",
                        undefined.len(),
                        done.len(),
                        shown(v)
                    ),
                );
            }
        }

        // Ignored and inert parameters.
        // The preset's own point and every computed one.
        let seen: Vec<&Point> = std::iter::once(&here).chain(done.iter().map(|t| &t.2)).collect();
        let fingerprints: BTreeSet<u64> = seen
            .iter()
            .filter_map(|p| match p {
                Point::Done { figures, .. } => Some(*figures),
                _ => None,
            })
            .collect();
        let scalars_move = keys.iter().any(|key| {
            let xs: BTreeSet<u64> = seen
                .iter()
                .filter_map(|p| p.scalar(key))
                .map(|x| if x.is_nan() { u64::MAX } else { x.to_bits() })
                .collect();
            xs.len() > 1
        });
        if line.spec.figure_only && scalars_move {
            push(
                Irregularity::Moves,
                "",
                Vec::new(),
                "declared to set only what a figure shows, but a scalar moves with it".into(),
            );
        }
        if !scalars_move && !done.is_empty() {
            if fingerprints.len() > 1 {
                push(Irregularity::Ignored, "", Vec::new(), "changes the figures but no scalar".into());
            } else {
                report.inert.push(line.key);
            }
        }

        // Step candidates along numbers.
        if let Sweep::Number { log, .. } = line.sweep {
            for key in &keys {
                let ys: Vec<Option<f64>> =
                    line.points.iter().map(|(_, _, p)| p.scalar(key).filter(|x| x.is_finite())).collect();
                let change = |i: usize| -> Option<f64> {
                    let (a, b) = (ys.get(i).copied()??, ys.get(i + 1).copied()??);
                    let scale = a.abs().max(b.abs());
                    Some(if scale > 0.0 { (b - a).abs() / scale } else { 0.0 })
                };
                for i in 0..ys.len().saturating_sub(1) {
                    let Some(d) = change(i) else { continue };
                    let mut around: Vec<f64> = [i.wrapping_sub(2), i.wrapping_sub(1), i + 1, i + 2]
                        .iter()
                        .filter_map(|&j| change(j))
                        .collect();
                    around.sort_by(f64::total_cmp);
                    let trend = if around.is_empty() { 0.0 } else { around[around.len() / 2] };
                    let (ya, yb) = (ys[i].unwrap_or(0.0), ys[i + 1].unwrap_or(0.0));
                    let sd = noise.get(*key).copied().unwrap_or(0.0);
                    if d > RELEVANT && d > TREND * trend && (yb - ya).abs() > NOISE * sd {
                        candidates.push(Candidate {
                            line: line.key,
                            scalar: key,
                            log,
                            a: (line.points[i].0, ya),
                            b: (line.points[i + 1].0, yb),
                            sd,
                        });
                    }
                }
            }
        }
    }

    // Bisect the candidates: a jump stays, a steep slope shrinks.
    let random = !noise.is_empty();
    let steps: Vec<(Option<Bracket>, usize)> = candidates
        .into_par_iter()
        .map(|c| {
            let (mut a, mut b) = (c.a, c.b);
            let scale = a.1.abs().max(b.1.abs());
            let d0 = (b.1 - a.1).abs();
            // The share of the last bracket's change its larger half carries.
            let mut share = 1.0;
            for _ in 0..options.refine {
                let u = 0.5 * (a.0 + b.0);
                let x = if c.log { u.exp() } else { u };
                let Some(p) = with(base, c.line, &Value::Number(x)) else { return Ok((None, 0)) };
                let Some(y) = compute(&p, progress)?.scalar(c.scalar).filter(|y| y.is_finite()) else {
                    // The scalar leaves its defined range inside: a stated
                    // boundary, not a step.
                    return Ok((None, 0));
                };
                let whole = (b.1 - a.1).abs();
                let (left, right) = ((y - a.1).abs(), (b.1 - y).abs());
                share = if whole > 0.0 { left.max(right) / whole } else { 1.0 };
                if left >= right {
                    b = (u, y);
                } else {
                    a = (u, y);
                }
            }
            let d = (b.1 - a.1).abs();
            let jump = d > KEEPS * d0 && d > RELEVANT * scale && d > NOISE * c.sd && share >= ONE_SIDED;
            if !jump || !random {
                return Ok((jump.then_some((c, a, b)), 0));
            }
            // Random runs scatter by different amounts in different regimes
            // (a steady state of erosion or fragmentation scatters more than
            // the preset's growth), and the bisection picked the bracket
            // whose two runs differ most, so their difference overstates the
            // step. Independent seeds at both ends decide: their means must
            // differ by more than NOISE standard errors.
            let mut ends = Vec::with_capacity(2);
            for u in [a.0, b.0] {
                let x = if c.log { u.exp() } else { u };
                let Some(p) = with(base, c.line, &Value::Number(x)) else { return Ok((None, 0)) };
                let values: Vec<f64> =
                    seeded(&p, progress)?.iter().filter_map(|q| q.scalar(c.scalar)).filter(|y| y.is_finite()).collect();
                ends.push(values);
            }
            Ok((apart(&ends[0], &ends[1]).then_some((c, a, b)), 2 * SEEDS))
        })
        .collect::<Result<_, SceneError>>()?;
    report.computations += steps.len() * options.refine + steps.iter().map(|s| s.1).sum::<usize>();
    let steps: Vec<Bracket> = steps.into_iter().filter_map(|s| s.0).collect();
    // A step declared as the model's resolution is held to it: at four times
    // the count that sets the resolution, the same bracket must change by
    // less than half as much. The change there, relative to the step's.
    let finer: Vec<Option<Result<Finer, String>>> = steps
        .par_iter()
        .map(|(c, a, b)| {
            let Some(count) = Declared::find(declared, Irregularity::Step, c.scalar, c.line).and_then(|d| d.resolution)
            else {
                return Ok(None);
            };
            // A count (batches) or a real number (an event limit, in millions):
            // finer is `times` as much, at most its largest value.
            let (n, max) = match (base.get(count), base.spec(count).map(|s| &s.kind)) {
                (Some(Value::Count(n)), Some(SpecKind::Count { max, .. })) if n < *max => (n as f64, *max as f64),
                (Some(Value::Number(n)), Some(SpecKind::Number { max, .. })) if n < *max => (n, *max),
                _ => return Ok(Some(Err(format!("{count} is at its largest value: no finer resolution to check")))),
            };
            let whole = matches!(base.get(count), Some(Value::Count(_)));
            let x = |u: f64| if c.log { u.exp() } else { u };
            let at = |u: f64, refined: f64| -> Result<Option<f64>, SceneError> {
                let Some(p) = with(base, c.line, &Value::Number(x(u))) else { return Ok(None) };
                let refined = if whole { Value::Count(refined as usize) } else { Value::Number(refined) };
                let Some(p) = with(&p, count, &refined) else { return Ok(None) };
                Ok(match compute(&p, progress)? {
                    Point::Done { scalars, .. } => {
                        scalars.iter().find(|s| s.0 == c.scalar).map(|s| s.1).filter(|v| v.is_finite())
                    }
                    _ => None,
                })
            };
            let step = (b.1 - a.1).abs();
            let change = |refined: f64| -> Result<Result<f64, String>, SceneError> {
                Ok(match (at(a.0, refined)?, at(b.0, refined)?) {
                    (Some(ya), Some(yb)) if step > 0.0 => Ok((yb - ya).abs() / step),
                    _ => Err(format!("no value at {refined} {count}")),
                })
            };
            let four = change((4.0 * n).min(max))?;
            Ok(Some(match four {
                Ok(ratio) if ratio >= RESOLVED && 4.0 * n < max => match change((16.0 * n).min(max))? {
                    Ok(sixteen) => Ok(Finer { four: ratio, sixteen: Some(sixteen) }),
                    Err(_) => Ok(Finer { four: ratio, sixteen: None }),
                },
                other => other.map(|four| Finer { four, sixteen: None }),
            }))
        })
        .collect::<Result<_, SceneError>>()?;
    report.computations += finer
        .iter()
        .flatten()
        .map(|f| f.as_ref().map_or(2, |f| 2 + 2 * usize::from(f.sixteen.is_some())))
        .sum::<usize>();
    for ((c, a, b), finer) in steps.into_iter().zip(finer) {
        let x = |u: f64| if c.log { u.exp() } else { u };
        let shown = |u: f64| match lines.iter().find(|l| l.key == c.line) {
            Some(l) => l.spec.display(&Value::Number(x(u))),
            None => short(x(u)),
        };
        let sunit = match &here {
            Point::Done { scalars, .. } => scalars.iter().find(|s| s.0 == c.scalar).map(|s| s.2).unwrap_or(""),
            _ => "",
        };
        let rel = if a.1 != 0.0 { format!(" ({:+.1} %)", 100.0 * (b.1 / a.1 - 1.0)) } else { String::new() };
        let detail = format!(
            "{} → {} {sunit}{rel} between {} = {} and {}",
            short(a.1),
            short(b.1),
            c.line,
            shown(a.0),
            shown(b.0),
        );
        let mut d = Declared::find(declared, Irregularity::Step, c.scalar, c.line).map(|d| d.why);
        let mut detail = detail.replace("  ", " ").trim_end().to_string();
        match finer {
            Some(Ok(Finer { four, .. })) if four < RESOLVED => {
                detail += &format!("; {:.0} % of it at four times the resolution", 100.0 * four);
            }
            Some(Ok(Finer { four, sixteen: Some(sixteen) })) if sixteen < RESOLVED * RESOLVED => {
                detail += &format!(
                    "; {:.0} % of it at four times the resolution and {:.0} % at sixteen times",
                    100.0 * four,
                    100.0 * sixteen
                );
            }
            Some(Ok(Finer { four, sixteen })) => {
                // Not a resolution step after all: open, unless a later
                // declaration says it is physics.
                let sixteen = sixteen.map_or(String::new(), |r| format!(" and {:.0} % at sixteen times", 100.0 * r));
                detail += &format!(
                    "; at four times the resolution it keeps {:.0} % of its size{sixteen}: not a step of the resolution",
                    100.0 * four
                );
                d = Declared::find_physics(declared, Irregularity::Step, c.scalar, c.line).map(|d| d.why);
            }
            Some(Err(why)) => detail += &format!("; not checked at a finer resolution: {why}"),
            None => {}
        }
        report.findings.push(Finding {
            kind: Irregularity::Step,
            parameter: c.line,
            scalar: c.scalar.to_string(),
            at: vec![x(a.0), x(b.0)],
            detail,
            declared: d,
        });
    }
    Ok(report)
}

/// A step candidate: scalar `scalar` along `line` between grid points `a`
/// and `b` ((u, y) each).
#[derive(Debug, Clone)]
struct Candidate {
    line: &'static str,
    scalar: &'static str,
    log: bool,
    a: (f64, f64),
    b: (f64, f64),
    sd: f64,
}

/// Whether a value of scalar `key` is a number or has a stated meaning.
fn meant(censored: &[scene::Censored], key: &str, x: f64) -> bool {
    x.is_finite()
        || !matches!(scene::status(censored, key, x), scene::Status::Undefined { why } if why == scene::NOT_FINITE)
}

/// For a scene of random runs, each scalar's standard deviation over four
/// independent seeds at the preset's point (of the scene's own mean over
/// its runs); empty for a deterministic scene.
fn spread(
    base: &SceneParams,
    keys: &[&'static str],
    progress: &Progress,
) -> Result<BTreeMap<&'static str, f64>, SceneError> {
    let done = seeded(base, progress)?;
    if done.is_empty() {
        return Ok(BTreeMap::new());
    }
    Ok(keys
        .iter()
        .map(|key| {
            let xs: Vec<f64> = done.iter().filter_map(|p| p.scalar(key)).filter(|x| x.is_finite()).collect();
            (*key, mean_and_variance(&xs).1.sqrt())
        })
        .collect())
}

/// The points of [`SEEDS`] independent sets of a random scene's runs (first
/// seeds after the preset's own runs); empty for a deterministic scene.
fn seeded(base: &SceneParams, progress: &Progress) -> Result<Vec<Point>, SceneError> {
    let mut p = base.clone();
    let Some((first, runs)) = p.seeds().map(|s| (*s.first, *s.runs)) else { return Ok(Vec::new()) };
    let points: Vec<SceneParams> = (1..=SEEDS)
        .map(|k| {
            let mut q = base.clone();
            if let Some(s) = q.seeds() {
                *s.first = first + k * runs.max(1);
            }
            q
        })
        .collect();
    points.par_iter().map(|q| compute(q, progress)).collect()
}

/// The mean and the sample variance (0 for fewer than two values).
fn mean_and_variance(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n.max(1.0);
    let var = if xs.len() > 1 { xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0) } else { 0.0 };
    (mean, var)
}

/// Whether two sets of a scalar's values over independent seeds come from
/// different distributions: their means differ by more than [`NOISE`]
/// standard errors (Welch's statistic). Values that are all positive are
/// compared in ln: a peak mass near a runaway scatters over decades, and its
/// logarithm is the nearer to normal. Sets without scatter differ when
/// their means do; fewer than two values on a side decide nothing.
fn apart(a: &[f64], b: &[f64]) -> bool {
    if a.len() < 2 || b.len() < 2 {
        return false;
    }
    let positive = a.iter().chain(b).all(|x| *x > 0.0);
    let tr = |xs: &[f64]| -> Vec<f64> { if positive { xs.iter().map(|x| x.ln()).collect() } else { xs.to_vec() } };
    let ((ma, va), (mb, vb)) = (mean_and_variance(&tr(a)), mean_and_variance(&tr(b)));
    let se = (va / a.len() as f64 + vb / b.len() as f64).sqrt();
    let d = (mb - ma).abs();
    if se > 0.0 { d > NOISE * se } else { d > 1e-12 * ma.abs().max(mb.abs()).max(1e-300) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent seeds decide a random step: the peak masses of four
    /// seeds on either side of α = 2.15 × 10⁻⁵ (`mc-fig-5-2-porosity` at its
    /// coarse setting, runs cut by the event limit in the runaway) scatter
    /// over a factor of five and are one distribution; ζ = 1 exactly against
    /// a shattering column, and a shift of forty standard errors, are steps.
    #[test]
    fn seeds_tell_a_step_from_scatter() {
        let below = [1.886e11, 2.940e11, 3.703e11, 4.645e11];
        let above = [3.043e11, 1.393e11, 5.535e11, 8.920e10];
        assert!(!apart(&below, &above));
        assert!(apart(&[1.0; 4], &[-0.93, -0.95, -0.88, -0.91]));
        assert!(apart(&[1.0, 1.01, 0.99, 1.0], &[1.4, 1.41, 1.39, 1.4]));
        assert!(!apart(&[1.0, 1.01, 0.99, 1.0], &[1.0, 1.005, 1.0, 0.995]));
        // No scatter on either side: the means decide.
        assert!(!apart(&[2.0; 4], &[2.0; 4]));
        assert!(apart(&[2.0; 4], &[3.0; 4]));
        // One value a side decides nothing.
        assert!(!apart(&[1.0], &[5.0]));
    }

    /// A ceiling ends a number's grid at itself (from the documented
    /// smallest value, in the control's own spacing); without one the grid
    /// spans the documented range.
    #[test]
    fn a_ceiling_ends_a_numbers_grid() {
        let base = SceneParams::default_for("restitution").expect("scene");
        let key = "velocity";
        let Some(SpecKind::Number { min, max, log: true, .. }) = base.spec(key).map(|s| &s.kind) else {
            panic!("{key} is a logarithmic number")
        };
        let grid = |ceilings: Vec<(String, f64)>| -> Vec<f64> {
            let options = Options { points: 5, only: vec![key.into()], ceilings, ..Options::default() };
            plan(&base, &options)[0]
                .2
                .iter()
                .map(|(_, v)| if let Value::Number(x) = v { *x } else { f64::NAN })
                .collect()
        };
        let full = grid(Vec::new());
        assert!((full[0] / min - 1.0).abs() < 1e-12 && (full[4] / max - 1.0).abs() < 1e-12, "{full:?}");
        let capped = grid(vec![(key.into(), 3.0)]);
        assert_eq!(capped.len(), 5);
        assert!((capped[0] / min - 1.0).abs() < 1e-12 && (capped[4] / 3.0 - 1.0).abs() < 1e-12, "{capped:?}");
        // Evenly spaced in ln v, as the control is.
        assert!(((capped[2] / capped[1]) / (capped[1] / capped[0]) - 1.0).abs() < 1e-9, "{capped:?}");
        // A ceiling at or below the smallest value leaves nothing to sweep.
        let options =
            Options { points: 5, only: vec![key.into()], ceilings: vec![(key.into(), *min)], ..Options::default() };
        assert!(plan(&base, &options).is_empty());
    }

    /// The ceilings of a Monte Carlo column's coarse setting are the
    /// resolution it lowers: the groups per decade and the event limit.
    #[test]
    fn a_monte_carlo_columns_coarse_setting_caps_its_resolution() {
        let mut full = SceneParams::default_for("mass-distribution").expect("scene");
        full.set("groups_per_decade", "60").expect("w*");
        full.set("runs", "4").expect("runs");
        let coarse = full.coarse().expect("a preview");
        assert_eq!(
            ceilings(&full, &coarse),
            vec![("groups_per_decade".to_string(), 10.0), ("max_events_millions".to_string(), 0.2)]
        );
    }
}
