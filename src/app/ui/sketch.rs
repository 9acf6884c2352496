//! A sketch of the two spheres and their contact neck at the time cursor.

use crate::scene::Trajectory;
use egui::{Color32, Pos2, Stroke, pos2, vec2};

/// Draws the sketch into a rectangle of `size`.
pub fn show(ui: &mut egui::Ui, t: &Trajectory, fraction: f64, size: egui::Vec2) {
    let (rect, _) = ui.allocate_exact_size(vec2(size.x, size.y - 60.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
    let Some(s) = t.sample_at(fraction) else {
        return;
    };
    let text_color = ui.visuals().text_color();
    let (delta, a) = (s[1], s[2]);
    let a_max = t.samples.iter().map(|s| s[2]).fold(0.0, f64::max).max(1e-30);

    // The readout along the bottom, wrapped to the sketch's width in the
    // body text size (large in lecture mode).
    let readout = format!(
        "t = {:.2} ns   δ = {:.2} nm\na = {:.1} nm   F_E = {:.3} µN\n(contact in red; vertical scale exaggerated)",
        s[0] * 1e9,
        delta * 1e9,
        a * 1e9,
        s[3] * 1e6
    );
    let font = egui::TextStyle::Body.resolve(ui.style());
    let galley = painter.layout(readout, font, text_color, (rect.width() - 16.0).max(40.0));
    let text_top = rect.max.y - galley.size().y - 6.0;
    painter.galley(pos2(rect.min.x + 8.0, text_top), galley, text_color);

    // Left: the two bodies at true scale.
    let left = egui::Rect::from_min_size(rect.min, vec2(rect.width() * 0.35, (text_top - rect.min.y - 4.0).max(20.0)));
    let r1 = t.radius_1;
    let r2 = if t.radius_2.is_finite() { t.radius_2 } else { 3.0 * r1 };
    let scale = (left.height() as f64 * 0.45) / (r1 + r2);
    let cx = left.center().x;
    let contact_y = left.min.y + (2.0 * r1 * scale) as f32 + 0.05 * left.height();
    let sphere = Color32::from_rgb(120, 160, 210);
    painter.circle(
        pos2(cx, contact_y - (r1 * scale) as f32),
        (r1 * scale) as f32,
        sphere,
        Stroke::new(1.0, text_color),
    );
    if t.radius_2.is_finite() {
        painter.circle(
            pos2(cx, contact_y + (r2 * scale) as f32),
            (r2 * scale) as f32,
            sphere,
            Stroke::new(1.0, text_color),
        );
    } else {
        let wall =
            egui::Rect::from_min_max(pos2(left.min.x + 8.0, contact_y), pos2(left.max.x - 8.0, left.max.y - 8.0));
        painter.rect_filled(wall, 0.0, Color32::from_rgb(150, 150, 150));
    }

    // Right: the contact neck, horizontal scale 3 a_max, vertical exaggerated.
    let right = egui::Rect::from_min_max(
        pos2(left.max.x + 10.0, rect.min.y + 10.0),
        pos2(rect.max.x - 10.0, (text_top - 8.0).max(rect.min.y + 30.0)),
    );
    let half_w = 1.5 * a_max;
    let mid = right.center();
    let x_scale = right.width() as f64 / (2.0 * half_w);
    let z_edge = (half_w * half_w) / (2.0 * r1.min(r2));
    let z_scale = (right.height() as f64 * 0.4) / z_edge.max(1e-30);
    let profile = |sign: f64, radius: f64| -> Vec<Pos2> {
        (0..=120)
            .map(|i| {
                let x = -half_w + 2.0 * half_w * i as f64 / 120.0;
                let z = if x.abs() < a { 0.0 } else { (x * x - a * a) / (2.0 * radius) };
                pos2(mid.x + (x * x_scale) as f32, mid.y - (sign * z * z_scale) as f32)
            })
            .collect()
    };
    let upper = profile(1.0, r1);
    let lower = profile(-1.0, if t.radius_2.is_finite() { r2 } else { f64::INFINITY });
    painter.add(egui::Shape::line(upper, Stroke::new(2.0, Color32::from_rgb(31, 119, 180))));
    painter.add(egui::Shape::line(lower, Stroke::new(2.0, Color32::from_rgb(31, 119, 180))));
    let ax = (a * x_scale) as f32;
    painter.line_segment(
        [pos2(mid.x - ax, mid.y), pos2(mid.x + ax, mid.y)],
        Stroke::new(4.0, Color32::from_rgb(214, 39, 40)),
    );
}
