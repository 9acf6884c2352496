//! Sweeps: a scene's scalar results over a grid of parameter values, as one
//! tidy table (a row per point: the varied parameters, then the scalars).
//!
//! A [`Plan`] is a preset's parameters and the parameters varied
//! ([`Vary`], each `NAME=lin|log:FROM:TO:N` or `NAME=list:V1:V2:…`); its points are numbered in a
//! fixed order (the last varied parameter fastest), so that a [`Shard`] of
//! the plan, its rows and a merge of shards are deterministic: the rows of
//! every shard together are the rows of the whole plan, byte for byte.
//! Points run in parallel (rayon); one that fails records its error in its
//! row and the sweep goes on. Nothing here touches files: the command line
//! reads and writes the table.

use crate::parallel::prelude::*;
use crate::scene::{self, Progress, SceneError, SceneOutput, SceneParams, Status};
use std::fmt::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Why a sweep cannot be planned, or a table not read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    /// A `--vary` text that is not `NAME=lin|log:FROM:TO:N` or `NAME=list:V1:V2:…`.
    #[error("'{0}' is not NAME=lin|log:FROM:TO:N or NAME=list:V1:V2:… (e.g. surface_energy=log:0.1:1:20)")]
    Syntax(String),
    /// A varied parameter the scene does not have, or not a number.
    #[error("{0}")]
    Parameter(String),
    /// A shard that is not `K/N` with 1 ≤ K ≤ N, or `auto` outside a Slurm array.
    #[error("{0}")]
    Shard(String),
    /// A table that does not belong to this plan or is malformed.
    #[error("{0}")]
    Table(String),
}

/// How the values of a varied parameter are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Spacing {
    /// Evenly.
    Lin,
    /// Evenly in the logarithm (both ends positive).
    Log,
    /// The values given, in their order.
    List,
}

/// One varied parameter: its key and its values.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Vary {
    /// The parameter's documented key (SI units).
    pub key: String,
    /// Spacing of the values.
    pub spacing: Spacing,
    /// First value.
    pub from: f64,
    /// Last value.
    pub to: f64,
    /// Number of values (at least 1).
    pub n: usize,
    /// The values of a [`Spacing::List`] (empty otherwise).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub given: Vec<f64>,
}

impl Vary {
    /// Evenly spaced values (`Lin` or `Log`), `from` first and `to` last.
    pub fn range(key: &str, spacing: Spacing, from: f64, to: f64, n: usize) -> Vary {
        Vary { key: key.to_string(), spacing, from, to, n, given: Vec::new() }
    }

    /// Reads `NAME=lin|log:FROM:TO:N` or `NAME=list:V1:V2:…`.
    pub fn parse(text: &str) -> Result<Vary, SweepError> {
        let bad = || SweepError::Syntax(text.to_string());
        let (key, rest) = text.split_once('=').ok_or_else(bad)?;
        let parts: Vec<&str> = rest.split(':').collect();
        let number = |s: &str| s.trim().parse::<f64>().ok().filter(|v| v.is_finite());
        if let ["list", values @ ..] = &parts[..] {
            let given = values.iter().map(|v| number(v)).collect::<Option<Vec<f64>>>().ok_or_else(bad)?;
            let key = key.trim();
            if key.is_empty() || given.is_empty() || given.len() > 1_000_000 {
                return Err(bad());
            }
            let (from, to) = (given[0], given[given.len() - 1]);
            return Ok(Vary { key: key.to_string(), spacing: Spacing::List, from, to, n: given.len(), given });
        }
        let [spacing, from, to, n] = parts[..] else { return Err(bad()) };
        let spacing = match spacing {
            "lin" => Spacing::Lin,
            "log" => Spacing::Log,
            _ => return Err(bad()),
        };
        let (Some(from), Some(to)) = (number(from), number(to)) else { return Err(bad()) };
        let n: usize = n.trim().parse().map_err(|_| bad())?;
        let key = key.trim().to_string();
        if key.is_empty() || n == 0 || n > 1_000_000 {
            return Err(bad());
        }
        if spacing == Spacing::Log && !(from > 0.0 && to > 0.0) {
            return Err(SweepError::Syntax(format!("{text}: a log range needs positive ends")));
        }
        Ok(Vary::range(&key, spacing, from, to, n))
    }

