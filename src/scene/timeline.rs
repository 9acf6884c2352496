//! Time cursors over computed histories: where a scene's cursor stands and
//! what it marks on each figure. A cursor is a styling parameter, so moving
//! it (by hand or by playing the history) never recomputes the model; the
//! marks are read off the figures already computed.

use super::core::SceneOutput;
use crate::figure::{Figure, Fill, Scale, Series, Shape, Style};

/// What a time cursor marks on one figure, in the figure's axis units.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A point: where a history stands at the cursor's time, with the
    /// palette colour of the curve it sits on when several share a time
    /// (so that each dot tells its curve).
    Point([f64; 2], Option<usize>),
    /// A vertical line at this x (the cursor's time on a time axis).
    Time(f64),
    /// A whole curve: the snapshot the cursor selects.
    Curve(Vec<[f64; 2]>),
}

/// A time cursor: the fraction of the history it stands at, the time as
/// text, and what it marks on each figure (by figure id).
#[derive(Debug, Clone, PartialEq)]
pub struct Cursor {
    /// Fraction of the run, 0–1.
    pub fraction: f64,
    /// The time it stands at, e.g. "t = 12.5 ns".
    pub label: String,
    /// (figure id, mark) pairs; a figure may carry several marks.
    pub marks: Vec<(String, Mark)>,
    /// Whether the marks are drawn only once the history is played or
    /// scrubbed (scenes whose figure reads as the thesis's without them);
    /// otherwise they are always drawn, and exported with the figures.
    pub optional: bool,
}

/// Colour index in [`crate::figure::PALETTE`] of the cursor's marks in
/// exported files: the palette's neutral grey, apart from the data colours
/// (the window draws them in the text colour).
pub const CURSOR_COLOR: usize = 6;

impl Cursor {
    /// The marks on figure `id`.
    pub fn marks_on<'a>(&'a self, id: &'a str) -> impl Iterator<Item = &'a Mark> + 'a {
        self.marks.iter().filter(move |(f, _)| f == id).map(|(_, m)| m)
    }

    /// Adds the cursor's marks to the figures as ordinary series (named
    /// "time cursor"), so that an exported figure or a movie frame shows
    /// what the window shows.
    pub fn apply(&self, figures: &mut [Figure]) {
        for fig in figures.iter_mut() {
            let y_range = fig.bounds().map(|b| [b[2], b[3]]);
            let marks: Vec<Mark> = self.marks_on(&fig.id).cloned().collect();
            for mark in marks {
                // The points share one legend entry; the time line is named by the time.
                let series = match mark {
                    Mark::Point(p, color) => Series::new(
                        "time cursor",
                        vec![p],
                        Style::Symbol(Shape::Circle, Fill::Filled),
                        color.unwrap_or(CURSOR_COLOR),
                    )
                    .keyed("time cursor"),
                    Mark::Time(x) => match y_range {
                        Some([lo, hi]) => {
                            Series::new(self.label.clone(), vec![[x, lo], [x, hi]], Style::Dotted, CURSOR_COLOR)
                        }
                        None => continue,
                    },
                    Mark::Curve(points) => Series::new(self.label.clone(), points, Style::Line, CURSOR_COLOR),
                };
                fig.series.push(series);
            }
        }
    }
}

