//! Head-on collision of two adhesive viscoelastic spheres (thesis Sects. 2.2–2.3,
//! App. 2.A–2.C).
//!
//! The state is the mutual approach δ, its rate δ̇ and the contact radius a,
//! plus the two dissipated energies U_CD (crack) and U_BD (bulk) as
//! quadratures. δ obeys m* δ̈ = −(F_E + F_D) (2.20) with the elastic force
//! (2.2) and the bulk dissipative force F_D = 2AE*aδ̇ (2.19), A = T_vis/ν²;
//! a follows Greenwood's crack law (2.14)–(2.17). The system is stiff (the
//! crack relaxes on a time scale ∝ T_vis, the bulk damping on one ∝ 1/T_vis),
//! so it is integrated with an L-stable Rosenbrock method in scaled variables,
//! stepping in logarithmic time while the neck heals
//! ([`LogClock`](crate::solver::LogClock)). Once the parted spheres' neck
//! collapses on its own, the rest of the collapse is integrated in ln β
//! with an explicit Runge–Kutta pair instead: a finite-time singularity in
//! t, it is smooth in β.
//!
//! Contact starts at δ = 0, δ̇ = v with a from (2.38) at G_eff = 1.01kγ
//! (App. 2.B; the time offset of (2.39) is negligible and not added). Contact
//! ends when β reaches (1 − 10⁻³)/k, where the crack opens without bound,
//! once the spheres no longer overlap (δ ≤ 0): while δ > 0, a² ≥ δR, and β
//! near 1/k only says that the crack opens as fast as the parting spheres
//! require (a slow crack on a large sphere, T_vis ≥ 10⁻⁷ s at 2 cm). The
//! collision sticks when separation has become impossible: the mechanical
//! energy U_K + U_E + U_S, which only decreases, is negative (separated spheres
//! have U_E = U_S = 0 and U_K ≥ 0), or the spheres turn back towards each other
//! while still in contact (they failed to separate with more energy than they
//! will ever have again).

use super::PhysicsError;
use super::contact::Pair;
use super::crack::{CrackLaw, ResolvedLaw};
use super::plasticity;
use crate::solver::{LogClock, Matrix, Rosenbrock4, State, StiffSystem};
use std::cell::Cell;
use std::f64::consts::PI;

/// Everything that defines a colliding pair apart from the impact speed. SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setup {
    /// Reduced elastic and adhesive properties.
    pub pair: Pair,
    /// Viscous relaxation time T_vis, s.
    pub t_vis: f64,
    /// Poisson ratio entering the bulk dissipation constant A = T_vis/ν².
    pub poisson_ratio: f64,
    /// Range of the surface forces z₀ (σ₀ = γ/z₀), m.
    pub z0: f64,
    /// Crack-speed law.
    pub crack: CrackLaw,
    /// Yield strength Y, Pa; `None` disables plasticity (e_P = 1).
    pub yield_strength: Option<f64>,
}

impl Setup {
    /// The reference set of the thesis (Figs. 2.2–2.4): two water-ice spheres
    /// of radius 2 µm, γ = 0.74 J/m², z₀ = 0.3 nm, k = 0.02, T_vis = 10⁻¹¹ s,
    /// with the full crack relation (the thesis's law is [`Setup::with_crack`]).
    pub fn reference_ice() -> Setup {
        let m = super::sphere_mass(1000.0, 2e-6);
        Setup {
            pair: Pair {
                modulus: 7e9 / (2.0 * (1.0 - 0.25 * 0.25)),
                radius: 1e-6,
                mass: m / 2.0,
                surface_energy: 0.74,
            },
            t_vis: 1e-11,
            poisson_ratio: 0.25,
            z0: 3e-10,
            crack: CrackLaw::full(0.02),
            yield_strength: None,
        }
    }

    /// This setup with another crack law.
    pub fn with_crack(self, crack: CrackLaw) -> Setup {
        Setup { crack, ..self }
    }

    /// Bulk dissipation constant A = T_vis/ν² (2.19), s.
    pub fn dissipation_time(&self) -> f64 {
        self.t_vis / self.poisson_ratio.powi(2)
    }

    /// Prefactor C of the crack speed ȧ = C g(β): C = E*γ/(σ₀²T_vis) = E*z₀²/(γT_vis), m/s.
    pub fn crack_speed_scale(&self) -> f64 {
        self.pair.modulus * self.z0 * self.z0 / (self.pair.surface_energy * self.t_vis)
    }

    /// Initial contact radius (2.38) at G_eff = 1.01kγ, m.
    pub fn initial_radius(&self) -> f64 {
        let p = &self.pair;
        (2.0 * PI * p.radius.powi(2) * 1.01 * self.crack.k * p.surface_energy / p.modulus).cbrt()
    }

    /// Yield velocity v_y (2.28), m/s (infinite without plasticity).
    pub fn yield_velocity(&self) -> f64 {
        self.yield_strength.map_or(f64::INFINITY, |y| plasticity::yield_velocity(&self.pair, y))
    }

