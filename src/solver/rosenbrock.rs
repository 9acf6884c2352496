//! An adaptive, L-stable, stiffly accurate fourth-order Rosenbrock integrator
//! (RODAS4) for small stiff autonomous systems.
//!
//! Six stages, six right-hand-side evaluations and one Jacobian and LU
//! factorisation per step (for three driving components, the inverse of
//! their block by its cofactors), with an embedded third-order solution for
//! error control. Rosenbrock methods are linearly implicit, so a step needs no
//! Newton iteration: for systems of a handful of equations a step costs about
//! a microsecond, which keeps the stiff contact problems of the collision
//! scenes cheap enough to recompute while a slider moves. Stiff accuracy
//! matters here: with a method that is merely A-stable (R(∞) ≠ 0), stiff
//! components are not damped, a solution can drift off a thin quasi-static
//! manifold, and the error estimate does not notice.
//!
//! A right-hand side may refuse a state (for example one outside the physical
//! domain of a crack law) by returning `None`; the step is then rejected and
//! retried with a smaller step size.

use nalgebra::{SMatrix, SVector};

/// A state vector of dimension `N`.
pub type State<const N: usize> = SVector<f64, N>;
/// A square matrix of dimension `N` (the Jacobian).
pub type Matrix<const N: usize> = SMatrix<f64, N, N>;

/// An autonomous system `dy/dt = f(y)` with its Jacobian.
pub trait StiffSystem<const N: usize> {
    /// The right-hand side `f(y)`, or `None` when `y` lies outside the domain
    /// where `f` is defined.
    fn rhs(&self, y: &State<N>) -> Option<State<N>>;
    /// The Jacobian `∂f/∂y` at `y`, or `None` outside the domain.
    fn jacobian(&self, y: &State<N>) -> Option<Matrix<N>>;
    /// Whether a step from `from` to `to` may be accepted; a system can
    /// refuse steps that jump across a feature the error estimate does not
    /// see. Refused steps are retried with a quarter of the step size.
    fn admissible(&self, _from: &State<N>, _to: &State<N>) -> bool {
        true
    }
    /// `f(y)` and the Jacobian together, for systems that share work between
    /// them; by default the two calls.
    fn rhs_and_jacobian(&self, y: &State<N>) -> Option<(State<N>, Matrix<N>)> {
        Some((self.rhs(y)?, self.jacobian(y)?))
    }
    /// The number of leading components that drive the system. The others
    /// are quadratures (running integrals such as dissipated energies): no
    /// component of `f` depends on them, so their Jacobian columns are zero,
    /// and a step factorises only the leading block.
    const DRIVING: usize = N;
}

/// Why an integration could not continue.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolverError {
    /// The step size fell below the smallest allowed value.
    #[error("step size underflow at step {steps} (h = {h:.3e})")]
    StepSizeUnderflow {
        /// Accepted steps so far.
        steps: usize,
        /// The rejected step size.
        h: f64,
    },
    /// The step budget was exhausted.
    #[error("more than {0} steps needed")]
    TooManySteps(usize),
}

/// Counters describing the work done by an integrator (a [`Rosenbrock4`],
/// or [`dormand_prince`](super::dormand_prince)).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SolverStats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps (error too large or state outside the domain).
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Jacobian evaluations (one per attempted step).
    pub jacobian_evals: usize,
}

impl std::ops::AddAssign for SolverStats {
    fn add_assign(&mut self, other: Self) {
        self.accepted += other.accepted;
        self.rejected += other.rejected;
        self.rhs_evals += other.rhs_evals;
        self.jacobian_evals += other.jacobian_evals;
    }
}

// RODAS4 of Hairer & Wanner (Solving ODEs II, Sect. IV.7), in the
// transformed form (stage inputs a_ij, stage couplings c_ij); stiffly
// accurate: the solution is the input of a last stage plus its increment,
// and the embedded error estimate is that increment.
const GAM: f64 = 0.25;
const A: [[f64; 5]; 5] = [
    [1.544, 0.0, 0.0, 0.0, 0.0],
    [0.946_678_528_081_582_6, 0.255_701_169_898_328_4, 0.0, 0.0, 0.0],
    [3.314_825_187_068_521, 2.896_124_015_972_201, 0.998_641_913_997_781_7, 0.0, 0.0],
    [1.221_224_509_226_641, 6.019_134_481_288_629, 12.537_083_329_320_87, -0.687_886_036_105_895, 0.0],
    [1.221_224_509_226_641, 6.019_134_481_288_629, 12.537_083_329_320_87, -0.687_886_036_105_895, 1.0],
];
const C: [[f64; 5]; 5] = [
    [-5.6688, 0.0, 0.0, 0.0, 0.0],
    [-2.430_093_356_833_875, -0.206_359_915_709_191_5, 0.0, 0.0, 0.0],
    [-0.107_352_905_815_137_5, -9.594_562_251_023_355, -20.470_286_148_096_16, 0.0, 0.0],
    [7.496_443_313_967_647, -10.246_804_314_643_52, -33.999_903_528_199_05, 11.708_908_932_061_6, 0.0],
    [
        8.083_246_795_921_522,
        -7.981_132_988_064_893,
        -31.521_594_328_743_71,
        16.319_305_431_231_36,
        -6.058_818_238_834_054,
    ],
];

