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
    let lecture = cx.lecture();
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
    let mut whole_tab = false;
    let mut study = m.whole.study.clone();
    let mut run_whole = false;
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
                let (chart, curve) = (!m.figure && !m.whole_tab, m.figure && !m.whole_tab);
                if ui.selectable_label(chart, egui::RichText::new("What matters").size(text)).clicked() {
                    tab = Some(false);
                }
                if ui.selectable_label(curve, egui::RichText::new("Curve or map").size(text)).clicked() {
                    tab = Some(true);
                }
                if ui
                    .selectable_label(m.whole_tab, egui::RichText::new("Whole ranges").size(text))
                    .on_hover_text("Morris's elementary effects or Sobol' indices of the result over every chosen parameter's whole range")
                    .clicked()
                {
                    whole_tab = true;
                }
            });
            ui.separator();
            if m.whole_tab {
                if let Some(s) = study.as_mut() {
                    let view = WholeView { text, progress: cx.work.progress, params: cx.state.params(), output: &output };
                    let (run, click) = whole(ui, s, &m.whole, &view);
                    run_whole = run;
                    if click.is_some() {
                        clicked = click;
                    }
                }
            } else if m.figure {
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
                     within its range, on a log scale of X/X₀; sorted by the change of X, the physics first, then \
                     the numerical resolutions (a converged answer does not depend on them). Monte Carlo results \
                     are means over the seeds, with σ; “~” marks an effect below that noise. Click a parameter to \
                     draw X against it over its whole range.",
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
    if whole_tab {
        cx.send(Command::MattersWhole(true));
    }
    if let Some(s) = study
        && Some(&s) != cx.state.matters.whole.study.as_ref()
    {
        cx.send(Command::SetWholeRange(Box::new(s)));
    }
    if run_whole {
        cx.send(Command::RunWholeRange);
    }
}

/// What the whole-ranges tab shows besides the study.
struct WholeView<'a> {
    text: f32,
    progress: f64,
    params: &'a crate::scene::SceneParams,
    output: &'a str,
}

