//! Background work: every job the window starts (a scene's computation with
//! its coarse preview, a family sweep, rendering an export or a movie) is a
//! value of [`Job`], and [`run`] does it: the preview, the scene caches and
//! the cache of whole results live here, once. A [`Runner`] only decides
//! where jobs run and carries them and their results: [`ThreadRunner`] on
//! native threads; the browser build (`web/`) sends the same values to Web
//! Workers of the same code. Each job belongs to a [`Lane`]; a new job on a
//! lane cancels the one running there, and [`Lanes`] (which every runner
//! keeps) drops a result whose job is stale.

use crate::figure::{self, Figure, Series, Style};
use crate::preset::Preset;
use crate::provenance::Stamp;
use crate::scene::{self, Caches, Progress, SceneError, SceneOutput, SceneParams};
use crate::session::Pin;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Mutex};

/// Where a job runs beside others: one job at a time per lane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Lane {
    /// The open scene's result: the newest wins.
    Compute,
    /// A family sweep or "what matters", beside the scene's own
    /// computation: the newest wins.
    Sweep,
    /// A sensitivity curve or map, beside "what matters": the newest wins.
    Curve,
    /// A share of the runs of a study over whole ranges, beside the rest:
    /// the newest wins.
    Study,
    /// Figures rendered for an export: the newest wins.
    Export,
    /// A history rendered as a movie: the newest wins.
    Movie,
}

/// Points of a sensitivity curve.
const CURVE_POINTS: usize = 50;
/// Points along each side of a sensitivity map.
const MAP_POINTS: usize = 24;

/// A piece of work, as plain data (bytes too: a browser sends it to a Web
/// Worker).
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub enum Job {
    /// Scene `scene`'s result for `params`; `coarse`, when given, is
    /// computed beside it as a preview shown until the full result lands.
    Scene {
        /// Index of the scene in [`scene::SCENES`].
        scene: usize,
        /// The parameters.
        params: Box<SceneParams>,
        /// Coarse parameters for a quick preview.
        coarse: Option<Box<SceneParams>>,
    },
    /// One model curve set per value of parameter `key`, pinned as a family.
    Sweep {
        /// The parameters the sweep starts from and the one parameter varied.
        plan: Box<crate::sweep::Plan>,
        /// Palette index of the first pin.
        first_color: usize,
    },
    /// Every parameter's influence on scalar `output` around `base`.
    WhatMatters {
        /// The parameters.
        base: Box<SceneParams>,
        /// The scalar's key.
        output: String,
        /// The factor around each parameter's value.
        factor: f64,
        /// Whether to answer with the scene's coarse parameters (a first pass).
        coarse: bool,
    },
    /// Scalar `output` against parameter `key` over its range, or over
    /// `key` and `second` as a map.
    Curve {
        /// The parameters.
        base: Box<SceneParams>,
        /// The scalar's key.
        output: String,
        /// The parameter's key.
        key: String,
        /// The map's second parameter, if any.
        second: Option<String>,
    },
    /// Runs `from..to` of a study over whole ranges (Morris or Sobol'):
    /// scalar `output` (unit `unit`) at the design's points around `base`.
    WholeRange {
        /// The parameters the factors vary around (the others stay).
        base: Box<SceneParams>,
        /// The design.
        design: Box<crate::global_sensitivity::Design>,
        /// The scalar's key.
        output: String,
        /// Its unit.
        unit: String,
        /// The first run.
        from: usize,
        /// One past the last run.
        to: usize,
    },
    /// Figures rendered as PNG, SVG and CSV files carrying the state.
    Export {
        /// The figures as drawn.
        figures: Vec<Figure>,
        /// The state the files carry.
        stamp: Box<Stamp>,
        /// Prefix of every file name.
        prefix: String,
    },
    /// A played history as frames and an animated PNG per figure, or (with
    /// `sheet`) as one animated PNG of every figure.
    Movie {
        /// The scene's state.
        preset: Box<Preset>,
        /// Frames per figure.
        frames: usize,
        /// One file (a platform that saves by downloads) rather than a folder.
        #[serde(default)]
        sheet: bool,
    },
}

