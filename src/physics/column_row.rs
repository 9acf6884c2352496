//! The pair data of one family of a Monte Carlo column with every other
//! family, computed over the whole row at once.
//!
//! A run computes a new family's row after almost every event (the product of
//! a sticking collision is a family of its own), and a pair's data take about
//! thirty divisions and square roots in a chain: one pair at a time the row
//! waits on their latency. Here the families' properties are kept beside
//! them, one array per property ([`Lanes`], updated as families change), and
//! one loop without branches computes every pair's relative velocity, rate
//! coefficient, outcome, filling-factor change and headroom, eight pairs
//! per instruction where the processor has AVX-512 (found when the program
//! runs; elsewhere pairs are computed one at a time, as before). The loop does exactly the operations of
//! [`Column::pair`](super::monte_carlo::Model::pair) and [`PairRule::data`]
//! in the same order, with the branch-free logarithm and exponential of
//! [`super::fdlibm`] that they take too, so every pair's data are the same to
//! the last bit; a pair whose numbers leave the range those hold in (or the
//! normal numbers) is marked and recomputed one at a time by those functions.
//! A test holds the two equal over random families and every outcome.

// Off x86-64 the loop serves the tests alone.
#![cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]

use super::aggregate::DriftTerms;
use super::coagulation::Props;
use super::fdlibm::{EXP_RANGE, exp_moderate, ln_normal, small_integer};
use super::monte_carlo::{Family, Pair, PairRule};
use std::cell::RefCell;

/// The properties of a column's families that their pairs need, one array
/// per property, in the order of the families.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Lanes {
    mass: Vec<f64>,
    filling: Vec<f64>,
    /// Volume m/(ρ₀φ), m³.
    volume: Vec<f64>,
    stokes: Vec<f64>,
    sqrt_stokes: Vec<f64>,
    /// 1/(1 + St).
    inv_1p: Vec<f64>,
    settling: Vec<f64>,
    radial: Vec<f64>,
    azimuthal: Vec<f64>,
    radius: Vec<f64>,
    scale_height2: Vec<f64>,
}

/// One family's entries of [`Lanes`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Lead {
    pub mass: f64,
    pub filling: f64,
    pub volume: f64,
    pub drift: DriftTerms,
    pub inv_1p: f64,
    pub radius: f64,
    pub scale_height2: f64,
}

impl Lead {
    /// The entries of family `f` for monomers of internal density `rho0`.
    pub fn of(f: &Family<Props>, rho0: f64) -> Lead {
        Lead {
            mass: f.mass,
            filling: f.filling,
            volume: f.mass / (rho0 * f.filling),
            drift: f.props.drift,
            inv_1p: 1.0 / (1.0 + f.props.drift.stokes),
            radius: f.props.radius,
            scale_height2: f.props.scale_height2,
        }
    }
}

impl Lanes {
    /// The arrays, each as a mutable vector.
    fn arrays(&mut self) -> [&mut Vec<f64>; 11] {
        [
            &mut self.mass,
            &mut self.filling,
            &mut self.volume,
            &mut self.stokes,
            &mut self.sqrt_stokes,
            &mut self.inv_1p,
            &mut self.settling,
            &mut self.radial,
            &mut self.azimuthal,
            &mut self.radius,
            &mut self.scale_height2,
        ]
    }

    /// Family i is now `lead` (i = the number of families: a new one).
    pub(crate) fn set(&mut self, i: usize, lead: &Lead) {
        let d = &lead.drift;
        let values = [
            lead.mass,
            lead.filling,
            lead.volume,
            d.stokes,
            d.sqrt_stokes,
            lead.inv_1p,
            d.settling,
            d.radial,
            d.azimuthal,
            lead.radius,
            lead.scale_height2,
        ];
        for (array, value) in self.arrays().into_iter().zip(values) {
            if i == array.len() {
                array.push(value);
            } else {
                array[i] = value;
            }
        }
    }

    /// Family i is removed; the last takes its index.
    pub(crate) fn swap_remove(&mut self, i: usize) {
        for array in self.arrays() {
            array.swap_remove(i);
        }
    }

