//! Painting a plot's legend, its symbols and its colour bar by hand, in
//! the corner the layout chose, so that they match the exported files.

use super::{Entry, Look, transform};
use crate::figure::layout::{ColourBar, Corner};
use crate::figure::ticks::ticks;
use crate::figure::{Figure, Fill, Heatmap, Shape, Style, colormap, family_fraction, human};
use egui::{Color32, Pos2, Rect, Stroke, Vec2};
use egui_plot::PlotPoints;

pub(super) fn legend_size_one(ui: &egui::Ui, e: &Entry, font: &egui::FontId) -> Vec2 {
    let w = ui.painter().layout_no_wrap(e.text.clone(), font.clone(), Color32::WHITE).size().x;
    Vec2::new(w + 50.0, font.size * 1.45)
}

pub(super) fn corner_rect(frame: Rect, c: Corner, size: Vec2) -> Rect {
    let m = 8.0;
    let x = match c {
        Corner::UpperLeft | Corner::LowerLeft => frame.left() + m,
        Corner::UpperRight | Corner::LowerRight => frame.right() - m - size.x,
    };
    let y = match c {
        Corner::UpperLeft | Corner::UpperRight => frame.top() + m,
        Corner::LowerLeft | Corner::LowerRight => frame.bottom() - m - size.y,
    };
    Rect::from_min_size(Pos2::new(x, y), size)
}

pub(super) fn paint_legend(ui: &mut egui::Ui, legend: &[Entry], rect: Rect, look: Look) {
    let painter = ui.painter().clone();
    let bg = if look.dark { Color32::from_black_alpha(215) } else { Color32::from_white_alpha(235) };
    painter.rect(rect, 3.0, bg, Stroke::new(1.0, Color32::GRAY), egui::StrokeKind::Inside);
    let row = look.text * 1.45;
    for (k, e) in legend.iter().enumerate() {
        let r = Rect::from_min_size(
            Pos2::new(rect.left(), rect.top() + 5.0 + k as f32 * row),
            Vec2::new(rect.width(), row),
        );
        paint_entry(ui, e, r, look);
    }
}

/// A [`Style::Symbol`] of radius `r` at `c`, as egui_plot draws it.
pub(super) fn paint_symbol(
    painter: &egui::Painter,
    c: Pos2,
    r: f32,
    shape: Shape,
    fill: Fill,
    color: Color32,
    line: f32,
) {
    let stroke = Stroke::new((0.7 * line).max(1.2), color);
    let poly = |pts: Vec<Pos2>| {
        if fill == Fill::Filled {
            egui::Shape::convex_polygon(pts, color, Stroke::NONE)
        } else {
            egui::Shape::closed_line(pts, stroke)
        }
    };
    if let Some(corners) = shape.outline() {
        painter.add(poly(corners.iter().map(|p| c + Vec2::new(p[0] as f32, p[1] as f32) * r).collect()));
        return;
    }
    match shape {
        Shape::Circle if fill == Fill::Filled => {
            painter.circle_filled(c, r, color);
        }
        Shape::Circle => {
            painter.circle_stroke(c, r, stroke);
        }
        Shape::Plus => {
            painter.line_segment([c - Vec2::new(r, 0.0), c + Vec2::new(r, 0.0)], stroke);
            painter.line_segment([c - Vec2::new(0.0, r), c + Vec2::new(0.0, r)], stroke);
        }
        // The polygonal shapes have their outline.
        Shape::Square | Shape::Diamond | Shape::TriangleDown | Shape::TriangleUp | Shape::Asterisk => {
            for k in 0..3 {
                let a = std::f32::consts::FRAC_PI_2 + k as f32 * std::f32::consts::PI / 3.0;
                let d = Vec2::new(a.cos(), -a.sin()) * r;
                painter.line_segment([c - d, c + d], stroke);
            }
        }
    }
}

