//! The semi-analytical growth model of the mass-dominating particle
//! (thesis Sect. 4.5, Sect. 5.2.4, App. 5.C): dm/dt = Σ_d σ_col v_rel /
//! ((2π)^{1/2} h_d) (4.35) and dR/dt = −v_drift (4.36), with the filling
//! factor set by hit-and-stick growth, collisional compaction, and gas and
//! self-gravity compaction.
//!
//! Collisional compaction follows this project's reconstruction (Okuzumi et
//! al. 2012 Eq. 31 is not available here): compaction starts when the
//! same-size impact energy m v²/4 exceeds 3bE_roll (b = 0.15); from there the
//! filling factor follows Suyama et al.'s (2008) law for equal-mass
//! compressive collisions, φ ∝ (E_imp/(bN E_roll))^{3/10} N^{-1/5}, made
//! continuous at the onset and never below the hit-and-stick value. In the
//! Epstein/turbulent, Stokes/turbulent and Ωt_s > 1 regimes this gives the
//! closed forms φ ∝ m^{-1/8}, const and m^{-1/5}.

use super::aggregate::{
    Aggregate, CompactionConstants, Monomer, Particle, R_CRIT, RelativeVelocity, Thresholds, TurbulenceModel,
    dust_scale_height, gas_compaction_filling_with, gravity_filling, radial_drift, relative_velocity, stopping_time,
    stopping_time_and_radius,
};
use super::disk::{GasDisk, Local};
use super::tabled::{self, Bounds};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How the filling factor evolves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Porosity {
    /// Compact spheres, φ = 1.
    Compact,
    /// Hit-and-stick growth and collisional compaction only.
    Collisional,
    /// Collisional, gas-pressure and self-gravity compaction.
    Full,
}

/// Why a track stopped growing or ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Stop {
    /// Reached the planetesimal mass.
    Planetesimal,
    /// Drifted inside the inner edge.
    InnerEdge,
    /// The time limit was reached.
    TimeLimit,
    /// The step budget ran out.
    Steps,
}

/// The semi-analytical model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GrowthModel {
    /// Gas disk.
    pub disk: GasDisk,
    /// Monomers.
    pub monomer: Monomer,
    /// Filling-factor model.
    pub porosity: Porosity,
    /// Collision thresholds.
    pub thresholds: Thresholds,
    /// Turbulence model.
    pub turbulence: TurbulenceModel,
    /// Dispersion ε of the mass-to-area ratio (0.1).
    pub epsilon: f64,
    /// Count differential settling (at one dust scale height) among the
    /// relative velocities, as ch. 4 does (Sect. 4.2.2). Off: the velocities
    /// of App. 5.B, Brownian motion, turbulence and radial and azimuthal
    /// drift at the midplane, where settling vanishes.
    pub settling: bool,
    /// Include Newton drag.
    pub newton: bool,
    /// Let the particle drift (false: a local model at fixed R).
    pub drift: bool,
    /// Planetesimal mass, kg (10¹⁶ g).
    pub planetesimal_mass: f64,
    /// Inner edge, m.
    pub inner_edge: f64,
    /// Growth per step, Δln m.
    pub dlnm: f64,
    /// Largest step as a fraction of the drift time R/|Ṙ| (0.05, Sect. 5.2.5).
    pub drift_step: f64,
    /// The second-order scheme: advance mass and radius with the rates at
    /// the middle of the step (mass, radius and filling factor there), end
    /// the step exactly at the planetesimal mass or the inner edge, and hold
    /// the first-regime growth time at its value where the regime is
    /// entered. False: the thesis's first-order scheme (rates at the start of
    /// the step, the held value where a step first lands in the regime).
    pub midpoint: bool,
}

/// A [`GrowthModel`] ready for a run of steps: the constants its monomers
/// fix in the compaction laws (the rolling energy and logarithms built on
/// it) are taken once, where each step would otherwise take them twice.
#[derive(Debug, Clone, Copy)]
pub struct Stepper<'a> {
    model: &'a GrowthModel,
    compaction: CompactionConstants,
}

