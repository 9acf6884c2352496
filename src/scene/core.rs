//! What every scene shares: the [`Scene`] trait, its output, errors, progress
//! and caches. This module imports no scene, so each scene file can import it
//! without a cycle; the registry in [`crate::scene`] sits on top of both.

pub use super::grid::logspace;
pub use super::timeline::Cursor;
use crate::figure::Figure;
use crate::physics::fit::Measurement;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::any::{Any, TypeId};
use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};

/// Static description of a scene.
#[derive(Debug, Clone, Copy)]
pub struct SceneInfo {
    /// Identifier used on the command line and in presets.
    pub id: &'static str,
    /// Title shown in the scene list.
    pub title: &'static str,
    /// Thesis sections and figures it covers.
    pub source: &'static str,
    /// Explanation with the key equations, for teaching.
    pub explanation: &'static str,
    /// Whether a recompute is slow enough to need the worker thread.
    pub heavy: bool,
}

/// One scene of the explorer, implemented by the scene's parameter type:
/// its description, its controls and its pure computation. Each scene
/// implements it in its own file; the window, the command line and the tests
/// reach scenes only through it (by way of [`crate::scene::SceneParams`]).
/// The parameters are stored in presets (every field defaults, so old presets
/// keep loading).
pub trait Scene:
    Clone
    + Default
    + PartialEq
    + std::fmt::Debug
    + Serialize
    + DeserializeOwned
    + Send
    + Sync
    + 'static
    + super::schema::ParamSet
{
    /// Identifier, title, thesis reference and explanation.
    const INFO: SceneInfo;

    /// Whether the computation honours [`Progress::set_paused`].
    const PAUSABLE: bool = false;

    /// What the scene's non-finite scalars mean: a bound (the value lies
    /// beyond what was searched) or an undefined result, with the reason.
    /// Every output (JSON, CSV, Python, the window, the sensitivity tools)
    /// reads a non-finite scalar through [`status`]. Empty by default.
    const CENSORED: &'static [Censored] = &[];

    /// What the continuity audit ([`crate::audit`]) finds in this scene that
    /// is the model's physics, not a defect (a threshold such as sticking, a
    /// regime boundary, a parameter that only shapes a figure), with the
    /// reason. Empty by default: every finding is a defect.
    const DECLARED: &'static [Declared] = &[];

    /// Computes the scene. Pure: the same parameters give the same output;
    /// the caches only save work.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError>;

    /// After a material was picked: re-derives what depends on it (e.g. the
    /// combined surface energy). Does nothing by default.
    fn material_changed(&mut self) {}

    /// A time cursor over the computed history: where it stands and the
    /// points it marks on the figures. None by default.
    fn cursor(&self, _out: &SceneOutput) -> Option<Cursor> {
        None
    }

    /// The time cursor over the computed history (a fraction of the run,
    /// 0–1), which the window plays and movies step; None (the default) for
    /// a scene whose result is no history.
    fn time_cursor(&mut self) -> Option<&mut f64> {
        None
    }

    /// The first seed and the number of runs of a scene that averages
    /// independent random runs; None (the default) for a deterministic one.
    fn seeds(&mut self) -> Option<Seeds<'_>> {
        None
    }

    /// What a click at `at` (axis units) on figure `figure` of `out` shows:
    /// the model's numbers at that point and where to go from there. None
    /// by default (the point is not inspectable).
    fn inspect(&self, _out: &SceneOutput, _figure: &str, _at: [f64; 2]) -> Option<super::inspect::Inspection> {
        None
    }

    /// Imported measurements the scene works on, if it takes any.
    fn measurements(&mut self) -> Option<&mut Vec<Measurement>> {
        None
    }

    /// A cheaper version of the parameters (fewer batches, fewer Monte Carlo
    /// groups, coarser grids) whose result a heavy scene shows first, within
    /// about 0.1 s, while the full one computes. None (the default): no preview.
    fn coarse(&self) -> Option<Self> {
        None
    }

    /// The parameters whose result the window shows first while the full
    /// result computes: by default [`Scene::coarse`]. None: no separate
    /// preview (a scene whose computation offers its own first picture with
    /// [`Progress::publish`], from runs the full result uses, returns None
    /// so that no run is made twice).
    fn preview(&self) -> Option<Self> {
        self.coarse()
    }

    /// Scalar `key` alone, where the scene can compute it without its
    /// figures (for sweeps, which need one number per point). The value must
    /// equal that of `compute(..).scalar(key)` exactly. None (the default):
    /// the sweep computes the whole scene.
    fn scalar(&self, _key: &str, _progress: &Progress) -> Option<Result<f64, SceneError>> {
        None
    }
}

