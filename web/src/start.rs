//! The page's entry: starts the explorer on a canvas and opens what the
//! page's address names.

use crate::platform::{WebPlatform, kind_of};
use crate::runner::WorkerRunner;
use grainscope::app::GrainscopeApp;
use grainscope::app::command::Command;
use grainscope::app::platform::Answer;
use grainscope::links::Opened;
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// The explorer with what only a page has: files dropped on it arrive as
/// names and are read asynchronously; their bytes reach the explorer as the
/// platform's answers, as a picked file's do.
struct PageApp {
    app: GrainscopeApp,
    answers: Rc<RefCell<Vec<Answer>>>,
    /// How often the page redraws while workers compute.
    redraw: std::time::Duration,
}

impl eframe::App for PageApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let dropped = ui.ctx().input_mut(|i| std::mem::take(&mut i.raw.dropped_files));
        for file in dropped {
            let (answers, ctx) = (Rc::clone(&self.answers), ui.ctx().clone());
            wasm_bindgen_futures::spawn_local(async move {
                let name = file.path().display().to_string();
                let answer = match file.bytes_async().await {
                    Ok(bytes) => Answer::Opened(kind_of(&name), grainscope::app::platform::Picked { name, bytes }),
                    Err(e) => Answer::Failed(kind_of(&name), format!("cannot read the dropped {name}: {e}")),
                };
                answers.borrow_mut().push(answer);
                ctx.request_repaint();
            });
        }
        self.app.ui(ui, frame);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        self.app.save(storage);
    }

    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(self)
    }
}

/// What a scene that starts lighter in the browser says.
const LIGHTER: &str = "In the browser this scene starts from 1 run, w* = 14 groups per decade and f = 0.3 \
(tens of seconds on one thread); the desktop's defaults are 2 runs, w* = 40 and f = 0.1.";

/// How often the page redraws while workers compute (for their progress):
/// every 400 ms, where a frame costs the GPU a few milliseconds.
const REDRAW: std::time::Duration = std::time::Duration::from_millis(400);

/// The same where the browser draws without a GPU: every 2 s. There a frame
/// costs the browser's GPU process 50-250 ms of a core, taken from the
/// workers; at 400 ms Fig. 5.9's formation zone took 17.4-17.7 s on two
/// cores, at 2 s 15.5-15.6 s.
const SOFTWARE_REDRAW: std::time::Duration = std::time::Duration::from_secs(2);

/// Whether the page's WebGL draws in software (SwiftShader, llvmpipe and
/// the like), by the renderer the browser names: the unmasked one where
/// the browser offers it.
fn draws_in_software(gl: &eframe::glow::Context) -> bool {
    use eframe::glow::HasContext;
    /// UNMASKED_RENDERER_WEBGL of the WEBGL_debug_renderer_info extension.
    const UNMASKED_RENDERER: u32 = 0x9246;
    // SAFETY: a query of a string on the context the page draws with; the
    // unmasked renderer only where its extension is there (no GL error).
    let renderer = unsafe {
        if gl.supported_extensions().contains("WEBGL_debug_renderer_info") {
            gl.get_parameter_string(UNMASKED_RENDERER)
        } else {
            gl.get_parameter_string(eframe::glow::RENDERER)
        }
    }
    .to_lowercase();
    ["swiftshader", "llvmpipe", "softpipe", "software", "basic render driver"].iter().any(|s| renderer.contains(s))
}

/// The running explorer, kept by the page.
#[wasm_bindgen]
pub struct WebHandle {
    runner: eframe::WebRunner,
}

#[wasm_bindgen]
impl WebHandle {
    /// The message of a panic, if the explorer stopped on one.
    pub fn panic_message(&self) -> Option<String> {
        self.runner.panic_summary().map(|s| s.message())
    }

    /// Whether a result is still being computed.
    pub fn busy(&self) -> bool {
        self.runner.app_mut::<PageApp>().is_some_and(|p| p.app.busy())
    }

    /// The fraction done of the running computation (0 when none runs).
    pub fn progress(&self) -> f64 {
        self.runner.app_mut::<PageApp>().map_or(0.0, |p| p.app.progress())
    }

    /// How often the page redraws while workers compute, ms (every 2 s
    /// where it draws without a GPU, 400 ms otherwise).
    pub fn redraw_ms(&self) -> f64 {
        self.runner.app_mut::<PageApp>().map_or(f64::NAN, |p| p.redraw.as_secs_f64() * 1e3)
    }

