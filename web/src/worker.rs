//! The computing side of a Web Worker: it runs the jobs the page sends, one
//! at a time, with the same code the desktop runs on its threads, and posts
//! `[kind, payload]` messages back: `["progress", fraction]`,
//! `["partial", bytes]` (a coarse preview or a live view), and
//! `["done", bytes]` (the encoded `Result<Done, JobError>`, with the model
//! data that inspecting a clicked point needs). A job sent with its
//! [`Parts`] (the page shares its units among several workers) may instead
//! say `["sharing", n]` when it reaches a map it shares among n workers, and
//! end with `["share", bytes]` (the encoded [`grainscope::scene::Share`]).

use crate::wire;
use grainscope::app::jobs::{self, Done, Job, JobError};
use grainscope::scene::{Caches, Extra, Parts, Progress, Report, SceneOutput, Watcher};
use std::cell::Cell;
use std::sync::{Arc, Mutex};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// Least time between two progress messages, ms.
const PROGRESS_EVERY: f64 = 100.0;
/// Least time between two intermediate results, ms.
const PARTIAL_EVERY: f64 = 400.0;

thread_local! {
    /// Results kept between the jobs of this worker.
    static CACHES: Mutex<Caches> = Mutex::default();
    /// When the last progress and intermediate result were posted, ms.
    static LAST: Cell<(f64, f64)> = const { Cell::new((f64::NEG_INFINITY, f64::NEG_INFINITY)) };
}

/// Posts `[kind, payload]` to the page.
fn post(kind: &str, payload: &JsValue) {
    let scope: web_sys::DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
    let _ = scope.post_message(&js_sys::Array::of2(&JsValue::from_str(kind), payload));
}

/// An intermediate output as the page receives it: the model data, for
/// inspecting the final result, stays here.
fn portable(out: &SceneOutput) -> SceneOutput {
    let extra = if matches!(out.extra, Extra::Model(_)) { Extra::None } else { out.extra.clone() };
    SceneOutput { extra, ..out.clone() }
}

/// Posts an intermediate result.
fn post_partial(out: &SceneOutput) {
    if let Ok(bytes) = wire::encode(&portable(out)) {
        post("partial", &js_sys::Uint8Array::from(&bytes[..]).into());
    }
}

/// Tells the page of a report, no more often than it can use.
fn report(r: Report<'_>) {
    let now = js_sys::Date::now();
    let (progress_at, partial_at) = LAST.with(Cell::get);
    match r {
        Report::Fraction(f) if now - progress_at >= PROGRESS_EVERY => {
            LAST.with(|l| l.set((now, partial_at)));
            post("progress", &JsValue::from_f64(f));
        }
        Report::Partial(out) if now - partial_at >= PARTIAL_EVERY => {
            LAST.with(|l| l.set((progress_at, now)));
            post_partial(out);
        }
        Report::Sharing(n) => post("sharing", &JsValue::from_f64(n as f64)),
        _ => {}
    }
}

/// Runs a job as the desktop does ([`jobs::run`]: a heavy scene's coarse
/// preview, unless its result is cached, comes first here, where no thread
/// can compute it beside), posting what it reports.
/// With `parts`, the job takes its share of them; a job that stopped to
/// share a map posts its share, and the page sends it again with every
/// share known.
fn run(job: Job, parts: Option<Parts>) -> Option<Result<Done, JobError>> {
    let mut progress = Progress::watched(Watcher(Arc::new(report)));
    if let Some(parts) = parts {
        progress = progress.with_parts(parts);
    }
    let result = CACHES.with(|caches| jobs::run(job, &progress, caches));
    match progress.share().map(|share| wire::encode(&share)) {
        Some(Ok(bytes)) => {
            post("share", &js_sys::Uint8Array::from(&bytes[..]).into());
            None
        }
        Some(Err(e)) => Some(Err(JobError::Failed(format!("a share cannot be sent: {e}")))),
        None => Some(result),
    }
}

/// Runs the job encoded in `job` (with its share of the encoded [`Parts`]
/// `parts`, if given) and posts its progress and result.
#[wasm_bindgen]
pub fn run_job(job: &[u8], parts: Option<Vec<u8>>) {
    console_error_panic_hook::set_once();
    LAST.with(|l| l.set((f64::NEG_INFINITY, f64::NEG_INFINITY)));
    let parts = match parts.map(|p| wire::decode::<Parts>(&p)).transpose() {
        Ok(parts) => parts,
        Err(e) => {
            return post("failed", &JsValue::from_str(&format!("the page sent parts the worker cannot read: {e}")));
        }
    };
    let result = match wire::decode::<Job>(job) {
        Ok(job) => match run(job, parts) {
            Some(result) => result,
            None => return,
        },
        Err(e) => Err(JobError::Failed(format!("the page sent a job the worker cannot read: {e}"))),
    };
    let encoded = wire::encode(&result)
        .or_else(|e| wire::encode(&Err::<Done, _>(JobError::Failed(format!("the result cannot be sent: {e}")))));
    match encoded {
        Ok(bytes) => post("done", &js_sys::Uint8Array::from(&bytes[..]).into()),
        Err(e) => post("failed", &JsValue::from_str(&e)),
    }
}