    /// The number of families.
    pub(crate) fn len(&self) -> usize {
        self.mass.len()
    }
}

/// A row's results: K/V, headroom, whether the pair must be computed one at a
/// time, and how many pairs stick beyond the onset of collisional compaction.
#[derive(Debug, Default)]
struct Out {
    c: Vec<f64>,
    headroom: Vec<f32>,
    scalar: Vec<bool>,
    /// Pairs of the row that stick beyond the onset of collisional compaction.
    compacting: usize,
    /// Whether rows take the compaction law in vectors: where few pairs
    /// reach it (no compaction, or full compaction's compact products),
    /// its two logarithms and exponential for every pair would cost more
    /// than those few one at a time. Set from the row before (a run's rows
    /// are alike); either way the numbers are the same.
    compact: bool,
}

/// Everything a pair needs that is the same along the row.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RowConstants {
    /// Dispersion ε of the mass-to-area ratio.
    pub epsilon: f64,
    /// 8k_BT/π, J.
    pub brownian: f64,
    /// Turbulence: Re^{-1/2}, V_g Re^{1/4}, 1.55 V_g, V_g.
    pub st_eta: f64,
    pub vg_re: f64,
    pub vg_155: f64,
    pub vg: f64,
    /// Gas: α, Ω, H, ηv_K.
    pub alpha: f64,
    pub omega: f64,
    pub scale_height: f64,
    pub eta_vk: f64,
    /// Monomer internal density ρ₀ and mass m₀; collisional-compaction onset 3bE_roll.
    pub rho0: f64,
    pub m0: f64,
    pub onset: f64,
    /// Thresholds and erosion prefactor c₁.
    pub r_crit: f64,
    pub v_eros: f64,
    pub v_frag: f64,
    pub v_bounce: f64,
    pub c1: f64,
    /// From the engine: V, f_m, f_φ.
    pub rule: PairRule,
}

thread_local! {
    static OUT: RefCell<Out> = RefCell::new(Out::default());
}

/// Computes the pair data of `lead` with every family of `lanes` into
/// `out[j]`; the pairs that `exact` must compute one at a time are passed to
/// it (it gets the index j). Without vector units for the loop (AVX-512) every
/// pair is computed one at a time: the loop alone is no faster, and the
/// compiler's estimate keeps it out of AVX2's narrower vectors.
pub(crate) fn pair_data_row(
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    out: &mut [Pair],
    mut exact: impl FnMut(usize) -> Pair,
) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx512f") {
        return in_rows(k, lead, lanes, out, exact, |compact, k, lead, lanes, row| {
            // SAFETY: the processor has AVX-512F (checked just above).
            unsafe {
                if compact {
                    run_avx512::<true>(k, lead, lanes, row);
                } else {
                    run_avx512::<false>(k, lead, lanes, row);
                }
            }
        });
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (k, lead);
    for (j, pair) in out.iter_mut().enumerate().take(lanes.len()) {
        *pair = exact(j);
    }
}

/// [`pair_data_row`] by the loop compiled without vector units, taking the
/// compaction law in the loop or not: what the loop computes on any
/// processor, for the tests that hold it to one pair at a time.
#[cfg(test)]
pub(crate) fn loop_row(
    compact: bool,
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    out: &mut [Pair],
    exact: impl FnMut(usize) -> Pair,
) {
    let run = move |_: bool, k: &RowConstants, lead: &Lead, lanes: &Lanes, row: &mut Out| {
        if compact {
            kernel::<true>(k, lead, lanes, row);
        } else {
            kernel::<false>(k, lead, lanes, row);
        }
    };
    in_rows(k, lead, lanes, out, exact, run);
}

