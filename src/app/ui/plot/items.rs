//! What a plot draws inside its axes: the pinned and current series, the
//! labels, and the time cursor.

use super::paint::heatmap;
use super::{Look, Overlay, family_rgb, pin_color, points, rgb, runs, transform};
use crate::figure::{Anchor, Figure, Fill, Series, Shape, Style};
use crate::scene::timeline::{CURSOR_COLOR, Mark};
use egui::{Color32, Stroke};
use egui_plot::{Line, LineStyle, MarkerShape, PlotPoints, Points};

/// Draws the figure's items into the plot: `px` is pixels per axis unit.
pub(super) fn draw_items(
    plot_ui: &mut egui_plot::PlotUi<'_>,
    fig: &Figure,
    overlay: &Overlay,
    stale: bool,
    look: Look,
    px: [f64; 2],
) {
    if let Some(h) = &fig.heatmap {
        heatmap(plot_ui, fig, h);
    }
    for s in &overlay.pinned {
        let c = rgb(pin_color(s, overlay, look.dark), false);
        // Pins of a sweep are solid in their family colour, at the figure's
        // width; others are wide solid lines under the current curves. Like
        // the current curves, they break where the axes cannot show a point.
        let family = s.family.is_some() && overlay.family.is_some();
        let width = if family { look.line * 0.8 } else { look.line * super::PIN_WIDTH };
        for run in runs(fig, s) {
            plot_ui.line(line(s.name.clone(), run).color(c).width(width));
        }
    }
    let family = fig.family.as_ref().zip(fig.family_range());
    for s in &fig.series {
        let color = match (family, s.family) {
            (Some((f, (lo, hi))), Some(v)) => family_rgb(crate::figure::family_fraction(v, lo, hi, f.scale), look.dark),
            _ => fig.color_of(s),
        };
        let c = rgb(color, stale);
        let name = s.name.clone();
        if s.style.is_line() {
            // A point the axes cannot show breaks the line, as in the files.
            for run in runs(fig, s) {
                if s.style == Style::Arrow
                    && let [.., from, tip] = run[..]
                {
                    plot_ui.arrows(
                        egui_plot::Arrows::new(String::new(), vec![from], vec![tip])
                            .color(c)
                            .tip_length(12.0)
                            .allow_hover(false),
                    );
                }
                let run = if matches!(s.style, Style::Line | Style::Arrow) { run } else { thinned(run, px) };
                let l = line(name.clone(), run).color(c);
                plot_ui.line(match s.style {
                    Style::Dotted => l.width(look.line * 0.6).style(LineStyle::Dotted { spacing: 2.2 * look.line }),
                    Style::Dashed => l.width(look.line * 0.85).style(LineStyle::Dashed { length: 9.0 }),
                    _ => l.width(look.line),
                });
            }
            continue;
        }
        let pts = points(fig, s);
        match s.style {
            Style::Line | Style::Dotted | Style::Dashed | Style::Arrow => {}
            Style::Region => plot_ui.polygon(
                egui_plot::Polygon::new(name, PlotPoints::from(pts))
                    .fill_color(c.gamma_multiply(0.3))
                    .stroke(Stroke::new(0.6 * look.line, c)),
            ),
            marker_style => {
                // Marker shape, radius in line widths, filled.
                let (shape, radius, filled) = match marker_style {
                    Style::Marker => (MarkerShape::Diamond, 3.0, true),
                    Style::LowerLimit => (MarkerShape::Up, 2.5, true),
                    Style::UpperLimit => (MarkerShape::Down, 2.5, true),
                    Style::Symbol(shape, fill) => {
                        let shape = match shape {
                            Shape::Circle => MarkerShape::Circle,
                            Shape::Square => MarkerShape::Square,
                            Shape::Diamond => MarkerShape::Diamond,
                            Shape::TriangleDown => MarkerShape::Down,
                            Shape::TriangleUp => MarkerShape::Up,
                            Shape::Asterisk => MarkerShape::Asterisk,
                            Shape::Plus => MarkerShape::Plus,
                        };
                        (shape, 2.6, fill == Fill::Filled)
                    }
                    _ => (MarkerShape::Circle, 1.5, true),
                };
                plot_ui.points(
                    Points::new(name, PlotPoints::from(pts))
                        .color(c)
                        .radius(look.line * radius * s.size_factor() as f32)
                        .shape(shape)
                        .filled(filled),
                )
            }
        }
    }
    for l in &fig.labels {
        let (Some(x), Some(y)) = (transform(l.at[0], fig.x.scale), transform(l.at[1], fig.y.scale)) else { continue };
        let anchor = match l.anchor {
            Anchor::Left => egui::Align2::LEFT_BOTTOM,
            Anchor::Right => egui::Align2::RIGHT_BOTTOM,
            Anchor::Center => egui::Align2::CENTER_CENTER,
        };
        let text_color = if look.dark { Color32::WHITE } else { Color32::BLACK };
        let c = l.color.map_or(text_color, |k| rgb(crate::figure::PALETTE[k % crate::figure::PALETTE.len()], stale));
        // On the dark theme a coloured label is lightened to read on black.
        let c = if look.dark && l.color.is_some() { c.lerp_to_gamma(Color32::WHITE, 0.45) } else { c };
        let text = egui::RichText::new(&l.text).size(0.9 * look.text).color(c).background_color(if look.dark {
            Color32::from_black_alpha(170)
        } else {
            Color32::from_white_alpha(200)
        });
        plot_ui.text(egui_plot::Text::new("", egui_plot::PlotPoint::new(x, y), text).anchor(anchor).allow_hover(false));
    }
    // The cursor in the text colour, apart from every data colour.
    let c = if look.dark { Color32::WHITE } else { Color32::BLACK };
    for mark in &overlay.cursor {
        match mark {
            Mark::Point(p, color) => {
                if let (Some(x), Some(y)) = (transform(p[0], fig.x.scale), transform(p[1], fig.y.scale)) {
                    // A dot in the text colour; one on a curve of several
                    // has its curve's colour inside the ring.
                    plot_ui.points(
                        Points::new("time cursor", PlotPoints::from(vec![[x, y]]))
                            .color(c)
                            .radius(look.line * 2.8)
                            .shape(MarkerShape::Circle)
                            .filled(true)
                            .allow_hover(false),
                    );
                    if let Some(k) = color {
                        plot_ui.points(
                            Points::new("time cursor", PlotPoints::from(vec![[x, y]]))
                                .color(rgb(crate::figure::PALETTE[k % crate::figure::PALETTE.len()], false))
                                .radius(look.line * 1.9)
                                .shape(MarkerShape::Circle)
                                .filled(true)
                                .allow_hover(false),
                        );
                    }
                }
            }
            Mark::Time(x) => {
                if let Some(x) = transform(*x, fig.x.scale) {
                    plot_ui.vline(
                        egui_plot::VLine::new("time cursor", x)
                            .color(c)
                            .width(look.line * 0.7)
                            .style(LineStyle::Dashed { length: 6.0 })
                            .allow_hover(false),
                    );
                }
            }
            Mark::Curve(points) => {
                let s = Series::new("time cursor", points.clone(), Style::Line, CURSOR_COLOR);
                for run in runs(fig, &s) {
                    plot_ui.line(line("time cursor".into(), run).color(c).width(look.line * 1.8));
                }
            }
        }
    }
}

