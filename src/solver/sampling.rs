//! Adaptive sampling of a smooth, expensive function of one variable.
//!
//! A curve drawn at hundreds of points rarely needs hundreds of evaluations:
//! where it is smooth, a local cubic through a few samples reproduces it to
//! far below the width of a line. [`refine`] places samples where the curve
//! needs them: it predicts the value in the middle of every interval from
//! the samples it has, evaluates the function there (all middles of a round
//! at once, so the caller can spread them over threads), and splits again
//! only the intervals whose prediction missed. [`interpolate`] then reads the
//! curve anywhere. (Written here: the refinement has to hand whole rounds of
//! points to a caller that evaluates them in parallel and may fail or be
//! cancelled, which the interpolation crates do not offer; the interpolant is
//! a few lines.)

/// Samples (x, y) sorted by x with distinct x.
pub type Samples = Vec<[f64; 2]>;

/// The local cubic through the (up to) four samples around `x`: the two on
/// either side of it, shifted inwards at the ends. Two samples give a
/// straight line, one a constant; outside the samples it extrapolates the end
/// cubic.
pub fn interpolate(samples: &[[f64; 2]], x: f64) -> f64 {
    let n = samples.len();
    match n {
        0 => return f64::NAN,
        1 => return samples[0][1],
        _ => {}
    }
    // Index of the interval [x_i, x_{i+1}] holding x (clamped to the ends).
    let i = samples.partition_point(|s| s[0] <= x).clamp(1, n - 1) - 1;
    let first = i.saturating_sub(1).min(n.saturating_sub(4));
    let window = &samples[first..(first + 4).min(n)];
    // Lagrange form: fine for four points at most.
    window
        .iter()
        .enumerate()
        .map(|(j, &[xj, yj])| {
            let w: f64 =
                window.iter().enumerate().filter(|&(k, _)| k != j).map(|(_, &[xk, _])| (x - xk) / (xj - xk)).product();
            w * yj
        })
        .sum()
}

/// The largest miss (in units of the tolerance) after which the two halves
/// of an interval are accepted without evaluating their middles: halving
/// divides a cubic's error by 16, so they miss by at most a half.
pub const HALVES_TRUSTED: f64 = 8.0;

/// How a refinement went.
#[derive(Debug, Clone, PartialEq)]
pub enum Refined {
    /// Every interval passed its test: the samples, sorted.
    Converged(Samples),
    /// The next round would exceed `max_samples`: the samples so far.
    Budget(Samples),
}

/// Refines `samples` (sorted by x, at least two) until every interval's
/// middle is predicted by [`interpolate`] from the others within tolerance,
/// or an interval is narrower than `min_width`. `miss(x, predicted,
/// evaluated)` is the error of a prediction in units of the tolerance (≤ 1
/// passes). An interval that missed by at most [`HALVES_TRUSTED`] is split
/// and its halves are accepted unchecked: the local cubic's error falls as
/// the fourth power of the width, so theirs is below half the tolerance. `evaluate` receives each round's new abscissae and returns
/// their values in order; its error ends the refinement.
pub fn refine<E>(
    mut samples: Samples,
    min_width: f64,
    max_samples: usize,
    miss: impl Fn(f64, f64, f64) -> f64,
    mut evaluate: impl FnMut(&[f64]) -> Result<Vec<f64>, E>,
) -> Result<Refined, E> {
    crate::sorting::sort_by_key(&mut samples, |a| a[0]);
    samples.dedup_by(|a, b| a[0] == b[0]);
    let mut pending: Vec<[f64; 2]> = samples.windows(2).map(|w| [w[0][0], w[1][0]]).collect();
    loop {
        pending.retain(|[a, b]| b - a > min_width);
        if pending.is_empty() || samples.len() < 2 {
            return Ok(Refined::Converged(samples));
        }
        if samples.len() + pending.len() > max_samples {
            return Ok(Refined::Budget(samples));
        }
        let middles: Vec<f64> = pending.iter().map(|[a, b]| 0.5 * (a + b)).collect();
        let predicted: Vec<f64> = middles.iter().map(|&m| interpolate(&samples, m)).collect();
        let values = evaluate(&middles)?;
        let mut next = Vec::new();
        for ((&[a, b], &m), (&p, &y)) in pending.iter().zip(&middles).zip(predicted.iter().zip(&values)) {
            if miss(m, p, y) > HALVES_TRUSTED {
                next.push([a, m]);
                next.push([m, b]);
            }
        }
        samples.extend(middles.iter().zip(&values).map(|(&m, &y)| [m, y]));
        crate::sorting::sort_by_key(&mut samples, |a| a[0]);
        pending = next;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> Samples {
        (0..n).map(|i| a + (b - a) * i as f64 / (n - 1) as f64).map(|x| [x, f(x)]).collect()
    }

    #[test]
    fn a_cubic_is_reproduced_exactly() {
        let f = |x: f64| 2.0 - x + 0.5 * x * x - 0.25 * x.powi(3);
        let s = grid(f, -1.0, 2.0, 6);
        for x in [-1.0, -0.3, 0.0, 0.77, 1.5, 2.0] {
            assert!((interpolate(&s, x) - f(x)).abs() < 1e-12, "{x}");
        }
        // Two samples: the straight line through them.
        let line = f(-1.0) + (f(-0.4) - f(-1.0)) / 0.6;
        assert!((interpolate(&s[..2], 0.0) - line).abs() < 1e-12);
    }

    #[test]
    fn refinement_meets_its_tolerance_everywhere_with_few_samples() {
        // Smooth but with a steep region: the samples crowd there.
        let f = |x: f64| (8.0 * x).tanh() + 0.1 * x.sin();
        let tol = 1e-5;
        let mut calls = 0;
        let out = refine(
            grid(f, -3.0, 3.0, 7),
            1e-9,
            1000,
            |_, p, y| (p - y).abs() / tol,
            |xs| -> Result<Vec<f64>, ()> {
                calls += xs.len();
                Ok(xs.iter().map(|&x| f(x)).collect())
            },
        )
        .expect("no error");
        let Refined::Converged(s) = out else { panic!("budget") };
        assert_eq!(s.len(), 7 + calls);
        let worst =
            (0..=6000).map(|i| -3.0 + i as f64 * 1e-3).map(|x| (interpolate(&s, x) - f(x)).abs()).fold(0.0, f64::max);
        assert!(worst <= tol, "worst error {worst:e} with {} samples", s.len());
        assert!(s.len() < 300, "{} samples", s.len());
        // Samples are denser in the steep middle than at the flat ends.
        let near = s.iter().filter(|p| p[0].abs() < 0.5).count();
        let far = s.iter().filter(|p| p[0] > 2.0).count();
        assert!(near > 3 * far, "{near} vs {far}");
    }

    #[test]
    fn the_budget_and_errors_end_the_refinement() {
        let f = |x: f64| (50.0 * x).sin();
        let out = refine(
            grid(f, 0.0, 1.0, 3),
            1e-12,
            20,
            |_, p, y| (p - y).abs() / 1e-12,
            |xs| -> Result<Vec<f64>, ()> { Ok(xs.iter().map(|&x| f(x)).collect()) },
        );
        let Ok(Refined::Budget(s)) = out else { panic!("{out:?}") };
        assert!(s.len() <= 20);
        let err = refine(grid(f, 0.0, 1.0, 3), 1e-12, 20, |_, _, _| f64::INFINITY, |_| Err("cancelled"));
        assert_eq!(err, Err("cancelled"));
    }
}