impl Stepper<'_> {
    /// [`GrowthModel::step`], with the same result to the last bit.
    pub fn step(
        &self,
        s: &mut GrowthState,
        sigma_d: Option<&dyn Fn(f64, f64) -> f64>,
        t_until: f64,
    ) -> (TrackPoint, Option<Stop>) {
        self.model.step_with(&self.compaction, s, sigma_d, t_until)
    }
}

/// Growth and drift rates of a particle at one place.
struct Rates {
    env: super::disk::Local,
    stopping: super::aggregate::Stopping,
    stokes: f64,
    radius: f64,
    v_rel: super::aggregate::RelativeVelocity,
    /// m/ṁ, s, before the first-regime rule.
    t_grow: f64,
    /// The first turbulence regime below St_η, where t_grow is held.
    first_regime: bool,
    /// |Ṙ|, m s⁻¹.
    v_drift: f64,
}

/// The filling factor after a step and what set it.
struct Filling {
    /// Filling factor.
    phi: f64,
    /// Collisional compaction onset: (mass, φ, E/N).
    onset: Option<(f64, f64, f64)>,
    /// Gas-pressure compaction sets it.
    gas: bool,
    /// Self-gravity compaction sets it.
    gravity: bool,
}

/// One point of a track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackPoint {
    /// Time, s.
    pub t: f64,
    /// Radius in the disk, m.
    pub r: f64,
    /// Mass of the mass-dominating particle, kg.
    pub mass: f64,
    /// Filling factor.
    pub filling: f64,
    /// Aggregate radius, m.
    pub radius: f64,
    /// Stokes number Ωt_s.
    pub stokes: f64,
    /// Same-size collision velocity, m s⁻¹.
    pub v_rel: f64,
    /// Velocity against monomers, m s⁻¹.
    pub v_monomer: f64,
    /// Growth time m/ṁ, s (infinite when growth is halted).
    pub t_grow: f64,
    /// Drift time R/|Ṙ|, s.
    pub t_drift: f64,
    /// Growth is halted by fragmentation, bouncing or erosion.
    pub halted: bool,
}

/// Points of Fig. 4.8 where the track first reaches a condition: (mass, φ).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Markers {
    /// a = λ_mfp.
    pub radius_mfp: Option<[f64; 2]>,
    /// t_s = t_η.
    pub kolmogorov: Option<[f64; 2]>,
    /// Ωt_s = α.
    pub settling: Option<[f64; 2]>,
    /// Ωt_s = 1.
    pub stokes_one: Option<[f64; 2]>,
    /// First collisional compaction.
    pub collisional: Option<[f64; 2]>,
    /// First gas-pressure compaction.
    pub gas: Option<[f64; 2]>,
    /// First self-gravity compaction.
    pub gravity: Option<[f64; 2]>,
}

/// A growth track.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The points.
    pub points: Vec<TrackPoint>,
    /// Why it ended.
    pub stop: Stop,
    /// Turning points.
    pub markers: Markers,
    /// Why growth was last halted, if it was.
    pub halted_by: Option<&'static str>,
}

impl GrowthModel {
    /// The model of ch. 4 at 5 AU in the MMSN with α = 10⁻³ and 0.1 µm ice, perfect sticking.
    pub fn chapter4(porosity: Porosity) -> GrowthModel {
        GrowthModel {
            disk: GasDisk::mmsn(1e-3, 1e-2),
            monomer: Monomer::ice(),
            porosity,
            thresholds: Thresholds {
                v_frag: f64::INFINITY,
                v_eros: f64::INFINITY,
                v_bounce: f64::INFINITY,
                r_crit: R_CRIT,
            },
            turbulence: TurbulenceModel::Thesis,
            epsilon: 0.1,
            settling: true,
            newton: true,
            drift: true,
            planetesimal_mass: 1e13,
            inner_edge: super::constants::AU,
            dlnm: 0.1,
            drift_step: 0.05,
            midpoint: false,
        }
    }

    /// A fresh particle state: monomers at radius `r0` (m).
    pub fn start(&self, r0: f64) -> GrowthState {
        GrowthState {
            t: 0.0,
            r: r0,
            mass: self.monomer.mass(),
            filling: 1.0,
            onset: None,
            frozen_t_grow: None,
            previous: None,
            markers: Markers::default(),
            halted_by: None,
            disk_here: None,
        }
    }

