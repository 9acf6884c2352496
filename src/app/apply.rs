//! The one place where commands change the state. What a command needs of
//! the world (a file read or written, a dialog, a job) comes back as
//! [`Effect`]s for the window to carry out.

use super::command::{Action, Command, Field};
use super::history;
use super::jobs::Job;
use super::opening::{self, Opened};
use super::platform::{FileKind, Picked};
use super::playback;
use super::state::{AppState, Effect, Inspected, Then};
use crate::figure::{self, View};
use crate::preset::Preset;
use crate::scene::{self, SCENES, SceneParams};
use crate::session::Pin;
use std::path::Path;

impl AppState {
    /// Applies `command`; returns what it asks of the platform and runner.
    pub fn apply(&mut self, command: Command) -> Vec<Effect> {
        let mut fx = Vec::new();
        match command {
            Command::Act(action) => self.act(action, &mut fx),
            Command::OpenScene(i) => self.open_scene(i),
            Command::SetParams(p) => {
                if p.info().id == self.params().info().id {
                    *self.params_mut() = *p;
                }
            }
            Command::Refuse { key, message } => self.control_notice = Some((key, message)),
            Command::Accept(key) => {
                if self.control_notice.as_ref().is_some_and(|(k, _)| *k == key) {
                    self.control_notice = None;
                }
            }
            Command::OpenParams(params, why) => {
                let id = params.info().id;
                self.session.params.insert(id.to_string(), *params);
                if let Some(i) = SCENES.iter().position(|s| s.id == id) {
                    self.open_scene(i);
                }
                self.inspected = None;
                self.status = why;
            }
            Command::ApplyPreset(p, origin) => self.apply_preset(*p, &origin),
            Command::Present(deck, at) => self.present(*deck, at),
            Command::GoToSlide(i) => self.go_to_slide(i),
            Command::StopPresenting => self.stop_presenting(),
            Command::OpenBytes(picked) => self.open_bytes(picked, Then::Open),
            Command::OpenPath(path) => fx.push(Effect::Read(path, Then::Open)),
            Command::LoadDataPath => fx.push(Effect::Read(self.session.data_path.clone(), Then::Import)),
            Command::Pick(kind) => fx.push(Effect::Pick(kind)),
            Command::SavePresetPath => match self.preset_text() {
                Ok(bytes) => fx.push(Effect::Write {
                    name: self.session.preset_path.clone(),
                    bytes,
                    done: "saved preset to",
                    failed: "preset not saved",
                }),
                Err(e) => self.error = Some(format!("preset not saved: {e}")),
            },
            Command::SavePresetAs => match self.preset_text() {
                Ok(bytes) => fx.push(Effect::SaveAs(FileKind::Preset, "preset.ron".into(), bytes)),
                Err(e) => self.error = Some(format!("preset not saved: {e}")),
            },
            Command::ClearData => {
                if let Some(data) = self.params_mut().measurements() {
                    data.clear();
                }
            }
            Command::ExportFigure(fig, ext) => {
                let name = format!("{}-{}.{ext}", self.params().info().id, fig.id);
                match self.figure_file(&fig, ext) {
                    Ok(bytes) => fx.push(Effect::WriteAll {
                        folder: self.session.export_dir.clone(),
                        files: vec![(name, bytes)],
                        what: "figure",
                    }),
                    Err(e) => self.error = Some(format!("export failed: {e}")),
                }
            }
            Command::SaveFigureAs(fig) => {
                let name = format!("{}-{}.png", self.params().info().id, fig.id);
                match self.figure_file(&fig, "png") {
                    Ok(bytes) => fx.push(Effect::SaveAs(FileKind::Figure, name, bytes)),
                    Err(e) => self.error = Some(format!("export failed: {e}")),
                }
            }
            Command::Movie => {
                if !self.movie_running {
                    let preset = self.current_preset();
                    self.movie_running = true;
                    let sheet = !self.paths;
                    self.status = if sheet {
                        "making the movie (one animated PNG of every figure)…".to_string()
                    } else {
                        format!("writing the movie to {}…", self.movie_folder())
                    };
                    fx.push(Effect::Submit(Job::Movie { preset: Box::new(preset), frames: 48, sheet }));
                }
            }
            Command::Pin => self.pin_current(),
            Command::ClearPins => {
                let id = self.params().info().id;
                self.session.pins.retain(|p| p.params.info().id != id);
            }
            Command::SetSweep(s) => self.sweep = s,
            Command::DrawFamily => self.draw_family(&mut fx),
            Command::SetMatters(output, factor) => {
                self.matters.output = output;
                self.matters.factor = factor;
            }
            Command::WhatMatters => self.what_matters(&mut fx),
            Command::CloseMatters => self.matters.open = false,
            Command::ShowPanel(id) => match &mut self.presenter {
                // On a slide the choice holds for the slide; in the explorer, for the scene.
                Some(p) => p.panel = Some(id),
                None => {
                    let scene = self.params().info().id.to_string();
                    self.session.panels.insert(scene, id);
                }
            },
            Command::MattersFigure(on) => {
                self.matters.figure = on;
                self.matters.whole_tab = false;
            }
            Command::MattersWhole(on) => {
                self.matters.whole_tab = on;
                self.matters.open |= on;
                if on && self.matters.whole.study.is_none() {
                    self.matters.whole.study = Some(self.default_whole_range());
                }
            }
            Command::SetWholeRange(study) => self.set_whole_range(*study),
            Command::RunWholeRange => self.run_whole_range(&mut fx),
            Command::DrawSensitivity(x, y) => self.draw_sensitivity(x, y, &mut fx),
            Command::ExportSensitivity => self.export_sensitivity(&mut fx),
            Command::ResetAll => self.reset_all(),
            Command::SetLight(on) => self.session.light = on,
            Command::SetPalette(filter) => self.palette = filter,
            Command::SetLecture(on) => self.session.lecture = on,
            Command::SetLectureParams(on) => self.lecture_params = on,
            Command::SetDrawer(open) => self.drawer = open,
            Command::SetHelp(on) => self.help = on,
            Command::HideLink => self.link = None,
            Command::SetText(field, text) => match field {
                Field::PresetPath => self.session.preset_path = text,
                Field::DataPath => self.session.data_path = text,
                Field::ExportDir => self.session.export_dir = text,
                Field::DeckPath => self.deck_editor.path = text,
            },
            Command::SetTime(t) => self.set_time(t),
            Command::StopPlaying => self.playback.playing = false,
            Command::SetSpeed(v) => self.playback.speed = v,
            Command::SetLooping(on) => self.playback.looping = on,
            Command::Tick(dt) => self.tick(dt),
            Command::LockAxes(views) => self.locked = views,
            Command::Inspect(figure, at, screen) => self.inspect(&figure, at, screen),
            Command::CloseInspection => self.inspected = None,
            Command::Dismiss(i) => {
                if i < self.notices.len() {
                    self.notices.remove(i);
                }
            }
            Command::Deck(edit) => self.edit_deck(edit, &mut fx),
            Command::CloseNotesWindow => {
                if let Some(p) = &mut self.presenter {
                    p.notes_window = false;
                }
            }
            Command::PauseJob(paused) => {
                self.status = if paused { "paused; Resume continues the run".into() } else { "resumed".into() };
                fx.push(Effect::Pause(paused));
            }
            Command::InkStroke(mut stroke) => {
                let inside = |p: &[f32; 2]| p.iter().all(|x| x.is_finite() && (-0.01..=1.01).contains(x));
                stroke.on.retain(|(_, points)| points.iter().flatten().all(|v| v.is_finite()));
                if stroke.points.len() >= 2 && stroke.points.iter().all(inside) {
                    self.classroom.strokes.push(stroke);
                }
            }
            Command::SetInkInExports(on) => {
                self.classroom.ink_in_exports = on;
                self.status = if on {
                    "exported figures (PNG, SVG) carry the ink drawn on them".into()
                } else {
                    "exported figures leave the ink out".into()
                };
            }
            Command::Clock(seconds) => {
                // A frame's time (a long pause, e.g. a sleeping laptop, counts in full).
                if let Some(p) = &mut self.presenter
                    && seconds.is_finite()
                    && seconds > 0.0
                {
                    p.elapsed += seconds;
                }
            }
            Command::SetCountdown(length) => {
                if let Some(p) = &mut self.presenter {
                    p.countdown = length.filter(|s| s.is_finite() && *s > 0.0);
                }
            }
            Command::CancelJob => {
                self.status = "cancelled; showing the last good result".into();
                fx.push(Effect::Cancel);
            }
        }
        fx
    }