/// A row by `run` (given whether to take the compaction law in the loop),
/// with the pairs it marks computed by `exact`.
fn in_rows(
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    out: &mut [Pair],
    mut exact: impl FnMut(usize) -> Pair,
    run: impl FnOnce(bool, &RowConstants, &Lead, &Lanes, &mut Out),
) {
    OUT.with(|cell| {
        let mut row = cell.borrow_mut();
        let row = &mut *row;
        let n = lanes.len();
        row.c.resize(n, 0.0);
        row.headroom.resize(n, 0.0);
        row.scalar.resize(n, false);
        run(row.compact, k, lead, lanes, row);
        row.compact = 32 * row.compacting > n;
        for (j, ((pair, &c), (&headroom, &scalar))) in
            out.iter_mut().zip(&row.c).zip(row.headroom.iter().zip(&row.scalar)).enumerate()
        {
            *pair = if scalar { exact(j) } else { Pair { c, headroom } };
        }
    });
}

/// The loop, compiled for AVX-512.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn run_avx512<const COMPACT: bool>(k: &RowConstants, lead: &Lead, lanes: &Lanes, out: &mut Out) {
    kernel::<COMPACT>(k, lead, lanes, out);
}

/// ⌊log₂ x⌋ from the binary exponent, and whether x is a positive normal
/// number (where that is exact; see `monte_carlo::floor_log2`).
#[inline(always)]
fn exponent(x: f64) -> (f64, bool) {
    let biased = (x.to_bits() >> 52) & 0x7ff;
    (small_integer(biased) - 1023.0, x > 0.0 && biased != 0 && biased != 0x7ff)
}

