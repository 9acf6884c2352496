//! The figure area: the open scene's figures laid out as panels (a lead
//! figure, small multiples, or one panel alone with a strip to pick it), with pins, the time
//! cursor and the inspected point drawn over them, a ladder of linked
//! numbers or the contact sketch beside them, and their export buttons.

use super::plot;
use super::{Cx, sketch};
use crate::app::command::{Command, Field};
use crate::app::state::AppState;
use crate::figure::{self, Figure, Series, Style, View};
use crate::scene::{self, Extra};
use std::sync::Arc;

/// The figures, with a scene's ladder of linked numbers beside them.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let ladder = match cx.state.output().map(|o| &o.extra) {
        Some(Extra::Ladder(rungs)) => Some(Arc::clone(rungs)),
        _ => None,
    };
    let Some(rungs) = ladder else {
        panels(ui, cx, None);
        return;
    };
    let avail = ui.available_size();
    let width = (0.3 * avail.x).clamp(250.0, 440.0);
    // Where the figures beside the ladder would be narrower than a legible
    // panel, the ladder is one more panel among them.
    if avail.x - width < 440.0 {
        panels(ui, cx, Some(rungs));
        return;
    }
    let text = super::look::body_size(cx.lecture());
    // The figure shown alone (a slide's enlarged one, or the user's pick):
    // its rung is scrolled into view.
    let alone = match &cx.state.presenter {
        Some(p) => p.panel.clone(),
        None => cx.state.session.panels.get(cx.state.params().info().id).cloned(),
    };
    ui.horizontal_top(|ui| {
        ui.allocate_ui_with_layout(egui::vec2(width, avail.y), egui::Layout::top_down(egui::Align::Min), |ui| {
            ui.set_width(width);
            egui::ScrollArea::vertical()
                .id_salt("ladder")
                .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
                .show(ui, |ui| ladder_panel(ui, &rungs, text, alone.as_deref()));
        });
        ui.vertical(|ui| panels(ui, cx, None));
    });
}

/// The identifier of the contact sketch among a scene's panels.
const SKETCH: &str = "contact-sketch";
/// The identifier of a scene's ladder where it is one of the panels.
const LADDER: &str = "scale-ladder";
/// Height of the strip that picks the panel shown.
const STRIP: f32 = 30.0;

/// The strip of a multi-panel scene: every panel at once, or one of them
/// alone (the one shown, if any, highlighted). Returns the choice clicked.
fn strip(
    ui: &mut egui::Ui,
    ids: &[(String, String)],
    alone: Option<usize>,
    fits: bool,
    lecture: bool,
    compact: bool,
) -> Option<Command> {
    let text = super::look::body_size(lecture);
    let mut picked = None;
    // Titles shortened to fit a tab, in full where two would read alike.
    let short = |title: &str| -> String {
        if title.chars().count() > 44 {
            format!("{}…", title.chars().take(43).collect::<String>().trim_end())
        } else {
            title.to_string()
        }
    };
    let shorts: Vec<String> = ids.iter().map(|(_, t)| short(t)).collect();
    let names: Vec<String> = ids
        .iter()
        .zip(&shorts)
        .map(|((_, t), s)| if shorts.iter().filter(|o| *o == s).count() > 1 { t.clone() } else { s.clone() })
        .collect();
    // Many panels (a grid of experiments), or a phone's width: a menu
    // instead of a strip of tabs.
    if ids.len() > 4 || compact {
        ui.horizontal(|ui| {
            let label = ui.label(egui::RichText::new("Show").size(text));
            let shown = alone.and_then(|k| names.get(k).cloned()).unwrap_or_else(|| "all panels".into());
            egui::ComboBox::from_id_salt("panel-choice")
                .selected_text(egui::RichText::new(shown).size(text))
                .width(ui.available_width().min(420.0))
                .show_ui(ui, |ui| {
                    if ui.selectable_label(alone.is_none(), "all panels").clicked() {
                        picked = Some(Command::ShowPanel(crate::session::ALL_PANELS.into()));
                    }
                    for (k, ((id, _), name)) in ids.iter().zip(&names).enumerate() {
                        if ui.selectable_label(alone == Some(k), name).clicked() {
                            picked = Some(Command::ShowPanel(id.clone()));
                        }
                    }
                })
                .response
                .labelled_by(label.id);
        });
        return picked;
    }
    ui.horizontal_wrapped(|ui| {
        let all = ui
            .selectable_label(alone.is_none(), egui::RichText::new("All panels").size(text))
            .on_hover_text(if fits { "every panel at once" } else { "every panel at once (small on this screen)" });
        if all.clicked() {
            picked = Some(Command::ShowPanel(crate::session::ALL_PANELS.into()));
        }
        ui.separator();
        for (k, ((id, title), name)) in ids.iter().zip(&names).enumerate() {
            let r = ui
                .selectable_label(alone == Some(k), egui::RichText::new(name).size(text))
                .on_hover_text(format!("{title}: this panel alone, across the whole figure area"));
            if r.clicked() {
                picked = Some(Command::ShowPanel(id.clone()));
            }
        }
    });
    picked
}

