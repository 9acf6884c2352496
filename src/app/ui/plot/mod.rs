//! Drawing a [`Figure`] with egui_plot by the same rules as the exported
//! files: ticks from [`crate::figure::ticks`], the default range from
//! [`View::of`], the legend in a free corner (from
//! [`crate::figure::layout::free_corner`]) or beside the plot, colour bars
//! for heat maps and families, and the shared palette and line styles. Log
//! axes are drawn as log10 of the data with tick labels showing the values.

use crate::figure::layout::{self, ColourBar, View};
use crate::figure::ticks::ticks;
use crate::figure::{Family, Figure, Scale, Series, Style, colormap, family_fraction, human};
use crate::scene::timeline::Mark;
use egui::{Color32, Rect, Vec2};
use egui_plot::{GridInput, GridMark, Plot};
use std::cell::RefCell;
use std::rc::Rc;

/// The largest share of a panel's height a legend below its plot takes:
/// every entry shows, in columns as wide as the widest, unless the panel is
/// too small for that, when the rows that fit show and the rest scroll.
const LEGEND_BELOW_SHARE: f32 = 0.4;

mod items;
mod paint;
use items::draw_items;
use paint::{corner_rect, legend_size_one, paint_bar, paint_entry, paint_legend};

fn rgb(c: [u8; 3], faded: bool) -> Color32 {
    if faded { Color32::from_rgba_unmultiplied(c[0], c[1], c[2], 110) } else { Color32::from_rgb(c[0], c[1], c[2]) }
}

/// A band across the top of a plot that says what it shows is not the
/// result yet (a coarse preview, a live view of a run, or the result of the
/// parameters before): an audience must not read it as the answer. It keeps
/// clear of the legend drawn inside the plot (`legend`): beside it at the
/// top where there is room, else along the bottom.
fn provisional(ui: &egui::Ui, frame: Rect, look: Look, legend: Option<Rect>) {
    let painter = ui.painter_at(frame);
    let font = egui::FontId::proportional(look.text);
    let mut galley =
        painter.layout_no_wrap("provisional: the full result is computing".into(), font.clone(), Color32::BLACK);
    // A narrow plot (a phone) gets the short form.
    if galley.size().x + 28.0 > frame.width() {
        galley = painter.layout_no_wrap("provisional".into(), font, Color32::BLACK);
    }
    let size = galley.size() + Vec2::new(16.0, 8.0);
    let at = |x: f32, y: f32| Rect::from_min_size(egui::pos2(x, y), size);
    let top = at(frame.center().x - size.x / 2.0, frame.top() + 6.0);
    let band = match legend {
        Some(l) if l.expand(4.0).intersects(top) => {
            let right_of = at(l.right() + 8.0, frame.top() + 6.0);
            let left_of = at(l.left() - 8.0 - size.x, frame.top() + 6.0);
            if right_of.right() <= frame.right() - 6.0 {
                right_of
            } else if left_of.left() >= frame.left() + 6.0 {
                left_of
            } else {
                at(frame.center().x - size.x / 2.0, frame.bottom() - 6.0 - size.y)
            }
        }
        _ => top,
    };
    painter.rect_filled(band, 4.0, Color32::from_rgba_unmultiplied(255, 196, 64, 230));
    painter.galley(band.min + Vec2::new(8.0, 4.0), galley, Color32::BLACK);
}

fn transform(v: f64, scale: Scale) -> Option<f64> {
    match scale {
        Scale::Linear => v.is_finite().then_some(v),
        Scale::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
    }
}

fn untransform(v: f64, scale: Scale) -> f64 {
    match scale {
        Scale::Linear => v,
        Scale::Log => 10f64.powf(v),
    }
}

fn points(fig: &Figure, s: &Series) -> Vec<[f64; 2]> {
    s.points.iter().filter_map(|p| Some([transform(p[0], fig.x.scale)?, transform(p[1], fig.y.scale)?])).collect()
}

