//! Local Monte Carlo coagulation of porous aggregates in a vertical disk
//! column (thesis Sects. 4.3–4.4): the collision model of the column for the
//! distribution-method engine, and runs with snapshots and diagnostics.
//!
//! Rates: the vertically integrated kernel (4.19),
//! K = σ h_{d,ij}/((2π)^{1/2} h_i h_j) v_rel(z = 0), with σ = π(a_i + a_j)²,
//! h_{d,ij} = (h_i⁻² + h_j⁻²)^{-1/2}; the column holds the particles of
//! area V = M/Σ_d, so a pair collides at K/V.
//!
//! Outcomes (Sect. 4.2.3): sticking; erosion of the target by projectiles
//! with mass ratio < R_crit above v_eros (efficiency (4.13), γ = 1), the
//! (1 + ε)m_proj not kept by the target leaving as fragments of m_proj/10
//! whose filling factor follows from the target's fractal dimension (4.14);
//! catastrophic fragmentation above v_frag into fragments of m_proj/10.
//!
//! Filling factor of a sticking collision (this project's reconstruction of
//! Okuzumi et al. 2012, whose Eq. 15 is not available here, with the limits
//! the physics notes give): the hit-and-stick volume of Suyama et al. (2012);
//! when the impact energy E = μv²/2 exceeds 3bE_roll (b = 0.15) the product
//! is at least as compact as Suyama et al.'s (2008) equal-mass law
//! φ = (E/(3bN E_roll))^{3/10} N^{-1/5} for N = m/m₀ monomers — which joins the
//! hit-and-stick fractal φ = N^{-1/2} exactly at the onset, gives φ ∝ m^{-1/8},
//! const and m^{-1/5} in the three regimes of the semi-analytical track, and
//! leaves a target hit by a much smaller projectile (E/N small) uncompressed.
//! With full compaction the product is then compressed until it withstands
//! gas ram pressure and self-gravity (4.15)–(4.16), Sect. 4.3.5.

use super::PhysicsError;
use super::aggregate::{
    Aggregate, CompactionConstants, DriftTerms, Monomer, Outcome, Particle, Thresholds, TurbulenceConstants,
    TurbulenceModel, dust_scale_height, effective_difference, gas_compaction_filling_with, gas_relative_velocity,
    gravity_filling, hit_and_stick_growth, hit_and_stick_volume, outcome, radial_drift, relative_velocity,
    stopping_time, stopping_time_and_radius,
};
use super::column_row::{self, Lanes, Lead, RowConstants};
use super::constants::K_B;
use super::disk::Local;
use super::fdlibm;
use super::monte_carlo::{Body, Collision, Effect, Engine, Family, Model, PairRow, PairRule, Settings};
use crate::parallel::Turn;
use std::f64::consts::PI;

/// Compaction mechanisms (Sect. 4.4.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Compaction {
    /// Hit-and-stick and collisional compaction only (Fig. 4.4).
    Collisional,
    /// Also gas ram pressure and self-gravity (Fig. 4.6 onwards).
    Full,
}

/// The collision model of a column at one radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Column {
    /// Midplane gas at the column's radius.
    pub env: Local,
    /// Monomers.
    pub monomer: Monomer,
    /// Collision thresholds (v_frag, v_eros, R_crit; bouncing is not used for aggregates).
    pub thresholds: Thresholds,
    /// Erosion efficiency prefactor c₁ of (4.13) (1).
    pub c1: f64,
    /// Compaction mechanisms.
    pub compaction: Compaction,
    /// Turbulence model.
    pub turbulence: TurbulenceModel,
    /// Dispersion ε of the mass-to-area ratio (0.1).
    pub epsilon: f64,
    /// Include Newton drag.
    pub newton: bool,
}

/// Cached properties of a family of aggregates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Props {
    /// Radius, m.
    pub radius: f64,
    /// Stokes number Ωt_s.
    pub stokes: f64,
    /// Dust scale height, m.
    pub scale_height: f64,
    /// The terms of the relative velocity that depend on this family alone,
    /// for the pairs in which it has the larger Stokes number.
    pub(crate) drift: DriftTerms,
    /// Scale height squared, m².
    pub(crate) scale_height2: f64,
}

/// The column's constants that every pair needs, computed once per row of pairs.
#[derive(Debug, Clone, Copy)]
struct Constants {
    /// Monomer internal density ρ₀, kg m⁻³.
    rho0: f64,
    /// Monomer mass m₀, kg.
    m0: f64,
    /// Rolling energy E_roll, J.
    e_roll: f64,
    /// 8k_BT/π, J: the Brownian term is this times (m₁ + m₂)/(m₁m₂).
    brownian: f64,
    /// The settling, radial and azimuthal terms of a particle with St = 0.
    at_rest: (f64, f64, f64),
    /// The gas's constants of the thesis's turbulent term.
    turbulence: TurbulenceConstants,
}

impl Constants {
    fn of(column: &Column) -> Constants {
        let mono = &column.monomer;
        Constants {
            rho0: mono.density,
            m0: mono.mass(),
            e_roll: mono.rolling_energy(),
            brownian: 8.0 * K_B * column.env.temperature / PI,
            at_rest: drift_terms(&column.env, 0.0),
            turbulence: TurbulenceConstants::of(&column.env),
        }
    }
}

/// Collisional-compaction parameter b (Okuzumi et al. 2012).
use super::monomer::COMPACTION_B as B_COMPACT;

impl Column {
    fn particle(&self, f: &Family<Props>) -> Particle {
        Particle { mass: f.mass, stokes: f.props.stokes }
    }

