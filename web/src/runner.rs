//! The browser's job runner: each lane has a Web Worker running the same
//! WebAssembly module, so that long computations never hold up the page.
//! A job goes to its lane's worker as bytes; progress, intermediate results
//! and the result come back as messages. Cancelling a running job ends its
//! worker (a worker computing cannot be interrupted otherwise); the next
//! job starts a fresh one. Cheap scenes compute on the page at once.
//!
//! Every core: a job goes out with [`Parts`] for as many workers as the
//! browser reports cores. When it reaches a map of independent units (the
//! disks of a grid, the runs of a column) its worker says so, and helper
//! workers (started then, and ended with the job) run the same job to the
//! same map, each taking its share of the units; the page gathers the
//! shares and sends the job to the lane's worker again, with every unit
//! known, until it runs through (see `grainscope::scene::parts`).

use crate::wire;
use grainscope::app::jobs::{self, Done, Finished, Job, JobError, Lane, Lanes, Runner};
use grainscope::scene::{Caches, Parts, Progress, SceneError, SceneOutput, SceneParams, Share};
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::sync::{Arc, Mutex};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// The script each worker runs (beside the page).
const WORKER_SCRIPT: &str = "./worker.js";

/// The most workers a lane shares a job among.
const MOST_WORKERS: usize = 8;

/// What a worker reports of its job (besides progress and previews).
enum Note {
    /// The job ran through: its result.
    Done(Result<Done, JobError>),
    /// It shares a map among this many workers.
    Sharing(usize),
    /// It stopped after its share of a map.
    Share(Share),
}

/// A report as a worker makes it: lane, part, generation, what.
type Report = (Lane, usize, u64, Note);

/// A job a lane's workers share: the job (without its preview, which the
/// first round alone computes) and the shares so far.
struct Fan {
    job: Vec<u8>,
    /// Workers to share among (1 once a helper could not be started).
    workers: usize,
    /// Units known from earlier rounds, and made in this one.
    known: Vec<(usize, String)>,
    made: Vec<(usize, String)>,
    /// Shares of this round still to come.
    waiting: usize,
}

/// A lane's worker and what it reported of its job.
struct Slot {
    worker: web_sys::Worker,
    /// The job it runs (or ran last).
    generation: Rc<Cell<u64>>,
    busy: bool,
    fraction: Rc<Cell<f64>>,
    partial: Rc<RefCell<Option<Arc<SceneOutput>>>>,
    _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _on_error: Closure<dyn FnMut(web_sys::ErrorEvent)>,
}

impl Drop for Slot {
    fn drop(&mut self) {
        // Messages still queued from it find no handler.
        self.worker.set_onmessage(None);
        self.worker.set_onerror(None);
        self.worker.terminate();
    }
}

/// Runs jobs in Web Workers: one per lane, and helpers per lane for its
/// share of a job's units.
pub struct WorkerRunner {
    /// Each worker with its lane and part (0: the lane's own worker).
    slots: Vec<(Lane, usize, Slot)>,
    fans: Vec<(Lane, Fan)>,
    /// Workers a job is shared among: the browser's cores.
    workers: usize,
    inbox: Rc<RefCell<Vec<Report>>>,
    lanes: Lanes,
    caches: Mutex<Caches>,
    repaint: Rc<dyn Fn()>,
    /// How often the page redraws while a job runs.
    redraw: std::time::Duration,
}

impl WorkerRunner {
    /// A runner that calls `repaint` when a worker reports, and has the
    /// page redrawn every `redraw` while a job runs (for its progress).
    pub fn new(repaint: impl Fn() + 'static, redraw: std::time::Duration) -> Self {
        let cores = web_sys::window().map_or(1.0, |w| w.navigator().hardware_concurrency());
        WorkerRunner {
            slots: Vec::new(),
            fans: Vec::new(),
            workers: (cores as usize).clamp(1, MOST_WORKERS),
            inbox: Rc::default(),
            lanes: Lanes::default(),
            caches: Mutex::default(),
            repaint: Rc::new(repaint),
            redraw,
        }
    }