    /// The relative velocity of two particles with this model's sources.
    fn relative_velocity(&self, env: &Local, p1: &Particle, p2: &Particle) -> RelativeVelocity {
        let mut v = relative_velocity(env, p1, p2, self.turbulence, self.epsilon);
        if !self.settling {
            v.settling = 0.0;
        }
        v
    }

    /// Growth and drift rates of a particle of mass `m` (kg) and filling
    /// factor `phi` at radius `r` (m) in dust of surface density `sigma_d`
    /// (kg m⁻²; `None`: the disk's own).
    fn rates(&self, m: f64, phi: f64, r: f64, sigma_d: Option<f64>) -> Rates {
        self.rates_in(self.disk.local(r), m, phi, sigma_d)
    }

    /// [`GrowthModel::rates`] in the environment `env` (the disk's at the radius).
    fn rates_in(&self, env: Local, m: f64, phi: f64, sigma_d: Option<f64>) -> Rates {
        let mono = self.monomer;
        let agg = Aggregate { mass: m, filling: phi };
        let (stopping, a) = stopping_time_and_radius(&env, &mono, &agg, self.newton);
        let st = stopping.time * env.omega;
        let me = Particle { mass: m, stokes: st };
        let rv = self.relative_velocity(&env, &me, &me);
        let h_d = dust_scale_height(env.alpha, st) * env.scale_height;
        let sigma = sigma_d.unwrap_or(env.dust_surface_density);
        let m_dot = sigma / ((2.0 * PI).sqrt() * h_d) * PI * (2.0 * a).powi(2) * rv.total();
        let t_grow = if m_dot > 0.0 { m / m_dot } else { f64::INFINITY };
        let first_regime = rv.dominant() == 1 && st < 1.0 / env.reynolds.sqrt();
        let v_drift = radial_drift(env.eta_vk, st);
        Rates { env, stopping, stokes: st, radius: a, v_rel: rv, t_grow, first_regime, v_drift }
    }

    /// Evaluates the state, then advances it by one step, never beyond
    /// `t_until`. `sigma_d` overrides the dust surface density of the disk
    /// (kg m⁻², as a function of time and radius; the batch model uses the
    /// batches' own). Returns the point evaluated before the step and whether
    /// the particle left the disk (planetesimal reached or inner edge crossed;
    /// the state is then final).
    pub fn step(
        &self,
        s: &mut GrowthState,
        sigma_d: Option<&dyn Fn(f64, f64) -> f64>,
        t_until: f64,
    ) -> (TrackPoint, Option<Stop>) {
        self.stepper().step(s, sigma_d, t_until)
    }

