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
//! Surface density (5.7): the derivative of the cumulative mass (5.6) needs a
//! radial scale. By default Σ_d is a kernel estimate: each batch's mass spread
//! by a triangular kernel in ln R of a stated half-width (a model parameter,
//! at least [`KERNEL_SPACINGS`] initial batch spacings), renormalised where
//! the kernel reaches past the dust's inner or outer end. The reach does not
//! grow where batches are sparse, so a pile-up of drifting batches is seen
//! over the same radial scale whatever the batch count, and Σ_d changes
//! continuously as batches move. The estimate of earlier versions (each
//! batch's annulus and its neighbours', [`Smoothing::Annuli`]) stays for the
//! files that used it.

use super::PhysicsError;
use super::aggregate::dust_scale_height;
use super::constants::{AU, YEAR};
use super::disk::GasDisk;
use super::growth::{GrowthModel, GrowthState, Stop};
use super::tabled::Bounds;
use crate::parallel::prelude::*;
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
    /// How Σ_d is read from the batches.
    pub smoothing: Smoothing,
    /// Recorded frames per decade of time, from one year (the last frame is
    /// at `t_end`); 0 records the end state alone (a run asked only for the
    /// fates: the dynamics never read the frames, so the fates are the same
    /// to the last bit).
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
            smoothing: Smoothing::Kernel { half_width: KERNEL_HALF_WIDTH },
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
        if let Smoothing::Kernel { half_width } = self.smoothing
            && !(half_width > 0.0 && half_width.is_finite())
        {
            return bad("smoothing", half_width, "the kernel half-width must be finite and > 0");
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

    /// The initial spacing of the batches in ln R.
    pub fn spacing(&self) -> f64 {
        (self.r_out / self.r_in).ln() / ((self.batches.max(2) - 1) as f64 + self.offset)
    }

    /// The region the batches represent, in ln R: from half an initial
    /// spacing inside the first batch to half a spacing outside the last. The
    /// kernel estimate is renormalised on it, so the first and last batches
    /// see the density of their neighbourhood at the start, while dust that
    /// drifts inside it, or batches left alone at the front of the dust, are
    /// not inflated.
    pub fn domain(&self) -> (f64, f64) {
        let spacing = self.spacing();
        (self.r_in.ln() + (self.offset - 0.5) * spacing, self.r_out.ln() + 0.5 * spacing)
    }

    /// The surface-density estimate the run uses: the kernel widened to
    /// [`KERNEL_SPACINGS`] initial spacings where the batches are too few for
    /// the stated width.
    pub fn density_smoothing(&self) -> Smoothing {
        self.smoothing.at_spacing(self.spacing())
    }
}

/// How the dust surface density (5.7) is estimated from the batches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Smoothing {
    /// Each batch's mass spread by a triangular kernel in ln R of this
    /// half-width, renormalised on the extent of the dust.
    Kernel {
        /// Half-width in ln R.
        half_width: f64,
    },
    /// The estimate of earlier versions: the mass of `k` neighbours on each
    /// side over the area of their annuli, widened to at least
    /// ±`half_width` in ln R.
    Annuli {
        /// Neighbours on each side.
        k: usize,
        /// Smallest half-width in ln R.
        half_width: f64,
    },
}

/// The kernel's default half-width in ln R: ±10 % in radius, about two gas
/// scale heights between 5 and 20 AU. Narrower kernels resolve the few
/// batches at the inner front of the dust only with thousands of batches (at
/// 0.07 the largest midplane loading of Fig. 5.13's disk is 0.54 with 1000
/// batches and 0.35 with 2000).
pub const KERNEL_HALF_WIDTH: f64 = 0.1;

/// The fewest initial batch spacings a kernel spans on each side.
pub const KERNEL_SPACINGS: f64 = 2.0;

impl Smoothing {
    /// The estimate of earlier versions (two neighbours, ±5 %).
    pub const ANNULI: Smoothing = Smoothing::Annuli { k: 2, half_width: MIN_HALF_WIDTH };