    fn slot(&self, lane: Lane) -> Option<&Slot> {
        self.slots.iter().find(|(l, k, _)| *l == lane && *k == 0).map(|(_, _, s)| s)
    }

    /// Sends `job` (encoded) to worker `part` of `lane`, starting it if
    /// needed, as job `generation`.
    fn send(
        &mut self,
        lane: Lane,
        part: usize,
        generation: u64,
        job: &[u8],
        parts: Option<Parts>,
    ) -> Result<(), String> {
        if !self.slots.iter().any(|(l, k, _)| *l == lane && *k == part) {
            let slot = self.spawn(lane, part)?;
            self.slots.push((lane, part, slot));
        }
        let Some((_, _, slot)) = self.slots.iter_mut().find(|(l, k, _)| *l == lane && *k == part) else {
            return Err("no worker".into());
        };
        slot.generation.set(generation);
        slot.busy = true;
        let parts = match parts.map(|p| wire::encode(&p)).transpose()? {
            Some(bytes) => JsValue::from(js_sys::Uint8Array::from(&bytes[..])),
            None => JsValue::NULL,
        };
        let message = js_sys::Array::of3(&JsValue::from_str("job"), &js_sys::Uint8Array::from(job), &parts);
        slot.worker.post_message(&message).map_err(|e| format!("the job could not be sent to a worker ({e:?})"))
    }

    /// Acts on a worker's note that its job shares a map among `of`
    /// workers (part 0) or has made its share (any part).
    fn fan(&mut self, lane: Lane, generation: u64, note: Note) -> Option<Result<Done, JobError>> {
        let i = self.fans.iter().position(|(l, _)| *l == lane)?;
        match note {
            Note::Sharing(of) => {
                let fan = &mut self.fans[i].1;
                fan.made.clear();
                fan.waiting = of;
                let (job, workers, known) = (fan.job.clone(), fan.workers, fan.known.clone());
                for part in 1..of {
                    let parts = Parts { part, of: workers, known: known.clone() };
                    if self.send(lane, part, generation, &job, Some(parts)).is_err() {
                        // No helper: the lane's worker does the rest alone.
                        let fan = &mut self.fans[i].1;
                        fan.workers = 1;
                        fan.waiting -= 1;
                    }
                }
                None
            }
            Note::Share(share) => {
                let fan = &mut self.fans[i].1;
                fan.made.extend(share.made);
                fan.waiting = fan.waiting.saturating_sub(1);
                if fan.waiting > 0 {
                    return None;
                }
                let made = std::mem::take(&mut fan.made);
                fan.known.extend(made);
                let parts = Parts { part: 0, of: fan.workers, known: fan.known.clone() };
                let job = fan.job.clone();
                self.send(lane, 0, generation, &job, Some(parts)).err().map(|e| Err(JobError::Failed(e)))
            }
            Note::Done(_) => None,
        }
    }