impl Job {
    /// The lane the job runs on.
    pub fn lane(&self) -> Lane {
        match self {
            Job::Scene { .. } => Lane::Compute,
            Job::Sweep { .. } | Job::WhatMatters { .. } => Lane::Sweep,
            Job::Curve { .. } => Lane::Curve,
            Job::WholeRange { .. } => Lane::Study,
            Job::Export { .. } => Lane::Export,
            Job::Movie { .. } => Lane::Movie,
        }
    }
}

/// What a finished job produced.
#[derive(Debug, serde::Serialize, serde::Deserialize)]
pub enum Done {
    /// A scene's result.
    Scene(usize, SceneOutput),
    /// A sweep's pins.
    Sweep(Vec<Pin>),
    /// A curve of a scalar against a parameter, for the parameters given.
    Curve(Box<SceneParams>, Box<Figure>),
    /// What matters: the parameters, X there, each parameter's influence,
    /// and whether it is the coarse first pass.
    Matters(Box<SceneParams>, crate::sensitivity::Matters, bool),
    /// Runs of a study over whole ranges: the parameters and design they
    /// are for, the first run's number and each run's value.
    WholeRange(
        Box<SceneParams>,
        Box<crate::global_sensitivity::Design>,
        usize,
        Vec<crate::global_sensitivity::RunValue>,
    ),
    /// Files to write: what they are ("export", "movie"), and (name, bytes).
    Files(String, Vec<(String, Vec<u8>)>),
}

/// Why a job gave no result.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
pub enum JobError {
    /// It was cancelled (nothing to report).
    #[error("cancelled")]
    Cancelled,
    /// It failed: why.
    #[error("{0}")]
    Failed(String),
}

impl From<SceneError> for JobError {
    fn from(e: SceneError) -> Self {
        match e {
            SceneError::Cancelled => JobError::Cancelled,
            e => JobError::Failed(e.to_string()),
        }
    }
}

/// A job's result with where it came from.
#[derive(Debug)]
pub struct Finished {
    /// The lane it ran on.
    pub lane: Lane,
    /// Its result; a cancelled job reports nothing.
    pub result: Result<Done, JobError>,
}

