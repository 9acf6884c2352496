//! The inspection card: a click on a plot asks the scene what its model says
//! at that point; the card shows it and opens the scenes that look closer.

use super::Cx;
use crate::app::command::Command;
use crate::figure;
use crate::scene::SceneParams;

/// The card, beside the plots, while its scene is open.
pub fn window(ctx: &egui::Context, cx: &mut Cx<'_>) {
    let Some(insp) = cx.state.inspection().cloned() else { return };
    // In the corner of the screen farthest from the clicked point.
    let at = cx.state.inspected.as_ref().map_or(egui::Pos2::ZERO, |i| egui::pos2(i.at[0], i.at[1]));
    let screen = ctx.content_rect();
    let right = at.x < screen.center().x;
    let bottom = at.y < screen.center().y;
    let align = egui::Align2([
        if right { egui::Align::Max } else { egui::Align::Min },
        if bottom { egui::Align::Max } else { egui::Align::Min },
    ]);
    let offset = egui::vec2(if right { -12.0 } else { 12.0 }, if bottom { -36.0 } else { 60.0 });
    let mut open = true;
    let mut chosen: Option<(SceneParams, String)> = None;
    let lecture = cx.lecture();
    let text = super::look::body_size(lecture);
    egui::Window::new("Inspect")
        .open(&mut open)
        .anchor(align, offset)
        .default_width(360.0)
        .max_width(if lecture { 470.0 } else { 400.0 })
        .collapsible(true)
        .resizable(false)
        .show(ctx, |ui| {
            ui.label(egui::RichText::new(&insp.title).strong().size(text + 1.0));
            egui::Grid::new("inspection-rows").num_columns(2).spacing([12.0, 2.0]).striped(true).show(ui, |ui| {
                for (k, v) in &insp.rows {
                    ui.label(egui::RichText::new(k).size(text));
                    ui.add(egui::Label::new(egui::RichText::new(v).size(text)).wrap());
                    ui.end_row();
                }
            });
            if let Some((title, bars)) = &insp.bars {
                ui.add_space(4.0);
                ui.label(egui::RichText::new(title).size(text));
                bar_chart(ui, bars, text);
            }
            if let Some(outcome) = &insp.outcome {
                ui.add_space(4.0);
                ui.add(egui::Label::new(egui::RichText::new(outcome).strong().size(text)).wrap());
            }
            for a in &insp.actions {
                if ui.button(egui::RichText::new(&a.label).size(text)).on_hover_text(&a.hint).clicked() {
                    chosen = Some((a.open.clone(), a.hint.clone()));
                }
            }
        });
    if let Some((params, hint)) = chosen {
        cx.send(Command::OpenParams(Box::new(params), hint));
    } else if !open {
        cx.send(Command::CloseInspection);
    }
}

/// Horizontal bars of non-negative values, each labelled with its value.
fn bar_chart(ui: &mut egui::Ui, bars: &[(String, f64)], text: f32) {
    let max = bars.iter().map(|b| b.1).fold(0.0, f64::max);
    let label_w = 7.5 * text;
    let width = ui.available_width().max(240.0);
    for (name, v) in bars {
        let (rect, _) = ui.allocate_exact_size(egui::vec2(width, text * 1.5), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        let color = ui.visuals().text_color();
        painter.text(rect.left_center(), egui::Align2::LEFT_CENTER, name, egui::FontId::proportional(text), color);
        let room = (rect.width() - label_w - 6.0 * text).max(20.0);
        let len = if max > 0.0 { (v / max) as f32 * room } else { 0.0 };
        let bar = egui::Rect::from_min_size(
            egui::pos2(rect.left() + label_w, rect.center().y - 0.35 * text),
            egui::vec2(len.max(1.0), 0.7 * text),
        );
        painter.rect_filled(bar, 1.0, ui.visuals().selection.bg_fill);
        painter.text(
            egui::pos2(bar.right() + 4.0, rect.center().y),
            egui::Align2::LEFT_CENTER,
            figure::human(*v),
            egui::FontId::proportional(text * 0.9),
            color,
        );
    }
}
