//! The global "dust batch" model of ch. 5: batches of identical particles at
//! many radii grow (5.10) and drift (5.8) in a gas disk; the dust surface
//! density follows from the batch positions (5.6)–(5.7); particles that reach
//! the planetesimal mass become planetesimals, batches inside the inner edge
//! are lost. Streaming-instability conditions of Sect. 5.4.1 are evaluated
//! along the way.
//!
//! Time stepping: batches exchange information only through Σ_d. Each batch
//! advances with its own steps (Δln m growth or 5 % of its drift time, the
//! rule of Sect. 5.2.5 applied per batch); the batch furthest behind in time
//! steps next and reads Σ_d from where its neighbours are now, so Σ_d is never
//! older than one of the neighbours' own steps. Frames are interpolated to
//! fixed, logarithmically spaced times.
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
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
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
    /// Neighbours on each side in the surface-density smoothing.
    pub smoothing: usize,
    /// Smallest half-width of the smoothing annulus in ln R ([`MIN_HALF_WIDTH`]).
    pub smoothing_width: f64,
    /// Recorded frames per decade of time, from one year (the last frame is at `t_end`).
    pub frames_per_decade: usize,
    /// Shift of the initial grid, in batch spacings, 0 ≤ offset < 1: batch i
    /// starts at r_in (r_out/r_in)^{(i + offset)/(N − 1 + offset)} (0: the
    /// first batch at r_in). Runs that differ only in it sample how the result
    /// depends on where the batches happen to sit.
    pub offset: f64,
}

