//! The side panel: the scene navigator, the headline result, the monomer
//! card and parameters, what the scene shows, its numbers, and comparing
//! (pins and families).

use super::Cx;
use super::controls::{self, Select};
use crate::app::command::{Action, Command, Sweep};
use crate::app::shortcuts::Mode;
use crate::figure;
use crate::scene::{self, SCENES};
use crate::sensitivity::Knob;

/// The whole side panel.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    // On a phone the navigator stays in the bar above the drawer.
    if !cx.memo.compact {
        navigator(ui, cx, 230.0);
    }
    let info = cx.state.params().info();
    ui.small(format!("{} · {}", scene::chapter(cx.state.index()).heading, info.source));
    if !cx.memo.compact {
        headline(ui, cx);
    }
    if let Some(note) = cx.state.lighter_note() {
        ui.add(egui::Label::new(egui::RichText::new(note).small().weak()).wrap());
    }
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
        if ui.button("◀").on_hover_text(crate::app::shortcuts::hint(Action::PreviousScene, Mode::Explorer)).clicked()
        {
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
        if ui.button("▶").on_hover_text(crate::app::shortcuts::hint(Action::NextScene, Mode::Explorer)).clicked() {
            cx.send(Command::Act(Action::NextScene));
        }
    });
}

/// The scene's headline result in large type.
pub fn headline(ui: &mut egui::Ui, cx: &Cx<'_>) {
    let Some(out) = cx.state.output() else { return };
    let text = match (out.scalar("e"), out.scalar("sticks"), out.scalar("v_stick")) {
        (Some(e), Some(s), _) => format!("e = {} ({})", figure::human(e), if s > 0.5 { "sticks" } else { "bounces" }),
        // The search ends at 10⁴ m/s: above it the spheres stick at every speed tried.
        (_, _, Some(v)) if v.is_infinite() => "v_stick > 10⁴ m/s".to_string(),
        (_, _, Some(v)) => format!("v_stick = {} m/s", figure::human(v)),
        // A short first note serves as the headline; a paragraph stays
        // among the notes below the parameters instead of pushing them
        // down.
        _ => out.notes.first().filter(|n| n.chars().count() <= 60).cloned().unwrap_or_default(),
    };
    if text.is_empty() {
        return;
    }
    ui.add(egui::Label::new(egui::RichText::new(text).size(20.0).strong()).wrap());
}