/// The runs of a line between the points its axes cannot show (non-finite,
/// or not positive on a log axis), in plot coordinates.
fn runs(fig: &Figure, s: &Series) -> Vec<Vec<[f64; 2]>> {
    let mut out: Vec<Vec<[f64; 2]>> = vec![Vec::new()];
    for p in &s.points {
        match (transform(p[0], fig.x.scale), transform(p[1], fig.y.scale)) {
            (Some(x), Some(y)) => out.last_mut().into_iter().for_each(|r| r.push([x, y])),
            _ if out.last().is_some_and(|r| !r.is_empty()) => out.push(Vec::new()),
            _ => {}
        }
    }
    out.retain(|r| !r.is_empty());
    out
}

/// Extra items drawn over a figure (pins and cursors).
#[derive(Default)]
pub struct Overlay {
    /// Pinned series with their labels: dashed in their palette colour, or
    /// coloured by value when they belong to `family` (a sweep).
    pub pinned: Vec<Series>,
    /// The parameter a sweep varied across the pinned series marked with a
    /// family value.
    pub family: Option<Family>,
    /// What the time cursor marks on this figure, in data units.
    pub cursor: Vec<Mark>,
}

/// How plots are drawn: line width and text size grow in lecture mode.
#[derive(Clone, Copy)]
pub struct Look {
    /// Width of data lines, points.
    pub line: f32,
    /// Size of legend and colour-bar text, points.
    pub text: f32,
    /// Whether the window uses a dark theme (for the legend's background).
    pub dark: bool,
    /// Whether the legend is drawn (a scene shows a legend that repeats an
    /// earlier panel's only once).
    pub legend: bool,
}

/// Labelled and unlabelled grid marks for one axis, from the shared tick
/// rule; the labels are remembered for the axis formatter.
/// On an x-axis (`char_px` > 0, the width of one character of tick text),
/// fewer labels are asked for until their text fits side by side.
fn grid_marks(
    input: GridInput,
    scale: Scale,
    px_per_label: f64,
    char_px: f64,
    labels: &RefCell<Vec<(f64, String)>>,
) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    let span = hi - lo;
    let usable = span > 0.0 && input.base_step_size > 0.0;
    if !usable {
        return Vec::new();
    }
    // egui_plot passes the value of its minimum grid spacing (8 points).
    let px = span / input.base_step_size * 8.0;
    let mut n = ((px / px_per_label) as usize).clamp(2, 10);
    let mut t = ticks(untransform(lo, scale), untransform(hi, scale), scale, n);
    while char_px > 0.0 && n > 2 {
        let text: usize = t.iter().filter_map(|t| t.label.as_ref()).map(|l| l.chars().count() + 2).sum();
        if text as f64 * char_px <= px {
            break;
        }
        n -= 1;
        t = ticks(untransform(lo, scale), untransform(hi, scale), scale, n);
    }
    let mut remembered = labels.borrow_mut();
    remembered.clear();
    t.into_iter()
        .filter_map(|t| {
            let v = transform(t.value, scale)?;
            // An x label that would reach past the axis' right end is left
            // off rather than cut.
            let past_end = |l: &str| char_px > 0.0 && (hi - v) / span * px < 0.5 * l.chars().count() as f64 * char_px;
            Some(match t.label {
                Some(l) if past_end(&l) => GridMark { value: v, step_size: span / 60.0 },
                Some(l) => {
                    remembered.push((v, l));
                    // A step as wide as the axis: labels and lines at full strength.
                    GridMark { value: v, step_size: span }
                }
                None => GridMark { value: v, step_size: span / 60.0 },
            })
        })
        .collect()
}

fn label_of(v: f64, labels: &RefCell<Vec<(f64, String)>>) -> String {
    labels
        .borrow()
        .iter()
        .find(|(x, _)| (x - v).abs() <= 1e-9 * x.abs().max(1e-300))
        .map_or(String::new(), |(_, l)| l.clone())
}

