//! One description of a figure (series, axes, scales, labels) that the window
//! draws with egui_plot and the file writers render to SVG, PNG and CSV, so
//! that the command line makes the same figures without a window.

pub mod contour;
mod export;
pub mod layout;
mod svg;
pub mod ticks;

pub use export::{
    ExportError, FONT_FAMILY, csv_bytes, font_ttf, png_bytes, png_bytes_with_text, svg_string, tick_label, write_csv,
    write_png, write_svg,
};
pub use layout::View;
pub use ticks::{Tick, number};

/// A number for a legend or a note: three significant digits, written as
/// people write it ("0.0123", "215", "1.5×10⁻⁷").
pub fn human(v: f64) -> String {
    ticks::number(v, 3)
}

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
    /// Dotted line (a third line style, e.g. for a third value of a
    /// parameter that line styles tell apart).
    Dotted,
    /// A closed region (the points are its outline), filled translucent in
    /// its colour and outlined (e.g. an observational constraint).
    Region,
    /// A solid line with an arrowhead at its last point (the direction of a
    /// change, e.g. the parameter arrows of Fig. 6.2).
    Arrow,
    /// Markers only.
    Points,
    /// A single highlighted marker (e.g. the JKR equilibrium).
    Marker,
    /// Lower limits: markers pointing up (towards larger values).
    LowerLimit,
    /// Upper limits: markers pointing down.
    UpperLimit,
    /// A symbol of the given shape, open or filled (events marked along
    /// curves, as the thesis's figures mark them).
    Symbol(Shape, Fill),
}

/// The shape of a [`Style::Symbol`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Shape {
    /// ○ / ●
    Circle,
    /// □ / ■
    Square,
    /// ◇ / ◆
    Diamond,
    /// ▽ / ▼
    TriangleDown,
    /// △ / ▲
    TriangleUp,
    /// ✳ (an asterisk of three strokes; the same open or filled)
    Asterisk,
    /// + (two strokes; the same open or filled)
    Plus,
}

impl Shape {
    /// The corners of a polygonal shape of unit radius, in screen
    /// coordinates (y down), shared by the window and the file writers;
    /// `None` for the circle and the stroked shapes (+, ✳).
    pub fn outline(self) -> Option<&'static [[f64; 2]]> {
        match self {
            Shape::Square => Some(&[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]),
            Shape::Diamond => Some(&[[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]]),
            Shape::TriangleDown => Some(&[[-1.0, -0.6], [1.0, -0.6], [0.0, 1.0]]),
            Shape::TriangleUp => Some(&[[-1.0, 0.6], [0.0, -1.0], [1.0, 0.6]]),
            Shape::Circle | Shape::Asterisk | Shape::Plus => None,
        }
    }
}

/// Whether a [`Style::Symbol`] is drawn open (outline) or filled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Fill {
    /// Outline only.
    Open,
    /// Filled.
    Filled,
}

impl Style {
    /// Whether the style draws a line (as opposed to markers at the points).
    pub fn is_line(self) -> bool {
        matches!(self, Style::Line | Style::Dashed | Style::Dotted | Style::Arrow)
    }
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
    /// The value of the figure's varied parameter ([`Figure::family`]) this
    /// series belongs to: drawn in the colour of the value on a sequential
    /// map, with a colour bar instead of a legend entry.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub family: Option<f64>,
    /// The legend entry this series shares with other series of the same
    /// style (one symbol for an event marked on several curves): listed
    /// once under this text, in a neutral grey when their colours differ.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub legend: Option<String>,
    /// Marker size relative to the style's own (points of many overlapping
    /// series are drawn smaller); None is 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<f64>,
}

impl Series {
    /// A series from points.
    pub fn new(name: impl Into<String>, points: Vec<[f64; 2]>, style: Style, color: usize) -> Self {
        Series { name: name.into(), points, style, color, family: None, legend: None, size: None }
    }