    /// Relative velocity of two families at the midplane, m s⁻¹: the
    /// quadratic sum of [`relative_velocity`], with the terms of the family
    /// with the larger Stokes number taken from its cached properties (the
    /// same numbers to rounding; a unit test holds them together).
    pub fn velocity(&self, a: &Family<Props>, b: &Family<Props>) -> f64 {
        self.velocity_with(&Constants::of(self), a, b)
    }

    /// [`Column::velocity`] with the constants computed once. A projectile
    /// whose effective Stokes number is 0 (St₂ ≤ ε²St₁/2 or so) has the
    /// drift terms of a particle at rest, computed once.
    fn velocity_with(&self, k: &Constants, a: &Family<Props>, b: &Family<Props>) -> f64 {
        if self.turbulence != TurbulenceModel::Thesis {
            return relative_velocity(&self.env, &self.particle(a), &self.particle(b), self.turbulence, self.epsilon)
                .total();
        }
        let env = &self.env;
        let (p1, p2) = if a.props.stokes >= b.props.stokes { (a, b) } else { (b, a) };
        let (s1, s2) = (p1.props.stokes, p2.props.stokes);
        let (diff, s2_eff) = effective_difference(s1, s2, self.epsilon);
        // 8k_BT/(πμ) with 1/μ = 1/m_a + 1/m_b (the row keeps every 1/m).
        let brownian2 = k.brownian * (1.0 / a.mass + 1.0 / b.mass);
        let d1 = &p1.props.drift;
        let turbulence = k.turbulence.velocity(d1, s2_eff, diff);
        let (settling2, radial2, azimuthal2) = if s2_eff > 0.0 { drift_terms(env, s2_eff) } else { k.at_rest };
        let settling = d1.settling - settling2;
        let radial = d1.radial - radial2;
        let azimuthal = d1.azimuthal - azimuthal2;
        (brownian2 + turbulence * turbulence + settling * settling + radial * radial + azimuthal * azimuthal).sqrt()
    }

    /// Filling factor of the product of a sticking collision after
    /// hit-and-stick and collisional compaction (gas and self-gravity act
    /// afterwards, once, in [`Model::compact`]).
    pub fn filling_after(&self, t: Body, p: Body, v: f64) -> f64 {
        let k = Constants::of(self);
        let volume = |b: Body| b.mass / (k.rho0 * b.filling);
        filling_with(&k, (t.mass, volume(t)), (p.mass, volume(p)), v)
    }

    /// The change of the target's filling factor in a sticking collision
    /// before gas and self-gravity act: [`Column::filling_after`] − φ_t,
    /// computed without that difference's cancellation (see
    /// [`Model::collide`]'s sticking outcome).
    pub fn filling_change(&self, t: Body, p: Body, v: f64) -> f64 {
        let k = Constants::of(self);
        let volume = |b: Body| b.mass / (k.rho0 * b.filling);
        filling_change_with(&k, (t.mass, volume(t), t.filling), (p.mass, volume(p)), v)
    }

    /// The filling factor after compression by gas ram pressure and
    /// self-gravity (4.15)–(4.16), Sect. 4.3.5: at least the value at which
    /// the compressive strength withstands both.
    pub fn external_compaction(&self, body: Body) -> f64 {
        let mono = &self.monomer;
        let (m, mut phi) = (body.mass, body.filling);
        let constants = CompactionConstants::of(mono);
        let e_roll = constants.e_roll;
        // Gas ram pressure: solve only if it exceeds the strength P_c = E_roll φ³/a₀³ (4.15).
        let agg = Aggregate { mass: m, filling: phi };
        let (stopping, a) = stopping_time_and_radius(&self.env, mono, &agg, self.newton);
        let ts = stopping.time;
        let p_gas = gas_relative_velocity(self.env.eta_vk, self.env.omega * ts) * m / (PI * a.powi(2) * ts);
        if e_roll / mono.radius.powi(3) * phi.powi(3) < p_gas {
            phi = phi.max(gas_compaction_filling_with(&self.env, mono, &constants, m, self.newton, phi));
        }
        phi.max(gravity_filling(mono, &constants, m)).min(1.0)
    }

    /// A fragment of mass `m` (at least a monomer) chipped off a target with
    /// filling factor and mass `target`: same fractal dimension (4.14).
    fn fragment(&self, m: f64, target: Body) -> Body {
        let m0 = self.monomer.mass();
        if m <= m0 * (1.0 + 1e-9) {
            return Body { mass: m0, filling: 1.0 };
        }
        let agg = Aggregate { mass: target.mass, filling: target.filling };
        let d_f = agg.fractal_dimension(&self.monomer);
        let phi = (m / m0).powf(1.0 - 3.0 / d_f).min(1.0);
        Body { mass: m, filling: phi }
    }
}

/// The settling, radial and azimuthal terms of [`DriftTerms::of`] with
/// three divisions instead of five and St/α taken as St·(1/α), as a row of
/// pairs takes it (the same formulas; a test holds the velocity built from
/// them to [`relative_velocity`]).
fn drift_terms(env: &Local, st: f64) -> (f64, f64, f64) {
    let inv1 = 1.0 / (1.0 + st);
    let inv2 = 1.0 / (1.0 + st * st);
    let h_d = 1.0 / (1.0 + st * (1.0 / env.alpha) * (1.0 + 2.0 * st) * inv1).sqrt();
    (env.omega * st * inv1 * h_d * env.scale_height, 2.0 * st * env.eta_vk * inv2, env.eta_vk * inv2)
}

/// [`Column::filling_after`] for a target and a projectile given as (mass,
/// volume m/(ρ₀φ)). The compaction law's two logarithms and exponential are
/// taken only where it can exceed the hit-and-stick filling factor: it does
/// where φ_c¹⁰ = x³/N² (x = E/(3bN E_roll)) exceeds φ_hs¹⁰, compared in
/// products (the same result; a near tie takes the logarithms).
fn filling_with(k: &Constants, target: (f64, f64), projectile: (f64, f64), v: f64) -> f64 {
    sticking_filling(k, target, projectile, v).0
}