/// The "Lock axes" switch: keeps every plot's range while parameters change.
fn lock_axes(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let mut lock = cx.state.locked.is_some();
    if ui
        .checkbox(&mut lock, "Lock axes")
        .on_hover_text("keep every plot's range while parameters change (double-click a plot to reset a zoom)")
        .changed()
    {
        cx.send(Command::LockAxes(cx.state.lock_views(lock)));
    }
}

fn panels(ui: &mut egui::Ui, cx: &mut Cx<'_>, ladder: Option<Arc<Vec<scene::Rung>>>) {
    let state = cx.state;
    let Some(out) = state.outputs[state.index()].clone() else {
        // A still word, not a spinner: a spinner asks for a new frame every
        // frame, and a page that draws without a GPU pays for each with a
        // core its workers compute on (Fig. 5.9's formation zone took 15.7 s
        // instead of 14.6 s in a browser with one turning until its first
        // picture). The progress bar below moves at the window's own pace.
        ui.centered_and_justified(|ui| ui.label(egui::RichText::new("computing…").weak()));
        return;
    };
    for warning in &out.warnings {
        let text = egui::RichText::new(format!("Warning: {warning}")).color(ui.visuals().warn_fg_color).strong();
        ui.add(egui::Label::new(text).wrap());
    }
    let lecture = cx.lecture();
    let compact = cx.memo.compact;
    if compact {
        // A phone: the transport on lines of its own, no axis lock (a
        // swipe over a plot scrolls rather than pans).
        super::transport::row(ui, cx);
    } else if !lecture {
        ui.horizontal_wrapped(|ui| {
            lock_axes(ui, cx);
            ui.separator();
            super::transport::row(ui, cx);
        });
    }
    let full_cursor = state.params().cursor(&out);
    let trajectory = match &out.extra {
        Extra::Collision(t) => Some(Arc::clone(t)),
        Extra::Paths(_) | Extra::Model(_) | Extra::Ladder(_) | Extra::None => None,
    };
    let n_panels = out.figures.len() + usize::from(trajectory.is_some()) + usize::from(ladder.is_some());
    // Many panels (a grid of experiments) are small multiples: each keeps
    // a legible size, as many columns as fit, and the grid scrolls; the
    // first figure leads above them at twice the width.
    let multiples = n_panels > 6;
    // Panels below this size leave a plot area under ~400 × 260 px once
    // titles, ticks and legends are placed: one at a time then.
    // A colour bar takes ~140 px beside its plot.
    let bar_w = if out.figures.iter().any(|f| f.heatmap.is_some() || f.family.is_some()) { 140.0 } else { 0.0 };
    let legible = egui::vec2(420.0 + bar_w, 340.0);
    // `at_least`: the smallest panel (small multiples, or every panel at a
    // legible size when all are asked for and do not fit).
    let grid = |avail: egui::Vec2, at_least: Option<egui::Vec2>| {
        let (min_w, min_h) = match at_least {
            Some(m) => (m.x, m.y),
            None if multiples => (if lecture { 300.0 } else { 250.0 }, 210.0),
            None => (200.0, 160.0),
        };
        let cols = match n_panels {
            _ if multiples || at_least.is_some() => ((avail.x / (min_w + 12.0)) as usize).clamp(1, 4),
            1 => 1,
            2..=4 => 2,
            _ => 3,
        };
        // A narrow area (beside a ladder, a small window) takes fewer columns.
        let cols = cols.min(((avail.x + 12.0) / (min_w + 12.0)).max(1.0) as usize);
        let rows = n_panels.div_ceil(cols);
        let raw = egui::vec2(avail.x / cols as f32 - 12.0, avail.y / rows as f32 - if lecture { 8.0 } else { 40.0 });
        (cols, raw, egui::vec2(raw.x.max(min_w), raw.y.max(min_h)))
    };
    // The panels one at a time (a strip to pick one) where they do not all
    // fit at a legible size, or where the user picked one; remembered per scene.
    let ids: Vec<(String, String)> = out
        .figures
        .iter()
        .map(|f| (f.id.clone(), f.title.clone()))
        .chain(trajectory.as_ref().map(|_| (SKETCH.to_string(), "Contact sketch".to_string())))
        .chain(ladder.as_ref().map(|_| (LADDER.to_string(), "Scale ladder".to_string())))
        .collect();
    let choice = match &state.presenter {
        Some(p) => p.panel.as_ref(),
        None => state.session.panels.get(state.params().info().id),
    };
    let fits = {
        let (_, raw, _) = grid(ui.available_size() - egui::vec2(0.0, STRIP), None);
        raw.x >= legible.x && raw.y >= legible.y
    };
    let alone: Option<usize> = match choice.map(String::as_str) {
        _ if n_panels < 2 => None,
        Some(crate::session::ALL_PANELS) => None,
        Some(id) if ids.iter().any(|(i, _)| i == id) => ids.iter().position(|(i, _)| i == id),
        _ if fits => None,
        // The ladder first where it is a panel: it is the scene.
        _ if ladder.is_some() => Some(n_panels - 1),
        _ => Some(0),
    };
    // (A slide that enlarges a figure shows it alone, the others a click away.)
    if n_panels > 1
        && let Some(c) = strip(ui, &ids, alone, fits, lecture, compact)
    {
        cx.out.push(c);
    }
    // All panels asked for where they do not fit: each at a legible size,
    // in a grid that scrolls, rather than squeezed.
    let squeezed = alone.is_none() && n_panels > 1 && !fits && !multiples;
    let avail = ui.available_size();
    let (cols, _, size) = grid(avail, squeezed.then_some(legible));
    let lead_size = egui::vec2((2.0 * size.x + 12.0).min(avail.x - 12.0), 1.3 * size.y);
    let cursor_fraction = full_cursor.as_ref().map_or(0.0, |c| c.fraction);
    let cursor = full_cursor.filter(|c| state.marks_shown(c));
    let mut commands: Vec<Command> = Vec::new();
    cx.memo.plot_rects.clear();
    cx.memo.plot_frames.clear();
    let look = super::look::plot_look(ui, lecture);
    // Figures first seen while locked are locked at their first view.
    let locked_views = state.locked.clone().map(|mut locked| {
        for fig in &out.figures {
            locked.entry(fig.id.clone()).or_insert_with(|| View::of(fig));
        }
        locked
    });
    if locked_views != state.locked {
        commands.push(Command::LockAxes(locked_views.clone()));
    }
    let mut export_dir = state.session.export_dir.clone();
    let save_hint = if state.paths { "save into the export folder" } else { "download" };
    let mut legends_shown: Vec<Vec<(String, figure::Style, [u8; 3])>> = Vec::new();
    let memo = &mut *cx.memo;
    let stale = cx.work.stale;
    // Files show what the window shows, the time cursor included.
    let drawn = |fig: &Figure| state.drawn_figures(&out).into_iter().find(|f| f.id == fig.id).unwrap_or(fig.clone());
    // Small multiples scroll; one panel alone is sized to the area and does not.
    let scrolls = (multiples || squeezed) && alone.is_none();
    let scroll = egui::ScrollArea::new([scrolls, scrolls])
        .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
        .max_height(if scrolls { avail.y - if lecture { 0.0 } else { 32.0 } } else { f32::INFINITY });
    scroll.show(ui, |ui| {
        // One panel: the plot with its legend, and its export buttons.
        let mut panel = |ui: &mut egui::Ui, fig: &Figure, size: egui::Vec2| {
            let mut marks: Vec<scene::Mark> =
                cursor.as_ref().map(|c| c.marks_on(&fig.id).cloned().collect()).unwrap_or_default();
            marks.extend(state.inspected_mark(&fig.id));
            let overlay = overlay_for(state, fig, marks);
            let locked = locked_views.as_ref().and_then(|l| l.get(&fig.id).copied());
            let mut look = look;
            // A legend that repeats an earlier panel's (same entries,
            // styles and colours) is drawn once.
            if overlay.pinned.is_empty() {
                let signature = plot::legend_signature(fig);
                look.legend = !legends_shown.contains(&signature);
                legends_shown.push(signature);
            }
            ui.vertical(|ui| {
                let shown = plot::show(ui, fig, &overlay, size, stale, look, locked);
                memo.plot_rects.push(shown.response.rect);
                memo.plot_frames.push((fig.id.clone(), shown.placed));
                if let Some((at, pos)) = shown.clicked {
                    commands.push(Command::Inspect(fig.id.clone(), at, [pos.x, pos.y]));
                }
                if lecture {
                    return;
                }
                ui.horizontal(|ui| {
                    for ext in ["png", "svg", "csv"] {
                        if ui.small_button(ext.to_uppercase()).on_hover_text(save_hint).clicked() {
                            commands.push(Command::ExportFigure(Box::new(drawn(fig)), ext));
                        }
                    }
                    if ui.small_button("Save as…").clicked() {
                        commands.push(Command::SaveFigureAs(Box::new(drawn(fig))));
                    }
                });
            });
        };
        // One item: a figure, or (None) the contact sketch.
        let mut draw = |ui: &mut egui::Ui, item: Option<&Figure>, size: egui::Vec2| match (item, &trajectory) {
            (Some(fig), _) => panel(ui, fig, size),
            (None, Some(t)) => {
                ui.vertical(|ui| {
                    ui.label(egui::RichText::new("Contact sketch").strong());
                    sketch::show(ui, t, cursor_fraction, size);
                    if lecture {
                        return;
                    }
                    ui.small("play the collision or move its time above the plots");
                    if state.paths {
                        ui.horizontal(|ui| {
                            let label = ui.label("export folder");
                            ui.text_edit_singleline(&mut export_dir).labelled_by(label.id);
                        });
                    }
                });
            }
            (None, None) => {
                if let Some(rungs) = &ladder {
                    let text = super::look::body_size(lecture);
                    ui.allocate_ui(size, |ui| {
                        ui.set_width(size.x.min(480.0));
                        egui::ScrollArea::vertical()
                            .id_salt("ladder-panel")
                            .max_height(size.y)
                            .show(ui, |ui| ladder_panel(ui, rungs, text, None));
                    });
                }
            }
        };
        if let Some(k) = alone {
            // One panel across the whole figure area.
            let big = egui::vec2(avail.x - 12.0, avail.y - if lecture { 8.0 } else { 40.0 });
            draw(ui, out.figures.get(k), big);
            return;
        }
        let lead = if multiples { Some(0) } else { None };
        let items: Vec<Option<&Figure>> = out
            .figures
            .iter()
            .enumerate()
            .filter(|(k, _)| Some(*k) != lead)
            .map(|(_, f)| Some(f))
            .chain(trajectory.as_ref().map(|_| None))
            .chain(ladder.as_ref().map(|_| None))
            .collect();
        if let Some(fig) = lead.and_then(|k| out.figures.get(k)) {
            draw(ui, Some(fig), lead_size);
        }
        // Row by row; a last row with fewer panels shares the full width
        // (no empty quadrant), except among small multiples.
        for row in items.chunks(cols) {
            let size = if row.len() < cols && !multiples {
                let spacing = ui.spacing().item_spacing.x;
                egui::vec2((avail.x - spacing * row.len() as f32) / row.len() as f32 - 4.0, size.y)
            } else {
                size
            };
            ui.horizontal_top(|ui| {
                for item in row {
                    draw(ui, *item, size);
                }
            });
        }
    });
    if trajectory.is_none() && !lecture && state.paths {
        ui.horizontal(|ui| {
            let label = ui.label("export folder");
            ui.text_edit_singleline(&mut export_dir).labelled_by(label.id);
        });
    }
    if export_dir != state.session.export_dir {
        commands.push(Command::SetText(Field::ExportDir, export_dir));
    }
    cx.out.extend(commands);
}

