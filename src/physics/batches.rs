//! The global "dust batch" model of ch. 5: batches of identical particles at
//! many radii grow (5.10) and drift (5.8) in a gas disk; the dust surface
//! density follows from the batch positions (5.6)–(5.7); particles that reach
//! the planetesimal mass become planetesimals, batches inside the inner edge
//! are lost. Streaming-instability conditions of Sect. 5.4.1 are evaluated
//! along the way.
//!
//! Time stepping: batches exchange information only through Σ_d. Σ_d is
//! recomputed at synchronisation times spaced logarithmically in time; between
//! them each batch advances with its own steps (Δln m growth or 5 % of its
//! drift time, the rule of Sect. 5.2.5 applied per batch) in the Σ_d of the
//! last synchronisation.
//!
//! Surface density: the batches, sorted by radius, own the annuli between the
//! geometric midpoints of their neighbours; Σ_d at a batch is the mass of it
//! and its `smoothing` neighbours on each side divided by the area of their
//! annuli, so a few batches in a depleted region do not make spikes.

use super::PhysicsError;
use super::aggregate::dust_scale_height;
use super::constants::{AU, YEAR};
use super::disk::GasDisk;
use super::growth::{GrowthModel, GrowthState, Stop};
use rayon::prelude::*;
use std::f64::consts::PI;

/// What became of a batch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fate {
    /// Still dust.
    Dust,
    /// Became planetesimals at time t (s) and radius r (m).
    Planetesimals {
        /// Time, s.
        t: f64,
        /// Radius, m.
        r: f64,
    },
    /// Drifted inside the inner edge at time t (s).
    Lost {
        /// Time, s.
        t: f64,
    },
}

/// Configuration of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchConfig {
    /// Disk, monomers, porosity, thresholds; its `planetesimal_mass` and `inner_edge` are used.
    pub model: GrowthModel,
    /// Innermost initial radius, m.
    pub r_in: f64,
    /// Outermost initial radius, m.
    pub r_out: f64,
    /// Number of batches.
    pub batches: usize,
    /// Duration, s.
    pub t_end: f64,
    /// Let particles grow (false: the drift-only test of Fig. 5.1).
    pub coagulation: bool,
    /// Synchronisations per decade of time.
    pub syncs_per_decade: usize,
    /// Neighbours on each side in the surface-density smoothing.
    pub smoothing: usize,
    /// Record a frame every this many synchronisations (0: only the last).
    pub frame_every: usize,
}

impl BatchConfig {
    /// The porous perfect-sticking run of Fig. 5.6: M_D = 0.01 M☉, Z₀ = 0.02,
    /// R_c = 30 AU, γ = 1, α = 10⁻³, 0.1 µm ice, 3–200 AU, 10⁶ yr.
    pub fn figure_5_6(batches: usize) -> BatchConfig {
        let mut model = GrowthModel::chapter4(super::growth::Porosity::Full);
        model.disk = GasDisk {
            profile: super::disk::Profile::TruncatedPowerLaw { mass: 0.01, r_c: 30.0, slope: 1.0 },
            cold: false,
            alpha: 1e-3,
            metallicity: 0.02,
        };
        model.dlnm = 0.2;
        BatchConfig {
            model,
            r_in: 3.0 * AU,
            r_out: 200.0 * AU,
            batches,
            t_end: 1e6 * YEAR,
            coagulation: true,
            syncs_per_decade: 160,
            smoothing: 2,
            frame_every: 4,
        }
    }

