//! Writing figures to SVG, PNG and CSV files, through
//! [`crate::files`]: a failed export never leaves a truncated or temporary
//! file and never destroys an earlier one.

use super::Figure;
use crate::files::{WriteError, write_atomically};
use std::path::Path;
use std::sync::{Arc, OnceLock};

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
        Some(h) => w.write_record(["series", &fig.x.title(), &fig.y.title(), &h.title()])?,
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

/// The bundled font (DejaVu Sans) that exported text is measured and drawn
/// with, so that no system font is needed and every label's glyphs exist.
pub fn font_ttf() -> &'static [u8] {
    static FONT: OnceLock<Vec<u8>> = OnceLock::new();
    // Compressed by the build script (half the size in the browser's module).
    static PACKED: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/DejaVuSans.ttf.zlib"));
    FONT.get_or_init(|| fdeflate::decompress_to_vec(PACKED).expect("the bundled font inflates"))
}

/// The family name of [`font_ttf`].
pub const FONT_FAMILY: &str = "DejaVu Sans";

/// Renders the figure as an SVG document (text kept as text).
pub fn svg_string(fig: &Figure, size: (u32, u32)) -> Result<String, ExportError> {
    Ok(super::svg::render(fig, size))
}

/// Writes the figure as SVG.
pub fn write_svg(fig: &Figure, path: &Path, size: (u32, u32)) -> Result<(), ExportError> {
    Ok(write_atomically(path, svg_string(fig, size)?.as_bytes())?)
}

fn fonts() -> Arc<resvg::usvg::fontdb::Database> {
    static FONTS: OnceLock<Arc<resvg::usvg::fontdb::Database>> = OnceLock::new();
    Arc::clone(FONTS.get_or_init(|| {
        let mut db = resvg::usvg::fontdb::Database::new();
        db.load_font_data(font_ttf().to_vec());
        db.set_sans_serif_family(FONT_FAMILY);
        Arc::new(db)
    }))
}

/// Renders the figure as PNG bytes: the SVG document rasterised with the
/// bundled font, so both files show the same figure.
pub fn png_bytes(fig: &Figure, size: (u32, u32)) -> Result<Vec<u8>, ExportError> {
    png_bytes_with_text(fig, size, &[])
}

/// Like [`png_bytes`], with (keyword, text) pairs stored as international
/// text chunks (iTXt, UTF-8) that image viewers list as metadata.
pub fn png_bytes_with_text(fig: &Figure, size: (u32, u32), text: &[(&str, &str)]) -> Result<Vec<u8>, ExportError> {
    let draw_err = |message: String| ExportError::Draw { id: fig.id.clone(), message };
    let svg = svg_string(fig, size)?;
    let options = resvg::usvg::Options { fontdb: fonts(), font_family: FONT_FAMILY.into(), ..Default::default() };
    let tree = resvg::usvg::Tree::from_str(&svg, &options).map_err(|e| draw_err(e.to_string()))?;
    let (w, h) = (size.0.max(50), size.1.max(50));
    let mut pixmap =
        resvg::tiny_skia::Pixmap::new(w, h).ok_or_else(|| draw_err(format!("cannot make a {w}×{h} image")))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    // Opaque white background: premultiplied and straight RGB agree.
    let rgb: Vec<u8> = pixmap.data().chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, w, h);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        for (keyword, value) in text {
            encoder.add_itxt_chunk(keyword.to_string(), value.to_string()).map_err(|e| draw_err(e.to_string()))?;
        }
        let mut writer = encoder.write_header().map_err(|e| draw_err(e.to_string()))?;
        writer.write_image_data(&rgb).map_err(|e| draw_err(e.to_string()))?;
        writer.finish().map_err(|e| draw_err(e.to_string()))?;
    }
    Ok(out)
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

#[cfg(test)]
mod tests {
    /// The font the build compressed inflates to the file in `assets/fonts`, byte for byte.
    #[test]
    fn the_bundled_font_inflates_to_the_file() {
        let file = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf")).expect("font");
        assert!(super::font_ttf() == file.as_slice());
    }
}