/// Does `job`, reporting to `progress`; scene results come from and go to
/// `caches`. The same function runs wherever a runner runs it.
pub fn run(job: Job, progress: &Progress, caches: &Mutex<Caches>) -> Result<Done, JobError> {
    match job {
        Job::Scene { scene, params, coarse } => {
            let key = params.compute_key();
            if let Some(out) = caches.lock().ok().and_then(|mut c| c.get::<Results>().find(&key)) {
                return Ok(Done::Scene(scene, out));
            }
            let finished = Flag::default();
            if let Some(c) = coarse {
                // First, on every core: a coarse preview costs a fraction of a
                // second alone, but several seconds beside the full run.
                preview(&c, progress, &finished);
            }
            let mut c = caches.lock().map_err(|_| JobError::Cancelled)?;
            let out = scene::compute_cached(&params, progress, &mut c);
            finished.store(true, std::sync::atomic::Ordering::Relaxed);
            let out = out?;
            c.get::<Results>().keep(key, &out);
            Ok(Done::Scene(scene, out))
        }
        Job::Sweep { plan, first_color } => {
            let key = &plan.vary[0].key;
            let points: Vec<usize> = (0..plan.len()).collect();
            let finished = std::sync::atomic::AtomicUsize::new(0);
            // Each point is a unit of its own: a browser shares them among its workers.
            let pins = progress.units(&points, |&j| {
                progress.check()?;
                let v = plan.point(j)[0];
                let params = plan.params_at(j)?;
                let out = scene::compute(&params, &progress.quiet_child())?;
                // Tagged with the swept value, except on figures that colour
                // their curves by a value of their own (their colour bar stays).
                let curves = out
                    .figures
                    .iter()
                    .flat_map(|f| {
                        let own = f.family.is_some();
                        f.series.iter().filter(|s| s.style == Style::Line).map(move |s| {
                            let s = if own { Series { family: None, ..(*s).clone() } } else { s.clone().at(v) };
                            (f.id.clone(), s)
                        })
                    })
                    .collect();
                let n = finished.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                progress.set(n as f64 / points.len().max(1) as f64);
                Ok(Pin { params, label: format!("{key} = {}", figure::tick_label(v)), curves, color: first_color + j })
            })?;
            Ok(Done::Sweep(pins))
        }
        Job::WhatMatters { base, output, factor, coarse } => {
            let at = if coarse { base.coarse().unwrap_or_else(|| (*base).clone()) } else { (*base).clone() };
            let m = crate::sensitivity::what_matters(&at, &output, factor, progress)?;
            Ok(Done::Matters(base, m, coarse))
        }
        Job::WholeRange { base, design, output, unit, from, to } => {
            let values = crate::global_sensitivity::run_values(&base, &design, &output, &unit, from..to, progress)
                .map_err(|e| if progress.cancelled() { JobError::Cancelled } else { JobError::Failed(e) })?;
            Ok(Done::WholeRange(base, design, from, values))
        }
        Job::Curve { base, output, key, second } => {
            let fig = match second {
                Some(y) => crate::sensitivity::map(&base, &output, &key, &y, MAP_POINTS, progress)?,
                None => crate::sensitivity::curve(&base, &output, &key, CURVE_POINTS, progress)?,
            };
            Ok(Done::Curve(base, Box::new(fig)))
        }
        Job::Export { figures, stamp, prefix } => {
            let mut files = Vec::new();
            for (k, fig) in figures.iter().enumerate() {
                for ext in ["png", "svg", "csv"] {
                    progress.check()?;
                    let bytes = crate::provenance::figure_bytes(fig, ext, figure::EXPORT_SIZE, Some(&stamp))
                        .map_err(|e| JobError::Failed(format!("{e:#}")))?;
                    files.push((format!("{prefix}{}.{ext}", fig.id), bytes));
                }
                progress.set((k + 1) as f64 / figures.len().max(1) as f64);
            }
            Ok(Done::Files("export".into(), files))
        }
        Job::Movie { preset, frames, sheet } => {
            let failed = |e: anyhow::Error| {
                if progress.cancelled() { JobError::Cancelled } else { JobError::Failed(format!("{e:#}")) }
            };
            let files = if sheet {
                vec![crate::handout::movie_sheet(&preset, frames, 12, &|| progress.cancelled()).map_err(failed)?]
            } else {
                crate::handout::movie_files(&preset, frames, None, true, 12, &|| progress.cancelled())
                    .map_err(failed)?
            };
            Ok(Done::Files("movie".into(), files))
        }
    }
}

/// The line series of every figure of `out`, by figure id (what a pin keeps).
pub fn line_curves(out: &SceneOutput) -> Vec<(String, Series)> {
    out.figures
        .iter()
        .flat_map(|f| f.series.iter().filter(|s| s.style == Style::Line).map(move |s| (f.id.clone(), s.clone())))
        .collect()
}

/// Runs jobs somewhere other than the window's frame.
pub trait Runner {
    /// Starts `job` on its lane, cancelling the job running there.
    fn submit(&mut self, job: Job);
    /// Cancels the job on `lane`, if any.
    fn cancel(&mut self, lane: Lane);
    /// Whether a job runs on `lane`.
    fn busy(&self, lane: Lane) -> bool;
    /// The fraction done of the job on `lane`.
    fn progress(&self, lane: Lane) -> f64;
    /// Pauses or resumes the job on `lane` (jobs that do not honour pauses run on).
    fn set_paused(&self, lane: Lane, paused: bool);
    /// Whether the job on `lane` is paused.
    fn paused(&self, lane: Lane) -> bool;
    /// The newest intermediate result the job on `lane` offered.
    fn partial(&self, lane: Lane) -> Option<Arc<SceneOutput>>;
    /// Results of the newest jobs that finished since the last call; stale
    /// and cancelled ones are dropped.
    fn poll(&mut self) -> Vec<Finished>;
    /// Computes a cheap scene at once, sharing the runner's caches.
    fn compute_now(&self, params: &SceneParams) -> Result<SceneOutput, SceneError>;
    /// Whether jobs that honour pauses can be paused here.
    fn can_pause(&self) -> bool {
        true
    }
    /// How often the window redraws while a job runs, for its progress:
    /// every 100 ms, unless drawing takes the cores the jobs run on.
    fn redraw_every(&self) -> std::time::Duration {
        std::time::Duration::from_millis(100)
    }
}