    /// The kernel widened to [`KERNEL_SPACINGS`] times `spacing` (ln R) if narrower.
    pub fn at_spacing(self, spacing: f64) -> Smoothing {
        match self {
            Smoothing::Kernel { half_width } => {
                Smoothing::Kernel { half_width: half_width.max(KERNEL_SPACINGS * spacing) }
            }
            other => other,
        }
    }
}

/// The triangular kernel's cumulative weight from −1 to `u`.
fn kernel_cdf(u: f64) -> f64 {
    let u = u.clamp(-1.0, 1.0);
    if u <= 0.0 { 0.5 * (1.0 + u).powi(2) } else { 1.0 - 0.5 * (1.0 - u).powi(2) }
}

/// Σ_d at radius `r` from the masses at ln-radii `points` (only those within
/// `h` count), a triangular kernel of half-width `h` renormalised on the dust's
/// extent `[a, b]` in ln R, kg m⁻².
fn kernel_density(r: f64, points: impl Iterator<Item = (f64, f64)>, h: f64, (a, b): (f64, f64)) -> f64 {
    let x = r.ln();
    let inv_h = 1.0 / h;
    let sum: f64 = points
        .map(|(xj, m)| {
            // A select rather than a branch (or `f64::max`, which WebAssembly
            // has no one instruction for): beyond the half-width the weight
            // is +0, which leaves the sum as it is.
            let w = 1.0 - (x - xj).abs() * inv_h;
            m * if w > 0.0 { w } else { 0.0 }
        })
        .sum::<f64>()
        * inv_h;
    let covered = kernel_cdf((b - x) / h) - kernel_cdf((a - x) / h);
    let least = 0.5 * ((b - a) / h).at_most(1.0);
    sum / (2.0 * PI * r * r * covered.at_least(least))
}

/// The extent of the dust in ln R from its sorted ln-radii `x`: half a
/// spacing beyond the first and last batch (at most `h`).
fn extent(x: &[f64], h: f64) -> (f64, f64) {
    let n = x.len();
    if n < 2 {
        return (x[0] - 0.5 * h, x[0] + 0.5 * h);
    }
    (x[0] - (0.5 * (x[1] - x[0])).at_most(h), x[n - 1] + (0.5 * (x[n - 1] - x[n - 2])).at_most(h))
}

