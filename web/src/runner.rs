//! The browser's job runner: each lane has a Web Worker running the same
//! WebAssembly module, so that long computations never hold up the page.
//! A job goes to its lane's worker as bytes; progress, intermediate results
//! and the result come back as messages. Cancelling a running job ends its
//! worker (a worker computing cannot be interrupted otherwise); the next
//! job starts a fresh one. Cheap scenes compute on the page at once.

use crate::wire;
use grainscope::app::jobs::{self, Done, Finished, Job, JobError, Lane, Lanes, Runner};
use grainscope::scene::{Caches, Progress, SceneError, SceneOutput, SceneParams};
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::sync::{Arc, Mutex};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// The script each worker runs (beside the page).
const WORKER_SCRIPT: &str = "./worker.js";

/// A result as a worker reports it: lane, generation, result.
type Report = (Lane, u64, Result<Done, JobError>);

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

/// Runs jobs in Web Workers, one per lane.
pub struct WorkerRunner {
    slots: Vec<(Lane, Slot)>,
    inbox: Rc<RefCell<Vec<Report>>>,
    lanes: Lanes,
    caches: Mutex<Caches>,
    repaint: Rc<dyn Fn()>,
}

impl WorkerRunner {
    /// A runner that calls `repaint` when a worker reports.
    pub fn new(repaint: impl Fn() + 'static) -> Self {
        WorkerRunner {
            slots: Vec::new(),
            inbox: Rc::default(),
            lanes: Lanes::default(),
            caches: Mutex::default(),
            repaint: Rc::new(repaint),
        }
    }

    fn slot(&self, lane: Lane) -> Option<&Slot> {
        self.slots.iter().find(|(l, _)| *l == lane).map(|(_, s)| s)
    }

    /// A new worker for `lane`, given this page's compiled module.
    fn spawn(&self, lane: Lane) -> Result<Slot, String> {
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
                    "progress" => fraction.set(payload.as_f64().unwrap_or(0.0)),
                    "partial" => {
                        if let Ok(out) = wire::decode::<SceneOutput>(&bytes()) {
                            *partial.borrow_mut() = Some(Arc::new(out));
                        }
                    }
                    "done" => {
                        let result = wire::decode::<Result<Done, JobError>>(&bytes()).unwrap_or_else(|e| {
                            Err(JobError::Failed(format!("the worker's result could not be read: {e}")))
                        });
                        inbox.borrow_mut().push((lane, generation.get(), result));
                    }
                    _ => {
                        let why = payload.as_string().unwrap_or_else(|| "no reason given".into());
                        inbox.borrow_mut().push((lane, generation.get(), Err(JobError::Failed(why))));
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
                inbox.borrow_mut().push((lane, generation.get(), Err(JobError::Failed(why))));
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
        let bytes = match wire::encode(&job) {
            Ok(b) => b,
            Err(e) => {
                let why = JobError::Failed(format!("the job could not be sent to a worker: {e}"));
                self.inbox.borrow_mut().push((lane, generation, Err(why)));
                return;
            }
        };
        if self.slot(lane).is_none() {
            match self.spawn(lane) {
                Ok(slot) => self.slots.push((lane, slot)),
                Err(why) => {
                    // No worker (a page opened from a file, say): on the page itself.
                    let result = jobs::run(job, &Progress::default(), &self.caches);
                    let result = result.map_err(|e| match e {
                        JobError::Failed(f) => JobError::Failed(format!("{f} ({why})")),
                        c => c,
                    });
                    self.inbox.borrow_mut().push((lane, generation, result));
                    (self.repaint)();
                    return;
                }
            }
        }
        let Some((_, slot)) = self.slots.iter_mut().find(|(l, _)| *l == lane) else { return };
        slot.generation.set(generation);
        slot.busy = true;
        slot.fraction.set(0.0);
        *slot.partial.borrow_mut() = None;
        let message = js_sys::Array::of2(&JsValue::from_str("job"), &js_sys::Uint8Array::from(&bytes[..]));
        if let Err(e) = slot.worker.post_message(&message) {
            let why = JobError::Failed(format!("the job could not be sent to a worker ({e:?})"));
            self.inbox.borrow_mut().push((lane, generation, Err(why)));
        }
    }

    fn cancel(&mut self, lane: Lane) {
        self.lanes.cancel(lane);
        // A worker that computes cannot be told to stop: it is ended.
        self.slots.retain(|(l, s)| *l != lane || !s.busy);
    }

    fn busy(&self, lane: Lane) -> bool {
        self.slot(lane).is_some_and(|s| s.busy)
    }

    fn progress(&self, lane: Lane) -> f64 {
        self.slot(lane).map_or(0.0, |s| s.fraction.get())
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

    fn partial(&self, lane: Lane) -> Option<Arc<SceneOutput>> {
        self.slot(lane).filter(|s| s.busy).and_then(|s| s.partial.borrow().clone())
    }

    fn poll(&mut self) -> Vec<Finished> {
        let reports = std::mem::take(&mut *self.inbox.borrow_mut());
        let mut out = Vec::new();
        for (lane, generation, result) in reports {
            // Reports of a job cancelled since are dropped.
            if self.lanes.running(lane) != Some(generation) {
                continue;
            }
            let failed = matches!(result, Err(JobError::Failed(_)));
            match self.slots.iter_mut().find(|(l, _)| *l == lane) {
                // A worker that failed (a panic) is not trusted with another job.
                Some(_) if failed => self.slots.retain(|(l, _)| *l != lane),
                Some((_, slot)) => slot.busy = false,
                None => {}
            }
            out.extend(self.lanes.accept(lane, generation, result));
        }
        out
    }

    fn compute_now(&self, params: &SceneParams) -> Result<SceneOutput, SceneError> {
        jobs::compute_now(params, &self.caches)
    }
}
