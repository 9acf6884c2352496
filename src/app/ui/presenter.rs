//! Presenting a deck (full screen, in the lecture look, slide by slide with
//! the keys a presentation clicker sends): the bar above the slide, the
//! speaker notes under it or in a window of their own.

use super::Cx;
use super::controls::{self, Select};
use crate::app::command::{Action, Command};
use crate::app::shortcuts::{self, Mode};

/// The bar above the slide: position, title and the presenter's buttons.
pub fn bar(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let Some(p) = &cx.state.presenter else { return };
    let (i, n) = (p.index, p.deck.deck.slides.len());
    let title = p.slide().title.clone();
    let (notes, notes_window) = (p.notes, p.notes_window);
    let highlight = p.slide().highlight.clone();
    // The title in full (it wraps); the buttons follow it, on the next line
    // where the title leaves no room.
    ui.horizontal_wrapped(|ui| {
        if ui.button("◀").on_hover_text(hint(Action::PreviousSlide)).clicked() {
            cx.send(Command::Act(Action::PreviousSlide));
        }
        ui.label(egui::RichText::new(format!("{} / {n}", i + 1)).strong());
        if ui.button("▶").on_hover_text(hint(Action::NextSlide)).clicked() {
            cx.send(Command::Act(Action::NextSlide));
        }
        ui.separator();
        ui.add(egui::Label::new(egui::RichText::new(title).heading().strong()).wrap());
        ui.separator();
        if ui.selectable_label(notes, "Notes").on_hover_text(hint(Action::ToggleNotes)).clicked() {
            cx.send(Command::Act(Action::ToggleNotes));
        }
        if ui.selectable_label(notes_window, "Notes window").on_hover_text(hint(Action::NotesWindow)).clicked() {
            cx.send(Command::Act(Action::NotesWindow));
        }
        let mut params = cx.state.lecture_params;
        if ui
            .toggle_value(&mut params, "Parameters")
            .on_hover_text("every parameter of the scene, over the plots")
            .changed()
        {
            cx.send(Command::SetLectureParams(params));
        }
        if ui.button("Reset slide").on_hover_text(hint(Action::ResetSlide)).clicked() {
            cx.send(Command::Act(Action::ResetSlide));
        }
        super::classroom::menu(ui, cx, false);
        super::classroom::timer(ui, cx);
        if ui.button("Leave").on_hover_text(hint(Action::Leave)).clicked() {
            cx.send(Command::StopPresenting);
        }
    });
    if !highlight.is_empty() {
        // The slide's highlighted controls in one row, after the headline.
        ui.horizontal_wrapped(|ui| {
            super::scene_panel::headline(ui, cx);
            ui.separator();
            controls::show(ui, cx, Select::Slide(&highlight));
        });
    }
    super::transport::row(ui, cx);
}

/// The speaker notes, under the plots.
pub fn notes(ui: &mut egui::Ui, cx: &Cx<'_>) {
    let Some(p) = &cx.state.presenter else { return };
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        ui.add(egui::Label::new(egui::RichText::new(&p.slide().notes).size(18.0)).wrap());
    });
}

/// The speaker notes in a window of their own (a separate window where
/// the platform has them): this slide's title and notes, the next
/// slide's title, and the slide keys, which work there too.
pub fn notes_window(ctx: &egui::Context, cx: &mut Cx<'_>) {
    let Some(p) = &cx.state.presenter else { return };
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
                actions = crate::app::shortcuts::pressed(&ctx, crate::app::shortcuts::Mode::Presenter);
            }
            let mut body = |ui: &mut egui::Ui| {
                ui.horizontal(|ui| {
                    if ui.button("◀").clicked() {
                        actions.push(Action::PreviousSlide);
                    }
                    ui.label(egui::RichText::new(format!("{} / {n}", i + 1)).strong());
                    if ui.button("▶").clicked() {
                        actions.push(Action::NextSlide);
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
        cx.send(Command::Act(a));
    }
    if close {
        cx.send(Command::CloseNotesWindow);
    }
}

/// A tooltip for `action` while presenting: what it does and its keys, from the action table.
fn hint(action: Action) -> String {
    shortcuts::hint(action, Mode::Presenter)
}