    /// The model ready for a run of steps ([`Stepper::step`]): what its
    /// monomers fix in the compaction laws is taken once, not at every step.
    pub fn stepper(&self) -> Stepper<'_> {
        Stepper { model: self, compaction: CompactionConstants::of(&self.monomer) }
    }

    /// [`GrowthModel::step`] with the monomers' compaction constants given.
    fn step_with(
        &self,
        constants: &CompactionConstants,
        s: &mut GrowthState,
        sigma_d: Option<&dyn Fn(f64, f64) -> f64>,
        t_until: f64,
    ) -> (TrackPoint, Option<Stop>) {
        let mono = self.monomer;
        let m0 = mono.mass();
        let (m, phi, r) = (s.mass, s.filling, s.r);
        // The disk here, kept from the step that ended here if there was one.
        let here = match s.disk_here {
            Some(env) if env.r.to_bits() == r.to_bits() => env,
            _ => self.disk.local(r),
        };
        let start = self.rates_in(here, m, phi, sigma_d.map(|f| f(s.t, r)));
        let Rates { env, stopping, stokes: st, radius: a, v_rel: rv, first_regime, v_drift, .. } = start;
        let mono_particle = Particle {
            mass: m0,
            stokes: stopping_time(&env, &mono, &Aggregate { mass: m0, filling: 1.0 }, self.newton).time * env.omega,
        };
        let me = Particle { mass: m, stokes: st };
        let v = rv.total();
        let v_mono = self.relative_velocity(&env, &me, &mono_particle).total();
        let mut t_grow = start.t_grow;
        let st_eta = 1.0 / env.reynolds.sqrt();
        // In the first turbulence regime same-size velocities vanish and the
        // particles grow by sweeping up smaller ones at a roughly constant
        // rate (Sect. 4.5): keep t_grow at its value on entering that regime.
        if first_regime && t_grow.is_finite() {
            let held = match (s.frozen_t_grow, s.previous) {
                (Some(held), _) => held,
                // Entered during the last step: the value where it was entered.
                (None, Some(before)) if self.midpoint => {
                    self.entry_growth_time(before, [s.t, m, phi, r], sigma_d).unwrap_or(t_grow)
                }
                (None, _) => t_grow,
            };
            s.frozen_t_grow = Some(held);
            t_grow = held;
        } else {
            s.frozen_t_grow = None;
        }
        s.previous = if first_regime { None } else { Some([s.t, m, phi, r]) };
        let th = &self.thresholds;
        let halted = if v >= th.v_frag {
            s.halted_by = Some("fragmentation");
            true
        } else if self.porosity == Porosity::Compact && v >= th.v_bounce {
            s.halted_by = Some("bouncing");
            true
        } else if v_mono > th.v_eros {
            s.halted_by = Some("erosion");
            true
        } else {
            !t_grow.is_finite()
        };
        let t_drift = r / v_drift;
        let point = TrackPoint {
            t: s.t,
            r,
            mass: m,
            filling: phi,
            radius: a,
            stokes: st,
            v_rel: v,
            v_monomer: v_mono,
            t_grow: if halted { f64::INFINITY } else { t_grow },
            t_drift,
            halted,
        };
        let here = [m, phi];
        let mk = &mut s.markers;
        if a >= env.mean_free_path && mk.radius_mfp.is_none() {
            mk.radius_mfp = Some(here);
        }
        if stopping.time >= st_eta / env.omega && mk.kolmogorov.is_none() {
            mk.kolmogorov = Some(here);
        }
        if st >= env.alpha && mk.settling.is_none() {
            mk.settling = Some(here);
        }
        if st >= 1.0 && mk.stokes_one.is_none() {
            mk.stokes_one = Some(here);
        }
        if m >= self.planetesimal_mass {
            return (point, Some(Stop::Planetesimal));
        }
        // Time step: a fixed growth in ln m, or a small part of the drift time.
        let mut dt = (t_until - s.t).at_least(0.0);
        if !halted {
            dt = dt.at_most(self.dlnm * t_grow);
        }
        if self.drift {
            dt = dt.at_most(self.drift_step * t_drift);
        }
        // Rates over the step: at its start, or at its middle (with the mass,
        // radius and filling factor there).
        let (mut growth_time, mut drift_speed) = (t_grow, v_drift);
        let (mut lands, mut leaves) = (false, false);
        if self.midpoint && dt > 0.0 {
            let half = 0.5 * dt;
            let m_h = if halted { m } else { m * tabled::exp(half / t_grow) };
            let r_h = if self.drift { r - v_drift * half } else { r };
            if r_h > 0.0 {
                // The disk at the middle, for its filling factor and rates.
                let env_h = if self.drift { self.disk.local(r_h) } else { env };
                let phi_h = if halted { phi } else { self.filling(constants, s.onset, m, phi, v, m_h, &env_h).phi };
                let mid = self.rates_in(env_h, m_h, phi_h, sigma_d.map(|f| f(s.t + half, r_h)));
                growth_time = match s.frozen_t_grow {
                    Some(frozen) if mid.first_regime => frozen,
                    _ => mid.t_grow,
                };
                drift_speed = mid.v_drift;
            }
            // End the step where the particle reaches the planetesimal mass
            // or the inner edge, not beyond.
            if !halted && m * tabled::exp(dt / growth_time) >= self.planetesimal_mass {
                dt = growth_time * (self.planetesimal_mass / m).ln();
                lands = true;
            }
            if self.drift && r - drift_speed * dt <= self.inner_edge {
                dt = (r - self.inner_edge) / drift_speed;
                leaves = true;
            }
        }
        s.t += dt;
        if self.drift {
            s.r = if leaves { self.inner_edge } else { s.r - drift_speed * dt };
            if s.r <= self.inner_edge {
                return (point, Some(Stop::InnerEdge));
            }
        }
        if halted {
            return (point, None);
        }
        let m_new = if lands && !leaves {
            self.planetesimal_mass
        } else if self.midpoint {
            (m * tabled::exp(dt / growth_time)).at_most(self.planetesimal_mass)
        } else {
            m * tabled::exp(dt / growth_time)
        };
        // The disk where the step ends (only gas compaction reads it).
        let env_new = if self.drift && self.porosity == Porosity::Full { self.disk.local(s.r) } else { env };
        let next = self.filling(constants, s.onset, m, phi, v, m_new, &env_new);
        if next.onset != s.onset {
            s.markers.collisional = Some([m, phi]);
        }
        if next.gas && s.markers.gas.is_none() {
            s.markers.gas = Some([m, phi]);
        }
        if next.gravity && s.markers.gravity.is_none() {
            s.markers.gravity = Some([m, phi]);
        }
        s.onset = next.onset;
        s.filling = next.phi;
        s.mass = m_new;
        s.disk_here = Some(env_new);
        (point, None)
    }

    /// The filling factor after growth from mass `m` (kg, filling factor
    /// `phi`, same-size velocity `v`, m s⁻¹) to `m_new` in the environment
    /// `env_new` (the disk's where the step ends), given the collisional
    /// compaction onset so far and the monomers' compaction constants.
    #[allow(clippy::too_many_arguments)]
    fn filling(
        &self,
        constants: &CompactionConstants,
        onset: Option<(f64, f64, f64)>,
        m: f64,
        phi: f64,
        v: f64,
        m_new: f64,
        env_new: &Local,
    ) -> Filling {
        let mono = self.monomer;
        let m0 = mono.mass();
        let e_roll = constants.e_roll;
        let n = m_new / m0;
        let phi_hs = (1.0 / n.sqrt()).at_most(1.0);
        let mut out = Filling { phi: 1.0, onset, gas: false, gravity: false };
        if self.porosity == Porosity::Compact {
            return out;
        }
        let e_per_n = m * v * v / 4.0 / (m / m0);
        let collisional = match onset {
            None if m * v * v / 4.0 > 3.0 * super::monomer::COMPACTION_B * e_roll => {
                out.onset = Some((m, phi, e_per_n));
                phi
            }
            None => phi_hs,
            Some((mc, phic, ec)) => (phic * tabled::exp(0.3 * (e_per_n / ec).ln() - 0.2 * (n / (mc / m0)).ln()))
                .at_least(phi_hs)
                .at_most(1.0),
        };
        if self.porosity != Porosity::Full {
            out.phi = collisional;
            return out;
        }
        let gas = {
            // Only solve for the gas-compaction φ when the gas can compress.
            let trial = Aggregate { mass: m_new, filling: collisional };
            let (stopping, a) = stopping_time_and_radius(env_new, &mono, &trial, self.newton);
            let ts = stopping.time;
            let p_gas = super::aggregate::gas_relative_velocity(env_new.eta_vk, env_new.omega * ts) * m_new
                / (PI * a.powi(2) * ts);
            let p_c = e_roll / mono.radius.powi(3) * collisional.powi(3);
            if p_c < p_gas {
                gas_compaction_filling_with(env_new, &mono, constants, m_new, self.newton, phi)
            } else {
                0.0
            }
        };
        let grav = gravity_filling(&mono, constants, m_new);
        out.gas = gas > collisional && gas >= grav;
        out.gravity = grav > collisional && grav > gas;
        out.phi = collisional.at_least(gas).at_least(grav).at_most(1.0);
        out
    }

    /// The growth time where a step from `before` to `after` (each
    /// [t, m, φ, R]) entered the first turbulence regime, found by bisection
    /// in ln m with t, φ and R interpolated alongside, so the held value does
    /// not depend on where the steps happen to fall. `None` when the start is
    /// already in the regime or a rate is not finite.
    fn entry_growth_time(
        &self,
        before: [f64; 4],
        after: [f64; 4],
        sigma_d: Option<&dyn Fn(f64, f64) -> f64>,
    ) -> Option<f64> {
        let at = |w: f64| {
            let lerp = |k: usize| before[k] + w * (after[k] - before[k]);
            let (t, r) = (lerp(0), lerp(3));
            let m = before[1] * (after[1] / before[1]).powf(w);
            self.rates(m, lerp(2), r, sigma_d.map(|f| f(t, r)))
        };
        if at(0.0).first_regime {
            return None;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if at(mid).first_regime { hi = mid } else { lo = mid }
        }
        Some(at(hi).t_grow).filter(|t| t.is_finite())
    }

    /// Runs a track from monomers at radius `r0` (m) for `t_end` seconds.
    pub fn run(&self, r0: f64, t_end: f64) -> Track {
        let stepper = self.stepper();
        let mut s = self.start(r0);
        let mut points = Vec::new();
        let mut stop = Stop::Steps;
        for _ in 0..200_000 {
            let done = s.t >= t_end;
            let (point, ended) = stepper.step(&mut s, None, t_end);
            points.push(point);
            if let Some(e) = ended {
                stop = e;
                break;
            }
            if done {
                stop = Stop::TimeLimit;
                break;
            }
        }
        Track { points, stop, markers: s.markers, halted_by: s.halted_by }
    }
}

