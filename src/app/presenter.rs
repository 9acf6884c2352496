//! Presenting a deck (full screen, in the lecture look, slide by slide with
//! the keys a presentation clicker sends) and building one from the window.

use super::GrainscopeApp;
use crate::deck::{Deck, LoadedDeck, Slide};
use crate::scene::SCENES;
use std::path::{Path, PathBuf};

/// A deck being presented.
pub struct Presenter {
    /// The deck, every slide resolved.
    pub deck: LoadedDeck,
    /// The slide shown (0-based).
    pub index: usize,
    /// Whether the speaker notes are shown under the plots.
    pub notes: bool,
    /// Whether the speaker notes are shown in a window of their own, which
    /// the lecturer keeps on a second screen.
    pub notes_window: bool,
    /// Whether lecture mode was on before presenting (restored on leaving).
    lecture_before: bool,
}

impl Presenter {
    /// The slide shown.
    pub fn slide(&self) -> &Slide {
        &self.deck.deck.slides[self.index]
    }
}

/// The deck being built in the window.
pub struct DeckEditor {
    /// Whether the editor window is open.
    pub open: bool,
    /// The deck.
    pub deck: Deck,
    /// Path typed for saving and opening.
    pub path: String,
}

impl Default for DeckEditor {
    fn default() -> Self {
        DeckEditor {
            open: false,
            deck: Deck { title: "My lecture".into(), ..Deck::default() },
            path: "presets/decks/my-lecture.ron".into(),
        }
    }
}

impl GrainscopeApp {
    /// Starts presenting `deck` at slide `at` (0-based): full screen, the
    /// lecture look, the slide's state applied.
    pub fn present(&mut self, deck: LoadedDeck, at: usize) {
        let lecture_before = match &self.presenter {
            Some(p) => p.lecture_before,
            None => self.session.lecture,
        };
        let n = deck.deck.slides.len();
        self.presenter = Some(Presenter { deck, index: 0, notes: false, notes_window: false, lecture_before });
        self.session.lecture = true;
        self.go_to_slide(at.min(n.saturating_sub(1)));
    }

    /// The deck being presented, if any.
    pub fn presenting(&self) -> Option<&Presenter> {
        self.presenter.as_ref()
    }

    /// Shows slide `i` as the deck defines it (its scene and parameters).
    pub fn go_to_slide(&mut self, i: usize) {
        let Some(p) = &mut self.presenter else { return };
        let Some(params) = p.deck.params.get(i).cloned() else { return };
        p.index = i;
        let title = p.deck.deck.slides[i].title.clone();
        let id = params.info().id;
        self.session.params.insert(id.to_string(), params);
        if let Some(k) = SCENES.iter().position(|s| s.id == id) {
            self.open_scene(k);
        }
        self.playback.playing = false;
        self.status = format!("slide {}: {title}", i + 1);
        self.error = None;
    }

    /// Moves `by` slides (stays at the ends).
    pub fn step_slide(&mut self, by: isize) {
        let Some(p) = &self.presenter else { return };
        let n = p.deck.deck.slides.len() as isize;
        let next = (p.index as isize + by).clamp(0, n - 1) as usize;
        if next != p.index {
            self.go_to_slide(next);
        }
    }

    /// Leaves presenter mode, restoring the look from before.
    pub fn stop_presenting(&mut self) {
        if let Some(p) = self.presenter.take() {
            self.session.lecture = p.lecture_before;
        }
    }