    /// Checks that every quantity is finite and in its physical domain.
    pub fn validate(&self) -> Result<(), PhysicsError> {
        super::positive("E*", self.pair.modulus)?;
        super::positive("R", self.pair.radius)?;
        super::positive("m*", self.pair.mass)?;
        super::positive("gamma", self.pair.surface_energy)?;
        super::positive("T_vis", self.t_vis)?;
        super::positive("nu", self.poisson_ratio)?;
        super::positive("z0", self.z0)?;
        if !(self.crack.k > 0.0 && self.crack.k < 0.5) {
            return Err(PhysicsError::InvalidParameter {
                name: "k",
                value: self.crack.k,
                reason: "must lie in (0, 0.5)",
            });
        }
        if let Some(y) = self.yield_strength {
            super::positive("Y", y)?;
        }
        Ok(())
    }
}

/// Integration options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Relative tolerance of the integrator (dimensionless). The default 1e-6
    /// keeps |Δe| below 1e-5 over the documented ranges (see the benchmark).
    pub rtol: f64,
    /// Record the trajectory (finer steps, samples every step).
    pub record: bool,
    /// After sticking is certain, keep integrating for this many Hertz times
    /// (to show the spiral into the JKR equilibrium); 0 stops at once.
    pub follow_after_stick: f64,
    /// Give up (and call the collision sticking) after this many Hertz times.
    pub max_time: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options { rtol: 1e-6, record: false, follow_after_stick: 0.0, max_time: 2000.0 }
    }
}

/// How a collision ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Outcome {
    /// The spheres separated.
    Bounce,
    /// The spheres stayed in contact.
    Stick,
}

/// One recorded instant of a collision. SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time since first contact, s.
    pub t: f64,
    /// Mutual approach δ, m.
    pub delta: f64,
    /// Approach rate δ̇, m/s (positive while approaching).
    pub velocity: f64,
    /// Contact radius a, m.
    pub radius: f64,
    /// Elastic force F_E, N (positive = repulsive).
    pub elastic_force: f64,
    /// G_eff/γ.
    pub beta: f64,
    /// Kinetic energy U_K, J.
    pub kinetic: f64,
    /// Elastic energy U_E, J.
    pub elastic: f64,
    /// Surface energy U_S, J.
    pub surface: f64,
    /// Energy dissipated at the crack U_CD, J.
    pub crack_dissipated: f64,
    /// Energy dissipated in the bulk U_BD, J.
    pub bulk_dissipated: f64,
}

impl Sample {
    /// Sum of all energies, J (conserved).
    pub fn total_energy(&self) -> f64 {
        self.kinetic + self.elastic + self.surface + self.crack_dissipated + self.bulk_dissipated
    }
}

/// The result of one collision.
#[derive(Debug, Clone, PartialEq)]
pub struct Collision {
    /// Bounce or stick.
    pub outcome: Outcome,
    /// Whether sticking was proven (false if the time limit ended the run).
    pub resolved: bool,
    /// Impact speed, m/s.
    pub velocity: f64,
    /// Adhesive–viscoelastic restitution e_A (2.23); 0 for sticking.
    pub e_adhesive: f64,
    /// Contact time t_c, s (for sticking: when sticking became certain).
    pub contact_time: f64,
    /// Hertz time t_H (2.22), s.
    pub hertz_time: f64,
    /// Initial kinetic energy ½m*v², J.
    pub initial_kinetic: f64,
    /// State at the end of contact (or of the run).
    pub last: Sample,
    /// Largest |ΣU(t) − ΣU(0)| / U_K(0) seen during the run.
    pub energy_error: f64,
    /// Recorded trajectory (empty unless `Options::record`).
    pub samples: Vec<Sample>,
    /// Integrator work.
    pub stats: crate::solver::SolverStats,
}

impl Collision {
    /// Fraction of the initial kinetic energy dissipated at the crack tip.
    pub fn crack_fraction(&self) -> f64 {
        self.last.crack_dissipated / self.initial_kinetic
    }
    /// Fraction of the initial kinetic energy dissipated in the bulk.
    pub fn bulk_fraction(&self) -> f64 {
        self.last.bulk_dissipated / self.initial_kinetic
    }
}

/// The contact equations in scaled variables
/// y = (δ/ℓ, δ̇τ/ℓ, ln u, U_CD/U₀, U_BD/U₀) with u = (a² − δR)/ℓ² and
/// U₀ = m*ℓ²/τ².
///
/// The crack law depends on a and δ only through β ∝ u²/a, and u is a small
/// difference of a² and δR when the contact is nearly Hertzian. Integrating
/// ln u instead of a makes the error control act on u's relative error (so
/// β is resolved however thin the quasi-static manifold) and keeps u > 0,
/// the physical branch with a tensile edge (as in JKR theory).
struct ContactOde {
    c1: f64,
    c2: f64,
    c3: f64,
    cb: f64,
    rho: f64,
    cg: f64,
    cs: f64,
    crack: ResolvedLaw,
    /// The last β computed, with the (δ/ℓ, ln u) it was computed at: a step
    /// asks for β at its end up to three times (whether the step may be
    /// accepted, what it ends, and as the start of the next).
    beta_memo: Cell<[f64; 3]>,
}

/// Derived quantities at one state.
struct Point {
    /// Scaled contact radius a/ℓ.
    s: f64,
    /// Scaled crack speed ȧτ/ℓ.
    sdot: f64,
}

impl ContactOde {
    /// Scaled contact radius from (δ/ℓ, ln u); `None` once the neck has collapsed.
    fn radius(&self, x: f64, q: f64) -> Option<f64> {
        let a2 = q.exp() + self.rho * x;
        (a2 > 0.0).then(|| a2.sqrt())
    }

