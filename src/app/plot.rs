//! Drawing a [`Figure`] with egui_plot. Log axes are drawn as log10 of the
//! data with tick labels showing the values.

use crate::figure::{Figure, Heatmap, PALETTE, Scale, Series, Style, colormap, tick_label};
use egui::Color32;
use egui_plot::{Legend, Line, LineStyle, MarkerShape, Plot, PlotPoints, Points};

fn color(i: usize, faded: bool) -> Color32 {
    let [r, g, b] = PALETTE[i % PALETTE.len()];
    if faded { Color32::from_rgba_unmultiplied(r, g, b, 150) } else { Color32::from_rgb(r, g, b) }
}

fn transform(v: f64, scale: Scale) -> Option<f64> {
    match scale {
        Scale::Linear => v.is_finite().then_some(v),
        Scale::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
    }
}

fn points(fig: &Figure, s: &Series) -> Vec<[f64; 2]> {
    s.points.iter().filter_map(|p| Some([transform(p[0], fig.x.scale)?, transform(p[1], fig.y.scale)?])).collect()
}

/// Extra items drawn over a figure (pins and cursors).
#[derive(Default)]
pub struct Overlay {
    /// Pinned series with their labels, drawn faded.
    pub pinned: Vec<Series>,
    /// Highlighted point (e.g. the time cursor), in data units.
    pub cursor: Option<[f64; 2]>,
}

/// Shows the figure in a plot of the given size.
pub fn show(ui: &mut egui::Ui, fig: &Figure, overlay: &Overlay, size: egui::Vec2, stale: bool) -> egui::Response {
    let (xs, ys) = (fig.x.scale, fig.y.scale);
    let fmt = move |scale: Scale| {
        move |mark: egui_plot::GridMark, _range: &std::ops::RangeInclusive<f64>| match scale {
            Scale::Linear => tick_label(mark.value),
            Scale::Log => tick_label(10f64.powf(mark.value)),
        }
    };
    let title = if stale { format!("{} (updating…)", fig.title) } else { fig.title.clone() };
    ui.vertical(|ui| {
        ui.label(egui::RichText::new(title).strong());
        Plot::new(("figure", fig.id.as_str()))
            .width(size.x)
            .height(size.y - 20.0)
            .legend(Legend::default())
            .x_axis_label(fig.x.title())
            .y_axis_label(fig.y.title())
            .x_axis_formatter(fmt(xs))
            .y_axis_formatter(fmt(ys))
            .label_formatter(move |hover: &egui_plot::HoverPosition<'_>| {
                let (name, p) = match hover {
                    egui_plot::HoverPosition::NearDataPoint { plot_name, position, .. } => (*plot_name, *position),
                    egui_plot::HoverPosition::Elsewhere { position } => ("", *position),
                };
                let x = if xs == Scale::Log { 10f64.powf(p.x) } else { p.x };
                let y = if ys == Scale::Log { 10f64.powf(p.y) } else { p.y };
                let head = if name.is_empty() { String::new() } else { format!("{name}\n") };
                Some(format!("{head}x = {}\ny = {}", tick_label(x), tick_label(y)))
            })
            .show(ui, |plot_ui| {
                if let Some(h) = &fig.heatmap {
                    heatmap(plot_ui, fig, h);
                }
                for s in &overlay.pinned {
                    let pts = points(fig, s);
                    plot_ui
                        .line(Line::new(s.name.clone(), PlotPoints::from(pts)).color(color(s.color, true)).width(1.5));
                }
                for s in &fig.series {
                    let pts = points(fig, s);
                    let c = color(s.color, stale);
                    match s.style {
                        Style::Line => {
                            plot_ui.line(Line::new(s.name.clone(), PlotPoints::from(pts)).color(c).width(2.0))
                        }
                        Style::Dashed => plot_ui.line(
                            Line::new(s.name.clone(), PlotPoints::from(pts))
                                .color(c)
                                .width(1.5)
                                .style(LineStyle::dashed_loose()),
                        ),
                        Style::Points => {
                            plot_ui.points(Points::new(s.name.clone(), PlotPoints::from(pts)).color(c).radius(3.0))
                        }
                        Style::Marker => plot_ui.points(
                            Points::new(s.name.clone(), PlotPoints::from(pts))
                                .color(c)
                                .radius(7.0)
                                .shape(MarkerShape::Asterisk),
                        ),
                        Style::LowerLimit => plot_ui.points(
                            Points::new(s.name.clone(), PlotPoints::from(pts))
                                .color(c)
                                .radius(6.0)
                                .shape(MarkerShape::Up),
                        ),
                        Style::UpperLimit => plot_ui.points(
                            Points::new(s.name.clone(), PlotPoints::from(pts))
                                .color(c)
                                .radius(6.0)
                                .shape(MarkerShape::Down),
                        ),
                    }
                }
                if let Some(p) = overlay.cursor
                    && let (Some(x), Some(y)) = (transform(p[0], xs), transform(p[1], ys))
                {
                    plot_ui.points(
                        Points::new("time cursor", PlotPoints::from(vec![[x, y]]))
                            .color(Color32::from_rgb(255, 200, 0))
                            .radius(5.0)
                            .shape(MarkerShape::Circle)
                            .filled(true),
                    );
                }
            })
            .response
    })
    .inner
}

/// Draws a heatmap as one filled polygon per cell (cells may be uneven on log axes).
fn heatmap(plot_ui: &mut egui_plot::PlotUi<'_>, fig: &Figure, h: &Heatmap) {
    let ex = Heatmap::edges(&h.x, fig.x.scale);
    let ey = Heatmap::edges(&h.y, fig.y.scale);
    let (lo, hi) = h.range();
    let span = if hi > lo { hi - lo } else { 1.0 };
    for j in 0..h.y.len() {
        for i in 0..h.x.len() {
            let corners = [[ex[i], ey[j]], [ex[i + 1], ey[j]], [ex[i + 1], ey[j + 1]], [ex[i], ey[j + 1]]];
            let Some(pts) = corners
                .iter()
                .map(|p| Some([transform(p[0], fig.x.scale)?, transform(p[1], fig.y.scale)?]))
                .collect::<Option<Vec<_>>>()
            else {
                continue;
            };
            let [r, g, b] = colormap((h.values[j * h.x.len() + i] - lo) / span);
            let c = Color32::from_rgb(r, g, b);
            plot_ui
                .polygon(egui_plot::Polygon::new("", PlotPoints::from(pts)).fill_color(c).stroke(egui::Stroke::NONE));
        }
    }
}