    /// The values, `from` first and `to` last. Values between are rounded to
    /// 15 significant digits, so that a log grid from 1e-6 to 4e-6 holds
    /// 2e-6 (not 2.000000000000001e-6) and tables print them as written.
    pub fn values(&self) -> Vec<f64> {
        let round = |x: f64| format!("{x:.14e}").parse().unwrap_or(x);
        if self.spacing == Spacing::List {
            return self.given.clone();
        }
        if self.n == 1 {
            return vec![self.from];
        }
        let last = (self.n - 1) as f64;
        (0..self.n)
            .map(|i| match (i, self.spacing) {
                (0, _) => self.from,
                (i, _) if i == self.n - 1 => self.to,
                (_, Spacing::List) => self.given[i],
                (i, Spacing::Lin) => round(self.from + (self.to - self.from) * i as f64 / last),
                (i, Spacing::Log) => round((self.from.ln() + (self.to / self.from).ln() * i as f64 / last).exp()),
            })
            .collect()
    }

    /// The text it was read from, in canonical form.
    pub fn text(&self) -> String {
        let s = match self.spacing {
            Spacing::Lin => "lin",
            Spacing::Log => "log",
            Spacing::List => {
                let values: Vec<String> = self.given.iter().map(|v| v.to_string()).collect();
                return format!("{}=list:{}", self.key, values.join(":"));
            }
        };
        format!("{}={s}:{}:{}:{}", self.key, self.from, self.to, self.n)
    }

    /// Whether a figure shows the values on a logarithmic axis: evenly in
    /// the logarithm, or a list of positive values over two decades or more.
    pub fn log_axis(&self) -> bool {
        match self.spacing {
            Spacing::Log => true,
            Spacing::Lin => false,
            Spacing::List => {
                let (lo, hi) = self.given.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), &v| (lo.min(v), hi.max(v)));
                lo > 0.0 && hi >= 100.0 * lo
            }
        }
    }
}

/// A deterministic slice of a plan: points K, K + N, K + 2N, … (1-based K).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which slice, 1 ≤ k ≤ n.
    pub k: usize,
    /// How many slices.
    pub n: usize,
}

impl Shard {
    /// The whole plan.
    pub const ALL: Shard = Shard { k: 1, n: 1 };

    /// Reads `K/N`, or `auto`: the Slurm job array's task (from
    /// `SLURM_ARRAY_TASK_ID` and `SLURM_ARRAY_TASK_COUNT`, with
    /// `SLURM_ARRAY_TASK_MIN` as the first task, 0 if unset) given as `env`.
    pub fn parse(text: &str, env: impl Fn(&str) -> Option<String>) -> Result<Shard, SweepError> {
        if text == "auto" {
            let get = |name: &str| -> Result<usize, SweepError> {
                let v = env(name).ok_or_else(|| {
                    SweepError::Shard(format!("--shard auto needs {name}: run it as a task of a Slurm job array"))
                })?;
                v.trim().parse().map_err(|_| SweepError::Shard(format!("{name}={v} is not a whole number")))
            };
            let id = get("SLURM_ARRAY_TASK_ID")?;
            let count = get("SLURM_ARRAY_TASK_COUNT")?;
            let min = env("SLURM_ARRAY_TASK_MIN").and_then(|v| v.trim().parse::<usize>().ok()).unwrap_or(0);
            let k = id.checked_sub(min).map(|k| k + 1);
            return match k {
                Some(k) if k <= count => Ok(Shard { k, n: count }),
                _ => Err(SweepError::Shard(format!(
                    "task {id} is outside the array of {count} tasks from {min} (use --array={min}-{})",
                    min + count.max(1) - 1
                ))),
            };
        }
        let bad = || SweepError::Shard(format!("--shard {text}: expected K/N with 1 ≤ K ≤ N, or auto"));
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (k, n): (usize, usize) = (k.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if k == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { k, n })
    }

    /// Whether point `index` belongs to this shard.
    pub fn owns(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }
}