/// One legend row.
pub(super) struct Entry {
    text: String,
    style: Style,
    color: Color32,
    swatch: bool,
    /// A pinned curve: drawn as a wide line ([`PIN_WIDTH`]).
    pin: bool,
}

/// A legend below a plot `width` wide, for entries `widths` wide filled top
/// to bottom: (rows, the columns' widths) with the most columns that fit,
/// each as wide as its widest entry (one column, cut to `width`, when none fit).
fn legend_columns(widths: &[f32], width: f32, gap: f32) -> (usize, Vec<f32>) {
    let n = widths.len();
    for wanted in (2..=n).rev() {
        let rows = n.div_ceil(wanted);
        let columns: Vec<f32> = widths.chunks(rows).map(|c| c.iter().copied().fold(0.0, f32::max)).collect();
        let total = columns.iter().sum::<f32>() + gap * (columns.len() - 1) as f32;
        if total <= width {
            return (rows, columns);
        }
    }
    (n, vec![widths.iter().copied().fold(0.0, f32::max).min(width)])
}

/// Pinned curves are lines this many times as wide as the figure's own,
/// solid, under them: neither a dashed reference curve nor a current one.
const PIN_WIDTH: f32 = 2.4;

/// What a figure's legend lists: (name, style, colour) of each entry, to
/// tell panels with the same legend apart from the rest.
pub fn legend_signature(fig: &Figure) -> Vec<(String, Style, [u8; 3])> {
    let mut out = fig.legend();
    if let Some(h) = &fig.heatmap {
        out.extend(
            h.categories.iter().enumerate().map(|(i, c)| (c.clone(), Style::Points, h.color_of(i as f64, (0.0, 1.0)))),
        );
    }
    out
}

fn entries(fig: &Figure, overlay: &Overlay, stale: bool) -> Vec<Entry> {
    let mut out: Vec<Entry> = fig
        .legend()
        .into_iter()
        .map(|(text, style, color)| Entry { text, style, color: rgb(color, stale), swatch: false, pin: false })
        .collect();
    for s in overlay.pinned.iter().filter(|s| s.family.is_none() || overlay.family.is_none()) {
        out.push(Entry {
            text: s.name.clone(),
            style: Style::Line,
            color: rgb(pin_color(s, overlay, false), false),
            swatch: false,
            pin: true,
        });
    }
    if let Some(h) = &fig.heatmap {
        for (i, c) in h.categories.iter().enumerate() {
            out.push(Entry {
                text: c.clone(),
                style: Style::Points,
                color: rgb(h.color_of(i as f64, (0.0, 1.0)), false),
                swatch: true,
                pin: false,
            });
        }
    }
    out
}

fn pin_range(overlay: &Overlay) -> Option<(f64, f64)> {
    let vals = overlay.pinned.iter().filter_map(|s| s.family);
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    (overlay.family.is_some() && lo <= hi).then_some((lo, hi))
}

/// Colours of pinned curves: the hues of Paul Tol's "muted" scheme
/// (colour-blind safe) that the figures' own Okabe–Ito colours do not use,
/// so that a pin never reads as one of the scene's reference curves; each
/// set in lightness so that it stands at least 3:1 against both plot
/// backgrounds, white and the dark theme's #1B1B1B (the scheme's indigo,
/// wine, teal and sand did not).
const PIN_PALETTE: [[u8; 3]; 8] = [
    [119, 102, 204],
    [204, 102, 119],
    [17, 136, 68],
    [170, 68, 153],
    [170, 90, 40],
    [128, 128, 40],
    [40, 128, 110],
    [140, 120, 30],
];

/// Where a family's colours start on the dark theme: viridis' darkest
/// purples vanish on a black plot.
const DARK_FAMILY_FLOOR: f64 = 0.25;