/// The lanes' bookkeeping that every runner keeps: each job's generation
/// and the newest job of each lane, so that the result of a job cancelled
/// or superseded since is dropped, whichever runner ran it.
#[derive(Debug, Default)]
pub struct Lanes {
    generation: u64,
    newest: Vec<(Lane, u64)>,
}

impl Lanes {
    /// A new job on `lane`: its generation, now the lane's newest.
    pub fn start(&mut self, lane: Lane) -> u64 {
        self.generation += 1;
        self.cancel(lane);
        self.newest.push((lane, self.generation));
        self.generation
    }

    /// Forgets the job on `lane`: its result will be dropped.
    pub fn cancel(&mut self, lane: Lane) {
        self.newest.retain(|(l, _)| *l != lane);
    }

    /// The generation of the job running on `lane`, if any.
    pub fn running(&self, lane: Lane) -> Option<u64> {
        self.newest.iter().find(|(l, _)| *l == lane).map(|(_, g)| *g)
    }

    /// A job's report: the result to show, and the lane free again; None
    /// for the report of a stale job, and for a cancelled one.
    pub fn accept(&mut self, lane: Lane, generation: u64, result: Result<Done, JobError>) -> Option<Finished> {
        if self.running(lane) != Some(generation) {
            return None;
        }
        self.cancel(lane);
        (!matches!(result, Err(JobError::Cancelled))).then_some(Finished { lane, result })
    }
}

/// A job's result as a runner thread sends it: lane, generation, result.
type Report = (Lane, u64, Result<Done, JobError>);

/// Set once a job's full result is in, so that its preview is not shown.
type Flag = Arc<std::sync::atomic::AtomicBool>;

/// A runner on native threads: a thread per job and one set of caches
/// shared by all.
pub struct ThreadRunner {
    caches: Arc<Mutex<Caches>>,
    done: (Sender<Report>, Receiver<Report>),
    lanes: Lanes,
    /// The progress of the job running on each lane.
    running: Vec<(Lane, Progress)>,
    repaint: Arc<dyn Fn() + Send + Sync>,
}

impl ThreadRunner {
    /// A runner that calls `repaint` whenever a result is ready.
    pub fn new(repaint: impl Fn() + Send + Sync + 'static) -> Self {
        ThreadRunner {
            caches: Arc::new(Mutex::new(Caches::default())),
            done: channel(),
            lanes: Lanes::default(),
            running: Vec::new(),
            repaint: Arc::new(repaint),
        }
    }

    fn running(&self, lane: Lane) -> Option<&Progress> {
        self.running.iter().find(|(l, _)| *l == lane).map(|(_, p)| p)
    }
}

/// A runner that goes away (its window closed, a test's app dropped) stops
/// its jobs: nothing reads their results, and they would hold the shared
/// thread pool from the jobs of other runners in the process.
impl Drop for ThreadRunner {
    fn drop(&mut self) {
        for (_, progress) in &self.running {
            progress.cancel();
        }
    }
}

impl Runner for ThreadRunner {
    fn submit(&mut self, job: Job) {
        let lane = job.lane();
        self.cancel(lane);
        let generation = self.lanes.start(lane);
        let progress = Progress::default();
        self.running.push((lane, progress.clone()));
        let (tx, caches, repaint) = (self.done.0.clone(), Arc::clone(&self.caches), Arc::clone(&self.repaint));
        let started = std::thread::Builder::new().name("grainscope-job".into()).spawn(move || {
            let result = run(job, &progress, &caches);
            let _ = tx.send((lane, generation, result));
            repaint();
        });
        if started.is_err() {
            // No thread: the job is dropped and the lane reports an error.
            let _ = self.done.0.send((lane, generation, Err(JobError::Failed("no thread to run the job on".into()))));
        }
    }