/// The evolving state of one particle (or batch) of the growth model.
#[derive(Debug, Clone, PartialEq)]
pub struct GrowthState {
    /// Time, s.
    pub t: f64,
    /// Radius, m.
    pub r: f64,
    /// Particle mass, kg.
    pub mass: f64,
    /// Filling factor.
    pub filling: f64,
    /// Collisional compaction onset: (mass, φ, E/N).
    onset: Option<(f64, f64, f64)>,
    /// Growth time held in the first turbulence regime, s.
    frozen_t_grow: Option<f64>,
    /// The last evaluated state outside the first turbulence regime: [t, m, φ, R].
    previous: Option<[f64; 4]>,
    /// Turning points reached so far.
    pub markers: Markers,
    /// Why growth was last halted.
    pub halted_by: Option<&'static str>,
    /// The disk where a step ended, where the full model computed it: the
    /// next step starts there (kept only while [`GrowthState::r`] is its
    /// radius; a state is stepped by the model that started it).
    disk_here: Option<Local>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::constants::{AU, YEAR};

    /// A step that starts where the last one ended takes the disk that step
    /// computed there: a drifting track of the full model, which fragmentation
    /// halts (and a halted step drifts without computing the disk where it
    /// ends), is the same to the last bit when every step computes its disk
    /// afresh.
    #[test]
    fn the_disk_kept_between_steps_changes_no_step() {
        let mut model = GrowthModel::chapter4(Porosity::Full);
        model.drift = true;
        model.thresholds.v_frag = 5.0;
        let stepper = model.stepper();
        let (mut kept, mut fresh) = (model.start(20.0 * AU), model.start(20.0 * AU));
        let (mut steps, mut reused) = (0, 0);
        loop {
            fresh.disk_here = None;
            reused += usize::from(kept.disk_here.is_some_and(|e| e.r.to_bits() == kept.r.to_bits()));
            let (a, b) = (stepper.step(&mut kept, None, 1e6 * YEAR), stepper.step(&mut fresh, None, 1e6 * YEAR));
            assert_eq!(a, b, "step {steps}");
            assert_eq!((kept.t, kept.r, kept.mass, kept.filling), (fresh.t, fresh.r, fresh.mass, fresh.filling));
            steps += 1;
            if a.1.is_some() || kept.t >= 1e6 * YEAR || steps == 100_000 {
                break;
            }
        }
        let halted = kept.halted_by.is_some();
        assert!(halted && steps > 100 && reused + 1 >= steps / 2, "{reused} of {steps} steps took the kept disk");
    }

    #[test]
    fn local_perfect_sticking_reaches_planetesimal_mass() {
        let mut model = GrowthModel::chapter4(Porosity::Full);
        model.drift = false;
        let track = model.run(5.0 * AU, 1e6 * YEAR);
        assert_eq!(track.stop, Stop::Planetesimal, "{:?}", track.points.last());
        assert!(
            track.points.iter().all(|p| p.filling > 0.0 && p.filling <= 1.0 && p.stokes > 0.0 && p.v_rel.is_finite())
        );
    }
}
