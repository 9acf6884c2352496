//! The side panel: the scene navigator, the headline result, the monomer
//! card and parameters, what the scene shows, its numbers, and comparing
//! (pins and families).

use super::Cx;
use super::controls::{self, Select};
use crate::app::command::{Command, Sweep};
use crate::figure;
use crate::scene::{self, ControlKind, SCENES};

/// The whole side panel.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    navigator(ui, cx, 230.0);
    let info = cx.state.params().info();
    ui.small(format!("{} · {}", scene::chapter(cx.state.index()).heading, info.source));
    headline(ui, cx);
    ui.separator();
    ui.label(egui::RichText::new("Parameters").strong());
    parameters(ui, cx);
    ui.separator();
    egui::CollapsingHeader::new("What this scene shows").default_open(false).show(ui, |ui| {
        ui.label(info.explanation);
        ui.small(format!("Thesis: {}", info.source));
    });
    scalars(ui, cx);
    ui.separator();
    compare(ui, cx);
}

/// The monomer card (where the scene has one) and the other parameters.
pub fn parameters(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    if cx.state.params().monomer_card().is_some() {
        super::monomer_card::show(ui, cx);
    }
    controls::show(ui, cx, Select::Parameters);
}

/// The scene navigator: previous / next buttons and a list grouped by
/// thesis chapter with the figures each scene reproduces.
pub fn navigator(ui: &mut egui::Ui, cx: &mut Cx<'_>, width: f32) {
    use crate::app::command::Action;
    ui.horizontal(|ui| {
        if ui.button("◀").on_hover_text("previous scene (Page Up)").clicked() {
            cx.send(Command::Act(Action::PreviousScene));
        }
        let here = cx.state.index();
        let label = ui.label("Scene");
        let entry = |i: usize| {
            let s = &SCENES[i];
            let figs = scene::figures_of(s);
            if figs.is_empty() { s.title.to_string() } else { format!("{} · {figs}", s.title) }
        };
        let mut chosen = None;
        egui::ComboBox::from_id_salt("scene-navigator")
            .width(width)
            .height(ui.ctx().content_rect().height() * 0.8)
            .selected_text(egui::RichText::new(SCENES[here].title).strong())
            .show_ui(ui, |ui| {
                for (chapter, list) in scene::scenes_by_chapter() {
                    ui.label(egui::RichText::new(chapter.heading).strong().underline());
                    for i in list {
                        if ui.selectable_label(i == here, entry(i)).clicked() {
                            chosen = Some(i);
                        }
                    }
                }
            })
            .response
            .labelled_by(label.id)
            .on_hover_text(format!("{} — {}", scene::chapter(here).heading, SCENES[here].source));
        if let Some(i) = chosen {
            cx.send(Command::OpenScene(i));
        }
        if ui.button("▶").on_hover_text("next scene (Page Down)").clicked() {
            cx.send(Command::Act(Action::NextScene));
        }
    });
}

/// The scene's headline result in large type.
pub fn headline(ui: &mut egui::Ui, cx: &Cx<'_>) {
    let Some(out) = cx.state.output() else { return };
    let text = match (out.scalar("e"), out.scalar("sticks"), out.scalar("v_stick")) {
        (Some(e), Some(s), _) => format!("e = {e:.4} ({})", if s > 0.5 { "sticks" } else { "bounces" }),
        // The search ends at 10⁴ m/s: above it the spheres stick at every speed tried.
        (_, _, Some(v)) if v.is_infinite() => "v_stick > 10⁴ m/s".to_string(),
        (_, _, Some(v)) => format!("v_stick = {} m/s", figure::tick_label(v)),
        // A short first note serves as the headline; a paragraph stays
        // among the notes below the parameters instead of pushing them
        // down.
        _ => out.notes.first().filter(|n| n.chars().count() <= 60).cloned().unwrap_or_default(),
    };
    if text.is_empty() {
        return;
    }
    ui.label(egui::RichText::new(text).size(20.0).strong());
}