    /// Checks the configuration.
    pub fn validate(&self) -> Result<(), PhysicsError> {
        let bad = |name, value, reason| Err(PhysicsError::InvalidParameter { name, value, reason });
        if !(self.r_in > 0.0 && self.r_in < self.r_out && self.r_out.is_finite()) {
            return bad("r_in", self.r_in, "need 0 < r_in < r_out");
        }
        if self.r_in <= self.model.inner_edge {
            return bad("r_in", self.r_in, "must lie outside the inner edge");
        }
        if self.batches < 2 {
            return bad("batches", self.batches as f64, "need at least 2 batches");
        }
        if !(self.t_end > 0.0 && self.t_end.is_finite()) {
            return bad("t_end", self.t_end, "must be finite and > 0");
        }
        if let super::disk::Profile::TruncatedPowerLaw { mass, r_c, slope } = self.model.disk.profile {
            if !(mass > 0.0 && mass.is_finite()) {
                return bad("disk mass", mass, "must be finite and > 0");
            }
            if !(r_c > 0.0 && r_c.is_finite()) {
                return bad("R_c", r_c, "must be finite and > 0");
            }
            if !(slope.is_finite() && slope < 2.0) {
                return bad("slope", slope, "must be finite and < 2");
            }
        }
        let z = self.model.disk.metallicity;
        if !(z > 0.0 && z < 1.0) {
            return bad("metallicity", z, "need 0 < Z0 < 1");
        }
        let alpha = self.model.disk.alpha;
        if !(alpha > 0.0 && alpha.is_finite()) {
            return bad("alpha", alpha, "must be finite and > 0");
        }
        Ok(())
    }
}

/// One batch in a frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchSample {
    /// Radius, m.
    pub r: f64,
    /// Particle mass, kg.
    pub mass: f64,
    /// Filling factor.
    pub filling: f64,
    /// Stokes number.
    pub stokes: f64,
    /// Growth time, s (infinite when halted).
    pub t_grow: f64,
    /// Midplane dust-to-gas ratio of 10⁻² ≤ Ωt_s ≤ 1 particles, (ρ*_d/ρ_g) = Z* h_g/h_d (5.13).
    pub loading: f64,
    /// Streaming-instability conditions i), ii) and iv) all hold.
    pub si: bool,
    /// Still dust (not planetesimal, not lost).
    pub dust: bool,
}

/// The state of all batches at one time.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Time, s.
    pub t: f64,
    /// One sample per batch, in the initial order.
    pub batches: Vec<BatchSample>,
    /// Mass in dust, planetesimals and lost inside the inner edge, kg.
    pub budget: [f64; 3],
}

/// A finished run.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchRun {
    /// Total mass of each batch, kg.
    pub masses: Vec<f64>,
    /// Initial radii, m.
    pub initial_radii: Vec<f64>,
    /// Fates at the end.
    pub fates: Vec<Fate>,
    /// Recorded frames (the last one is the end state).
    pub frames: Vec<Frame>,
    /// Total initial dust mass, kg.
    pub total_mass: f64,
}

impl BatchRun {
    /// Outermost initial radius of a batch that became planetesimals, m (0 if none).
    pub fn formation_edge(&self) -> f64 {
        self.fates
            .iter()
            .zip(&self.initial_radii)
            .filter(|(f, _)| matches!(f, Fate::Planetesimals { .. }))
            .map(|(_, r)| *r)
            .fold(0.0, f64::max)
    }

    /// Outermost radius at which planetesimals formed, m (0 if none).
    pub fn outermost_planetesimals(&self) -> f64 {
        self.fates
            .iter()
            .filter_map(|f| if let Fate::Planetesimals { r, .. } = f { Some(*r) } else { None })
            .fold(0.0, f64::max)
    }

    /// Fraction of the initial dust turned into planetesimals by the end.
    pub fn converted_fraction(&self) -> f64 {
        self.frames.last().map_or(0.0, |f| f.budget[1] / self.total_mass)
    }
}

/// A surface-density profile known at sorted radii, interpolated linearly in
/// (ln R, ln Σ) and held constant beyond its ends.
struct Profile1d {
    ln_r: Vec<f64>,
    ln_sigma: Vec<f64>,
}