    /// The bar above the slide: position, title and the presenter's buttons.
    pub(super) fn presenter_bar(&mut self, ui: &mut egui::Ui) {
        let Some(p) = &self.presenter else { return };
        let (i, n) = (p.index, p.deck.deck.slides.len());
        let title = p.slide().title.clone();
        let notes = p.notes;
        let notes_window = p.notes_window;
        let mut toggle_window = false;
        let mut go: Option<isize> = None;
        let mut toggle_notes = false;
        let mut reset = false;
        let mut leave = false;
        ui.horizontal(|ui| {
            if ui.button("◀").on_hover_text("previous slide (←, Page Up)").clicked() {
                go = Some(-1);
            }
            ui.label(egui::RichText::new(format!("{} / {n}", i + 1)).strong());
            if ui.button("▶").on_hover_text("next slide (→, Page Down, Space)").clicked() {
                go = Some(1);
            }
            ui.separator();
            // The buttons keep the right end; a long title is cut before them.
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                leave = ui.button("Leave").on_hover_text("leave presenter mode (Esc)").clicked();
                reset = ui.button("Reset slide").on_hover_text("as the deck defines it (R)").clicked();
                ui.toggle_value(&mut self.lecture_params, "Parameters")
                    .on_hover_text("every parameter of the scene, over the plots");
                toggle_notes =
                    ui.selectable_label(notes, "Notes").on_hover_text("speaker notes under the plots (N)").clicked();
                toggle_window = ui
                    .selectable_label(notes_window, "Notes window")
                    .on_hover_text("speaker notes in a window of their own, for a second screen (W)")
                    .clicked();
                ui.with_layout(egui::Layout::left_to_right(egui::Align::Center), |ui| {
                    ui.add(egui::Label::new(egui::RichText::new(title).heading().strong()).truncate());
                });
            });
        });
        if self.presenter.as_ref().is_some_and(|p| !p.slide().highlight.is_empty()) {
            ui.horizontal(|ui| self.highlighted_controls(ui));
        }
        self.transport_row(ui);
        if let Some(by) = go {
            self.step_slide(by);
        }
        if toggle_notes {
            self.toggle_notes();
        }
        if toggle_window {
            self.act(super::shortcuts::Action::NotesWindow);
        }
        if reset {
            self.reset_slide();
        }
        if leave {
            self.stop_presenting();
        }
    }

    /// Speaker notes on or off.
    pub fn toggle_notes(&mut self) {
        if let Some(p) = &mut self.presenter {
            p.notes = !p.notes;
        }
    }

    /// Restores the slide as the deck defines it.
    pub fn reset_slide(&mut self) {
        if let Some(i) = self.presenter.as_ref().map(|p| p.index) {
            self.go_to_slide(i);
            self.status = "slide reset as the deck defines it".into();
        }
    }

    /// The speaker notes, under the plots.
    pub(super) fn notes_panel(&self, ui: &mut egui::Ui) {
        let Some(p) = &self.presenter else { return };
        egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
            ui.add(egui::Label::new(egui::RichText::new(&p.slide().notes).size(17.0)).wrap());
        });
    }

    /// The speaker notes in a window of their own (a separate window where
    /// the platform has them): this slide's title and notes, the next
    /// slide's title, and the slide keys, which work there too.
    pub(super) fn notes_window(&mut self, ctx: &egui::Context) {
        let Some(p) = &self.presenter else { return };
        if !p.notes_window {
            return;
        }
        let (i, n) = (p.index, p.deck.deck.slides.len());
        let slide = p.slide().clone();
        let next = p.deck.deck.slides.get(i + 1).map(|s| s.title.clone());
        let mut actions = Vec::new();
        let mut close = false;
        ctx.show_viewport_immediate(
            egui::ViewportId::from_hash_of("grainscope-notes"),
            egui::ViewportBuilder::default().with_title("grainscope — speaker notes").with_inner_size([640.0, 480.0]),
            |ui, class| {
                let ctx = ui.ctx().clone();
                if ctx.input(|i| i.viewport().close_requested()) {
                    close = true;
                }
                // Keys pressed in a window of its own are its own; an
                // embedded window shares the main window's keys.
                if class != egui::ViewportClass::EmbeddedWindow {
                    actions = super::shortcuts::pressed(&ctx, super::shortcuts::Mode::Presenter);
                }
                let mut body = |ui: &mut egui::Ui| {
                    ui.horizontal(|ui| {
                        if ui.button("◀").clicked() {
                            actions.push(super::shortcuts::Action::PreviousSlide);
                        }
                        ui.label(egui::RichText::new(format!("{} / {n}", i + 1)).strong());
                        if ui.button("▶").clicked() {
                            actions.push(super::shortcuts::Action::NextSlide);
                        }
                        ui.add(egui::Label::new(egui::RichText::new(&slide.title).heading().strong()).truncate());
                    });
                    ui.separator();
                    egui::ScrollArea::vertical().max_height((ui.available_height() - 30.0).max(80.0)).show(ui, |ui| {
                        ui.add(egui::Label::new(egui::RichText::new(&slide.notes).size(18.0)).wrap());
                    });
                    ui.separator();
                    ui.label(match &next {
                        Some(t) => format!("next: {t}"),
                        None => "last slide".to_string(),
                    });
                };
                if class == egui::ViewportClass::EmbeddedWindow {
                    body(ui);
                } else {
                    egui::CentralPanel::default().show(ui, |ui| body(ui));
                }
            },
        );
        for a in actions {
            self.act(a);
        }
        if close && let Some(p) = &mut self.presenter {
            p.notes_window = false;
        }
    }

    /// The slide's highlighted controls in one row, after the headline.
    pub(super) fn highlighted_controls(&mut self, ui: &mut egui::Ui) {
        let Some(keys) = self.presenter.as_ref().map(|p| p.slide().highlight.clone()) else { return };
        self.headline(ui);
        ui.separator();
        self.controls_of(ui, super::Select::Slide(&keys));
    }

    /// The deck editor: slides from the window's state, reordered, titled,
    /// annotated, saved and presented.
    pub(super) fn deck_editor(&mut self, ctx: &egui::Context) {
        if !self.deck_editor.open {
            return;
        }
        let mut open = true;
        let mut action: Option<EditorAction> = None;
        egui::Window::new("Deck").open(&mut open).default_width(460.0).show(ctx, |ui| {
            let editor = &mut self.deck_editor;
            ui.horizontal(|ui| {
                let label = ui.label("title");
                ui.text_edit_singleline(&mut editor.deck.title).labelled_by(label.id);
            });
            ui.separator();
            let n = editor.deck.slides.len();
            egui::ScrollArea::vertical().max_height(ctx.content_rect().height() * 0.55).show(ui, |ui| {
                for (i, slide) in editor.deck.slides.iter_mut().enumerate() {
                    ui.push_id(i, |ui| {
                        let mut number = None;
                        ui.horizontal(|ui| {
                            let label = ui.label(format!("{}.", i + 1));
                            number = Some(label.id);
                            ui.add(egui::TextEdit::singleline(&mut slide.title).desired_width(220.0))
                                .labelled_by(label.id);
                            if ui.add_enabled(i > 0, egui::Button::new("↑")).on_hover_text("move up").clicked() {
                                action = Some(EditorAction::Swap(i - 1, i));
                            }
                            if ui.add_enabled(i + 1 < n, egui::Button::new("↓")).on_hover_text("move down").clicked()
                            {
                                action = Some(EditorAction::Swap(i, i + 1));
                            }
                            if ui.button("Present").on_hover_text("present from this slide").clicked() {
                                action = Some(EditorAction::Present(i));
                            }
                            if ui.button("✕").on_hover_text("remove the slide").clicked() {
                                action = Some(EditorAction::Remove(i));
                            }
                        });
                        let notes = ui.add(
                            egui::TextEdit::multiline(&mut slide.notes)
                                .hint_text("speaker notes")
                                .desired_rows(2)
                                .desired_width(f32::INFINITY),
                        );
                        if let Some(id) = number {
                            notes.labelled_by(id);
                        }
                    });
                }
            });
            if ui.button("Add the current state as a slide").clicked() {
                action = Some(EditorAction::Add);
            }
            ui.separator();
            ui.horizontal(|ui| {
                let label = ui.label("deck file");
                ui.add(egui::TextEdit::singleline(&mut editor.path).desired_width(220.0)).labelled_by(label.id);
                if ui.button("Save deck").clicked() {
                    action = Some(EditorAction::Save);
                }
                if ui.button("Open deck").clicked() {
                    action = Some(EditorAction::Open);
                }
            });
            ui.horizontal(|ui| {
                ui.label("shipped:");
                for (file, _) in crate::deck::SHIPPED {
                    if ui.small_button(file.trim_end_matches(".ron")).clicked() {
                        action = Some(EditorAction::Shipped(file));
                    }
                }
            });
        });
        self.deck_editor.open = open;
        match action {
            Some(EditorAction::Swap(a, b)) => self.deck_editor.deck.slides.swap(a, b),
            Some(EditorAction::Remove(i)) => {
                self.deck_editor.deck.slides.remove(i);
            }
            Some(EditorAction::Add) => self.add_slide(),
            Some(EditorAction::Present(i)) => {
                let base = Path::new(&self.deck_editor.path).parent().map(Path::to_path_buf);
                match resolve_all(&self.deck_editor.deck, base.as_deref()) {
                    Ok(deck) => self.present(deck, i),
                    Err(e) => self.error = Some(e),
                }
            }
            Some(EditorAction::Save) => {
                let path = PathBuf::from(&self.deck_editor.path);
                match self.deck_editor.deck.save(&path) {
                    Ok(()) => self.status = format!("saved deck to {}", path.display()),
                    Err(e) => self.error = Some(format!("deck not saved: {e}")),
                }
            }
            Some(EditorAction::Open) => {
                let path = PathBuf::from(&self.deck_editor.path);
                match Deck::load(&path) {
                    Ok(d) => self.deck_editor.deck = d.deck,
                    Err(e) => self.error = Some(format!("deck not opened, nothing changed: {e}")),
                }
            }
            Some(EditorAction::Shipped(file)) => match crate::deck::resolve(file) {
                Ok(d) => self.deck_editor.deck = d.deck,
                Err(e) => self.error = Some(e.to_string()),
            },
            None => {}
        }
    }

    /// Appends the window's current scene and parameters as a slide.
    pub fn add_slide(&mut self) {
        let params = self.params().clone();
        let title = params.info().title.to_string();
        self.deck_editor.deck.slides.push(Slide { title, scene: Some(params), ..Slide::default() });
        self.status = format!("added slide {}", self.deck_editor.deck.slides.len());
    }
}

/// What the deck editor was asked to do this frame.
enum EditorAction {
    Swap(usize, usize),
    Remove(usize),
    Add,
    Present(usize),
    Save,
    Open,
    Shipped(&'static str),
}

/// Resolves every slide of a deck built in the window.
fn resolve_all(deck: &Deck, base: Option<&Path>) -> Result<LoadedDeck, String> {
    if deck.slides.is_empty() {
        return Err("the deck has no slides yet: add the current state as a slide".into());
    }
    let params = deck
        .slides
        .iter()
        .enumerate()
        .map(|(i, s)| s.resolve(base).map_err(|e| format!("slide {} ('{}'): {e}", i + 1, s.title)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(LoadedDeck { deck: deck.clone(), params, origin: "the deck editor".into() })
}
