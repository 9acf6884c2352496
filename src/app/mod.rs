//! The explorer window. It draws scene outputs and edits parameters; all
//! physics happens in [`crate::scene`], inline for cheap scenes and on a
//! worker thread for heavy ones.

mod history;
mod inspector;
mod monomer_card;
mod playback;
mod plot;
mod presenter;
pub mod shortcuts;
mod sketch;
mod worker;

pub use worker::Worker;

use shortcuts::{Action, Mode};

use crate::figure::{self, Figure, Series, Style, View};
use crate::preset::{Preset, resolve};
use crate::scene::{self, Caches, ControlKind, Extra, SCENES, SceneError, SceneOutput, SceneParams};
pub use crate::session::{Pin, Session};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Mutex};

/// Key under which earlier versions kept the session in eframe's storage
/// (read once when no session file exists yet).
const SESSION_KEY: &str = "grainscope-session";

/// Environment variable naming the session file (default: `session.ron` in
/// the platform's data folder for grainscope).
pub const SESSION_ENV: &str = "GRAINSCOPE_SESSION";

/// Where the session is kept.
pub fn session_path() -> Option<PathBuf> {
    match std::env::var_os(SESSION_ENV) {
        Some(p) if !p.is_empty() => Some(PathBuf::from(p)),
        _ => eframe::storage_dir("grainscope").map(|d| d.join("session.ron")),
    }
}