/// The seeds of a scene's random runs: runs `first`, `first + 1`, … up to
/// `runs` of them.
#[derive(Debug)]
pub struct Seeds<'a> {
    /// The first seed.
    pub first: &'a mut usize,
    /// The number of runs.
    pub runs: &'a mut usize,
}

/// What a computation may use besides its parameters.
pub struct Context<'a> {
    /// Progress, cancellation and intermediate results.
    pub progress: &'a Progress,
    /// Partial results kept between computations.
    pub caches: &'a mut Caches,
}

/// A scalar result, e.g. the coefficient of restitution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scalar {
    /// Key in JSON output, e.g. "e".
    pub key: &'static str,
    /// Label as shown, e.g. "restitution e".
    pub label: &'static str,
    /// Value in SI units (or dimensionless).
    pub value: f64,
    /// Unit of `value`, empty for dimensionless quantities.
    pub unit: &'static str,
}

/// What a non-finite value of one scalar means.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Censored {
    /// The scalar's key.
    pub key: &'static str,
    /// What +∞ means: the value lies above this bound (in the scalar's
    /// unit), for this reason; None when +∞ does not occur.
    pub above: Option<(f64, &'static str)>,
    /// What any other non-finite value (NaN, or +∞ without `above`)
    /// means: no value exists, for this reason.
    pub undefined: Option<&'static str>,
}

/// What the continuity audit can find along one parameter's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Irregularity {
    /// The computation fails at a value inside the documented range.
    Error,
    /// The scalar is non-finite where the scene declares no meaning for it.
    Undefined,
    /// The scalar is reported at some values and absent at others.
    Missing,
    /// The scalar jumps: the change between two neighbouring values stays
    /// as the interval between them shrinks.
    Step,
    /// The parameter changes the figures but no scalar.
    Ignored,
    /// A parameter declared to set only what a figure shows changes a scalar.
    Moves,
}

impl Irregularity {
    /// The irregularity as one word, as the audit prints it.
    pub fn word(&self) -> &'static str {
        match self {
            Irregularity::Error => "error",
            Irregularity::Undefined => "undefined",
            Irregularity::Missing => "missing",
            Irregularity::Step => "step",
            Irregularity::Ignored => "ignored",
            Irregularity::Moves => "moves",
        }
    }
}

/// An audit finding declared as the model's physics: scalar `scalar`
/// (\"*\" any) shows `kind` along parameter `parameter` (\"*\" any), for
/// the reason `why`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Declared {
    /// The scalar's key, or \"*\" for every scalar (and for
    /// [`Irregularity::Ignored`], which concerns no one scalar).
    pub scalar: &'static str,
    /// The parameter's key, or \"*\" for every parameter.
    pub parameter: &'static str,
    /// What is found.
    pub kind: Irregularity,
    /// Why it is physics.
    pub why: &'static str,
    /// For a step of the model's resolution rather than of its physics: the
    /// count parameter that sets it (e.g. the number of batches). The audit
    /// then checks the declaration: at four times that count (at most its
    /// largest value) the step's bracket must change by less than half as
    /// much, or the step is reported as open. None: a step of the physics.
    pub resolution: Option<&'static str>,
}

impl Declared {
    /// The declaration in `declared` that covers `kind` of `scalar` along
    /// `parameter`, if any.
    pub fn find<'a>(
        declared: &'a [Declared],
        kind: Irregularity,
        scalar: &str,
        parameter: &str,
    ) -> Option<&'a Declared> {
        declared.iter().find(|d| d.covers(kind, scalar, parameter))
    }

    /// The first declaration in `declared` that covers `kind` of `scalar`
    /// along `parameter` as physics (no resolution to check): what a step
    /// falls back to when the resolution it was first declared to be does
    /// not explain it.
    pub fn find_physics<'a>(
        declared: &'a [Declared],
        kind: Irregularity,
        scalar: &str,
        parameter: &str,
    ) -> Option<&'a Declared> {
        declared.iter().find(|d| d.resolution.is_none() && d.covers(kind, scalar, parameter))
    }

    /// Whether this declaration covers `kind` of `scalar` along `parameter`.
    fn covers(&self, kind: Irregularity, scalar: &str, parameter: &str) -> bool {
        self.kind == kind
            && (self.scalar == "*" || self.scalar == scalar)
            && (self.parameter == "*" || self.parameter == parameter)
    }
}