/// The filling factor of a sticking product (as [`filling_with`]) and
/// whether it is the hit-and-stick value below 1 (neither compacted nor
/// capped).
fn sticking_filling(k: &Constants, (mt, vt): (f64, f64), (mp, vp): (f64, f64), v: f64) -> (f64, bool) {
    let m = mt + mp;
    let phi_hs = m / (k.rho0 * hit_and_stick_volume(vt, vp));
    if phi_hs >= 1.0 {
        return (1.0, false);
    }
    let inv_m = 1.0 / m;
    let e = 0.5 * mt * mp * inv_m * v * v;
    let onset = 3.0 * B_COMPACT * k.e_roll;
    if e <= onset {
        return (phi_hs, true);
    }
    let n = m * (1.0 / k.m0);
    let x = e * k.m0 * inv_m * (1.0 / onset);
    let hs2 = phi_hs * phi_hs;
    let hs10 = hs2 * hs2 * hs2 * hs2 * hs2;
    let below = x * x * x < hs10 * n * n * (1.0 - 1e-9);
    if below && hs10 > 1e-250 && n < 1e100 {
        return (phi_hs, true);
    }
    // fdlibm's logarithm and exponential, as the row of pairs takes them.
    let phi_c = fdlibm::exp(0.3 * fdlibm::ln(x) - 0.2 * fdlibm::ln(n));
    if phi_c > phi_hs { (phi_c.min(1.0), false) } else { (phi_hs, true) }
}

/// The change of the target's filling factor in a sticking collision,
/// φ_product − φ_t, for a target (mass, volume, φ) and a projectile (mass,
/// volume). Where the product keeps the hit-and-stick value it is
/// φ_t (m_p/m_t − ΔV/V_t)/(1 + ΔV/V_t) with ΔV the volume the collision adds
/// ([`hit_and_stick_growth`]): a small projectile changes φ by far less than
/// the rounding of φ itself (10⁻²² of it for a monomer on a body of 10⁴
/// kg), and a sequence of 2^N such collisions (4.21) extrapolates that
/// change, not the rounding of a difference of two filling factors.
fn filling_change_with(k: &Constants, (mt, vt, phi_t): (f64, f64, f64), (mp, vp): (f64, f64), v: f64) -> f64 {
    let (phi, hit_and_stick) = sticking_filling(k, (mt, vt), (mp, vp), v);
    if !hit_and_stick {
        return phi - phi_t;
    }
    // φ_t (m_p/m_t − g/V_t)/(1 + g/V_t) for the volume g added, in one division.
    let grown = hit_and_stick_growth(vt, vp);
    phi_t * (mp * vt - mt * grown) / (mt * (vt + grown))
}

impl Column {
    /// [`Model::pair`] with the constants computed once.
    fn pair_with(&self, k: &Constants, a: &Family<Props>, b: &Family<Props>) -> (f64, Effect) {
        let v = self.velocity_with(k, a, b);
        let (t, p) = if a.mass >= b.mass { (a, b) } else { (b, a) };
        let effect = match outcome(t.mass, p.mass, v, &self.thresholds) {
            Outcome::Stick => {
                // From the family's mass and φ, not its cached properties: a
                // merge may move them a little without refreshing those, and
                // the change of φ in one collision is a small difference.
                let volume = |f: &Family<Props>| f.mass / (k.rho0 * f.filling);
                let change = filling_change_with(k, (t.mass, volume(t), t.filling), (p.mass, volume(p)), v);
                Effect::Stick { change }
            }
            Outcome::Erode { efficiency } => {
                let lost = self.c1 * efficiency * p.mass;
                if lost >= t.mass { Effect::Shatter } else { Effect::Erode { loss: lost } }
            }
            Outcome::Fragment => Effect::Shatter,
            Outcome::Bounce => Effect::Bounce,
        };
        (self.rate_at(a, b, v), effect)
    }
}

impl Model for Column {
    type Props = Props;
    type Lanes = Lanes;

    fn props(&self, body: Body) -> Props {
        let agg = Aggregate { mass: body.mass, filling: body.filling };
        let (stopping, radius) = stopping_time_and_radius(&self.env, &self.monomer, &agg, self.newton);
        let st = stopping.time * self.env.omega;
        let scale_height = dust_scale_height(self.env.alpha, st) * self.env.scale_height;
        Props {
            radius,
            stokes: st,
            scale_height,
            drift: DriftTerms::of(&self.env, st),
            scale_height2: scale_height * scale_height,
        }
    }

    fn rate(&self, a: &Family<Props>, b: &Family<Props>) -> f64 {
        self.rate_at(a, b, self.velocity(a, b))
    }

    /// One relative velocity for both the rate and the outcome, and no
    /// fragments made where only the target's mass change is needed.
    fn pair(&self, a: &Family<Props>, b: &Family<Props>) -> (f64, Effect) {
        self.pair_with(&Constants::of(self), a, b)
    }

    /// The families' properties, one array per property ([`column_row::Lanes`]).
    fn set_lane(&self, lanes: &mut Lanes, i: usize, family: &Family<Props>) {
        lanes.set(i, &Lead::of(family, self.monomer.density));
    }

    fn remove_lane(&self, lanes: &mut Lanes, i: usize) {
        lanes.swap_remove(i);
    }