/// Opens the explorer window with `files`: presets (files or shipped
/// names), figures exported by grainscope (their embedded state) or a deck
/// (presented at once). A file that cannot be loaded does not stop the
/// window: it opens with the restored session and shows why.
pub fn run(files: Vec<String>) -> anyhow::Result<()> {
    let initial: Vec<Result<Opened, String>> = files
        .iter()
        .map(|f| {
            open_named(f).map_err(|message| {
                let _ = writeln!(std::io::stderr(), "error: {message}");
                message
            })
        })
        .collect();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1440.0, 920.0])
            .with_title("grainscope")
            .with_drag_and_drop(true),
        ..Default::default()
    };
    eframe::run_native(
        "grainscope",
        options,
        Box::new(move |cc| {
            let mut app = GrainscopeApp::new(cc.egui_ctx.clone(), None);
            if let Some(path) = session_path() {
                app.open_session(path, cc.storage);
            }
            for (opened, name) in initial.into_iter().zip(&files) {
                match opened {
                    Ok(Opened::Preset(p)) => app.apply_preset(*p, name),
                    Ok(Opened::Deck(d)) => app.present(d, 0),
                    Err(message) => app.notify(message),
                }
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| anyhow::anyhow!("cannot open the window: {e}"))
}

/// What a file or name given to the window stands for.
pub enum Opened {
    /// A scene's state.
    Preset(Box<Preset>),
    /// A lecture.
    Deck(crate::deck::LoadedDeck),
}

/// Resolves a name as the window opens it: a preset (file, shipped name or
/// exported figure), else a deck (file or shipped name).
pub fn open_named(name: &str) -> Result<Opened, String> {
    match resolve(name) {
        Ok(p) => Ok(Opened::Preset(Box::new(p))),
        Err(preset_error) => match crate::deck::resolve(name) {
            Ok(d) => Ok(Opened::Deck(d)),
            Err(crate::deck::DeckError::Read { .. }) | Err(crate::deck::DeckError::Syntax { .. }) => {
                Err(format!("preset not loaded: {preset_error}"))
            }
            Err(deck_error) => Err(format!("deck not loaded: {deck_error}")),
        },
    }
}

/// Results of the worker.
enum Job {
    Scene(usize, SceneOutput),
    Sweep(Vec<Pin>),
}

/// What a file dialog returned.
enum Dialog {
    Open(Option<PathBuf>),
    /// Files written on a thread of their own: what they were, and the result.
    Written(&'static str, Result<Vec<PathBuf>, String>),
    Save(Option<PathBuf>),
    Export(Option<PathBuf>, Box<Figure>),
    ImportData(Option<PathBuf>),
}

/// Settings of a parameter sweep.
struct Sweep {
    key: String,
    from: f64,
    to: f64,
    steps: usize,
}

/// Which of the open scene's controls to draw.
#[derive(Clone, Copy)]
enum Select<'a> {
    /// All but those on the monomer card.
    Parameters,
    /// The monomer card's.
    Card,
    /// A slide's highlighted parameters, side by side.
    Slide(&'a [String]),
}

impl Select<'_> {
    fn id(&self) -> u8 {
        match self {
            Select::Parameters => 0,
            Select::Card => 1,
            Select::Slide(_) => 2,
        }
    }
}

/// The explorer application.
pub struct GrainscopeApp {
    /// Persisted state.
    pub session: Session,
    outputs: Vec<Option<Arc<SceneOutput>>>,
    requested: Vec<Option<SceneParams>>,
    stale: bool,
    status: String,
    error: Option<String>,
    worker: Worker<Job>,
    caches: Arc<Mutex<Caches>>,
    dialogs: (Sender<Dialog>, Receiver<Dialog>),
    sweep: Sweep,
    /// The (lecture, light) look last applied to the context.
    look_applied: Option<(bool, bool)>,
    /// Whether the bundled font was given to the context.
    fonts_installed: bool,
    /// Where the plots were drawn in the last frame (screen points).
    plot_rects: Vec<egui::Rect>,
    /// The frame of every plot drawn in the last frame, by figure id.
    plot_frames: Vec<(String, egui::Rect)>,
    /// Axes kept fixed while parameters change, by figure id (when locked).
    locked: Option<std::collections::HashMap<String, View>>,
    /// Whether the parameter panel is open over the plots in lecture mode.
    lecture_params: bool,
    /// Shipped presets for the menu: (chapter, title, file, text), parsed once.
    shipped_menu: Option<Vec<(scene::Chapter, String, &'static str, &'static str)>>,
    /// The scene the running worker job computes (none for sweeps), whose
    /// intermediate results are shown while it runs.
    live_scene: Option<usize>,
    /// Default parameters of every scene, in the order of [`SCENES`].
    defaults: Vec<SceneParams>,
    /// Messages that stay until dismissed (an unreadable session, a preset
    /// given on the command line that could not be loaded).
    notices: Vec<String>,
    /// A value typed into a control that was refused: (control key, why).
    control_notice: Option<(String, String)>,
    /// The session file, written on save (none in tests).
    session_path: Option<PathBuf>,
    /// Whether saving the session failed already (said once).
    session_save_failed: bool,
    /// Playing the open scene's history.
    playback: playback::Playback,
    /// Scenes (by index) whose optional time-cursor marks are shown: those
    /// played or scrubbed.
    timeline_shown: std::collections::HashSet<usize>,
    /// Undo and redo of parameter changes.
    history: history::History,
    /// Whether the list of keyboard shortcuts is shown.
    help: bool,
    /// The deck being presented.
    presenter: Option<presenter::Presenter>,
    /// The deck being built.
    deck_editor: presenter::DeckEditor,
    /// Whether a movie is being written.
    movie_running: bool,
    /// The monomer shared between scenes.
    monomer_link: monomer_card::MonomerLink,
    /// The point of a figure last clicked, and what the model says there.
    inspected: Option<inspector::Inspected>,
}

impl GrainscopeApp {
    /// A new application; restores the session from `storage` when present.
    pub fn new(ctx: egui::Context, storage: Option<&dyn eframe::Storage>) -> Self {
        let session = storage
            .and_then(|s| eframe::get_value::<Session>(s, SESSION_KEY))
            .map(Session::repaired)
            .unwrap_or_default();
        let n = SCENES.len();
        GrainscopeApp {
            session,
            outputs: vec![None; n],
            requested: vec![None; n],
            stale: false,
            status: String::new(),
            error: None,
            worker: Worker::new(move || ctx.request_repaint()),
            caches: Arc::new(Mutex::new(Caches::default())),
            dialogs: channel(),
            sweep: Sweep { key: "velocity".into(), from: 1.0, to: 10.0, steps: 5 },
            look_applied: None,
            fonts_installed: false,
            plot_rects: Vec::new(),
            plot_frames: Vec::new(),
            locked: None,
            lecture_params: false,
            shipped_menu: None,
            live_scene: None,
            defaults: SCENES.iter().filter_map(|s| SceneParams::default_for(s.id)).collect(),
            notices: Vec::new(),
            control_notice: None,
            session_path: None,
            session_save_failed: false,
            playback: playback::Playback::default(),
            timeline_shown: Default::default(),
            history: history::History::default(),
            help: false,
            presenter: None,
            deck_editor: presenter::DeckEditor::default(),
            movie_running: false,
            monomer_link: Default::default(),
            inspected: None,
        }
    }

    /// Restores the session from the file at `path` (kept there from now on).
    /// With no file yet, a session kept by an earlier version in `storage` is
    /// used. An unreadable file leaves the default settings and a notice.
    pub fn open_session(&mut self, path: PathBuf, storage: Option<&dyn eframe::Storage>) {
        let restored = crate::session::load(&path);
        if restored.found {
            self.session = restored.session;
        } else if let Some(old) = storage.and_then(|s| eframe::get_value::<Session>(s, SESSION_KEY))
            && restored.notice.is_none()
        {
            self.session = old.repaired();
        } else {
            self.session = restored.session;
        }
        if let Some(notice) = restored.notice {
            self.notify(notice);
        }
        self.session_path = restored.may_save.then_some(path);
        self.look_applied = None;
    }

    /// Shows a message that stays until dismissed.
    pub fn notify(&mut self, message: String) {
        if !self.notices.contains(&message) {
            self.notices.push(message);
        }
    }

    /// Messages shown until dismissed.
    pub fn notices(&self) -> &[String] {
        &self.notices
    }

    /// The notice of a refused control value: (key, why).
    pub fn control_notice(&self) -> Option<(&str, &str)> {
        self.control_notice.as_ref().map(|(k, m)| (k.as_str(), m.as_str()))
    }

    /// Writes the session file, saying once if that fails.
    pub fn save_session(&mut self) {
        let Some(path) = &self.session_path else { return };
        match crate::session::save(&self.session, path) {
            Ok(()) => self.session_save_failed = false,
            Err(e) if !self.session_save_failed => {
                self.session_save_failed = true;
                self.notify(format!("the session could not be saved: {e}"));
            }
            Err(_) => {}
        }
    }

    /// The current scene's parameters.
    pub fn params(&self) -> &SceneParams {
        match self.session.params.get(&self.session.scene) {
            Some(p) => p,
            None => &self.defaults[self.session.index()],
        }
    }

    /// The current scene's parameters, for editing.
    fn params_mut(&mut self) -> &mut SceneParams {
        let i = self.session.index();
        let default = &self.defaults[i];
        self.session.params.entry(SCENES[i].id.to_string()).or_insert_with(|| default.clone())
    }

    /// The parameters of scene `i` of [`SCENES`].
    fn params_of(&self, i: usize) -> &SceneParams {
        self.session.params.get(SCENES[i].id).unwrap_or(&self.defaults[i])
    }

    /// Opens scene `i` of [`SCENES`].
    fn open_scene(&mut self, i: usize) {
        if self.session.index() != i {
            self.playback.playing = false;
        }
        self.session.scene = SCENES[i].id.to_string();
        self.control_notice = None;
    }

    /// The current scene's last good output.
    pub fn output(&self) -> Option<&SceneOutput> {
        self.outputs[self.session.index()].as_deref()
    }

    /// Whether a result is still being computed (a worker job runs, or the
    /// open scene's result is older than its parameters).
    pub fn busy(&self) -> bool {
        self.worker.busy() || self.stale
    }

    /// The frame (inside the axes) of figure `figure` as drawn in the last
    /// frame, in screen points.
    pub fn plot_frame(&self, figure: &str) -> Option<egui::Rect> {
        self.plot_frames.iter().find(|(id, _)| id == figure).map(|(_, r)| *r)
    }

    /// The smallest rectangle holding every plot drawn in the last frame
    /// (axes and legends included), in screen points.
    pub fn plot_area(&self) -> Option<egui::Rect> {
        self.plot_rects.iter().copied().reduce(|a, b| a.union(b))
    }

    /// The status line (last message).
    pub fn status(&self) -> &str {
        &self.status
    }

    /// Switches to the preset's scene and parameters.
    pub fn apply_preset(&mut self, preset: Preset, origin: &str) {
        let id = preset.scene.info().id;
        self.session.scene = id.to_string();
        let shared = preset.scene.monomer_card().filter(|_| !preset.scene.own_monomer());
        self.session.params.insert(id.to_string(), preset.scene);
        // The preset's monomer becomes the monomer of every linked scene.
        if let Some(card) = shared {
            self.share_monomer(self.session.index(), &card);
        }
        self.status = format!("loaded preset '{}' from {origin}", preset.title);
        self.error = None;
        self.control_notice = None;
    }

    /// Loads measurements from a CSV file into the open scene if it takes
    /// measurements, else into the first scene that does, and opens it. A
    /// rejected file changes nothing.
    pub fn import_data(&mut self, path: &Path) {
        let takes = |p: &SceneParams| p.clone().measurements().is_some();
        let target = if takes(self.params()) {
            Some(self.session.index())
        } else {
            (0..SCENES.len()).find(|&i| takes(self.params_of(i)))
        };
        let Some(i) = target else {
            self.error = Some("no scene takes measurements (nothing imported)".into());
            return;
        };
        match crate::measurements::load(path) {
            Ok(data) => {
                self.open_scene(i);
                self.status = format!("imported {} measurements from {}", data.len(), path.display());
                if let Some(slot) = self.params_mut().measurements() {
                    *slot = data;
                }
                self.error = None;
            }
            Err(e) => self.error = Some(format!("{}: {e} (nothing imported)", path.display())),
        }
    }

    /// Opens a file as a user means it: a preset or a deck (.ron), a figure
    /// exported by grainscope (its embedded state), or measurements (a CSV
    /// file without embedded state). A file that cannot be used changes
    /// nothing and says why.
    pub fn open_file(&mut self, path: &Path) {
        let is_csv = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("csv"));
        if is_csv && matches!(crate::provenance::read(path), Err(crate::provenance::ProvenanceError::Missing(_))) {
            self.import_data(path);
            return;
        }
        let shown = path.display().to_string();
        match open_named(&path.to_string_lossy()) {
            Ok(Opened::Preset(p)) => self.apply_preset(*p, &shown),
            Ok(Opened::Deck(d)) => self.present(d, 0),
            Err(message) => self.error = Some(format!("{message}; nothing changed")),
        }
    }

    fn save_preset_file(&mut self, path: &Path) {
        let info = self.params().info();
        let preset = Preset {
            title: format!("{} (saved)", info.title),
            description: String::new(),
            scene: self.params().clone(),
        };
        match preset.save(path) {
            Ok(()) => self.status = format!("saved preset to {}", path.display()),
            Err(e) => self.error = Some(format!("preset not saved: {e}")),
        }
    }

    /// Starts (or runs inline) the computation of the current scene if its
    /// computed parameters changed.
    fn request(&mut self) {
        let i = self.session.index();
        let key = self.params().compute_key();
        if self.requested[i].as_ref() == Some(&key) {
            return;
        }
        self.requested[i] = Some(key);
        let params = self.params().clone();
        if SCENES[i].heavy {
            let caches = Arc::clone(&self.caches);
            self.stale = true;
            self.live_scene = Some(i);
            let coarse = params.coarse();
            self.worker.submit(move |progress| {
                // A coarse preview on its own thread, shown until the full
                // result arrives (and never, if the full one is cached).
                let finished = Arc::new(std::sync::atomic::AtomicBool::new(false));
                if let Some(c) = coarse {
                    let (progress, finished) = (progress.clone(), Arc::clone(&finished));
                    std::thread::spawn(move || preview(&c, &progress, &finished));
                }
                let mut c = caches.lock().map_err(|_| SceneError::Cancelled)?;
                let result = scene::compute_cached(&params, progress, &mut c).map(|o| Job::Scene(i, o));
                finished.store(true, std::sync::atomic::Ordering::Relaxed);
                result
            });
        } else {
            self.worker.cancel();
            self.stale = false;
            let result = match self.caches.lock() {
                Ok(mut c) => scene::compute_cached(&params, &scene::Progress::default(), &mut c),
                Err(_) => scene::compute(&params, &scene::Progress::default()),
            };
            self.finish(i, result);
        }
    }

    fn finish(&mut self, i: usize, result: Result<SceneOutput, SceneError>) {
        match result {
            Ok(o) => {
                self.outputs[i] = Some(Arc::new(o));
                self.error = None;
            }
            Err(e) => self.error = Some(format!("{}: {e} (showing the last good result)", SCENES[i].title)),
        }
    }

    fn poll(&mut self, ctx: &egui::Context) {
        if let Some(result) = self.worker.poll() {
            self.stale = false;
            match result {
                Ok(Job::Scene(i, o)) => self.finish(i, Ok(o)),
                Ok(Job::Sweep(pins)) => {
                    self.status = format!("swept {} values", pins.len());
                    self.session.pins.extend(pins);
                }
                Err(e) => self.error = Some(e.to_string()),
            }
        }
        while let Ok(d) = self.dialogs.1.try_recv() {
            match d {
                Dialog::Open(Some(p)) => self.open_file(&p),
                Dialog::Written(what, result) => {
                    if what == "movie" {
                        self.movie_running = false;
                    }
                    match result {
                        Ok(files) => {
                            self.status = format!(
                                "wrote the {what}: {} files, {}",
                                files.len(),
                                files.last().map_or(String::new(), |f| f.display().to_string())
                            )
                        }
                        Err(e) => self.error = Some(format!("{what} not written, earlier files untouched: {e}")),
                    }
                }
                Dialog::Save(Some(p)) => self.save_preset_file(&p),
                Dialog::Export(Some(p), fig) => self.export(&fig, &p),
                Dialog::ImportData(Some(p)) => self.import_data(&p),
                Dialog::Open(None) | Dialog::Save(None) | Dialog::Export(None, _) | Dialog::ImportData(None) => {
                    self.status =
                        "no file chosen (cancelled, or no file dialog on this desktop: type a path instead)".into();
                }
            }
        }
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw.dropped_files.iter().map(|f| f.path().to_path_buf()).filter(|p| !p.as_os_str().is_empty()).collect()
        });
        for p in dropped {
            self.open_file(&p);
        }
        if self.worker.busy() {
            // A long run offers intermediate results: draw them as they come.
            if let (Some(i), Some(part)) = (self.live_scene, self.worker.partial())
                && !self.outputs[i].as_ref().is_some_and(|o| Arc::ptr_eq(o, &part))
            {
                self.outputs[i] = Some(part);
            }
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    /// Writes `fig` to `path` (PNG, SVG or CSV by its extension), carrying
    /// the open scene's state so that the file reopens it.
    fn export(&mut self, fig: &Figure, path: &Path) {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        if !matches!(ext.as_str(), "png" | "svg" | "csv") {
            self.error = Some(format!("cannot export to {}: use a .png, .svg or .csv file name", path.display()));
            return;
        }
        let preset = self.current_preset();
        let stamp = match crate::provenance::Stamp::of(&preset) {
            Ok(s) => s,
            Err(e) => {
                self.error = Some(format!("export failed: {e}"));
                return;
            }
        };
        let result = crate::provenance::figure_bytes(fig, &ext, figure::EXPORT_SIZE, Some(&stamp))
            .map_err(|e| e.to_string())
            .and_then(|bytes| crate::files::write_atomically(path, &bytes).map_err(|e| e.to_string()));
        match result {
            Ok(()) => self.status = format!("exported {}", path.display()),
            Err(e) => self.error = Some(format!("export failed, earlier files untouched: {e}")),
        }
    }

    /// The open scene's state as a preset.
    pub fn current_preset(&self) -> Preset {
        let params = self.params().clone();
        Preset { title: params.info().title.to_string(), description: String::new(), scene: params }
    }

    /// The open scene's figures as drawn: with the time cursor's marks when
    /// they are shown.
    fn drawn_figures(&self, out: &SceneOutput) -> Vec<Figure> {
        let mut figures = out.figures.clone();
        if let Some(c) = self.shown_cursor(out) {
            c.apply(&mut figures);
        }
        figures
    }

    /// The open scene's time cursor over `out` when its marks are shown.
    fn shown_cursor(&self, out: &SceneOutput) -> Option<scene::Cursor> {
        self.params().cursor(out).filter(|c| self.marks_shown(c))
    }

    /// Whether a cursor's marks are drawn: always, or once the open scene's
    /// history was played or scrubbed.
    fn marks_shown(&self, cursor: &scene::Cursor) -> bool {
        !cursor.optional || self.timeline_shown.contains(&self.session.index())
    }

    /// Exports every figure of the open scene (PNG, SVG, CSV, as drawn and
    /// carrying its state) to the export folder, all or nothing, rendered on
    /// a thread of its own.
    fn export_all(&mut self) {
        let Some(out) = self.outputs[self.session.index()].clone() else { return };
        let dir = PathBuf::from(&self.session.export_dir);
        if let Err(e) = std::fs::create_dir_all(&dir) {
            self.error = Some(format!("cannot create export folder {}: {e}", dir.display()));
            return;
        }
        let stamp = match crate::provenance::Stamp::of(&self.current_preset()) {
            Ok(s) => s,
            Err(e) => {
                self.error = Some(format!("export failed: {e}"));
                return;
            }
        };
        let figures = self.drawn_figures(&out);
        let prefix = format!("{}-", self.params().info().id);
        let tx = self.dialogs.0.clone();
        self.status = format!("exporting {} figures to {}…", figures.len(), dir.display());
        std::thread::spawn(move || {
            let mut set = crate::files::FileSet::new();
            let result = crate::provenance::stage_figures(&mut set, &figures, &dir, &prefix, Some(&stamp))
                .and_then(|()| Ok(set.commit()?))
                .map_err(|e| format!("{e:#}"));
            let _ = tx.send(Dialog::Written("export", result));
        });
    }

    /// Writes the open scene's played history as frames (and an animated
    /// PNG) into the export folder, on a thread of its own.
    fn export_movie(&mut self) {
        if self.movie_running {
            return;
        }
        let preset = self.current_preset();
        let dir = PathBuf::from(&self.session.export_dir).join(format!("{}-movie", preset.scene.info().id));
        let tx = self.dialogs.0.clone();
        self.movie_running = true;
        self.status = format!("writing the movie to {}…", dir.display());
        std::thread::spawn(move || {
            let result =
                crate::handout::movie(&preset, 48, None, true, 12, &dir, &|| false).map_err(|e| format!("{e:#}"));
            let _ = tx.send(Dialog::Written("movie", result));
        });
    }

    fn spawn_dialog(&self, make: impl FnOnce() -> Dialog + Send + 'static) {
        let tx = self.dialogs.0.clone();
        std::thread::spawn(move || {
            let _ = tx.send(make());
        });
    }

    /// Applies the theme and text sizes: lecture mode is light, high-contrast
    /// and large; otherwise the chosen light or dark theme at normal size.
    fn apply_look(&mut self, ctx: &egui::Context) {
        if !self.fonts_installed {
            self.fonts_installed = true;
            install_fonts(ctx);
        }
        let want = (self.session.lecture, self.session.light);
        if self.look_applied == Some(want) {
            return;
        }
        let lecture_changed = self.look_applied.is_none_or(|(l, _)| l != want.0);
        self.look_applied = Some(want);
        let light = want.0 || want.1;
        ctx.set_theme(if light { egui::Theme::Light } else { egui::Theme::Dark });
        let lecture = want.0;
        ctx.all_styles_mut(|style| {
            use egui::{FontFamily, FontId, TextStyle};
            let sizes = if lecture { [15.0, 19.0, 19.0, 26.0, 17.0] } else { [10.0, 13.0, 13.0, 19.0, 12.5] };
            style.text_styles = [
                (TextStyle::Small, FontId::new(sizes[0], FontFamily::Proportional)),
                (TextStyle::Body, FontId::new(sizes[1], FontFamily::Proportional)),
                (TextStyle::Button, FontId::new(sizes[2], FontFamily::Proportional)),
                (TextStyle::Heading, FontId::new(sizes[3], FontFamily::Proportional)),
                (TextStyle::Monospace, FontId::new(sizes[4], FontFamily::Monospace)),
            ]
            .into();
            style.spacing.interact_size.y = if lecture { 26.0 } else { 18.0 };
        });
        if lecture {
            // High contrast: black text on white, strong strokes.
            ctx.style_mut_of(egui::Theme::Light, |style| {
                style.visuals.override_text_color = Some(egui::Color32::BLACK);
                style.visuals.widgets.noninteractive.fg_stroke.color = egui::Color32::BLACK;
                style.visuals.panel_fill = egui::Color32::WHITE;
                style.visuals.extreme_bg_color = egui::Color32::WHITE;
            });
        } else {
            ctx.style_mut_of(egui::Theme::Light, |style| style.visuals = egui::Visuals::light());
        }
        ctx.set_zoom_factor(1.0);
        if lecture_changed {
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(lecture));
        }
    }

    /// How plots are drawn in the current look.
    fn plot_look(&self, ui: &egui::Ui) -> plot::Look {
        let lecture = self.session.lecture;
        plot::Look {
            line: if lecture { 3.0 } else { 2.0 },
            text: if lecture { 17.0 } else { 12.5 },
            dark: ui.visuals().dark_mode,
            legend: true,
        }
    }

    /// Draws the whole window content into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.poll(&ctx);
        self.apply_look(&ctx);
        self.keys(&ctx);
        self.play(&ctx);
        if self.presenter.is_some() {
            egui::Panel::top("top").show(ui, |ui| self.presenter_bar(ui));
        } else {
            egui::Panel::top("top").show(ui, |ui| self.top_bar(ui));
        }
        if !self.notices.is_empty() {
            egui::Panel::top("notices").show(ui, |ui| self.notices_bar(ui));
        }
        // In lecture mode the status line shows only while something runs
        // or went wrong, so that the plots keep the bottom of the screen.
        if !self.session.lecture || self.worker.busy() || self.error.is_some() {
            egui::Panel::bottom("status").show(ui, |ui| self.status_bar(ui));
        }
        if self.presenter.as_ref().is_some_and(|p| p.notes) {
            let height = (0.27 * ctx.content_rect().height()).max(120.0);
            egui::Panel::bottom("notes").exact_size(height).show(ui, |ui| self.notes_panel(ui));
        }
        if !self.session.lecture {
            egui::Panel::left("controls").resizable(true).default_size(360.0).show(ui, |ui| {
                // The content never asks for more than the panel's width, so
                // the panel changes width only when the user drags its edge
                // (wider content, e.g. while a slider moves, would otherwise
                // widen it a little every frame).
                let width = ui.available_width();
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.set_max_width(width);
                    self.side_panel(ui)
                });
            });
        }
        self.request();
        egui::CentralPanel::default().show(ui, |ui| self.figures(ui));
        if self.session.lecture && self.lecture_params {
            let mut open = true;
            egui::Window::new("Parameters")
                .open(&mut open)
                .anchor(egui::Align2::RIGHT_TOP, [-10.0, 60.0])
                .default_width(420.0)
                .collapsible(true)
                .show(&ctx, |ui| {
                    egui::ScrollArea::vertical().max_height(ctx.content_rect().height() * 0.7).show(ui, |ui| {
                        self.headline(ui);
                        self.controls(ui);
                        ui.separator();
                        self.scalars(ui);
                    });
                });
            self.lecture_params = open;
        }
        self.deck_editor(&ctx);
        self.notes_window(&ctx);
        self.inspection_window(&ctx);
        if self.help {
            self.help_overlay(&ctx);
        }
        self.link_monomer();
        // A whole slider drag is one step of the history.
        if !ctx.input(|i| i.pointer.any_down()) {
            let now = self.params().clone();
            self.history.observe(&self.session.scene, &now);
        }
    }

    /// The keyboard shortcuts (see [`shortcuts::SHORTCUTS`]); none while a
    /// text field has the keyboard.
    fn keys(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let mode = if self.presenter.is_some() { Mode::Presenter } else { Mode::Explorer };
        for action in shortcuts::pressed(ctx, mode) {
            self.act(action);
        }
    }

    /// Does what a shortcut (or its button) asks.
    pub fn act(&mut self, action: Action) {
        match action {
            Action::Help => self.help = !self.help,
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            Action::PlayPause => self.toggle_play(),
            Action::StepForward => self.step_time(1.0),
            Action::StepBack => self.step_time(-1.0),
            Action::Rewind => self.set_time(0.0),
            Action::NextScene => self.step_scene(1),
            Action::PreviousScene => self.step_scene(-1),
            Action::ToggleLecture => self.session.lecture = !self.session.lecture,
            Action::Leave => {
                if self.help {
                    self.help = false;
                } else if self.presenter.is_some() {
                    self.stop_presenting();
                } else {
                    self.session.lecture = false;
                }
            }
            Action::ResetScene => self.reset_scene(),
            Action::Export => self.export_all(),
            Action::NextSlide => self.step_slide(1),
            Action::PreviousSlide => self.step_slide(-1),
            Action::FirstSlide => self.step_slide(isize::MIN / 2),
            Action::LastSlide => self.step_slide(isize::MAX / 2),
            Action::Slide(n) => {
                if self.presenter.as_ref().is_some_and(|p| n < p.deck.deck.slides.len()) {
                    self.go_to_slide(n);
                }
            }
            Action::ToggleNotes => self.toggle_notes(),
            Action::NotesWindow => {
                if let Some(p) = &mut self.presenter {
                    p.notes_window = !p.notes_window;
                }
            }
            Action::ResetSlide => self.reset_slide(),
        }
    }

    /// Whether the open scene's history is playing.
    pub fn playing(&self) -> bool {
        self.playback.playing
    }

    /// The open scene's time cursor (fraction of its history), if it has one.
    pub fn time(&self) -> Option<f64> {
        self.params().clone().cursor_mut().map(|c| *c)
    }

    fn set_time(&mut self, fraction: f64) {
        let i = self.session.index();
        if let Some(c) = self.params_mut().cursor_mut() {
            *c = fraction.clamp(0.0, 1.0);
            self.timeline_shown.insert(i);
        }
    }

    fn toggle_play(&mut self) {
        let i = self.session.index();
        let mut playback = self.playback.clone();
        if let Some(c) = self.params_mut().cursor_mut() {
            playback.toggle(c);
            self.timeline_shown.insert(i);
            self.status = if playback.playing { "playing (Space pauses)".into() } else { "paused".into() };
        } else {
            self.status = "this scene has no history to play".into();
        }
        self.playback = playback;
    }

    fn step_time(&mut self, by: f64) {
        self.playback.playing = false;
        if let Some(t) = self.time() {
            self.set_time(playback::step(t, by));
        }
    }

    /// Advances a playing history by the frame's time.
    fn play(&mut self, ctx: &egui::Context) {
        if !self.playback.playing {
            return;
        }
        let dt = f64::from(ctx.input(|i| i.stable_dt));
        let mut playback = self.playback.clone();
        match self.params_mut().cursor_mut() {
            Some(c) => *c = playback.advance(*c, dt),
            None => playback.playing = false,
        }
        self.playback = playback;
        ctx.request_repaint();
    }

    /// Undoes the last parameter change (opening the scene it was made in).
    pub fn undo(&mut self) {
        let now = self.all_params();
        match self.history.undo(|id| now(id)) {
            Some(step) => self.restore(step, "undone"),
            None => self.status = "nothing to undo".into(),
        }
    }

    /// Redoes the last undone change.
    pub fn redo(&mut self) {
        let now = self.all_params();
        match self.history.redo(|id| now(id)) {
            Some(step) => self.restore(step, "redone"),
            None => self.status = "nothing to redo".into(),
        }
    }

    /// Every scene's parameters now, by scene id (a snapshot, so that the
    /// history can be edited while it is read).
    fn all_params(&self) -> impl Fn(&str) -> SceneParams + use<> {
        let params = self.session.params.clone();
        let defaults = self.defaults.clone();
        move |id: &str| match params.get(id) {
            Some(p) => p.clone(),
            None => defaults.iter().find(|d| d.info().id == id).unwrap_or(&defaults[0]).clone(),
        }
    }

    fn restore(&mut self, step: history::Step, what: &str) {
        let mut last = None;
        for (id, p) in step {
            last = SCENES.iter().position(|s| s.id == id);
            self.session.params.insert(id, p);
        }
        if let Some(i) = last {
            self.open_scene(i);
        }
        let (u, r) = self.history.depth();
        self.status = format!("{what} ({u} more to undo, {r} to redo)");
        self.control_notice = None;
    }

    /// Resets the open scene's parameters to their defaults (one undo step).
    pub fn reset_scene(&mut self) {
        let default = self.defaults[self.session.index()].clone();
        *self.params_mut() = default;
        self.control_notice = None;
        self.status = "scene reset to its defaults (Ctrl+Z undoes)".into();
    }

    /// Resets every scene's parameters to their defaults (one undo step).
    pub fn reset_all(&mut self) {
        let before: history::Step = SCENES
            .iter()
            .enumerate()
            .filter(|(i, s)| self.session.params.get(s.id).is_some_and(|p| p != &self.defaults[*i]))
            .map(|(_, s)| (s.id.to_string(), self.session.params[s.id].clone()))
            .collect();
        let after: history::Step =
            SCENES.iter().zip(&self.defaults).map(|(s, d)| (s.id.to_string(), d.clone())).collect();
        let n = before.len();
        self.history.record(before, &after);
        self.session.params = after.into_iter().collect();
        self.control_notice = None;
        self.status = format!("reset {n} scenes to their defaults (Ctrl+Z undoes)");
    }

    /// The list of keyboard shortcuts, over everything.
    fn help_overlay(&mut self, ctx: &egui::Context) {
        let mut open = true;
        let height = ctx.content_rect().height() * 0.86;
        egui::Window::new("Keyboard shortcuts")
            .open(&mut open)
            .collapsible(false)
            .default_height(height)
            .anchor(egui::Align2::CENTER_CENTER, [0.0, 0.0])
            .show(ctx, |ui| {
                egui::ScrollArea::vertical().max_height(height - 40.0).show(ui, |ui| {
                    // One grid, so that the keys line up across the three lists.
                    egui::Grid::new("shortcuts").num_columns(2).striped(true).show(ui, |ui| {
                        for mode in [Mode::Anywhere, Mode::Explorer, Mode::Presenter] {
                            ui.label(egui::RichText::new(mode.heading()).strong());
                            ui.end_row();
                            for s in shortcuts::SHORTCUTS.iter().filter(|s| s.mode == mode) {
                                let keys = if matches!(s.action, Action::Slide(_)) {
                                    "1 … 9".to_string()
                                } else {
                                    s.keys.iter().map(|k| k.text()).collect::<Vec<_>>().join(", ")
                                };
                                ui.label(egui::RichText::new(keys).monospace());
                                ui.label(s.text);
                                ui.end_row();
                            }
                        }
                    });
                });
            });
        self.help = self.help && open;
    }

    /// Opens the scene `by` places after the open one in navigator order.
    fn step_scene(&mut self, by: isize) {
        let order: Vec<usize> = scene::scenes_by_chapter().into_iter().flat_map(|(_, v)| v).collect();
        let here = order.iter().position(|&i| i == self.session.index()).unwrap_or(0) as isize;
        let n = order.len() as isize;
        let next = order[(here + by).rem_euclid(n) as usize];
        self.open_scene(next);
    }

    /// The scene navigator: previous / next buttons and a list grouped by
    /// thesis chapter with the figures each scene reproduces.
    fn navigator(&mut self, ui: &mut egui::Ui, width: f32) {
        ui.horizontal(|ui| {
            if ui.button("◀").on_hover_text("previous scene (Page Up)").clicked() {
                self.step_scene(-1);
            }
            let here = self.session.index();
            let label = ui.label("Scene");
            let entry = |i: usize| {
                let s = &SCENES[i];
                let figs = scene::figures_of(s);
                if figs.is_empty() { s.title.to_string() } else { format!("{} · {figs}", s.title) }
            };
            let mut chosen = None;
            egui::ComboBox::from_id_salt("scene-navigator")
                .width(width)
                .height(ui.ctx().content_rect().height() * 0.8)
                .selected_text(egui::RichText::new(SCENES[here].title).strong())
                .show_ui(ui, |ui| {
                    for (chapter, list) in scene::scenes_by_chapter() {
                        ui.label(egui::RichText::new(chapter.heading).strong().underline());
                        for i in list {
                            if ui.selectable_label(i == here, entry(i)).clicked() {
                                chosen = Some(i);
                            }
                        }
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(format!("{} — {}", scene::chapter(here).heading, SCENES[here].source));
            if let Some(i) = chosen {
                self.open_scene(i);
            }
            if ui.button("▶").on_hover_text("next scene (Page Down)").clicked() {
                self.step_scene(1);
            }
        });
    }

    /// The shipped presets menu: grouped by chapter, each by its title.
    fn presets_menu(&mut self, ui: &mut egui::Ui) {
        let menu = self.shipped_menu.get_or_insert_with(|| {
            let mut items: Vec<(scene::Chapter, String, &'static str, &'static str)> = crate::preset::SHIPPED
                .iter()
                .map(|(file, text)| match Preset::from_ron(text, file) {
                    Ok(p) => {
                        let i = SCENES.iter().position(|s| s.id == p.scene.info().id).unwrap_or(0);
                        (scene::chapter(i), p.title, *file, *text)
                    }
                    Err(_) => (scene::Chapter { heading: "Other", order: 9 }, file.to_string(), *file, *text),
                })
                .collect();
            items.sort_by(|a, b| a.0.order.cmp(&b.0.order).then(a.0.heading.cmp(b.0.heading)).then(a.1.cmp(&b.1)));
            items
        });
        let mut picked = None;
        let max_h = (ui.ctx().content_rect().height() - 140.0).max(200.0);
        egui::ScrollArea::vertical().max_height(max_h).show(ui, |ui| {
            let mut heading = "";
            for (chapter, title, file, text) in menu.iter() {
                if chapter.heading != heading {
                    heading = chapter.heading;
                    ui.label(egui::RichText::new(heading).strong().underline());
                }
                if ui.button(title.as_str()).on_hover_text(*file).clicked() {
                    picked = Some((*file, *text));
                }
            }
        });
        if let Some((file, text)) = picked {
            match Preset::from_ron(text, file) {
                Ok(p) => self.apply_preset(p, file),
                Err(e) => self.error = Some(e.to_string()),
            }
            ui.close();
        }
    }

    fn top_bar(&mut self, ui: &mut egui::Ui) {
        if self.session.lecture {
            ui.horizontal(|ui| {
                self.navigator(ui, 320.0);
                ui.separator();
                ui.toggle_value(&mut self.lecture_params, "Parameters")
                    .on_hover_text("show the parameters over the plots");
                ui.menu_button("Presets", |ui| self.presets_menu(ui));
                ui.menu_button("Present", |ui| self.decks_menu(ui));
                ui.separator();
                ui.checkbox(&mut self.session.lecture, "Lecture mode").on_hover_text("F5 toggles, Esc leaves");
                if ui.button("?").on_hover_text("keyboard shortcuts (F1)").clicked() {
                    self.help = !self.help;
                }
            });
            // The scene's headline result (e.g. e = 0.657, bounces) stays on
            // screen while the parameters are hidden, with the transport of
            // a history beside it.
            ui.horizontal(|ui| {
                if !self.lecture_params {
                    self.headline(ui);
                }
                self.transport_row(ui);
            });
            return;
        }
        ui.horizontal_wrapped(|ui| {
            ui.heading("grainscope");
            ui.separator();
            if ui.button("Open preset…").clicked() {
                self.spawn_dialog(|| Dialog::Open(rfd::FileDialog::new().add_filter("preset", &["ron"]).pick_file()));
            }
            if ui.button("Save preset…").clicked() {
                self.spawn_dialog(|| {
                    Dialog::Save(
                        rfd::FileDialog::new().add_filter("preset", &["ron"]).set_file_name("preset.ron").save_file(),
                    )
                });
            }
            ui.add(
                egui::TextEdit::singleline(&mut self.session.preset_path).desired_width(220.0).hint_text("preset path"),
            )
            .on_hover_text(
                "path for Load/Save when no file dialog is available; presets can also be dropped on the window",
            );
            if ui.button("Load").clicked() {
                let p = PathBuf::from(&self.session.preset_path);
                self.open_file(&p);
            }
            if ui.button("Save").clicked() {
                let p = PathBuf::from(&self.session.preset_path);
                self.save_preset_file(&p);
            }
            ui.menu_button("Shipped presets", |ui| self.presets_menu(ui));
            ui.separator();
            ui.checkbox(&mut self.session.light, "Light theme");
            ui.checkbox(&mut self.session.lecture, "Lecture mode")
                .on_hover_text("plots fill the screen in a light high-contrast theme (F5 toggles, Esc leaves)");
            ui.separator();
            let (undo, redo) = self.history.depth();
            if ui
                .add_enabled(undo > 0, egui::Button::new("Undo"))
                .on_hover_text("undo the last parameter change (Ctrl+Z)")
                .clicked()
            {
                self.undo();
            }
            if ui.add_enabled(redo > 0, egui::Button::new("Redo")).on_hover_text("redo (Ctrl+Shift+Z)").clicked() {
                self.redo();
            }
            if ui
                .button("Reset all")
                .on_hover_text("every scene's parameters to their defaults (Ctrl+Z undoes)")
                .clicked()
            {
                self.reset_all();
            }
            ui.separator();
            ui.toggle_value(&mut self.deck_editor.open, "Deck")
                .on_hover_text("build a lecture from the window's states");
            ui.menu_button("Present", |ui| self.decks_menu(ui));
            if ui.button("Keys").on_hover_text("keyboard shortcuts (F1)").clicked() {
                self.help = !self.help;
            }
        });
    }

    /// The shipped decks, each presented from its first slide when picked.
    fn decks_menu(&mut self, ui: &mut egui::Ui) {
        let mut picked = None;
        for (file, text) in crate::deck::SHIPPED {
            let title = ron::from_str::<crate::deck::Deck>(text).map_or_else(|_| file.to_string(), |d| d.title);
            if ui.button(title).on_hover_text(file).clicked() {
                picked = Some(file);
            }
        }
        if let Some(file) = picked {
            match crate::deck::resolve(file) {
                Ok(d) => self.present(d, 0),
                Err(e) => self.error = Some(e.to_string()),
            }
            ui.close();
        }
    }

    fn notices_bar(&mut self, ui: &mut egui::Ui) {
        let mut dismissed = None;
        for (i, notice) in self.notices.iter().enumerate() {
            ui.horizontal(|ui| {
                if ui.button("Dismiss").clicked() {
                    dismissed = Some(i);
                }
                ui.add(egui::Label::new(egui::RichText::new(notice).color(ui.visuals().warn_fg_color)).wrap());
            });
        }
        if let Some(i) = dismissed {
            self.notices.remove(i);
        }
    }

    fn status_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            if self.worker.busy() {
                ui.add(egui::ProgressBar::new(self.worker.progress() as f32).desired_width(160.0).show_percentage());
                if self.live_scene.is_some_and(|i| self.params_of(i).pausable()) {
                    let paused = self.worker.paused();
                    if ui.button(if paused { "Resume" } else { "Pause" }).clicked() {
                        self.worker.set_paused(!paused);
                        self.status = if paused { "resumed".into() } else { "paused; Resume continues the run".into() };
                    }
                }
                if ui.button("Cancel").clicked() {
                    self.worker.cancel();
                    self.stale = false;
                    self.requested[self.session.index()] = None;
                    self.status = "cancelled; showing the last good result".into();
                }
            }
            // Long messages wrap instead of running off the window's edge.
            if let Some(e) = &self.error {
                ui.add(egui::Label::new(egui::RichText::new(e).color(egui::Color32::from_rgb(200, 40, 40))).wrap());
            } else {
                ui.add(egui::Label::new(&self.status).wrap());
            }
        });
    }

    fn side_panel(&mut self, ui: &mut egui::Ui) {
        self.navigator(ui, 230.0);
        let info = self.params().info();
        ui.small(format!("{} · {}", scene::chapter(self.session.index()).heading, info.source));
        self.headline(ui);
        ui.separator();
        ui.label(egui::RichText::new("Parameters").strong());
        self.controls(ui);
        ui.separator();
        egui::CollapsingHeader::new("What this scene shows").default_open(false).show(ui, |ui| {
            ui.label(info.explanation);
            ui.small(format!("Thesis: {}", info.source));
        });
        self.scalars(ui);
        ui.separator();
        self.compare(ui);
    }

    fn headline(&self, ui: &mut egui::Ui) {
        let Some(out) = self.output() else { return };
        let text = match (out.scalar("e"), out.scalar("sticks"), out.scalar("v_stick")) {
            (Some(e), Some(s), _) => format!("e = {e:.4} ({})", if s > 0.5 { "sticks" } else { "bounces" }),
            // The search ends at 10⁴ m/s: above it the spheres stick at every speed tried.
            (_, _, Some(v)) if v.is_infinite() => "v_stick > 10⁴ m/s".to_string(),
            (_, _, Some(v)) => format!("v_stick = {} m/s", figure::tick_label(v)),
            // A short first note serves as the headline; a paragraph stays
            // among the notes below the parameters instead of pushing them
            // down.
            _ => out.notes.first().filter(|n| n.chars().count() <= 60).cloned().unwrap_or_default(),
        };
        if text.is_empty() {
            return;
        }
        ui.label(egui::RichText::new(text).size(20.0).strong());
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        if self.params().monomer_card().is_some() {
            self.monomer_card(ui);
        }
        self.controls_of(ui, Select::Parameters);
    }

    /// The open scene's controls: all but the monomer card's, the card's, or
    /// only those of a slide (its highlighted parameters, side by side).
    fn controls_of(&mut self, ui: &mut egui::Ui, select: Select<'_>) {
        let only = match select {
            Select::Slide(keys) => Some(keys),
            _ => None,
        };
        let card_keys = self.params().monomer_card().map(|_| monomer_card::shown_keys(self.params()));
        let shown = |key: &str| match select {
            Select::Slide(keys) => keys.iter().any(|k| k == key),
            Select::Card => card_keys.as_ref().is_some_and(|k| k.contains(&key)),
            Select::Parameters => !monomer_card::is_card_key(key) || card_keys.is_none(),
        };
        let mut material_changed = false;
        let data_path = &mut self.session.data_path;
        let mut load_typed = false;
        if let Some(data) = self
            .session
            .params
            .get_mut(&self.session.scene)
            .and_then(|p| p.measurements())
            .filter(|_| matches!(select, Select::Parameters))
        {
            let n = data.len();
            ui.horizontal(|ui| {
                ui.label(if n == 0 {
                    "data: synthetic example".to_string()
                } else {
                    format!("data: {n} measurements")
                });
                if n > 0 && ui.button("Clear data").clicked() {
                    data.clear();
                }
            });
            let mut import = false;
            ui.horizontal(|ui| {
                import = ui
                    .button("Import data…")
                    .on_hover_text(
                        "CSV: 'velocity [m/s]', 'restitution', optional 'uncertainty'; or drop a .csv on the window",
                    )
                    .clicked();
                let label = ui.label("or path");
                ui.text_edit_singleline(data_path).labelled_by(label.id);
                load_typed = ui.button("Load data").clicked();
            });
            if import {
                self.spawn_dialog(|| {
                    Dialog::ImportData(rfd::FileDialog::new().add_filter("measurements", &["csv"]).pick_file())
                });
            }
        }
        if load_typed {
            let path = PathBuf::from(&self.session.data_path);
            self.import_data(&path);
        }
        // A refused typed value: shown under its control until the control
        // takes a valid value (or another is refused).
        let shown_notice = self.control_notice.clone();
        let mut refused: Option<(String, String)> = None;
        let mut accepted: Option<String> = None;
        {
            let params = self.params_mut();
            let mut controls = params.controls();
            egui::Grid::new(("controls", select.id())).num_columns(1).striped(false).show(ui, |ui| {
                // A slide's few highlighted controls sit side by side in one row.
                let in_row = only.is_some();
                for c in controls.iter_mut().filter(|c| shown(c.key)) {
                    let (key, label, unit, doc) = (c.key, c.label, c.unit, c.doc);
                    match &mut c.kind {
                        ControlKind::Number { value, min, max, log, display_scale } => {
                            let mut shown = **value * *display_scale;
                            let (lo, hi) = (*min * *display_scale, *max * *display_scale);
                            let is_log = *log;
                            let suffix = if unit.is_empty() { String::new() } else { format!(" {unit}") };
                            let current = shown;
                            let slider = egui::Slider::new(&mut shown, lo..=hi).logarithmic(is_log).suffix(suffix);
                            let (changed, typed) = typed_slider(ui, slider, current, label, doc, |v| field_text(v, is_log));
                            let unit_text = if unit.is_empty() { String::new() } else { format!(" {unit}") };
                            // The range is checked in SI units, with a rounding allowance
                            // for the conversion to display units.
                            let si = shown / *display_scale;
                            let slack = 1e-12 * min.abs().max(max.abs());
                            if changed && si.is_finite() && si >= *min - slack && si <= *max + slack {
                                **value = si.clamp(*min, *max);
                                accepted = Some(key.to_string());
                            } else if changed || (typed.is_some() && parse_number(typed.as_deref().unwrap_or("")).is_none()) {
                                let text = typed.unwrap_or_else(|| shown.to_string());
                                let why = if parse_number(&text).is_some() {
                                    "is outside the valid range"
                                } else {
                                    "is not a number; valid range"
                                };
                                refused = Some((
                                    key.to_string(),
                                    format!(
                                        "{label}: {text}{unit_text} {why} {} … {}{unit_text}; kept {}{unit_text}",
                                        figure::tick_label(lo),
                                        figure::tick_label(hi),
                                        figure::tick_label(**value * *display_scale),
                                    ),
                                ));
                            }
                        }
                        ControlKind::Count { value, min, max } => {
                            let mut shown = **value as f64;
                            let current = shown;
                            let slider = egui::Slider::new(&mut shown, *min as f64..=*max as f64).integer();
                            let (changed, typed) = typed_slider(ui, slider, current, label, doc, |v| format!("{v:.0}"));
                            // The widget rounds to whole numbers; what was typed decides.
                            let typed_whole = typed.as_deref().and_then(parse_number).is_none_or(|v| v.fract() == 0.0);
                            let whole = shown.is_finite() && shown.fract() == 0.0 && typed_whole;
                            if changed && whole && shown >= *min as f64 && shown <= *max as f64 {
                                **value = shown as usize;
                                accepted = Some(key.to_string());
                            } else if changed || typed.as_deref().is_some_and(|t| parse_number(t).is_none() || !typed_whole) {
                                let text = typed.unwrap_or_else(|| shown.to_string());
                                refused = Some((
                                    key.to_string(),
                                    format!(
                                        "{label}: {text} is not a whole number in the valid range {min} … {max}; kept {}",
                                        **value
                                    ),
                                ));
                            }
                        }
                        ControlKind::Toggle(v) => {
                            ui.checkbox(v, label).on_hover_text(doc);
                        }
                        ControlKind::Material(m) => {
                            egui::ComboBox::from_label(label).selected_text(m.name.clone()).show_ui(ui, |ui| {
                                for candidate in crate::physics::material::materials() {
                                    if ui.selectable_label(m.name == candidate.name, &candidate.name).clicked() {
                                        **m = candidate.clone();
                                        material_changed = true;
                                    }
                                }
                            });
                        }
                        ControlKind::Choice { value, options } => {
                            let shown = options.iter().find(|(k, _)| *k == value.as_str()).map_or("?", |(_, l)| *l);
                            egui::ComboBox::from_label(label).selected_text(shown).show_ui(ui, |ui| {
                                for (k, l) in options.iter() {
                                    if ui.selectable_label(value.as_str() == *k, *l).clicked() {
                                        **value = k.to_string();
                                    }
                                }
                            });
                        }
                    }
                    if !in_row {
                        ui.end_row();
                    }
                    if let Some((k, message)) = &shown_notice
                        && k == key
                        && accepted.as_deref() != Some(key)
                    {
                        ui.add(egui::Label::new(egui::RichText::new(message).color(ui.visuals().warn_fg_color)).wrap());
                        ui.end_row();
                    }
                }
            });
        }
        if let Some(notice) = refused {
            self.control_notice = Some(notice);
        } else if accepted.is_some_and(|k| self.control_notice.as_ref().is_some_and(|(n, _)| *n == k)) {
            self.control_notice = None;
        }
        if material_changed {
            self.params_mut().material_changed();
        }
        if matches!(select, Select::Parameters)
            && ui.button("Reset to defaults").on_hover_text("this scene's parameters (Ctrl+R)").clicked()
        {
            self.reset_scene();
        }
    }

    fn scalars(&self, ui: &mut egui::Ui) {
        let Some(out) = self.output() else {
            ui.label("computing…");
            return;
        };
        egui::Grid::new("scalars").num_columns(2).striped(true).show(ui, |ui| {
            for s in &out.scalars {
                ui.label(s.label);
                ui.label(format!("{} {}", figure::tick_label(s.value), s.unit));
                ui.end_row();
            }
        });
        for n in &out.notes {
            ui.label(egui::RichText::new(n).italics());
        }
    }

    fn compare(&mut self, ui: &mut egui::Ui) {
        ui.label(egui::RichText::new("Compare").strong());
        ui.horizontal(|ui| {
            if ui
                .button("Pin curves")
                .on_hover_text("keep the current model curves while you change parameters")
                .clicked()
            {
                self.pin_current();
            }
            if ui.button("Clear pins").clicked() {
                let id = self.params().info().id;
                self.session.pins.retain(|p| p.params.info().id != id);
            }
        });
        let mut params = self.params().clone();
        let keys: Vec<(&'static str, &'static str)> = params
            .controls()
            .iter()
            .filter(|c| matches!(c.kind, ControlKind::Number { .. }) && !c.style_only)
            .map(|c| (c.key, c.label))
            .collect();
        ui.horizontal(|ui| {
            let current = keys.iter().find(|k| k.0 == self.sweep.key).map_or("choose", |k| k.1);
            egui::ComboBox::from_label("sweep parameter").selected_text(current).show_ui(ui, |ui| {
                for (k, l) in &keys {
                    ui.selectable_value(&mut self.sweep.key, k.to_string(), *l);
                }
            });
        });
        ui.horizontal(|ui| {
            ui.add(egui::DragValue::new(&mut self.sweep.from).speed(0.01).prefix("from "));
            ui.add(egui::DragValue::new(&mut self.sweep.to).speed(0.01).prefix("to "));
            ui.add(egui::DragValue::new(&mut self.sweep.steps).range(2..=12).prefix("n "));
        });
        ui.small("sweep values are in SI units, log-spaced when both ends are positive");
        if ui.button("Draw family").clicked() {
            self.start_sweep();
        }
    }

    fn pin_current(&mut self) {
        let Some(out) = self.output() else { return };
        let curves: Vec<(String, Series)> = out
            .figures
            .iter()
            .flat_map(|f| f.series.iter().filter(|s| s.style == Style::Line).map(move |s| (f.id.clone(), s.clone())))
            .collect();
        let color = self.session.pins.len() + 1;
        let params = self.params().clone();
        self.session.pins.push(Pin { params, label: String::new(), curves, color });
    }

    fn start_sweep(&mut self) {
        let base = self.params().clone();
        let (from, to, n) = (self.sweep.from, self.sweep.to, self.sweep.steps.clamp(2, 12));
        let values: Vec<f64> = if from > 0.0 && to > 0.0 {
            scene::logspace(from, to, n)
        } else {
            (0..n).map(|i| from + (to - from) * i as f64 / (n - 1) as f64).collect()
        };
        // Check every value before starting, so a bad range is reported at once.
        for v in &values {
            let mut trial = base.clone();
            if let Err(e) = trial.set(&self.sweep.key, &v.to_string()) {
                self.error = Some(format!("sweep not started: {e}"));
                return;
            }
        }
        let key = self.sweep.key.clone();
        let first_color = self.session.pins.len() + 1;
        self.stale = true;
        self.live_scene = None;
        self.worker.submit(move |progress| {
            let mut pins = Vec::new();
            for (j, v) in values.iter().enumerate() {
                progress.check()?;
                progress.set(j as f64 / values.len() as f64);
                let mut p = base.clone();
                p.set(&key, &v.to_string())?;
                let out = scene::compute(&p, &scene::Progress::default())?;
                let curves: Vec<(String, Series)> = out
                    .figures
                    .iter()
                    .flat_map(|f| {
                        f.series.iter().filter(|s| s.style == Style::Line).map(move |s| (f.id.clone(), s.clone()))
                    })
                    .collect();
                let curves = curves.into_iter().map(|(id, s): (String, Series)| (id, s.at(*v))).collect();
                pins.push(Pin {
                    params: p,
                    label: format!("{key} = {}", figure::tick_label(*v)),
                    curves,
                    color: first_color + j,
                });
            }
            Ok(Job::Sweep(pins))
        });
        // The scene itself must be recomputed when the sweep is done.
        self.requested[self.session.index()] = None;
    }

    fn overlay_for(&self, fig: &Figure, cursor: Vec<scene::Mark>) -> plot::Overlay {
        let current = self.params();
        let pinned: Vec<Series> = self
            .session
            .pins
            .iter()
            .filter(|p| p.params.info().id == current.info().id)
            .flat_map(|pin| {
                let label = if pin.label.is_empty() {
                    let d = pin.params.differences(current);
                    if d.is_empty() {
                        "pinned (same parameters)".to_string()
                    } else {
                        format!("pinned: {}", d.join(", "))
                    }
                } else {
                    pin.label.clone()
                };
                pin.curves.iter().filter(|(id, _)| *id == fig.id).map(move |(_, s)| {
                    let name = if s.name.is_empty() { label.clone() } else { format!("{label} — {}", s.name) };
                    let mut pinned = Series::new(name, s.points.clone(), Style::Dashed, pin.color);
                    pinned.family = s.family;
                    pinned
                })
            })
            .collect();
        // A sweep's pins form a family coloured by the swept value.
        let family = self
            .session
            .pins
            .iter()
            .find(|p| p.params.info().id == current.info().id && p.curves.iter().any(|(_, s)| s.family.is_some()))
            .and_then(|p| {
                let key = p.label.split(" = ").next()?.to_string();
                let mut params = current.clone();
                let controls = params.controls();
                let c = controls.iter().find(|c| c.key == key)?;
                let values: Vec<f64> = pinned.iter().filter_map(|s| s.family).collect();
                let positive = values.iter().all(|&v| v > 0.0);
                let scale = if positive { figure::Scale::Log } else { figure::Scale::Linear };
                Some(figure::Family { label: c.label.to_string(), unit: c.si_unit.to_string(), scale })
            });
        plot::Overlay { pinned, family, cursor }
    }

    /// The transport, when the open scene's result is a history.
    fn transport_row(&mut self, ui: &mut egui::Ui) {
        let Some(out) = self.outputs[self.session.index()].clone() else { return };
        if let Some(c) = self.params().cursor(&out) {
            self.transport(ui, &c.label);
        }
    }

    /// The transport of a scene whose result is a history: rewind, step,
    /// play/pause, a scrubber, the time, the speed, loop and (outside the
    /// lecture look) the movie export.
    fn transport(&mut self, ui: &mut egui::Ui, label: &str) {
        let Some(mut t) = self.time() else { return };
        let before = t;
        let lecture = self.session.lecture;
        ui.horizontal_wrapped(|ui| {
            if ui.button("|◀").on_hover_text("to the start (Home)").clicked() {
                self.playback.playing = false;
                t = 0.0;
            }
            if ui.button("◀").on_hover_text("step back (,)").clicked() {
                self.playback.playing = false;
                t = playback::step(t, -1.0);
            }
            let play = if self.playback.playing { "❚❚ Pause" } else { "▶ Play" };
            let keys = if self.presenter.is_some() { "play or pause (P)" } else { "play or pause (Space, P)" };
            if ui.button(play).on_hover_text(keys).clicked() {
                self.toggle_play();
                t = self.time().unwrap_or(t);
            }
            if ui.button("▶|").on_hover_text("step forward (.)").clicked() {
                self.playback.playing = false;
                t = playback::step(t, 1.0);
            }
            let width = if lecture { 200.0 } else { 160.0 };
            ui.spacing_mut().slider_width = width;
            let scrub = ui
                .add(egui::Slider::new(&mut t, 0.0..=1.0).show_value(false))
                .on_hover_text("scrub through the history");
            if scrub.dragged() {
                self.playback.playing = false;
            }
            scrub.labelled_by(ui.label(egui::RichText::new(label).monospace()).id);
            let speed_text = |v: f64| match v {
                0.25 => "¼×".to_string(),
                0.5 => "½×".to_string(),
                v => format!("{v}×"),
            };
            egui::ComboBox::from_label("speed").selected_text(speed_text(self.playback.speed)).width(60.0).show_ui(
                ui,
                |ui| {
                    for v in playback::SPEEDS {
                        ui.selectable_value(&mut self.playback.speed, v, speed_text(v));
                    }
                },
            );
            ui.checkbox(&mut self.playback.looping, "loop");
            if !lecture {
                let busy = self.movie_running;
                if ui
                    .add_enabled(!busy, egui::Button::new(if busy { "Writing movie…" } else { "Movie" }))
                    .on_hover_text("write 48 frames of the history (PNG) and an animated PNG into the export folder")
                    .clicked()
                {
                    self.export_movie();
                }
            }
        });
        if t != before {
            self.set_time(t);
        }
    }

    /// The "Lock axes" switch: keeps every plot's range while parameters change.
    fn lock_axes(&mut self, ui: &mut egui::Ui, figures: &[Figure]) {
        let mut lock = self.locked.is_some();
        if ui
            .checkbox(&mut lock, "Lock axes")
            .on_hover_text("keep every plot's range while parameters change (double-click a plot to reset a zoom)")
            .changed()
        {
            self.locked = lock.then(|| figures.iter().map(|f| (f.id.clone(), View::of(f))).collect());
        }
    }

    /// The figures, with a scene's ladder of linked numbers beside them.
    fn figures(&mut self, ui: &mut egui::Ui) {
        let ladder = match self.outputs[self.session.index()].as_deref().map(|o| &o.extra) {
            Some(Extra::Ladder(rungs)) => Some(Arc::clone(rungs)),
            _ => None,
        };
        let Some(rungs) = ladder else {
            self.figure_panels(ui);
            return;
        };
        let avail = ui.available_size();
        let width = (0.3 * avail.x).clamp(250.0, 440.0);
        let text = if self.session.lecture { 16.0 } else { 13.0 };
        ui.horizontal_top(|ui| {
            ui.allocate_ui_with_layout(egui::vec2(width, avail.y), egui::Layout::top_down(egui::Align::Min), |ui| {
                ui.set_width(width);
                egui::ScrollArea::vertical().id_salt("ladder").show(ui, |ui| ladder_panel(ui, &rungs, text));
            });
            ui.vertical(|ui| self.figure_panels(ui));
        });
    }

    fn figure_panels(&mut self, ui: &mut egui::Ui) {
        let Some(out) = self.outputs[self.session.index()].clone() else {
            ui.centered_and_justified(|ui| ui.spinner());
            return;
        };
        for warning in &out.warnings {
            let text = egui::RichText::new(format!("Warning: {warning}")).color(ui.visuals().warn_fg_color).strong();
            ui.add(egui::Label::new(text).wrap());
        }
        let lecture = self.session.lecture;
        if !lecture {
            ui.horizontal_wrapped(|ui| {
                self.lock_axes(ui, &out.figures);
                ui.separator();
                self.transport_row(ui);
            });
        }
        let full_cursor = self.params().cursor(&out);
        let trajectory = match &out.extra {
            Extra::Collision(t) => Some(Arc::clone(t)),
            Extra::Paths(_) | Extra::Model(_) | Extra::Ladder(_) | Extra::None => None,
        };
        let n_panels = out.figures.len() + usize::from(trajectory.is_some());
        // A slide may enlarge one figure: it leads across the full width,
        // the others share one row below it.
        let enlarged = self
            .presenter
            .as_ref()
            .and_then(|p| p.slide().enlarge.clone())
            .and_then(|id| out.figures.iter().position(|f| f.id == id));
        // Many panels (a grid of experiments) are small multiples: each keeps
        // a legible size, as many columns as fit, and the grid scrolls; the
        // first figure leads above them at twice the width.
        let multiples = n_panels > 6 && enlarged.is_none();
        let avail = ui.available_size();
        let (min_w, min_h) = if multiples { (if lecture { 300.0 } else { 250.0 }, 210.0) } else { (200.0, 160.0) };
        let cols = match n_panels {
            _ if multiples => ((avail.x / (min_w + 12.0)) as usize).clamp(1, 4),
            1 => 1,
            2..=4 => 2,
            _ => 3,
        };
        // A narrow area (beside a ladder, a small window) takes fewer columns.
        let cols = cols.min(((avail.x + 12.0) / (min_w + 12.0)).max(1.0) as usize);
        let rows = n_panels.div_ceil(cols);
        let size = egui::vec2(
            (avail.x / cols as f32 - 12.0).max(min_w),
            (avail.y / rows as f32 - if lecture { 8.0 } else { 40.0 }).max(min_h),
        );
        let lead_size = egui::vec2((2.0 * size.x + 12.0).min(avail.x - 12.0), 1.3 * size.y);
        let cursor_fraction = full_cursor.as_ref().map_or(0.0, |c| c.fraction);
        let cursor = full_cursor.filter(|c| self.marks_shown(c));
        let mut export: Option<(Figure, &'static str)> = None;
        self.plot_rects.clear();
        self.plot_frames.clear();
        let look = self.plot_look(ui);
        if let Some(locked) = &mut self.locked {
            // Figures first seen while locked are locked at their first view.
            for fig in &out.figures {
                locked.entry(fig.id.clone()).or_insert_with(|| View::of(fig));
            }
        }
        let mut save_as: Option<Figure> = None;
        // Edited beside the contact sketch while the panels borrow `self`.
        let mut export_dir = std::mem::take(&mut self.session.export_dir);
        let mut legends_shown: Vec<Vec<(String, figure::Style, [u8; 3])>> = Vec::new();
        // A click on a plot, to inspect: (figure id, point in axis units).
        let mut clicked: Option<(String, [f64; 2], egui::Pos2)> = None;
        let scroll = egui::ScrollArea::new([multiples, multiples])
            .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
            .max_height(if multiples { avail.y - if lecture { 0.0 } else { 32.0 } } else { f32::INFINITY });
        scroll.show(ui, |ui| {
            // One panel: the plot with its legend, and its export buttons.
            let mut panel = |ui: &mut egui::Ui, fig: &Figure, size: egui::Vec2| {
                let mut marks: Vec<scene::Mark> =
                    cursor.as_ref().map(|c| c.marks_on(&fig.id).cloned().collect()).unwrap_or_default();
                marks.extend(self.inspected_mark(&fig.id));
                let overlay = self.overlay_for(fig, marks);
                let locked = self.locked.as_ref().and_then(|l| l.get(&fig.id).copied());
                let mut look = look;
                // A legend that repeats an earlier panel's (same entries,
                // styles and colours) is drawn once.
                if overlay.pinned.is_empty() {
                    let signature = plot::legend_signature(fig);
                    look.legend = !legends_shown.contains(&signature);
                    legends_shown.push(signature);
                }
                // Beside an enlarged figure the small plots keep their
                // height: no legend (hovering still names each curve).
                if enlarged.is_some_and(|k| out.figures.get(k).is_some_and(|f| f.id != fig.id)) {
                    look.legend = false;
                }
                ui.vertical(|ui| {
                    let shown = plot::show(ui, fig, &overlay, size, self.stale, look, locked);
                    self.plot_rects.push(shown.response.rect);
                    self.plot_frames.push((fig.id.clone(), shown.frame));
                    if let Some((at, pos)) = shown.clicked {
                        clicked = Some((fig.id.clone(), at, pos));
                    }
                    if lecture {
                        return;
                    }
                    ui.horizontal(|ui| {
                        for ext in ["png", "svg", "csv"] {
                            if ui
                                .small_button(ext.to_uppercase())
                                .on_hover_text("save into the export folder")
                                .clicked()
                            {
                                export = Some((fig.clone(), ext));
                            }
                        }
                        if ui.small_button("Save as…").clicked() {
                            save_as = Some(fig.clone());
                        }
                    });
                });
            };
            // One item: a figure, or (None) the contact sketch.
            let mut draw = |ui: &mut egui::Ui, item: Option<&Figure>, size: egui::Vec2| match (item, &trajectory) {
                (Some(fig), _) => panel(ui, fig, size),
                (None, Some(t)) => {
                    ui.vertical(|ui| {
                        ui.label(egui::RichText::new("Contact sketch").strong());
                        sketch::show(ui, t, cursor_fraction, size);
                        if lecture {
                            return;
                        }
                        ui.small("play the collision or move its time above the plots");
                        ui.horizontal(|ui| {
                            let label = ui.label("export folder");
                            ui.text_edit_singleline(&mut export_dir).labelled_by(label.id);
                        });
                    });
                }
                (None, None) => {}
            };
            let lead = if multiples { Some(0) } else { enlarged };
            let items: Vec<Option<&Figure>> = out
                .figures
                .iter()
                .enumerate()
                .filter(|(k, _)| Some(*k) != lead)
                .map(|(_, f)| Some(f))
                .chain(trajectory.as_ref().map(|_| None))
                .collect();
            if let Some(k) = enlarged {
                // The enlarged figure fills most of the width; the others
                // stack beside it.
                let side_w = if items.is_empty() { 0.0 } else { (0.34 * avail.x).max(220.0) };
                let lead_size = egui::vec2(avail.x - side_w - 16.0, avail.y - 8.0);
                let each = egui::vec2(side_w - 8.0, ((avail.y - 8.0) / items.len().max(1) as f32 - 10.0).max(140.0));
                ui.horizontal_top(|ui| {
                    draw(ui, out.figures.get(k), lead_size);
                    ui.vertical(|ui| {
                        for item in &items {
                            draw(ui, *item, each);
                        }
                    });
                });
                return;
            }
            if let Some(fig) = lead.and_then(|k| out.figures.get(k)) {
                draw(ui, Some(fig), lead_size);
            }
            // Row by row; a last row with fewer panels shares the full width
            // (no empty quadrant), except among small multiples.
            for row in items.chunks(cols) {
                let size = if row.len() < cols && !multiples {
                    let spacing = ui.spacing().item_spacing.x;
                    egui::vec2((avail.x - spacing * row.len() as f32) / row.len() as f32 - 4.0, size.y)
                } else {
                    size
                };
                ui.horizontal_top(|ui| {
                    for item in row {
                        draw(ui, *item, size);
                    }
                });
            }
        });
        self.session.export_dir = export_dir;
        if let Some((figure, at, pos)) = clicked {
            self.inspect_at(&out, &figure, at, pos);
        }
        if trajectory.is_none() && !lecture {
            ui.horizontal(|ui| {
                let label = ui.label("export folder");
                ui.text_edit_singleline(&mut self.session.export_dir).labelled_by(label.id);
            });
        }
        // Files show what the window shows, the time cursor included.
        let drawn = |fig: Figure| self.drawn_figures(&out).into_iter().find(|f| f.id == fig.id).unwrap_or(fig);
        let export = export.map(|(fig, ext)| (drawn(fig), ext));
        let save_as = save_as.map(drawn);
        if let Some((fig, ext)) = export {
            let dir = PathBuf::from(&self.session.export_dir);
            if let Err(e) = std::fs::create_dir_all(&dir) {
                self.error = Some(format!("cannot create export folder {}: {e}", dir.display()));
            } else {
                let name = format!("{}-{}.{ext}", self.params().info().id, fig.id);
                self.export(&fig, &dir.join(name));
            }
        }
        if let Some(fig) = save_as {
            let name = format!("{}-{}.png", self.params().info().id, fig.id);
            self.spawn_dialog(move || {
                let path = rfd::FileDialog::new()
                    .add_filter("PNG, SVG or CSV", &["png", "svg", "csv"])
                    .set_file_name(name)
                    .save_file();
                Dialog::Export(path, Box::new(fig))
            });
        }
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

/// The rungs of a ladder, smallest scale on top, an arrow between them.
fn ladder_panel(ui: &mut egui::Ui, rungs: &[scene::Rung], text: f32) {
    for (k, rung) in rungs.iter().enumerate() {
        if k > 0 {
            ui.vertical_centered(|ui| ui.label(egui::RichText::new("↓").size(text)));
        }
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(egui::RichText::new(&rung.scale).strong().size(text + 1.0));
            egui::Grid::new(("rung", k)).num_columns(2).spacing([8.0, 1.0]).show(ui, |ui| {
                for (quantity, value, source) in &rung.items {
                    ui.label(egui::RichText::new(quantity).size(text)).on_hover_text(source);
                    ui.label(egui::RichText::new(value).size(text).strong()).on_hover_text(source);
                    ui.end_row();
                }
            });
        });
    }
}

