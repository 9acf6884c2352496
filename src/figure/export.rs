//! Writing figures to SVG, PNG and CSV files, through
//! [`crate::files`]: a failed export never leaves a truncated or temporary
//! file and never destroys an earlier one.

use super::{Figure, Heatmap, PALETTE, Scale, Style, colormap};
use crate::files::{WriteError, write_atomically};
use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// Why an export failed; the message names the file.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// The figure could not be drawn.
    #[error("cannot draw figure '{id}': {message}")]
    Draw {
        /// Figure id.
        id: String,
        /// What went wrong.
        message: String,
    },
}

/// The figure's data as CSV: one row per point, columns `series`, x and y,
/// with the header naming quantities and units.
pub fn csv_bytes(fig: &Figure) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    match &fig.heatmap {
        None => w.write_record(["series", &fig.x.title(), &fig.y.title()])?,
        Some(h) => w.write_record(["series", &fig.x.title(), &fig.y.title(), &h.label])?,
    }
    let extra = usize::from(fig.heatmap.is_some());
    for s in &fig.series {
        for p in &s.points {
            let mut row = vec![s.name.clone(), format!("{:e}", p[0]), format!("{:e}", p[1])];
            row.extend(std::iter::repeat_n(String::new(), extra));
            w.write_record(&row)?;
        }
    }
    if let Some(h) = &fig.heatmap {
        for (j, y) in h.y.iter().enumerate() {
            for (i, x) in h.x.iter().enumerate() {
                let v = h.values[j * h.x.len() + i];
                w.write_record([h.label.clone(), format!("{x:e}"), format!("{y:e}"), format!("{v:e}")])?;
            }
        }
    }
    w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
}

/// Writes the figure's data to a CSV file.
pub fn write_csv(fig: &Figure, path: &Path) -> Result<(), ExportError> {
    let bytes = csv_bytes(fig).map_err(|e| ExportError::Draw { id: fig.id.clone(), message: e.to_string() })?;
    Ok(write_atomically(path, &bytes)?)
}

/// Renders the figure as an SVG document.
pub fn svg_string(fig: &Figure, size: (u32, u32)) -> Result<String, ExportError> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        draw(&root, fig).map_err(|message| ExportError::Draw { id: fig.id.clone(), message })?;
    }
    Ok(out)
}

/// Writes the figure as SVG.
pub fn write_svg(fig: &Figure, path: &Path, size: (u32, u32)) -> Result<(), ExportError> {
    Ok(write_atomically(path, svg_string(fig, size)?.as_bytes())?)
}

static FONT: Once = Once::new();

/// Renders the figure as PNG bytes.
pub fn png_bytes(fig: &Figure, size: (u32, u32)) -> Result<Vec<u8>, ExportError> {
    let draw_err = |message: String| ExportError::Draw { id: fig.id.clone(), message };
    let mut buf = vec![0u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        draw(&root, fig).map_err(draw_err)?;
    }
    let img = image::RgbImage::from_raw(size.0, size.1, buf).ok_or_else(|| draw_err("bad buffer size".into()))?;
    let mut png = std::io::Cursor::new(Vec::new());
    img.write_to(&mut png, image::ImageFormat::Png).map_err(|e| draw_err(e.to_string()))?;
    Ok(png.into_inner())
}

/// Writes the figure as PNG.
pub fn write_png(fig: &Figure, path: &Path, size: (u32, u32)) -> Result<(), ExportError> {
    Ok(write_atomically(path, &png_bytes(fig, size)?)?)
}

/// Compact tick label: plain numbers in a readable range, otherwise scientific.
pub fn tick_label(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        let s = format!("{v:.1e}");
        s.replace(".0e", "e")
    }
}

fn padded(lo: f64, hi: f64, scale: Scale) -> (f64, f64) {
    match scale {
        Scale::Linear => {
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            (lo - 0.04 * span, hi + 0.04 * span)
        }
        Scale::Log => {
            if hi > lo {
                (lo / 1.15, hi * 1.15)
            } else {
                (lo / 2.0, hi * 2.0)
            }
        }
    }
}

fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, fig: &Figure) -> Result<(), String> {
    // Text is measured (SVG) and rendered (PNG) with the font that ships
    // inside egui's default fonts, so no system font is needed.
    FONT.call_once(|| {
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT);
    });
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let [x0, x1, y0, y1] = fig.bounds().unwrap_or([1.0, 10.0, 1.0, 10.0]);
    let (x0, x1) = padded(x0, x1, fig.x.scale);
    let (y0, y1) = padded(y0, y1, fig.y.scale);
    match (fig.x.scale, fig.y.scale) {
        (Scale::Linear, Scale::Linear) => draw_in(root, fig, x0..x1, y0..y1),
        (Scale::Log, Scale::Linear) => draw_in(root, fig, (x0..x1).log_scale(), y0..y1),
        (Scale::Linear, Scale::Log) => draw_in(root, fig, x0..x1, (y0..y1).log_scale()),
        (Scale::Log, Scale::Log) => draw_in(root, fig, (x0..x1).log_scale(), (y0..y1).log_scale()),
    }
}

fn draw_in<DB, X, Y>(root: &DrawingArea<DB, Shift>, fig: &Figure, xr: X, yr: Y) -> Result<(), String>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let mut chart = ChartBuilder::on(root)
        .caption(&fig.title, ("sans-serif", 22))
        .margin(14)
        .x_label_area_size(48)
        .y_label_area_size(84)
        .build_cartesian_2d(xr, yr)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(fig.x.title())
        .y_desc(fig.y.title())
        .x_label_formatter(&|v| tick_label(*v))
        .y_label_formatter(&|v| tick_label(*v))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    if let Some(h) = &fig.heatmap {
        let ex = Heatmap::edges(&h.x, fig.x.scale);
        let ey = Heatmap::edges(&h.y, fig.y.scale);
        let (lo, hi) = h.range();
        let span = if hi > lo { hi - lo } else { 1.0 };
        let cells = (0..h.y.len()).flat_map(|j| (0..h.x.len()).map(move |i| (i, j))).map(|(i, j)| {
            let [r, g, b] = colormap((h.values[j * h.x.len() + i] - lo) / span);
            Rectangle::new([(ex[i], ey[j]), (ex[i + 1], ey[j + 1])], RGBColor(r, g, b).filled())
        });
        chart.draw_series(cells).map_err(e)?;
    }
    for s in &fig.series {
        let [r, g, b] = PALETTE[s.color % PALETTE.len()];
        let color = RGBColor(r, g, b);
        let pts: Vec<(f64, f64)> = s.points.iter().filter(|p| fig.visible(p)).map(|p| (p[0], p[1])).collect();
        if pts.is_empty() {
            continue;
        }
        let legend = move |(x, y): (i32, i32)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2));
        let anno = match s.style {
            Style::Line => chart.draw_series(LineSeries::new(pts, color.stroke_width(2))).map_err(e)?,
            Style::Dashed => chart.draw_series(DashedLineSeries::new(pts, 8, 5, color.stroke_width(2))).map_err(e)?,
            Style::Points => {
                chart.draw_series(pts.into_iter().map(|p| Circle::new(p, 3, color.filled()))).map_err(e)?
            }
            Style::Marker | Style::LowerLimit => {
                chart.draw_series(pts.into_iter().map(|p| TriangleMarker::new(p, 8, color.filled()))).map_err(e)?
            }
            Style::UpperLimit => {
                chart.draw_series(pts.into_iter().map(|p| Cross::new(p, 6, color.stroke_width(2)))).map_err(e)?
            }
        };
        if !s.name.is_empty() {
            anno.label(s.name.clone()).legend(legend);
        }
    }
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(e)?;
    root.present().map_err(e)?;
    Ok(())
}