    /// [`Model::pair_data_row`] over the whole row at once
    /// ([`column_row`]), with the pairs that need a logarithm computed one
    /// at a time; the same numbers to the last bit. A part of a row, or a
    /// row with another turbulence model, is computed one pair at a time.
    fn pair_data_row(
        &self,
        lanes: &Lanes,
        a: &Family<Props>,
        others: &[Family<Props>],
        which: &[usize],
        rule: &PairRule,
        mut out: PairRow<'_>,
    ) {
        let k = Constants::of(self);
        let one = |j: usize| {
            let b = &others[j];
            let (rate, effect) = self.pair_with(&k, a, b);
            rule.data(a, b, rate, effect)
        };
        let whole = which.len() == others.len() && lanes.len() == others.len();
        if self.turbulence != TurbulenceModel::Thesis || !whole {
            for &j in which {
                out.set(j, one(j));
            }
            return;
        }
        let row = self.row_constants(&k, rule);
        column_row::pair_data_row(&row, &Lead::of(a, k.rho0), lanes, out, one);
    }

    /// Sticking gives the filling factor after hit-and-stick and collisional
    /// compaction; gas and self-gravity act in [`Model::compact`].
    fn collide(&self, target: &Family<Props>, projectile: &Family<Props>) -> Collision {
        let v = self.velocity(target, projectile);
        let (t, p) = (target.body(), projectile.body());
        let m0 = self.monomer.mass();
        // Fragments of a tenth of the projectile's mass, at least a monomer,
        // at most `mass` in all; counted by the mass they are given, so that
        // `count` of them carry `mass` exactly, also where `mass` is less
        // than one monomer (`fragment` never makes a lighter one).
        let fragments_of = |mass: f64| {
            let fragment = self.fragment((projectile.mass / 10.0).max(m0).min(mass), t);
            (fragment, mass / fragment.mass)
        };
        match outcome(t.mass, p.mass, v, &self.thresholds) {
            Outcome::Stick => Collision::Stick { change: self.filling_change(t, p, v) },
            Outcome::Erode { efficiency } => {
                let eps = self.c1 * efficiency; // erosion_efficiency(c1, v, v_eros)
                let lost = eps * p.mass;
                if lost >= t.mass {
                    let (fragment, count) = fragments_of(t.mass + p.mass);
                    return Collision::Shatter { fragment, count };
                }
                let (fragment, count) = fragments_of((1.0 + eps) * p.mass);
                Collision::Erode { loss: lost, fragment, count }
            }
            Outcome::Fragment => {
                let (fragment, count) = fragments_of(t.mass + p.mass);
                Collision::Shatter { fragment, count }
            }
            Outcome::Bounce => Collision::Bounce,
        }
    }

    fn compact(&self, body: Body) -> f64 {
        if self.compaction == Compaction::Full { self.external_compaction(body) } else { body.filling }
    }
}

impl Column {
    /// What every pair of a row needs ([`column_row`]).
    fn row_constants(&self, k: &Constants, rule: &PairRule) -> RowConstants {
        let th = &self.thresholds;
        RowConstants {
            epsilon: self.epsilon,
            brownian: k.brownian,
            st_eta: k.turbulence.st_eta,
            vg_re: k.turbulence.vg * k.turbulence.re_quarter,
            vg_155: k.turbulence.vg * 1.55,
            vg: k.turbulence.vg,
            inv_alpha: 1.0 / self.env.alpha,
            omega: self.env.omega,
            scale_height: self.env.scale_height,
            eta_vk: self.env.eta_vk,
            rho0: k.rho0,
            m0: k.m0,
            inv_m0: 1.0 / k.m0,
            onset: 3.0 * B_COMPACT * k.e_roll,
            inv_onset: 1.0 / (3.0 * B_COMPACT * k.e_roll),
            r_crit: th.r_crit,
            v_eros: th.v_eros,
            inv_v_eros: 1.0 / th.v_eros,
            v_frag: th.v_frag,
            v_bounce: th.v_bounce,
            c1: self.c1,
            rule: *rule,
            inv_volume: 1.0 / rule.volume,
        }
    }

    /// The rate coefficient of a pair at relative velocity `v`:
    /// h_ij/(h_i h_j) with h_ij = (h_i⁻² + h_j⁻²)^{-1/2} is 1/(h_i² + h_j²)^{1/2}.
    fn rate_at(&self, a: &Family<Props>, b: &Family<Props>, v: f64) -> f64 {
        // π/(2π)^{1/2} = (π/2)^{1/2}.
        const ROOT_HALF_PI: f64 = 1.253_314_137_315_500_3;
        let r = a.props.radius + b.props.radius;
        ROOT_HALF_PI * r * r * v / (a.props.scale_height2 + b.props.scale_height2).sqrt()
    }
}

/// A Monte Carlo run of a column.
#[derive(Debug, Clone, PartialEq)]
pub struct RunConfig {
    /// The collision model.
    pub column: Column,
    /// Mass in the simulated column, kg (sets its area M/Σ_d; results do not depend on it
    /// while every decade holds many particles).
    pub column_mass: f64,
    /// Distribution-method settings (its seed is the first run's).
    pub settings: Settings,
    /// Snapshot times, s (ascending); the run ends at the last.
    pub snapshots: Vec<f64>,
    /// History samples per decade of time.
    pub history_per_decade: usize,
    /// Stop after this many events (a safety limit).
    pub max_events: u64,
    /// Stop when the peak mass reaches this, kg (infinite: never).
    pub stop_mass: f64,
}

/// One family at a snapshot.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FamilyPoint {
    /// Particle mass, kg.
    pub mass: f64,
    /// Filling factor.
    pub filling: f64,
    /// Number of particles in the column.
    pub particles: f64,
    /// Stokes number.
    pub stokes: f64,
}