/// Pins of the open scene drawn over `fig` (a sweep's as a family coloured
/// by the swept value), with the cursor's marks.
fn overlay_for(state: &AppState, fig: &Figure, cursor: Vec<scene::Mark>) -> plot::Overlay {
    let current = state.params();
    let here = |p: &&crate::session::Pin| p.params.info().id == current.info().id;
    // The newest sweep's pins form a family coloured by the swept value;
    // pins of an earlier sweep of another parameter are drawn as plain pins.
    let swept = |p: &crate::session::Pin| {
        p.curves.iter().any(|(_, s)| s.family.is_some()).then(|| p.label.split(" = ").next().unwrap_or("").to_string())
    };
    let key = state.session.pins.iter().filter(here).rev().find_map(swept);
    let pinned: Vec<Series> = state
        .session
        .pins
        .iter()
        .filter(here)
        .flat_map(|pin| {
            let label = if pin.label.is_empty() {
                let d = pin.params.differences(current);
                if d.is_empty() { "pinned (same parameters)".to_string() } else { format!("pinned: {}", d.join(", ")) }
            } else {
                pin.label.clone()
            };
            let in_family = key.is_some() && swept(pin) == key;
            pin.curves.iter().filter(|(id, _)| *id == fig.id).map(move |(_, s)| {
                let name = if s.name.is_empty() { label.clone() } else { format!("{label} — {}", s.name) };
                let mut pinned = Series::new(name, s.points.clone(), Style::Dashed, pin.color);
                pinned.family = if in_family { s.family } else { None };
                pinned
            })
        })
        .collect();
    let family = key.and_then(|key| {
        let c = current.spec(&key)?;
        let values: Vec<f64> = pinned.iter().filter_map(|s| s.family).collect();
        if values.is_empty() {
            return None;
        }
        let positive = values.iter().all(|&v| v > 0.0);
        let scale = if positive { figure::Scale::Log } else { figure::Scale::Linear };
        Some(figure::Family { label: c.label.to_string(), unit: c.si_unit.to_string(), scale })
    });
    plot::Overlay { pinned, family, cursor }
}

