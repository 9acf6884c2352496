//! The bar along the top: file actions, shipped presets, the look, undo and
//! redo, decks and help; in the lecture look a short bar with the navigator,
//! the headline and the transport.

use super::Cx;
use super::scene_panel::{headline, navigator};
use crate::app::command::{Action, Command, DeckEdit, Field};
use crate::app::platform::FileKind;
use crate::app::shortcuts::{self, Mode};
use crate::preset::Preset;
use crate::scene::{self, SCENES};

/// The bar above the plots outside presenter mode.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    if cx.memo.compact {
        phone(ui, cx);
        return;
    }
    if cx.lecture() {
        ui.horizontal(|ui| {
            navigator(ui, cx, 290.0);
            ui.separator();
            let mut params = cx.state.lecture_params;
            if ui.toggle_value(&mut params, "Parameters").on_hover_text("show the parameters over the plots").changed()
            {
                cx.send(Command::SetLectureParams(params));
            }
            ui.menu_button("Presets", |ui| presets_menu(ui, cx));
            ui.menu_button("Present", |ui| decks_menu(ui, cx));
            ui.separator();
            let mut lecture = true;
            if ui.checkbox(&mut lecture, "Lecture mode").on_hover_text(hint(Action::ToggleLecture)).changed() {
                cx.send(Command::SetLecture(lecture));
            }
            // The palette is on F2 here, and the list of keys in the tools:
            // the bar has no room left at 1024 px.
            super::classroom::menu(ui, cx, true);
        });
        // The scene's headline result (e.g. e = 0.657, bounces) stays on
        // screen while the parameters are hidden, with the transport of
        // a history beside it.
        ui.horizontal(|ui| {
            if !cx.state.lecture_params {
                headline(ui, cx);
            }
            super::transport::row(ui, cx);
        });
        return;
    }
    ui.horizontal_wrapped(|ui| {
        ui.heading("grainscope");
        ui.separator();
        if ui.button("Open preset…").clicked() {
            cx.send(Command::Pick(FileKind::Preset));
        }
        if ui.button("Save preset…").clicked() {
            cx.send(Command::SavePresetAs);
        }
        if cx.state.paths {
            let mut path = cx.state.session.preset_path.clone();
            if ui
                .add(egui::TextEdit::singleline(&mut path).desired_width(220.0).hint_text("preset path"))
                .on_hover_text(
                    "path for Load/Save when no file dialog is available; presets can also be dropped on the window",
                )
                .changed()
            {
                cx.send(Command::SetText(Field::PresetPath, path.clone()));
            }
            if ui.button("Load").clicked() {
                cx.send(Command::OpenPath(path));
            }
            if ui.button("Save").clicked() {
                cx.send(Command::SavePresetPath);
            }
        }
        ui.menu_button("Shipped presets", |ui| presets_menu(ui, cx));
        ui.separator();
        let mut light = cx.state.session.light;
        if ui.checkbox(&mut light, "Light theme").on_hover_text(hint(Action::ToggleTheme)).changed() {
            cx.send(Command::SetLight(light));
        }
        let mut lecture = false;
        if ui.checkbox(&mut lecture, "Lecture mode").on_hover_text(hint(Action::ToggleLecture)).changed() {
            cx.send(Command::SetLecture(lecture));
        }
        ui.separator();
        let (undo, redo) = cx.state.history.depth();
        if ui.add_enabled(undo > 0, egui::Button::new("Undo")).on_hover_text(hint(Action::Undo)).clicked() {
            cx.send(Command::Act(Action::Undo));
        }
        if ui.add_enabled(redo > 0, egui::Button::new("Redo")).on_hover_text(hint(Action::Redo)).clicked() {
            cx.send(Command::Act(Action::Redo));
        }
        action_button(ui, cx, Action::ResetAll, Action::ResetAll.text().name);
        ui.separator();
        let mut open = cx.state.deck_editor.open;
        if ui.toggle_value(&mut open, "Deck").on_hover_text(hint(Action::DeckEditor)).changed() {
            cx.send(Command::Deck(DeckEdit::Show(open)));
        }
        ui.menu_button("Present", |ui| decks_menu(ui, cx));
        // The palette's button and the tools last: the buttons before them keep their places.
        for action in [Action::Help, Action::CopyLink, Action::Palette] {
            action_button(ui, cx, action, action.text().name);
        }
        super::classroom::menu(ui, cx, false);
    });
}

