//! The list of keyboard shortcuts, over everything: read from the same
//! table the keys are dispatched from, with each action's own text, so it
//! lists exactly what exists.

use super::Cx;
use crate::app::command::{Action, Command};
use crate::app::shortcuts::{self, Mode};

/// The overlay, while it is open.
pub fn overlay(ctx: &egui::Context, cx: &mut Cx<'_>) {
    if !cx.state.help {
        return;
    }
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
                            ui.label(s.action.text().does);
                            ui.end_row();
                        }
                    }
                });
            });
        });
    if !open {
        cx.send(Command::SetHelp(false));
    }
}