    /// Draws the markers at `factor` times their usual size (builder style).
    pub fn sized(mut self, factor: f64) -> Self {
        self.size = (factor.is_finite() && factor > 0.0).then_some(factor);
        self
    }

    /// The marker size factor (1 unless [`Series::sized`]).
    pub fn size_factor(&self) -> f64 {
        self.size.unwrap_or(1.0)
    }

    /// Shares the legend entry `text` with the other series of the same style
    /// that name it (builder style).
    pub fn keyed(mut self, text: impl Into<String>) -> Self {
        self.legend = Some(text.into());
        self
    }

    /// Marks the series as the member of the figure's family at `value`
    /// (in the unit of [`Family::unit`]).
    pub fn at(mut self, value: f64) -> Self {
        self.family = value.is_finite().then_some(value);
        self
    }
}

/// A parameter varied across the series of a figure (snapshot times, disk
/// masses, pinned sweeps): its members are coloured on a sequential map and
/// explained by a colour bar labelled with the parameter and its unit.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Family {
    /// The varied quantity, e.g. "time".
    pub label: String,
    /// Its unit as shown, e.g. "yr".
    pub unit: String,
    /// Whether the values are spread logarithmically.
    pub scale: Scale,
}

impl Family {
    /// "label [unit]".
    pub fn title(&self) -> String {
        if self.unit.is_empty() { self.label.clone() } else { format!("{} [{}]", self.label, self.unit) }
    }
}

/// Default size of exported figures, pixels: wide enough for a slide.
pub const EXPORT_SIZE: (u32, u32) = (1600, 1100);

/// Colours shared by the window and the file writers (RGB): the Okabe–Ito
/// colour-blind-safe set, with grey and a darker yellow in place of its black
/// and yellow so that every entry reads on light and dark backgrounds.
pub const PALETTE: [[u8; 3]; 8] = [
    [213, 94, 0],
    [0, 114, 178],
    [0, 158, 115],
    [230, 159, 0],
    [204, 121, 167],
    [86, 180, 233],
    [128, 128, 128],
    [181, 158, 0],
];

/// How far up viridis a family's colours reach: its palest yellows vanish on
/// a white slide.
pub const FAMILY_TOP: f64 = 0.82;

/// The colour of ink drawn by hand over a figure: a saturated magenta, apart
/// from every curve's colour and ≥ 4.5:1 against white and the dark theme.
pub const INK: [u8; 3] = [0xD4, 0x00, 0x8A];

/// The colour of a legend entry shared by series of different colours.
pub const NEUTRAL: [u8; 3] = [110, 110, 110];

/// A colour map over a rectangular grid (e.g. a χ² landscape).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Heatmap {
    /// Cell centres along x, increasing (axis units).
    pub x: Vec<f64>,
    /// Cell centres along y, increasing (axis units).
    pub y: Vec<f64>,
    /// Values, row by row: `values[j * x.len() + i]` belongs to (x[i], y[j]).
    pub values: Vec<f64>,
    /// What the colour shows, e.g. "log10 χ²".
    pub label: String,
    /// Unit of the values as shown on the colour bar; empty if dimensionless.
    pub unit: String,
    /// Names of the categories for a categorical map (values are indices
    /// into it, coloured from [`PALETTE`]); empty for a continuous map.
    pub categories: Vec<String>,
}

impl Heatmap {
    /// A continuous map of `values` (row by row, see [`Heatmap::values`]).
    pub fn new(x: Vec<f64>, y: Vec<f64>, values: Vec<f64>, label: &str, unit: &str) -> Self {
        Heatmap { x, y, values, label: label.into(), unit: unit.into(), categories: Vec::new() }
    }

