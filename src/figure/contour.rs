//! Contour lines of a map (marching squares), as a series of line pieces
//! separated by non-finite points, which every renderer draws as breaks.

use super::Scale;

/// The points of the contour at `level` of `values` over the grid of cell
/// centres `x` × `y` (row by row, `values[j * x.len() + i]` at
/// (x[i], y[j])). Crossings are interpolated linearly in the axis
/// coordinates (log10 on logarithmic axes). Each piece is two points followed
/// by a `[NaN, NaN]` break; non-finite values make no crossing.
pub fn contour(x: &[f64], y: &[f64], values: &[f64], level: f64, scales: (Scale, Scale)) -> Vec<[f64; 2]> {
    let (nx, ny) = (x.len(), y.len());
    let mut out = Vec::new();
    if nx < 2 || ny < 2 || values.len() != nx * ny || !level.is_finite() {
        return out;
    }
    let to_axis = |v: f64, s: Scale| if s == Scale::Log { v.log10() } else { v };
    let from_axis = |v: f64, s: Scale| if s == Scale::Log { 10f64.powf(v) } else { v };
    let ax: Vec<f64> = x.iter().map(|&v| to_axis(v, scales.0)).collect();
    let ay: Vec<f64> = y.iter().map(|&v| to_axis(v, scales.1)).collect();
    let at = |i: usize, j: usize| values[j * nx + i];
    // Where the level crosses the edge from corner a to corner b (axis units).
    let cross = |(pa, va): ([f64; 2], f64), (pb, vb): ([f64; 2], f64)| {
        let t = (level - va) / (vb - va);
        [pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1])]
    };
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            // Corners counter-clockwise from the lower left.
            let c = [
                ([ax[i], ay[j]], at(i, j)),
                ([ax[i + 1], ay[j]], at(i + 1, j)),
                ([ax[i + 1], ay[j + 1]], at(i + 1, j + 1)),
                ([ax[i], ay[j + 1]], at(i, j + 1)),
            ];
            if c.iter().any(|(_, v)| !v.is_finite()) {
                continue;
            }
            // The edges the level crosses, in order around the cell.
            let crossings: Vec<[f64; 2]> = (0..4)
                .filter_map(|k| {
                    let (a, b) = (c[k], c[(k + 1) % 4]);
                    ((a.1 < level) != (b.1 < level)).then(|| cross(a, b))
                })
                .collect();
            // Two crossings make one piece; four (a saddle) make two, paired
            // around the cell.
            for pair in crossings.chunks_exact(2) {
                for p in pair {
                    out.push([from_axis(p[0], scales.0), from_axis(p[1], scales.1)]);
                }
                out.push([f64::NAN, f64::NAN]);
            }
        }
    }
    out
}

/// Where to write a contour's level on the map over `x` × `y`: the middle
/// one of its crossings in the order they were found (row by row), so the
/// label sits on the line and nested contours are labelled at different
/// heights, preferring crossings away from the map's edges where a centred
/// label would be cut; None for an empty contour.
pub fn label_point(points: &[[f64; 2]], x: &[f64], y: &[f64], scales: (Scale, Scale)) -> Option<[f64; 2]> {
    let to_axis = |v: f64, s: Scale| if s == Scale::Log { v.log10() } else { v };
    let fraction = |v: f64, ends: &[f64], s: Scale| {
        let (a, b) = (to_axis(*ends.first()?, s), to_axis(*ends.last()?, s));
        Some((to_axis(v, s) - a) / (b - a))
    };
    let finite: Vec<[f64; 2]> = points.iter().copied().filter(|p| p[0].is_finite() && p[1].is_finite()).collect();
    let inside: Vec<[f64; 2]> = finite
        .iter()
        .copied()
        .filter(|p| {
            fraction(p[0], x, scales.0).is_some_and(|f| (0.15..=0.85).contains(&f))
                && fraction(p[1], y, scales.1).is_some_and(|f| (0.06..=0.94).contains(&f))
        })
        .collect();
    let pick = if inside.is_empty() { finite } else { inside };
    pick.get(pick.len() / 2).copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_is_traced_at_its_radius() {
        let g: Vec<f64> = (0..41).map(|k| -2.0 + 0.1 * k as f64).collect();
        let values: Vec<f64> = g.iter().flat_map(|&y| g.iter().map(move |&x| (x * x + y * y).sqrt())).collect();
        let pts = contour(&g, &g, &values, 1.0, (Scale::Linear, Scale::Linear));
        let on_line: Vec<&[f64; 2]> = pts.iter().filter(|p| p[0].is_finite()).collect();
        assert!(on_line.len() > 50, "{} points", on_line.len());
        for p in on_line {
            let r = p[0].hypot(p[1]);
            assert!((r - 1.0).abs() < 0.01, "r = {r}");
        }
        // Every piece is two points and a break.
        assert_eq!(pts.len() % 3, 0);
        assert!(pts.chunks(3).all(|c| c[0][0].is_finite() && c[1][0].is_finite() && c[2][0].is_nan()));
    }

    #[test]
    fn log_axes_interpolate_in_decades() {
        // v = log10(x) on x = 1, 100: the level 1 crosses at x = 10.
        let x = [1.0, 100.0];
        let y = [1.0, 2.0];
        let values = [0.0, 2.0, 0.0, 2.0];
        let pts = contour(&x, &y, &values, 1.0, (Scale::Log, Scale::Linear));
        assert!(pts.iter().filter(|p| p[0].is_finite()).all(|p| (p[0] - 10.0).abs() < 1e-9));
    }

    #[test]
    fn no_crossing_and_bad_input_give_nothing() {
        let g = [0.0, 1.0];
        assert!(contour(&g, &g, &[0.0; 4], 1.0, (Scale::Linear, Scale::Linear)).is_empty());
        assert!(contour(&g, &g, &[0.0; 3], 0.5, (Scale::Linear, Scale::Linear)).is_empty());
        assert!(contour(&g, &g, &[0.0, f64::NAN, 1.0, 1.0], 0.5, (Scale::Linear, Scale::Linear)).is_empty());
    }
}
