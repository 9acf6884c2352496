//! One description of a figure (series, axes, scales, labels) that the window
//! draws with egui_plot and the file writers render to SVG, PNG and CSV, so
//! that the command line makes the same figures without a window.

mod export;

pub use export::{ExportError, csv_bytes, png_bytes, svg_string, tick_label, write_csv, write_png, write_svg};

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
        Axis { label: label.into(), unit: unit.into(), scale: Scale::Linear }
    }
    /// A logarithmic axis.
    pub fn log(label: &str, unit: &str) -> Self {
        Axis { label: label.into(), unit: unit.into(), scale: Scale::Log }
    }
    /// "label [unit]" (or just the label when dimensionless).
    pub fn title(&self) -> String {
        if self.unit.is_empty() { self.label.clone() } else { format!("{} [{}]", self.label, self.unit) }
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
    /// Lower limits: markers pointing up (towards larger values).
    LowerLimit,
    /// Upper limits: markers pointing down.
    UpperLimit,
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
        Series { name: name.into(), points, style, color }
    }
}

/// Size of exported figures, pixels.
pub const EXPORT_SIZE: (u32, u32) = (900, 620);

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

/// A colour map over a rectangular grid (e.g. a χ² landscape).
#[derive(Debug, Clone, PartialEq)]
pub struct Heatmap {
    /// Cell centres along x, increasing (axis units).
    pub x: Vec<f64>,
    /// Cell centres along y, increasing (axis units).
    pub y: Vec<f64>,
    /// Values, row by row: `values[j * x.len() + i]` belongs to (x[i], y[j]).
    pub values: Vec<f64>,
    /// What the colour shows, e.g. "log10 χ²".
    pub label: String,
}

impl Heatmap {
    /// Cell edges along one axis: midpoints between centres (geometric on log axes).
    pub fn edges(centres: &[f64], scale: Scale) -> Vec<f64> {
        let n = centres.len();
        if n == 1 {
            let c = centres[0];
            return match scale {
                Scale::Linear => vec![c - 0.5, c + 0.5],
                Scale::Log => vec![c / 1.5, c * 1.5],
            };
        }
        let mid = |a: f64, b: f64| match scale {
            Scale::Linear => 0.5 * (a + b),
            Scale::Log => (a * b).sqrt(),
        };
        let mut e = Vec::with_capacity(n + 1);
        let first = match scale {
            Scale::Linear => centres[0] - 0.5 * (centres[1] - centres[0]),
            Scale::Log => centres[0] / (centres[1] / centres[0]).sqrt(),
        };
        e.push(first);
        for w in centres.windows(2) {
            e.push(mid(w[0], w[1]));
        }
        let last = match scale {
            Scale::Linear => centres[n - 1] + 0.5 * (centres[n - 1] - centres[n - 2]),
            Scale::Log => centres[n - 1] * (centres[n - 1] / centres[n - 2]).sqrt(),
        };
        e.push(last);
        e
    }

    /// Smallest and largest finite value.
    pub fn range(&self) -> (f64, f64) {
        self.values
            .iter()
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }
}

/// Colour of a value in [0, 1] on a perceptually ordered blue–green–yellow ramp.
pub fn colormap(t: f64) -> [u8; 3] {
    const STOPS: [[f64; 3]; 5] =
        [[68.0, 1.0, 84.0], [59.0, 82.0, 139.0], [33.0, 145.0, 140.0], [94.0, 201.0, 98.0], [253.0, 231.0, 37.0]];
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 1.0 };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    std::array::from_fn(|c| (STOPS[i][c] + f * (STOPS[i + 1][c] - STOPS[i][c])).round() as u8)
}

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
    /// An optional colour map drawn below the series.
    pub heatmap: Option<Heatmap>,
}

impl Figure {
    /// An empty figure.
    pub fn new(id: &str, title: &str, x: Axis, y: Axis) -> Self {
        Figure { id: id.into(), title: title.into(), x, y, series: Vec::new(), heatmap: None }
    }

    /// Adds a series and returns the figure (builder style).
    pub fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// The data range over all finite points that the axes can show
    /// (positive values only on log axes): `[x_min, x_max, y_min, y_max]`.
    pub fn bounds(&self) -> Option<[f64; 4]> {
        let mut b = [f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY];
        let mut any = false;
        let corners: Vec<[f64; 2]> = self
            .heatmap
            .iter()
            .flat_map(|h| {
                let ex = Heatmap::edges(&h.x, self.x.scale);
                let ey = Heatmap::edges(&h.y, self.y.scale);
                [[ex[0], ey[0]], [ex[ex.len() - 1], ey[ey.len() - 1]]]
            })
            .collect();
        for p in self.series.iter().flat_map(|s| s.points.iter()).chain(corners.iter()) {
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