// The coefficients d_i of ∂f/∂t of the same method, for non-autonomous
// systems (here: an autonomous one in a changed time); its stage times are
// c = (0, 0.386, 0.21, 0.63, 1, 1).
const D: [f64; 6] = [0.25, -0.1043, 0.1035, -0.0362, 0.0, 0.0];

/// A change of the independent variable, t = t(σ), for a solution that
/// varies on the time scale of t itself at first (a power law in t, such as
/// a crack that starts far from equilibrium at t = 0) and on a fixed time
/// scale later: dt/dσ = (t + t₀) t₁/(t + t₀ + t₁) in effect, logarithmic
/// time ln(1 + t/t₀) while t ≪ t₁ and t/t₁ beyond, as the closed form
/// t(σ) = t₁ ln(1 + (t₀/t₁)(e^σ − 1)).
///
/// A fourth-order method in t needs a step of about a quarter of t to follow
/// a power law to 10⁻⁵, so every decade of t costs some ten steps; in
/// logarithmic time the same solution is nearly linear.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogClock {
    t1: f64,
    /// t₀/t₁, ln t₀/t₁ and ln(1 − t₀/t₁).
    a: f64,
    ln_a: f64,
    ln_1ma: f64,
}

/// A point σ of a [`LogClock`]'s changed time, with b = ((1 − a)/a)e^{−σ}
/// (a = t₀/t₁), in which dt/dσ = t₁/(1 + b): a step multiplies b by
/// e^{−h}, and a stage's rate needs no more.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClockInstant {
    sigma: f64,
    b: f64,
}

impl LogClock {
    /// A clock with the inner time scale `t0` and the outer one `t1` (0 < t0 < t1).
    pub fn new(t0: f64, t1: f64) -> Self {
        let a = t0 / t1;
        Self { t1, a, ln_a: a.ln(), ln_1ma: (-a).ln_1p() }
    }

    /// σ = 0, where t = 0.
    pub fn start(&self) -> ClockInstant {
        ClockInstant { sigma: 0.0, b: (1.0 - self.a) / self.a }
    }

    /// The instant `h` later in σ.
    pub fn after(&self, at: ClockInstant, h: f64) -> ClockInstant {
        ClockInstant { sigma: at.sigma + h, b: at.b * (-h).exp() }
    }

    /// The time t at an instant: t₁ ln(1 − a + a e^σ), written so that
    /// neither a small t nor a large σ loses digits.
    pub fn time(&self, at: ClockInstant) -> f64 {
        if at.b > 1e-200 {
            self.t1 * (self.ln_1ma + (1.0 / at.b).ln_1p())
        } else {
            self.t1 * (at.sigma + self.ln_a + at.b.ln_1p())
        }
    }

    /// dt/dσ at an instant.
    pub fn rate(&self, at: ClockInstant) -> f64 {
        self.t1 / (1.0 + at.b)
    }

    /// What a step of `h` from `at` needs, where f(yₙ) is `f0`.
    fn tick<const N: usize>(&self, at: ClockInstant, h: f64, f0: &State<N>) -> Tick<N> {
        let (rate, slope) = self.stage_rates(at, h);
        Tick { rate, slope_f: f0 * slope }
    }

    /// dt/dσ at each stage of a step of `h` from `at`, and d²t/dσ² at `at`.
    fn stage_rates(&self, at: ClockInstant, h: f64) -> ([f64; 6], f64) {
        let r = |b: f64| self.t1 / (1.0 + b);
        let (e21, e386, e1) = ((-0.21 * h).exp(), (-0.386 * h).exp(), (-h).exp());
        let b = at.b;
        let (r0, r1) = (r(b), r(b * e1));
        ([r0, r(b * e386), r(b * e21), r(b * (e21 * e21 * e21)), r1, r1], r0 * b / (1.0 + b))
    }
}

/// What a step in changed time σ needs: dt/dσ at each stage, and
/// d²t/dσ² f(yₙ) (the time derivative of the changed right-hand side).
struct Tick<const N: usize> {
    rate: [f64; 6],
    slope_f: State<N>,
}

