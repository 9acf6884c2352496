//! The "what matters" view: for one result of the open scene, every
//! parameter's elasticity ∂ln X/∂ln p at the current point and the result's
//! range over a factor around each parameter's value, sorted, as a tornado
//! chart with the numbers beside it.

use super::Cx;
use crate::app::command::Command;
use crate::figure::human;

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
    let text = if lecture { 16.0 } else { 13.0 };
    let (key, factor) = (m.output.clone(), m.factor);
    let label = cx
        .state
        .output()
        .and_then(|o| o.scalars.iter().find(|s| s.key == key))
        .map_or(key.clone(), |s| format!("{} ({key})", s.label));
    let unit = cx.state.output().and_then(|o| o.scalars.iter().find(|s| s.key == key)).map_or("", |s| s.unit);
    let mut open = true;
    let mut clicked: Option<String> = None;
    egui::Window::new("What matters")
        .open(&mut open)
        .default_width(620.0)
        .default_height(0.85 * ctx.content_rect().height())
        .collapsible(true)
        .resizable(true)
        .vscroll(true)
        .show(ctx, |ui| {
            ui.label(egui::RichText::new(format!("What moves {label}")).strong().size(text + 1.0));
            let Some((at, x0, rows)) = &m.result else {
                ui.label(egui::RichText::new("computing…").size(text));
                return;
            };
            if at != cx.state.params() {
                ui.colored_label(
                    ui.visuals().warn_fg_color,
                    "the parameters changed since: press “What matters” again for the current point",
                );
            }
            ui.label(
                egui::RichText::new(format!("here {} {unit}; each parameter ×÷ {}", human(*x0), human(factor)))
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
            if let Some(key) = chart(ui, rows, *x0, text) {
                clicked = Some(key);
            }
            if let Some((at, fig)) = &m.curve {
                ui.separator();
                if at != cx.state.params() {
                    ui.colored_label(ui.visuals().warn_fg_color, "drawn for earlier parameters");
                }
                let look = super::look::plot_look(ui, lecture);
                let size = egui::vec2(ui.available_width().max(300.0), if lecture { 250.0 } else { 240.0 });
                super::plot::show(ui, fig, &super::plot::Overlay::default(), size, false, look, None);
            }
            ui.small(
                "elasticity ∂ln X/∂ln p at the current value (? where steps of 1 % and 0.5 % disagree: a jump or \
                 noise); bars: X with the parameter divided (blue) and multiplied (orange) by the factor, \
                 within its range, on a log scale of X/X₀; sorted by the change of X. Click a parameter to draw X \
                 against it over its whole range.",
            );
        });
    if !open {
        cx.send(Command::CloseMatters);
    }
    if let Some(key) = clicked {
        cx.send(Command::MattersCurve(key));
    }
}

/// The tornado chart with a row of numbers per parameter.
/// Returns the key of a parameter whose name was clicked (to draw X against it).
fn chart(ui: &mut egui::Ui, rows: &[crate::sweep::Influence], x0: f64, text: f32) -> Option<String> {
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
            ui.label(egui::RichText::new(format!("{} {}", human(r.value), r.unit)).size(text));
            let e = match r.elasticity {
                Some(e) if e.abs() < 5e-4 => "0".to_string(),
                Some(e) => format!("{e:+.3}{}", if r.converged { "" } else { " ?" }),
                None => "—".to_string(),
            };
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
            let range = |x: Option<f64>| x.map_or("undefined".to_string(), human);
            resp.on_hover_text(format!(
                "X = {} at p ÷ factor, {} here, {} at p × factor",
                range(r.range[0]),
                human(x0),
                range(r.range[1])
            ));
            ui.end_row();
        }
    });
    clicked
}