/// Adds `slider` with its value field made for typing: typed text is taken
/// only on Enter (or leaving the field) and not clamped, so the caller can
/// refuse an out-of-range value with a notice; the field's own text of
/// `current`, left unedited, keeps the exact value (`text_of` formats the
/// field). Returns whether the value changed and the text typed, if any.
fn typed_slider(
    ui: &mut egui::Ui,
    slider: egui::Slider<'_>,
    current: f64,
    label: &str,
    doc: &str,
    text_of: impl Fn(f64) -> String + Copy,
) -> (bool, Option<String>) {
    let typed = std::cell::RefCell::new(None::<String>);
    let changed = {
        let slider = slider
            .text(label)
            .clamping(egui::SliderClamping::Never)
            .update_while_editing(false)
            .custom_formatter(move |v, _| text_of(v))
            .custom_parser(|text| {
                if text.trim() == text_of(current) {
                    // Left as shown: no change from the field's rounding.
                    return Some(current);
                }
                *typed.borrow_mut() = Some(text.trim().to_string());
                parse_number(text)
            });
        ui.add(slider).on_hover_text(doc).changed()
    };
    (changed, typed.into_inner())
}

/// The text of a value field: powers of ten on logarithmic sliders, four
/// significant digits on linear ones.
fn field_text(v: f64, log: bool) -> String {
    let a = v.abs();
    if log {
        figure::tick_label(v)
    } else if v == 0.0 || !v.is_finite() {
        format!("{v}")
    } else if (1e-3..1e5).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
    } else {
        format!("{v:.3e}").replace(".000e", "e")
    }
}