    /// Does what a key (or its button) asks.
    fn act(&mut self, action: Action, fx: &mut Vec<Effect>) {
        if self.classroom.blank && action != Action::Blank {
            // Any key brings a blank screen back, and does nothing else.
            self.classroom.blank = false;
            return;
        }
        if !matches!(action, Action::Slide(_) | Action::Zero | Action::GoToTyped) {
            self.classroom.typed.clear();
        }
        match action {
            Action::Help => self.help = !self.help,
            Action::CopyLink => match crate::links::link_to(self.params()) {
                Some(query) => fx.push(Effect::ShareLink(query)),
                None => self.status = "this state is too large for a link: save it as a preset instead".into(),
            },
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
                // The innermost thing open closes first.
                if self.palette.is_some() {
                    self.palette = None;
                } else if self.help {
                    self.help = false;
                } else if self.link.is_some() {
                    self.link = None;
                } else if self.inspected.is_some() {
                    self.inspected = None;
                } else if self.matters.open {
                    self.matters.open = false;
                } else if self.deck_editor.open {
                    self.deck_editor.open = false;
                } else if let Some(p) = self.presenter.as_mut().filter(|p| p.notes_window) {
                    p.notes_window = false;
                } else if self.presenter.is_some() {
                    self.stop_presenting();
                } else {
                    self.session.lecture = false;
                }
            }
            Action::ResetScene => {
                let default = self.defaults[self.index()].clone();
                *self.params_mut() = default;
                self.control_notice = None;
                self.status = "scene reset to its defaults (Ctrl+Z undoes)".into();
            }
            Action::Export => self.export_all(fx),
            Action::Sensitivity => self.what_matters(fx),
            Action::NextSlide => self.step_slide(1),
            Action::PreviousSlide => self.step_slide(-1),
            Action::FirstSlide => self.step_slide(isize::MIN / 2),
            Action::LastSlide => self.step_slide(isize::MAX / 2),
            Action::Slide(n) => {
                self.type_digit(char::from(b'1' + (n.min(8) as u8)));
                if self.presenter.as_ref().is_some_and(|p| n < p.deck.deck.slides.len()) {
                    self.go_to_slide(n);
                }
            }
            Action::Zero => self.type_digit('0'),
            Action::RestartTimer => {
                if let Some(p) = &mut self.presenter {
                    p.elapsed = 0.0;
                }
            }
            Action::GoToTyped => self.go_to_typed(),
            Action::StartShow => self.start_show(false),
            Action::ResumeShow => self.start_show(true),
            Action::Blank => self.classroom.blank = !self.classroom.blank,
            Action::Pointer => self.classroom.pointer = !self.classroom.pointer,
            Action::Ink => {
                self.classroom.ink = !self.classroom.ink;
                self.status = if self.classroom.ink {
                    "ink: drag over the figures to draw (U undoes a stroke, C clears)".into()
                } else {
                    "ink off: the figures move again".into()
                };
            }
            Action::UndoInk => {
                self.classroom.strokes.pop();
            }
            Action::ClearInk => self.classroom.strokes.clear(),
            Action::InkInExports => {
                let on = !self.classroom.ink_in_exports;
                fx.extend(self.apply(Command::SetInkInExports(on)));
            }
            Action::ToggleNotes => {
                if let Some(p) = &mut self.presenter {
                    p.notes = !p.notes;
                }
            }
            Action::NotesWindow => {
                if let Some(p) = &mut self.presenter {
                    p.notes_window = !p.notes_window;
                }
            }
            Action::ResetSlide => {
                if let Some(i) = self.presenter.as_ref().map(|p| p.index) {
                    self.go_to_slide(i);
                    self.status = "slide reset as the deck defines it".into();
                }
            }
            Action::Palette => self.palette = if self.palette.is_some() { None } else { Some(String::new()) },
            Action::Pin => fx.extend(self.apply(Command::Pin)),
            Action::ClearPins => fx.extend(self.apply(Command::ClearPins)),
            Action::Movie => fx.extend(self.apply(Command::Movie)),
            Action::ResetAll => fx.extend(self.apply(Command::ResetAll)),
            Action::OpenFile => fx.extend(self.apply(Command::Pick(FileKind::Preset))),
            Action::SavePreset => fx.extend(self.apply(Command::SavePresetAs)),
            Action::ToggleTheme => self.session.light = !self.session.light,
            Action::DeckEditor => {
                let open = !self.deck_editor.open;
                fx.extend(self.apply(Command::Deck(super::command::DeckEdit::Show(open))));
            }
        }
    }

    /// Opens scene `i` of [`SCENES`].
    pub fn open_scene(&mut self, i: usize) {
        if self.index() != i {
            self.playback.playing = false;
        }
        self.session.scene = SCENES[i].id.to_string();
        self.control_notice = None;
    }

    /// Opens the scene `by` places after the open one in navigator order.
    fn step_scene(&mut self, by: isize) {
        let order: Vec<usize> = scene::scenes_by_chapter().into_iter().flat_map(|(_, v)| v).collect();
        let here = order.iter().position(|&i| i == self.index()).unwrap_or(0) as isize;
        let n = order.len() as isize;
        let next = order[(here + by).rem_euclid(n) as usize];
        self.open_scene(next);
    }

    /// Switches to the preset's scene and parameters.
    pub fn apply_preset(&mut self, preset: Preset, origin: &str) {
        let id = preset.scene.info().id;
        self.session.scene = id.to_string();
        let shared = preset.scene.monomer_card().filter(|_| !preset.scene.own_monomer());
        self.session.params.insert(id.to_string(), preset.scene);
        // A file exported from the sensitivity view reopens it.
        if let Some(view) = preset.sensitivity {
            self.matters.output = view.output;
            self.matters.factor = if view.factor.is_finite() && view.factor > 1.0 { view.factor } else { 2.0 };
            self.matters.x = view.x;
            self.matters.y = view.y;
            self.matters.result = None;
            self.matters.curve = None;
            self.matters.reopen = true;
            self.matters.whole = super::state::Whole { study: view.whole, ..Default::default() };
            self.matters.whole_tab = self.matters.whole.study.is_some();
        }
        // The preset's monomer becomes the monomer of every linked scene.
        if let Some(card) = shared {
            self.share_monomer(self.index(), &card);
        }
        self.status = format!("loaded preset '{}' from {origin}", preset.title);
        self.error = None;
        self.control_notice = None;
    }

    /// Uses a file's bytes: `then` says how. A file that cannot be used
    /// changes nothing and says why.
    pub fn open_bytes(&mut self, picked: Picked, then: Then) {
        match then {
            Then::Import => self.import(&picked),
            Then::EditDeck => match opening::deck(&picked) {
                Ok(d) => self.deck_editor.deck = d.deck,
                Err(e) => self.error = Some(format!("deck not opened, nothing changed: {e}")),
            },
            Then::Open => match opening::open(&picked) {
                Ok(Opened::Preset(p)) => self.apply_preset(*p, &picked.name),
                Ok(Opened::Deck(d)) => self.present(d, 0),
                Ok(Opened::Measurements) => self.import(&picked),
                Err(message) => self.error = Some(format!("{message}; nothing changed")),
            },
        }
    }

    /// Loads measurements into the open scene if it takes measurements,
    /// else into the first scene that does, and opens it. A rejected file
    /// changes nothing.
    fn import(&mut self, picked: &Picked) {
        let takes = |p: &SceneParams| p.clone().measurements().is_some();
        let target = if takes(self.params()) {
            Some(self.index())
        } else {
            (0..SCENES.len()).find(|&i| takes(self.params_of(i)))
        };
        let Some(i) = target else {
            self.error = Some("no scene takes measurements (nothing imported)".into());
            return;
        };
        match opening::measurements(picked) {
            Ok(data) => {
                self.open_scene(i);
                self.status = format!("imported {} measurements from {}", data.len(), picked.name);
                if let Some(slot) = self.params_mut().measurements() {
                    *slot = data;
                }
                self.error = None;
            }
            Err(e) => self.error = Some(format!("{}: {e} (nothing imported)", picked.name)),
        }
    }

    /// The open scene as the text of a preset file.
    fn preset_text(&self) -> Result<Vec<u8>, String> {
        let info = self.params().info();
        let preset = Preset {
            title: format!("{} (saved)", info.title),
            description: String::new(),
            scene: self.params().clone(),
            sensitivity: None,
        };
        preset.to_ron().map(String::into_bytes).map_err(|e| e.to_string())
    }

    /// One figure as a file (PNG, SVG or CSV) carrying the open scene's state.
    fn figure_file(&self, fig: &figure::Figure, ext: &str) -> Result<Vec<u8>, String> {
        let stamp = crate::provenance::Stamp::of(&self.current_preset()).map_err(|e| e.to_string())?;
        let mut fig = fig.clone();
        self.ink_onto(&mut fig);
        crate::provenance::figure_bytes(&fig, ext, figure::EXPORT_SIZE, Some(&stamp)).map_err(|e| e.to_string())
    }

    /// Puts the ink drawn on `fig` onto it, where exports are to carry it.
    fn ink_onto(&self, fig: &mut figure::Figure) {
        if self.classroom.ink_in_exports {
            let on = self.classroom.strokes.iter().flat_map(|s| &s.on);
            fig.ink = on.filter(|(id, _)| *id == fig.id).map(|(_, points)| points.clone()).collect();
        }
    }

    /// Exports every figure of the open scene (PNG, SVG, CSV, as drawn and
    /// carrying its state) to the export folder, rendered as a job.
    fn export_all(&mut self, fx: &mut Vec<Effect>) {
        let Some(out) = self.outputs[self.index()].clone() else { return };
        let stamp = match crate::provenance::Stamp::of(&self.current_preset()) {
            Ok(s) => s,
            Err(e) => {
                self.error = Some(format!("export failed: {e}"));
                return;
            }
        };
        let mut figures = self.drawn_figures(&out);
        for fig in &mut figures {
            self.ink_onto(fig);
        }
        let prefix = format!("{}-", self.params().info().id);
        self.status = format!("exporting {} figures to {}…", figures.len(), self.session.export_dir);
        fx.push(Effect::Submit(Job::Export { figures, stamp: Box::new(stamp), prefix }));
    }

    /// The folder a movie of the open scene goes to.
    pub fn movie_folder(&self) -> String {
        Path::new(&self.session.export_dir).join(format!("{}-movie", self.params().info().id)).display().to_string()
    }

    fn pin_current(&mut self) {
        let Some(out) = self.output() else { return };
        let curves = super::jobs::line_curves(out);
        let color = self.session.pins.len() + 1;
        let params = self.params().clone();
        self.session.pins.push(Pin { params, label: String::new(), curves, color });
    }

    /// Resets every scene's parameters to their defaults (one undo step).
    fn reset_all(&mut self) {
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

    fn undo(&mut self) {
        let now = self.all_params();
        match self.history.undo(|id| now(id)) {
            Some(step) => self.restore(step, "undone"),
            None => self.status = "nothing to undo".into(),
        }
    }

    fn redo(&mut self) {
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

    fn set_time(&mut self, fraction: f64) {
        let i = self.index();
        if let Some(c) = self.params_mut().cursor_mut() {
            *c = fraction.clamp(0.0, 1.0);
            self.timeline_shown.insert(i);
        }
    }

    fn toggle_play(&mut self) {
        let i = self.index();
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

    /// Advances a playing history by `dt` seconds.
    fn tick(&mut self, dt: f64) {
        if !self.playback.playing {
            return;
        }
        let mut playback = self.playback.clone();
        match self.params_mut().cursor_mut() {
            Some(c) => *c = playback.advance(*c, dt),
            None => playback.playing = false,
        }
        self.playback = playback;
    }

    /// Asks the open scene about the point `at` of figure `figure`; a point
    /// the scene cannot inspect closes the card.
    fn inspect(&mut self, figure: &str, at: [f64; 2], screen: [f32; 2]) {
        let scene = self.index();
        let Some(out) = self.outputs[scene].clone() else { return };
        self.inspected = self.params().inspect(&out, figure, at).map(|inspection| Inspected {
            scene,
            figure: figure.to_string(),
            inspection,
            at: screen,
        });
    }

    /// Axes locked at every figure's current view (or unlocked).
    pub fn lock_views(&self, lock: bool) -> Option<std::collections::HashMap<String, View>> {
        let out = self.output()?;
        lock.then(|| out.figures.iter().map(|f| (f.id.clone(), View::of(f))).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn number(p: &SceneParams, key: &str) -> f64 {
        match p.get(key) {
            Some(scene::DefaultValue::Number(v)) => v,
            _ => f64::NAN,
        }
    }

    fn with(state: &AppState, key: &str, value: &str) -> Box<SceneParams> {
        let mut p = state.params().clone();
        p.set(key, value).expect("valid");
        Box::new(p)
    }

    /// An edit at rest is one undo step; undo and redo restore it.
    #[test]
    fn edits_undo_and_redo() {
        let mut s = AppState::default();
        s.at_rest(false);
        let p = with(&s, "velocity", "3");
        s.apply(Command::SetParams(p));
        s.at_rest(false);
        assert_eq!(number(s.params(), "velocity"), 3.0);
        s.apply(Command::Act(Action::Undo));
        assert_eq!(number(s.params(), "velocity"), 8.0);
        s.apply(Command::Act(Action::Redo));
        assert_eq!(number(s.params(), "velocity"), 3.0);
        assert!(s.status.starts_with("redone"), "{}", s.status);
    }

    /// Edits of another scene's parameters are refused (a stale panel).
    #[test]
    fn parameters_of_another_scene_are_not_taken() {
        let mut s = AppState::default();
        let other = SceneParams::default_for("rocking").expect("scene");
        let before = s.session.clone();
        s.apply(Command::SetParams(Box::new(other)));
        assert_eq!(s.session, before);
    }

    /// A deck steps forward and back, stays at its ends and restores each
    /// slide's state; leaving restores the look from before.
    #[test]
    fn presenting_steps_through_slides() {
        let mut s = AppState::default();
        let deck = crate::deck::resolve("sticking-and-rolling").expect("shipped");
        let n = deck.deck.slides.len();
        s.apply(Command::Present(Box::new(deck), 0));
        assert!(s.session.lecture);
        s.apply(Command::Act(Action::PreviousSlide));
        assert_eq!(s.presenter.as_ref().map(|p| p.index), Some(0));
        s.apply(Command::Act(Action::LastSlide));
        assert_eq!(s.presenter.as_ref().map(|p| p.index), Some(n - 1));
        s.apply(Command::Act(Action::NextSlide));
        assert_eq!(s.presenter.as_ref().map(|p| p.index), Some(n - 1));
        s.apply(Command::Act(Action::Leave));
        assert!(s.presenter.is_none() && !s.session.lecture);
    }

    /// A file that is neither a preset, a deck, a figure with state nor
    /// measurements changes nothing and says why.
    #[test]
    fn a_bad_file_changes_nothing() {
        let mut s = AppState::default();
        let before = s.session.clone();
        for (name, bytes) in [("x.ron", &b"(nonsense"[..]), ("x.png", b"not a png"), ("x.csv", b"a,b\n1,2\n")] {
            s.apply(Command::OpenBytes(Picked { name: name.into(), bytes: bytes.to_vec() }));
            assert_eq!(s.session, before, "{name}");
            assert!(s.error.as_deref().is_some_and(|e| e.contains("x.")), "{name}: {:?}", s.error);
        }
        // Measurements open the fit scene.
        let csv = b"velocity [m/s],restitution\n5,0.7\n10,0.75\n".to_vec();
        s.apply(Command::OpenBytes(Picked { name: "m.csv".into(), bytes: csv }));
        assert_eq!(s.params().info().id, "fit");
    }

    /// Saving asks the platform to write the preset's text at the typed path.
    #[test]
    fn saving_a_preset_writes_its_text() {
        let mut s = AppState::default();
        let fx = s.apply(Command::SavePresetPath);
        match fx.as_slice() {
            [Effect::Write { name, bytes, .. }] => {
                assert_eq!(name, &s.session.preset_path);
                let text = std::str::from_utf8(bytes).expect("utf8");
                let back = Preset::from_ron(text, name).expect("reads back");
                assert_eq!(&back.scene, s.params());
            }
            other => panic!("{other:?}"),
        }
    }

    /// Ink goes into an exported PNG or SVG only when asked, in the figure's
    /// axis units, and never into its CSV.
    #[test]
    fn ink_goes_into_exports_when_asked() {
        let mut s = AppState::default();
        s.at_rest(false);
        let out = crate::scene::compute(s.params(), &crate::scene::Progress::default()).expect("computed");
        let fig = out.figures[0].clone();
        let view = crate::figure::layout::View::of(&fig);
        let mid = |r: [f64; 2]| 0.5 * (r[0] + r[1]);
        let (x, y) = ([view.x[0], mid(view.x), view.x[1]], mid(view.y));
        let stroke = crate::app::command::InkStroke {
            points: vec![[0.3, 0.3], [0.5, 0.5], [0.7, 0.3]],
            on: vec![(fig.id.clone(), x.iter().map(|x| [*x, y]).collect()), ("elsewhere".into(), vec![[1.0, 1.0]; 2])],
        };
        s.apply(Command::InkStroke(stroke));
        let svg = |s: &mut AppState, ext: &'static str| {
            let fx = s.apply(Command::ExportFigure(Box::new(fig.clone()), ext));
            match fx.as_slice() {
                [Effect::WriteAll { files, .. }] => String::from_utf8_lossy(&files[0].1).into_owned(),
                other => panic!("{other:?}"),
            }
        };
        let ink = "stroke=\"#d4008a\"";
        assert!(!svg(&mut s, "svg").contains(ink), "no ink unless asked");
        s.apply(Command::Act(Action::InkInExports));
        assert!(s.classroom.ink_in_exports);
        let drawn = svg(&mut s, "svg");
        assert_eq!(drawn.matches(ink).count(), 1, "the one stroke drawn on this figure");
        assert!(!svg(&mut s, "csv").contains("d4008a") && svg(&mut s, "csv").lines().count() > 2);
        s.apply(Command::Act(Action::ClearInk));
        assert!(!svg(&mut s, "svg").contains(ink), "cleared ink is gone from exports too");
    }

    /// Playing advances the cursor with the clock and stops at the end.
    #[test]
    fn playing_moves_the_cursor() {
        let mut s = AppState::default();
        s.apply(Command::SetTime(0.0));
        s.apply(Command::Act(Action::PlayPause));
        assert!(s.playback.playing);
        s.apply(Command::Tick(0.2));
        let t = s.time().expect("a history");
        assert!(t > 0.0 && t < 0.1, "{t}");
        for _ in 0..200 {
            s.apply(Command::Tick(0.25));
        }
        assert_eq!(s.time(), Some(1.0));
        assert!(!s.playback.playing);
    }
}
