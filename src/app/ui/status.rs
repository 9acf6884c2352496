//! The status line (progress, pause, cancel and the last message) and the
//! notices that stay until dismissed.

use super::Cx;
use crate::app::command::Command;

/// Messages that stay until dismissed.
pub fn notices(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    for (i, notice) in cx.state.notices.iter().enumerate() {
        ui.horizontal(|ui| {
            if ui.button("Dismiss").clicked() {
                cx.out.push(Command::Dismiss(i));
            }
            ui.add(egui::Label::new(egui::RichText::new(notice).color(ui.visuals().warn_fg_color)).wrap());
        });
    }
}

/// The status line along the bottom.
pub fn bar(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    // On a phone the message has a line of its own below the progress.
    if cx.memo.compact {
        ui.vertical(|ui| {
            ui.horizontal(|ui| progress(ui, cx));
            message(ui, cx);
        });
    } else {
        ui.horizontal(|ui| {
            progress(ui, cx);
            message(ui, cx);
        });
    }
}

/// The running job's progress, with Pause (where it can) and Cancel.
fn progress(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let work = cx.work;
    if work.running {
        ui.add(egui::ProgressBar::new(work.progress as f32).desired_width(160.0).show_percentage());
        if work.pausable && ui.button(if work.paused { "Resume" } else { "Pause" }).clicked() {
            cx.send(Command::PauseJob(!work.paused));
        }
        if ui.button("Cancel").clicked() {
            cx.send(Command::CancelJob);
        }
    }
}

/// The last error, else the status; long messages wrap instead of running
/// off the window's edge.
fn message(ui: &mut egui::Ui, cx: &Cx<'_>) {
    if let Some(e) = &cx.state.error {
        ui.add(egui::Label::new(egui::RichText::new(e).color(egui::Color32::from_rgb(200, 40, 40))).wrap());
    } else {
        ui.add(egui::Label::new(&cx.state.status).wrap());
    }
}