    /// A categorical map: `values` are indices into `categories`.
    /// The cell nearest to the point `at` (axis units; nearest in log10 on
    /// logarithmic axes): its centre, its value, and the value as shown
    /// ("0.53", or the category's name). The window's hover and the Inspect card name the
    /// same cell.
    pub fn cell_at(&self, at: [f64; 2], scales: (Scale, Scale)) -> Option<([f64; 2], f64, String)> {
        let nearest = |grid: &[f64], v: f64, s: Scale| {
            let d = |g: f64| if s == Scale::Log { (g / v).ln().abs() } else { (g - v).abs() };
            (0..grid.len()).min_by(|&a, &b| d(grid[a]).total_cmp(&d(grid[b])))
        };
        if !(at[0].is_finite() && at[1].is_finite()) {
            return None;
        }
        let (i, j) = (nearest(&self.x, at[0], scales.0)?, nearest(&self.y, at[1], scales.1)?);
        let v = *self.values.get(j * self.x.len() + i)?;
        let text = if self.categories.is_empty() {
            human(v)
        } else {
            self.categories.get(v.round().max(0.0) as usize).cloned().unwrap_or_else(|| "—".into())
        };
        Some(([self.x[i], self.y[j]], v, text))
    }

    pub fn categorical(x: Vec<f64>, y: Vec<f64>, values: Vec<f64>, label: &str, categories: &[&str]) -> Self {
        Heatmap {
            x,
            y,
            values,
            label: label.into(),
            unit: String::new(),
            categories: categories.iter().map(|c| c.to_string()).collect(),
        }
    }

    /// "label [unit]".
    pub fn title(&self) -> String {
        if self.unit.is_empty() { self.label.clone() } else { format!("{} [{}]", self.label, self.unit) }
    }

    /// The colour of the cell holding `v`.
    pub fn color_of(&self, v: f64, range: (f64, f64)) -> [u8; 3] {
        if !self.categories.is_empty() {
            return if v.is_finite() && v >= 0.0 {
                PALETTE[v.round() as usize % PALETTE.len()]
            } else {
                [255, 255, 255]
            };
        }
        let (lo, hi) = range;
        let span = if hi > lo { hi - lo } else { 1.0 };
        colormap((v - lo) / span)
    }

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

/// Colour of a value in [0, 1] on viridis, the perceptually uniform
/// purple–blue–green–yellow map (sampled at nine stops).
pub fn colormap(t: f64) -> [u8; 3] {
    const STOPS: [[f64; 3]; 9] = [
        [68.0, 1.0, 84.0],
        [71.0, 44.0, 122.0],
        [59.0, 81.0, 139.0],
        [44.0, 113.0, 142.0],
        [33.0, 144.0, 141.0],
        [39.0, 173.0, 129.0],
        [92.0, 200.0, 99.0],
        [170.0, 220.0, 50.0],
        [253.0, 231.0, 37.0],
    ];
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 1.0 };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    std::array::from_fn(|c| (STOPS[i][c] + f * (STOPS[i + 1][c] - STOPS[i][c])).round() as u8)
}

/// Where a [`Label`]'s text sits relative to its point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Anchor {
    /// Text starts at the point, just above it.
    Left,
    /// Text ends at the point, just above it.
    Right,
    /// Text centred on the point (a contour's level, on its line).
    Center,
}

/// Text placed in the plot at a data point: the name of a reference line,
/// the level of a contour.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Label {
    /// Position in axis units.
    pub at: [f64; 2],
    /// The text.
    pub text: String,
    /// Colour index into [`PALETTE`]; None for the text colour (a level
    /// written on a colour map).
    pub color: Option<usize>,
    /// Alignment to `at`.
    pub anchor: Anchor,
}