/// The colour of a family member at `frac` (a [`family_fraction`], 0 to
/// [`crate::figure::FAMILY_TOP`]); on the dark theme the map starts higher.
pub(super) fn family_rgb(frac: f64, dark: bool) -> [u8; 3] {
    let top = crate::figure::FAMILY_TOP;
    colormap(if dark { DARK_FAMILY_FLOOR + frac / top * (top - DARK_FAMILY_FLOOR) } else { frac })
}

fn pin_color(s: &Series, overlay: &Overlay, dark: bool) -> [u8; 3] {
    match (&overlay.family, s.family, pin_range(overlay)) {
        (Some(f), Some(v), Some((lo, hi))) => family_rgb(family_fraction(v, lo, hi, f.scale), dark),
        // Pins are numbered from 1.
        _ => PIN_PALETTE[s.color.saturating_sub(1) % PIN_PALETTE.len()],
    }
}

fn colour_bar(fig: &Figure, overlay: &Overlay) -> Option<ColourBar> {
    ColourBar::of(fig).or_else(|| ColourBar::family(overlay.family.as_ref()?, pin_range(overlay)?))
}

/// Shows the figure in a panel of the given size (title, plot, legend and
/// colour bar) and returns the panel's response. `locked` keeps the axes at
/// a chosen view instead of following the data.
pub fn show(
    ui: &mut egui::Ui,
    fig: &Figure,
    overlay: &Overlay,
    size: Vec2,
    stale: bool,
    look: Look,
    locked: Option<View>,
) -> Shown {
    let (xs, ys) = (fig.x.scale, fig.y.scale);
    let view = locked.unwrap_or_else(|| View::of(fig));
    let title = if stale { format!("{} (updating…)", fig.title) } else { fig.title.clone() };
    let font = egui::FontId::proportional(look.text);
    let legend = if look.legend { entries(fig, overlay, stale) } else { Vec::new() };
    let bar = colour_bar(fig, overlay);
    let shown = ui.vertical(|ui| {
        ui.set_max_width(size.x);
        // A long title is set smaller before it is cut.
        let title_size = {
            let full = look.text + 1.0;
            let w =
                ui.painter().layout_no_wrap(title.clone(), egui::FontId::proportional(full), Color32::WHITE).size().x;
            if w > size.x { (full * size.x / w).max(0.8 * full) } else { full }
        };
        ui.add(egui::Label::new(egui::RichText::new(title).strong().size(title_size)).truncate());
        // Legend size in points, to find it a free corner.
        let row = look.text * 1.45;
        // Each entry's width (swatch, gap, text), measured once.
        let entry_w: Vec<f32> = legend.iter().map(|e| legend_size_one(ui, e, &font).x).collect();
        // A margin after the longest entry.
        let legend_size =
            Vec2::new(entry_w.iter().copied().fold(0.0, f32::max) + 4.0, legend.len() as f32 * row + 10.0);
        let bar_w = if bar.is_some() { 36.0 + 6.0 * look.text } else { 0.0 };
        let mut plot_size = Vec2::new(size.x - bar_w, size.y - look.text * 1.6 - 6.0);
        // Whether the legend found no free corner in the last frame, measured
        // on the plot as drawn (its frame and range); it then goes outside.
        let memory = ui.scope_id().with(("legend-outside", fig.id.as_str()));
        let was_outside = !legend.is_empty() && ui.data(|d| d.get_temp::<bool>(memory)).unwrap_or(false);
        // No free corner: the legend goes beside the plot when it is narrow
        // enough, below it otherwise.
        // A map already has its colour bar beside it: its legend goes below.
        // Beside only when it is as short as the plot; below, at most three
        // rows are shown and the rest scroll, so that a long legend (many
        // pins) neither pushes the panel out nor shrinks the plot away.
        let beside = was_outside && bar.is_none() && legend_size.x < 0.4 * plot_size.x && legend_size.y < plot_size.y;
        let below = was_outside && !beside;
        if beside {
            plot_size.x -= legend_size.x + 8.0;
        }
        // Below: entries in as many columns as the panel holds, filled top
        // to bottom.
        let gap = ui.spacing().item_spacing;
        let (rows_below, columns) = legend_columns(&entry_w, size.x - 16.0, gap.x);
        let below_rows = if below { rows_below } else { 0 };
        // A wrapped row of entries: the entry and the spacing between rows.
        let row_below = row + gap.y;
        let below_shown = below_rows.min(((LEGEND_BELOW_SHARE * size.y / row_below) as usize).max(1));
        if below {
            plot_size.y -= below_shown as f32 * row_below + 8.0;
        }
        if fig.square {
            // The frame is square when the plot's outer size allows for its
            // axes: about three text heights below, four text widths left.
            let (axes_x, axes_y) = (4.5 * look.text + 10.0, 3.2 * look.text + 10.0);
            let side = (plot_size.x - axes_x).min(plot_size.y - axes_y).max(40.0);
            plot_size = Vec2::new(side + axes_x, side + axes_y);
        }
        // The frame is shorter than the plot by the x-axis ticks and title.
        let y_title = axis_title_fitting(ui, &fig.y, plot_size.y - 3.2 * look.text - 16.0, look.text);
        let x_labels: Rc<RefCell<Vec<(f64, String)>>> = Rc::default();
        let y_labels: Rc<RefCell<Vec<(f64, String)>>> = Rc::default();
        let (xl1, xl2, yl1, yl2) =
            (Rc::clone(&x_labels), Rc::clone(&x_labels), Rc::clone(&y_labels), Rc::clone(&y_labels));
        let (x_unit, y_unit) = (fig.x.unit.clone(), fig.y.unit.clone());
        let (x_name, y_name) = (fig.x.label.clone(), fig.y.label.clone());
        let map = fig.heatmap.as_ref();
        let bounds = |r: [f64; 2], s: Scale| match (transform(r[0], s), transform(r[1], s)) {
            (Some(a), Some(b)) if b > a => (a, b),
            _ => (0.0, 1.0),
        };
        let (bx, by) = (bounds(view.x, xs), bounds(view.y, ys));
        // Room per labelled tick, points: about four characters of the tick
        // text across, three lines up.
        let (x_gap, y_gap) = (4.0 * look.text as f64, 2.9 * look.text as f64);
        let char_px = 0.6 * look.text as f64;
        let response = ui
            .horizontal(|ui| {
                let mut plot = Plot::new(("figure", fig.id.as_str()))
                    .width(plot_size.x.max(80.0))
                    .height(plot_size.y.max(60.0))
                    // Grid lines in grey, lighter than any data line, so that
                    // reference lines on a decade (Ωt_s = 1, loading = 1) stay
                    // visible on a projector.
                    .grid_color(if look.dark { Color32::from_gray(105) } else { Color32::from_gray(185) })
                    .x_axis_label(fig.x.title())
                    .y_axis_label(y_title)
                    .default_x_bounds(bx.0, bx.1)
                    .default_y_bounds(by.0, by.1)
                    .x_grid_spacer(move |input| grid_marks(input, xs, x_gap, char_px, &xl1))
                    .y_grid_spacer(move |input| grid_marks(input, ys, y_gap, 0.0, &yl1))
                    .x_axis_formatter(move |mark, _| label_of(mark.value, &xl2))
                    .y_axis_formatter(move |mark, _| label_of(mark.value, &yl2))
                    .label_formatter(move |hover: &egui_plot::HoverPosition<'_>| {
                        let (name, p) = match hover {
                            egui_plot::HoverPosition::NearDataPoint { plot_name, position, .. } => {
                                (*plot_name, *position)
                            }
                            egui_plot::HoverPosition::Elsewhere { position } => ("", *position),
                        };
                        let x = untransform(p.x, xs);
                        let y = untransform(p.y, ys);
                        // Away from the data the values are the pointer's, and
                        // the label says so (an audience reads them as data).
                        let head = if name.is_empty() { "pointer at\n".to_string() } else { format!("{name}\n") };
                        // On a map: the cell under the pointer, as Inspect names it.
                        if let Some((h, (c, v, text))) = map.and_then(|h| Some((h, h.cell_at([x, y], (xs, ys))?))) {
                            let unit = if h.unit.is_empty() { String::new() } else { format!(" {}", h.unit) };
                            // A map of log₁₀ X reads as X.
                            let value = match h.label.strip_prefix("log₁₀ ") {
                                Some(q) if h.categories.is_empty() && v.is_finite() => {
                                    format!("{q} = {}{unit}", human(10f64.powf(v)))
                                }
                                _ => format!("{} = {text}{unit}", h.label),
                            };
                            return Some(format!(
                                "{value}\nin the cell at\n{x_name} = {} {x_unit}\n{y_name} = {} {y_unit}",
                                human(c[0]),
                                human(c[1])
                            ));
                        }
                        Some(format!("{head}{x_name} = {} {x_unit}\n{y_name} = {} {y_unit}", human(x), human(y)))
                    });
                // egui_plot keeps the first default bounds it was given: when
                // the data's range moves (a parameter changed, axes unlocked),
                // the plot is reset to the new range; a user's zoom stays
                // while the range does not change.
                let range_key = egui::Id::NULL.with(("figure-range", fig.id.as_str()));
                let range = [bx.0, bx.1, by.0, by.1];
                if ui.data(|d| d.get_temp::<[f64; 4]>(range_key)) != Some(range) {
                    ui.data_mut(|d| d.insert_temp(range_key, range));
                    plot = plot.reset();
                }
                // Pixels per axis unit (log10 units on log axes) at the
                // default view, for thinning dense dashed lines.
                let px = [plot_size.x as f64 / (bx.1 - bx.0), plot_size.y as f64 / (by.1 - by.0)];
                let shown = plot.show(ui, |plot_ui| draw_items(plot_ui, fig, overlay, stale, look, px));
                let frame = *shown.transform.frame();
                // A click (not a drag) at a point of the plot, in axis units.
                let clicked =
                    shown.response.clicked().then(|| shown.response.interact_pointer_pos()).flatten().map(|pos| {
                        let v = shown.transform.value_from_position(pos);
                        ([untransform(v.x, xs), untransform(v.y, ys)], pos)
                    });
                // The colour bar first: a legend inside the plot places its
                // labels with the layout, which would move what follows.
                if let Some(b) = &bar {
                    let (rect, _) = ui.allocate_exact_size(Vec2::new(bar_w, plot_size.y), egui::Sense::hover());
                    paint_bar(ui, b, Rect::from_x_y_ranges(rect.x_range(), frame.y_range()), look);
                }
                let mut legend_inside = None;
                if !legend.is_empty() {
                    // The frame the plot would have with the legend inside.
                    let inside_w = frame.width() + if beside { legend_size.x + 8.0 } else { 0.0 };
                    let inside_h = frame.height() + if below { below_shown as f32 * row_below + 8.0 } else { 0.0 };
                    let b = shown.transform.bounds();
                    let drawn = View {
                        x: [untransform(b.min()[0], xs), untransform(b.max()[0], xs)],
                        y: [untransform(b.min()[1], ys), untransform(b.max()[1], ys)],
                        x_scale: xs,
                        y_scale: ys,
                    };
                    let frac = |a: f32, total: f32| (a / total.max(1.0)) as f64;
                    let found = layout::free_corner(
                        fig.series.iter().chain(&overlay.pinned),
                        fig.heatmap.is_some(),
                        &drawn,
                        [frac(legend_size.x, inside_w), frac(legend_size.y, inside_h)],
                        [frac(8.0, inside_w), frac(8.0, inside_h)],
                    );
                    if let (Some(c), false) = (found, was_outside) {
                        let rect = corner_rect(frame, c, legend_size);
                        paint_legend(ui, &legend, rect, look);
                        legend_inside = Some(rect);
                    }
                    if found.is_none() != was_outside {
                        ui.data_mut(|d| d.insert_temp(memory, found.is_none()));
                        ui.ctx().request_repaint();
                    }
                }
                if beside {
                    let (rect, _) = ui.allocate_exact_size(legend_size, egui::Sense::hover());
                    paint_legend(ui, &legend, rect, look);
                }
                // Last, so that no legend hides it.
                if stale {
                    provisional(ui, frame, look, legend_inside);
                }
                let b = shown.transform.bounds();
                let placed =
                    Placed { frame, bounds: [b.min()[0], b.max()[0], b.min()[1], b.max()[1]], scales: (xs, ys) };
                (shown.response, clicked, placed)
            })
            .inner;
        if below {
            let width = size.x;
            // The scroll bar always shows when rows are hidden: they exist.
            let bar = if below_rows > below_shown {
                egui::scroll_area::ScrollBarVisibility::AlwaysVisible
            } else {
                egui::scroll_area::ScrollBarVisibility::AlwaysHidden
            };
            ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
            egui::ScrollArea::vertical()
                .id_salt(("legend-below", fig.id.as_str()))
                .scroll_bar_visibility(bar)
                .max_height(below_shown as f32 * row_below + 4.0)
                .max_width(width)
                .show(ui, |ui| {
                    ui.set_max_width(width);
                    let (block, _) = ui.allocate_exact_size(
                        Vec2::new(width - 16.0, below_rows as f32 * row_below),
                        egui::Sense::hover(),
                    );
                    let mut x = block.left();
                    for (c, column) in legend.chunks(below_rows.max(1)).enumerate() {
                        for (r, e) in column.iter().enumerate() {
                            let at = egui::pos2(x, block.top() + r as f32 * row_below);
                            paint_entry(ui, e, Rect::from_min_size(at, Vec2::new(columns[c], row)), look);
                        }
                        x += columns[c] + gap.x;
                    }
                });
        }
        response
    });
    // The whole panel: title, plot with its axes, legend and colour bar.
    let (plot_response, clicked, placed) = shown.inner;
    Shown { response: shown.response.union(plot_response), clicked, frame: placed.frame, placed }
}