/// A dashed line's points without those closer than a few pixels (at `px`
/// pixels per unit) to the last one kept: egui cuts dashes into one piece
/// per segment, and pieces shorter than a pixel all but vanish, so a dense
/// dashed curve (a collision's 400 samples) would show only specks.
fn thinned(pts: Vec<[f64; 2]>, px: [f64; 2]) -> Vec<[f64; 2]> {
    const GAP: f64 = 3.0;
    if pts.len() < 3 || !px.iter().all(|v| v.is_finite() && *v > 0.0) {
        return pts;
    }
    let mut out = Vec::with_capacity(pts.len());
    let mut last = pts[0];
    out.push(last);
    for p in &pts[1..pts.len() - 1] {
        if ((p[0] - last[0]) * px[0]).hypot((p[1] - last[1]) * px[1]) >= GAP {
            out.push(*p);
            last = *p;
        }
    }
    out.push(pts[pts.len() - 1]);
    out
}

/// A line through `pts` drawn as a stroke of even width. (egui_plot would
/// otherwise merge points less than a pixel apart into vertical bands, which
/// makes steep stretches of dense curves look thinner than flat ones.)
fn line(name: String, pts: Vec<[f64; 2]>) -> Line<'static> {
    Line::new(name, PlotPoints::from(pts)).allow_band(false)
}