/// A complete figure.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
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
    /// The parameter varied across the series marked with [`Series::at`].
    pub family: Option<Family>,
    /// On a logarithmic y-axis, how many decades below the highest point the
    /// axis reaches by default (distributions: the decades that hold mass).
    pub y_decades: Option<f64>,
    /// Whether the plot area is square (maps of one quantity against itself,
    /// such as mass against mass, or x against y in the same unit).
    pub square: bool,
    /// Text placed at data points (drawn over the series).
    pub labels: Vec<Label>,
    /// Strokes drawn by hand over the figure (a lecturer's ink), in axis
    /// units: drawn over everything in a PNG or SVG, left out of a CSV.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ink: Vec<Vec<[f64; 2]>>,
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
            heatmap: None,
            family: None,
            y_decades: None,
            square: false,
            labels: Vec::new(),
            ink: Vec::new(),
        }
    }

    /// Adds a text label at a data point (builder style).
    pub fn label(mut self, at: [f64; 2], text: impl Into<String>, color: Option<usize>, anchor: Anchor) -> Self {
        self.labels.push(Label { at, text: text.into(), color, anchor });
        self
    }

    /// Makes the plot area square (builder style).
    pub fn square(mut self) -> Self {
        self.square = true;
        self
    }

    /// Declares the parameter varied across the series marked with
    /// [`Series::at`] (builder style).
    pub fn family(mut self, label: &str, unit: &str, scale: Scale) -> Self {
        self.family = Some(Family { label: label.into(), unit: unit.into(), scale });
        self
    }

    /// Limits a logarithmic y-axis to `decades` below the highest point
    /// (builder style).
    pub fn y_decades(mut self, decades: f64) -> Self {
        self.y_decades = Some(decades);
        self
    }

    /// The smallest and largest family value among the series.
    pub fn family_range(&self) -> Option<(f64, f64)> {
        self.family.as_ref()?;
        let vals = self.series.iter().filter_map(|s| s.family);
        let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        (lo <= hi).then_some((lo, hi))
    }

    /// Whether a series has a legend entry: named, and not a family member
    /// (those are explained by the colour bar) unless it names a shared
    /// legend entry (e.g. the line style of a second varied parameter).
    pub fn in_legend(&self, s: &Series) -> bool {
        !s.name.is_empty() && (self.family.is_none() || s.family.is_none() || s.legend.is_some())
    }

    /// The legend's entries in drawing order: (text, style, colour). Series
    /// that share a legend key ([`Series::keyed`]) and style are listed once,
    /// in [`NEUTRAL`] when their colours differ. The window and the file
    /// writers list the same entries.
    pub fn legend(&self) -> Vec<(String, Style, [u8; 3])> {
        let mut out: Vec<(String, Style, [u8; 3])> = Vec::new();
        for s in self.series.iter().filter(|s| self.in_legend(s)) {
            let color = self.color_of(s);
            match &s.legend {
                Some(key) => match out.iter_mut().find(|e| &e.0 == key && e.1 == s.style) {
                    Some(e) if e.2 != color => e.2 = NEUTRAL,
                    Some(_) => {}
                    None => out.push((key.clone(), s.style, color)),
                },
                None => out.push((s.name.clone(), s.style, color)),
            }
        }
        out
    }

    /// The colour of a series: its family value on the sequential map, or
    /// its palette entry.
    pub fn color_of(&self, s: &Series) -> [u8; 3] {
        match (&self.family, s.family, self.family_range()) {
            (Some(f), Some(v), Some((lo, hi))) => colormap(family_fraction(v, lo, hi, f.scale)),
            _ => PALETTE[s.color % PALETTE.len()],
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

/// Where `v` sits between `lo` and `hi` on a family's colour scale, in
/// [0, 1]; the map runs to [`FAMILY_TOP`] only, so the last member stays
/// visible on a light background.
pub fn family_fraction(v: f64, lo: f64, hi: f64, scale: Scale) -> f64 {
    let t = match scale {
        Scale::Log if lo > 0.0 && hi > lo => (v / lo).ln() / (hi / lo).ln(),
        _ if hi > lo => (v - lo) / (hi - lo),
        _ => 0.5,
    };
    FAMILY_TOP * t.clamp(0.0, 1.0)
}