/// A preset's parameters and the parameters varied over them.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Plan {
    /// The parameters every point starts from.
    pub base: SceneParams,
    /// The varied parameters, the last fastest.
    pub vary: Vec<Vary>,
    /// The SI unit of each varied parameter.
    pub units: Vec<String>,
    values: Vec<Vec<f64>>,
    /// Explicit points (a sample design), SI, one per row in the order of
    /// `vary`; empty for a grid.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    points: Vec<Vec<f64>>,
    /// Parameters that take another's value at every point, (tied, source):
    /// `radius_2 = radius_1` keeps the spheres equal.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ties: Vec<(String, String)>,
}

/// Reads a tie, `TIED=SOURCE` (both parameter keys).
pub fn parse_tie(text: &str) -> Result<(String, String), SweepError> {
    match text.split_once('=') {
        Some((a, b)) if !a.trim().is_empty() && !b.trim().is_empty() => {
            Ok((a.trim().to_string(), b.trim().to_string()))
        }
        _ => Err(SweepError::Syntax(format!("--tie {text}: expected TIED=SOURCE, e.g. radius_2=radius_1"))),
    }
}

impl Plan {
    /// A plan, checked: every varied key is a number of the scene, and every
    /// value lies in its documented range.
    pub fn new(base: SceneParams, vary: Vec<Vary>) -> Result<Plan, SweepError> {
        if vary.is_empty() {
            return Err(SweepError::Parameter("nothing to vary: give --vary NAME=lin|log:FROM:TO:N".into()));
        }
        let mut units = Vec::new();
        for v in &vary {
            let c = base.spec(&v.key).ok_or_else(|| {
                let numbers: Vec<&str> = base.specs().iter().filter(|s| s.is_numeric()).map(|s| s.key).collect();
                SweepError::Parameter(format!(
                    "{} has no parameter '{}' (numbers: {})",
                    base.info().id,
                    v.key,
                    numbers.join(", ")
                ))
            })?;
            if !c.is_numeric() {
                return Err(SweepError::Parameter(format!("'{}' is not a number and cannot be varied", v.key)));
            }
            units.push(c.si_unit.to_string());
        }
        if vary.iter().enumerate().any(|(i, v)| vary[..i].iter().any(|w| w.key == v.key)) {
            return Err(SweepError::Parameter("a parameter is varied twice".into()));
        }
        let total = vary.iter().try_fold(1usize, |acc, v| acc.checked_mul(v.n));
        if total.is_none_or(|t| t > 100_000_000) {
            return Err(SweepError::Parameter("more than 10⁸ points".into()));
        }
        let values: Vec<Vec<f64>> = vary.iter().map(Vary::values).collect();
        // Every value is accepted on its own (a range check, not a computation).
        for (v, vals) in vary.iter().zip(&values) {
            for x in vals {
                let mut trial = base.clone();
                trial.set_number(&v.key, *x).map_err(|e| SweepError::Parameter(format!("--vary {}: {e}", v.text())))?;
            }
        }
        Ok(Plan { base, vary, units, values, points: Vec::new(), ties: Vec::new() })
    }

    /// A plan of explicit points (a sample design): `points` holds one row
    /// of SI values per point, a value for each of `vary` (whose ranges
    /// bound them: each range's ends are checked, and every value must lie
    /// between them).
    pub fn of_points(base: SceneParams, vary: Vec<Vary>, points: Vec<Vec<f64>>) -> Result<Plan, SweepError> {
        for v in &vary {
            for x in [v.from, v.to] {
                let mut trial = base.clone();
                trial.set_number(&v.key, x).map_err(|e| SweepError::Parameter(format!("a point's {e}")))?;
            }
        }
        let mut plan = Plan::new(base, vary.iter().map(|v| Vary { n: 2, ..v.clone() }).collect())?;
        plan.vary = vary;
        plan.values = plan.vary.iter().map(|v| vec![v.from]).collect();
        for (n, row) in points.iter().enumerate() {
            let inside = row.len() == plan.vary.len()
                && row.iter().zip(&plan.vary).all(|(x, v)| {
                    let (lo, hi) = (v.from.min(v.to), v.from.max(v.to));
                    x.is_finite() && *x >= lo - 1e-12 * lo.abs() && *x <= hi + 1e-12 * hi.abs()
                });
            if !inside {
                return Err(SweepError::Parameter(format!("point {n}: {row:?} is outside the ranges")));
            }
        }
        if points.is_empty() {
            return Err(SweepError::Parameter("a design without points".into()));
        }
        plan.points = points;
        Ok(plan)
    }

