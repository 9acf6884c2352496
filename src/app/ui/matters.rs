//! The sensitivity view: for one result of the open scene, every
//! parameter's elasticity ∂ln X/∂ln p at the current point and the result's
//! range over a factor around each parameter's value, sorted, as a tornado
//! chart with the numbers beside it; below it the result over one
//! parameter's whole range (a curve) or two (a map).

use super::Cx;
use crate::app::command::Command;
use crate::figure::human;
use crate::units;

/// Blue for the parameter divided by the factor, orange for multiplied.
const LOW: egui::Color32 = egui::Color32::from_rgb(0, 114, 178);
const HIGH: egui::Color32 = egui::Color32::from_rgb(230, 159, 0);

/// The view, as a window, while it is open.
pub fn window(ctx: &egui::Context, cx: &mut Cx<'_>) {
    let m = &cx.state.matters;
    if !m.open {
        return;
    }
    let lecture = cx.state.session.lecture;
    let text = super::look::body_size(lecture);
    let factor = m.factor;
    let scalars: Vec<(&'static str, &'static str, &'static str)> =
        cx.state.output().map(|o| o.scalars.iter().map(|s| (s.key, s.label, s.unit)).collect()).unwrap_or_default();
    let mut params: Vec<(&'static str, &'static str)> = Vec::new();
    for s in cx.state.params().specs() {
        if matches!(s.kind, crate::scene::schema::SpecKind::Number { .. }) && !s.style_only {
            params.push((s.key, s.label));
        }
    }
    let (mut output, mut x, mut y) = (m.output.clone(), m.x.clone(), m.y.clone());
    let unit = scalars.iter().find(|s| s.0 == output).map_or("", |s| s.2);
    let system = crate::scene::chapter(cx.state.index()).units();
    let mut open = true;
    let mut clicked: Option<String> = None;
    let (mut recompute, mut draw, mut export) = (false, false, false);
    let mut tab: Option<bool> = None;
    egui::Window::new("Sensitivity")
        .open(&mut open)
        .default_width(640.0)
        .default_height(0.85 * ctx.content_rect().height())
        .collapsible(true)
        .resizable(true)
        .vscroll(true)
        .show(ctx, |ui| {
            ui.horizontal_wrapped(|ui| {
                let shown = scalars.iter().find(|s| s.0 == output).map_or(output.clone(), |s| s.1.to_string());
                let label = ui.label(egui::RichText::new("What moves").size(text));
                egui::ComboBox::from_id_salt("sensitivity-output")
                    .selected_text(shown)
                    .width(220.0)
                    .show_ui(ui, |ui| {
                        for (k, l, _) in &scalars {
                            ui.selectable_value(&mut output, k.to_string(), *l);
                        }
                    })
                    .response
                    .labelled_by(label.id);
                recompute |= ui.button("Recompute").on_hover_text(format!("the chart for this result at the current parameters ({})", crate::app::shortcuts::keys(crate::app::command::Action::Sensitivity, crate::app::shortcuts::Mode::Explorer))).clicked();
                export |= ui
                    .button("Export")
                    .on_hover_text("the chart's table (CSV) and the curve or map (PNG, SVG, CSV) to the export folder; opening any of them reopens this view")
                    .clicked();
            });
            ui.horizontal_wrapped(|ui| {
                let name = |k: &str| params.iter().find(|p| p.0 == k).map_or("(choose)".to_string(), |p| p.1.to_string());
                let label = ui.label(egui::RichText::new("Across").size(text));
                egui::ComboBox::from_id_salt("sensitivity-x")
                    .selected_text(name(&x))
                    .width(170.0)
                    .show_ui(ui, |ui| {
                        for (k, l) in &params {
                            ui.selectable_value(&mut x, k.to_string(), *l);
                        }
                    })
                    .response
                    .labelled_by(label.id);
                let label = ui.label(egui::RichText::new("and").size(text));
                let shown_y = if y.is_empty() { "— (a curve)".to_string() } else { name(&y) };
                egui::ComboBox::from_id_salt("sensitivity-y")
                    .selected_text(shown_y)
                    .width(170.0)
                    .show_ui(ui, |ui| {
                        ui.selectable_value(&mut y, String::new(), "— (a curve)");
                        for (k, l) in &params {
                            ui.selectable_value(&mut y, k.to_string(), *l);
                        }
                    })
                    .response
                    .labelled_by(label.id);
                draw |= ui
                    .add_enabled(!x.is_empty(), egui::Button::new("Draw"))
                    .on_hover_text("the result over the whole range of one parameter (a curve) or two (a map)")
                    .clicked();
            });
            ui.horizontal(|ui| {
                if ui.selectable_label(!m.figure, egui::RichText::new("What matters").size(text)).clicked() {
                    tab = Some(false);
                }
                if ui.selectable_label(m.figure, egui::RichText::new("Curve or map").size(text)).clicked() {
                    tab = Some(true);
                }
            });
            ui.separator();
            if m.figure {
                if let Some((at, fig)) = &m.curve {
                    if at != cx.state.params() {
                        ui.colored_label(ui.visuals().warn_fg_color, "drawn for earlier parameters");
                    }
                    let look = super::look::plot_look(ui, lecture);
                    let height = (0.62 * ctx.content_rect().height()).clamp(260.0, 620.0);
                    let size = egui::vec2(ui.available_width().max(300.0), height);
                    super::plot::show(ui, fig, &super::plot::Overlay::default(), size, false, look, None);
                    if fig.heatmap.as_ref().is_some_and(|h| h.values.iter().any(|v| !v.is_finite()))
                        || fig.series.iter().any(|s| s.name.is_empty() && s.style == crate::figure::Style::Line)
                    {
                        ui.small("blank or broken where the result is undefined (e.g. the spheres stick at every velocity)");
                    }
                } else if m.x.is_empty() {
                    ui.label(egui::RichText::new("choose a parameter under “Across” (or click one in the chart)").size(text));
                } else {
                    ui.label(egui::RichText::new(format!("drawing… {:.0} %", 100.0 * cx.work.progress)).size(text));
                }
            } else {
                match &m.result {
                    None => {
                        ui.label(egui::RichText::new("computing…").size(text));
                    }
                    Some((at, answer)) => {
                        if at != cx.state.params() {
                            ui.colored_label(
                                ui.visuals().warn_fg_color,
                                "the parameters changed since: press “What matters” again for the current point",
                            );
                        }
                        // The mean in the chapter's units; σ scaled alike.
                        let shown = answer.here.mean.map(|v| units::show(v, unit, system));
                        let scale = match (answer.here.mean, &shown) {
                            (Some(v), Some(s)) if v != 0.0 && v.is_finite() => s.value / v,
                            _ => 1.0,
                        };
                        let (here, shown_unit) =
                            shown.map_or(("undefined".to_string(), String::new()), |s| (human(s.value), s.unit));
                        let noise = match answer.here.sd {
                            Some(sd) => format!(" ± {} (σ over {} seeds)", human(sd * scale), answer.here.runs),
                            None => String::new(),
                        };
                        ui.label(
                            egui::RichText::new(format!(
                                "here {here}{noise} {shown_unit}; each parameter ×÷ {}",
                                human(factor)
                            ))
                            .size(text),
                        );
                        if m.coarse {
                            ui.colored_label(
                                ui.visuals().warn_fg_color,
                                egui::RichText::new(format!(
                                    "coarse first answer (the scene's quick preview settings); the full one is {:.0} % computed",
                                    100.0 * cx.work.progress
                                ))
                                .size(text),
                            );
                        }
                        // Each parameter in its control's own display unit.
                        let mut params = at.clone();
                        let shown_as: Vec<(&'static str, &'static str, f64)> = params
                            .controls()
                            .iter()
                            .filter_map(|c| match c.kind {
                                crate::scene::ControlKind::Number { display_scale, .. } => {
                                    Some((c.key, c.unit, display_scale))
                                }
                                _ => None,
                            })
                            .collect();
                        if let Some(key) =
                            chart(ui, &answer.rows, answer.here.mean.unwrap_or(0.0), text, system, &shown_as)
                        {
                            clicked = Some(key);
                        }
                    }
                }
                ui.small(
                    "elasticity ∂ln X/∂ln p at the current value (? where steps of 1 % and 0.5 % disagree: a jump or \
                     noise); bars: X with the parameter divided (blue) and multiplied (orange) by the factor, \
                     within its range, on a log scale of X/X₀; sorted by the change of X. Monte Carlo results are \
                     means over the seeds, with σ; “~” marks an effect below that noise. Click a parameter to draw X \
                     against it over its whole range.",
                );
            }
        });
    if !open {
        cx.send(Command::CloseMatters);
        return;
    }
    if output != cx.state.matters.output {
        cx.send(Command::SetMatters(output, factor));
        cx.send(Command::WhatMatters);
    } else if recompute {
        cx.send(Command::WhatMatters);
    }
    if let Some(key) = clicked {
        cx.send(Command::DrawSensitivity(key, String::new()));
    } else if draw && !x.is_empty() {
        let y = if y == x { String::new() } else { y };
        cx.send(Command::DrawSensitivity(x, y));
    }
    if export {
        cx.send(Command::ExportSensitivity);
    }
    if let Some(on) = tab {
        cx.send(Command::MattersFigure(on));
    }
}

/// The tornado chart with a row of numbers per parameter.
/// Returns the key of a parameter whose name was clicked (to draw X against it).
fn chart(
    ui: &mut egui::Ui,
    rows: &[crate::sensitivity::Influence],
    x0: f64,
    text: f32,
    system: units::System,
    shown_as: &[(&'static str, &'static str, f64)],
) -> Option<String> {
    let mut clicked = None;
    // Log scale of X/X₀ where every value is positive, else linear in X − X₀.
    let positive = x0 > 0.0 && rows.iter().flat_map(|r| r.range.iter().flatten()).all(|&x| x > 0.0);
    let pos = |x: f64| if positive { (x / x0).ln() } else { x - x0 };
    let reach = rows.iter().flat_map(|r| r.range.iter().flatten()).map(|&x| pos(x).abs()).fold(0.0_f64, f64::max);
    let reach = if reach > 0.0 { reach } else { 1.0 };
    let bar_width = 220.0;
    egui::Grid::new("matters").num_columns(4).spacing([10.0, 3.0]).striped(true).show(ui, |ui| {
        for h in ["parameter", "value", "elasticity", "X over the range"] {
            ui.label(egui::RichText::new(h).strong().size(text));
        }
        ui.end_row();
        for r in rows {
            if ui
                .link(egui::RichText::new(&r.label).size(text))
                .on_hover_text(format!("{}: click to draw X against it over its whole range", r.key))
                .clicked()
            {
                clicked = Some(r.key.clone());
            }
            // As the parameter's control shows it; in the chapter's units otherwise.
            let value = match shown_as.iter().find(|(key, ..)| *key == r.key) {
                Some((_, "", scale)) => human(r.value * scale),
                Some((_, unit, scale)) => format!("{} {}", human(r.value * scale), units::pretty(unit)),
                None => units::text(r.value, &r.unit, system),
            };
            ui.label(egui::RichText::new(value).size(text));
            let e = match r.elasticity {
                Some(e) if e.abs() < 5e-4 => "0".to_string(),
                Some(e) => format!("{e:+.3}{}", if r.converged { "" } else { " ?" }),
                None => "—".to_string(),
            };
            let e = if r.below_noise { format!("~ {e}") } else { e };
            ui.label(egui::RichText::new(e).size(text).monospace());
            let (rect, resp) = ui.allocate_exact_size(egui::vec2(bar_width, text + 2.0), egui::Sense::hover());
            let painter = ui.painter_at(rect);
            let x_of = |v: f64| rect.center().x + (v / reach) as f32 * (bar_width / 2.0 - 2.0);
            for (x, colour) in [(r.range[0], LOW), (r.range[1], HIGH)] {
                if let Some(x) = x {
                    let (a, b) = (x_of(0.0), x_of(pos(x)));
                    let bar = egui::Rect::from_x_y_ranges(
                        a.min(b)..=a.max(b).max(a.min(b) + 1.0),
                        rect.y_range().shrink(2.0),
                    );
                    painter.rect_filled(bar, 1.0, colour);
                }
            }
            painter.vline(rect.center().x, rect.y_range(), ui.visuals().widgets.noninteractive.fg_stroke);
            let range = |x: Option<f64>, why: &str| {
                x.map_or_else(|| if why.is_empty() { "undefined".to_string() } else { why.to_string() }, human)
            };
            let sd = |s: Option<f64>| s.map_or(String::new(), |s| format!(" ± {}", human(s)));
            let noise = if r.below_noise { " (below the noise of the seeds)" } else { "" };
            resp.on_hover_text(format!(
                "X = {}{} at p ÷ factor, {} here, {}{} at p × factor{noise}",
                range(r.range[0], &r.range_status[0]),
                sd(r.range_sd[0]),
                human(x0),
                range(r.range[1], &r.range_status[1]),
                sd(r.range_sd[1])
            ));
            ui.end_row();
        }
    });
    clicked
}