/// The scene's numbers and notes.
pub fn scalars(ui: &mut egui::Ui, cx: &Cx<'_>) {
    let Some(out) = cx.state.output() else {
        ui.label("computing…");
        return;
    };
    let system = crate::scene::chapter(cx.state.index()).units();
    egui::Grid::new("scalars").num_columns(2).striped(true).show(ui, |ui| {
        for s in &out.scalars {
            ui.label(s.label);
            ui.label(crate::units::text(s.value, s.unit, system));
            ui.end_row();
        }
    });
    for n in &out.notes {
        ui.label(egui::RichText::new(n).italics());
    }
}

/// Pins and the family tool.
fn compare(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    ui.label(egui::RichText::new("Compare").strong());
    ui.horizontal(|ui| {
        if ui.button("Pin curves").on_hover_text("keep the current model curves while you change parameters").clicked()
        {
            cx.send(Command::Pin);
        }
        if ui.button("Clear pins").clicked() {
            cx.send(Command::ClearPins);
        }
    });
    let mut params = cx.state.params().clone();
    let keys: Vec<(&'static str, &'static str)> = params
        .controls()
        .iter()
        .filter(|c| matches!(c.kind, ControlKind::Number { .. }) && !c.style_only)
        .map(|c| (c.key, c.label))
        .collect();
    let mut sweep: Sweep = cx.state.sweep.clone();
    ui.horizontal(|ui| {
        let current = keys.iter().find(|k| k.0 == sweep.key).map_or("choose", |k| k.1);
        egui::ComboBox::from_label("sweep parameter").selected_text(current).show_ui(ui, |ui| {
            for (k, l) in &keys {
                ui.selectable_value(&mut sweep.key, k.to_string(), *l);
            }
        });
    });
    ui.horizontal(|ui| {
        ui.add(egui::DragValue::new(&mut sweep.from).speed(0.01).prefix("from "));
        ui.add(egui::DragValue::new(&mut sweep.to).speed(0.01).prefix("to "));
        ui.add(egui::DragValue::new(&mut sweep.steps).range(2..=12).prefix("n "));
    });
    if sweep != cx.state.sweep {
        cx.send(Command::SetSweep(sweep));
    }
    ui.small("sweep values are in SI units, log-spaced where the parameter is logarithmic");
    if ui.button("Draw family").clicked() {
        cx.send(Command::DrawFamily);
    }
    what_matters(ui, cx);
}

/// The "what matters" tool: a result of the scene and a factor.
fn what_matters(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let scalars: Vec<(&'static str, &'static str)> =
        cx.state.output().map(|o| o.scalars.iter().map(|s| (s.key, s.label)).collect()).unwrap_or_default();
    if scalars.is_empty() {
        return;
    }
    ui.add_space(4.0);
    let mut output = cx.state.matters.output.clone();
    if !scalars.iter().any(|s| s.0 == output) {
        output = scalars[0].0.to_string();
    }
    let mut factor = cx.state.matters.factor;
    ui.horizontal(|ui| {
        let current = scalars.iter().find(|s| s.0 == output).map_or("", |s| s.1);
        egui::ComboBox::from_label("result").selected_text(current).width(180.0).show_ui(ui, |ui| {
            for (k, l) in &scalars {
                ui.selectable_value(&mut output, k.to_string(), *l);
            }
        });
    });
    ui.horizontal(|ui| {
        ui.add(egui::DragValue::new(&mut factor).range(1.1..=10.0).speed(0.05).prefix("each parameter ×÷ "));
        if ui
            .button("What matters")
            .on_hover_text("every parameter's elasticity ∂ln X/∂ln p here, and X over the factor around it")
            .clicked()
        {
            cx.send(Command::SetMatters(output.clone(), factor));
            cx.send(Command::WhatMatters);
        }
    });
    if output != cx.state.matters.output || factor != cx.state.matters.factor {
        cx.send(Command::SetMatters(output, factor));
    }
}