    /// The plan with `ties`: each tied parameter takes its source's value at
    /// every point. A tied parameter must be a number the plan does not
    /// vary; its source, a number of the scene.
    pub fn with_ties(mut self, ties: Vec<(String, String)>) -> Result<Plan, SweepError> {
        for (tied, source) in &ties {
            for key in [tied, source] {
                if !self.base.spec(key).is_some_and(|s| s.is_numeric()) {
                    return Err(SweepError::Parameter(format!(
                        "--tie {tied}={source}: {} has no number '{key}'",
                        self.base.info().id
                    )));
                }
            }
            if self.vary.iter().any(|v| &v.key == tied) || tied == source {
                return Err(SweepError::Parameter(format!(
                    "--tie {tied}={source}: the tied parameter must be another, not varied"
                )));
            }
        }
        if ties.is_empty() {
            return Ok(self);
        }
        self.ties = ties;
        // Every point stays inside the tied parameters' ranges too.
        for i in 0..self.len() {
            self.params_at(i).map_err(|e| SweepError::Parameter(format!("--tie, at point {i}: {e}")))?;
        }
        Ok(self)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        if !self.points.is_empty() {
            return self.points.len();
        }
        self.values.iter().map(Vec::len).product()
    }

    /// Whether the points are a sample design rather than a grid.
    pub fn is_design(&self) -> bool {
        !self.points.is_empty()
    }

    /// Whether the plan has no points (never, for a checked plan).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The varied values of point `index` (the last parameter fastest).
    pub fn point(&self, index: usize) -> Vec<f64> {
        if let Some(p) = self.points.get(index) {
            return p.clone();
        }
        let mut rest = index;
        let mut out = vec![0.0; self.values.len()];
        for (k, vals) in self.values.iter().enumerate().rev() {
            out[k] = vals[rest % vals.len()];
            rest /= vals.len();
        }
        out
    }

    /// The parameters of point `index`.
    pub fn params_at(&self, index: usize) -> Result<SceneParams, SceneError> {
        let mut p = self.base.clone();
        for (v, x) in self.vary.iter().zip(self.point(index)) {
            p.set_number(&v.key, x)?;
        }
        for (tied, source) in &self.ties {
            if let Some(crate::scene::schema::Value::Number(x)) = p.get(source) {
                p.set_number(tied, x)?;
            } else if let Some(crate::scene::schema::Value::Count(n)) = p.get(source) {
                p.set_number(tied, n as f64)?;
            }
        }
        Ok(p)
    }
}

/// The scalar columns of a table: keys and units.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Columns {
    /// Scalar keys, as in `run --json`.
    pub keys: Vec<String>,
    /// Their units (empty: dimensionless).
    pub units: Vec<String>,
    /// Whether the scalar can be a bound or undefined (the scene declares
    /// it, see [`crate::scene::Scene::CENSORED`]): such a column is followed
    /// by a `KEY status` column.
    pub censored: Vec<bool>,
}

impl Columns {
    /// The columns `keys` with their `units` for a sweep of `base`'s scene.
    pub fn new(keys: Vec<String>, units: Vec<String>, base: &SceneParams) -> Columns {
        let declared = base.censored();
        let censored = keys.iter().map(|k| declared.iter().any(|c| c.key == k)).collect();
        Columns { keys, units, censored }
    }

    /// The columns of the scene's result at the plan's base parameters: all
    /// its scalars, or those named in `only` (in that order).
    pub fn of(plan: &Plan, only: &[String], progress: &Progress) -> Result<Columns, SweepError> {
        let out = scene::compute(&plan.base, progress)
            .map_err(|e| SweepError::Parameter(format!("the preset itself does not compute: {e}")))?;
        let all: Vec<(String, String)> = out.scalars.iter().map(|s| (s.key.to_string(), s.unit.to_string())).collect();
        let chosen: Vec<(String, String)> = if only.is_empty() {
            all
        } else {
            only.iter()
                .map(|k| {
                    all.iter().find(|(key, _)| key == k).cloned().ok_or_else(|| {
                        let keys: Vec<&str> = all.iter().map(|(k, _)| k.as_str()).collect();
                        SweepError::Parameter(format!("no scalar '{k}' (scalars: {})", keys.join(", ")))
                    })
                })
                .collect::<Result<_, _>>()?
        };
        Ok(Columns::new(
            chosen.iter().map(|c| c.0.clone()).collect(),
            chosen.into_iter().map(|c| c.1).collect(),
            &plan.base,
        ))
    }
}

