//! The deck editor: slides from the window's states, reordered, titled,
//! annotated, saved and presented.

use super::Cx;
use crate::app::command::{Command, DeckEdit, Field};

/// The editor's window, while it is open.
pub fn window(ctx: &egui::Context, cx: &mut Cx<'_>) {
    if !cx.state.deck_editor.open {
        return;
    }
    let mut open = true;
    let mut edits: Vec<DeckEdit> = Vec::new();
    let mut deck = cx.state.deck_editor.deck.clone();
    let mut path = cx.state.deck_editor.path.clone();
    egui::Window::new("Deck").open(&mut open).default_width(460.0).show(ctx, |ui| {
        ui.horizontal(|ui| {
            let label = ui.label("title");
            ui.text_edit_singleline(&mut deck.title).labelled_by(label.id);
        });
        ui.separator();
        let n = deck.slides.len();
        egui::ScrollArea::vertical().max_height(ctx.content_rect().height() * 0.55).show(ui, |ui| {
            for (i, slide) in deck.slides.iter_mut().enumerate() {
                ui.push_id(i, |ui| {
                    let mut number = None;
                    ui.horizontal(|ui| {
                        let label = ui.label(format!("{}.", i + 1));
                        number = Some(label.id);
                        ui.add(egui::TextEdit::singleline(&mut slide.title).desired_width(220.0)).labelled_by(label.id);
                        if ui.add_enabled(i > 0, egui::Button::new("↑")).on_hover_text("move up").clicked() {
                            edits.push(DeckEdit::Swap(i - 1, i));
                        }
                        if ui.add_enabled(i + 1 < n, egui::Button::new("↓")).on_hover_text("move down").clicked() {
                            edits.push(DeckEdit::Swap(i, i + 1));
                        }
                        if ui.button("Present").on_hover_text("present from this slide").clicked() {
                            edits.push(DeckEdit::Present(i));
                        }
                        if ui.button("✕").on_hover_text("remove the slide").clicked() {
                            edits.push(DeckEdit::Remove(i));
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
            edits.push(DeckEdit::AddCurrent);
        }
        ui.separator();
        ui.horizontal(|ui| {
            let label = ui.label("deck file");
            ui.add(egui::TextEdit::singleline(&mut path).desired_width(220.0)).labelled_by(label.id);
            if ui.button("Save deck").clicked() {
                edits.push(DeckEdit::Save);
            }
            if ui.button("Open deck").clicked() {
                edits.push(DeckEdit::OpenFile);
            }
        });
        ui.horizontal(|ui| {
            ui.label("shipped:");
            for (file, _) in crate::deck::SHIPPED {
                if ui.small_button(file.trim_end_matches(".ron")).clicked() {
                    edits.push(DeckEdit::Shipped(file));
                }
            }
        });
    });
    // Titles and notes typed this frame come first, then what was clicked.
    if deck != cx.state.deck_editor.deck {
        cx.send(Command::Deck(DeckEdit::Replace(Box::new(deck))));
    }
    if path != cx.state.deck_editor.path {
        cx.send(Command::SetText(Field::DeckPath, path));
    }
    for e in edits {
        cx.send(Command::Deck(e));
    }
    if !open {
        cx.send(Command::Deck(DeckEdit::Show(false)));
    }
}
