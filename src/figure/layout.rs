//! Decisions the window and the file writers share: the range a figure shows
//! by default and where its legend goes without covering data.

use super::{Family, Figure, Scale, Series, Style};

/// The data range a figure shows, in data units, with its axis scales.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Left and right ends of the x-axis.
    pub x: [f64; 2],
    /// Bottom and top ends of the y-axis.
    pub y: [f64; 2],
    /// Scale of the x-axis.
    pub x_scale: Scale,
    /// Scale of the y-axis.
    pub y_scale: Scale,
}

fn padded(lo: f64, hi: f64, scale: Scale) -> [f64; 2] {
    match scale {
        Scale::Linear => {
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            [lo - 0.04 * span, hi + 0.04 * span]
        }
        Scale::Log => {
            if hi > lo {
                let f = (hi / lo).powf(0.04).max(1.05);
                [lo / f, hi * f]
            } else {
                [lo / 2.0, hi * 2.0]
            }
        }
    }
}

impl View {
    /// The default view of a figure: its data with a small margin; on a
    /// logarithmic y-axis limited to [`Figure::y_decades`] below the peak.
    pub fn of(fig: &Figure) -> View {
        let [x0, x1, mut y0, y1] = fig.bounds().unwrap_or([1.0, 10.0, 1.0, 10.0]);
        if let (Scale::Log, Some(d)) = (fig.y.scale, fig.y_decades)
            && d > 0.0
        {
            y0 = y0.max(y1 / 10f64.powf(d));
        }
        if fig.heatmap.is_some() {
            // A map fills its frame.
            return View { x: [x0, x1], y: [y0, y1], x_scale: fig.x.scale, y_scale: fig.y.scale };
        }
        View {
            x: padded(x0, x1, fig.x.scale),
            y: padded(y0, y1, fig.y.scale),
            x_scale: fig.x.scale,
            y_scale: fig.y.scale,
        }
    }

    /// Where a data point sits in the view, as fractions of its width and
    /// height from the lower left corner (outside 0..1 when off the view);
    /// `None` if the axes cannot show it.
    pub fn fraction(&self, p: [f64; 2]) -> Option<[f64; 2]> {
        Some([frac(p[0], self.x, self.x_scale)?, frac(p[1], self.y, self.y_scale)?])
    }
}

fn frac(v: f64, [lo, hi]: [f64; 2], scale: Scale) -> Option<f64> {
    match scale {
        Scale::Linear if v.is_finite() && hi != lo => Some((v - lo) / (hi - lo)),
        Scale::Log if v > 0.0 && v.is_finite() && lo > 0.0 && hi > lo => Some((v / lo).ln() / (hi / lo).ln()),
        _ => None,
    }
}

/// What a colour bar beside a plot shows: a continuous heat map's values or
/// the members of a family.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourBar {
    /// "quantity [unit]".
    pub title: String,
    /// Value at the bottom.
    pub lo: f64,
    /// Value at the top.
    pub hi: f64,
    /// How values spread along the bar.
    pub scale: Scale,
    /// Fraction of the colour map the top reaches (families stop at [`super::FAMILY_TOP`]).
    pub top: f64,
}

impl ColourBar {
    /// The bar of a figure: its continuous heat map, else its family.
    pub fn of(fig: &Figure) -> Option<ColourBar> {
        if let Some(h) = fig.heatmap.as_ref().filter(|h| h.categories.is_empty()) {
            let (lo, hi) = h.range();
            return (lo <= hi).then(|| ColourBar { title: h.title(), lo, hi, scale: Scale::Linear, top: 1.0 });
        }
        ColourBar::family(fig.family.as_ref()?, fig.family_range()?)
    }

    /// The bar of a family whose members span `lo..=hi`.
    pub fn family(f: &Family, (lo, hi): (f64, f64)) -> Option<ColourBar> {
        let scale = if f.scale == Scale::Log && lo > 0.0 { Scale::Log } else { Scale::Linear };
        Some(ColourBar { title: f.title(), lo, hi, scale, top: super::FAMILY_TOP })
    }
}

/// A corner of the plot area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Top right.
    UpperRight,
    /// Top left.
    UpperLeft,
    /// Bottom right.
    LowerRight,
    /// Bottom left.
    LowerLeft,
}

impl Corner {
    /// The box of size `size` (fractions of the plot) in this corner, inset
    /// by `inset`: `[x0, y0, x1, y1]` in fractions from the lower left.
    pub fn rect(self, size: [f64; 2], inset: [f64; 2]) -> [f64; 4] {
        let (x0, x1) = match self {
            Corner::UpperLeft | Corner::LowerLeft => (inset[0], inset[0] + size[0]),
            Corner::UpperRight | Corner::LowerRight => (1.0 - inset[0] - size[0], 1.0 - inset[0]),
        };
        let (y0, y1) = match self {
            Corner::LowerLeft | Corner::LowerRight => (inset[1], inset[1] + size[1]),
            Corner::UpperLeft | Corner::UpperRight => (1.0 - inset[1] - size[1], 1.0 - inset[1]),
        };
        [x0, y0, x1, y1]
    }
}