/// One point's row: its number, varied values, scalars (None where the scene
/// reports none: a gap, not a zero; the bound where only a bound is known),
/// their status and its error, if it failed.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The point's number in the plan.
    pub index: usize,
    /// The varied values.
    pub values: Vec<f64>,
    /// The scalars, in column order.
    pub scalars: Vec<Option<f64>>,
    /// For each scalar, "" for a value, else "above: WHY" (the scalar is the
    /// bound) or "undefined: WHY".
    pub status: Vec<String>,
    /// Why the point has no result.
    pub error: Option<String>,
}

/// Computes the scene at the points `indices` of `plan` in parallel (rayon)
/// and hands each result to `each` (from any thread, as it finishes); returns
/// what `each` made, in the order of `indices`. Cancelling `progress` stops
/// starting new points and gives [`SceneError::Cancelled`]. The engine of the
/// command line's sweeps and the window's families alike.
pub fn for_points<T: Send>(
    plan: &Plan,
    indices: &[usize],
    progress: &Progress,
    each: &(dyn Fn(usize, Result<SceneOutput, SceneError>) -> T + Sync),
) -> Result<Vec<T>, SceneError> {
    for_each_point(plan, indices, progress, &scene::compute, each)
}

/// [`for_points`] with the computation `compute` of each point's parameters.
fn for_each_point<R, T: Send>(
    plan: &Plan,
    indices: &[usize],
    progress: &Progress,
    compute: &(dyn Fn(&SceneParams, &Progress) -> Result<R, SceneError> + Sync),
    each: &(dyn Fn(usize, Result<R, SceneError>) -> T + Sync),
) -> Result<Vec<T>, SceneError> {
    let finished = AtomicUsize::new(0);
    let made: Vec<Option<T>> = indices
        .par_iter()
        .map(|&i| {
            if progress.cancelled() {
                return None;
            }
            let result = plan.params_at(i).and_then(|p| compute(&p, &progress.quiet_child()));
            if matches!(result, Err(SceneError::Cancelled)) {
                return None;
            }
            let t = each(i, result);
            let n = finished.fetch_add(1, Ordering::Relaxed) + 1;
            progress.set(n as f64 / indices.len().max(1) as f64);
            Some(t)
        })
        .collect();
    progress.check()?;
    made.into_iter().map(|t| t.ok_or(SceneError::Cancelled)).collect()
}

/// The row of point `index` from its result.
fn row_of(plan: &Plan, columns: &Columns, index: usize, result: Result<SceneOutput, SceneError>) -> Row {
    row_from(plan, columns, index, result.map(|out| columns.keys.iter().map(|k| out.scalar(k)).collect()))
}

/// The row of point `index` from its scalars in column order.
fn row_from(plan: &Plan, columns: &Columns, index: usize, result: Result<Vec<Option<f64>>, SceneError>) -> Row {
    let values = plan.point(index);
    let n = columns.keys.len();
    match result {
        Ok(found) => {
            let declared = plan.base.censored();
            let (scalars, status) = columns
                .keys
                .iter()
                .zip(found)
                .map(|(k, found)| match found {
                    Some(v) => match scene::status(declared, k, v) {
                        Status::Value => (Some(v), String::new()),
                        Status::Above { bound, why } => (Some(bound), format!("above: {why}")),
                        Status::Undefined { why } => (None, format!("undefined: {why}")),
                    },
                    None => (None, String::new()),
                })
                .unzip();
            Row { index, values, scalars, status, error: None }
        }
        Err(e) => {
            Row { index, values, scalars: vec![None; n], status: vec![String::new(); n], error: Some(e.to_string()) }
        }
    }
}