/// The scene's numbers and notes.
pub fn scalars(ui: &mut egui::Ui, cx: &Cx<'_>) {
    let Some(out) = cx.state.output() else {
        ui.label("computing…");
        return;
    };
    let system = crate::scene::chapter(cx.state.index()).units();
    let censored = cx.state.params().censored();
    // A bound reads "> 10⁴ m/s", an undefined value "undefined"; hovering
    // either says why.
    let values: Vec<(String, Option<&str>)> = out
        .scalars
        .iter()
        .map(|s| match crate::scene::status(censored, s.key, s.value) {
            crate::scene::Status::Value => (crate::units::text(s.value, s.unit, system), None),
            crate::scene::Status::Above { bound, why } => {
                (format!("> {}", crate::units::text(bound, s.unit, system)), Some(why))
            }
            crate::scene::Status::Undefined { why } => ("undefined".to_string(), Some(why)),
        })
        .collect();
    // The values (with their units) are never cut: the names wrap in the
    // width the widest value leaves them.
    let font = egui::TextStyle::Body.resolve(ui.style());
    let widest = values
        .iter()
        .map(|(v, _)| ui.painter().layout_no_wrap(v.clone(), font.clone(), egui::Color32::WHITE).size().x)
        .fold(0.0, f32::max);
    let spacing = ui.spacing().item_spacing.x;
    let names = (ui.available_width() - widest - spacing - 4.0).max(60.0);
    egui::Grid::new("scalars").num_columns(2).striped(true).show(ui, |ui| {
        for (s, (value, why)) in out.scalars.iter().zip(values) {
            ui.scope(|ui| {
                ui.set_max_width(names);
                ui.add(egui::Label::new(s.label).wrap());
            });
            let shown = ui.label(value);
            if let Some(why) = why {
                shown.on_hover_text(why);
            }
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
        if ui.button("Pin curves").on_hover_text(crate::app::shortcuts::hint(Action::Pin, Mode::Explorer)).clicked() {
            cx.send(Command::Pin);
        }
        if ui
            .button("Clear pins")
            .on_hover_text(crate::app::shortcuts::hint(Action::ClearPins, Mode::Explorer))
            .clicked()
        {
            cx.send(Command::ClearPins);
        }
    });
    let knobs = crate::sensitivity::knobs(cx.state.params());
    // A range around the parameter's value: ×÷ 3 on a log scale, ± a
    // quarter of its range otherwise, inside the documented range.
    let around = |k: &Knob, steps: usize| {
        let (from, to) = if k.log && k.value > 0.0 {
            ((k.value / 3.0).max(k.min), (k.value * 3.0).min(k.max))
        } else {
            let half = 0.25 * (k.max - k.min).min(k.value.abs().max(1e-300) * 4.0);
            ((k.value - half).max(k.min), (k.value + half).min(k.max))
        };
        Sweep { key: k.key.to_string(), from, to, steps }
    };
    let mut sweep: Sweep = cx.state.sweep.clone();
    // A form left from another scene starts again from this scene's first parameter.
    let mut knob = knobs.iter().find(|k| k.key == sweep.key);
    if knob.is_none()
        && let Some(first) = knobs.first()
    {
        sweep = around(first, sweep.steps);
        knob = Some(first);
    }
    ui.horizontal(|ui| {
        let current = knob.map_or("choose", |k| k.label);
        egui::ComboBox::from_label("sweep parameter").selected_text(current).show_ui(ui, |ui| {
            for k in &knobs {
                if ui.selectable_label(k.key == sweep.key, k.label).clicked() && k.key != sweep.key {
                    sweep = around(k, sweep.steps);
                }
            }
        });
    });
    let (scale, unit) =
        knobs.iter().find(|k| k.key == sweep.key).map_or((1.0, ""), |k| (k.display_scale, k.shown_unit));
    let suffix = if unit.is_empty() { String::new() } else { format!(" {}", crate::units::pretty(unit)) };
    ui.horizontal(|ui| {
        // Shown in the parameter's display unit, kept in SI.
        let (mut from, mut to) = (sweep.from * scale, sweep.to * scale);
        if ui.add(sweep_field(&mut from, "from ", &suffix, unit)).changed() {
            sweep.from = from / scale;
        }
        if ui.add(sweep_field(&mut to, "to ", &suffix, unit)).changed() {
            sweep.to = to / scale;
        }
        ui.add(egui::DragValue::new(&mut sweep.steps).range(2..=12).prefix("n "));
    });
    if sweep != cx.state.sweep {
        cx.send(Command::SetSweep(sweep));
    }
    ui.small("log-spaced where the parameter is logarithmic");
    if ui.button("Draw family").clicked() {
        cx.send(Command::DrawFamily);
    }
    what_matters(ui, cx);
}

/// A sweep end in the parameter's display unit: three digits, and a typed
/// value may name its unit.
fn sweep_field<'a>(v: &'a mut f64, prefix: &str, suffix: &str, unit: &'static str) -> egui::DragValue<'a> {
    egui::DragValue::new(v)
        .speed(0.01)
        .prefix(prefix)
        .suffix(suffix)
        .custom_formatter(|v, _| figure::human(v))
        .custom_parser(move |t| crate::units::parse_in(t, unit).ok())
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
        // The label first, the choice in the rest of the line, cut if long.
        let label = ui.label("result");
        let width = (ui.available_width() - 8.0).max(120.0);
        egui::ComboBox::from_id_salt("matters-result")
            .selected_text(current)
            .width(width)
            .truncate()
            .show_ui(ui, |ui| {
                for (k, l) in &scalars {
                    ui.selectable_value(&mut output, k.to_string(), *l);
                }
            })
            .response
            .labelled_by(label.id);
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