    /// A new worker for `lane`'s part `part`, given this page's compiled module.
    fn spawn(&self, lane: Lane, part: usize) -> Result<Slot, String> {
        let options = web_sys::WorkerOptions::new();
        options.set_type(web_sys::WorkerType::Module);
        let worker = web_sys::Worker::new_with_options(WORKER_SCRIPT, &options)
            .map_err(|e| format!("no Web Worker for the computation ({e:?})"))?;
        let generation = Rc::new(Cell::new(0));
        let fraction = Rc::new(Cell::new(0.0));
        let partial: Rc<RefCell<Option<Arc<SceneOutput>>>> = Rc::default();
        let on_message = {
            let (generation, fraction, partial) = (Rc::clone(&generation), Rc::clone(&fraction), Rc::clone(&partial));
            let (inbox, repaint) = (Rc::clone(&self.inbox), Rc::clone(&self.repaint));
            Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |event: web_sys::MessageEvent| {
                let message = js_sys::Array::from(&event.data());
                let (kind, payload) = (message.get(0).as_string().unwrap_or_default(), message.get(1));
                let bytes = || js_sys::Uint8Array::new(&payload).to_vec();
                match kind.as_str() {
                    // Progress is drawn at the window's own pace (see `redraw_every`).
                    "progress" => return fraction.set(payload.as_f64().unwrap_or(0.0)),
                    "partial" => {
                        if let Ok(out) = wire::decode::<SceneOutput>(&bytes()) {
                            *partial.borrow_mut() = Some(Arc::new(out));
                        }
                    }
                    "done" => {
                        let result = wire::decode::<Result<Done, JobError>>(&bytes()).unwrap_or_else(|e| {
                            Err(JobError::Failed(format!("the worker's result could not be read: {e}")))
                        });
                        inbox.borrow_mut().push((lane, part, generation.get(), Note::Done(result)));
                    }
                    "sharing" => {
                        let of = payload.as_f64().unwrap_or(1.0) as usize;
                        inbox.borrow_mut().push((lane, part, generation.get(), Note::Sharing(of)));
                    }
                    "share" => {
                        let note = match wire::decode::<Share>(&bytes()) {
                            Ok(share) => Note::Share(share),
                            Err(e) => {
                                Note::Done(Err(JobError::Failed(format!("a worker's share could not be read: {e}"))))
                            }
                        };
                        inbox.borrow_mut().push((lane, part, generation.get(), note));
                    }
                    _ => {
                        let why = payload.as_string().unwrap_or_else(|| "no reason given".into());
                        inbox.borrow_mut().push((lane, part, generation.get(), Note::Done(Err(JobError::Failed(why)))));
                    }
                }
                repaint();
            })
        };
        let on_error = {
            let generation = Rc::clone(&generation);
            let (inbox, repaint) = (Rc::clone(&self.inbox), Rc::clone(&self.repaint));
            Closure::<dyn FnMut(web_sys::ErrorEvent)>::new(move |event: web_sys::ErrorEvent| {
                let why = format!("the computation stopped: {}", event.message());
                inbox.borrow_mut().push((lane, part, generation.get(), Note::Done(Err(JobError::Failed(why)))));
                repaint();
            })
        };
        worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
        worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
        // The worker instantiates the module this page already compiled.
        worker
            .post_message(&js_sys::Array::of2(&JsValue::from_str("module"), &wasm_bindgen::module()))
            .map_err(|e| format!("the worker could not be started ({e:?})"))?;
        Ok(Slot { worker, generation, busy: false, fraction, partial, _on_message: on_message, _on_error: on_error })
    }
}

impl Runner for WorkerRunner {
    fn submit(&mut self, job: Job) {
        let lane = job.lane();
        self.cancel(lane);
        let generation = self.lanes.start(lane);
        // Rounds after the first, and the helpers, leave out the preview.
        let shared = match &job {
            Job::Scene { scene, params, .. } => Job::Scene { scene: *scene, params: params.clone(), coarse: None },
            other => other.clone(),
        };
        let (bytes, shared) = match wire::encode(&job).and_then(|b| Ok((b, wire::encode(&shared)?))) {
            Ok(b) => b,
            Err(e) => {
                let why = JobError::Failed(format!("the job could not be sent to a worker: {e}"));
                self.inbox.borrow_mut().push((lane, 0, generation, Note::Done(Err(why))));
                return;
            }
        };
        for (l, _, slot) in &self.slots {
            if *l == lane {
                slot.fraction.set(0.0);
                *slot.partial.borrow_mut() = None;
            }
        }
        let parts = (self.workers > 1).then(|| Parts { part: 0, of: self.workers, known: Vec::new() });
        if parts.is_some() {
            let fan = Fan { job: shared, workers: self.workers, known: Vec::new(), made: Vec::new(), waiting: 0 };
            self.fans.push((lane, fan));
        }
        if let Err(why) = self.send(lane, 0, generation, &bytes, parts) {
            self.fans.retain(|(l, _)| *l != lane);
            if self.slot(lane).is_some() {
                self.inbox.borrow_mut().push((lane, 0, generation, Note::Done(Err(JobError::Failed(why)))));
                return;
            }
            // No worker (a page opened from a file, say): on the page itself.
            let result = jobs::run(job, &Progress::default(), &self.caches);
            let result = result.map_err(|e| match e {
                JobError::Failed(f) => JobError::Failed(format!("{f} ({why})")),
                c => c,
            });
            self.inbox.borrow_mut().push((lane, 0, generation, Note::Done(result)));
            (self.repaint)();
        }
    }