/// LU factorisation with partial pivoting of a small dense matrix, or, for
/// a leading block of three, that block's inverse ([`Lu::invert3`]).
///
/// Written out because nalgebra's `LU` needs type-level dimension bounds
/// that do not compose with a const-generic `N`.
struct Lu<const N: usize> {
    lu: Matrix<N>,
    perm: [usize; N],
    /// Reciprocals of U's diagonal.
    inv_diag: [f64; N],
    /// Size of the leading block that was pivoted.
    k: usize,
}

impl<const N: usize> Lu<N> {
    /// Factors `m`, whose columns `k..N` are zero off the diagonal (a
    /// Rosenbrock matrix I/(γh) − J of a system with `k` driving components);
    /// `k = N` is the plain LU with partial pivoting. Pivots come from the
    /// leading block, and the trailing rows need only their multipliers.
    /// `None` if `m` is singular or not finite.
    fn factor(mut m: Matrix<N>, k: usize) -> Option<Self> {
        let mut perm = [0; N];
        for (i, p) in perm.iter_mut().enumerate() {
            *p = i;
        }
        if k == 3 {
            return Self::invert3(m, perm);
        }
        for col in 0..N {
            let mut piv = col;
            for row in col + 1..k {
                if m[(row, col)].abs() > m[(piv, col)].abs() {
                    piv = row;
                }
            }
            let d = m[(piv, col)];
            if d == 0.0 || !d.is_finite() {
                return None;
            }
            if col >= k {
                continue;
            }
            if piv != col {
                m.swap_rows(piv, col);
                perm.swap(piv, col);
            }
            for row in col + 1..N {
                let f = m[(row, col)] / d;
                m[(row, col)] = f;
                for c in col + 1..k {
                    let v = m[(col, c)];
                    m[(row, c)] -= f * v;
                }
            }
        }
        let mut inv_diag = [0.0; N];
        for (i, d) in inv_diag.iter_mut().enumerate() {
            *d = 1.0 / m[(i, i)];
        }
        Some(Lu { lu: m, perm, inv_diag, k })
    }