    /// The status line.
    pub fn status(&self) -> String {
        self.runner.app_mut::<PageApp>().map(|p| p.app.status().to_string()).unwrap_or_default()
    }

    /// The open scene's scalars as one JSON object, keyed as the command
    /// line's `--json` (empty while there is no result).
    pub fn scalars_json(&self) -> String {
        let app = self.runner.app_mut::<PageApp>();
        app.and_then(|p| p.app.output().map(|o| o.scalars_json(p.app.params().censored()).to_string()))
            .unwrap_or_default()
    }

    /// Milliseconds to compute shipped preset `name` from cold on the page's
    /// own thread (no caches): the figure of merit against the desktop.
    pub fn time_preset(&self, name: &str) -> Result<f64, JsValue> {
        let preset = grainscope::preset::resolve(name).map_err(|e| e.to_string())?;
        let clock = web_sys::window().and_then(|w| w.performance()).ok_or("no clock")?;
        let start = clock.now();
        grainscope::scene::compute(&preset.scene, &grainscope::scene::Progress::default())
            .map_err(|e| e.to_string())?;
        Ok(clock.now() - start)
    }

    /// The notices shown above the figures (one per line; empty when none).
    pub fn notices(&self) -> String {
        self.runner.app_mut::<PageApp>().map(|p| p.app.state.notices.join("\n")).unwrap_or_default()
    }

    /// The title of what the last click on a figure shows (empty when
    /// nothing is inspected).
    pub fn inspection(&self) -> String {
        let app = self.runner.app_mut::<PageApp>();
        app.and_then(|p| p.app.inspection().map(|i| i.title.clone())).unwrap_or_default()
    }

    /// Where figure `figure`'s axes were drawn in the last frame, in CSS
    /// pixels: `[left, top, right, bottom]` (empty when it was not drawn).
    pub fn plot_frame(&self, figure: &str) -> Vec<f32> {
        let app = self.runner.app_mut::<PageApp>();
        app.and_then(|p| p.app.plot_frame(figure)).map(|r| vec![r.min.x, r.min.y, r.max.x, r.max.y]).unwrap_or_default()
    }

    /// The open scene's identifier.
    pub fn scene(&self) -> String {
        self.runner.app_mut::<PageApp>().map(|p| p.app.params().info().id.to_string()).unwrap_or_default()
    }
}

/// Starts the explorer on the canvas with id `canvas_id`, with the session
/// the page kept and what the page's address names.
#[wasm_bindgen]
pub async fn start(canvas_id: String) -> Result<WebHandle, JsValue> {
    console_error_panic_hook::set_once();
    let window = web_sys::window().ok_or("no window")?;
    let document = window.document().ok_or("no document")?;
    let canvas = document
        .get_element_by_id(&canvas_id)
        .ok_or_else(|| format!("no element {canvas_id} on the page"))?
        .dyn_into::<web_sys::HtmlCanvasElement>()?;
    let query = window.location().search().unwrap_or_default();
    let runner = eframe::WebRunner::new();
    runner
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(move |cc| {
                let (ctx, woken) = (cc.egui_ctx.clone(), cc.egui_ctx.clone());
                let software = cc.gl.as_deref().is_some_and(draws_in_software);
                let redraw = if software { SOFTWARE_REDRAW } else { REDRAW };
                let jobs = WorkerRunner::new(move || ctx.request_repaint(), redraw);
                let platform = WebPlatform::new(move || woken.request_repaint());
                let answers = platform.answers();
                let mut app = GrainscopeApp::with_runner(Box::new(platform), Box::new(jobs));
                app.restore_session();
                // The Monte Carlo columns start at the decks' quicker setting.
                for id in ["mass-distribution", "families", "erosion-balance"] {
                    let sets = [("runs", "1"), ("groups_per_decade", "14"), ("f_limit", "0.3")];
                    if let Err(e) = app.lighten_defaults(id, &sets, LIGHTER) {
                        app.state.notify(e);
                    }
                }
                match grainscope::links::open(&query) {
                    Ok(Opened::Preset(preset, name)) => app.apply(Command::ApplyPreset(preset, name)),
                    Ok(Opened::Deck(deck, slide)) => app.apply(Command::Present(deck, slide)),
                    Ok(Opened::Nothing) => {}
                    Err(message) => app.state.notify(message),
                }
                Ok(Box::new(PageApp { app, answers, redraw }))
            }),
        )
        .await?;
    Ok(WebHandle { runner })
}
