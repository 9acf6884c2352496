//! The explorer window, in layers: [`state`] holds what the user sees
//! (no toolkit types), every user action is a [`command::Command`] applied
//! in one place (`apply.rs`), background work goes through one job
//! [`jobs::Runner`], files, dialogs, storage and the clock sit behind
//! [`platform::Platform`], and the panels under [`ui`] draw the state and
//! report commands. This file composes them into one frame.

mod apply;
mod apply_deck;
mod apply_sweep;
pub mod command;
#[cfg(not(target_arch = "wasm32"))]
pub mod desktop;
mod effects;
pub mod history;
pub mod jobs;
pub mod opening;
pub mod platform;
pub mod playback;
pub mod shortcuts;
pub mod state;
pub mod ui;

pub use crate::session::{Pin, Session};
#[cfg(not(target_arch = "wasm32"))]
pub use desktop::{SESSION_ENV, open_named, run, session_path};

use command::{Action, Command};
use jobs::{Job, Lane, Runner, ThreadRunner};
use platform::Platform;
use shortcuts::Mode;
use state::AppState;
use ui::{Cx, Memo, Work};

/// Bookkeeping of the open scene's computation.
#[derive(Default)]
struct Computing {
    /// The compute key last requested of each scene.
    requested: Vec<Option<crate::scene::SceneParams>>,
    /// Whether the open scene's result is older than its parameters.
    stale: bool,
    /// The scene the running job computes (none for sweeps), whose
    /// intermediate results are shown while it runs.
    live_scene: Option<usize>,
    /// The folder files rendered on each lane go to.
    folders: Vec<(Lane, String)>,
}

/// The explorer application: state, the panels' memory, a job runner and
/// a platform.
pub struct GrainscopeApp {
    /// What the window shows.
    pub state: AppState,
    memo: Memo,
    computing: Computing,
    runner: Box<dyn Runner>,
    platform: Box<dyn Platform>,
}

impl GrainscopeApp {
    /// A new application on `platform`, with default settings (see
    /// [`GrainscopeApp::restore_session`]); jobs run on native threads and
    /// repaint `ctx` when they finish.
    pub fn new(ctx: egui::Context, platform: Box<dyn Platform>) -> Self {
        Self::with_runner(platform, Box::new(ThreadRunner::new(move || ctx.request_repaint())))
    }

    /// A new application on `platform` whose jobs run on `runner` (a
    /// browser's Web Worker, for example).
    pub fn with_runner(platform: Box<dyn Platform>, runner: Box<dyn Runner>) -> Self {
        let n = crate::scene::SCENES.len();
        let state = AppState { paths: platform.paths(), ..AppState::default() };
        GrainscopeApp {
            state,
            memo: Memo::default(),
            computing: Computing { requested: vec![None; n], ..Computing::default() },
            runner,
            platform,
        }
    }

    /// Starts scene `id` from lighter defaults (`sets`: keys and values as
    /// `--set` takes them) and says so with `note` beside its parameters: a
    /// browser computes on one thread, so its heaviest scenes start smaller.
    /// A scene still at its own defaults moves to the lighter ones; one whose
    /// parameters the user changed keeps them.
    pub fn lighten_defaults(&mut self, id: &str, sets: &[(&str, &str)], note: &str) -> Result<(), String> {
        let i = crate::scene::SCENES.iter().position(|s| s.id == id).ok_or_else(|| format!("no scene {id}"))?;
        let mut lighter = self.state.defaults[i].clone();
        for (key, value) in sets {
            lighter.set(key, value).map_err(|e| e.to_string())?;
        }
        let old = std::mem::replace(&mut self.state.defaults[i], lighter.clone());
        if let Some(p) = self.state.session.params.get_mut(id)
            && *p == old
        {
            *p = lighter;
        }
        self.state.default_notes[i] = Some(note.to_string());
        self.state.lighter_keys[i] = sets.iter().map(|(key, _)| key.to_string()).collect();
        Ok(())
    }

    /// Restores the session the platform kept; an unreadable one leaves the
    /// default settings and a notice. Returns whether a session was found.
    pub fn restore_session(&mut self) -> bool {
        let restored = self.platform.load_session();
        self.state.session = restored.session;
        if let Some(notice) = restored.notice {
            self.state.notify(notice);
        }
        self.memo.look_applied = None;
        restored.found
    }

    /// Keeps the session for the next start, saying once if that fails.
    pub fn save_session(&mut self) {
        let result =
            crate::session::to_ron(&self.state.session).and_then(|text| self.platform.save_session(text.as_bytes()));
        match result {
            Ok(()) => self.state.session_save_failed = false,
            Err(e) if !self.state.session_save_failed => {
                self.state.session_save_failed = true;
                self.state.notify(format!("the session could not be saved: {e}"));
            }
            Err(_) => {}
        }
    }