    fn point(&self, y: &State<5>) -> Option<Point> {
        let (_, s, _, g, _) = self.parts(y)?;
        Some(Point { s, sdot: self.cg * g })
    }

    fn beta(&self, y: &State<5>) -> f64 {
        let [x, q, memo] = self.beta_memo.get();
        if x == y[0] && q == y[2] {
            return memo;
        }
        let u = y[2].exp();
        let a2 = u + self.rho * y[0];
        let beta = if a2 > 0.0 { self.cb * u * u / a2.sqrt() } else { f64::INFINITY };
        self.beta_memo.set([y[0], y[2], beta]);
        beta
    }

    fn elastic_energy(&self, x: f64, s: f64) -> f64 {
        let q = 1.0 / self.rho;
        0.5 * self.c1 * (x * x * s - 2.0 / 3.0 * q * x * s.powi(3) + q * q / 5.0 * s.powi(5))
    }

    fn surface_energy(&self, s: f64) -> f64 {
        -0.5 * self.cs * s * s
    }

    /// The end of a collapse that outruns the spheres: the neck shrinks at
    /// the present δ and δ̇ until β reaches `beta_end`, and the elastic and
    /// surface energy it releases on the way is dissipated at the crack
    /// (energy is conserved, and the kinetic energy stays put). `y` itself
    /// if the spheres still overlap or β is there already.
    fn collapsed(&self, y: &State<5>, beta_end: f64) -> State<5> {
        let x = y[0];
        let (Some(s), true) = (self.radius(x, y[2]), x < 0.0) else { return *y };
        let beta_of = |s: f64| {
            let u = s * s - self.rho * x;
            self.cb * u * u / s
        };
        // Below s² = ρ|δ|/3, β falls as s grows: the collapse runs down
        // this branch to β → ∞ at s → 0.
        let top = s.min((-self.rho * x / 3.0).sqrt());
        let (f_top, lo) = (beta_of(top) - beta_end, top * 1e-12);
        if f_top >= 0.0 {
            return *y;
        }
        let root = crate::solver::illinois(
            |s| beta_of(s) - beta_end,
            [lo, top],
            [beta_of(lo) - beta_end, f_top],
            1e-13 * top,
            200,
        );
        let s_end = root.x();
        let stored = |s: f64| self.elastic_energy(x, s) + self.surface_energy(s);
        let mut end = *y;
        end[2] = (s_end * s_end - self.rho * x).ln();
        end[3] += stored(s) - stored(s_end);
        end
    }

    /// The rest of a collapse from `y` (δ < 0, the neck shrinking), to where
    /// β reaches `beta_end`, integrated in λ = ln β rather than in time: the
    /// neck's collapse is a finite-time singularity in t (|ȧ| grows without
    /// bound), but smooth in β, and the crack speed is then a function of
    /// the independent variable alone. On the branch 3a² < −δR (where β
    /// grows as a shrinks at fixed δ, and as δ falls at fixed a) β only
    /// grows: dλ/dσ = 4s²/u − 1 − (2ρ/u)(w s/ṡ) < 0 with σ = ln s. The state
    /// z = (σ, t, δ/ℓ, δ̇τ/ℓ, U_CD, U_BD) follows dz/dλ = (dz/dσ)/(dλ/dσ),
    /// with dt/dσ = s/ṡ. Returns the time the rest takes, the state at its
    /// end and the work, or `None` if the neck leaves that branch or the
    /// spheres turn back on the way. `accepted` gets every step's time and
    /// state.
    fn collapse(
        &self,
        y: &State<5>,
        beta_end: f64,
        rtol: f64,
        scale: &State<5>,
        mut accepted: impl FnMut(f64, &State<5>),
    ) -> Option<(f64, State<5>, crate::solver::SolverStats)> {
        let rate = |lambda: f64, z: &State<6>| -> Option<State<6>> {
            let (s, x, w) = (z[0].exp(), z[2], z[3]);
            let u = s * s - self.rho * x;
            let beta = lambda.exp();
            if !(u > 0.0 && w < 0.0 && x < 0.0) {
                return None;
            }
            let (g, _) = self.crack.speed(beta)?;
            let sdot = self.cg * g;
            let dt = s / sdot;
            let dlambda = 4.0 * s * s / u - 1.0 - 2.0 * self.rho / u * w * dt;
            if !(sdot < 0.0 && dlambda < 0.0) {
                return None;
            }
            let inv = 1.0 / dlambda;
            let dt = dt * inv;
            Some(State::<6>::from([
                inv,
                dt,
                w * dt,
                -(self.c1 * s * x - self.c2 * s * s * s + self.c3 * s * w) * dt,
                self.cs * s * s * (1.0 - beta) * inv,
                self.c3 * s * w * w * dt,
            ]))
        };
        let state = |z: &State<6>| {
            let s = z[0].exp();
            State::<5>::new(z[2], z[3], (s * s - self.rho * z[2]).ln(), z[4], z[5])
        };
        let s = self.radius(y[0], y[2])?;
        let z = State::<6>::from([s.ln(), 0.0, y[0], y[1], y[3], y[4]]);
        let z_scale = State::<6>::from([1.0, 1.0, scale[0], scale[1], scale[3], scale[4]]);
        let (from, to) = (self.beta(y).ln(), beta_end.ln());
        let (z_end, work) =
            crate::solver::dormand_prince(rate, (from, z), to, 0.125 * (to - from), rtol, &z_scale, |_, z| {
                accepted(z[1], &state(z))
            })
            .ok()?;
        Some((z_end[1], state(&z_end), work))
    }

