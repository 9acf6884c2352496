//! One description of a figure (series, axes, scales, labels) that the window
//! draws with egui_plot and the file writers render to SVG, PNG and CSV, so
//! that the command line makes the same figures without a window.

mod export;

pub use export::{
    ExportError, csv_bytes, png_bytes, svg_string, tick_label, write_atomically, write_csv,
    write_png, write_svg,
};

/// Axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Scale {
    /// Linear axis.
    Linear,
    /// Base-10 logarithmic axis (non-positive values are dropped).
    Log,
}

/// One axis: the quantity, its unit and its scale.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Axis {
    /// Quantity, e.g. "mutual approach δ".
    pub label: String,
    /// Unit as shown, e.g. "nm"; empty for dimensionless quantities.
    pub unit: String,
    /// Linear or logarithmic.
    pub scale: Scale,
}

impl Axis {
    /// A linear axis.
    pub fn linear(label: &str, unit: &str) -> Self {
        Axis {
            label: label.into(),
            unit: unit.into(),
            scale: Scale::Linear,
        }
    }
    /// A logarithmic axis.
    pub fn log(label: &str, unit: &str) -> Self {
        Axis {
            label: label.into(),
            unit: unit.into(),
            scale: Scale::Log,
        }
    }
    /// "label [unit]" (or just the label when dimensionless).
    pub fn title(&self) -> String {
        if self.unit.is_empty() {
            self.label.clone()
        } else {
            format!("{} [{}]", self.label, self.unit)
        }
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Style {
    /// Solid line.
    Line,
    /// Dashed line (references such as Hertz or JKR).
    Dashed,
    /// Markers only.
    Points,
    /// A single highlighted marker (e.g. the JKR equilibrium).
    Marker,
}

/// A named set of (x, y) points.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points in axis units.
    pub points: Vec<[f64; 2]>,
    /// Drawing style.
    pub style: Style,
    /// Colour index into [`PALETTE`].
    pub color: usize,
}

impl Series {
    /// A series from points.
    pub fn new(name: impl Into<String>, points: Vec<[f64; 2]>, style: Style, color: usize) -> Self {
        Series {
            name: name.into(),
            points,
            style,
            color,
        }
    }
}

/// Colours shared by the window and the file writers (RGB).
pub const PALETTE: [[u8; 3]; 8] = [
    [214, 39, 40],
    [31, 119, 180],
    [44, 160, 44],
    [255, 127, 14],
    [148, 103, 189],
    [140, 86, 75],
    [127, 127, 127],
    [23, 190, 207],
];

/// A complete figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Stable identifier, used as file stem (e.g. "contact-radius").
    pub id: String,
    /// Title shown above the plot.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// The data.
    pub series: Vec<Series>,
}

impl Figure {
    /// An empty figure.
    pub fn new(id: &str, title: &str, x: Axis, y: Axis) -> Self {
        Figure {
            id: id.into(),
            title: title.into(),
            x,
            y,
            series: Vec::new(),
        }
    }

    /// Adds a series and returns the figure (builder style).
    pub fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// The data range over all finite points that the axes can show
    /// (positive values only on log axes): `[x_min, x_max, y_min, y_max]`.
    pub fn bounds(&self) -> Option<[f64; 4]> {
        let mut b = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let mut any = false;
        for p in self.series.iter().flat_map(|s| s.points.iter()) {
            if !self.visible(p) {
                continue;
            }
            any = true;
            b[0] = b[0].min(p[0]);
            b[1] = b[1].max(p[0]);
            b[2] = b[2].min(p[1]);
            b[3] = b[3].max(p[1]);
        }
        any.then_some(b)
    }

    /// Whether a point can be drawn on this figure's axes.
    pub fn visible(&self, p: &[f64; 2]) -> bool {
        let ok = |v: f64, s: Scale| v.is_finite() && (s == Scale::Linear || v > 0.0);
        ok(p[0], self.x.scale) && ok(p[1], self.y.scale)
    }
}