/// The weight of a batch's own mass in its kernel estimate, from the gaps in
/// ln R to its neighbours inside and outside. The batch's mass is taken as
/// spread evenly over its cell (half of each gap, or the one gap at an end),
/// and the weight is the kernel's mean over that cell relative to its peak:
/// 1 − c/2h for a cell of half-width c ≤ h, h/2c beyond. A batch left alone
/// by its neighbours then sees its own mass over its cell instead of in the
/// kernel's peak, a bias that would shrink only as the batch count grows.
fn self_weight(h: f64, gap_in: Option<f64>, gap_out: Option<f64>) -> f64 {
    let cell = match (gap_in, gap_out) {
        (Some(a), Some(b)) => 0.5 * (a.abs() + b.abs()),
        (Some(a), None) | (None, Some(a)) => a.abs(),
        (None, None) => return 1.0,
    };
    let c = 0.5 * cell;
    if c <= h { 1.0 - c / (2.0 * h) } else { h / (2.0 * c) }
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
        crate::sorting::sort_by_key(&mut formed, |a| a.0);
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

    /// The midplane loading ρ*_d/ρ_g that the share `share` (0–1) of the
    /// dust reaches at least once (0 where less than that share ever enters
    /// the streaming-instability window 10⁻² ≤ Ωt_s ≤ 1, outside which a
    /// batch adds nothing to ρ*_d).
    ///
    /// Each batch's peak loading over the recorded frames is weighed by its
    /// mass; the batches are ordered from the most loaded down, each placed
    /// at the middle of its mass on the cumulative axis, and the value at
    /// `share` of the dust is interpolated linearly between them (the first
    /// and last batches hold the ends). Unlike the largest loading, which one
    /// batch at the inner front of the window sets, this is a quantile of a
    /// mass distribution: it settles as the batches grow in number.
    pub fn loading_reached_by(&self, share: f64) -> f64 {
        let mut peak = vec![0.0f64; self.masses.len()];
        for frame in &self.frames {
            for (p, b) in peak.iter_mut().zip(&frame.batches) {
                if b.dust {
                    *p = p.max(b.loading);
                }
            }
        }
        let mut batches: Vec<(f64, f64)> = peak.into_iter().zip(self.masses.iter().copied()).collect();
        crate::sorting::sort_by_key(&mut batches, |a| -a.0);
        let total: f64 = batches.iter().map(|x| x.1).sum();
        let at = share.clamp(0.0, 1.0) * total;
        let mut below = 0.0;
        let mut previous: Option<(f64, f64)> = None;
        for &(value, mass) in &batches {
            let middle = below + 0.5 * mass;
            if at <= middle {
                return match previous {
                    Some((x0, v0)) if middle > x0 => v0 + (value - v0) * (at - x0) / (middle - x0),
                    _ => value,
                };
            }
            previous = Some((middle, value));
            below += mass;
        }
        batches.last().map_or(0.0, |x| x.0)
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
/// in the input order.
///
/// With [`Smoothing::Kernel`], each point's value is the kernel estimate of
/// all masses within the half-width (renormalised at the ends of the points'
/// extent). With [`Smoothing::Annuli`], it is the mass of the batches from `k`
/// neighbours inside to `k` outside, divided by the area between their outer
/// cell edges (geometric midpoints to the next batches), widened one
/// neighbour on each side at a time to at least ±`half_width` in ln R.
pub fn surface_density(points: &[(f64, f64)], smoothing: Smoothing) -> Vec<f64> {
    surface_density_in(points, smoothing, None)
}

/// [`surface_density`] with the kernel renormalised on a fixed `domain`
/// (ln R) instead of the points' own extent: the region the batches of a
/// run represent ([`BatchConfig::domain`]).
pub fn surface_density_in(points: &[(f64, f64)], smoothing: Smoothing, domain: Option<(f64, f64)>) -> Vec<f64> {
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let keys: Vec<f64> = points.iter().map(|p| p.0).collect();
    let order = crate::sorting::order(&keys);
    let r: Vec<f64> = order.iter().map(|&i| points[i].0).collect();
    let m: Vec<f64> = order.iter().map(|&i| points[i].1).collect();
    let mut out = vec![0.0; n];
    match smoothing {
        Smoothing::Kernel { half_width: h } => {
            let x: Vec<f64> = r.iter().map(|r| r.ln()).collect();
            let span = domain.unwrap_or_else(|| extent(&x, h));
            let (mut lo, mut hi) = (0, 0);
            for (p, &i) in order.iter().enumerate() {
                while x[p] - x[lo] >= h {
                    lo += 1;
                }
                while hi + 1 < n && x[hi + 1] - x[p] < h {
                    hi += 1;
                }
                let own = m[p] * self_weight(h, (p > 0).then(|| x[p] - x[p - 1]), (p + 1 < n).then(|| x[p + 1] - x[p]));
                let points = (lo..=hi).map(|q| (x[q], if q == p { own } else { m[q] }));
                out[i] = kernel_density(r[p], points, h, span);
            }
        }
        Smoothing::Annuli { k, half_width } => {
            let min_ratio = (2.0 * half_width.max(0.0)).exp();
            for (p, &i) in order.iter().enumerate() {
                out[i] = density_at(&r, &m, p, k, min_ratio);
            }
        }
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
    /// ln R of the radii, in the same order.
    x: Vec<f64>,
    /// The last step in ln R of the batch of each rank, in the same order
    /// (read in sequence by the kernel): (t₀, ln R₀, d ln R/dt over the
    /// step, ln R₁).
    ln_step: Vec<[f64; 4]>,
    /// The region the batches represent, ln R (the kernel is renormalised on it).
    domain: (f64, f64),
}

impl Ranks {
    fn new(radii: &[f64], masses: &[f64], domain: (f64, f64)) -> Ranks {
        let id = crate::sorting::order(radii);
        let mut rank = vec![0; radii.len()];
        for (p, &i) in id.iter().enumerate() {
            rank[i] = p;
        }
        Ranks {
            r: id.iter().map(|&i| radii[i]).collect(),
            m: id.iter().map(|&i| masses[i]).collect(),
            rank,
            step: radii.iter().map(|&r| [0.0, r, 0.0, r]).collect(),
            x: id.iter().map(|&i| radii[i].ln()).collect(),
            ln_step: id.iter().map(|&i| [0.0, radii[i].ln(), 0.0, radii[i].ln()]).collect(),
            id,
            domain,
        }
    }

    /// Where batch `j` is at time `t`, m: interpolated in its last step, which
    /// began no later than the time of the batch furthest behind, or carried
    /// on at the speed of that step beyond its end.
    fn at(&self, j: usize, t: f64) -> f64 {
        let [t0, r0, t1, r1] = self.step[j];
        if t1 > t0 { (r0 + (r1 - r0) * ((t - t0) / (t1 - t0)).at_least(0.0)).at_least(0.5 * r1) } else { r1 }
    }

    /// Surface density at batch `i` at time `t` if it is at radius `r_i`,
    /// kg m⁻², from the positions of its neighbours at that same time.
    fn density(&self, i: usize, t: f64, r_i: f64, smoothing: Smoothing) -> f64 {
        match smoothing {
            Smoothing::Kernel { half_width } => self.kernel(i, t, r_i, half_width),
            Smoothing::Annuli { k, half_width } => self.annuli(i, t, r_i, k, (2.0 * half_width.max(0.0)).exp()),
        }
    }

    /// The kernel estimate at batch `i` (see [`kernel_density`]): every batch
    /// whose last known radius lies within twice the half-width is placed at
    /// time `t`, and those within the half-width count.
    fn kernel(&self, i: usize, t: f64, r_i: f64, h: f64) -> f64 {
        let n = self.x.len();
        let p = self.rank[i];
        let x = r_i.ln();
        let near = |q: usize| (self.x[q] - x).abs() < 2.0 * h;
        let mut lo = p;
        while lo > 0 && near(lo - 1) {
            lo -= 1;
        }
        let mut hi = p;
        while hi + 1 < n && near(hi + 1) {
            hi += 1;
        }
        let place = |q: usize| if q == p { x } else { self.ln_at(q, t) };
        let own = self.m[p] * self_weight(h, (p > 0).then(|| x - place(p - 1)), (p + 1 < n).then(|| place(p + 1) - x));
        let points = (lo..=hi).map(|q| if q == p { (x, own) } else { (place(q), self.m[q]) });
        kernel_density(r_i, points, h, self.domain)
    }

    /// ln R of the batch of rank `q` at time `t`, interpolated in ln R
    /// within its last step (see [`Ranks::at`]).
    fn ln_at(&self, q: usize, t: f64) -> f64 {
        let [t0, x0, rate, x1] = self.ln_step[q];
        (x0 + rate * (t - t0).at_least(0.0)).at_least(x1 - std::f64::consts::LN_2)
    }

    /// The annuli estimate of earlier versions at batch `i`.
    fn annuli(&self, i: usize, t: f64, r_i: f64, k: usize, min_ratio: f64) -> f64 {
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
            crate::sorting::sort_by_key(&mut local, |a| a.0);
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
        let (x0, x1) = (self.x[p], r.ln());
        self.ln_step[p] = if t1 > t0 { [t0, x0, (x1 - x0) / (t1 - t0), x1] } else { [t0, x1, 0.0, x1] };
        self.r[p] = r;
        self.x[p] = r.ln();
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
        self.x.swap(a, b);
        self.m.swap(a, b);
        self.ln_step.swap(a, b);
        self.id.swap(a, b);
        self.rank[self.id[a]] = a;
        self.rank[self.id[b]] = b;
    }

    /// Takes batch `i` out of the dust.
    fn remove(&mut self, i: usize) {
        let p = self.rank[i];
        self.r.remove(p);
        self.x.remove(p);
        self.m.remove(p);
        self.ln_step.remove(p);
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
    // On a worker of the thread pool: each wave's parallel step is then a
    // join among the workers, not a job handed to the pool from outside and
    // waited for (a sleep and a wake of the calling thread per wave).
    crate::parallel::on_pool(|| run_here(cfg, cancelled))
}

fn run_here(cfg: &BatchConfig, cancelled: &(dyn Fn(f64) -> bool + Sync)) -> Result<BatchRun, PhysicsError> {
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
    let smoothing = cfg.density_smoothing();
    let stepper = model.stepper();
    let mut states: Vec<GrowthState> = radii.iter().map(|&r| model.start(r)).collect();
    let mut fates = vec![Fate::Dust; n];
    let mut ranks = Ranks::new(&radii, &masses, cfg.domain());
    // The times of the frames; the progress is counted on the regular ones.
    let regular = frame_times(cfg.t_end, cfg.frames_per_decade);
    let times = if cfg.frames_per_decade == 0 { vec![cfg.t_end] } else { regular.clone() };
    let blank =
        BatchSample { r: 0.0, mass: 0.0, filling: 1.0, stokes: 0.0, t_grow: 0.0, loading: 0.0, si: false, dust: true };
    let mut samples: Vec<Vec<BatchSample>> = vec![vec![blank; n]; times.len()];
    // The next frame each batch has not yet passed.
    let mut next_frame = vec![0usize; n];
    let mut queue: std::collections::BinaryHeap<Due> = (0..n).map(|i| Due(0.0, i)).collect();
    let span = (cfg.t_end / regular[0]).ln();
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
        if waves.is_multiple_of(256) && cancelled(((t / regular[0]).max(1.0).ln() / span).clamp(0.0, 1.0)) {
            return Err(PhysicsError::InvalidParameter { name: "run", value: 0.0, reason: "cancelled" });
        }
        let stepped: Vec<(GrowthState, super::growth::TrackPoint, Option<Stop>)> = wave
            .par_iter()
            .map(|&i| {
                let sigma = |t: f64, r: f64| ranks.density(i, t, r, smoothing);
                let mut s = states[i].clone();
                let (point, ended) = stepper.step(&mut s, Some(&sigma), cfg.t_end);
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
            let sigma_star = surface_density_in(&star, smoothing, Some(cfg.domain()));
            for (j, &i) in dust.iter().enumerate() {
                let b = &mut batches[i];
                // Only particles with 10⁻² ≤ Ωt_s ≤ 1 make ρ*_d (Sect. 5.4.1):
                // a batch outside that window adds nothing to the loading.
                let z_star = sigma_star[j] / disk.surface_density(b.r);
                b.loading = if (1e-2..=1.0).contains(&b.stokes) {
                    z_star / dust_scale_height(disk.alpha, b.stokes)
                } else {
                    0.0
                };
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
    fn the_loading_a_share_of_the_dust_reaches_is_a_mass_quantile_of_each_batch_peak() {
        let sample = |loading: f64, dust: bool| BatchSample {
            r: AU,
            mass: 1.0,
            filling: 1.0,
            stokes: 0.1,
            t_grow: 1.0,
            loading,
            si: false,
            dust,
        };
        // Peaks over the frames 4, 3, 2 and 0 (batch 3's 9 is no longer dust),
        // with masses 1, 1, 1 and 1: middles at 0.5, 1.5, 2.5 and 3.5 of 4.
        let frames = vec![
            Frame {
                t: 1.0,
                batches: vec![sample(1.0, true), sample(3.0, true), sample(0.0, true), sample(0.0, true)],
                budget: [0.0; 3],
            },
            Frame {
                t: 2.0,
                batches: vec![sample(4.0, true), sample(0.5, true), sample(2.0, true), sample(9.0, false)],
                budget: [0.0; 3],
            },
        ];
        let run = BatchRun {
            masses: vec![1.0; 4],
            initial_radii: vec![AU; 4],
            fates: vec![Fate::Dust; 4],
            frames,
            total_mass: 4.0,
        };
        assert_eq!(run.loading_reached_by(0.1), 4.0);
        assert_eq!(run.loading_reached_by(0.5), 2.5);
        assert_eq!(run.loading_reached_by(0.75), 1.0);
        assert_eq!(run.loading_reached_by(1.0), 0.0);
        // A heavier batch moves the quantile towards its own peak.
        let heavy = BatchRun { masses: vec![1.0, 1.0, 6.0, 0.0], ..run.clone() };
        assert_eq!(heavy.loading_reached_by(0.625), 2.0);
        assert!(heavy.loading_reached_by(0.5) < run.loading_reached_by(0.5));
        // No dust in the window: 0 for every share.
        let none = BatchRun { frames: Vec::new(), ..run };
        assert_eq!(none.loading_reached_by(0.1), 0.0);
    }

    #[test]
    fn surface_density_of_uniform_annuli_is_recovered() {
        // Batches carrying the mass of a Σ ∝ 1/r disk in log-spaced annuli.
        let n = 200;
        let radii: Vec<f64> = (0..n).map(|i| AU * 100f64.powf(i as f64 / (n - 1) as f64)).collect();
        let e = edges(&radii);
        let sigma = |r: f64| 10.0 * AU / r;
        let points: Vec<(f64, f64)> = (0..n).map(|i| (radii[i], 2.0 * PI * 10.0 * AU * (e[i + 1] - e[i]))).collect();
        // The annuli inside the first and last five batches within 2 %; the
        // kernel within 2 % beyond its half-width from the ends, 3 % nearer.
        for smoothing in [Smoothing::ANNULI, Smoothing::Kernel { half_width: KERNEL_HALF_WIDTH }] {
            let s = surface_density(&points, smoothing);
            let spacing = (radii[1] / radii[0]).ln();
            for i in 0..n {
                let from_end = i.min(n - 1 - i) as f64 * spacing;
                let tolerance = match smoothing {
                    Smoothing::Annuli { .. } if i < 5 || i >= n - 5 => continue,
                    Smoothing::Kernel { half_width } if from_end < half_width => 0.03,
                    _ => 0.02,
                };
                let off = (s[i] / sigma(radii[i]) - 1.0).abs();
                assert!(off < tolerance, "{smoothing:?}, {i}: {} vs {}", s[i], sigma(radii[i]));
            }
        }
    }

    #[test]
    fn kernel_density_is_continuous_and_bounded_for_a_pile_up() {
        // Twenty batches at nearly one radius: the kernel sees their mass over
        // its half-width, and a batch moving through it sees a continuous Σ_d.
        let h = 0.1;
        let mut points: Vec<(f64, f64)> = (0..20).map(|i| (5.0 * AU * (1.0 + 1e-4 * i as f64), 1e20)).collect();
        points.push((5.0 * AU, 0.0));
        let mut last = f64::NAN;
        for step in 0..400 {
            let r = 5.0 * AU * (-0.2 + 0.001 * step as f64).exp();
            points[20].0 = r;
            // Inside the region the batches represent, as in a run.
            let domain = Some(((AU).ln(), (50.0 * AU).ln()));
            let s = surface_density_in(&points, Smoothing::Kernel { half_width: h }, domain)[20];
            let peak = 20.0 * 1e20 / h / (2.0 * PI * r * r);
            assert!(s <= peak * (1.0 + 1e-9), "{s:e} above {peak:e}");
            if last.is_finite() {
                // The kernel's slope moves Σ_d by 1 % of the peak a step; a
                // top-hat would jump by the whole pile.
                assert!((s - last).abs() <= 0.012 * peak, "a jump of {:e} at step {step}", s - last);
            }
            last = s;
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
