//! The Link card: the address of the present state and its QR code, large
//! enough to be scanned from a lecture hall's back row when projected.

use super::Cx;
use crate::app::command::Command;
use crate::app::state::QrModules;

/// Modules of light margin around a QR code (the standard's quiet zone).
const QUIET: usize = 4;

/// The card, while a link is shown.
pub fn card(ctx: &egui::Context, cx: &mut Cx<'_>) {
    let Some(link) = cx.state.link.clone() else {
        return;
    };
    let mut open = true;
    let screen = ctx.content_rect();
    egui::Window::new("Link to this state")
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, [0.0, 0.0])
        .show(ctx, |ui| {
            ui.set_max_width((screen.width() * 0.8).min(560.0));
            ui.label("Scan the code or type the address: it opens this scene with these parameters.");
            ui.add_space(6.0);
            match &link.modules {
                Some(modules) => {
                    // Within the card on a phone's narrow screen as well.
                    let side = (screen.height() - 260.0).clamp(160.0, 420.0).min(screen.width() * 0.8 - 24.0);
                    ui.vertical_centered(|ui| draw(ui, modules, side));
                }
                None => {
                    ui.colored_label(
                        ui.visuals().warn_fg_color,
                        "This address is too long for a QR code: save a preset and share the file instead.",
                    );
                }
            }
            ui.add_space(6.0);
            ui.add(egui::Label::new(egui::RichText::new(&link.address).monospace()).wrap());
            ui.horizontal(|ui| {
                if ui.button("Copy address").clicked() {
                    ui.ctx().copy_text(link.address.clone());
                }
                if ui.button("Close").clicked() {
                    cx.send(Command::HideLink);
                }
            });
        });
    if !open {
        cx.send(Command::HideLink);
    }
}

/// Draws the code `side` points square, dark on white whatever the theme
/// (scanners expect it so), with its quiet zone.
fn draw(ui: &mut egui::Ui, modules: &QrModules, side: f32) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, egui::Color32::WHITE);
    let cells = (modules.width + 2 * QUIET) as f32;
    let cell = side / cells;
    for (i, _) in modules.dark.iter().enumerate().filter(|(_, dark)| **dark) {
        let (row, col) = (i / modules.width, i % modules.width);
        let min = rect.min + egui::vec2((col + QUIET) as f32 * cell, (row + QUIET) as f32 * cell);
        // A hair wider than the cell, so that neighbours leave no seam.
        painter.rect_filled(
            egui::Rect::from_min_size(min, egui::vec2(cell + 0.5, cell + 0.5)),
            0.0,
            egui::Color32::BLACK,
        );
    }
}
