//! The classroom's own tools, over everything else: a blank screen, a
//! pointer, ink on the figures, the menu that holds their buttons and the
//! presenter's timer.

use super::Cx;
use crate::app::command::{Action, Command};
use crate::app::shortcuts::{self, Mode};

/// Ink's colour, as exports draw it.
const INK: egui::Color32 = egui::Color32::from_rgb(crate::figure::INK[0], crate::figure::INK[1], crate::figure::INK[2]);

/// The pointer's colour: a red spot with a white ring, visible on light and dark.
const POINTER: egui::Color32 = egui::Color32::from_rgb(0xE0, 0x10, 0x10);

/// Draws the blank screen, the ink and the pointer over the window, and
/// takes the drags over `figures` (the figures' area) while ink is on.
pub fn layer(ctx: &egui::Context, cx: &mut Cx<'_>, figures: egui::Rect) {
    let tools = &cx.state.classroom;
    let screen = ctx.content_rect();
    if tools.blank {
        egui::Area::new(egui::Id::unique("blank screen")).order(egui::Order::Foreground).fixed_pos(screen.min).show(
            ctx,
            |ui| {
                let response = ui.allocate_rect(screen, egui::Sense::click());
                ui.painter().rect_filled(screen, 0.0, egui::Color32::BLACK);
                if response.clicked() {
                    cx.send(Command::Act(Action::Blank));
                }
            },
        );
        return;
    }
    let to_screen = |p: [f32; 2]| screen.min + egui::vec2(p[0] * screen.width(), p[1] * screen.height());
    let width = (screen.width() / 300.0).clamp(3.0, 8.0);
    let stroke = egui::Stroke::new(width, INK);
    let painter = ctx.layer_painter(egui::LayerId::new(egui::Order::Foreground, egui::Id::unique("ink")));
    for line in &tools.strokes {
        painter.add(egui::Shape::line(line.points.iter().map(|p| to_screen(*p)).collect(), stroke));
    }
    if tools.ink {
        egui::Area::new(egui::Id::unique("ink area")).order(egui::Order::Middle).fixed_pos(figures.min).show(
            ctx,
            |ui| {
                let response = ui.allocate_rect(figures, egui::Sense::drag());
                let response = response.on_hover_cursor(egui::CursorIcon::Crosshair);
                if let Some(pos) = response.interact_pointer_pos().filter(|_| response.dragged()) {
                    let at = (pos - screen.min) / screen.size();
                    cx.memo.ink_stroke.push([at.x, at.y]);
                }
                if response.drag_stopped() {
                    let points = std::mem::take(&mut cx.memo.ink_stroke);
                    // The stroke in the axis units of every plot it touches.
                    let on_screen: Vec<egui::Pos2> = points.iter().map(|p| to_screen(*p)).collect();
                    let on = cx
                        .memo
                        .plot_frames
                        .iter()
                        .filter(|(_, placed)| on_screen.iter().any(|q| placed.frame.contains(*q)))
                        .map(|(id, placed)| (id.clone(), on_screen.iter().map(|q| placed.value_at(*q)).collect()))
                        .collect();
                    cx.send(Command::InkStroke(crate::app::command::InkStroke { points, on }));
                }
            },
        );
        let drawing = &cx.memo.ink_stroke;
        if drawing.len() >= 2 {
            painter.add(egui::Shape::line(drawing.iter().map(|p| to_screen(*p)).collect(), stroke));
        }
    }
    if tools.pointer
        && let Some(pos) = ctx.input(|i| i.pointer.hover_pos())
    {
        let radius = (screen.width() / 70.0).clamp(10.0, 24.0);
        let spot = ctx.layer_painter(egui::LayerId::new(egui::Order::Tooltip, egui::Id::unique("pointer")));
        spot.circle(pos, radius, POINTER.gamma_multiply(0.85), egui::Stroke::new(3.0, egui::Color32::WHITE));
        ctx.set_cursor_icon(egui::CursorIcon::None);
    }
}

/// The menu of the classroom's tools (a button each, with its key), and
/// the list of keys too where `with_keys` (a bar with no room for its button).
pub fn menu(ui: &mut egui::Ui, cx: &mut Cx<'_>, with_keys: bool) {
    let tools = &cx.state.classroom;
    let (pointer, ink, strokes) = (tools.pointer, tools.ink, !tools.strokes.is_empty());
    let ink_exported = tools.ink_in_exports;
    let mode = if cx.state.presenter.is_some() { Mode::Presenter } else { Mode::Explorer };
    let label = if ink || pointer { "Tools ●" } else { "Tools" };
    ui.menu_button(label, |ui| {
        let mut button = |ui: &mut egui::Ui, action: Action, on: Option<bool>, enabled: bool| {
            let text = action.text();
            let keys = shortcuts::keys(action, mode);
            let name = if keys.is_empty() { text.name.to_string() } else { format!("{} ({keys})", text.name) };
            let response = match on {
                Some(on) => ui.add_enabled(enabled, egui::Button::selectable(on, name)),
                None => ui.add_enabled(enabled, egui::Button::new(name)),
            };
            if response.on_hover_text(text.does).clicked() {
                cx.send(Command::Act(action));
            }
        };
        button(ui, Action::Blank, None, true);
        button(ui, Action::Pointer, Some(pointer), true);
        button(ui, Action::Ink, Some(ink), true);
        button(ui, Action::UndoInk, None, strokes);
        button(ui, Action::ClearInk, None, strokes);
        button(ui, Action::InkInExports, Some(ink_exported), true);
        if with_keys {
            ui.separator();
            button(ui, Action::Help, None, true);
        }
    });
}

/// The presenter's timer: time since the deck started, and what is left of
/// a countdown when one is set (its length in minutes beside it).
pub fn timer(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let Some(p) = &cx.state.presenter else { return };
    let clock = |s: f64| {
        let s = s.abs().floor() as u64;
        format!("{}:{:02}", s / 60, s % 60)
    };
    let mut text = clock(p.elapsed);
    let mut over = false;
    if let Some(length) = p.countdown {
        let left = length - p.elapsed;
        over = left < 0.0;
        text = if over { format!("{text} · {} over", clock(left)) } else { format!("{text} · {} left", clock(left)) };
    }
    let size = ui.style().text_styles.get(&egui::TextStyle::Button).map_or(18.0, |f| f.size);
    let rich = egui::RichText::new(text).monospace().strong().size(size);
    let rich = if over { rich.color(ui.visuals().error_fg_color) } else { rich };
    let hint = shortcuts::hint(Action::RestartTimer, Mode::Presenter);
    if ui
        .add(egui::Label::new(rich).sense(egui::Sense::click()))
        .on_hover_text(format!("time since the deck started, and what is left of the talk; a click: {hint}"))
        .clicked()
    {
        cx.send(Command::Act(Action::RestartTimer));
    }
    let mut minutes = p.countdown.map_or(0.0, |s| s / 60.0);
    let field = egui::DragValue::new(&mut minutes)
        .range(0.0..=240.0)
        .speed(1.0)
        .custom_formatter(|v, _| if v > 0.0 { format!("{v:.0} min talk") } else { "no countdown".to_string() });
    if ui.add(field).on_hover_text("the talk's length in minutes, for a countdown (0: none)").changed() {
        cx.send(Command::SetCountdown((minutes > 0.0).then_some(minutes * 60.0)));
    }
}