/// Computes the rows of the points `indices`, calling `done` with each row
/// as it finishes (from any thread); returns them in point order.
pub fn run(
    plan: &Plan,
    columns: &Columns,
    indices: &[usize],
    progress: &Progress,
    done: &(dyn Fn(&Row) + Sync),
) -> Result<Vec<Row>, SceneError> {
    let mut rows = match &columns.keys[..] {
        // One scalar: through the scene's quick path where it has one (the
        // same value as the whole computation, without the figures).
        [key] => for_each_point(
            plan,
            indices,
            progress,
            &|p, progress| scene::scalar(p, key, progress).map(|v| vec![v]),
            &|i, result| {
                let row = row_from(plan, columns, i, result);
                done(&row);
                row
            },
        )?,
        _ => for_points(plan, indices, progress, &|i, result| {
            let row = row_of(plan, columns, i, result);
            done(&row);
            row
        })?,
    };
    rows.sort_by_key(|r| r.index);
    Ok(rows)
}

/// A number as the table writes it: the shortest text that reads back to
/// the same value.
fn number(v: f64) -> String {
    format!("{v}")
}

/// A column's name with its unit, as in the header: `key [unit]`.
fn titled(key: &str, unit: &str) -> String {
    if unit.is_empty() { key.to_string() } else { format!("{key} [{unit}]") }
}

/// Quotes a CSV field where needed.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) { format!("\"{}\"", s.replace('"', "\"\"")) } else { s.to_string() }
}

/// The table's header line (without line end).
pub fn header(plan: &Plan, columns: &Columns) -> String {
    let mut h = vec!["point".to_string()];
    h.extend(plan.vary.iter().zip(&plan.units).map(|(v, u)| titled(&v.key, u)));
    for ((k, u), censored) in columns.keys.iter().zip(&columns.units).zip(&columns.censored) {
        h.push(titled(k, u));
        if *censored {
            h.push(format!("{k} status"));
        }
    }
    h.push("error".into());
    h.iter().map(|s| field(s)).collect::<Vec<_>>().join(",")
}

/// One row as a line of the table (without line end).
pub fn line(row: &Row, columns: &Columns) -> String {
    let mut s = row.index.to_string();
    for v in &row.values {
        let _ = write!(s, ",{}", number(*v));
    }
    for (k, v) in row.scalars.iter().enumerate() {
        s.push(',');
        if let Some(v) = v {
            s.push_str(&number(*v));
        }
        if columns.censored.get(k).copied().unwrap_or(false) {
            s.push(',');
            s.push_str(&field(row.status.get(k).map_or("", String::as_str)));
        }
    }
    s.push(',');
    if let Some(e) = &row.error {
        s.push_str(&field(e));
    }
    s
}

/// The whole table: header and rows in point order, each line ending in `\n`.
pub fn table(plan: &Plan, columns: &Columns, rows: &[Row]) -> String {
    let mut s = header(plan, columns);
    s.push('\n');
    for r in rows {
        s.push_str(&line(r, columns));
        s.push('\n');
    }
    s
}