/// The rungs of a ladder, smallest scale on top, an arrow between them.
/// The rung of the figure `alone` is scrolled into view once, when that
/// figure comes to be shown alone; the user scrolls freely after.
fn ladder_panel(ui: &mut egui::Ui, rungs: &[scene::Rung], text: f32, alone: Option<&str>) {
    let memory = egui::Id::NULL.with("ladder-rung-in-view");
    let before = ui.data(|d| d.get_temp::<Option<String>>(memory)).flatten();
    if before.as_deref() != alone {
        ui.data_mut(|d| d.insert_temp(memory, alone.map(str::to_string)));
    }
    for (k, rung) in rungs.iter().enumerate() {
        if k > 0 {
            ui.vertical_centered(|ui| ui.label(egui::RichText::new("↓").size(text)));
        }
        let card = egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(egui::RichText::new(&rung.scale).strong().size(text + 1.0));
            egui::Grid::new(("rung", k)).num_columns(2).spacing([8.0, 1.0]).show(ui, |ui| {
                for (quantity, value, source) in &rung.items {
                    ui.label(egui::RichText::new(quantity).size(text)).on_hover_text(source);
                    ui.label(egui::RichText::new(value).size(text).strong()).on_hover_text(source);
                    ui.end_row();
                }
            });
        });
        if alone.is_some() && rung.figure.as_deref() == alone && before.as_deref() != alone {
            card.response.scroll_to_me(Some(egui::Align::Max));
        }
    }
}