/// The state of a run at one time.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Snapshot {
    /// Time, s.
    pub t: f64,
    /// Every family.
    pub families: Vec<FamilyPoint>,
    /// Diagnostics.
    pub sample: Sample,
    /// Projectile distribution of the largest body: (projectile mass, dm_max/dt contribution, kg s⁻¹).
    pub projectiles: Vec<(f64, f64)>,
}

/// Diagnostics of the distribution at one time.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Sample {
    /// Time, s.
    pub t: f64,
    /// Events so far.
    pub events: u64,
    /// Families.
    pub families: usize,
    /// Average mass m_a (4.28), kg.
    pub m_a: f64,
    /// Average filling factor φ_a.
    pub phi_a: f64,
    /// Peak mass m_p (4.29), kg.
    pub m_p: f64,
    /// Peak filling factor φ_p.
    pub phi_p: f64,
    /// Largest mass, kg.
    pub m_max: f64,
    /// Stokes number of the largest body.
    pub stokes_max: f64,
    /// Stokes number of a peak-mass particle (φ = φ_p).
    pub stokes_p: f64,
    /// ζ (4.34) of the largest body.
    pub zeta: f64,
    /// Radial drift time R/v_drift (4.31) of the peak mass, s.
    pub t_drift: f64,
    /// Relative mass error (M − M₀)/M₀.
    pub mass_error: f64,
}

/// How a run that reached its event limit ended ([`Run::ended`]).
pub const ENDED_AT_EVENT_LIMIT: &str = "event limit";

/// The result of one run.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Run {
    /// Seed.
    pub seed: u64,
    /// Snapshots at the requested times (fewer if the run stopped early).
    pub snapshots: Vec<Snapshot>,
    /// Diagnostics over time (log-spaced).
    pub history: Vec<Sample>,
    /// Group events.
    pub events: u64,
    /// Why the run ended.
    #[serde(deserialize_with = "crate::statics::deserialize")]
    pub ended: crate::statics::Text,
    /// Dust mass per column area at the start, kg m⁻², to normalise m²f(m).
    pub surface_density: f64,
    /// Column area, m².
    pub area: f64,
    /// What the events did.
    pub tally: super::monte_carlo::Tally,
}

/// ζ (4.34) from a projectile distribution.
pub fn zeta(projectiles: &[(f64, f64)]) -> f64 {
    let pos: f64 = projectiles.iter().map(|p| p.1.max(0.0)).sum();
    let neg: f64 = projectiles.iter().map(|p| (-p.1).max(0.0)).sum();
    if pos + neg > 0.0 { (pos - neg) / (pos + neg) } else { 1.0 }
}

fn sample(engine: &Engine<Column>) -> (Sample, Vec<(f64, f64)>) {
    let column = engine.model();
    let (m_a, m_p, m_max) = engine.moments();
    let (phi_a, phi_p) = engine.filling_moments();
    let big = engine.largest();
    let projectiles = engine.projectile_distribution(big);
    let peak = Aggregate { mass: m_p, filling: phi_p };
    let st_p = stopping_time(&column.env, &column.monomer, &peak, column.newton).time * column.env.omega;
    let v_drift = radial_drift(column.env.eta_vk, st_p);
    let s = Sample {
        t: engine.time(),
        events: engine.events(),
        families: engine.families().len(),
        m_a,
        phi_a,
        m_p,
        phi_p,
        m_max,
        stokes_max: engine.families()[big].props.stokes,
        stokes_p: st_p,
        zeta: zeta(&projectiles),
        t_drift: column.env.r / v_drift,
        mass_error: (engine.mass() - engine.initial_mass()) / engine.initial_mass(),
    };
    (s, projectiles)
}

fn snapshot(engine: &Engine<Column>) -> Snapshot {
    let (s, projectiles) = sample(engine);
    let families = engine
        .families()
        .iter()
        .map(|f| FamilyPoint { mass: f.mass, filling: f.filling, particles: f.particles(), stokes: f.props.stokes })
        .collect();
    Snapshot { t: engine.time(), families, sample: s, projectiles }
}

/// When a run hands its state so far to an observer (live views only: the
/// result never depends on it). Where the platform has a clock the first view
/// comes after 0.05 s and later ones every 0.5 s. WebAssembly in a browser
/// has no clock in the standard library (`Instant::now` panics there), so
/// there views come every [`Pace::STEPS`] steps of the run instead.
struct Pace {
    #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
    shown: std::time::Instant,
    #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
    interval: f64,
    #[cfg(all(target_family = "wasm", target_os = "unknown"))]
    steps: u32,
}

impl Pace {
    /// Steps between two views where there is no clock.
    #[cfg(all(target_family = "wasm", target_os = "unknown"))]
    const STEPS: u32 = 250;

    #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
    fn start() -> Pace {
        Pace { shown: std::time::Instant::now(), interval: 0.05 }
    }

    #[cfg(all(target_family = "wasm", target_os = "unknown"))]
    fn start() -> Pace {
        Pace { steps: 0 }
    }

    /// Called once a step: whether to show the run now.
    #[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
    fn due(&mut self) -> bool {
        let due = self.shown.elapsed().as_secs_f64() > self.interval;
        if due {
            self.interval = 0.5;
            self.shown = std::time::Instant::now();
        }
        due
    }

    /// Called once a step: whether to show the run now.
    #[cfg(all(target_family = "wasm", target_os = "unknown"))]
    fn due(&mut self) -> bool {
        self.steps += 1;
        let due = self.steps >= Self::STEPS;
        if due {
            self.steps = 0;
        }
        due
    }
}

