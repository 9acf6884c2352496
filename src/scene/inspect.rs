//! Click-through inspection: what the model says at a point of a figure (a
//! cell of the collision-speed map, a point of a growth track or a batch
//! lifeline, a Monte Carlo family), as a card of numbers, an optional bar
//! chart, and the scenes that look at the same point more closely.

use super::SceneParams;
use crate::figure::Figure;
use crate::figure::layout::View;

/// What a click on a figure shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Inspection {
    /// Heading, e.g. "m_i = 10³ m₀, m_j = 10⁸ m₀".
    pub title: String,
    /// (quantity, value with unit), in reading order.
    pub rows: Vec<(String, String)>,
    /// A small bar chart: its title and (label, value) bars, values ≥ 0.
    pub bars: Option<(String, Vec<(String, f64)>)>,
    /// The verdict, e.g. the collision's outcome with the thresholds it was compared to.
    pub outcome: Option<String>,
    /// Where to go next.
    pub actions: Vec<Action>,
    /// The inspected point on the figure (axis units), to ring it.
    pub point: [f64; 2],
}

/// A scene opened at the inspected point.
#[derive(Debug, Clone, PartialEq)]
pub struct Action {
    /// Button text, e.g. "Open as a collision".
    pub label: String,
    /// What the scene will show.
    pub hint: String,
    /// The scene and its parameters.
    pub open: SceneParams,
}

/// A row: quantity and value with its unit.
pub fn row(quantity: &str, value: impl Into<String>) -> (String, String) {
    (quantity.to_string(), value.into())
}

/// A number as short text with its unit.
pub fn value(v: f64, unit: &str) -> String {
    let n = crate::figure::human(v);
    if unit.is_empty() { n } else { format!("{n} {unit}") }
}

/// A length (m) as text with a fitting unit (nm, µm, cm or m).
pub fn length(a: f64) -> String {
    if a < 1e-6 {
        value(a * 1e9, "nm")
    } else if a < 1e-3 {
        value(a * 1e6, "µm")
    } else if a < 1.0 {
        value(a * 1e2, "cm")
    } else if a < 1e3 {
        value(a, "m")
    } else {
        value(a * 1e-3, "km")
    }
}

/// Distance between two points of `fig` in fractions of its default view's
/// width and height, so that both axes count alike; infinite when a point
/// cannot be shown.
pub fn distance(fig: &Figure, a: [f64; 2], b: [f64; 2]) -> f64 {
    let view = View::of(fig);
    match (view.fraction(a), view.fraction(b)) {
        (Some(p), Some(q)) => (p[0] - q[0]).hypot(p[1] - q[1]),
        _ => f64::INFINITY,
    }
}

/// The point of `points` nearest to `at` on `fig`, within `within` of the
/// view (e.g. 0.05): its index and distance.
pub fn nearest(
    fig: &Figure,
    points: impl IntoIterator<Item = [f64; 2]>,
    at: [f64; 2],
    within: f64,
) -> Option<(usize, f64)> {
    points
        .into_iter()
        .enumerate()
        .map(|(i, p)| (i, distance(fig, p, at)))
        .filter(|(_, d)| *d <= within)
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

/// The figure with id `id` in `figures`.
pub fn figure<'a>(figures: &'a [Figure], id: &str) -> Option<&'a Figure> {
    figures.iter().find(|f| f.id == id)
}