/// How a scalar's value reads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Status {
    /// A value.
    Value,
    /// Only a bound is known: the value lies above `bound` (the scalar's unit).
    Above {
        /// The bound.
        bound: f64,
        /// Why there is no value.
        why: &'static str,
    },
    /// No value exists.
    Undefined {
        /// Why.
        why: &'static str,
    },
}

impl Status {
    /// The status as one word: "value", "above" or "undefined".
    pub fn word(&self) -> &'static str {
        match self {
            Status::Value => "value",
            Status::Above { .. } => "above",
            Status::Undefined { .. } => "undefined",
        }
    }

    /// Why there is no value ("" for a value).
    pub fn why(&self) -> &'static str {
        match self {
            Status::Value => "",
            Status::Above { why, .. } | Status::Undefined { why } => why,
        }
    }

    /// The number to show for the scalar: the value, the bound, or NaN.
    pub fn number(&self, value: f64) -> f64 {
        match self {
            Status::Value => value,
            Status::Above { bound, .. } => *bound,
            Status::Undefined { .. } => f64::NAN,
        }
    }

    /// The scalar as JSON: a number for a value, else an object with the
    /// status, the bound where there is one, and the reason.
    pub fn json(&self, value: f64) -> serde_json::Value {
        match self {
            Status::Value => serde_json::json!(value),
            Status::Above { bound, why } => serde_json::json!({"status": "above", "bound": bound, "why": why}),
            Status::Undefined { why } => serde_json::json!({"status": "undefined", "why": why}),
        }
    }
}

/// Why a non-finite scalar has no value where its scene declares nothing.
pub const NOT_FINITE: &str = "not a finite number";

/// How scalar `key` with value `value` reads, by the scene's declarations
/// `censored` (see [`Scene::CENSORED`]). A finite value is a value; a
/// non-finite one is what the scene declares, or undefined ("not a finite
/// number") where it declares nothing.
pub fn status(censored: &[Censored], key: &str, value: f64) -> Status {
    if value.is_finite() {
        return Status::Value;
    }
    let declared = censored.iter().find(|c| c.key == key);
    if value == f64::INFINITY
        && let Some((bound, why)) = declared.and_then(|c| c.above)
    {
        return Status::Above { bound, why };
    }
    Status::Undefined { why: declared.and_then(|c| c.undefined).unwrap_or(NOT_FINITE) }
}

/// A [`Scalar`] as read back from bytes; its texts are interned.
#[derive(serde::Deserialize)]
struct ScalarText {
    key: String,
    label: String,
    value: f64,
    unit: String,
}

impl<'de> serde::Deserialize<'de> for Scalar {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Scalar, D::Error> {
        let t = ScalarText::deserialize(deserializer)?;
        let intern = crate::statics::intern;
        Ok(Scalar { key: intern(&t.key), label: intern(&t.label), value: t.value, unit: intern(&t.unit) })
    }
}

/// A recorded collision for the contact sketch: time, approach and contact radius.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Trajectory {
    /// Radius of sphere 1, m.
    pub radius_1: f64,
    /// Radius of sphere 2, m (infinite for a wall).
    pub radius_2: f64,
    /// Samples (t [s], δ [m], a [m], F_E [N]).
    pub samples: Vec<[f64; 4]>,
}

impl Trajectory {
    /// The sample nearest after `fraction` (0–1) of the run's duration.
    pub fn sample_at(&self, fraction: f64) -> Option<[f64; 4]> {
        let last = self.samples.last()?;
        let target = fraction.clamp(0.0, 1.0) * last[0];
        let i = self.samples.partition_point(|s| s[0] < target).min(self.samples.len() - 1);
        Some(self.samples[i])
    }
}

/// Extra, scene-specific data the window needs beyond figures.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub enum Extra {
    /// Nothing beyond figures.
    #[default]
    None,
    /// A recorded collision, for the sketch of the two spheres.
    Collision(Arc<Trajectory>),
    /// Histories drawn on figures whose axes are not time (growth tracks):
    /// the time of every point, so that a time cursor can follow them.
    Paths(Arc<Vec<TimedPath>>),
    /// Linked numbers from the smallest scale to the largest, shown as a
    /// ladder beside the figures.
    Ladder(Arc<Vec<Rung>>),
    /// The model's own result (a batch run, Monte Carlo runs), kept so that
    /// a clicked point of a figure can be inspected without recomputing.
    /// The kinds the scenes inspect (batch runs, Monte Carlo runs) are
    /// written to bytes, so that a browser's page inspects what its worker
    /// computed; any other kind is left out.
    Model(ModelData),
}