impl RunConfig {
    /// Checks the configuration.
    pub fn check(&self) -> Result<(), PhysicsError> {
        let bad = |what: &str| Err(PhysicsError::Invalid(what.to_string()));
        if !(self.column_mass > 0.0 && self.column_mass.is_finite()) {
            return bad("the column mass must be finite and > 0");
        }
        if self.snapshots.is_empty() || self.snapshots.iter().any(|t| !(*t > 0.0 && t.is_finite())) {
            return bad("snapshot times must be finite and > 0");
        }
        if self.snapshots.windows(2).any(|w| w[1] < w[0]) {
            return bad("snapshot times must ascend");
        }
        if self.column.env.dust_surface_density.is_nan() || self.column.env.dust_surface_density <= 0.0 {
            return bad("the dust surface density must be > 0");
        }
        Ok(())
    }

    /// Runs with `seed`; `tick` is called now and then with the fraction of
    /// the run done (in log time) and stops the run when it returns false.
    pub fn run(&self, seed: u64, tick: &(dyn Fn(f64) -> bool + Sync)) -> Result<Run, PhysicsError> {
        self.run_observed(seed, tick, &|_| {})
    }

    /// As [`RunConfig::run`], and hands the run so far (with a snapshot of
    /// now appended) to `observe` after 0.05 s and then about twice a
    /// second, for live display.
    pub fn run_observed(
        &self,
        seed: u64,
        tick: &(dyn Fn(f64) -> bool + Sync),
        observe: &(dyn Fn(&Run) + Sync),
    ) -> Result<Run, PhysicsError> {
        self.check()?;
        let column = self.column;
        let mono = column.monomer;
        let sigma_d = column.env.dust_surface_density;
        let area = self.column_mass / sigma_d;
        let particles = self.column_mass / mono.mass();
        let settings = Settings { seed, ..self.settings };
        let mut engine = Engine::new(column, Body { mass: mono.mass(), filling: 1.0 }, particles, area, settings)
            .map_err(|e| PhysicsError::Invalid(e.to_string()))?;
        let t_end = *self.snapshots.last().unwrap_or(&0.0);
        // History: log-spaced from the first collision time scale to the end,
        // 100 linear steps (for late steady states), and whenever m_p has
        // grown by the same factor as a log step (for fast late growth).
        let t0 = 1.0 / engine.total_rate().max(1e-300) * 10.0;
        let per = self.history_per_decade.max(1) as f64;
        let n_hist = ((t_end / t0).log10().max(0.0) * per).ceil() as usize + 1;
        let mut marks: Vec<(f64, bool)> = (0..n_hist)
            .map(|k| (t0 * 10f64.powf(k as f64 / per), false))
            .chain((1..100).map(|k| (t_end * k as f64 / 100.0, false)))
            .filter(|(t, _)| *t < t_end)
            .chain(self.snapshots.iter().map(|&t| (t, true)))
            .collect();
        let growth_step = 10f64.powf(1.0 / per);
        let mut sampled_mass = engine.moments().1;
        crate::sorting::sort_by_key(&mut marks, |a| a.0);
        let mut snapshots = Vec::new();
        let mut history = Vec::new();
        let mut ended = "end time";
        let ln_span = (t_end / t0).ln().max(1e-9);
        let mut pace = Pace::start();
        let so_far = |engine: &Engine<Column>, snapshots: &[Snapshot], history: &[Sample]| {
            let mut snaps = snapshots.to_vec();
            snaps.push(snapshot(engine));
            Run {
                seed,
                snapshots: snaps,
                history: history.to_vec(),
                events: engine.events(),
                ended: "running",
                surface_density: sigma_d,
                area,
                tally: engine.tally(),
            }
        };
        'outer: for (t, is_snapshot) in marks {
            while engine.time() < t {
                if engine.events() >= self.max_events {
                    ended = ENDED_AT_EVENT_LIMIT;
                    break 'outer;
                }
                if !engine.run_until(t, 250.min(self.max_events - engine.events())) {
                    ended = "no more collisions";
                    break 'outer;
                }
                let m_p = engine.moments().1;
                if m_p > sampled_mass * growth_step || m_p < sampled_mass / growth_step {
                    history.push(sample(&engine).0);
                    sampled_mass = m_p;
                }
                let in_log = ((engine.time().max(t0) / t0).ln() / ln_span).clamp(0.0, 1.0);
                let done = 0.5 * in_log + 0.5 * (engine.time() / t_end).min(1.0);
                if !tick(done) {
                    ended = "cancelled";
                    break 'outer;
                }
                if pace.due() {
                    observe(&so_far(&engine, &snapshots, &history));
                }
                if engine.moments().1 >= self.stop_mass {
                    ended = "peak mass reached";
                    history.push(sample(&engine).0);
                    snapshots.push(snapshot(&engine));
                    break 'outer;
                }
            }
            if is_snapshot {
                snapshots.push(snapshot(&engine));
            }
            history.push(sample(&engine).0);
            sampled_mass = engine.moments().1;
        }
        Ok(Run {
            seed,
            snapshots,
            history,
            events: engine.events(),
            ended,
            surface_density: sigma_d,
            area,
            tally: engine.tally(),
        })
    }

    /// Runs seeds `seed, seed + 1, …` in parallel; each run depends only on
    /// its seed, so the result does not depend on the thread count.
    pub fn run_seeds(&self, runs: usize, tick: &(dyn Fn(f64) -> bool + Sync)) -> Result<Vec<Run>, PhysicsError> {
        self.run_seeds_observed(runs, tick, &|_| {})
    }

    /// As [`RunConfig::run_seeds`], handing the first run so far to `observe`.
    pub fn run_seeds_observed(
        &self,
        runs: usize,
        tick: &(dyn Fn(f64) -> bool + Sync),
        observe: &(dyn Fn(&Run) + Sync),
    ) -> Result<Vec<Run>, PhysicsError> {
        self.run_seeds_mapped(runs, tick, observe, |ks, run| {
            crate::parallel::longest_first(ks, run).into_iter().collect()
        })
    }

    /// As [`RunConfig::run_seeds_observed`], with the runs mapped over their
    /// numbers `0..runs` by `map` (which may share them among processes:
    /// [`crate::scene::Progress::units`], or let them take turns on the
    /// cores: [`crate::parallel::longest_first`]; each run reports its fraction
    /// done to its [`Turn`]).
    pub fn run_seeds_mapped<E>(
        &self,
        runs: usize,
        tick: &(dyn Fn(f64) -> bool + Sync),
        observe: &(dyn Fn(&Run) + Sync),
        map: impl FnOnce(&[usize], &(dyn Fn(&usize, &Turn) -> Result<Run, PhysicsError> + Sync)) -> Result<Vec<Run>, E>,
    ) -> Result<Vec<Run>, E> {
        let progress: Vec<std::sync::atomic::AtomicU32> =
            (0..runs).map(|_| std::sync::atomic::AtomicU32::new(0)).collect();
        let report = |k: usize, f: f64| {
            progress[k].store((f * 1e6) as u32, std::sync::atomic::Ordering::Relaxed);
            let total: f64 =
                progress.iter().map(|p| p.load(std::sync::atomic::Ordering::Relaxed) as f64 / 1e6).sum::<f64>();
            tick(total / runs as f64)
        };
        map(&(0..runs).collect::<Vec<_>>(), &|&k: &usize, turn: &Turn| {
            self.run_number(
                k,
                &|k, f| {
                    turn.tick(f);
                    report(k, f)
                },
                observe,
            )
        })
    }

    /// Run `k` (seed `seed + k`; the first one observed), reporting its
    /// fraction done as `report(k, f)`. Not inlined: every mapping of
    /// [`RunConfig::run_seeds_mapped`] calls this one copy of the engine.
    #[inline(never)]
    pub fn run_number(
        &self,
        k: usize,
        report: &(dyn Fn(usize, f64) -> bool + Sync),
        observe: &(dyn Fn(&Run) + Sync),
    ) -> Result<Run, PhysicsError> {
        let seed = self.settings.seed + k as u64;
        if k == 0 { self.run_observed(seed, &|f| report(k, f), observe) } else { self.run(seed, &|f| report(k, f)) }
    }
}