/// A drawn panel: its response, and where its plot was clicked (axis units).
pub struct Shown {
    /// The whole panel's response.
    pub response: egui::Response,
    /// The point clicked in this frame, if any: in axis units and on the screen.
    pub clicked: Option<([f64; 2], egui::Pos2)>,
    /// The plot's frame (inside its axes).
    pub frame: egui::Rect,
    /// Where the plot was drawn and the range it showed.
    pub placed: Placed,
}

/// Where a plot was drawn and the range it showed: turns a point of the
/// screen into axis units (for ink drawn over the plot).
#[derive(Debug, Clone, Copy)]
pub struct Placed {
    /// The plot's frame (inside its axes), screen points.
    pub frame: egui::Rect,
    /// The range shown, [x₀, x₁, y₀, y₁] in plot units (log₁₀ on a log axis).
    bounds: [f64; 4],
    /// The axes' scales.
    scales: (Scale, Scale),
}

impl Placed {
    /// The point of the screen `pos` in axis units (outside the frame too).
    pub fn value_at(&self, pos: egui::Pos2) -> [f64; 2] {
        let [x0, x1, y0, y1] = self.bounds;
        let f = self.frame;
        let fx = f64::from((pos.x - f.left()) / f.width().max(1.0));
        let fy = f64::from((f.bottom() - pos.y) / f.height().max(1.0));
        [untransform(x0 + fx * (x1 - x0), self.scales.0), untransform(y0 + fy * (y1 - y0), self.scales.1)]
    }
}