/// One scale of a ladder: its name and its numbers.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Rung {
    /// The scale, e.g. "Contact of two monomers (ch. 2–3)".
    pub scale: String,
    /// (quantity, value with unit, equation or section).
    pub items: Vec<(String, String, String)>,
    /// The id of the figure beside the ladder that shows this scale, if any.
    #[serde(default)]
    pub figure: Option<String>,
}

/// A model result shared with the window for inspection. It follows from the
/// same parameters as the figures beside it, so two outputs compare by what
/// they show: any two are equal.
#[derive(Clone)]
pub struct ModelData(pub Arc<dyn Any + Send + Sync>);

impl PartialEq for ModelData {
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for ModelData {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ModelData")
    }
}

/// The model results a [`ModelData`] is written to bytes as.
#[derive(serde::Serialize, serde::Deserialize)]
enum ModelBytes<B, R> {
    /// A batch run (disk map, lifelines, formation zone).
    Batches(B),
    /// Monte Carlo runs (families).
    Runs(R),
    /// A kind that no scene inspects: not kept.
    Other,
}

impl serde::Serialize for ModelData {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use crate::physics::{batches::BatchRun, coagulation::Run};
        let data = &self.0;
        let bytes: ModelBytes<&BatchRun, &Vec<Run>> = if let Some(run) = data.downcast_ref::<BatchRun>() {
            ModelBytes::Batches(run)
        } else if let Some(runs) = data.downcast_ref::<Vec<Run>>() {
            ModelBytes::Runs(runs)
        } else {
            ModelBytes::Other
        };
        bytes.serialize(serializer)
    }
}

impl<'de> serde::Deserialize<'de> for ModelData {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<ModelData, D::Error> {
        use crate::physics::{batches::BatchRun, coagulation::Run};
        let data: Arc<dyn Any + Send + Sync> =
            match <ModelBytes<BatchRun, Vec<Run>> as serde::Deserialize>::deserialize(deserializer)? {
                ModelBytes::Batches(run) => Arc::new(run),
                ModelBytes::Runs(runs) => Arc::new(runs),
                ModelBytes::Other => Arc::new(()),
            };
        Ok(ModelData(data))
    }
}

impl Extra {
    /// The model result of type `T`, if the output keeps one.
    pub fn model<T: Any + Send + Sync>(&self) -> Option<&T> {
        match self {
            Extra::Model(ModelData(data)) => data.downcast_ref::<T>(),
            _ => None,
        }
    }
}

/// A curve of a figure with the time of each of its points.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct TimedPath {
    /// Figure id.
    pub figure: String,
    /// Palette colour of the curve, for its cursor mark.
    pub color: Option<usize>,
    /// Time of each point (ascending), in the unit the scene's cursor shows.
    pub times: Vec<f64>,
    /// The points, in the figure's axis units.
    pub points: Vec<[f64; 2]>,
}

/// What a scene computes.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct SceneOutput {
    /// Scalar results.
    pub scalars: Vec<Scalar>,
    /// Figures, in display order.
    pub figures: Vec<Figure>,
    /// Remarks for the user (regime, discrepancies with the printed thesis).
    pub notes: Vec<String>,
    /// What makes the result untrustworthy (e.g. an under-determined fit):
    /// shown above the figures in the window and on standard error by the
    /// command line.
    pub warnings: Vec<String>,
    /// Scene-specific data for the window.
    pub extra: Extra,
}

impl SceneOutput {
    /// Scalars as one JSON object `{key: value}`, where a scalar that is a
    /// bound or undefined by the scene's declarations `censored` (see
    /// [`Scene::CENSORED`]) is an object `{"status": "above", "bound": …,
    /// "why": …}` or `{"status": "undefined", "why": …}`.
    pub fn scalars_json(&self, censored: &[Censored]) -> serde_json::Value {
        let map: serde_json::Map<String, serde_json::Value> =
            self.scalars.iter().map(|s| (s.key.to_string(), status(censored, s.key, s.value).json(s.value))).collect();
        serde_json::Value::Object(map)
    }

    /// Looks a scalar up by key.
    pub fn scalar(&self, key: &str) -> Option<f64> {
        self.scalars.iter().find(|s| s.key == key).map(|s| s.value)
    }
}