    /// Whether the neck is on the branch where its collapse runs away (see
    /// [`collapse`](Self::collapse)), with a margin: 3a² < 0.9(−δR), so
    /// that dλ/dσ ≤ −1/13 however slowly the spheres part.
    fn runaway(&self, y: &State<5>) -> bool {
        self.radius(y[0], y[2]).is_some_and(|s| 3.0 * s * s < -0.9 * self.rho * y[0])
    }

    fn mechanical_energy(&self, y: &State<5>) -> f64 {
        let s = self.radius(y[0], y[2]).unwrap_or(0.0);
        0.5 * y[1] * y[1] + self.elastic_energy(y[0], s) + self.surface_energy(s)
    }
}

impl ContactOde {
    /// u, s, β, g(β) and dg/dβ at a state; `None` outside the domain.
    fn parts(&self, y: &State<5>) -> Option<(f64, f64, f64, f64, f64)> {
        let u = y[2].exp();
        let a2 = u + self.rho * y[0];
        if a2 <= 0.0 {
            return None;
        }
        let s = a2.sqrt();
        let p = self.cb * u * u;
        let beta = p / s;
        let (g, dg) = self.crack.speed_of_ratio(p, s, beta)?;
        Some((u, s, beta, g, dg))
    }

    /// f(y) from its parts.
    fn rhs_from(&self, y: &State<5>, u: f64, s: f64, beta: f64, sdot: f64) -> State<5> {
        let (x, w) = (y[0], y[1]);
        State::<5>::new(
            w,
            -(self.c1 * s * x - self.c2 * s.powi(3) + self.c3 * s * w),
            (2.0 * s * sdot - self.rho * w) * (1.0 / u),
            self.cs * s * (1.0 - beta) * sdot,
            self.c3 * s * w * w,
        )
    }

    /// The Jacobian from the parts of f(y).
    fn jacobian_from(&self, y: &State<5>, (u, s, beta, g, dg): (f64, f64, f64, f64, f64)) -> Matrix<5> {
        let (x, w) = (y[0], y[1]);
        let sdot = self.cg * g;
        let f2 = (2.0 * s * sdot - self.rho * w) / u;
        // Partial derivatives with respect to (x, q) of s, β and ṡ.
        let s_x = self.rho / (2.0 * s);
        let s_q = u / (2.0 * s);
        let b_x = -beta * s_x / s;
        let b_q = beta * (2.0 - s_q / s);
        let sd_x = self.cg * dg * b_x;
        let sd_q = self.cg * dg * b_q;
        let force_s = self.c1 * x - 3.0 * self.c2 * s * s + self.c3 * w;
        let mut j = Matrix::<5>::zeros();
        j[(0, 1)] = 1.0;
        j[(1, 0)] = -(self.c1 * s + force_s * s_x);
        j[(1, 1)] = -self.c3 * s;
        j[(1, 2)] = -force_s * s_q;
        j[(2, 0)] = 2.0 * (s_x * sdot + s * sd_x) / u;
        j[(2, 1)] = -self.rho / u;
        j[(2, 2)] = 2.0 * (s_q * sdot + s * sd_q) / u - f2;
        j[(3, 0)] = self.cs * (s_x * (1.0 - beta) * sdot - s * b_x * sdot + s * (1.0 - beta) * sd_x);
        j[(3, 2)] = self.cs * (s_q * (1.0 - beta) * sdot - s * b_q * sdot + s * (1.0 - beta) * sd_q);
        j[(4, 0)] = self.c3 * w * w * s_x;
        j[(4, 1)] = 2.0 * self.c3 * s * w;
        j[(4, 2)] = self.c3 * w * w * s_q;
        j
    }
}

impl StiffSystem<5> for ContactOde {
    fn rhs(&self, y: &State<5>) -> Option<State<5>> {
        let (u, s, beta, g, _) = self.parts(y)?;
        Some(self.rhs_from(y, u, s, beta, self.cg * g))
    }

    fn jacobian(&self, y: &State<5>) -> Option<Matrix<5>> {
        Some(self.jacobian_from(y, self.parts(y)?))
    }

    fn rhs_and_jacobian(&self, y: &State<5>) -> Option<(State<5>, Matrix<5>)> {
        let parts = self.parts(y)?;
        let (u, s, beta, g, _) = parts;
        Some((self.rhs_from(y, u, s, beta, self.cg * g), self.jacobian_from(y, parts)))
    }

    /// The dissipated energies U_CD and U_BD are running integrals.
    const DRIVING: usize = 3;

    /// β may at most double or halve in one step, so that a step cannot jump
    /// across the thin quasi-static manifold unseen by the error estimate,
    /// and must stay inside the crack law's domain k < β < 1/k: the crack
    /// speed diverges at its ends, so the true solution never leaves it, and
    /// a step that does is too long (the next step could not start there).
    fn admissible(&self, from: &State<5>, to: &State<5>) -> bool {
        let (b0, b1) = (self.beta(from), self.beta(to));
        b1 <= 2.0 * b0 && b1 >= 0.5 * b0 && self.crack.defined_at(b1)
    }
}

