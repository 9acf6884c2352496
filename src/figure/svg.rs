//! A figure drawn as an SVG document, with text kept as text. PNG files are
//! this document rasterised, so both files show the same figure; ticks,
//! legend placement, colours and line styles come from the same rules the
//! window uses ([`super::ticks`], [`super::layout`], [`super::PALETTE`]).
//!
//! The document is written directly rather than through a plotting crate:
//! the figure needs ticks at chosen positions with superscript labels, a
//! legend placed by the shared rule (inside a free corner or outside the
//! plot) and colour bars, none of which the plotting crates available here
//! let one place; SVG itself is a handful of elements.

use super::layout::{self, ColourBar, View};
use super::ticks::{Tick, ticks};
use super::{Anchor, Figure, Fill, Heatmap, Label, PALETTE, Series, Shape, Style, family_fraction};
use std::fmt::Write;

/// Font family named in the document (the bundled font, then any sans-serif).
const FONT: &str = "DejaVu Sans, sans-serif";

/// Sizes of one rendering, scaled with the image width.
struct Look {
    s: f64,
    title: f64,
    axis: f64,
    tick: f64,
    legend: f64,
    line: f64,
}

impl Look {
    fn for_width(w: f64) -> Look {
        let s = (w / 800.0).max(0.4);
        Look { s, title: 18.0 * s, axis: 15.0 * s, tick: 13.5 * s, legend: 13.0 * s, line: 2.2 * s }
    }
    /// Approximate width of `text` at font size `fs` (DejaVu Sans averages
    /// about 0.6 em per character for labels like these).
    fn width(&self, text: &str, fs: f64) -> f64 {
        text.chars().map(|c| if is_narrow(c) { 0.35 } else { 0.6 }).sum::<f64>() * fs
    }
}

fn is_narrow(c: char) -> bool {
    matches!(c, '⁰' | '¹' | '²' | '³' | '⁴' | '⁵' | '⁶' | '⁷' | '⁸' | '⁹' | '⁻' | '.' | ',' | ' ' | 'i' | 'l' | '|')
}

/// One legend row: what it shows and its sample.
struct Entry {
    text: String,
    sample: Sample,
}

enum Sample {
    Series(Style, [u8; 3]),
    Swatch([u8; 3]),
}

