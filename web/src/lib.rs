//! grainscope in a browser tab: the same explorer window, compiled to
//! WebAssembly and drawn with WebGL on the page's canvas. What differs from
//! the desktop sits behind the window's two seams: [`platform::WebPlatform`]
//! (file picker, downloads, browser storage, the page's clock) and the job
//! runner, [`runner::WorkerRunner`], whose Web Workers run the same module
//! ([`worker`]). `web/build.sh` builds the page; `web/index.html` loads it.

#[cfg(target_arch = "wasm32")]
mod platform;
#[cfg(target_arch = "wasm32")]
mod runner;
#[cfg(target_arch = "wasm32")]
mod start;
#[cfg(target_arch = "wasm32")]
mod wire;
#[cfg(target_arch = "wasm32")]
mod worker;

#[cfg(target_arch = "wasm32")]
pub use start::start;
#[cfg(target_arch = "wasm32")]
pub use worker::run_job;