/// Where the integrator's clock turns from logarithmic time to time, in
/// Hertz times (see [`LogClock`]). Over reference ice at 3–25 m/s and the
/// hard cases T_vis = 10⁻¹⁴ and 10⁻¹⁵ s at 1.5–20 m/s, 0.3 t_H took the
/// fewest steps for a given worst error among 0.003–3 t_H.
const CLOCK_TIME: f64 = 0.3;

/// The tolerance of a collapse's integration in β (see
/// `ContactOde::collapse`), relative to the run's. The explicit pair
/// estimates its error less generously than the Rosenbrock method: at the
/// run's own tolerance, reference ice at rtol 9.1 × 10⁻⁶ ended 1.5 × 10⁻⁶
/// off in e.
const COLLAPSE_TOLERANCE: f64 = 0.1;

/// Simulates one head-on collision at impact speed `velocity` (m/s).
pub fn collide(setup: &Setup, velocity: f64, opts: &Options) -> Result<Collision, PhysicsError> {
    setup.validate()?;
    super::positive("v", velocity)?;
    super::positive("rtol", opts.rtol)?;
    let p = setup.pair;
    let t_h = p.hertz_time(velocity);
    let a_eq = p.jkr_equilibrium_radius();
    let delta_m = p.hertz_max_approach(velocity);
    // Scales: length ℓ of the largest contact radius expected, time τ = t_H.
    let ell = a_eq.max(p.hertz_radius(delta_m));
    let tau = t_h;
    let m = p.mass;
    let e = p.modulus;
    let a_diss = setup.dissipation_time();
    let ode = ContactOde {
        c1: 2.0 * e * ell * tau * tau / m,
        c2: 2.0 * e * ell * ell * tau * tau / (3.0 * p.radius * m),
        c3: 2.0 * a_diss * e * ell * tau / m,
        cb: e * ell.powi(3) / (2.0 * PI * p.radius.powi(2) * p.surface_energy),
        rho: p.radius / ell,
        cg: setup.crack_speed_scale() * tau / ell,
        cs: 2.0 * PI * p.surface_energy * tau * tau / m,
        crack: setup.crack.resolve(),
        beta_memo: Cell::new([f64::NAN; 3]),
    };
    let u_unit = m * ell * ell / (tau * tau);
    let v_scaled = velocity * tau / ell;
    let s0 = setup.initial_radius() / ell;
    let y0 = State::<5>::new(0.0, v_scaled, (s0 * s0).ln(), 0.0, 0.0);
    let ke0 = 0.5 * v_scaled * v_scaled;
    let total0 = ode.mechanical_energy(&y0);

    let delta_char = delta_m.max(a_eq * a_eq / p.radius) / ell;
    let scale = State::<5>::new(delta_char, v_scaled, 1.0, ke0, ke0);
    let sdot0 = ode.point(&y0).map_or(1.0, |pt| pt.sdot);
    let h0 = (1e-3 * s0 / sdot0.abs()).min(1e-3);
    // The crack starts far from equilibrium (β = 1.01k), and the neck heals
    // as a power law in t over many decades: the steps follow it in
    // logarithmic time from h0 to a few tenths of t_H, in time beyond.
    let clock = LogClock::new(h0, CLOCK_TIME);
    let mut solver = Rosenbrock4::new(opts.rtol, scale, 0.1);
    solver.h_min = h0 * 1e-9 / CLOCK_TIME;
    solver.max_steps = 1_000_000;
    let h_max = if opts.record { 1.0 / 200.0 } else { 0.05 };

    let beta_end = (1.0 - 1e-3) / setup.crack.k;
    let to_sample = |t: f64, y: &State<5>| -> Sample {
        let s = ode.radius(y[0], y[2]).unwrap_or(0.0);
        Sample {
            t: t * tau,
            delta: y[0] * ell,
            velocity: y[1] * ell / tau,
            radius: s * ell,
            elastic_force: p.elastic_force(s * ell, y[0] * ell),
            beta: ode.beta(y),
            kinetic: 0.5 * y[1] * y[1] * u_unit,
            elastic: ode.elastic_energy(y[0], s) * u_unit,
            surface: ode.surface_energy(s) * u_unit,
            crack_dissipated: y[3] * u_unit,
            bulk_dissipated: y[4] * u_unit,
        }
    };

    let mut samples = Vec::new();
    if opts.record {
        samples.push(to_sample(0.0, &y0));
    }
    let mut t = 0.0;
    let mut at = clock.start();
    let mut y = y0;
    let mut energy_error: f64 = 0.0;
    let mut stuck_at: Option<(f64, bool)> = if ode.mechanical_energy(&y0) < 0.0 { Some((0.0, true)) } else { None };
    let mut bounce: Option<(f64, State<5>)> = None;

    while stuck_at.is_none() || opts.follow_after_stick > 0.0 {
        if let Some((ts, _)) = stuck_at
            && t >= ts + opts.follow_after_stick
        {
            break;
        }
        let (y_new, at_new) = solver.advance_clocked(&ode, &y, h_max, &clock, at)?;
        at = at_new;
        let t_new = clock.time(at);
        let h = t_new - t;
        let beta_new = ode.beta(&y_new);
        // The spheres have parted (δ ≤ 0) at the end of this step: β near 1/k
        // ends the contact. Before that, the crack can only open as fast as
        // they part, and β creeps along below 1/k.
        let parted = y_new[0] <= 0.0;
        if beta_new >= beta_end && stuck_at.is_none() && parted {
            // End of contact inside this step, at the later of β reaching
            // its end and the spheres parting (δ = 0), each interpolated
            // linearly (β may have passed its end while they overlapped).
            let beta_old = ode.beta(&y);
            let f_beta = (beta_end - beta_old) / (beta_new - beta_old);
            let f_delta = if y[0] > 0.0 { y[0] / (y[0] - y_new[0]) } else { 0.0 };
            let f = f_beta.max(f_delta).clamp(0.0, 1.0);
            let y_end = y + f * (y_new - y);
            bounce = Some((t + f * h, y_end));
            break;
        }
        if stuck_at.is_none() && y_new[0] < 0.0 && y_new[1] < 0.0 && beta_new > 1.0 {
            // The parted spheres' neck collapses.
            if ode.runaway(&y_new) {
                // On the branch where it runs away, the rest is integrated
                // in β (see ContactOde::collapse), to a tenth of the tolerance.
                let mut steps = Vec::new();
                let rest = ode.collapse(&y_new, beta_end, COLLAPSE_TOLERANCE * opts.rtol, &scale, |tr, yr| {
                    let total = ode.mechanical_energy(yr) + yr[3] + yr[4];
                    energy_error = energy_error.max((total - total0).abs() / ke0);
                    if opts.record {
                        steps.push((tr, *yr));
                    }
                });
                if let Some((dt, y_end, work)) = rest {
                    solver.stats += work;
                    // The last step's end is the contact's `last` sample.
                    steps.pop();
                    samples.extend(steps.iter().map(|(tr, yr)| to_sample(t_new + tr, yr)));
                    bounce = Some((t_new + dt, y_end));
                    break;
                }
            }
            // A collapse that ends before it reaches the branch where it
            // runs away (where the integration in β above takes over), or
            // whose integration in β left that branch:
            // |ȧ| only grows and |F_E| only falls from here, so the velocity
            // can change by at most |F_E|/m* · a/|ȧ| before contact ends.
            // Stop once that bound is a tenth of the tolerance instead of
            // resolving the singularity: e then leaves out at most 0.1 rtol.
            // The rest of the collapse is closed at once, with the energy it
            // releases at the crack.
            if let (Some(f), Some(pt)) = (ode.rhs(&y_new), ode.point(&y_new)) {
                let t_left = pt.s / pt.sdot.abs();
                let dv = f[1].abs() * t_left;
                if pt.sdot < 0.0 && dv < 0.1 * opts.rtol * v_scaled {
                    bounce = Some((t_new + t_left, ode.collapsed(&y_new, beta_end)));
                    break;
                }
            }
        }
        if beta_new >= beta_end && stuck_at.is_some() {
            // A stuck pair cannot separate; the follow-up run ends here.
            break;
        }
        let mechanical = ode.mechanical_energy(&y_new);
        let total = mechanical + y_new[3] + y_new[4];
        energy_error = energy_error.max((total - total0).abs() / ke0);
        if stuck_at.is_none() {
            let turned_back = y[1] < 0.0 && y_new[1] >= 0.0;
            if mechanical < 0.0 || turned_back {
                stuck_at = Some((t_new, true));
            } else if t_new > opts.max_time {
                stuck_at = Some((t_new, false));
            }
        }
        t = t_new;
        y = y_new;
        if opts.record {
            samples.push(to_sample(t, &y));
        }
    }

    let initial_kinetic = 0.5 * m * velocity * velocity;
    let collision = match bounce {
        Some((tc, y_end)) => {
            let last = to_sample(tc, &y_end);
            if opts.record {
                samples.push(last);
            }
            Collision {
                outcome: Outcome::Bounce,
                resolved: true,
                velocity,
                // Energy only decreases, so e_A ≤ 1; larger values are integration error.
                e_adhesive: (-y_end[1] / v_scaled).clamp(0.0, 1.0),
                contact_time: tc * tau,
                hertz_time: t_h,
                initial_kinetic,
                last,
                energy_error,
                samples,
                stats: solver.stats,
            }
        }
        None => {
            let (ts, resolved) = stuck_at.unwrap_or((t, false));
            Collision {
                outcome: Outcome::Stick,
                resolved,
                velocity,
                e_adhesive: 0.0,
                contact_time: ts * tau,
                hertz_time: t_h,
                initial_kinetic,
                last: to_sample(t, &y),
                energy_error,
                samples,
                stats: solver.stats,
            }
        }
    };
    Ok(collision)
}

