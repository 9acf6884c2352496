//! Bracketed root finding: the Illinois variant of regula falsi, which keeps
//! the bracket of bisection and converges superlinearly on smooth functions;
//! where the bracket does not halve in two steps (a kink or a jump of f) the
//! next step bisects, so it never takes more than twice bisection's steps.
//! (Written here rather than taken from a crate: it is a few lines, the models
//! need the evaluation count and a bracket they already hold.)

/// A root found by [`illinois`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// The final bracket [lo, hi] around the sign change.
    pub bracket: [f64; 2],
    /// Function evaluations used.
    pub evaluations: usize,
}

impl Root {
    /// The middle of the final bracket.
    pub fn x(&self) -> f64 {
        0.5 * (self.bracket[0] + self.bracket[1])
    }
}

/// Narrows a bracket [lo, hi] with f(lo) = `f_lo` and f(hi) = `f_hi` of
/// opposite signs (or one of them zero) until it is narrower than `tol` or
/// `max_evaluations` are spent. Non-finite values of f fall back to bisection.
pub fn illinois(
    mut f: impl FnMut(f64) -> f64,
    [mut lo, mut hi]: [f64; 2],
    [mut f_lo, mut f_hi]: [f64; 2],
    tol: f64,
    max_evaluations: usize,
) -> Root {
    let mut evaluations = 0;
    let mut side = 0;
    // Bracket width two steps ago and one step ago.
    let mut widths = [f64::INFINITY; 2];
    let positive_low = f_lo > 0.0 || (f_lo == 0.0 && f_hi < 0.0);
    while hi - lo > tol && evaluations < max_evaluations {
        let stalled = hi - lo > 0.5 * widths[0];
        widths = [widths[1], hi - lo];
        let x = if !stalled && f_lo.is_finite() && f_hi.is_finite() && f_lo != f_hi {
            (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        } else {
            0.5 * (lo + hi)
        };
        let x = if x > lo && x < hi { x } else { 0.5 * (lo + hi) };
        let fx = f(x);
        evaluations += 1;
        if fx == 0.0 {
            return Root { bracket: [x, x], evaluations };
        }
        if (fx > 0.0) == positive_low {
            lo = x;
            f_lo = fx;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = x;
            f_hi = fx;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
        if (f_lo - f_hi).abs() < 1e-13 * f_lo.abs().max(f_hi.abs()).max(1e-300) {
            break;
        }
    }
    Root { bracket: [lo, hi], evaluations }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_roots_of_either_slope_to_the_tolerance() {
        for (f, root) in [
            (Box::new(|x: f64| x * x * x - 2.0) as Box<dyn Fn(f64) -> f64>, 2f64.cbrt()),
            (Box::new(|x: f64| (-x).exp() - 0.5), 2f64.ln()),
        ] {
            let (lo, hi) = (0.0, 3.0);
            let r = illinois(&f, [lo, hi], [f(lo), f(hi)], 1e-12, 200);
            assert!((r.x() - root).abs() < 1e-11, "{} vs {root}", r.x());
            assert!(r.evaluations < 20, "{} evaluations", r.evaluations);
        }
    }

    #[test]
    fn a_step_function_ends_in_a_bisection_bracket() {
        let f = |x: f64| if x < 0.3 { 1.0 } else { -1.0 };
        let r = illinois(f, [0.0, 1.0], [1.0, -1.0], 1e-9, 200);
        assert!(r.bracket[0] < 0.3 && r.bracket[1] >= 0.3 && r.bracket[1] - r.bracket[0] <= 1e-9);
    }
}