    fn cancel(&mut self, lane: Lane) {
        self.lanes.cancel(lane);
        self.fans.retain(|(l, _)| *l != lane);
        // A worker that computes cannot be told to stop: it is ended, and
        // so are the lane's helpers (each keeps the memory its share took).
        self.slots.retain(|(l, k, s)| *l != lane || (*k == 0 && !s.busy));
    }

    fn busy(&self, lane: Lane) -> bool {
        self.slots.iter().any(|(l, _, s)| *l == lane && s.busy)
    }

    /// The sum of what the lane's workers report: each reports the units it
    /// computed out of all.
    fn progress(&self, lane: Lane) -> f64 {
        let sum: f64 = self.slots.iter().filter(|(l, _, _)| *l == lane).map(|(_, _, s)| s.fraction.get()).sum();
        sum.min(1.0)
    }

    /// Pausing is not offered in the browser (a computing worker reads no
    /// messages); the job runs on.
    fn set_paused(&self, _lane: Lane, _paused: bool) {}

    fn can_pause(&self) -> bool {
        false
    }

    fn paused(&self, _lane: Lane) -> bool {
        false
    }

    /// As the page was told ([`WorkerRunner::new`]). (A preview, a live
    /// view, a share and the result each ask for a frame as they arrive.)
    fn redraw_every(&self) -> std::time::Duration {
        self.redraw
    }

    fn partial(&self, lane: Lane) -> Option<Arc<SceneOutput>> {
        if !self.busy(lane) {
            return None;
        }
        self.slot(lane).and_then(|s| s.partial.borrow().clone())
    }

    fn poll(&mut self) -> Vec<Finished> {
        let reports = std::mem::take(&mut *self.inbox.borrow_mut());
        let mut out = Vec::new();
        for (lane, part, generation, note) in reports {
            // Reports of a job cancelled since are dropped.
            if self.lanes.running(lane) != Some(generation) {
                continue;
            }
            // Helpers reach the shared map too; the lane's worker has said so.
            if part > 0 && matches!(note, Note::Sharing(_)) {
                continue;
            }
            if let Some((_, _, slot)) = self.slots.iter_mut().find(|(l, k, _)| *l == lane && *k == part)
                && !matches!(note, Note::Sharing(_))
            {
                slot.busy = false;
            }
            let result = match note {
                Note::Done(result) => result,
                note => match self.fan(lane, generation, note) {
                    Some(result) => result,
                    None => continue,
                },
            };
            // The job is over: its helpers are ended (a phone's memory is
            // not held by idle workers of every lane), and so is a worker
            // that failed (a panic): it is not trusted with another job.
            let failed = matches!(result, Err(JobError::Failed(_)));
            self.fans.retain(|(l, _)| *l != lane);
            let ended = |k: usize, s: &Slot| k > 0 || s.busy || (failed && k == part);
            self.slots.retain(|(l, k, s)| *l != lane || !ended(*k, s));
            out.extend(self.lanes.accept(lane, generation, result));
        }
        out
    }

    fn compute_now(&self, params: &SceneParams) -> Result<SceneOutput, SceneError> {
        jobs::compute_now(params, &self.caches)
    }
}