/// Why a scene could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// A parameter is out of range.
    #[error(transparent)]
    Param(#[from] super::controls::ParamError),
    /// The model rejected its input or failed.
    #[error(transparent)]
    Physics(#[from] crate::physics::PhysicsError),
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

/// Progress reporting and cancellation shared between a worker and the UI.
#[derive(Debug, Clone, Default)]
pub struct Progress {
    cancel: Arc<AtomicBool>,
    pause: Arc<AtomicBool>,
    permille: Arc<AtomicU32>,
    partial: Arc<std::sync::Mutex<Option<Arc<SceneOutput>>>>,
    watcher: Option<Watcher>,
    /// The share of the units this computation takes (see [`super::parts`]).
    pub(super) parts: Option<Arc<super::parts::Ledger>>,
}

/// What a computation reports as it goes, to a [`Watcher`].
#[derive(Debug)]
pub enum Report<'a> {
    /// The fraction done changed (0–1).
    Fraction(f64),
    /// An intermediate result was offered.
    Partial(&'a SceneOutput),
    /// The computation (given [`super::Parts`]) shares the units of a map
    /// among this many processes, and computes its own share now.
    Sharing(usize),
}

/// Told of every report of a computation as it is made: where no other
/// thread can look at a [`Progress`] (a browser's Web Worker computes alone
/// and posts its progress to the page), the computation tells it itself.
#[derive(Clone)]
pub struct Watcher(pub Arc<dyn Fn(Report<'_>) + Send + Sync>);

impl std::fmt::Debug for Watcher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Watcher")
    }
}

impl Progress {
    /// Requests cancellation.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
    /// Whether cancellation was requested.
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }
    /// Pauses (true) or resumes (false) a computation that honours it.
    pub fn set_paused(&self, paused: bool) {
        self.pause.store(paused, Ordering::Relaxed);
    }
    /// Whether a pause was requested.
    pub fn paused(&self) -> bool {
        self.pause.load(Ordering::Relaxed)
    }
    /// Blocks while paused (and not cancelled), looking again every 50 ms.
    /// Only another thread can lift a pause; WebAssembly in a browser has no
    /// threads to sleep (nor to lift it), so there this returns at once and
    /// the computation runs on.
    pub fn wait_while_paused(&self) {
        #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
        while self.paused() && !self.cancelled() {
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
    }
    /// Errors out if cancellation was requested.
    pub fn check(&self) -> Result<(), SceneError> {
        if self.cancelled() { Err(SceneError::Cancelled) } else { Ok(()) }
    }
    /// A progress whose reports also go to `watcher`.
    pub fn watched(watcher: Watcher) -> Progress {
        Progress { watcher: Some(watcher), ..Progress::default() }
    }
    /// Sets the fraction done (0–1).
    pub fn set(&self, fraction: f64) {
        let permille = (fraction.clamp(0.0, 1.0) * 1000.0) as u32;
        let before = self.permille.swap(permille, Ordering::Relaxed);
        if let Some(w) = &self.watcher
            && before != permille
        {
            (w.0)(Report::Fraction(f64::from(permille) / 1000.0));
        }
    }
    /// The fraction done (0–1).
    pub fn fraction(&self) -> f64 {
        self.permille.load(Ordering::Relaxed) as f64 / 1000.0
    }
    /// A progress that shares this one's cancellation and pause but reports
    /// its fraction and results nowhere (for a preview computed beside).
    pub fn quiet_child(&self) -> Progress {
        Progress { cancel: Arc::clone(&self.cancel), pause: Arc::clone(&self.pause), ..Progress::default() }
    }

    /// Tells the watcher, if any, of `report`.
    pub(super) fn tell(&self, report: Report<'_>) {
        if let Some(w) = &self.watcher {
            (w.0)(report);
        }
    }

    /// Offers an intermediate result of a long computation for display.
    pub fn publish(&self, output: SceneOutput) {
        if let Some(w) = &self.watcher {
            (w.0)(Report::Partial(&output));
        }
        if let Ok(mut slot) = self.partial.lock() {
            *slot = Some(Arc::new(output));
        }
    }
    /// The newest intermediate result, if any.
    pub fn partial(&self) -> Option<Arc<SceneOutput>> {
        self.partial.lock().ok().and_then(|slot| slot.clone())
    }
}

/// Partial results kept between computations, one slot per cache type, so
/// that a changed parameter recomputes only what it touches and scenes that
/// share a model share its runs. Results never depend on the cache.
#[derive(Debug, Default)]
pub struct Caches {
    slots: HashMap<TypeId, Box<dyn Any + Send>>,
}

impl Caches {
    /// The cache of type `T`, created empty on first use.
    pub fn get<T: Any + Send + Default>(&mut self) -> &mut T {
        let slot = self.slots.entry(TypeId::of::<T>()).or_insert_with(|| Box::new(T::default()));
        match slot.downcast_mut::<T>() {
            Some(cache) => cache,
            // The slot is keyed by the type it holds, so this cannot happen.
            None => unreachable!("cache slot holds another type"),
        }
    }
}