/// An axis title that fits `room` points: as it is, else in a smaller size,
/// else with its quantity shortened (the unit always kept), so that a short
/// plot's y title does not run into the figure title.
fn axis_title_fitting(ui: &egui::Ui, axis: &crate::figure::Axis, room: f32, size: f32) -> egui::RichText {
    let width = |text: &str, size: f32| {
        ui.painter().layout_no_wrap(text.to_string(), egui::FontId::proportional(size), Color32::WHITE).size().x
    };
    let title = axis.title();
    if width(&title, size) <= room {
        return egui::RichText::new(title);
    }
    let small = 0.8 * size;
    if width(&title, small) <= room {
        return egui::RichText::new(title).size(small);
    }
    let unit = if axis.unit.is_empty() { String::new() } else { format!(" [{}]", axis.unit) };
    let mut label: Vec<char> = axis.label.chars().collect();
    while !label.is_empty() {
        label.pop();
        let text = format!("{}…{unit}", label.iter().collect::<String>().trim_end());
        if width(&text, small) <= room {
            return egui::RichText::new(text).size(small);
        }
    }
    egui::RichText::new(unit.trim().to_string()).size(small)
}

#[cfg(test)]
mod pin_tests {
    use super::PIN_PALETTE;

    /// WCAG relative luminance of an sRGB colour.
    fn luminance(c: [u8; 3]) -> f64 {
        let channel = |v: u8| {
            let v = f64::from(v) / 255.0;
            if v <= 0.03928 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
        };
        0.2126 * channel(c[0]) + 0.7152 * channel(c[1]) + 0.0722 * channel(c[2])
    }