/// The first corner (upper right, upper left, lower right, lower left) where
/// a legend box of `size` (fractions of the plot's width and height), inset
/// by `inset`, touches none of the series drawn in `view`; `None` when
/// every corner holds data (the legend then goes outside the plot). A
/// figure with a heat map has no free corner.
pub fn free_corner<'a>(
    series: impl IntoIterator<Item = &'a Series> + Clone,
    heatmap: bool,
    view: &View,
    size: [f64; 2],
    inset: [f64; 2],
) -> Option<Corner> {
    if heatmap || size[0] >= 0.7 || size[1] >= 0.9 {
        return None;
    }
    [Corner::UpperRight, Corner::UpperLeft, Corner::LowerRight, Corner::LowerLeft].into_iter().find(|c| {
        // A little room around the box, so that a curve does not graze it.
        let [x0, y0, x1, y1] = c.rect(size, inset);
        let m = 0.015;
        let r = [x0 - m, y0 - m, x1 + m, y1 + m];
        !series.clone().into_iter().any(|s| touches(s, view, r))
    })
}

/// Whether a series drawn in `view` enters the rectangle `r` (fractions).
pub fn touches(s: &Series, view: &View, r: [f64; 4]) -> bool {
    let pts: Vec<Option<[f64; 2]>> = s.points.iter().map(|p| view.fraction(*p)).collect();
    let inside = |p: [f64; 2]| p[0] >= r[0] && p[0] <= r[2] && p[1] >= r[1] && p[1] <= r[3];
    match s.style {
        Style::Line | Style::Dashed | Style::Dotted | Style::Arrow => {
            if pts.len() == 1 {
                return pts[0].is_some_and(inside);
            }
            pts.windows(2).any(|w| match (w[0], w[1]) {
                (Some(a), Some(b)) => segment_meets(a, b, r),
                (Some(a), None) | (None, Some(a)) => inside(a),
                (None, None) => false,
            })
        }
        Style::Region => {
            // The whole region counts, not only its outline.
            let f: Vec<[f64; 2]> = pts.iter().flatten().copied().collect();
            let (lo, hi) = f.iter().fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(lo, hi), p| {
                ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
            });
            !f.is_empty() && lo[0] <= r[2] && hi[0] >= r[0] && lo[1] <= r[3] && hi[1] >= r[1]
        }
        _ => {
            // Markers have a size: about 2 % of the plot.
            let g = [r[0] - 0.02, r[1] - 0.02, r[2] + 0.02, r[3] + 0.02];
            pts.iter().flatten().any(|p| p[0] >= g[0] && p[0] <= g[2] && p[1] >= g[1] && p[1] <= g[3])
        }
    }
}

/// Whether the segment a–b meets the rectangle `r` (Liang–Barsky clipping).
fn segment_meets(a: [f64; 2], b: [f64; 2], r: [f64; 4]) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d[0], a[0] - r[0]), (d[0], r[2] - a[0]), (-d[1], a[1] - r[1]), (d[1], r[3] - a[1])] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::Axis;

    fn fig(points: Vec<[f64; 2]>) -> Figure {
        Figure::new("t", "t", Axis::linear("x", ""), Axis::linear("y", "")).with(Series::new(
            "s",
            points,
            Style::Line,
            0,
        ))
    }

    #[test]
    fn a_rising_curve_leaves_the_upper_left_corner_free() {
        let f = fig((0..=100).map(|i| [i as f64, (i as f64).powi(2)]).collect());
        let v = View::of(&f);
        let c = free_corner(&f.series, false, &v, [0.3, 0.2], [0.02, 0.02]);
        assert_eq!(c, Some(Corner::UpperLeft));
        let r = c.map(|c| c.rect([0.3, 0.2], [0.02, 0.02])).unwrap_or_default();
        assert!(!touches(&f.series[0], &v, r));
    }

    #[test]
    fn a_curve_through_every_corner_sends_the_legend_outside() {
        // A zig-zag that visits all four corners.
        let f = fig(vec![[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]);
        let v = View::of(&f);
        assert_eq!(free_corner(&f.series, false, &v, [0.25, 0.2], [0.02, 0.02]), None);
        assert_eq!(free_corner(&f.series, true, &v, [0.01, 0.01], [0.02, 0.02]), None);
    }

    #[test]
    fn a_segment_crossing_the_box_counts_even_with_no_point_inside() {
        // One long segment straight through the upper right corner box.
        let f = fig(vec![[0.0, 0.9], [2.0, 0.9], [2.0, 0.0]]);
        let v = View::of(&f);
        let r = Corner::UpperRight.rect([0.3, 0.3], [0.0, 0.0]);
        assert!(touches(&f.series[0], &v, r));
        assert_ne!(free_corner(&f.series, false, &v, [0.3, 0.3], [0.02, 0.02]), Some(Corner::UpperRight));
    }

    #[test]
    fn log_views_keep_the_decades_that_hold_mass() {
        let mut f = Figure::new("t", "t", Axis::log("m", "g"), Axis::log("f", "")).y_decades(6.0);
        f.series.push(Series::new("s", vec![[1.0, 1e-35], [10.0, 1.0], [100.0, 1e-3]], Style::Line, 0));
        let v = View::of(&f);
        assert!(v.y[0] > 5e-8 && v.y[0] < 1e-6, "{:?}", v.y);
        assert!(v.y[1] > 1.0);
    }
}