    /// Applies a user action and carries out what it asks of the platform
    /// and the runner.
    pub fn apply(&mut self, command: Command) {
        for effect in self.state.apply(command) {
            self.carry_out(effect);
        }
    }

    /// The current scene's parameters.
    pub fn params(&self) -> &crate::scene::SceneParams {
        self.state.params()
    }

    /// The current scene's last good output.
    pub fn output(&self) -> Option<&crate::scene::SceneOutput> {
        self.state.output()
    }

    /// What the last click on a figure of the open scene shows, if any.
    pub fn inspection(&self) -> Option<&crate::scene::inspect::Inspection> {
        self.state.inspection()
    }

    /// The status line (last message).
    pub fn status(&self) -> &str {
        &self.state.status
    }

    /// Whether a result is still being computed.
    pub fn busy(&self) -> bool {
        self.runner.busy(Lane::Compute)
            || self.runner.busy(Lane::Sweep)
            || self.runner.busy(Lane::Curve)
            || self.runner.busy(Lane::Study)
            || self.computing.stale
    }

    /// The fraction done of what is being computed (0 when nothing is).
    pub fn progress(&self) -> f64 {
        self.work().progress
    }

    /// The frame (inside the axes) of figure `figure` as drawn in the last
    /// frame, in screen points.
    pub fn plot_frame(&self, figure: &str) -> Option<egui::Rect> {
        self.memo.plot_frames.iter().find(|(id, _)| id == figure).map(|(_, r)| r.frame)
    }

    /// The smallest rectangle holding every plot drawn in the last frame.
    pub fn plot_area(&self) -> Option<egui::Rect> {
        self.memo.plot_rects.iter().copied().reduce(|a, b| a.union(b))
    }

    /// Starts (or computes at once, for a cheap scene) the open scene's
    /// result if its computed parameters changed.
    fn request(&mut self) {
        // A file that carried a sensitivity view: compute it for the opened scene.
        if std::mem::take(&mut self.state.matters.reopen) {
            self.apply(Command::Act(Action::Sensitivity));
            let (x, y) = (self.state.matters.x.clone(), self.state.matters.y.clone());
            if !x.is_empty() {
                self.apply(Command::DrawSensitivity(x, y));
            }
            if self.state.matters.whole.study.is_some() {
                self.apply(Command::MattersWhole(true));
                self.apply(Command::RunWholeRange);
            }
        }
        let i = self.state.index();
        let key = self.state.params().compute_key();
        if self.computing.requested[i].as_ref() == Some(&key) {
            return;
        }
        self.computing.requested[i] = Some(key);
        let params = self.state.params().clone();
        if crate::scene::SCENES[i].heavy {
            self.computing.stale = true;
            self.computing.live_scene = Some(i);
            let coarse = params.preview().map(Box::new);
            self.runner.submit(Job::Scene { scene: i, params: Box::new(params), coarse });
        } else {
            self.runner.cancel(Lane::Compute);
            self.computing.stale = false;
            let result = self.runner.compute_now(&params);
            self.state.finish(i, result);
        }
    }

    /// How the computation stands, for the panels.
    fn work(&self) -> Work {
        // The progress shown: a sweep's, else a curve's, else the scene's.
        let lane =
            [Lane::Sweep, Lane::Curve, Lane::Study].into_iter().find(|&l| self.runner.busy(l)).unwrap_or(Lane::Compute);
        let running = self.runner.busy(Lane::Compute) || lane != Lane::Compute;
        Work {
            running,
            stale: self.computing.stale,
            progress: self.runner.progress(lane),
            paused: self.runner.paused(Lane::Compute),
            pausable: self.runner.can_pause()
                && self.computing.live_scene.is_some_and(|i| self.state.params_of(i).pausable()),
        }
    }