/// The figure as an SVG document of `size` pixels.
pub fn render(fig: &Figure, size: (u32, u32)) -> String {
    let (w, h) = (f64::from(size.0.max(50)), f64::from(size.1.max(50)));
    let look = Look::for_width(w);
    let view = View::of(fig);
    let entries = legend_entries(fig);
    let bar = ColourBar::of(fig);

    // Margins around the plot area.
    let s = look.s;
    let top = 12.0 * s + look.title * 1.5;
    let bottom = 14.0 * s + look.axis * 1.4 + look.tick * 1.4 + 6.0 * s;
    let plot_h = (h - top - bottom).max(20.0);
    let y_ticks = ticks(view.y[0], view.y[1], view.y_scale, ((plot_h / (look.tick * 2.8)) as usize).clamp(2, 10));
    let y_label_w =
        y_ticks.iter().filter_map(|t| t.label.as_deref()).map(|l| look.width(l, look.tick)).fold(0.0, f64::max);
    let left = 12.0 * s + look.axis * 1.4 + y_label_w + 8.0 * s;
    let bar_w = bar.as_ref().map_or(0.0, |b| {
        let labels = ticks(b.lo, b.hi, b.scale, 6);
        let lw = labels.iter().filter_map(|t| t.label.as_deref()).map(|l| look.width(l, look.tick)).fold(0.0, f64::max);
        16.0 * s + 18.0 * s + 6.0 * s + lw + 8.0 * s + look.axis * 1.4
    });
    let row = look.legend * 1.45;
    let sample_w = 34.0 * s;
    let legend_w = entries.iter().map(|e| look.width(&e.text, look.legend)).fold(0.0, f64::max) + sample_w + 22.0 * s;
    let legend_h = entries.len() as f64 * row + 12.0 * s;
    let mut right = 18.0 * s + bar_w;
    let inside_w = (w - left - right).max(20.0);
    let inset = [10.0 * s / inside_w, 10.0 * s / plot_h];
    let corner = if entries.is_empty() {
        None
    } else {
        layout::free_corner(&fig.series, fig.heatmap.is_some(), &view, [legend_w / inside_w, legend_h / plot_h], inset)
    };
    let outside = !entries.is_empty() && corner.is_none();
    if outside {
        right += legend_w + 12.0 * s;
    }
    let mut plot = Rect { x0: left, y0: top, x1: (w - right).max(left + 20.0), y1: top + plot_h };
    if fig.square && plot.x1 - plot.x0 > plot_h {
        plot.x1 = plot.x0 + plot_h;
    }
    let x_ticks = ticks(view.x[0], view.x[1], view.x_scale, x_label_count(&view, plot.x1 - plot.x0, &look));

    let mut svg = String::with_capacity(64 * 1024);
    let _ = write!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="{FONT}">"#
    );
    let _ = write!(svg, r#"<title>{}</title><rect width="100%" height="100%" fill="white"/>"#, esc(&fig.title));
    let _ = write!(
        svg,
        r#"<defs><clipPath id="plot-area"><rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}"/></clipPath></defs>"#,
        plot.x0,
        plot.y0,
        plot.x1 - plot.x0,
        plot.y1 - plot.y0
    );
    let map = |p: [f64; 2]| view.fraction(p).map(|f| plot.at(f));

    // Grid at labelled ticks, below the data.
    let grid = |svg: &mut String, t: &Tick, vertical: bool| {
        let f = if vertical {
            view.fraction([t.value, first_positive(&view.y)])
        } else {
            view.fraction([first_positive(&view.x), t.value])
        };
        if let Some(f) = f {
            let p = plot.at(f);
            let (a, b) = if vertical { ([p[0], plot.y0], [p[0], plot.y1]) } else { ([plot.x0, p[1]], [plot.x1, p[1]]) };
            line(svg, a, b, "#e4e4e4", look.s);
        }
    };
    for t in x_ticks.iter().filter(|t| t.is_major()) {
        grid(&mut svg, t, true);
    }
    for t in y_ticks.iter().filter(|t| t.is_major()) {
        grid(&mut svg, t, false);
    }

    svg.push_str(r#"<g clip-path="url(#plot-area)">"#);
    if let Some(hm) = &fig.heatmap {
        heatmap(&mut svg, fig, hm, &map);
    }
    for series in &fig.series {
        draw_series(&mut svg, series, fig.color_of(series), &look, &map);
    }
    for l in &fig.labels {
        if let Some(q) = map(l.at) {
            label(&mut svg, l, q, &look);
        }
    }
    svg.push_str("</g>");

    // Frame, ticks and labels.
    let _ = write!(
        svg,
        r##"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="none" stroke="#222" stroke-width="{:.2}"/>"##,
        plot.x0,
        plot.y0,
        plot.x1 - plot.x0,
        plot.y1 - plot.y0,
        1.2 * s
    );
    for t in &x_ticks {
        let Some(f) = view.fraction([t.value, first_positive(&view.y)]) else { continue };
        let x = plot.at(f)[0];
        let len = if t.is_major() { 7.0 * s } else { 4.0 * s };
        line(&mut svg, [x, plot.y1], [x, plot.y1 - len], "#222", s);
        line(&mut svg, [x, plot.y0], [x, plot.y0 + len], "#222", s);
        if let Some(l) = &t.label {
            text(&mut svg, [x, plot.y1 + 6.0 * s + look.tick * 0.95], l, look.tick, "middle", "#111");
        }
    }
    for t in &y_ticks {
        let Some(f) = view.fraction([first_positive(&view.x), t.value]) else { continue };
        let y = plot.at(f)[1];
        let len = if t.is_major() { 7.0 * s } else { 4.0 * s };
        line(&mut svg, [plot.x0, y], [plot.x0 + len, y], "#222", s);
        line(&mut svg, [plot.x1, y], [plot.x1 - len, y], "#222", s);
        if let Some(l) = &t.label {
            text(&mut svg, [plot.x0 - 6.0 * s, y + look.tick * 0.36], l, look.tick, "end", "#111");
        }
    }
    let cx = 0.5 * (plot.x0 + plot.x1);
    text(&mut svg, [cx, h - 12.0 * s], &fig.x.title(), look.axis, "middle", "#111");
    let cy = 0.5 * (plot.y0 + plot.y1);
    let ty = 12.0 * s + look.axis;
    let _ = write!(
        svg,
        r##"<text x="{ty:.2}" y="{cy:.2}" font-size="{:.2}" text-anchor="middle" fill="#111" transform="rotate(-90 {ty:.2} {cy:.2})">{}</text>"##,
        look.axis,
        esc(&fig.y.title())
    );
    text(&mut svg, [cx, 10.0 * s + look.title], &fig.title, look.title, "middle", "#000");

    if let Some(b) = &bar {
        colour_bar_svg(&mut svg, b, [plot.x1 + 16.0 * s, plot.y0, plot.y1], &look);
    }
    if !entries.is_empty() {
        let (x0, y0) = match corner {
            Some(c) => {
                let [fx0, _, _, fy1] = c.rect([legend_w / (plot.x1 - plot.x0), legend_h / plot_h], inset);
                let p = plot.at([fx0, fy1]);
                (p[0], p[1])
            }
            // Beside a square plot that left room on its right; at the right
            // edge otherwise.
            None if fig.square => ((plot.x1 + 12.0 * s + bar_w).min(w - legend_w - 10.0 * s), plot.y0),
            None => (w - legend_w - 10.0 * s, plot.y0),
        };
        legend(&mut svg, &entries, [x0, y0, legend_w, legend_h], &look);
    }
    // Ink over everything, where it was drawn (beyond the frame too).
    let ink = rgb(super::INK);
    for stroke in &fig.ink {
        let mut points: Vec<String> = stroke
            .iter()
            .filter_map(|p| view.fraction(*p).map(|f| plot.at(f)))
            .filter(|q| q.iter().all(|v| v.is_finite()))
            .map(|q| format!("{:.1},{:.1}", q[0], q[1]))
            .collect();
        points.dedup();
        if points.len() >= 2 {
            let _ = write!(
                svg,
                r#"<polyline points="{}" fill="none" stroke="{ink}" stroke-width="{:.2}" stroke-linecap="round" stroke-linejoin="round"/>"#,
                points.join(" "),
                4.0 * s
            );
        }
    }
    svg.push_str("</svg>");
    svg
}

/// How many x labels fit: the widest label plus two characters of room each.
fn x_label_count(view: &View, width: f64, look: &Look) -> usize {
    let probe = ticks(view.x[0], view.x[1], view.x_scale, 10);
    let widest = probe.iter().filter_map(|t| t.label.as_deref()).map(|l| look.width(l, look.tick)).fold(0.0, f64::max);
    ((width / (widest + 2.5 * look.tick)) as usize).clamp(2, 10)
}

fn first_positive(r: &[f64; 2]) -> f64 {
    if r[0] > 0.0 { r[0] } else { r[1].max(f64::MIN_POSITIVE) }
}

/// The plot area in pixels (y grows downwards).
struct Rect {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
}

impl Rect {
    /// The pixel position of a point given as fractions from the lower left.
    fn at(&self, f: [f64; 2]) -> [f64; 2] {
        [self.x0 + f[0] * (self.x1 - self.x0), self.y1 - f[1] * (self.y1 - self.y0)]
    }
}

fn legend_entries(fig: &Figure) -> Vec<Entry> {
    let mut out: Vec<Entry> = fig
        .legend()
        .into_iter()
        .map(|(text, style, color)| Entry { text, sample: Sample::Series(style, color) })
        .collect();
    if let Some(h) = &fig.heatmap {
        for (i, c) in h.categories.iter().enumerate() {
            out.push(Entry { text: c.clone(), sample: Sample::Swatch(h.color_of(i as f64, (0.0, 1.0))) });
        }
    }
    out
}

fn rgb(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

fn esc(t: &str) -> String {
    t.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

fn line(svg: &mut String, a: [f64; 2], b: [f64; 2], color: &str, width: f64) {
    let _ = write!(
        svg,
        r#"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="{color}" stroke-width="{width:.2}"/>"#,
        a[0], a[1], b[0], b[1]
    );
}

fn text(svg: &mut String, at: [f64; 2], t: &str, size: f64, anchor: &str, color: &str) {
    let _ = write!(
        svg,
        r#"<text x="{:.2}" y="{:.2}" font-size="{size:.2}" text-anchor="{anchor}" fill="{color}">{}</text>"#,
        at[0],
        at[1],
        esc(t)
    );
}

/// A [`Label`] at `q` (pixels): its text over a white halo, so that it
/// reads across the lines beneath it.
fn label(svg: &mut String, l: &Label, q: [f64; 2], look: &Look) {
    let size = 0.9 * look.tick;
    let (anchor, dx, dy) = match l.anchor {
        Anchor::Left => ("start", 4.0 * look.s, -4.0 * look.s),
        Anchor::Right => ("end", -4.0 * look.s, -4.0 * look.s),
        Anchor::Center => ("middle", 0.0, 0.36 * size),
    };
    let color = l.color.map_or_else(|| "#111".to_string(), |c| rgb(PALETTE[c % PALETTE.len()]));
    let _ = write!(
        svg,
        r#"<text x="{:.2}" y="{:.2}" font-size="{size:.2}" text-anchor="{anchor}" fill="{color}" stroke="white" stroke-width="{:.2}" stroke-linejoin="round" paint-order="stroke">{}</text>"#,
        q[0] + dx,
        q[1] + dy,
        3.0 * look.s,
        esc(&l.text)
    );
}

/// The marker of a point style at `p` (pixels), `size` times its usual size.
fn marker(svg: &mut String, style: Style, p: [f64; 2], color: &str, look: &Look, size: f64) {
    let s = look.s * size;
    match style {
        Style::Line | Style::Dashed | Style::Dotted | Style::Arrow | Style::Region => {}
        Style::Points => {
            let _ = write!(svg, r#"<circle cx="{:.2}" cy="{:.2}" r="{:.2}" fill="{color}"/>"#, p[0], p[1], 3.2 * s);
        }
        Style::Marker => {
            let r = 6.5 * s;
            let _ = write!(
                svg,
                r##"<path d="M{:.2} {:.2}L{:.2} {:.2}L{:.2} {:.2}L{:.2} {:.2}Z" fill="{color}" stroke="#111" stroke-width="{:.2}"/>"##,
                p[0],
                p[1] - r,
                p[0] + r,
                p[1],
                p[0],
                p[1] + r,
                p[0] - r,
                p[1],
                0.8 * s
            );
        }
        Style::Symbol(shape, fill) => symbol(svg, shape, fill, p, 6.0 * s, color, look),
        Style::LowerLimit | Style::UpperLimit => {
            let r = 5.5 * s;
            let d = if style == Style::LowerLimit { -1.0 } else { 1.0 };
            let _ = write!(
                svg,
                r#"<path d="M{:.2} {:.2}L{:.2} {:.2}L{:.2} {:.2}Z" fill="{color}"/>"#,
                p[0],
                p[1] + d * r,
                p[0] + r,
                p[1] - d * 0.6 * r,
                p[0] - r,
                p[1] - d * 0.6 * r
            );
        }
    }
}

/// A [`Style::Symbol`] of radius `r` at `p` (pixels), drawn as the window
/// draws it.
fn symbol(svg: &mut String, shape: Shape, fill: Fill, p: [f64; 2], r: f64, color: &str, look: &Look) {
    let w = (1.6 * look.s).max(1.0);
    let paint = match fill {
        Fill::Filled => format!(r#"fill="{color}""#),
        Fill::Open => format!(r#"fill="none" stroke="{color}" stroke-width="{w:.2}""#),
    };
    let [x, y] = p;
    let polygon = |pts: &[[f64; 2]]| {
        let d: Vec<String> = pts.iter().map(|q| format!("{:.2} {:.2}", x + q[0] * r, y + q[1] * r)).collect();
        format!(r#"<path d="M{}Z" {paint}/>"#, d.join("L"))
    };
    if let Some(corners) = shape.outline() {
        let _ = write!(svg, "{}", polygon(corners));
        return;
    }
    let _ = match shape {
        Shape::Circle => write!(svg, r#"<circle cx="{x:.2}" cy="{y:.2}" r="{r:.2}" {paint}/>"#),
        Shape::Plus => write!(
            svg,
            r#"<path d="M{:.2} {y:.2}L{:.2} {y:.2}M{x:.2} {:.2}L{x:.2} {:.2}" fill="none" stroke="{color}" stroke-width="{w:.2}"/>"#,
            x - r,
            x + r,
            y - r,
            y + r
        ),
        // The polygonal shapes have their outline.
        Shape::Square | Shape::Diamond | Shape::TriangleDown | Shape::TriangleUp | Shape::Asterisk => {
            let mut d = String::new();
            for k in 0..3 {
                let a = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI / 3.0;
                let (dx, dy) = (a.cos() * r, -a.sin() * r);
                let _ = write!(d, "M{:.2} {:.2}L{:.2} {:.2}", x - dx, y - dy, x + dx, y + dy);
            }
            write!(svg, r#"<path d="{d}" fill="none" stroke="{color}" stroke-width="{w:.2}"/>"#)
        }
    };
}

/// A filled arrowhead of length `len` at `tip`, pointing away from `from`.
fn arrowhead(svg: &mut String, from: [f64; 2], tip: [f64; 2], color: &str, len: f64) {
    let (dx, dy) = (tip[0] - from[0], tip[1] - from[1]);
    let n = dx.hypot(dy);
    if n <= 0.0 {
        return;
    }
    let (ux, uy) = (dx / n, dy / n);
    let base = [tip[0] - len * ux, tip[1] - len * uy];
    let half = 0.45 * len;
    let _ = write!(
        svg,
        r#"<path d="M{:.2} {:.2}L{:.2} {:.2}L{:.2} {:.2}Z" fill="{color}"/>"#,
        tip[0],
        tip[1],
        base[0] - half * uy,
        base[1] + half * ux,
        base[0] + half * uy,
        base[1] - half * ux
    );
}

fn dash(style: Style, look: &Look) -> String {
    match style {
        Style::Dashed => format!(r#" stroke-dasharray="{:.1} {:.1}""#, 8.0 * look.s, 5.0 * look.s),
        Style::Dotted => {
            // Dots as long as the line is wide (the curves' round caps make
            // them round; the legend's samples are square).
            let w = look.line.max(1.0);
            format!(r#" stroke-dasharray="{w:.1} {:.1}""#, 2.2 * w)
        }
        _ => String::new(),
    }
}

fn draw_series(svg: &mut String, s: &Series, c: [u8; 3], look: &Look, map: &impl Fn([f64; 2]) -> Option<[f64; 2]>) {
    let color = rgb(c);
    match s.style {
        Style::Line | Style::Dashed | Style::Dotted | Style::Arrow => {
            // A point the axes cannot show breaks the line.
            let mut d = String::new();
            let mut pen_down = false;
            let mut last_two: [Option<[f64; 2]>; 2] = [None, None];
            for p in &s.points {
                match map(*p) {
                    Some(q) => {
                        let _ = write!(d, "{}{:.2} {:.2}", if pen_down { "L" } else { "M" }, q[0], q[1]);
                        pen_down = true;
                        last_two = [last_two[1], Some(q)];
                    }
                    None => pen_down = false,
                }
            }
            if let (Style::Arrow, [Some(from), Some(tip)]) = (s.style, last_two) {
                arrowhead(svg, from, tip, &color, 9.0 * look.s);
            }
            if !d.is_empty() {
                let _ = write!(
                    svg,
                    r#"<path d="{d}" fill="none" stroke="{color}" stroke-width="{:.2}" stroke-linejoin="round" stroke-linecap="round"{}/>"#,
                    look.line,
                    dash(s.style, look)
                );
            }
        }
        Style::Region => {
            let pts: Vec<String> =
                s.points.iter().filter_map(|p| map(*p)).map(|q| format!("{:.2} {:.2}", q[0], q[1])).collect();
            if pts.len() >= 3 {
                let _ = write!(
                    svg,
                    r#"<path d="M{}Z" fill="{color}" fill-opacity="0.3" stroke="{color}" stroke-width="{:.2}"/>"#,
                    pts.join("L"),
                    0.6 * look.line
                );
            }
        }
        style => {
            for q in s.points.iter().filter_map(|p| map(*p)) {
                marker(svg, style, q, &color, look, s.size_factor());
            }
        }
    }
}

fn heatmap(svg: &mut String, fig: &Figure, h: &Heatmap, map: &impl Fn([f64; 2]) -> Option<[f64; 2]>) {
    let ex = Heatmap::edges(&h.x, fig.x.scale);
    let ey = Heatmap::edges(&h.y, fig.y.scale);
    let range = h.range();
    svg.push_str(r#"<g shape-rendering="crispEdges">"#);
    for j in 0..h.y.len() {
        for i in 0..h.x.len() {
            let (Some(a), Some(b)) = (map([ex[i], ey[j]]), map([ex[i + 1], ey[j + 1]])) else { continue };
            let v = h.values[j * h.x.len() + i];
            if !v.is_finite() {
                continue;
            }
            let _ = write!(
                svg,
                r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{}"/>"#,
                a[0].min(b[0]),
                a[1].min(b[1]),
                (b[0] - a[0]).abs() + 0.5,
                (b[1] - a[1]).abs() + 0.5,
                rgb(h.color_of(v, range))
            );
        }
    }
    svg.push_str("</g>");
}

/// A vertical colour bar at `x` from `y0` (top) to `y1` (bottom).
fn colour_bar_svg(svg: &mut String, b: &ColourBar, [x, y0, y1]: [f64; 3], look: &Look) {
    let s = look.s;
    let bw = 18.0 * s;
    let n = 64;
    let hstep = (y1 - y0) / n as f64;
    svg.push_str(r#"<g shape-rendering="crispEdges">"#);
    for k in 0..n {
        let t = (k as f64 + 0.5) / n as f64;
        let c = super::colormap(t * b.top);
        let y = y1 - (k + 1) as f64 * hstep;
        let _ = write!(
            svg,
            r#"<rect x="{x:.2}" y="{y:.2}" width="{bw:.2}" height="{:.2}" fill="{}"/>"#,
            hstep + 0.5,
            rgb(c)
        );
    }
    svg.push_str("</g>");
    let _ = write!(
        svg,
        r##"<rect x="{x:.2}" y="{y0:.2}" width="{bw:.2}" height="{:.2}" fill="none" stroke="#222" stroke-width="{:.2}"/>"##,
        y1 - y0,
        s
    );
    let mut widest: f64 = 0.0;
    let bar_ticks = if b.hi > b.lo { ticks(b.lo, b.hi, b.scale, 6) } else { Vec::new() };
    for t in &bar_ticks {
        let f = family_fraction(t.value, b.lo, b.hi, b.scale) / 0.9;
        let y = y1 - f * (y1 - y0);
        let len = if t.is_major() { 5.0 * s } else { 3.0 * s };
        line(svg, [x + bw, y], [x + bw + len, y], "#222", s);
        if let Some(l) = &t.label {
            text(svg, [x + bw + 7.0 * s, y + look.tick * 0.36], l, look.tick, "start", "#111");
            widest = widest.max(look.width(l, look.tick));
        }
    }
    if bar_ticks.is_empty() {
        let l = super::human(b.lo);
        text(svg, [x + bw + 7.0 * s, 0.5 * (y0 + y1)], &l, look.tick, "start", "#111");
        widest = look.width(&l, look.tick);
    }
    let tx = x + bw + 9.0 * s + widest + look.axis;
    let cy = 0.5 * (y0 + y1);
    let _ = write!(
        svg,
        r##"<text x="{tx:.2}" y="{cy:.2}" font-size="{:.2}" text-anchor="middle" fill="#111" transform="rotate(-90 {tx:.2} {cy:.2})">{}</text>"##,
        look.axis,
        esc(&b.title)
    );
}

fn legend(svg: &mut String, entries: &[Entry], [x, y, w, h]: [f64; 4], look: &Look) {
    let s = look.s;
    let _ = write!(
        svg,
        r##"<rect x="{x:.2}" y="{y:.2}" width="{w:.2}" height="{h:.2}" fill="white" fill-opacity="0.92" stroke="#999" stroke-width="{:.2}"/>"##,
        s
    );
    let row = look.legend * 1.45;
    for (k, e) in entries.iter().enumerate() {
        let cy = y + 6.0 * s + (k as f64 + 0.5) * row;
        let sx = x + 8.0 * s;
        match e.sample {
            Sample::Series(style, c) => {
                let color = rgb(c);
                if style.is_line() {
                    let _ = write!(
                        svg,
                        r#"<line x1="{sx:.2}" y1="{cy:.2}" x2="{:.2}" y2="{cy:.2}" stroke="{color}" stroke-width="{:.2}"{}/>"#,
                        sx + 30.0 * s,
                        look.line,
                        dash(style, look)
                    );
                    if style == Style::Arrow {
                        arrowhead(svg, [sx, cy], [sx + 30.0 * s, cy], &color, 9.0 * s);
                    }
                } else if style == Style::Region {
                    let _ = write!(
                        svg,
                        r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{color}" fill-opacity="0.3" stroke="{color}" stroke-width="{:.2}"/>"#,
                        sx + 6.0 * s,
                        cy - 6.0 * s,
                        18.0 * s,
                        12.0 * s,
                        0.6 * look.line
                    );
                } else {
                    marker(svg, style, [sx + 15.0 * s, cy], &color, look, 1.0);
                }
            }
            Sample::Swatch(c) => {
                let _ = write!(
                    svg,
                    r##"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{}" stroke="#444" stroke-width="{:.2}"/>"##,
                    sx + 6.0 * s,
                    cy - 0.35 * row,
                    18.0 * s,
                    0.7 * row,
                    rgb(c),
                    0.6 * s
                );
            }
        }
        text(svg, [sx + 38.0 * s, cy + look.legend * 0.36], &e.text, look.legend, "start", "#111");
    }
}