impl Profile1d {
    fn new(points: &[(f64, f64)], sigma: &[f64]) -> Profile1d {
        let mut pairs: Vec<(f64, f64)> =
            points.iter().zip(sigma).filter(|(_, s)| **s > 0.0).map(|((r, _), s)| (r.ln(), s.ln())).collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (ln_r, ln_sigma) = pairs.into_iter().unzip();
        Profile1d { ln_r, ln_sigma }
    }

    fn at(&self, r: f64) -> f64 {
        let x = r.ln();
        let n = self.ln_r.len();
        if n == 0 {
            return 0.0;
        }
        let j = self.ln_r.partition_point(|&v| v < x);
        if j == 0 {
            return self.ln_sigma[0].exp();
        }
        if j == n {
            return self.ln_sigma[n - 1].exp();
        }
        let (x0, x1) = (self.ln_r[j - 1], self.ln_r[j]);
        let w = if x1 > x0 { (x - x0) / (x1 - x0) } else { 0.0 };
        (self.ln_sigma[j - 1] + w * (self.ln_sigma[j] - self.ln_sigma[j - 1])).exp()
    }
}

/// Annulus edges of sorted radii: geometric midpoints, extended at both ends.
fn edges(radii: &[f64]) -> Vec<f64> {
    let n = radii.len();
    let mut e = Vec::with_capacity(n + 1);
    if n == 1 {
        return vec![radii[0] / 1.05, radii[0] * 1.05];
    }
    e.push(radii[0] / (radii[1] / radii[0]).sqrt());
    for w in radii.windows(2) {
        e.push((w[0] * w[1]).sqrt());
    }
    e.push(radii[n - 1] * (radii[n - 1] / radii[n - 2]).sqrt());
    e
}

/// Smallest half-width, in ln R, of the annulus over which Σ_d is averaged
/// (±5 % in radius, about one gas scale height): batches that converge in
/// radius do not produce an unbounded surface density.
pub const MIN_HALF_WIDTH: f64 = 0.05;

/// Surface density at each of the given (radius, mass) points, kg m⁻²; returned
/// in the input order. Each point's value is the mass of the batches from `k`
/// neighbours inside to `k` outside, divided by the area between their outer
/// cell edges (geometric midpoints to the next batches). Where that annulus is
/// narrower than 2·`half_width` in ln R, it takes one more neighbour on each
/// side until it is not, so converging batches give a bounded density.
pub fn surface_density(points: &[(f64, f64)], k: usize, half_width: f64) -> Vec<f64> {
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| points[a].0.total_cmp(&points[b].0));
    let radii: Vec<f64> = order.iter().map(|&i| points[i].0).collect();
    let e = edges(&radii);
    let mut cumulative = Vec::with_capacity(n + 1);
    cumulative.push(0.0);
    for &i in &order {
        cumulative.push(cumulative[cumulative.len() - 1] + points[i].1);
    }
    let min_ratio = (2.0 * half_width.max(0.0)).exp();
    let mut out = vec![0.0; n];
    for (pos, &i) in order.iter().enumerate() {
        let mut lo = pos.saturating_sub(k);
        let mut hi = (pos + k).min(n - 1);
        while e[hi + 1] < min_ratio * e[lo] && (lo > 0 || hi < n - 1) {
            lo = lo.saturating_sub(1);
            hi = (hi + 1).min(n - 1);
        }
        let mass = cumulative[hi + 1] - cumulative[lo];
        out[i] = mass / (PI * (e[hi + 1].powi(2) - e[lo].powi(2)));
    }
    out
}

/// Midplane turbulence from Kelvin–Helmholtz and streaming instabilities (5.16):
/// α_mp = [(C₁C_eff ηZ)^{-2/3} + (C₂C_eff η/Z)^{-2}]⁻¹ Ωt_s, C₁ = 1, C₂ = 1.6, C_eff = 0.19.
pub fn alpha_midplane(eta: f64, z: f64, stokes: f64) -> f64 {
    let c_eff = 0.19;
    1.0 / ((1.0 * c_eff * eta * z).powf(-2.0 / 3.0) + (1.6 * c_eff * eta / z).powi(-2)) * stokes
}