    /// Draws a panel from the state, then applies what the user did in it.
    fn panel<R>(&mut self, draw: impl FnOnce(&mut Cx<'_>) -> R) -> R {
        let mut out = Vec::new();
        let work = self.work();
        let r = draw(&mut Cx { state: &self.state, memo: &mut self.memo, out: &mut out, work });
        for c in out {
            self.apply(c);
        }
        r
    }

    /// Draws the whole window content into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.poll(&ctx);
        // A phone's screen: one column, the parameters in a drawer (not
        // while presenting a deck, whose layout is the projector's). Lecture
        // mode is the projector's look: a phone keeps its own.
        let presenting = self.state.presenter.is_some();
        self.memo.compact = ui::compact(ctx.content_rect().size()) && !presenting;
        let compact = self.memo.compact;
        let lecture = self.state.session.lecture && !compact;
        ui::look::apply(&ctx, &mut self.memo, lecture, self.state.session.light);
        // The keyboard shortcuts; none while a text field has the keyboard.
        if !ctx.egui_wants_keyboard_input() {
            let mode = if self.state.presenter.is_some() { Mode::Presenter } else { Mode::Explorer };
            for action in shortcuts::pressed(&ctx, mode) {
                self.apply(Command::Act(action));
            }
        }
        if self.state.playback.playing {
            self.apply(Command::Tick(f64::from(ctx.input(|i| i.stable_dt))));
            ctx.request_repaint();
        }
        // The presenter's timer: the input clock's time since the last frame,
        // and a frame at least every second so that it ticks.
        let now = ctx.input(|i| i.time);
        if let Some(before) = self.memo.clock.replace(now)
            && self.state.presenter.is_some()
        {
            self.apply(Command::Clock(now - before));
            ctx.request_repaint_after(std::time::Duration::from_secs(1));
        }
        egui::Panel::top("top").show(ui, |ui| {
            self.panel(|cx| if presenting { ui::presenter::bar(ui, cx) } else { ui::top_bar::show(ui, cx) })
        });
        if !self.state.notices.is_empty() {
            egui::Panel::top("notices").show(ui, |ui| self.panel(|cx| ui::status::notices(ui, cx)));
        }
        // In lecture mode the status line shows only while something runs
        // or went wrong, so that the plots keep the bottom of the screen.
        if !lecture || self.work().running || self.state.error.is_some() {
            egui::Panel::bottom("status").show(ui, |ui| self.panel(|cx| ui::status::bar(ui, cx)));
        }
        if self.state.presenter.as_ref().is_some_and(|p| p.notes) {
            let height = (0.27 * ctx.content_rect().height()).max(120.0);
            egui::Panel::bottom("notes")
                .exact_size(height)
                .show(ui, |ui| self.panel(|cx| ui::presenter::notes(ui, cx)));
        }
        if !lecture && !compact {
            // A width the user drags within bounds: never more than ~40 % of
            // the window, so that the figures keep the larger part of it.
            let widest = (0.4 * ctx.content_rect().width()).max(320.0);
            egui::Panel::left("controls").resizable(true).default_size(360.0).size_range(300.0..=widest).show(
                ui,
                |ui| {
                    // The content never asks for more than the panel's width,
                    // nor less (a scroll area shrinks to narrower content, such
                    // as "computing…" in place of a table, while a job runs),
                    // so the panel changes width only when the user drags its
                    // edge.
                    let width = ui.available_width();
                    egui::ScrollArea::vertical().auto_shrink([false, false]).show(ui, |ui| {
                        ui.set_max_width(width);
                        self.panel(|cx| ui::scene_panel::show(ui, cx))
                    });
                },
            );
        }
        self.request();
        let figures = if compact && self.state.drawer {
            // The drawer: the parameters over the whole width, in place of the figures.
            egui::CentralPanel::default()
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .id_salt("drawer")
                        .auto_shrink([false, false])
                        .show(ui, |ui| self.panel(|cx| ui::scene_panel::show(ui, cx)));
                })
                .response
                .rect
        } else {
            egui::CentralPanel::default().show(ui, |ui| self.panel(|cx| ui::figures::show(ui, cx))).response.rect
        };
        if lecture && self.state.lecture_params {
            let mut open = true;
            egui::Window::new("Parameters")
                .open(&mut open)
                .anchor(egui::Align2::RIGHT_TOP, [-10.0, 60.0])
                .default_width(420.0)
                .collapsible(true)
                .show(&ctx, |ui| {
                    egui::ScrollArea::vertical().max_height(ctx.content_rect().height() * 0.7).show(ui, |ui| {
                        self.panel(|cx| {
                            ui::scene_panel::headline(ui, cx);
                            ui::scene_panel::parameters(ui, cx);
                            ui.separator();
                            ui::scene_panel::scalars(ui, cx);
                        })
                    });
                });
            if !open {
                self.apply(Command::SetLectureParams(false));
            }
        }
        self.panel(|cx| {
            ui::deck_editor::window(&ctx, cx);
            ui::presenter::notes_window(&ctx, cx);
            ui::inspector::window(&ctx, cx);
            ui::matters::window(&ctx, cx);
            ui::help::overlay(&ctx, cx);
            ui::palette::window(&ctx, cx);
            ui::link::card(&ctx, cx);
            ui::classroom::layer(&ctx, cx, figures);
        });
        // A whole slider drag is one step of the history.
        self.state.at_rest(ctx.input(|i| i.pointer.any_down()));
    }
}

impl eframe::App for GrainscopeApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, _storage: &mut dyn eframe::Storage) {
        self.save_session();
    }
}
