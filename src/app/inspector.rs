//! The inspection card: a click on a plot asks the scene what its model says
//! at that point; the card shows it and opens the scenes that look closer.

use super::GrainscopeApp;
use crate::figure;
use crate::scene::inspect::Inspection;
use crate::scene::{Mark, SceneOutput, SceneParams};

/// A clicked point and its inspection.
pub(super) struct Inspected {
    /// Index of the scene in [`crate::scene::SCENES`].
    scene: usize,
    /// The figure clicked.
    figure: String,
    /// What the scene said.
    pub(super) inspection: Inspection,
    /// Where the click was on the screen: the card keeps clear of it.
    at: egui::Pos2,
}

impl GrainscopeApp {
    /// Asks the open scene about the point `at` of figure `figure`; a point
    /// the scene cannot inspect closes the card.
    pub(super) fn inspect_at(&mut self, out: &SceneOutput, figure: &str, at: [f64; 2], screen: egui::Pos2) {
        let scene = self.session.index();
        self.inspected = self.params().inspect(out, figure, at).map(|inspection| Inspected {
            scene,
            figure: figure.to_string(),
            inspection,
            at: screen,
        });
    }

    /// The current inspection, if it belongs to the open scene.
    pub fn inspection(&self) -> Option<&Inspection> {
        self.inspected.as_ref().filter(|i| i.scene == self.session.index()).map(|i| &i.inspection)
    }

    /// The ring around the inspected point on figure `figure`.
    pub(super) fn inspected_mark(&self, figure: &str) -> Option<Mark> {
        let i = self.inspected.as_ref().filter(|i| i.scene == self.session.index() && i.figure == figure)?;
        Some(Mark::Point(i.inspection.point, None))
    }

    /// Opens `params`'s scene with those parameters (an action of the card).
    pub fn open_params(&mut self, params: SceneParams, why: &str) {
        let id = params.info().id;
        self.session.params.insert(id.to_string(), params);
        if let Some(i) = crate::scene::SCENES.iter().position(|s| s.id == id) {
            self.open_scene(i);
        }
        self.inspected = None;
        self.status = why.to_string();
    }

    /// The card, beside the plots, while its scene is open.
    pub(super) fn inspection_window(&mut self, ctx: &egui::Context) {
        let Some(insp) = self.inspection().cloned() else { return };
        // In the corner of the screen farthest from the clicked point.
        let at = self.inspected.as_ref().map_or(egui::Pos2::ZERO, |i| i.at);
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
        let text = if self.session.lecture { 17.0 } else { 13.0 };
        egui::Window::new("Inspect")
            .open(&mut open)
            .anchor(align, offset)
            .default_width(360.0)
            .max_width(if self.session.lecture { 470.0 } else { 400.0 })
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
            self.open_params(params, &hint);
        } else if !open {
            self.inspected = None;
        }
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