    /// A leading block of three, inverted by its cofactors (nalgebra's
    /// closed-form 3 × 3 inverse): no pivoting, where partial pivoting took
    /// compares, swaps and divisions one after the other, and a stage's
    /// solve is three independent dot products (each stage of a step waits
    /// on the solve before it). Solving with the inverse of the pivoted
    /// factors was as slow as the substitutions: the time was in the
    /// pivoting. The block's inverse replaces it in `lu`; the trailing rows
    /// keep their entries in the block's columns, and `inv_diag` their
    /// diagonal's reciprocals.
    fn invert3(mut m: Matrix<N>, perm: [usize; N]) -> Option<Self> {
        let block = m.fixed_view::<3, 3>(0, 0).into_owned().try_inverse()?;
        if !block.iter().all(|v| v.is_finite()) {
            return None;
        }
        let mut inv_diag = [0.0; N];
        for (i, d) in inv_diag.iter_mut().enumerate().skip(3) {
            let diagonal = m[(i, i)];
            if diagonal == 0.0 || !diagonal.is_finite() {
                return None;
            }
            *d = 1.0 / diagonal;
        }
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&block);
        Some(Lu { lu: m, perm, inv_diag, k: 3 })
    }

    /// Solves `m x = b`. Inlined: a stage's increment then stays in
    /// registers instead of being stored and read back at another width.
    #[inline(always)]
    fn solve(&self, b: &State<N>) -> Option<State<N>> {
        // Block sizes known at compile time unroll the loops.
        match self.k {
            1 => self.solve_block::<1>(b),
            2 => self.solve_block::<2>(b),
            3 => self.solve_inverse3(b),
            4 => self.solve_block::<4>(b),
            _ => self.solve_block::<N>(b),
        }
    }

    /// [`solve`](Self::solve) with the inverted leading block of
    /// [`invert3`](Self::invert3).
    #[inline(always)]
    fn solve_inverse3(&self, b: &State<N>) -> Option<State<N>> {
        let mut x = State::<N>::zeros();
        let l = &self.lu;
        for i in 0..3 {
            x[i] = l[(i, 0)] * b[0] + l[(i, 1)] * b[1] + l[(i, 2)] * b[2];
        }
        for i in 3..N {
            x[i] = (b[i] - l[(i, 0)] * x[0] - l[(i, 1)] * x[1] - l[(i, 2)] * x[2]) * self.inv_diag[i];
        }
        x.iter().all(|v| v.is_finite()).then_some(x)
    }

    /// [`solve`](Self::solve) with a leading block of `K` (= `self.k`, or
    /// `N`, since columns beyond `self.k` hold only the diagonal).
    #[inline(always)]
    fn solve_block<const K: usize>(&self, b: &State<N>) -> Option<State<N>> {
        let mut x = State::<N>::zeros();
        for i in 0..N {
            let mut s = b[self.perm[i]];
            for j in 0..i.min(K) {
                s -= self.lu[(i, j)] * x[j];
            }
            x[i] = s;
        }
        for i in (0..N).rev() {
            let mut s = x[i];
            for j in i + 1..K.max(i + 1) {
                s -= self.lu[(i, j)] * x[j];
            }
            x[i] = s * self.inv_diag[i];
        }
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// x^{1/4} by two square roots (a `powf` was a twentieth of a collision).
fn fourth_root(x: f64) -> f64 {
    x.sqrt().sqrt()
}

/// Adaptive Rosenbrock integrator with mixed relative/absolute error control.
///
/// The local error of component `i` is measured against
/// `rtol * max(|y_i|, |y_new_i|, scale_i)`: `scale_i` is a characteristic
/// magnitude of that component, below which errors are judged absolutely.
#[derive(Debug, Clone)]
pub struct Rosenbrock4<const N: usize> {
    /// Relative tolerance (dimensionless, e.g. 1e-8).
    pub rtol: f64,
    /// Characteristic magnitude of each component (same unit as the component).
    pub scale: State<N>,
    /// Smallest step size allowed before giving up (same unit as time).
    pub h_min: f64,
    /// Largest number of accepted steps before giving up.
    pub max_steps: usize,
    /// The step size to try next.
    pub h: f64,
    /// Work counters.
    pub stats: SolverStats,
    /// The step and error norm of the last accepted step (for the
    /// predictive step-size controller).
    last: Option<(f64, f64)>,
}

impl<const N: usize> Rosenbrock4<N> {
    /// A new integrator starting with step `h0`.
    pub fn new(rtol: f64, scale: State<N>, h0: f64) -> Self {
        Self { rtol, scale, h_min: h0 * 1e-12, max_steps: 200_000, h: h0, stats: SolverStats::default(), last: None }
    }

    /// [`try_step_ticked`](Self::try_step_ticked) in time itself.
    #[cfg(test)]
    fn try_step<S: StiffSystem<N>>(
        &mut self,
        sys: &S,
        y: &State<N>,
        at: &(State<N>, Matrix<N>),
        h: f64,
    ) -> Option<(State<N>, f64)> {
        self.try_step_ticked(sys, y, at, h, None)
    }

    /// One attempted step of size `h` from `y`, where `f(y)` and the
    /// Jacobian are `at` (shared by the retries of a rejected step). Returns
    /// the new state and the scaled error norm (≤ 1 means acceptable), or
    /// `None` if the system refused a stage state. With a `tick` the step is
    /// in changed time σ: the system is then dy/dσ = (dt/dσ)(σ) f(y),
    /// non-autonomous, and each stage adds h dᵢ times its σ-derivative.
    fn try_step_ticked<S: StiffSystem<N>>(
        &mut self,
        sys: &S,
        y: &State<N>,
        at: &(State<N>, Matrix<N>),
        h: f64,
        tick: Option<&Tick<N>>,
    ) -> Option<(State<N>, f64)> {
        let (f0, jac) = at;
        let mut w = match tick {
            Some(t) => -(jac * t.rate[0]),
            None => -jac,
        };
        for i in 0..N {
            w[(i, i)] += 1.0 / (GAM * h);
        }
        let lu = Lu::factor(w, S::DRIVING.min(N))?;
        let mut k = [State::<N>::zeros(); 6];
        k[0] = match tick {
            Some(t) => lu.solve(&(f0 * t.rate[0] + t.slope_f * (h * D[0])))?,
            None => lu.solve(f0)?,
        };
        let inv_h = 1.0 / h;
        for stage in 1..6 {
            let mut yi = *y;
            let mut coupling = State::<N>::zeros();
            for j in 0..stage {
                yi += A[stage - 1][j] * k[j];
                coupling += (C[stage - 1][j] * inv_h) * k[j];
            }
            let mut f = sys.rhs(&yi)?;
            self.stats.rhs_evals += 1;
            if let Some(t) = tick {
                f = f * t.rate[stage] + t.slope_f * (h * D[stage]);
            }
            k[stage] = lu.solve(&(f + coupling))?;
        }
        let mut y_new = *y + k[5];
        for j in 0..5 {
            y_new += A[4][j] * k[j];
        }
        let err = k[5];
        let mut sum = 0.0;
        for i in 0..N {
            let sc = self.rtol * y[i].abs().max(y_new[i].abs()).max(self.scale[i]);
            let r = err[i] / sc;
            sum += r * r;
        }
        let norm = (sum / N as f64).sqrt();
        if norm.is_finite() && y_new.iter().all(|v| v.is_finite()) { Some((y_new, norm)) } else { None }
    }

    /// Advances `y` by one accepted step no longer than `h_max`, adapting the
    /// step size. Returns the new state and the step taken. After an
    /// accepted step the next one follows Gustafsson's predictive controller
    /// (Hairer & Wanner, Sect. IV.8),
    /// h_{n+1} = 0.9 h_n (h_n/h_{n−1}) (err_{n−1}/err_n)^{1/4} err_n^{−1/4},
    /// with h_{n−1} and err_{n−1} those of the accepted step before, rejected
    /// attempts in between or not; after a rejection the step does not grow.
    /// The first accepted step takes h_{n+1} = 0.9 h_n err_n^{−1/4}.
    pub fn advance<S: StiffSystem<N>>(
        &mut self,
        sys: &S,
        y: &State<N>,
        h_max: f64,
    ) -> Result<(State<N>, f64), SolverError> {
        self.advance_in(sys, y, h_max, None)
    }

    /// [`advance`](Self::advance) in the changed time σ of `clock`, from
    /// the instant `at`: the step control acts on the error per step of σ
    /// (the step size kept between calls is in σ), `h_max` bounds the step
    /// in t (as dt/dσ at `at` times the step in σ), and the instant after
    /// the step is returned.
    pub fn advance_clocked<S: StiffSystem<N>>(
        &mut self,
        sys: &S,
        y: &State<N>,
        h_max: f64,
        clock: &LogClock,
        at: ClockInstant,
    ) -> Result<(State<N>, ClockInstant), SolverError> {
        let (y_new, h) = self.advance_in(sys, y, h_max / clock.rate(at), Some((clock, at)))?;
        Ok((y_new, clock.after(at, h)))
    }

    fn advance_in<S: StiffSystem<N>>(
        &mut self,
        sys: &S,
        y: &State<N>,
        h_max: f64,
        clock: Option<(&LogClock, ClockInstant)>,
    ) -> Result<(State<N>, f64), SolverError> {
        if self.stats.accepted >= self.max_steps {
            return Err(SolverError::TooManySteps(self.max_steps));
        }
        let mut h = self.h.min(h_max);
        let mut rejected = false;
        let at = sys.rhs_and_jacobian(y);
        self.stats.rhs_evals += 1;
        self.stats.jacobian_evals += 1;
        loop {
            if h < self.h_min {
                return Err(SolverError::StepSizeUnderflow { steps: self.stats.accepted, h });
            }
            let tick = match (clock, at.as_ref()) {
                (Some((c, at)), Some((f0, _))) => Some(c.tick(at, h, f0)),
                _ => None,
            };
            match at
                .as_ref()
                .and_then(|at| self.try_step_ticked(sys, y, at, h, tick.as_ref()))
                .filter(|(y_new, _)| sys.admissible(y, y_new))
            {
                Some((y_new, err)) if err <= 1.0 => {
                    self.stats.accepted += 1;
                    let growth = if rejected { 1.0 } else { 5.0 };
                    let err = err.max(1e-4);
                    let mut factor = 0.9 / fourth_root(err);
                    if let Some((h_last, err_last)) = self.last {
                        // Gustafsson's predictive controller: where the
                        // error per step stays put while the step grows (a
                        // power law in t), the step keeps growing. A
                        // rejection in between does not reset it: the last
                        // accepted step still says where the error goes
                        // (as in Hairer & Wanner's RADAU5).
                        factor *= (h / h_last) * fourth_root(err_last / err);
                    }
                    self.h = h * factor.clamp(0.2, growth);
                    self.last = Some((h, err));
                    return Ok((y_new, h));
                }
                Some((_, err)) => {
                    self.stats.rejected += 1;
                    rejected = true;
                    h *= (0.9 / err.cbrt()).clamp(0.1, 0.5);
                }
                None => {
                    self.stats.rejected += 1;
                    rejected = true;
                    h *= 0.25;
                }
            }
        }
    }

    /// Integrates from `y0` over a time span `t_end` and returns the final
    /// state (no events; used by tests and simple problems).
    pub fn integrate<S: StiffSystem<N>>(&mut self, sys: &S, y0: State<N>, t_end: f64) -> Result<State<N>, SolverError> {
        let mut t = 0.0;
        let mut y = y0;
        while t < t_end {
            let remaining = t_end - t;
            let (y_new, h) = self.advance(sys, &y, remaining)?;
            y = y_new;
            t = if h >= remaining { t_end } else { t + h };
        }
        Ok(y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Linear test system y' = M y with a stiff and an oscillatory mode.
    struct Linear(Matrix<3>);

    impl StiffSystem<3> for Linear {
        fn rhs(&self, y: &State<3>) -> Option<State<3>> {
            Some(self.0 * y)
        }
        fn jacobian(&self, _y: &State<3>) -> Option<Matrix<3>> {
            Some(self.0)
        }
    }

    fn system(stiff: f64) -> Linear {
        Linear(Matrix::<3>::new(-1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, -stiff))
    }

    fn exact_first(t: f64) -> f64 {
        (-t).exp()
    }

    /// The orders observed between errors at steps h, h/2 and h/4.
    fn orders([e1, e2, e3]: [f64; 3]) -> [f64; 2] {
        [(e1 / e2).log2(), (e2 / e3).log2()]
    }

    #[test]
    fn fixed_steps_converge_at_fourth_order() {
        // y' = -y, fixed steps: halving h must cut the error by ~2^4.
        let sys = system(0.0);
        let run = |n: usize| {
            let mut s = Rosenbrock4::<3>::new(1.0, State::<3>::from_element(1.0), 1.0 / n as f64);
            let mut y = State::<3>::new(1.0, 0.0, 0.0);
            for _ in 0..n {
                let (yn, err) =
                    s.try_step(&sys, &y, &sys.rhs_and_jacobian(&y).expect("in domain"), 1.0 / n as f64).expect("step");
                assert!(err.is_finite());
                y = yn;
            }
            (y[0] - exact_first(1.0)).abs()
        };
        let e1 = run(10);
        let e2 = run(20);
        let e3 = run(40);
        let [p1, p2] = orders([e1, e2, e3]);
        assert!(p1 > 3.7 && p2 > 3.7, "observed orders {p1:.2}, {p2:.2}");
    }

    /// Nonlinear pendulum-like system, which exercises the nonlinear order conditions.
    struct Nonlinear;

    impl StiffSystem<2> for Nonlinear {
        fn rhs(&self, y: &State<2>) -> Option<State<2>> {
            Some(State::<2>::new(y[1], -y[0].sin() - 0.5 * y[1] * y[1]))
        }
        fn jacobian(&self, y: &State<2>) -> Option<Matrix<2>> {
            Some(Matrix::<2>::new(0.0, 1.0, -y[0].cos(), -y[1]))
        }
    }

    #[test]
    fn nonlinear_problem_converges_at_fourth_order() {
        let run = |n: usize| {
            let mut s = Rosenbrock4::<2>::new(1.0, State::<2>::from_element(1.0), 1.0);
            let mut y = State::<2>::new(1.0, 0.3);
            let h = 2.0 / n as f64;
            for _ in 0..n {
                y = s.try_step(&Nonlinear, &y, &Nonlinear.rhs_and_jacobian(&y).expect("in domain"), h).expect("step").0;
            }
            y
        };
        let reference = run(20_000);
        let err = |n: usize| (run(n) - reference).norm();
        let (e1, e2, e3) = (err(20), err(40), err(80));
        let [p1, p2] = orders([e1, e2, e3]);
        assert!(p1 > 3.6 && p2 > 3.6, "observed orders {p1:.2}, {p2:.2}");
    }

    #[test]
    fn stiff_mode_is_damped_without_tiny_steps() {
        // A mode with rate 1e9 next to a mode of rate 1: L-stability lets the
        // integrator take steps set by the slow mode.
        let sys = system(1e9);
        let mut s = Rosenbrock4::<3>::new(1e-8, State::<3>::from_element(1e-3), 1e-6);
        let y = s.integrate(&sys, State::<3>::new(1.0, 1.0, 1.0), 5.0).expect("integrates");
        assert!((y[0] - exact_first(5.0)).abs() < 1e-7, "{}", y[0]);
        assert!(s.stats.accepted < 2_000, "{:?}", s.stats);
    }

    #[test]
    fn infinitely_stiff_modes_are_annihilated_in_one_step() {
        // L-stability with stiff accuracy: R(∞) = 0.
        let sys = Linear(Matrix::<3>::new(-1e15, 0.0, 0.0, 0.0, -1e12, 0.0, 0.0, 0.0, -1e9));
        let mut s = Rosenbrock4::<3>::new(1.0, State::<3>::from_element(1.0), 1.0);
        let y0 = State::<3>::new(1.0, 1.0, 1.0);
        let (y, _) = s.try_step(&sys, &y0, &sys.rhs_and_jacobian(&y0).expect("in domain"), 1.0).expect("step");
        assert!(y.iter().all(|v| v.abs() < 1e-6), "{y:?}");
    }

    #[test]
    fn refused_states_shrink_the_step() {
        struct Walled;
        impl StiffSystem<1> for Walled {
            fn rhs(&self, y: &State<1>) -> Option<State<1>> {
                (y[0] < 1.0).then(|| State::<1>::new(1.0 - y[0]))
            }
            fn jacobian(&self, y: &State<1>) -> Option<Matrix<1>> {
                (y[0] < 1.0).then(|| Matrix::<1>::new(-1.0))
            }
        }
        let mut s = Rosenbrock4::<1>::new(1e-9, State::<1>::new(1.0), 10.0);
        let y = s.integrate(&Walled, State::<1>::new(0.0), 3.0).expect("integrates");
        assert!((y[0] - (1.0 - (-3.0f64).exp())).abs() < 1e-7);
    }

    #[test]
    fn the_clock_is_logarithmic_then_linear_and_consistent() {
        let c = LogClock::new(1e-9, 0.3);
        let at = |sigma: f64| c.after(c.start(), sigma);
        assert!(c.time(c.start()).abs() < 1e-24);
        assert!((c.rate(c.start()) - 1e-9).abs() < 1e-24);
        // Early on, t + t₀ = t₀e^σ; late, t grows by t₁ per unit of σ.
        for sigma in [1e-3_f64, 0.1, 5.0] {
            let t = 1e-9 * sigma.exp_m1();
            assert!((c.time(at(sigma)) - t).abs() < 1e-6 * t, "σ = {sigma}");
        }
        assert!((c.rate(at(60.0)) - 0.3).abs() < 1e-15);
        // dt/dσ is the derivative of t(σ), across the change of formula
        // (b = 10⁻²⁰⁰ near σ = 481) and beyond b's underflow (σ ≈ 765).
        let mut far = c.start();
        for _ in 0..100 {
            far = c.after(far, 10.0);
        }
        assert!((c.time(far) - c.time(at(1000.0))).abs() < 1e-9 * c.time(far));
        for sigma in [0.5, 10.0, 20.0, 400.0, 480.0, 482.0, 900.0] {
            let h = 1e-5;
            let numeric = (c.time(at(sigma + h)) - c.time(at(sigma - h))) / (2.0 * h);
            let rate = c.rate(at(sigma));
            assert!((numeric - rate).abs() < 1e-6 * rate, "σ = {sigma}: {numeric} vs {rate}");
            let (rates, slope) = c.stage_rates(at(sigma), 0.7);
            assert_eq!(rates[0], rate);
            for (r, ci) in rates.iter().zip([0.0, 0.386, 0.21, 0.63, 1.0, 1.0]) {
                assert!((r - c.rate(at(sigma + ci * 0.7))).abs() <= 1e-14 * r, "σ = {sigma}, c = {ci}");
            }
            let numeric = (c.rate(at(sigma + h)) - c.rate(at(sigma - h))) / (2.0 * h);
            assert!((numeric - slope).abs() < 1e-6 * rate, "σ = {sigma}: {numeric} vs {slope}");
        }
    }

    #[test]
    fn steps_in_changed_time_converge_at_fourth_order() {
        // y' = −y in the changed time σ: the stepped system is
        // non-autonomous, which exercises the stage times and the
        // coefficients of ∂f/∂σ.
        let sys = system(0.0);
        let clock = LogClock::new(0.05, 0.3);
        let sigma_end = 4.0;
        let t_end = clock.time(clock.after(clock.start(), sigma_end));
        let run = |n: usize| {
            let h = sigma_end / n as f64;
            let mut s = Rosenbrock4::<3>::new(1.0, State::<3>::from_element(1.0), h);
            let mut y = State::<3>::new(1.0, 0.0, 0.0);
            let mut at = clock.start();
            for _ in 0..n {
                let f = sys.rhs_and_jacobian(&y).expect("in domain");
                y = s.try_step_ticked(&sys, &y, &f, h, Some(&clock.tick(at, h, &f.0))).expect("step").0;
                at = clock.after(at, h);
            }
            (y[0] - exact_first(t_end)).abs()
        };
        let (e1, e2, e3) = (run(10), run(20), run(40));
        let [p1, p2] = orders([e1, e2, e3]);
        assert!(p1 > 3.6 && p2 > 3.6, "observed orders {p1:.2}, {p2:.2} ({e1:.2e}, {e2:.2e}, {e3:.2e})");
    }

    #[test]
    fn a_clocked_run_reaches_the_solution_in_time() {
        // The adaptive path: y' = −y to t = 3 in changed time, from
        // t₀ = 10⁻⁹, with the bound on the step in t.
        let sys = system(0.0);
        let clock = LogClock::new(1e-9, 0.3);
        let mut s = Rosenbrock4::<3>::new(1e-9, State::<3>::from_element(1.0), 0.1);
        let (mut y, mut at) = (State::<3>::new(1.0, 0.0, 0.0), clock.start());
        while clock.time(at) < 3.0 {
            (y, at) = s.advance_clocked(&sys, &y, 0.5, &clock, at).expect("steps");
        }
        let t = clock.time(at);
        assert!((y[0] - exact_first(t)).abs() < 1e-8, "{} vs {}", y[0], exact_first(t));
        assert!(s.stats.accepted < 1000 && s.stats.rejected < 10, "{:?}", s.stats);
    }

    /// A damped oscillator with its dissipated energy as a quadrature.
    struct Damped<const D: usize>;

    impl<const D: usize> StiffSystem<3> for Damped<D> {
        fn rhs(&self, y: &State<3>) -> Option<State<3>> {
            Some(State::<3>::new(
                y[1],
                -y[0] - 50.0 * y[1] * (1.0 + y[0] * y[0]),
                50.0 * y[1] * y[1] * (1.0 + y[0] * y[0]),
            ))
        }
        fn jacobian(&self, y: &State<3>) -> Option<Matrix<3>> {
            let c = 1.0 + y[0] * y[0];
            Some(Matrix::<3>::new(
                0.0,
                1.0,
                0.0,
                -1.0 - 100.0 * y[0] * y[1],
                -50.0 * c,
                0.0,
                100.0 * y[0] * y[1] * y[1],
                100.0 * y[1] * c,
                0.0,
            ))
        }
        const DRIVING: usize = D;
    }

    /// Matrices shaped like a step's I/(γh) − J with three driving
    /// components and two quadratures, from well scaled to a stiff entry
    /// 10⁶ times the others, and one that needs pivoting (a zero corner).
    fn step_matrices() -> Vec<Matrix<5>> {
        let mut out = Vec::new();
        let mut x = 0.3_f64;
        let mut next = || {
            // A fixed pseudo-random sequence in [−1, 1).
            x = (x * 9301.0 + 0.4927).fract();
            2.0 * x - 1.0
        };
        for stiff in [1.0, 1e3, 1e6] {
            for _ in 0..20 {
                let mut m = Matrix::<5>::zeros();
                for i in 0..5 {
                    for j in 0..3 {
                        m[(i, j)] = next();
                    }
                    m[(i, i)] += 4.0;
                }
                m[(2, 2)] += stiff;
                out.push(m);
            }
        }
        let mut corner = out[0];
        corner[(0, 0)] = 0.0;
        out.push(corner);
        out
    }

    #[test]
    fn the_inverted_leading_block_solves_like_partial_pivoting() {
        for m in step_matrices() {
            let lu = Lu::factor(m, 3).expect("regular");
            let b = State::<5>::new(1.0, -2.0, 0.5, 3.0, -1.5);
            let x = lu.solve(&b).expect("finite");
            let reference = m.lu().solve(&b).expect("regular");
            assert!((x - reference).norm() <= 1e-13 * reference.norm(), "{x:?} vs {reference:?}");
            assert!((m * x - b).norm() <= 1e-13 * b.norm() * m.norm(), "residual of {m:?}");
        }
        // A singular block is refused, as is a zero quadrature diagonal.
        let mut singular = step_matrices()[0];
        for j in 0..3 {
            singular[(2, j)] = 0.0;
        }
        assert!(Lu::factor(singular, 3).is_none());
        singular[(2, 2)] = f64::NAN;
        assert!(Lu::factor(singular, 3).is_none());
        let mut zero = step_matrices()[1];
        zero[(4, 4)] = 0.0;
        assert!(Lu::factor(zero, 3).is_none());
    }

    #[test]
    fn the_block_factorisation_of_quadratures_solves_the_same_steps() {
        let y0 = State::<3>::new(1.0, 3.0, 0.0);
        let run = |block: bool| {
            let mut s = Rosenbrock4::<3>::new(1e-8, State::<3>::from_element(1.0), 1e-3);
            let y = if block { s.integrate(&Damped::<2>, y0, 10.0) } else { s.integrate(&Damped::<3>, y0, 10.0) };
            (y.expect("integrates"), s.stats)
        };
        let ((full, full_stats), (block, block_stats)) = (run(false), run(true));
        assert!((full - block).norm() <= 1e-12 * full.norm(), "{full:?} vs {block:?}");
        assert_eq!(full_stats.accepted, block_stats.accepted);
        // Energy: what the oscillator lost is what the quadrature gained.
        let energy = |y: &State<3>| 0.5 * (y[0] * y[0] + y[1] * y[1]) + y[2];
        assert!((energy(&block) - energy(&y0)).abs() < 1e-6, "{}", energy(&block));
    }
}