/// The bar on a phone's screen: the parameters drawer's button, the scene
/// navigator and a menu of the rest; below them the headline result.
fn phone(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let screen = ui.ctx().content_rect().width();
    ui.horizontal_wrapped(|ui| {
        let mut open = cx.state.drawer;
        if ui.toggle_value(&mut open, "Parameters").on_hover_text("the parameters in place of the figures").changed() {
            cx.send(Command::SetDrawer(open));
        }
        ui.menu_button("More", |ui| {
            if ui.button("Open preset…").clicked() {
                cx.send(Command::Pick(FileKind::Preset));
            }
            if ui.button("Save preset…").clicked() {
                cx.send(Command::SavePresetAs);
            }
            ui.menu_button("Shipped presets", |ui| presets_menu(ui, cx));
            ui.menu_button("Present", |ui| decks_menu(ui, cx));
            let mut light = cx.state.session.light;
            if ui.checkbox(&mut light, "Light theme").changed() {
                cx.send(Command::SetLight(light));
            }
            let (undo, redo) = cx.state.history.depth();
            if ui.add_enabled(undo > 0, egui::Button::new("Undo")).clicked() {
                cx.send(Command::Act(Action::Undo));
            }
            if ui.add_enabled(redo > 0, egui::Button::new("Redo")).clicked() {
                cx.send(Command::Act(Action::Redo));
            }
            for action in [Action::ResetAll, Action::CopyLink, Action::Palette, Action::Help] {
                action_button(ui, cx, action, action.text().name);
            }
        });
        // Beside the buttons where it fits (a phone held sideways).
        if screen > 600.0 {
            navigator(ui, cx, 320.0);
        }
    });
    if screen <= 600.0 {
        // ◀, "Scene" and ▶ take about 110 points beside the list.
        navigator(ui, cx, (screen - 130.0).max(100.0));
    }
    headline(ui, cx);
}

/// A tooltip for `action` in the explorer: what it does and its keys, from the action table.
fn hint(action: Action) -> String {
    shortcuts::hint(action, Mode::Explorer)
}

/// A button labelled `label` that runs `action`, with the action's tooltip.
fn action_button(ui: &mut egui::Ui, cx: &mut Cx<'_>, action: Action, label: &str) {
    if ui.button(label).on_hover_text(hint(action)).clicked() {
        cx.send(Command::Act(action));
    }
}

/// The shipped presets menu: grouped by chapter, each by its title.
fn presets_menu(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let menu = cx.memo.shipped_menu.get_or_insert_with(|| {
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
        let bytes = text.as_bytes().to_vec();
        cx.send(Command::OpenBytes(crate::app::platform::Picked { name: file.to_string(), bytes }));
        ui.close();
    }
}

/// The shipped decks, each presented from its first slide when picked.
pub fn decks_menu(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    // In lecture mode the bar has no room for the Link button: it is here too.
    if ui.button("Link and QR code to this state (Q)").clicked() {
        cx.send(Command::Act(Action::CopyLink));
        ui.close();
    }
    ui.separator();
    let mut picked = None;
    for (file, text) in crate::deck::SHIPPED {
        let title = ron::from_str::<crate::deck::Deck>(text).map_or_else(|_| file.to_string(), |d| d.title);
        if ui.button(title).on_hover_text(file).clicked() {
            picked = Some((file, text));
        }
    }
    if let Some((file, text)) = picked {
        let bytes = text.as_bytes().to_vec();
        cx.send(Command::OpenBytes(crate::app::platform::Picked { name: file.to_string(), bytes }));
        ui.close();
    }
}