    fn contrast(a: [u8; 3], b: [u8; 3]) -> f64 {
        let (x, y) = (luminance(a), luminance(b));
        (x.max(y) + 0.05) / (x.min(y) + 0.05)
    }

    /// Every pin colour stands at least 3:1 against the light and the dark
    /// plot background (and the check fails for the colours it replaced).
    #[test]
    fn pin_colours_stand_out_on_both_themes() {
        let (white, dark) = ([255, 255, 255], [27, 27, 27]);
        for c in PIN_PALETTE {
            assert!(contrast(c, white) >= 3.0, "{c:?} on white: {:.2}", contrast(c, white));
            assert!(contrast(c, dark) >= 3.0, "{c:?} on #1B1B1B: {:.2}", contrast(c, dark));
        }
        assert!(contrast([51, 34, 136], dark) < 1.5, "Tol's indigo on the dark theme");
        assert!(contrast([221, 204, 119], white) < 2.0, "Tol's sand on white");
    }
}

#[cfg(test)]
mod legend_tests {
    use super::legend_columns;

    /// The most columns that fit, filled top to bottom, each as wide as its
    /// widest entry; every entry has a place.
    #[test]
    fn legend_columns_are_the_most_that_fit() {
        let widths = [300.0, 100.0, 100.0, 250.0, 80.0];
        // Three columns (rows of 2) would need 300 + 250 + 80 + 2 gaps = 646.
        assert_eq!(legend_columns(&widths, 600.0, 8.0), (3, vec![300.0, 250.0]));
        assert_eq!(legend_columns(&widths, 646.0, 8.0), (2, vec![300.0, 250.0, 80.0]));
        assert_eq!(legend_columns(&widths, 2000.0, 8.0), (1, widths.to_vec()));
        // Nothing fits: one column, cut to the width.
        assert_eq!(legend_columns(&widths, 200.0, 8.0), (5, vec![200.0]));
        assert_eq!(legend_columns(&[], 200.0, 8.0), (0, vec![0.0]));
        for n in 1..=20 {
            for width in [150.0, 400.0, 558.0, 700.0, 900.0] {
                let widths: Vec<f32> = (0..n).map(|k| 60.0 + (k * 37 % 200) as f32).collect();
                let (rows, columns) = legend_columns(&widths, width, 8.0);
                // Filled top to bottom, `rows` at a time: one width per column.
                assert_eq!(widths.chunks(rows).count(), columns.len());
                assert!(columns.len() == 1 || columns.iter().sum::<f32>() + 8.0 * (columns.len() - 1) as f32 <= width);
            }
        }
    }
}