/// Mean and standard deviation over runs of the normalised mass distribution
/// m²f(m)/ρ_d (mass fraction per ln m) at snapshot `index`, in bins of
/// `per_decade` per decade: (bin centre, mean, σ).
pub fn mass_distribution(runs: &[Run], index: usize, per_decade: usize) -> Vec<(f64, f64, f64)> {
    let mut bins: std::collections::BTreeMap<i64, Vec<f64>> = std::collections::BTreeMap::new();
    let n = per_decade.max(1) as f64;
    let width = std::f64::consts::LN_10 / n;
    let used: Vec<&Run> = runs.iter().filter(|r| r.snapshots.len() > index).collect();
    for (k, r) in used.iter().enumerate() {
        let total: f64 = r.surface_density * r.area;
        for f in &r.snapshots[index].families {
            let b = (f.mass.log10() * n).floor() as i64;
            let v = bins.entry(b).or_insert_with(|| vec![0.0; used.len()]);
            v[k] += f.mass * f.particles / total / width;
        }
    }
    bins.into_iter()
        .map(|(b, v)| {
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let var = if v.len() > 1 {
                v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (v.len() - 1) as f64
            } else {
                0.0
            };
            (10f64.powf((b as f64 + 0.5) / n), mean, var.sqrt())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::aggregate::Thresholds;
    use crate::physics::constants::AU;
    use crate::physics::disk::GasDisk;
    use crate::physics::monte_carlo::OwnedRow;

    #[test]
    fn the_loop_over_a_row_equals_its_pairs_one_at_a_time_to_the_bit() {
        // The loop without vectors and on every vector unit this processor
        // has, with the compaction law in the loop and without; 403 families,
        // so that four-pair steps leave a tail (the build that runs is held
        // to one pair at a time through `Model::pair_data_row` in
        // tests/monte_carlo.rs too).
        use column_row::Vectors;
        use rand::{Rng, SeedableRng};
        let units = match Vectors::found() {
            Vectors::Avx512 => vec![Vectors::None, Vectors::Avx2, Vectors::Avx512],
            Vectors::Avx2 => vec![Vectors::None, Vectors::Avx2],
            Vectors::Simd128 => vec![Vectors::None, Vectors::Simd128],
            Vectors::None => vec![Vectors::None],
        };
        let mut rng = rand::rngs::StdRng::seed_from_u64(12);
        let mono = Monomer::ice();
        let m0 = mono.mass();
        let cases = [
            (f64::INFINITY, 80.0, f64::INFINITY, Compaction::Collisional),
            (20.0, 80.0, f64::INFINITY, Compaction::Full),
            (1e-3, 5.0, f64::INFINITY, Compaction::Full),
            (0.5, 10.0, 1e-3, Compaction::Collisional),
        ];
        for (v_eros, v_frag, v_bounce, compaction) in cases {
            let column = Column {
                env: GasDisk::mmsn(1e-3, 0.01).local(5.0 * AU),
                monomer: mono,
                thresholds: Thresholds { v_frag, v_eros, v_bounce, r_crit: 1e-2 },
                c1: 1.0,
                compaction,
                turbulence: TurbulenceModel::Thesis,
                epsilon: 0.1,
                newton: true,
            };
            let rule = PairRule { volume: 3.7e15, f_m: 0.1, f_phi: 0.1 };
            let families: Vec<Family<Props>> = (0..403)
                .map(|n| {
                    let mass = m0 * 10f64.powf(rng.random_range(0.0..28.0));
                    let filling = if n % 3 == 0 { 1.0 } else { 10f64.powf(rng.random_range(-5.0..0.0)) };
                    let props = column.props(Body { mass, filling });
                    Family { mass, filling, groups: 1.0, zoom: 0, props }
                })
                .collect();
            let mut lanes = Lanes::default();
            for (i, f) in families.iter().enumerate() {
                column.set_lane(&mut lanes, i, f);
            }
            let k = Constants::of(&column);
            let row = column.row_constants(&k, &rule);
            for lead in [0, 1, 2, 57, 399, 402] {
                let a = &families[lead];
                let one = |j: usize| {
                    let (rate, effect) = column.pair_with(&k, a, &families[j]);
                    rule.data(a, &families[j], rate, effect)
                };
                for (units, compact) in units.iter().flat_map(|&u| [(u, false), (u, true)]) {
                    let mut out = OwnedRow::new(families.len());
                    column_row::loop_row(units, compact, &row, &Lead::of(a, k.rho0), &lanes, out.row(), one);
                    for j in 0..out.len() {
                        let (pair, exact) = (out.get(j), one(j));
                        assert_eq!(
                            (pair.c.to_bits(), pair.headroom.to_bits()),
                            (exact.c.to_bits(), exact.headroom.to_bits()),
                            "{compaction:?}, v_eros {v_eros}: pair {lead}, {j}, {units:?}, compaction law in the loop: {compact}"
                        );
                    }
                }
            }
        }
    }

    /// A column eroding at `v_eros` (m/s), as in the tests below.
    fn eroding(v_eros: f64) -> Column {
        Column {
            env: GasDisk::mmsn(1e-3, 0.01).local(5.0 * AU),
            monomer: Monomer::ice(),
            thresholds: Thresholds { v_frag: 80.0, v_eros, v_bounce: f64::INFINITY, r_crit: 1e-2 },
            c1: 1.0,
            compaction: Compaction::Full,
            turbulence: TurbulenceModel::Thesis,
            epsilon: 0.1,
            newton: true,
        }
    }

    #[test]
    fn fragments_are_monomers_at_least_and_carry_exactly_the_mass_they_take() {
        // Projectiles from a tenth of a monomer to 10⁴ monomers, on targets
        // 100 to 10⁸ times heavier, eroding and shattering: the fragments
        // of one collision carry the mass that leaves, and none is lighter
        // than a monomer (sub-monomer fragments were counted as if they
        // kept their own mass, and created mass).
        let shattering =
            Column { thresholds: Thresholds { v_frag: 1e-3, ..eroding(1e-2).thresholds }, ..eroding(1e-2) };
        let mut seen = (0, 0);
        for column in [eroding(1e-2), shattering] {
            let m0 = column.monomer.mass();
            let family = |mass: f64| {
                let body = Body { mass, filling: 0.5 };
                Family { mass, filling: 0.5, groups: 1.0, zoom: 0, props: column.props(body) }
            };
            for p in [0.1, 0.5, 0.999, 1.0, 3.0, 1e4].map(|x| x * m0) {
                for ratio in [1.0, 3.0, 1e2, 1e4, 1e8] {
                    let (t, q) = (family(ratio * p), family(p));
                    let (fragment, count, leaves) = match column.collide(&t, &q) {
                        Collision::Erode { loss, fragment, count } => {
                            seen.0 += 1;
                            (fragment, count, loss + p)
                        }
                        Collision::Shatter { fragment, count } => {
                            seen.1 += 1;
                            (fragment, count, t.mass + p)
                        }
                        // Slower pairs stick.
                        Collision::Stick { .. } | Collision::Bounce => continue,
                    };
                    // (m₀ itself may differ in its last bit from one call site to another.)
                    assert!(fragment.mass >= m0 * (1.0 - 1e-14), "a fragment of {:e} m0", fragment.mass / m0);
                    let carried = count * fragment.mass;
                    assert!(
                        (carried / leaves - 1.0).abs() < 1e-13,
                        "{carried:e} kg leave as fragments, {leaves:e} kg left"
                    );
                }
            }
        }
        assert!(seen.0 > 3 && seen.1 > 0, "(eroding, shattering) cases: {seen:?}");
    }

    #[test]
    fn the_lanes_keys_and_rates_follow_the_families_through_every_change() {
        // Erosion at 1 m/s: families are added, merged, removed and
        // re-zoomed from the first events on.
        let column = Column {
            env: GasDisk::mmsn(1e-3, 0.01).local(5.0 * AU),
            monomer: Monomer::ice(),
            thresholds: Thresholds { v_frag: 80.0, v_eros: 1e-3, v_bounce: f64::INFINITY, r_crit: 1e-2 },
            c1: 1.0,
            compaction: Compaction::Full,
            turbulence: TurbulenceModel::Thesis,
            epsilon: 0.1,
            newton: true,
        };
        let mono = column.monomer;
        let settings = Settings { groups_per_decade: 10.0, ..Settings::default() };
        let first = Body { mass: mono.mass(), filling: 1.0 };
        let mut engine = Engine::new(column, first, 1e21 / mono.mass(), 1e21, settings).expect("valid");
        let mut tally = engine.tally();
        for _ in 0..20_000 {
            assert!(engine.step());
            assert!(engine.mirrors_match(), "after {} events", engine.events());
            if let Err(e) = engine.rates_match(1e-6) {
                panic!("after {} events: {e}", engine.events());
            }
            tally = engine.tally();
        }
        assert!(tally.erode > 100 && tally.merges > 100 && tally.rezooms > 10, "{tally:?}");
    }
}