/// One legend row: its line, marker or swatch, then its text.
pub(super) fn paint_entry(ui: &mut egui::Ui, e: &Entry, rect: Rect, look: Look) {
    let painter = ui.painter().clone();
    let y = rect.center().y;
    let x0 = rect.left() + 6.0;
    let stroke = Stroke::new(look.line, e.color);
    if e.pin {
        painter.line_segment(
            [Pos2::new(x0, y), Pos2::new(x0 + 30.0, y)],
            Stroke::new(look.line * super::PIN_WIDTH, e.color),
        );
    } else if e.swatch {
        painter.rect_filled(Rect::from_min_size(Pos2::new(x0 + 6.0, y - 6.0), Vec2::new(18.0, 12.0)), 1.0, e.color);
    } else {
        match e.style {
            Style::Line => {
                painter.line_segment([Pos2::new(x0, y), Pos2::new(x0 + 30.0, y)], stroke);
            }
            Style::Dashed => {
                painter.extend(egui::Shape::dashed_line(
                    &[Pos2::new(x0, y), Pos2::new(x0 + 30.0, y)],
                    stroke,
                    7.0,
                    4.0,
                ));
            }
            Style::Arrow => {
                painter.arrow(Pos2::new(x0, y), Vec2::new(30.0, 0.0), stroke);
            }
            Style::Region => {
                let r = Rect::from_min_size(Pos2::new(x0 + 6.0, y - 6.0), Vec2::new(18.0, 12.0));
                painter.rect(
                    r,
                    1.0,
                    e.color.gamma_multiply(0.3),
                    Stroke::new(0.6 * look.line, e.color),
                    egui::StrokeKind::Inside,
                );
            }
            Style::Dotted => {
                painter.extend(egui::Shape::dotted_line(
                    &[Pos2::new(x0, y), Pos2::new(x0 + 30.0, y)],
                    e.color,
                    2.2 * look.line,
                    0.6 * look.line,
                ));
            }
            Style::Points => {
                painter.circle_filled(Pos2::new(x0 + 15.0, y), 3.5, e.color);
            }
            Style::Marker => {
                let c = Pos2::new(x0 + 15.0, y);
                let r = 6.5;
                painter.add(egui::Shape::convex_polygon(
                    vec![c + Vec2::new(0.0, -r), c + Vec2::new(r, 0.0), c + Vec2::new(0.0, r), c + Vec2::new(-r, 0.0)],
                    e.color,
                    Stroke::new(1.0, Color32::BLACK),
                ));
            }
            Style::Symbol(shape, fill) => {
                paint_symbol(&painter, Pos2::new(x0 + 15.0, y), 6.0, shape, fill, e.color, look.line);
            }
            Style::LowerLimit | Style::UpperLimit => {
                let c = Pos2::new(x0 + 15.0, y);
                let d = if e.style == Style::LowerLimit { -1.0 } else { 1.0 };
                let r = 6.0;
                painter.add(egui::Shape::convex_polygon(
                    vec![c + Vec2::new(0.0, d * r), c + Vec2::new(r, -d * 0.6 * r), c + Vec2::new(-r, -d * 0.6 * r)],
                    e.color,
                    Stroke::NONE,
                ));
            }
        }
    }
    // The text is a label, so that it can be read out and found by tests.
    let text_rect = Rect::from_min_max(Pos2::new(x0 + 38.0, y - 0.62 * look.text), rect.right_bottom());
    ui.scope_builder(
        egui::UiBuilder::new().max_rect(text_rect).layout(egui::Layout::top_down(egui::Align::Min)),
        |ui| ui.add(egui::Label::new(egui::RichText::new(&e.text).size(look.text)).selectable(false).truncate()),
    );
}