/// One row, without branches: the same operations as the pair-at-a-time
/// functions, with both sides of every choice computed and one kept.
#[inline(always)]
fn kernel<const COMPACT: bool>(k: &RowConstants, a: &Lead, lanes: &Lanes, out: &mut Out) {
    let n = lanes.len();
    let (mass, filling, volume, stokes, sqrt_stokes, inv_1p) = (
        &lanes.mass[..n],
        &lanes.filling[..n],
        &lanes.volume[..n],
        &lanes.stokes[..n],
        &lanes.sqrt_stokes[..n],
        &lanes.inv_1p[..n],
    );
    let (settling, radial, azimuthal) = (&lanes.settling[..n], &lanes.radial[..n], &lanes.azimuthal[..n]);
    let (radius, scale_height2) = (&lanes.radius[..n], &lanes.scale_height2[..n]);
    let (out_c, out_h, out_s) = (&mut out.c[..n], &mut out.headroom[..n], &mut out.scalar[..n]);
    // A count rather than a flag per pair: one more array to write tips
    // the compiler's estimate against vectors.
    let mut compacting = 0usize;
    let d = &a.drift;
    for i in 0..n {
        let (mb, phib, sb) = (mass[i], filling[i], stokes[i]);
        // Relative velocity (Column::velocity_with).
        let a_first = d.stokes >= sb;
        let s1 = if a_first { d.stokes } else { sb };
        let s2 = if a_first { sb } else { d.stokes };
        let gap = s1 - s2;
        let spread = k.epsilon * s1;
        let diff = (gap * gap + spread * spread).sqrt();
        let s2e = (s1 - diff).max(0.0);
        let brownian2 = k.brownian * (a.mass + mb) / (a.mass * mb);
        let sqrt1 = if a_first { d.sqrt_stokes } else { sqrt_stokes[i] };
        // 1/(1 + St₁), kept per family.
        let inv1p = if a_first { a.inv_1p } else { inv_1p[i] };
        let fast = k.vg * (inv1p + 1.0 / (1.0 + s2e)).sqrt();
        let turbulence = if s1 < k.st_eta {
            k.vg_re * diff
        } else if s1 < 1.0 {
            k.vg_155 * sqrt1
        } else {
            fast
        };
        let inv1 = 1.0 / (1.0 + s2e);
        let inv2 = 1.0 / (1.0 + s2e * s2e);
        let h_d = 1.0 / (1.0 + s2e / k.alpha * (1.0 + 2.0 * s2e) * inv1).sqrt();
        let settling2 = k.omega * s2e * inv1 * h_d * k.scale_height;
        let radial2 = 2.0 * s2e * k.eta_vk * inv2;
        let azimuthal2 = k.eta_vk * inv2;
        let ds = (if a_first { d.settling } else { settling[i] }) - settling2;
        let dr = (if a_first { d.radial } else { radial[i] }) - radial2;
        let da = (if a_first { d.azimuthal } else { azimuthal[i] }) - azimuthal2;
        let v = (brownian2 + turbulence * turbulence + ds * ds + dr * dr + da * da).sqrt();
        // Rate coefficient (Column::rate_at).
        let r = a.radius + radius[i];
        let rate = 1.253_314_137_315_500_3 * r * r * v / (a.scale_height2 + scale_height2[i]).sqrt();
        // Outcome (aggregate::outcome).
        let a_target = a.mass >= mb;
        let (tm, tphi) = if a_target { (a.mass, a.filling) } else { (mb, phib) };
        let pm = if a_target { mb } else { a.mass };
        // Volumes m/(ρ₀φ), kept per family.
        let (vt, vp) = if a_target { (a.volume, volume[i]) } else { (volume[i], a.volume) };
        let ratio = tm.min(pm) / tm.max(pm);
        let small = ratio < k.r_crit;
        let eroding = small && v > k.v_eros;
        let shattering = v >= k.v_frag;
        let fragment = !small && shattering;
        let bounce = !small && !shattering && v >= k.v_bounce;
        let stick = !(eroding || fragment || bounce);
        let lost = k.c1 * (1.0 * (v / k.v_eros)) * pm;
        let shatter = fragment || (eroding && lost >= tm);
        // Filling-factor change of sticking (coagulation::filling_change_with).
        let (va, vb) = if vt >= vp { (vt, vp) } else { (vp, vt) };
        // hit_and_stick_void: capped above V₁/V₂ = 650.
        let void =
            if va > 650.0 * vb { 6.94 * vb } else { (0.99 - 1.03 * ln_normal(2.0 / (va / vb + 1.0))).min(6.94) * vb };
        let m = tm + pm;
        let phi_hs = m / (k.rho0 * (va + vb + void));
        let full = phi_hs >= 1.0;
        let inv_m = 1.0 / m;
        let e = 0.5 * tm * pm * inv_m * v * v;
        let n_mono = m / k.m0;
        let x = e * k.m0 * inv_m / k.onset;
        let hs2 = phi_hs * phi_hs;
        let hs10 = hs2 * hs2 * hs2 * hs2 * hs2;
        let below = x * x * x < hs10 * n_mono * n_mono * (1.0 - 1e-9);
        // Collisional compaction: the power law where it may exceed φ_hs.
        let compacting_here = !(full || e <= k.onset || (below && hs10 > 1e-250 && n_mono < 1e100));
        // Without COMPACT, every pair that gets here is computed one at a time.
        let (phi_c, in_range) = if COMPACT {
            let (okx, okn) = (x.is_normal() && x > 0.0, n_mono.is_normal() && n_mono > 0.0);
            let power = 0.3 * ln_normal(x) - 0.2 * ln_normal(n_mono);
            (exp_moderate(power), okx && okn && power.abs() < EXP_RANGE)
        } else {
            (0.0, false)
        };
        let compacted = compacting_here && phi_c > phi_hs;
        let grown = (vp + void) / vt;
        let change = if full {
            1.0 - tphi
        } else if compacted {
            phi_c.min(1.0) - tphi
        } else {
            tphi * (pm / tm - grown) / (1.0 + grown)
        };
        // Pair data (PairRule::data).
        let c = rate / k.rule.volume;
        let (dm, dphi) = if stick {
            (pm, change.abs())
        } else if bounce {
            (0.0, 0.0)
        } else if shatter {
            (tm, tphi)
        } else {
            (lost, 0.0)
        };
        let (hm, ok_m) = exponent(k.rule.f_m * tm / dm);
        let (hp, ok_p) = exponent(k.rule.f_phi * tphi / dphi);
        let hm = if dm > 0.0 { hm } else { f64::INFINITY };
        let hp = if dphi > 0.0 { hp } else { f64::INFINITY };
        out_c[i] = if bounce { 0.0 } else { c };
        out_h[i] = hm.min(hp) as f32;
        compacting += usize::from(stick && compacting_here);
        out_s[i] = (stick && compacting_here && !in_range) || (dm > 0.0 && !ok_m) || (dphi > 0.0 && !ok_p);
    }
    out.compacting = compacting;
}