/// The range of x over the solid lines of figure `id` of `out`.
pub fn x_range(out: &SceneOutput, id: &str) -> Option<(f64, f64)> {
    let fig = out.figures.iter().find(|f| f.id == id)?;
    let xs = fig.series.iter().filter(|s| s.style == Style::Line).flat_map(|s| s.points.iter().map(|p| p[0]));
    let (lo, hi) = xs
        .filter(|x| x.is_finite() && (fig.x.scale == Scale::Linear || *x > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    (lo < hi).then_some((lo, hi))
}

/// The time at `fraction` of `range`: evenly on a linear axis, evenly in
/// log on a logarithmic one.
pub fn time_at(range: (f64, f64), fraction: f64, scale: Scale) -> f64 {
    let f = fraction.clamp(0.0, 1.0);
    match scale {
        Scale::Linear => range.0 + f * (range.1 - range.0),
        Scale::Log => range.0 * (range.1 / range.0).powf(f),
    }
}

/// Marks for a cursor at `x` on figure `id`, whose x-axis is time: a
/// vertical line, and a point on every solid line where it passes `x`
/// (linear interpolation between its samples, in log on log axes).
pub fn along_x(out: &SceneOutput, id: &str, x: f64) -> Vec<(String, Mark)> {
    let Some(fig) = out.figures.iter().find(|f| f.id == id) else { return Vec::new() };
    let mut marks = vec![(id.to_string(), Mark::Time(x))];
    for s in fig.series.iter().filter(|s| s.style == Style::Line) {
        if let Some(y) = interpolate(&s.points, x, fig.x.scale, fig.y.scale) {
            marks.push((id.to_string(), Mark::Point([x, y], Some(s.color))));
        }
    }
    marks
}

/// The time span of timed paths: (earliest positive time, latest time).
pub fn span(paths: &[super::core::TimedPath]) -> Option<(f64, f64)> {
    let times = paths.iter().flat_map(|p| p.times.iter().copied()).filter(|t| *t > 0.0 && t.is_finite());
    let (lo, hi) = times.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| (a.min(t), b.max(t)));
    (lo < hi).then_some((lo, hi))
}

/// Where each timed path stands at time `t`: interpolated (in log) between
/// its samples; a path that ended before `t` stays at its last point, one
/// that starts after it is not marked.
pub fn along_paths(paths: &[super::core::TimedPath], t: f64) -> Vec<(String, Mark)> {
    let mut marks = Vec::new();
    for p in paths {
        let (Some(&first), Some(&last)) = (p.times.first(), p.times.last()) else { continue };
        if t < first || p.points.len() != p.times.len() {
            continue;
        }
        let at = if t >= last {
            p.points[p.points.len() - 1]
        } else {
            let k = p.times.partition_point(|&x| x <= t).clamp(1, p.times.len() - 1);
            let (t0, t1) = (p.times[k - 1], p.times[k]);
            let f = if t0 > 0.0 && t1 > t0 { (t / t0).ln() / (t1 / t0).ln() } else { 0.0 };
            let (a, b) = (p.points[k - 1], p.points[k]);
            let mix = |u: f64, v: f64| if u > 0.0 && v > 0.0 { u * (v / u).powf(f) } else { u + f * (v - u) };
            [mix(a[0], b[0]), mix(a[1], b[1])]
        };
        marks.push((p.figure.clone(), Mark::Point(at, p.color)));
    }
    marks
}

/// The y of a polyline at `x` (the first segment that spans it), or none
/// when it does not reach `x`.
fn interpolate(points: &[[f64; 2]], x: f64, xs: Scale, ys: Scale) -> Option<f64> {
    let t = |v: f64, s: Scale| match s {
        Scale::Linear => v,
        Scale::Log => v.ln(),
    };
    let tx = t(x, xs);
    for w in points.windows(2) {
        let (a, b) = (t(w[0][0], xs), t(w[1][0], xs));
        if !(a.is_finite() && b.is_finite()) || !((a <= tx && tx <= b) || (b <= tx && tx <= a)) {
            continue;
        }
        let f = if b == a { 0.0 } else { (tx - a) / (b - a) };
        let (ya, yb) = (t(w[0][1], ys), t(w[1][1], ys));
        if !(ya.is_finite() && yb.is_finite()) {
            continue;
        }
        let y = ya + f * (yb - ya);
        return Some(match ys {
            Scale::Linear => y,
            Scale::Log => y.exp(),
        });
    }
    None
}

/// The snapshot of figure `id` nearest `value` among its solid family
/// members (series marked with [`Series::at`]), as a curve mark, and that
/// member's value.
pub fn snapshot(out: &SceneOutput, id: &str, value: f64) -> Option<((String, Mark), f64)> {
    let fig = out.figures.iter().find(|f| f.id == id)?;
    let scale = fig.family.as_ref().map_or(Scale::Log, |f| f.scale);
    let distance = |v: f64| match scale {
        Scale::Log if v > 0.0 && value > 0.0 => (v / value).ln().abs(),
        _ => (v - value).abs(),
    };
    let s = fig
        .series
        .iter()
        .filter(|s| s.style == Style::Line && s.family.is_some())
        .min_by(|a, b| distance(a.family.unwrap_or(f64::NAN)).total_cmp(&distance(b.family.unwrap_or(f64::NAN))))?;
    Some(((id.to_string(), Mark::Curve(s.points.clone())), s.family?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::Axis;

    fn output() -> SceneOutput {
        let fig = Figure::new("f", "f", Axis::log("time", "yr"), Axis::log("m", "g"))
            .with(Series::new("a", vec![[1.0, 1.0], [100.0, 1e4]], Style::Line, 0))
            .with(Series::new("late", vec![[10.0, 5.0], [100.0, 50.0]], Style::Line, 1))
            .with(Series::new("ref", vec![[1.0, 3.0], [100.0, 3.0]], Style::Dashed, 2));
        SceneOutput { figures: vec![fig], ..SceneOutput::default() }
    }

    /// On log axes a power law is interpolated exactly; a line that starts
    /// later is not marked before it starts; dashed references are not marked.
    #[test]
    fn a_cursor_marks_the_lines_it_crosses() {
        let out = output();
        assert_eq!(x_range(&out, "f"), Some((1.0, 100.0)));
        let t = time_at((1.0, 100.0), 0.5, Scale::Log);
        assert!((t - 10.0).abs() < 1e-12);
        let marks = along_x(&out, "f", t);
        assert_eq!(marks[0].1, Mark::Time(t));
        let Mark::Point(p, _) = marks[1].1 else { panic!("a point") };
        assert!((p[1] - 100.0).abs() < 1e-9, "{p:?}");
        assert_eq!(marks.len(), 3, "the later line starts at 10 and is marked there");
        assert_eq!(along_x(&out, "f", 2.0).len(), 2, "before the later line starts");
    }

    /// A timed path is followed in log time and stays at its end.
    #[test]
    fn timed_paths_are_followed() {
        let path = crate::scene::core::TimedPath {
            figure: "f".into(),
            color: None,
            times: vec![1.0, 100.0],
            points: vec![[1.0, 10.0], [100.0, 1000.0]],
        };
        let late = crate::scene::core::TimedPath { times: vec![50.0, 100.0], ..path.clone() };
        let paths = [path, late];
        assert_eq!(span(&paths), Some((1.0, 100.0)));
        let marks = along_paths(&paths, 10.0);
        assert_eq!(marks.len(), 1, "the late path has not started");
        let Mark::Point(p, _) = marks[0].1 else { panic!("a point") };
        assert!((p[0] - 10.0).abs() < 1e-9 && (p[1] - 100.0).abs() < 1e-9, "{p:?}");
        assert_eq!(along_paths(&paths, 1e4)[0].1, Mark::Point([100.0, 1000.0], None));
    }

    /// Applying a cursor adds its marks as series, a time line spanning the data.
    #[test]
    fn applied_marks_become_series() {
        let out = output();
        let cursor = Cursor { fraction: 0.5, label: String::new(), marks: along_x(&out, "f", 10.0), optional: false };
        let mut figs = out.figures.clone();
        cursor.apply(&mut figs);
        let before = out.figures[0].series.len();
        let added: Vec<&Series> = figs[0].series[before..].iter().collect();
        assert_eq!(added.len(), 3);
        assert_eq!(added[0].points, vec![[10.0, 1.0], [10.0, 1e4]]);
        let legend = figs[0].legend();
        assert_eq!(legend.iter().filter(|e| e.0 == "time cursor").count(), 1, "the points are listed once");
    }
}