impl BatchConfig {
    /// The porous perfect-sticking run of Fig. 5.6: M_D = 0.01 M☉, Z₀ = 0.02,
    /// R_c = 30 AU, γ = 1, α = 10⁻³, 0.1 µm ice, 3–200 AU, 10⁶ yr, with the
    /// relative velocities of App. 5.B (no settling).
    pub fn figure_5_6(batches: usize) -> BatchConfig {
        let mut model = GrowthModel::chapter4(super::growth::Porosity::Full);
        model.settling = false;
        model.disk = GasDisk {
            profile: super::disk::Profile::TruncatedPowerLaw { mass: 0.01, r_c: 30.0, slope: 1.0 },
            cold: false,
            alpha: 1e-3,
            metallicity: 0.02,
        };
        model.dlnm = 0.2;
        model.midpoint = true;
        BatchConfig {
            model,
            r_in: 3.0 * AU,
            r_out: 200.0 * AU,
            batches,
            t_end: 1e6 * YEAR,
            coagulation: true,
            smoothing: 2,
            smoothing_width: MIN_HALF_WIDTH,
            frames_per_decade: 40,
            offset: 0.0,
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
        let dlnm = self.model.dlnm;
        if !(dlnm > 0.0 && dlnm <= 1.0) {
            return bad("dlnm", dlnm, "need 0 < dlnm <= 1");
        }
        if !(0.0..1.0).contains(&self.offset) {
            return bad("offset", self.offset, "need 0 <= offset < 1");
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
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
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
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Frame {
    /// Time, s.
    pub t: f64,
    /// One sample per batch, in the initial order.
    pub batches: Vec<BatchSample>,
    /// Mass in dust, planetesimals and lost inside the inner edge, kg.
    pub budget: [f64; 3],
}

/// A finished run.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
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

    /// Radius inside which the fraction `q` of the planetesimal mass formed, m
    /// (0 if none): a robust measure of the zone's extent, where the outermost
    /// radius follows a single batch.
    pub fn formation_radius_quantile(&self, q: f64) -> f64 {
        let mut formed: Vec<(f64, f64)> = self
            .fates
            .iter()
            .zip(&self.masses)
            .filter_map(|(f, m)| if let Fate::Planetesimals { r, .. } = f { Some((*r, *m)) } else { None })
            .collect();
        formed.sort_by(|a, b| a.0.total_cmp(&b.0));
        let total: f64 = formed.iter().map(|x| x.1).sum();
        let mut sum = 0.0;
        for (r, m) in &formed {
            sum += m;
            if sum >= q * total {
                return *r;
            }
        }
        formed.last().map_or(0.0, |x| x.0)
    }

    /// Fraction of the initial dust turned into planetesimals by the end.
    pub fn converted_fraction(&self) -> f64 {
        self.frames.last().map_or(0.0, |f| f.budget[1] / self.total_mass)
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
    let r: Vec<f64> = order.iter().map(|&i| points[i].0).collect();
    let m: Vec<f64> = order.iter().map(|&i| points[i].1).collect();
    let min_ratio = (2.0 * half_width.max(0.0)).exp();
    let mut out = vec![0.0; n];
    for (p, &i) in order.iter().enumerate() {
        out[i] = density_at(&r, &m, p, k, min_ratio);
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

/// Lower edge of the annulus of the batch at rank `j` among sorted radii `r`:
/// the geometric midpoint to the next batch inside, extended at the ends.
fn lower_edge(r: &[f64], j: usize) -> f64 {
    match (j, r.len()) {
        (_, 1) => r[0] / 1.05,
        (0, _) => r[0] / (r[1] / r[0]).sqrt(),
        (j, n) if j >= n => r[n - 1] * (r[n - 1] / r[n - 2]).sqrt(),
        (j, _) => (r[j - 1] * r[j]).sqrt(),
    }
}

/// The ranks `lo..=hi` whose annuli give the surface density at the batch of
/// rank `p` among radii `r` sorted outward: `k` ranks inside to `k` outside,
/// widened one rank on each side at a time until the annulus spans at least
/// `min_ratio` in radius.
fn window(r: &[f64], p: usize, k: usize, min_ratio: f64) -> (usize, usize) {
    let n = r.len();
    let mut lo = p.saturating_sub(k);
    let mut hi = (p + k).min(n - 1);
    while upper_edge(r, hi) < min_ratio * lower_edge(r, lo) && (lo > 0 || hi < n - 1) {
        lo = lo.saturating_sub(1);
        hi = (hi + 1).min(n - 1);
    }
    (lo, hi)
}

/// Upper edge of the annulus of the batch at rank `j`.
fn upper_edge(r: &[f64], j: usize) -> f64 {
    if r.len() == 1 { r[0] * 1.05 } else { lower_edge(r, j + 1) }
}

/// The mass of ranks `lo..=hi` over the area of their annuli.
fn mean_density(r: &[f64], m: &[f64], lo: usize, hi: usize) -> f64 {
    let mass: f64 = m[lo..=hi].iter().sum();
    mass / (PI * (upper_edge(r, hi).powi(2) - lower_edge(r, lo).powi(2)))
}

/// Surface density at the batch of rank `p` among radii `r` sorted outward
/// with masses `m` (see [`window`]).
fn density_at(r: &[f64], m: &[f64], p: usize, k: usize, min_ratio: f64) -> f64 {
    let (lo, hi) = window(r, p, k, min_ratio);
    mean_density(r, m, lo, hi)
}

/// The dust batches sorted by radius, kept sorted as they move, so the
/// surface density at any batch is read from the current positions of its
/// neighbours.
struct Ranks {
    /// Radii, ascending, m.
    r: Vec<f64>,
    /// Masses in the same order, kg.
    m: Vec<f64>,
    /// Batch index in the same order.
    id: Vec<usize>,
    /// Rank of each batch (`usize::MAX` once it left the dust).
    rank: Vec<usize>,
    /// Each batch's last step: (t₀, R₀, t₁, R₁), s and m.
    step: Vec<[f64; 4]>,
}

impl Ranks {
    fn new(radii: &[f64], masses: &[f64]) -> Ranks {
        let mut id: Vec<usize> = (0..radii.len()).collect();
        id.sort_by(|&a, &b| radii[a].total_cmp(&radii[b]).then(a.cmp(&b)));
        let mut rank = vec![0; radii.len()];
        for (p, &i) in id.iter().enumerate() {
            rank[i] = p;
        }
        Ranks {
            r: id.iter().map(|&i| radii[i]).collect(),
            m: id.iter().map(|&i| masses[i]).collect(),
            id,
            rank,
            step: radii.iter().map(|&r| [0.0, r, 0.0, r]).collect(),
        }
    }

    /// Where batch `j` is at time `t`, m: interpolated in its last step, which
    /// began no later than the time of the batch furthest behind, or carried
    /// on at the speed of that step beyond its end.
    fn at(&self, j: usize, t: f64) -> f64 {
        let [t0, r0, t1, r1] = self.step[j];
        if t1 > t0 { (r0 + (r1 - r0) * ((t - t0) / (t1 - t0)).max(0.0)).max(0.5 * r1) } else { r1 }
    }

    /// Surface density at batch `i` at time `t` if it is at radius `r`,
    /// kg m⁻², from the positions of its neighbours at that same time.
    fn density(&self, i: usize, t: f64, r_i: f64, k: usize, min_ratio: f64) -> f64 {
        let n = self.r.len();
        let p = self.rank[i];
        let mut reach = k + 4;
        loop {
            let lo = p.saturating_sub(reach);
            let hi = (p + reach).min(n - 1);
            let mut local: Vec<(f64, f64, usize)> = (lo..=hi)
                .map(|q| {
                    let j = self.id[q];
                    (if j == i { r_i } else { self.at(j, t) }, self.m[q], j)
                })
                .collect();
            local.sort_by(|a, b| a.0.total_cmp(&b.0));
            let r: Vec<f64> = local.iter().map(|x| x.0).collect();
            let m: Vec<f64> = local.iter().map(|x| x.1).collect();
            let q = local.iter().position(|x| x.2 == i).unwrap_or(p - lo);
            let (a, b) = window(&r, q, k, min_ratio);
            // The annulus must not touch a cut that is not the end of the disk.
            let inside = (a > 0 || lo == 0) && (b + 1 < r.len() || hi == n - 1);
            if inside || (lo == 0 && hi == n - 1) {
                return mean_density(&r, &m, a, b);
            }
            reach *= 2;
        }
    }

    /// Moves batch `i` to radius `r` after a step from `t0` to `t1`, swapping
    /// it past the batches it overtakes.
    fn move_to(&mut self, i: usize, t0: f64, t1: f64, r: f64) {
        let r0 = self.r[self.rank[i]];
        self.step[i] = [t0, r0, t1, r];
        let mut p = self.rank[i];
        self.r[p] = r;
        while p > 0 && self.r[p - 1] > r {
            self.swap(p - 1, p);
            p -= 1;
        }
        while p + 1 < self.r.len() && self.r[p + 1] < r {
            self.swap(p, p + 1);
            p += 1;
        }
    }

    fn swap(&mut self, a: usize, b: usize) {
        self.r.swap(a, b);
        self.m.swap(a, b);
        self.id.swap(a, b);
        self.rank[self.id[a]] = a;
        self.rank[self.id[b]] = b;
    }

    /// Takes batch `i` out of the dust.
    fn remove(&mut self, i: usize) {
        let p = self.rank[i];
        self.r.remove(p);
        self.m.remove(p);
        self.id.remove(p);
        for q in p..self.id.len() {
            self.rank[self.id[q]] = q;
        }
        self.rank[i] = usize::MAX;
    }
}

/// Batches stepped together, in parallel: the furthest behind in time. A
/// fixed number, so results do not depend on the thread count.
const WAVE: usize = 32;

/// A batch's time as a heap key: the earliest first, ties by index.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Due(f64, usize);

impl Eq for Due {}

impl PartialOrd for Due {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Due {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        // Reversed: `BinaryHeap` pops the largest.
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

/// Frame times: `per_decade` per decade from one year (or `t_end` if sooner) to `t_end`.
fn frame_times(t_end: f64, per_decade: usize) -> Vec<f64> {
    let t_first = YEAR.min(t_end);
    let decades = (t_end / t_first).log10().max(0.0);
    let count = ((decades * per_decade.max(1) as f64 - 1e-9).ceil() as usize).max(1);
    let mut times: Vec<f64> = (0..count).map(|j| t_first * 10f64.powf(j as f64 / per_decade.max(1) as f64)).collect();
    times.push(t_end);
    times
}

/// Runs the batch model.
///
/// Each batch advances with its own steps (Δln m growth or a fraction of its
/// drift time, the rule of Sect. 5.2.5 applied per batch), always the batch
/// furthest behind in time first, and reads Σ_d from the current positions of
/// its neighbours at every step: a batch that drifts carries its Σ_d with it
/// instead of reading a profile from an earlier time. The result does not
/// depend on the thread count.
pub fn run(cfg: &BatchConfig, cancelled: &(dyn Fn(f64) -> bool + Sync)) -> Result<BatchRun, PhysicsError> {
    cfg.validate()?;
    let disk = cfg.model.disk;
    let n = cfg.batches;
    let u = cfg.offset;
    let radii: Vec<f64> =
        (0..n).map(|i| cfg.r_in * (cfg.r_out / cfg.r_in).powf((i as f64 + u) / ((n - 1) as f64 + u))).collect();
    let e = edges(&radii);
    // Batch masses from the initial Σ_d = Z₀Σ_g, integrated over each annulus.
    let masses: Vec<f64> = (0..n)
        .into_par_iter()
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
    let min_ratio = (2.0 * cfg.smoothing_width).exp();
    let mut states: Vec<GrowthState> = radii.iter().map(|&r| model.start(r)).collect();
    let mut fates = vec![Fate::Dust; n];
    let mut ranks = Ranks::new(&radii, &masses);
    let times = frame_times(cfg.t_end, cfg.frames_per_decade);
    let blank =
        BatchSample { r: 0.0, mass: 0.0, filling: 1.0, stokes: 0.0, t_grow: 0.0, loading: 0.0, si: false, dust: true };
    let mut samples: Vec<Vec<BatchSample>> = vec![vec![blank; n]; times.len()];
    // The next frame each batch has not yet passed.
    let mut next_frame = vec![0usize; n];
    let mut queue: std::collections::BinaryHeap<Due> = (0..n).map(|i| Due(0.0, i)).collect();
    let span = (cfg.t_end / times[0]).ln();
    let (mut events, mut waves) = (0usize, 0usize);
    let mut wave: Vec<usize> = Vec::with_capacity(WAVE);
    while let Some(Due(t, _)) = queue.peek().copied() {
        // The batches furthest behind step together, each reading Σ_d at its
        // own time; the updates are applied in order afterwards.
        wave.clear();
        while wave.len() < WAVE {
            match queue.pop() {
                Some(Due(_, i)) => wave.push(i),
                None => break,
            }
        }
        events += wave.len();
        if events > 400_000 * n {
            return Err(PhysicsError::InvalidParameter {
                name: "run",
                value: events as f64,
                reason: "step budget exhausted",
            });
        }
        waves += 1;
        if waves.is_multiple_of(256) && cancelled(((t / times[0]).max(1.0).ln() / span).clamp(0.0, 1.0)) {
            return Err(PhysicsError::InvalidParameter { name: "run", value: 0.0, reason: "cancelled" });
        }
        let stepped: Vec<(GrowthState, super::growth::TrackPoint, Option<Stop>)> = wave
            .par_iter()
            .map(|&i| {
                let sigma = |t: f64, r: f64| ranks.density(i, t, r, cfg.smoothing, min_ratio);
                let mut s = states[i].clone();
                let (point, ended) = model.step(&mut s, Some(&sigma), cfg.t_end);
                (s, point, ended)
            })
            .collect();
        for (&i, (after, point, ended)) in wave.iter().zip(stepped) {
            let before = std::mem::replace(&mut states[i], after);
            let after = &states[i];
            // Samples for every frame this step reaches, interpolated in time.
            while next_frame[i] < times.len() && times[next_frame[i]] <= after.t {
                let tf = times[next_frame[i]];
                let w = if after.t > before.t { ((tf - before.t) / (after.t - before.t)).clamp(0.0, 1.0) } else { 1.0 };
                let gone = matches!(ended, Some(Stop::InnerEdge)) && w >= 1.0;
                samples[next_frame[i]][i] = BatchSample {
                    r: before.r + w * (after.r - before.r),
                    mass: before.mass * (after.mass / before.mass).powf(w),
                    filling: before.filling + w * (after.filling - before.filling),
                    stokes: point.stokes,
                    t_grow: point.t_grow,
                    loading: 0.0,
                    si: false,
                    dust: !gone,
                };
                next_frame[i] += 1;
            }
            match ended {
                Some(stop) => {
                    fates[i] = match stop {
                        Stop::Planetesimal => Fate::Planetesimals { t: after.t, r: after.r },
                        _ => Fate::Lost { t: after.t },
                    };
                    let last = BatchSample {
                        r: after.r,
                        mass: after.mass,
                        filling: after.filling,
                        stokes: point.stokes,
                        t_grow: point.t_grow,
                        loading: 0.0,
                        si: false,
                        dust: false,
                    };
                    for frame in &mut samples[next_frame[i]..] {
                        frame[i] = last;
                    }
                    next_frame[i] = times.len();
                    ranks.remove(i);
                }
                None => {
                    ranks.move_to(i, before.t, after.t, after.r);
                    if after.t < cfg.t_end {
                        queue.push(Due(after.t, i));
                    }
                }
            }
        }
    }
    // Budgets and the streaming-instability diagnostics of each frame:
    // Z* from batches with 10⁻² ≤ Ωt_s ≤ 1.
    let frames = times
        .iter()
        .zip(samples)
        .map(|(&t, mut batches)| {
            let mut budget = [0.0; 3];
            for (i, fate) in fates.iter().enumerate() {
                let k = match *fate {
                    Fate::Planetesimals { t: tp, .. } if tp <= t => 1,
                    Fate::Lost { t: tl } if tl <= t => 2,
                    _ => 0,
                };
                budget[k] += masses[i];
            }
            let dust: Vec<usize> = (0..n).filter(|&i| batches[i].dust).collect();
            let star: Vec<(f64, f64)> = dust
                .iter()
                .map(|&i| {
                    let st = batches[i].stokes;
                    (batches[i].r, if (1e-2..=1.0).contains(&st) { masses[i] } else { 0.0 })
                })
                .collect();
            let sigma_star = surface_density(&star, cfg.smoothing, cfg.smoothing_width);
            for (j, &i) in dust.iter().enumerate() {
                let b = &mut batches[i];
                let z_star = sigma_star[j] / disk.surface_density(b.r);
                b.loading = z_star / dust_scale_height(disk.alpha, b.stokes);
                let omega = disk.omega(b.r);
                b.si = (1e-2..=1.0).contains(&b.stokes) && b.loading >= 1.0 && b.t_grow > 1.0 / omega;
            }
            Frame { t, batches, budget }
        })
        .collect();
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
