//! An adaptive explicit Runge–Kutta integrator (Dormand & Prince's 5(4)
//! pair) for small non-stiff systems dy/dx = f(x, y).
//!
//! Seven stages (the last is the first of the next step), order 5 with an
//! embedded order 4 for error control (Hairer, Nørsett & Wanner, Solving
//! ODEs I, Sect. II.5). The right-hand side may refuse a stage (return
//! `None`, for example outside the domain of a crack law); the step is then
//! retried with a quarter of its size.

use super::rosenbrock::{SolverError, SolverStats, State};

const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 6] = [
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
    [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
    [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
];
/// The fifth-order weights minus the embedded fourth-order ones.
const E: [f64; 7] =
    [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];

/// Integrates dy/dx = `f`(x, y) from `start` = (x₀, y₀) to `x1` (either
/// side of x₀), with a first step of |`h0`|, keeping each component's local error
/// below `rtol` · max(|y_i|, |y_new,i|, `scale`_i). Calls `accepted`(x, y)
/// after every accepted step. Returns y(`x1`) and the work done.
pub fn dormand_prince<const N: usize>(
    f: impl Fn(f64, &State<N>) -> Option<State<N>>,
    start: (f64, State<N>),
    x1: f64,
    h0: f64,
    rtol: f64,
    scale: &State<N>,
    mut accepted: impl FnMut(f64, &State<N>),
) -> Result<(State<N>, SolverStats), SolverError> {
    let (x0, y0) = start;
    let direction = if x1 >= x0 { 1.0 } else { -1.0 };
    let span = (x1 - x0).abs();
    let h_min = 1e-12 * span.max(h0.abs());
    let mut stats = SolverStats::default();
    let (mut x, mut y) = (x0, y0);
    let mut h = h0.abs().min(span);
    let Some(mut k0) = f(x, &y) else {
        return Err(SolverError::StepSizeUnderflow { steps: 0, h: 0.0 });
    };
    stats.rhs_evals += 1;
    while (x1 - x) * direction > 0.0 {
        if stats.accepted >= 100_000 {
            return Err(SolverError::TooManySteps(100_000));
        }
        let last = h >= (x1 - x).abs();
        if last {
            h = (x1 - x).abs();
        }
        if h < h_min {
            return Err(SolverError::StepSizeUnderflow { steps: stats.accepted, h });
        }
        let hs = direction * h;
        let stepped = dormand_prince_step(&f, x, &y, &k0, hs);
        stats.rhs_evals += 6;
        match stepped.filter(|(y_new, _, err)| y_new.iter().chain(err.iter()).all(|v| v.is_finite())) {
            Some((y_new, k_new, err)) => {
                let mut sum = 0.0;
                for i in 0..N {
                    let sc = rtol * y[i].abs().max(y_new[i].abs()).max(scale[i]);
                    let r = err[i] / sc;
                    sum += r * r;
                }
                let norm = (sum / N as f64).sqrt();
                if norm <= 1.0 {
                    stats.accepted += 1;
                    x = if last { x1 } else { x + hs };
                    y = y_new;
                    k0 = k_new;
                    accepted(x, &y);
                    h *= (0.9 * norm.max(1e-10).powf(-0.2)).clamp(0.2, 5.0);
                } else if norm.is_finite() {
                    stats.rejected += 1;
                    h *= (0.9 * norm.powf(-0.2)).clamp(0.1, 0.5);
                } else {
                    stats.rejected += 1;
                    h *= 0.25;
                }
            }
            None => {
                stats.rejected += 1;
                h *= 0.25;
            }
        }
    }
    Ok((y, stats))
}

/// One Dormand–Prince step of `h` from (x, y), where f(x, y) = `k0`: the
/// fifth-order solution, f there (the next step's first stage) and its
/// difference to the embedded fourth-order one; `None` if `f` refuses a
/// stage.
#[allow(clippy::type_complexity)]
pub fn dormand_prince_step<const N: usize>(
    f: &impl Fn(f64, &State<N>) -> Option<State<N>>,
    x: f64,
    y: &State<N>,
    k0: &State<N>,
    h: f64,
) -> Option<(State<N>, State<N>, State<N>)> {
    let mut k = [State::<N>::zeros(); 7];
    k[0] = *k0;
    for stage in 1..7 {
        let mut yi = *y;
        for j in 0..stage {
            yi += (h * A[stage - 1][j]) * k[j];
        }
        k[stage] = f(x + C[stage] * h, &yi)?;
    }
    let mut y_new = *y;
    for j in 0..6 {
        y_new += (h * A[5][j]) * k[j];
    }
    let mut err = State::<N>::zeros();
    for j in 0..7 {
        err += (h * E[j]) * k[j];
    }
    Some((y_new, k[6], err))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fifth_order_in_fixed_steps() {
        // y' = y cos x, y(0) = 1: y = e^{sin x}, to x = 2 in n steps (a
        // tolerance no step misses); halving the step must cut the error
        // by about 2⁵.
        let f = |x: f64, y: &State<1>| Some(State::<1>::new(y[0] * x.cos()));
        let err = |n: usize| {
            let h = 2.0 / n as f64;
            let mut y = State::<1>::new(1.0);
            for i in 0..n {
                let x = h * i as f64;
                let (y_new, _) =
                    dormand_prince(f, (x, y), x + h, h, 1e9, &State::<1>::new(1.0), |_, _| {}).expect("steps");
                y = y_new;
            }
            (y[0] - 2f64.sin().exp()).abs()
        };
        let (e1, e2, e3) = (err(10), err(20), err(40));
        let (p1, p2) = ((e1 / e2).log2(), (e2 / e3).log2());
        assert!(p1 > 4.8 && p2 > 4.8, "observed orders {p1:.2}, {p2:.2}");
    }

    #[test]
    fn adaptive_steps_meet_the_tolerance_in_either_direction() {
        // y' = −2xy: y = exp(−x²), from 0 to 3 and back from 3 to 0.
        let f = |x: f64, y: &State<1>| Some(State::<1>::new(-2.0 * x * y[0]));
        let scale = State::<1>::new(1e-3);
        let (y, stats) =
            dormand_prince(f, (0.0, State::<1>::new(1.0)), 3.0, 0.01, 1e-8, &scale, |_, _| {}).expect("runs");
        assert!((y[0] - (-9f64).exp()).abs() < 1e-9, "{}", y[0]);
        assert!(stats.accepted < 200, "{} steps", stats.accepted);
        let start = State::<1>::new((-9f64).exp());
        let (back, _) = dormand_prince(f, (3.0, start), 0.0, 0.01, 1e-8, &scale, |_, _| {}).expect("runs");
        assert!((back[0] - 1.0).abs() < 1e-6, "{}", back[0]);
    }
}