/// Reads the rows of a table written by [`table`] (or appended line by line)
/// for this plan and these columns; a header of another plan is refused, and
/// an incomplete last line (a write cut short) is skipped.
pub fn read_rows(text: &str, plan: &Plan, columns: &Columns) -> Result<Vec<Row>, SweepError> {
    let mut lines = text.split_inclusive('\n');
    let expected = header(plan, columns);
    match lines.next() {
        Some(h) if h.trim_end_matches(['\n', '\r']) == expected => {}
        Some(h) => {
            return Err(SweepError::Table(format!(
                "its header is for another sweep: '{}' (this sweep: '{expected}')",
                h.trim_end()
            )));
        }
        None => return Ok(Vec::new()),
    }
    let body: String = lines.filter(|l| l.ends_with('\n')).collect();
    let mut reader = csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(body.as_bytes());
    let statuses = columns.censored.iter().filter(|c| **c).count();
    let width = 2 + plan.vary.len() + columns.keys.len() + statuses;
    let mut rows = Vec::new();
    for (n, record) in reader.records().enumerate() {
        let bad = |why: &str| SweepError::Table(format!("row {}: {why}", n + 1));
        let record = record.map_err(|e| bad(&e.to_string()))?;
        if record.len() != width {
            return Err(bad(&format!("{} fields, expected {width}", record.len())));
        }
        let index: usize = record[0].parse().map_err(|_| bad("no point number"))?;
        if index >= plan.len() {
            return Err(bad(&format!("point {index} is outside the plan's {} points", plan.len())));
        }
        let num = |s: &str| s.parse::<f64>().map_err(|_| bad(&format!("'{s}' is not a number")));
        let values = (1..=plan.vary.len()).map(|k| num(&record[k])).collect::<Result<Vec<_>, _>>()?;
        // Equal to the last digits: a row written by a build that did not
        // round its grid's interior values still belongs to the point.
        let same = |a: f64, b: f64| a == b || (a - b).abs() <= 1e-14 * a.abs().max(b.abs());
        if values.len() != plan.vary.len() || !values.iter().zip(plan.point(index)).all(|(&a, b)| same(a, b)) {
            return Err(bad(&format!("point {index} has other values than this sweep gives it")));
        }
        let mut at = 1 + plan.vary.len();
        let mut scalars = Vec::with_capacity(columns.keys.len());
        let mut status = Vec::with_capacity(columns.keys.len());
        for censored in &columns.censored {
            let s = &record[at];
            scalars.push(if s.is_empty() { None } else { Some(num(s)?) });
            at += 1;
            if *censored {
                status.push(record[at].to_string());
                at += 1;
            } else {
                status.push(String::new());
            }
        }
        let error = Some(record[width - 1].to_string()).filter(|e| !e.is_empty());
        rows.push(Row { index, values, scalars, status, error });
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan() -> Plan {
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let vary = vec![
            Vary::parse("velocity=log:1:100:3").expect("vary"),
            Vary::parse("surface_energy=lin:0.2:1:5").expect("vary"),
        ];
        Plan::new(base, vary).expect("plan")
    }

    #[test]
    fn values_hit_both_ends_and_space_as_asked() {
        let v = Vary::parse("velocity=log:1:100:3").expect("vary");
        assert_eq!(v.values(), vec![1.0, 10.0, 100.0]);
        let l = Vary::parse("alpha=lin:3.2:3.8:4").expect("vary");
        let x = l.values();
        assert_eq!((x[0], x[3]), (3.2, 3.8));
        assert!((x[1] - 3.4).abs() < 1e-12 && (x[2] - 3.6).abs() < 1e-12);
        for bad in ["velocity", "velocity=log:0:1:3", "v=cubic:1:2:3", "v=lin:1:2:0", "v=lin:1:nan:3", "=lin:1:2:3"] {
            assert!(Vary::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_list_gives_its_values_in_order_and_reads_back_from_its_text() {
        let v = Vary::parse("velocity=list:3:0.5:12.25").expect("vary");
        assert_eq!(v.values(), vec![3.0, 0.5, 12.25]);
        assert_eq!((v.from, v.to, v.n), (3.0, 12.25, 3));
        assert_eq!(Vary::parse(&v.text()).expect("its text"), v);
        assert!(!v.log_axis(), "less than two decades");
        assert!(Vary::parse("velocity=list:0.1:10").expect("vary").log_axis());
        let one_third = Vary::parse(&format!("velocity=list:{}", 1.0 / 3.0)).expect("vary");
        assert_eq!(Vary::parse(&one_third.text()).expect("its text").values(), vec![1.0 / 3.0]);
        for bad in ["velocity=list:", "velocity=list:1:x", "velocity=list:1:inf", "=list:1"] {
            assert!(Vary::parse(bad).is_err(), "{bad}");
        }
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let plan = Plan::new(base.clone(), vec![v]).expect("plan");
        assert_eq!((plan.len(), plan.point(1)), (3, vec![0.5]));
        assert!(Plan::new(base, vec![Vary::parse("velocity=list:1:-2").expect("vary")]).is_err(), "out of range");
    }

    #[test]
    fn points_run_the_last_parameter_fastest_and_shards_partition_them() {
        let p = plan();
        assert_eq!(p.len(), 15);
        assert_eq!(p.point(0), vec![1.0, 0.2]);
        assert_eq!(p.point(1)[0], 1.0);
        assert_eq!(p.point(5)[1], 0.2);
        assert_eq!(p.point(14), vec![100.0, 1.0]);
        for n in 1..6 {
            let shards: Vec<Shard> = (1..=n).map(|k| Shard { k, n }).collect();
            for i in 0..p.len() {
                assert_eq!(shards.iter().filter(|s| s.owns(i)).count(), 1);
            }
        }
    }

    #[test]
    fn shards_read_from_text_and_from_a_slurm_array() {
        let none = |_: &str| None;
        assert_eq!(Shard::parse("2/5", none), Ok(Shard { k: 2, n: 5 }));
        for bad in ["0/5", "6/5", "x", "1/0", "auto"] {
            assert!(Shard::parse(bad, none).is_err(), "{bad}");
        }
        let env = |id: &'static str, min: &'static str| {
            move |k: &str| match k {
                "SLURM_ARRAY_TASK_ID" => Some(id.to_string()),
                "SLURM_ARRAY_TASK_COUNT" => Some("4".to_string()),
                "SLURM_ARRAY_TASK_MIN" => Some(min.to_string()),
                _ => None,
            }
        };
        assert_eq!(Shard::parse("auto", env("0", "0")), Ok(Shard { k: 1, n: 4 }));
        assert_eq!(Shard::parse("auto", env("4", "1")), Ok(Shard { k: 4, n: 4 }));
        assert!(Shard::parse("auto", env("5", "1")).is_err());
    }

    #[test]
    fn a_failed_point_and_a_gap_survive_the_table() {
        let p = plan();
        let columns = Columns {
            keys: vec!["e".into(), "v_s".into()],
            units: vec![String::new(), "m s^-1".into()],
            censored: vec![false, true],
        };
        let none = || vec![String::new(), String::new()];
        let rows = vec![
            Row { index: 0, values: p.point(0), scalars: vec![Some(0.5), None], status: none(), error: None },
            Row {
                index: 1,
                values: p.point(1),
                scalars: vec![Some(0.1), Some(1e4)],
                status: vec![String::new(), "above: no bounce, up to 10⁴ m/s".into()],
                error: None,
            },
            Row {
                index: 3,
                values: p.point(3),
                scalars: vec![None, None],
                status: none(),
                error: Some("no \"bounce\", at all".into()),
            },
        ];
        let text = table(&p, &columns, &rows);
        assert!(
            text.starts_with("point,velocity [m s^-1],surface_energy [J m^-2],e,v_s [m s^-1],v_s status,error\n"),
            "{text}"
        );
        assert_eq!(read_rows(&text, &p, &columns).expect("reads"), rows);
        // A line cut short by a crash is skipped, not misread.
        let cut = &text[..text.len() - 5];
        assert_eq!(read_rows(cut, &p, &columns).expect("reads"), rows[..2]);
    }

    #[test]
    fn a_bad_plan_is_refused_with_the_reason() {
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let e = Plan::new(base.clone(), vec![Vary::parse("speed=lin:1:2:2").expect("vary")]).unwrap_err();
        assert!(e.to_string().contains("no parameter 'speed'") && e.to_string().contains("velocity"), "{e}");
        let e = Plan::new(base.clone(), vec![Vary::parse("velocity=lin:-1:2:2").expect("vary")]).unwrap_err();
        assert!(e.to_string().contains("velocity"), "{e}");
        assert!(Plan::new(base, Vec::new()).is_err());
    }

    #[test]
    fn rows_round_trip_through_the_table_and_shards_merge_into_the_whole() {
        let p = plan();
        let progress = Progress::default();
        let columns = Columns::of(&p, &["e".to_string(), "e_D".to_string()], &progress).expect("columns");
        let all: Vec<usize> = (0..p.len()).collect();
        let rows = run(&p, &columns, &all, &progress, &|_| {}).expect("runs");
        let whole = table(&p, &columns, &rows);
        // Sticking points have e = 0, bouncing ones not; e_D does not depend on γ.
        assert!(rows.iter().all(|r| r.error.is_none() && r.scalars.iter().all(Option::is_some)));
        let mut merged: Vec<Row> = Vec::new();
        for k in 1..=4 {
            let shard = Shard { k, n: 4 };
            let mine: Vec<usize> = all.iter().copied().filter(|&i| shard.owns(i)).collect();
            let part = run(&p, &columns, &mine, &progress, &|_| {}).expect("runs");
            merged.extend(read_rows(&table(&p, &columns, &part), &p, &columns).expect("reads"));
        }
        merged.sort_by_key(|r| r.index);
        assert_eq!(table(&p, &columns, &merged), whole);
        // Another plan's table is refused.
        let other = Plan::new(p.base.clone(), vec![Vary::parse("velocity=log:1:100:4").expect("vary")]).expect("plan");
        assert!(read_rows(&whole, &other, &columns).is_err());
    }
}