/// Restitution of one collision with all its parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restitution {
    /// Impact speed, m/s.
    pub velocity: f64,
    /// Adhesive–viscoelastic e_A (numerical).
    pub e_adhesive: f64,
    /// Plastic e_P (2.29).
    pub e_plastic: f64,
    /// Combined e (2.30).
    pub e: f64,
}

/// Coefficient of restitution at impact speed `velocity` (m/s), combining
/// the numerical e_A with Thornton–Ning plasticity (2.30).
pub fn restitution(setup: &Setup, velocity: f64, opts: &Options) -> Result<Restitution, PhysicsError> {
    let c = collide(setup, velocity, &Options { record: false, follow_after_stick: 0.0, ..*opts })?;
    let e_p = plasticity::e_plastic(velocity, setup.yield_velocity());
    Ok(Restitution {
        velocity,
        e_adhesive: c.e_adhesive,
        e_plastic: e_p,
        e: if c.e_adhesive > 0.0 { plasticity::e_combined(c.e_adhesive, e_p) } else { 0.0 },
    })
}

/// The sticking velocity once plastic yield is counted: the lowest impact
/// speed at which the combined e = (e_A² + e_P² − 1)^{1/2} (2.30) is
/// positive, to relative precision `rel`, given the adhesive sticking
/// velocity `adhesive` of [`sticking_search`] (m/s).
///
/// Below the yield velocity v_y, e_P = 1 and the two agree. Where v_y lies
/// below `adhesive`, bouncing needs e_A² > 1 − e_P²: the speeds from
/// `adhesive` to 10⁴ m/s are scanned in steps of 2^{1/8} for the first
/// bounce, which is then bracketed by bisection. Infinity means that no
/// collision up to 10⁴ m/s bounces (a lower bound, not a value): with
/// plastic yield every collision sticks.
pub fn sticking_velocity_with_yield(
    setup: &Setup,
    opts: &Options,
    adhesive: f64,
    rel: f64,
) -> Result<f64, PhysicsError> {
    super::positive("rel", rel)?;
    let v_y = setup.yield_velocity();
    if !(adhesive.is_finite() && adhesive > 0.0) || adhesive < v_y {
        return Ok(adhesive);
    }
    let bounces = |v: f64| -> Result<bool, PhysicsError> { Ok(restitution(setup, v, opts)?.e > 0.0) };
    let (v_max, step) = (1e4, 2f64.powf(0.125));
    let mut lo = adhesive;
    let mut hi = loop {
        let v = (lo * step).min(v_max);
        if bounces(v)? {
            break v;
        }
        if v >= v_max {
            return Ok(f64::INFINITY);
        }
        lo = v;
    };
    while hi / lo - 1.0 > rel {
        let mid = (lo * hi).sqrt();
        if bounces(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok((lo * hi).sqrt())
}

/// The result of a sticking-velocity search (see [`sticking_search`]).
#[derive(Debug, Clone, PartialEq)]
pub struct StickingSearch {
    /// The sticking velocity v_s, m/s: the geometric middle of `bracket`,
    /// infinity if the spheres still stick at 10⁴ m/s, zero if they still
    /// bounce at 10⁻⁶ m/s.
    pub velocity: f64,
    /// The final bracket [stick, bounce], m/s (equal ends when v_s lies
    /// outside the searched range).
    pub bracket: [f64; 2],
    /// Every bouncing collision of the search as (v in m/s, e_A), by velocity.
    pub bounces: Vec<[f64; 2]>,
    /// Collisions computed.
    pub evaluations: usize,
}

/// The sticking velocity v_s: the largest impact speed at which the spheres
/// stick through adhesion and viscosity (e_A = 0), to relative precision
/// `rel`. Plasticity, which only acts far above v_s, is not part of the
/// criterion. Searches 10⁻⁶–10⁴ m/s.
pub fn sticking_velocity(setup: &Setup, opts: &Options, rel: f64) -> Result<f64, PhysicsError> {
    Ok(sticking_search(setup, opts, rel)?.velocity)
}

/// Finds the sticking velocity and keeps what the search learned.
///
/// A bracket [stick, bounce] is found by doubling or halving from the JKR
/// v_c (2.25). Inside it the search extrapolates e_A of the bouncing
/// collisions nearest v_s to zero (see `extrapolate_to_sticking`). Once the
/// estimate sits within `rel` of one end of the bracket, the
/// next collision is placed to close the bracket from the other side. Where
/// two steps have not halved the bracket (in log v) the next one bisects, so
/// the search never needs more than twice the collisions of bisection; on
/// the reference ice set it needs 7 instead of 17 at `rel` = 10⁻⁴.
pub fn sticking_search(setup: &Setup, opts: &Options, rel: f64) -> Result<StickingSearch, PhysicsError> {
    search_from(setup, opts, rel, setup.pair.jkr_sticking_velocity(), 2.0)
}

/// [`sticking_search`] from a guess of v_s (m/s), for example the sticking
/// velocity of a neighbouring radius: the bracket is sought with a first
/// step of 2·`rel` that squares while it misses (at `rel` = 10⁻³: 0.2 %,
/// 0.4 %, 0.8 %, 1.6 %, 3.2 %, …), so a guess within `rel` costs three or
/// four collisions, and one 30 % off about a dozen.
pub fn sticking_search_near(
    setup: &Setup,
    opts: &Options,
    rel: f64,
    guess: f64,
) -> Result<StickingSearch, PhysicsError> {
    super::positive("guess", guess)?;
    search_from(setup, opts, rel, guess, 1.0 + 2.0 * rel)
}

/// The search of [`sticking_search`] starting at `start` with bracketing
/// steps of `factor`, squared after each miss when it is below 2.
fn search_from(
    setup: &Setup,
    opts: &Options,
    rel: f64,
    start: f64,
    mut factor: f64,
) -> Result<StickingSearch, PhysicsError> {
    setup.validate()?;
    super::positive("rel", rel)?;
    let opts = Options { record: false, follow_after_stick: 0.0, ..*opts };
    let mut bounces: Vec<[f64; 2]> = Vec::new();
    let mut evaluations = 0;
    // e_A at v, or None when the spheres stick.
    let mut try_v = |v: f64, bounces: &mut Vec<[f64; 2]>| -> Result<bool, PhysicsError> {
        evaluations += 1;
        let c = collide(setup, v, &opts)?;
        if c.outcome == Outcome::Stick {
            return Ok(true);
        }
        let at = bounces.partition_point(|b| b[0] < v);
        bounces.insert(at, [v, c.e_adhesive]);
        Ok(false)
    };
    let (v_min, v_max) = (1e-6, 1e4);
    let mut v = start.clamp(v_min, v_max);
    let mut widen = || {
        let f = factor;
        if factor < 2.0 {
            factor *= factor;
        }
        f
    };
    let (mut lo, mut hi);
    if try_v(v, &mut bounces)? {
        lo = v;
        loop {
            v *= widen();
            if v > v_max {
                return Ok(StickingSearch { velocity: f64::INFINITY, bracket: [lo, lo], bounces, evaluations });
            }
            if !try_v(v, &mut bounces)? {
                hi = v;
                break;
            }
            lo = v;
        }
    } else {
        hi = v;
        loop {
            v /= widen();
            if v < v_min {
                return Ok(StickingSearch { velocity: 0.0, bracket: [hi, hi], bounces, evaluations });
            }
            if try_v(v, &mut bounces)? {
                lo = v;
                break;
            }
            hi = v;
        }
    }
    // Bracket widths (in ln v) two steps ago and one step ago.
    let mut widths = [f64::INFINITY; 2];
    while hi / lo - 1.0 > rel {
        let width = (hi / lo).ln();
        // Where two steps have not halved the bracket, bisect.
        let bisect = width > 0.5 * widths[0];
        widths = [widths[1], width];
        let estimate = if bisect { None } else { extrapolate_to_sticking(&bounces).filter(|&v| v > lo && v < hi) };
        let v = match estimate {
            Some(v) if v * (1.0 + rel) >= hi => hi / (1.0 + 0.9 * rel),
            Some(v) if v <= lo * (1.0 + rel) => lo * (1.0 + 0.9 * rel),
            Some(v) => v,
            None => (lo * hi).sqrt(),
        };
        if try_v(v, &mut bounces)? {
            lo = v;
        } else {
            hi = v;
        }
    }
    Ok(StickingSearch { velocity: (lo * hi).sqrt(), bracket: [lo, hi], bounces, evaluations })
}

/// Where e_A reaches zero, from the slowest bounces: v as a quadratic in e
/// through three of them (inverse quadratic interpolation), a straight line
/// through two, or the JKR form e² = 1 − v_s²/v² (2.24) from one. Near v_s
/// the model's e_A rises as (v − v_s) where viscosity decides the outcome
/// and as (v − v_s)^{1/2} in the quasi-static limit: v(e) = v_s + c₁e + c₂e²
/// holds both exactly.
fn extrapolate_to_sticking(bounces: &[[f64; 2]]) -> Option<f64> {
    let v = match bounces {
        [] => return None,
        [[v, e]] => v * (1.0 - e * e).max(0.0).sqrt(),
        [[v1, e1], [v2, e2]] => v1 - e1 * (v2 - v1) / (e2 - e1),
        [a, b, c, ..] => {
            let points = [a, b, c];
            (0..3)
                .map(|i| {
                    let w: f64 =
                        (0..3).filter(|&j| j != i).map(|j| -points[j][1] / (points[i][1] - points[j][1])).product();
                    w * points[i][0]
                })
                .sum()
        }
    };
    (v.is_finite() && v > 0.0).then_some(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn analytic_jacobian_matches_finite_differences() {
        let ode = ContactOde {
            c1: 3.0,
            c2: 0.7,
            c3: 0.05,
            cb: 40.0,
            rho: 2.0,
            cg: 5.0,
            cs: 0.3,
            crack: CrackLaw::thesis(0.02).resolve(),
            beta_memo: Cell::new([f64::NAN; 3]),
        };
        for (w, s) in [(0.8, 0.3), (-0.4, 0.5), (-0.9, 0.25)] {
            // Choose u so that β lies in a smooth part of the crack law.
            for target_beta in [0.5, 2.0, 6.0] {
                let u = (target_beta * s / ode.cb).sqrt();
                let q = u.ln();
                let x = (s * s - u) / ode.rho;
                let y = State::<5>::new(x, w, q, 0.0, 0.0);
                let j = ode.jacobian(&y).expect("in domain");
                let f0 = ode.rhs(&y).expect("in domain");
                for c in 0..3 {
                    let h = 1e-7 * y[c].abs().max(1e-3);
                    let mut yp = y;
                    yp[c] += h;
                    let mut ym = y;
                    ym[c] -= h;
                    let col = (ode.rhs(&yp).expect("in") - ode.rhs(&ym).expect("in")) / (2.0 * h);
                    for r in 0..5 {
                        let scale = j[(r, c)].abs().max(f0[r].abs()).max(1e-6);
                        assert!(
                            (col[r] - j[(r, c)]).abs() < 1e-5 * scale,
                            "β={target_beta} ∂f{r}/∂y{c}: {} vs {}",
                            col[r],
                            j[(r, c)]
                        );
                    }
                }
            }
        }
    }
}