    fn cancel(&mut self, lane: Lane) {
        self.lanes.cancel(lane);
        self.running.retain(|(l, p)| {
            if *l == lane {
                p.cancel();
            }
            *l != lane
        });
    }

    fn busy(&self, lane: Lane) -> bool {
        self.running(lane).is_some()
    }

    fn progress(&self, lane: Lane) -> f64 {
        self.running(lane).map_or(0.0, Progress::fraction)
    }

    fn set_paused(&self, lane: Lane, paused: bool) {
        if let Some(p) = self.running(lane) {
            p.set_paused(paused);
        }
    }

    fn paused(&self, lane: Lane) -> bool {
        self.running(lane).is_some_and(Progress::paused)
    }

    fn partial(&self, lane: Lane) -> Option<Arc<SceneOutput>> {
        self.running(lane).and_then(Progress::partial)
    }

    fn poll(&mut self) -> Vec<Finished> {
        let mut out = Vec::new();
        while let Ok((lane, generation, result)) = self.done.1.try_recv() {
            let current = self.lanes.running(lane) == Some(generation);
            if current {
                self.running.retain(|(l, _)| *l != lane);
            }
            out.extend(self.lanes.accept(lane, generation, result));
        }
        out
    }

    fn compute_now(&self, params: &SceneParams) -> Result<SceneOutput, SceneError> {
        compute_now(params, &self.caches)
    }
}

/// Computes a cheap scene at once with `caches` (computed afresh if they
/// are poisoned): what every runner's [`Runner::compute_now`] does.
pub fn compute_now(params: &SceneParams, caches: &Mutex<Caches>) -> Result<SceneOutput, SceneError> {
    match caches.lock() {
        Ok(mut c) => scene::compute_cached(params, &Progress::default(), &mut c),
        Err(_) => scene::compute(params, &Progress::default()),
    }
}

/// The note a coarse preview carries.
pub const PREVIEW_NOTE: &str = "preview at low resolution; the full result follows";

/// How many whole results of scene jobs are kept.
const KEPT_RESULTS: usize = 4;

/// The newest whole results of scene jobs, by their parameters' compute key:
/// a job asked again (back to a heavy scene, an undo) answers at once, with
/// no preview.
#[derive(Default)]
struct Results(Vec<(SceneParams, SceneOutput)>);

impl Results {
    fn find(&self, key: &SceneParams) -> Option<SceneOutput> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, out)| out.clone())
    }

    fn keep(&mut self, key: SceneParams, out: &SceneOutput) {
        self.0.retain(|(k, _)| *k != key);
        if self.0.len() >= KEPT_RESULTS {
            self.0.remove(0);
        }
        self.0.push((key, out.clone()));
    }
}