/// Reads a number as typed into a value field (spaces ignored, "−" as minus).
fn parse_number(text: &str) -> Option<f64> {
    let cleaned: String = text.chars().filter(|c| !c.is_whitespace()).map(|c| if c == '−' { '-' } else { c }).collect();
    cleaned.parse().ok()
}

/// Makes the bundled DejaVu Sans the first proportional font (egui's own
/// fonts stay as fallbacks), so every figure label has its glyphs: powers of
/// ten, arrows, Greek letters, subscripts.
fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert("dejavu-sans".into(), Arc::new(egui::FontData::from_static(figure::FONT_TTF)));
    fonts.families.entry(egui::FontFamily::Proportional).or_default().insert(0, "dejavu-sans".into());
    fonts.families.entry(egui::FontFamily::Monospace).or_default().push("dejavu-sans".into());
    ctx.set_fonts(fonts);
}

/// Computes the coarse parameters `c` of a heavy scene and offers the result
/// for display, unless the full result came first or the job was cancelled.
fn preview(c: &scene::SceneParams, progress: &scene::Progress, finished: &std::sync::atomic::AtomicBool) {
    // On a thread pool of its own: in the global pool the preview's parallel
    // work would queue behind the full run's (seconds-long Monte Carlo runs).
    let compute = || scene::compute(c, &progress.quiet_child());
    let result = match rayon::ThreadPoolBuilder::new().num_threads(1).build() {
        Ok(pool) => pool.install(compute),
        Err(_) => compute(),
    };
    if let Ok(mut out) = result {
        if finished.load(std::sync::atomic::Ordering::Relaxed) || progress.cancelled() {
            return;
        }
        out.notes.insert(0, "preview at low resolution; the full result follows".into());
        // Only while nothing newer was offered (a live view of the full run).
        if progress.partial().is_none() {
            progress.publish(out);
        }
    }
}