pub(super) fn paint_bar(ui: &egui::Ui, b: &ColourBar, rect: Rect, look: Look) {
    let painter = ui.painter();
    let bar = Rect::from_min_size(rect.left_top() + Vec2::new(8.0, 0.0), Vec2::new(16.0, rect.height()));
    let n = 48;
    for k in 0..n {
        let t = (k as f64 + 0.5) / n as f64;
        // A family's bar (top below 1) matches its curves on the dark theme.
        let family = b.top < 1.0;
        let [r, g, bl] = if family { super::family_rgb(t * b.top, look.dark) } else { colormap(t * b.top) };
        let y1 = bar.bottom() - k as f32 / n as f32 * bar.height();
        let y0 = bar.bottom() - (k + 1) as f32 / n as f32 * bar.height();
        painter.rect_filled(Rect::from_x_y_ranges(bar.x_range(), y0..=y1 + 0.5), 0.0, Color32::from_rgb(r, g, bl));
    }
    let text_color = ui.visuals().text_color();
    painter.rect_stroke(bar, 0.0, Stroke::new(1.0, text_color), egui::StrokeKind::Inside);
    let font = egui::FontId::proportional(look.text);
    let mut widest: f32 = 0.0;
    let bar_ticks = if b.hi > b.lo { ticks(b.lo, b.hi, b.scale, 5) } else { Vec::new() };
    for t in &bar_ticks {
        let f = (family_fraction(t.value, b.lo, b.hi, b.scale) / 0.9) as f32;
        let y = bar.bottom() - f * bar.height();
        let len = if t.is_major() { 5.0 } else { 3.0 };
        painter
            .line_segment([Pos2::new(bar.right(), y), Pos2::new(bar.right() + len, y)], Stroke::new(1.0, text_color));
        if let Some(l) = &t.label {
            let r =
                painter.text(Pos2::new(bar.right() + 7.0, y), egui::Align2::LEFT_CENTER, l, font.clone(), text_color);
            widest = widest.max(r.width());
        }
    }
    if bar_ticks.is_empty() {
        let r = painter.text(
            Pos2::new(bar.right() + 7.0, bar.center().y),
            egui::Align2::LEFT_CENTER,
            human(b.lo),
            font.clone(),
            text_color,
        );
        widest = r.width();
    }
    let galley = painter.layout_no_wrap(b.title.clone(), egui::FontId::proportional(look.text), text_color);
    let x = (bar.right() + 10.0 + widest).min(rect.right() - galley.size().y);
    let pos = Pos2::new(x, bar.center().y + galley.size().x / 2.0);
    painter.add(egui::epaint::TextShape::new(pos, galley, text_color).with_angle(-std::f32::consts::FRAC_PI_2));
}

/// Draws a heatmap as one filled polygon per cell (cells may be uneven on log axes).
pub(super) fn heatmap(plot_ui: &mut egui_plot::PlotUi<'_>, fig: &Figure, h: &Heatmap) {
    let ex = Heatmap::edges(&h.x, fig.x.scale);
    let ey = Heatmap::edges(&h.y, fig.y.scale);
    let range = h.range();
    for j in 0..h.y.len() {
        for i in 0..h.x.len() {
            let v = h.values[j * h.x.len() + i];
            if !v.is_finite() {
                continue;
            }
            let corners = [[ex[i], ey[j]], [ex[i + 1], ey[j]], [ex[i + 1], ey[j + 1]], [ex[i], ey[j + 1]]];
            let Some(pts) = corners
                .iter()
                .map(|p| Some([transform(p[0], fig.x.scale)?, transform(p[1], fig.y.scale)?]))
                .collect::<Option<Vec<_>>>()
            else {
                continue;
            };
            let [r, g, b] = h.color_of(v, range);
            let c = Color32::from_rgb(r, g, b);
            // An outline in the cell's own colour closes the hairline seams that
            // anti-aliasing leaves between neighbouring cells.
            plot_ui
                .polygon(egui_plot::Polygon::new("", PlotPoints::from(pts)).fill_color(c).stroke(Stroke::new(0.8, c)));
        }
    }
}