/// Computes the coarse parameters `c` of a heavy scene and offers the result
/// for display, unless the full result came first or the job was cancelled.
fn preview(c: &SceneParams, progress: &Progress, finished: &std::sync::atomic::AtomicBool) {
    if let Ok(mut out) = scene::compute(c, &progress.quiet_child()) {
        if finished.load(std::sync::atomic::Ordering::Relaxed) || progress.cancelled() {
            return;
        }
        out.notes.insert(0, PREVIEW_NOTE.into());
        // Only while nothing newer was offered (a live view of the full run).
        if progress.partial().is_none() {
            progress.publish(out);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    fn wait(r: &mut ThreadRunner) -> Vec<Finished> {
        let start = Instant::now();
        loop {
            let got = r.poll();
            if !got.is_empty() || start.elapsed() > Duration::from_secs(60) {
                return got;
            }
            std::thread::sleep(Duration::from_millis(2));
        }
    }

    fn scene_job(velocity: f64) -> Job {
        let mut p = SceneParams::default_for("hysteresis").expect("scene");
        p.set("velocity", &velocity.to_string()).expect("valid");
        Job::Scene { scene: 0, params: Box::new(p), coarse: None }
    }

    /// A runner that is dropped cancels the jobs it still runs.
    #[test]
    fn a_dropped_runner_cancels_its_jobs() {
        let mut r = ThreadRunner::new(|| {});
        r.submit(scene_job(2.0));
        let progress = r.running.first().map(|(_, p)| p.clone()).expect("a running job");
        assert!(!progress.cancelled());
        drop(r);
        assert!(progress.cancelled());
    }

    /// A newer job on a lane wins: the older one's result never lands.
    #[test]
    fn the_newest_job_on_a_lane_wins() {
        let mut r = ThreadRunner::new(|| {});
        r.submit(scene_job(2.0));
        r.submit(scene_job(4.0));
        let got = wait(&mut r);
        assert_eq!(got.len(), 1);
        match &got[0].result {
            Ok(Done::Scene(_, out)) => {
                let e = out.scalar("e").expect("e");
                assert!((e - 0.2247).abs() < 0.002, "the 4 m/s result, e = {e}");
            }
            other => panic!("{other:?}"),
        }
        assert!(!r.busy(Lane::Compute));
        // A stale result that arrives late is dropped too.
        assert!(r.poll().is_empty());
    }

    /// A cancelled sweep reports nothing and frees its lane.
    #[test]
    fn a_cancelled_job_reports_nothing() {
        let mut r = ThreadRunner::new(|| {});
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let vary = crate::sweep::Vary::parse("velocity=lin:1:2:200").expect("vary");
        let plan = crate::sweep::Plan::new(base, vec![vary]).expect("plan");
        r.submit(Job::Sweep { plan: Box::new(plan), first_color: 1 });
        assert!(r.busy(Lane::Sweep) && !r.busy(Lane::Compute));
        r.cancel(Lane::Sweep);
        assert!(!r.busy(Lane::Sweep));
        std::thread::sleep(Duration::from_millis(50));
        assert!(r.poll().is_empty());
    }

    /// A family sweep shared among 2 and 3 processes, as a browser shares
    /// its points among its workers, gives the pins of one process.
    #[test]
    fn a_sweep_shared_among_processes_gives_the_same_pins() {
        let base = SceneParams::default_for("hysteresis").expect("scene");
        let vary = crate::sweep::Vary::parse("velocity=lin:1:3:5").expect("vary");
        let job =
            Job::Sweep { plan: Box::new(crate::sweep::Plan::new(base, vec![vary]).expect("plan")), first_color: 2 };
        let pins = |progress: &Progress| match run(job.clone(), progress, &Mutex::new(Caches::default())) {
            Ok(Done::Sweep(pins)) => Ok(pins),
            Err(JobError::Cancelled) => Err(SceneError::Cancelled),
            other => panic!("{other:?}"),
        };
        let whole = pins(&Progress::default()).expect("pins");
        assert_eq!(whole.len(), 5);
        for n in [2, 3] {
            let (shared, rounds) = crate::scene::parts::in_turns(n, pins).expect("pins");
            assert_eq!(rounds, 2, "{n} processes");
            assert_eq!(shared, whole, "{n} processes");
        }
    }

    /// Rendering an export gives three files per figure, named by the prefix.
    #[test]
    fn an_export_job_renders_every_figure_three_ways() {
        let preset = crate::preset::resolve("ice-bounce-8ms").expect("shipped");
        let out = scene::compute(&preset.scene, &Progress::default()).expect("computes");
        let stamp = Stamp::of(&preset).expect("stamp");
        let job = Job::Export { figures: out.figures.clone(), stamp: Box::new(stamp), prefix: "h-".into() };
        match run(job, &Progress::default(), &Mutex::new(Caches::default())) {
            Ok(Done::Files(what, files)) if what == "export" => {
                assert_eq!(files.len(), 3 * out.figures.len());
                assert!(files.iter().all(|(n, b)| n.starts_with("h-") && !b.is_empty()));
                let png = &files.iter().find(|(n, _)| n.ends_with(".png")).expect("a png").1;
                let back = crate::preset::from_embedded_bytes(png, "x.png").expect("carries its state");
                assert_eq!(back.scene, preset.scene);
            }
            other => panic!("{other:?}"),
        }
    }
}