/// The whole-ranges tab: the method, the parameters with their ranges (in
/// their controls' units), and the indices as the runs come in. Returns
/// whether Run was pressed and a parameter whose name was clicked.
fn whole(
    ui: &mut egui::Ui,
    study: &mut crate::sensitivity::WholeRange,
    w: &crate::app::state::Whole,
    view: &WholeView<'_>,
) -> (bool, Option<String>) {
    use crate::global_sensitivity::{Factor, Method};
    use crate::scene::schema::SpecKind;
    let text = view.text;
    let mut run = false;
    let mut clicked = None;
    ui.horizontal_wrapped(|ui| {
        let morris = matches!(study.design.method, Method::Morris { .. });
        if ui.selectable_label(morris, egui::RichText::new("Morris").size(text)).clicked() && !morris {
            study.design.method = Method::Morris { trajectories: 20, levels: 4 };
        }
        if ui.selectable_label(!morris, egui::RichText::new("Sobol'").size(text)).clicked() && morris {
            study.design.method = Method::Sobol { samples: 256, second_order: false };
        }
        match &mut study.design.method {
            Method::Morris { trajectories, .. } => {
                ui.label(egui::RichText::new("trajectories r").size(text));
                ui.add(egui::DragValue::new(trajectories).range(2..=200));
            }
            Method::Sobol { samples, .. } => {
                ui.label(egui::RichText::new("base samples N").size(text));
                let mut power = (*samples).max(2).ilog2();
                ui.add(
                    egui::DragValue::new(&mut power)
                        .range(1..=14)
                        .custom_formatter(|p, _| format!("{}", 1u64 << p as u32)),
                );
                *samples = 1usize << power;
            }
            Method::Given { .. } => {}
        }
        ui.checkbox(&mut study.log_output, egui::RichText::new("ln X").size(text))
            .on_hover_text("analyse the logarithm of the result: effects become relative changes");
        let runs = study.design.runs();
        run = ui
            .add_enabled(
                !w.running && !study.design.factors.is_empty(),
                egui::Button::new(format!("Run ({runs} runs)")),
            )
            .on_hover_text(
                "compute the runs at the current parameters; the indices fill in as they finish (Cancel below stops)",
            )
            .clicked();
    });
    ui.label(egui::RichText::new("Parameters and their ranges").strong().size(text));
    let factors = &mut study.design.factors;
    egui::Grid::new("whole-factors").num_columns(4).spacing([8.0, 2.0]).striped(true).show(ui, |ui| {
        for s in view.params.specs().iter().filter(|s| !s.style_only && !s.figure_only) {
            let SpecKind::Number { min, max, log, display_scale } = s.kind else { continue };
            if !(min < max && min.is_finite() && max.is_finite()) {
                continue;
            }
            let at = factors.iter().position(|f| f.key == s.key);
            let mut on = at.is_some();
            if ui.checkbox(&mut on, egui::RichText::new(s.label).size(text)).on_hover_text(s.doc).changed() {
                match at {
                    Some(k) if !on => {
                        factors.remove(k);
                    }
                    None if on => {
                        factors.push(Factor { key: s.key.to_string(), log: log && min > 0.0, from: min, to: max })
                    }
                    _ => {}
                }
            }
            let unit = units::pretty(s.unit);
            match factors.iter_mut().find(|f| f.key == s.key) {
                Some(f) => {
                    let (lo, hi) = (min * display_scale, max * display_scale);
                    let mut a = f.from * display_scale;
                    let mut b = f.to * display_scale;
                    ui.horizontal(|ui| {
                        ui.add(range_end(&mut a, lo, hi));
                        ui.label("…");
                        ui.add(range_end(&mut b, lo, hi));
                        ui.label(unit);
                    });
                    if a < b {
                        f.from = (a / display_scale).clamp(min, max);
                        f.to = (b / display_scale).clamp(min, max);
                    }
                    ui.checkbox(&mut f.log, "log").on_hover_text("uniform in the logarithm");
                    f.log &= f.from > 0.0;
                }
                None => {
                    ui.label(
                        egui::RichText::new(format!(
                            "{} … {} {unit}",
                            human(min * display_scale),
                            human(max * display_scale)
                        ))
                        .weak(),
                    );
                    ui.label("");
                }
            }
            ui.end_row();
        }
    });
    ui.separator();
    let stale = w.at.as_ref().is_some_and(|(p, o, _)| p != view.params || o != view.output);
    if stale {
        ui.colored_label(
            ui.visuals().warn_fg_color,
            "computed for other parameters or another result: Run again for these",
        );
    }
    if w.running {
        let total = study.design.runs().max(1);
        ui.colored_label(
            ui.visuals().warn_fg_color,
            egui::RichText::new(format!(
                "provisional: {} of {total} runs done; the indices below are those of the runs done so far",
                w.values.len()
            ))
            .size(text),
        );
        ui.add(egui::ProgressBar::new(((w.values.len() as f64 + view.progress) / total as f64) as f32));
    }
    let Some(answer) = &w.answer else {
        if !w.running {
            ui.label(
                egui::RichText::new("press Run: the indices appear after two trajectories or base samples").size(text),
            );
        }
        return (run, clicked);
    };
    let names: Vec<(String, String)> = w
        .study
        .as_ref()
        .map(|s| {
            s.design
                .factors
                .iter()
                .map(|f| {
                    let label = view.params.spec(&f.key).map_or(f.key.clone(), |s| s.label.to_string());
                    (f.key.clone(), label)
                })
                .collect()
        })
        .unwrap_or_default();
    ui.label(
        egui::RichText::new(format!(
            "{} runs analysed; {} undefined (left out), {} at a bound (entered at it)",
            answer.runs, answer.undefined, answer.bounded
        ))
        .size(text),
    );
    let bar = |ui: &mut egui::Ui, v: f64, conf: f64, reach: f64, colour: egui::Color32| {
        let width = 180.0;
        let (rect, resp) = ui.allocate_exact_size(egui::vec2(width, text + 2.0), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        let x = |v: f64| rect.left() + ((v / reach).clamp(0.0, 1.0) as f32) * (width - 2.0);
        if v.is_finite() {
            painter.rect_filled(
                egui::Rect::from_x_y_ranges(rect.left()..=x(v).max(rect.left() + 1.0), rect.y_range().shrink(3.0)),
                1.0,
                colour,
            );
            if conf.is_finite() {
                let y = rect.center().y;
                painter.hline(x(v - conf)..=x(v + conf), y, ui.visuals().widgets.noninteractive.fg_stroke);
            }
        }
        resp.on_hover_text(format!("{} ± {}", human(v), human(conf)));
    };
    let mut click = |ui: &mut egui::Ui, key: &str, label: &str| {
        if ui
            .link(egui::RichText::new(label).size(text))
            .on_hover_text("click to draw X against it over its whole range")
            .clicked()
        {
            clicked = Some(key.to_string());
        }
    };
    if let Some(morris) = &answer.morris {
        let reach =
            morris.iter().map(|m| m.mu_star + m.mu_star_conf).filter(|v| v.is_finite()).fold(0.0, f64::max).max(1e-300);
        // Largest μ* first.
        let order = crate::sorting::order(&morris.iter().map(|m| -m.mu_star).collect::<Vec<_>>());
        egui::Grid::new("whole-morris").num_columns(5).spacing([10.0, 3.0]).striped(true).show(ui, |ui| {
            for h in ["parameter", "μ*", "μ", "σ", "μ* with its 95 % interval"] {
                ui.label(egui::RichText::new(h).strong().size(text));
            }
            ui.end_row();
            for &k in &order {
                let (key, label) = names.get(k).cloned().unwrap_or_default();
                let m = &morris[k];
                click(ui, &key, &label);
                for v in [m.mu_star, m.mu, m.sigma] {
                    ui.label(egui::RichText::new(human(v)).size(text).monospace());
                }
                bar(ui, m.mu_star, m.mu_star_conf, reach, HIGH);
                ui.end_row();
            }
        });
        ui.small("μ*: mean absolute elementary effect (importance); σ: their spread (σ ≳ μ*: interactions or a curved response)");
    }
    if let Some(sobol) = &answer.sobol {
        // Largest total index first.
        let order = crate::sorting::order(&sobol.indices.iter().map(|i| -i.total).collect::<Vec<_>>());
        egui::Grid::new("whole-sobol").num_columns(5).spacing([10.0, 3.0]).striped(true).show(ui, |ui| {
            for h in ["parameter", "S1", "ST", "S1 (blue) with its interval", "ST (orange) with its interval"] {
                ui.label(egui::RichText::new(h).strong().size(text));
            }
            ui.end_row();
            for &k in &order {
                let (key, label) = names.get(k).cloned().unwrap_or_default();
                let s = &sobol.indices[k];
                click(ui, &key, &label);
                ui.label(
                    egui::RichText::new(format!("{} ± {}", human(s.first), human(s.first_conf))).size(text).monospace(),
                );
                ui.label(
                    egui::RichText::new(format!("{} ± {}", human(s.total), human(s.total_conf))).size(text).monospace(),
                );
                bar(ui, s.first, s.first_conf, 1.0, LOW);
                bar(ui, s.total, s.total_conf, 1.0, HIGH);
                ui.end_row();
            }
        });
        ui.small(format!(
            "S1: the share of the variance of X from the parameter alone; ST: with all its interactions ({} base samples used, {} left out)",
            sobol.samples, sobol.dropped
        ));
    }
    (run, clicked)
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
        for (i, r) in rows.iter().enumerate() {
            if r.numerical && (i == 0 || !rows[i - 1].numerical) {
                ui.label(egui::RichText::new("numerical resolution").italics().size(text))
                    .on_hover_text(crate::sensitivity::NUMERICAL_HEADING);
                ui.end_row();
            }
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

/// A typed end of a parameter's range, in its control's unit, within `lo..=hi`.
fn range_end(v: &mut f64, lo: f64, hi: f64) -> egui::DragValue<'_> {
    egui::DragValue::new(v).range(lo..=hi).speed(0.0).custom_formatter(|x, _| human(x))
}