/// Largest midplane dust-to-gas ratio under α_mp (5.17): Z*(Ωt_s/α_mp)^{1/2}, independent of Ωt_s.
pub fn max_loading(eta: f64, z: f64) -> f64 {
    z * (1.0 / alpha_midplane(eta, z, 1.0)).sqrt()
}

/// Runs the batch model.
pub fn run(cfg: &BatchConfig, cancelled: &(dyn Fn(f64) -> bool + Sync)) -> Result<BatchRun, PhysicsError> {
    cfg.validate()?;
    let disk = cfg.model.disk;
    let n = cfg.batches;
    let radii: Vec<f64> = (0..n).map(|i| cfg.r_in * (cfg.r_out / cfg.r_in).powf(i as f64 / (n - 1) as f64)).collect();
    let e = edges(&radii);
    // Batch masses from the initial Σ_d = Z₀Σ_g, integrated over each annulus.
    let masses: Vec<f64> = (0..n)
        .map(|i| {
            let sub = 64;
            (0..sub)
                .map(|j| {
                    let a = e[i] * (e[i + 1] / e[i]).powf(j as f64 / sub as f64);
                    let b = e[i] * (e[i + 1] / e[i]).powf((j + 1) as f64 / sub as f64);
                    let r = (a * b).sqrt();
                    2.0 * PI * r * disk.dust_surface_density(r) * (b - a)
                })
                .sum()
        })
        .collect();
    let total_mass: f64 = masses.iter().sum();
    let mut model = cfg.model;
    model.drift = true;
    if !cfg.coagulation {
        // Drift only: particles keep their initial (monomer) size.
        model.thresholds.v_frag = 0.0;
    }
    let mut states: Vec<GrowthState> = radii.iter().map(|&r| model.start(r)).collect();
    let mut fates = vec![Fate::Dust; n];
    let mut latest: Vec<BatchSample> = vec![
        BatchSample {
            r: 0.0,
            mass: 0.0,
            filling: 1.0,
            stokes: 0.0,
            t_grow: 0.0,
            loading: 0.0,
            si: false,
            dust: true
        };
        n
    ];
    // Synchronisation times.
    let t_first = YEAR.min(cfg.t_end);
    let decades = (cfg.t_end / t_first).log10().max(0.0);
    let syncs = ((decades * cfg.syncs_per_decade as f64).ceil() as usize).max(1);
    let times: Vec<f64> = std::iter::once(t_first)
        .chain((1..=syncs).map(|k| t_first * (cfg.t_end / t_first).powf(k as f64 / syncs as f64)))
        .collect();
    let mut frames = Vec::new();
    for (k, &t_next) in times.iter().enumerate() {
        if cancelled(k as f64 / times.len() as f64) {
            return Err(PhysicsError::InvalidParameter { name: "run", value: 0.0, reason: "cancelled" });
        }
        let dust: Vec<usize> = (0..n).filter(|&i| fates[i] == Fate::Dust).collect();
        let sigma_points: Vec<(f64, f64)> = dust.iter().map(|&i| (states[i].r, masses[i])).collect();
        let sigma = surface_density(&sigma_points, cfg.smoothing, MIN_HALF_WIDTH);
        let profile = Profile1d::new(&sigma_points, &sigma);
        // Advance every dust batch to t_next with Σ_d of this synchronisation
        // read at its current radius.
        let results: Vec<(usize, GrowthState, Option<Stop>, super::growth::TrackPoint)> = dust
            .par_iter()
            .map(|&i| {
                let mut s = states[i].clone();
                let mut last = None;
                let mut ended = None;
                for _ in 0..100_000 {
                    let here = profile.at(s.r);
                    let (p, e) = model.step(&mut s, Some(here), t_next);
                    last = Some(p);
                    if e.is_some() {
                        ended = e;
                        break;
                    }
                    if s.t >= t_next {
                        break;
                    }
                }
                let point = last.unwrap_or_else(|| model.step(&mut s.clone(), Some(profile.at(s.r)), s.t).0);
                (i, s, ended, point)
            })
            .collect();
        for (i, s, ended, p) in results {
            match ended {
                Some(Stop::Planetesimal) => fates[i] = Fate::Planetesimals { t: s.t, r: s.r },
                Some(Stop::InnerEdge) => fates[i] = Fate::Lost { t: s.t },
                _ => {}
            }
            latest[i] = BatchSample {
                r: s.r,
                mass: s.mass,
                filling: s.filling,
                stokes: p.stokes,
                t_grow: p.t_grow,
                loading: 0.0,
                si: false,
                dust: fates[i] == Fate::Dust,
            };
            states[i] = s;
        }
        // Streaming-instability diagnostics: Z* from batches with 10⁻² ≤ Ωt_s ≤ 1.
        let dust_now: Vec<usize> = (0..n).filter(|&i| fates[i] == Fate::Dust).collect();
        let star: Vec<(f64, f64)> = dust_now
            .iter()
            .map(|&i| {
                let st = latest[i].stokes;
                (latest[i].r, if (1e-2..=1.0).contains(&st) { masses[i] } else { 0.0 })
            })
            .collect();
        let sigma_star = surface_density(&star, cfg.smoothing, MIN_HALF_WIDTH);
        for (j, &i) in dust_now.iter().enumerate() {
            let b = &mut latest[i];
            let z_star = sigma_star[j] / disk.surface_density(b.r);
            b.loading = z_star / dust_scale_height(disk.alpha, b.stokes);
            let omega = disk.omega(b.r);
            b.si = (1e-2..=1.0).contains(&b.stokes) && b.loading >= 1.0 && b.t_grow > 1.0 / omega;
        }
        let last = k + 1 == times.len();
        if last || (cfg.frame_every > 0 && k % cfg.frame_every == 0) {
            let mut budget = [0.0; 3];
            for i in 0..n {
                match fates[i] {
                    Fate::Dust => budget[0] += masses[i],
                    Fate::Planetesimals { .. } => budget[1] += masses[i],
                    Fate::Lost { .. } => budget[2] += masses[i],
                }
            }
            frames.push(Frame { t: t_next, batches: latest.clone(), budget });
        }
    }
    Ok(BatchRun { masses, initial_radii: radii, fates, frames, total_mass })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_density_of_uniform_annuli_is_recovered() {
        // Batches carrying the mass of a Σ ∝ 1/r disk in log-spaced annuli.
        let n = 200;
        let radii: Vec<f64> = (0..n).map(|i| AU * 100f64.powf(i as f64 / (n - 1) as f64)).collect();
        let e = edges(&radii);
        let sigma = |r: f64| 10.0 * AU / r;
        let points: Vec<(f64, f64)> = (0..n).map(|i| (radii[i], 2.0 * PI * 10.0 * AU * (e[i + 1] - e[i]))).collect();
        let s = surface_density(&points, 2, MIN_HALF_WIDTH);
        for i in 5..n - 5 {
            assert!((s[i] / sigma(radii[i]) - 1.0).abs() < 0.02, "{i}: {} vs {}", s[i], sigma(radii[i]));
        }
    }

    #[test]
    fn midplane_turbulence_matches_section_5_4_4() {
        // α_KH ≈ 1e-6 and 1e-4 for Ωt_s = 1e-2 and 1 in the inner disk (η ~ 2–4e-3, Z ~ 0.01–0.02).
        for eta in [2e-3, 4e-3] {
            let a2 = alpha_midplane(eta, 0.01, 1e-2);
            let a0 = alpha_midplane(eta, 0.01, 1.0);
            assert!((2e-7..=5e-6).contains(&a2), "η = {eta}: {a2:e}");
            assert!((2e-5..=5e-4).contains(&a0), "η = {eta}: {a0:e}");
        }
    }
}
