//! The pair data of one family of a Monte Carlo column with every other
//! family, computed over the whole row at once.
//!
//! A run computes a new family's row after almost every event (the product of
//! a sticking collision is a family of its own), and a pair's data take nine
//! divisions, five square roots and a logarithm in a chain: one pair at a
//! time the row waits on their latency. Here the families' properties are
//! kept beside them, one array per property ([`Lanes`], updated as families
//! change), and one loop without branches computes every pair's relative
//! velocity, rate coefficient, outcome, filling-factor change and headroom,
//! several pairs per instruction: eight where the processor has AVX-512, four where it has
//! AVX2 (both found when the program runs), two in WebAssembly with its
//! 128-bit vectors; elsewhere pairs are computed one at a time. The loop
//! does exactly the operations of
//! [`Column::pair`](super::monte_carlo::Model::pair) and [`PairRule::data`]
//! in the same order, with the branch-free logarithm and exponential of
//! [`super::fdlibm`] that they take too, so every pair's data are the same to
//! the last bit; a pair whose numbers leave the range those hold in (or the
//! normal numbers) is marked and recomputed one at a time by those functions.
//! A test holds the two equal over random families and every outcome.

// Without vector units the loop serves the tests alone.
#![cfg_attr(
    not(any(target_arch = "x86_64", all(target_arch = "wasm32", target_feature = "simd128"))),
    allow(dead_code)
)]

use super::aggregate::DriftTerms;
use super::coagulation::Props;
use super::fdlibm::{EXP_RANGE, exp_moderate, ln_normal, small_integer};
use super::monte_carlo::{Family, Pair, PairRow, PairRule, SIGNIFICAND};
use super::wide::{Bits, Wide};
use std::cell::RefCell;

/// The properties of a column's families that their pairs need, one array
/// per property, in the order of the families.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Lanes {
    mass: Vec<f64>,
    /// 1/m.
    inv_mass: Vec<f64>,
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
    pub inv_mass: f64,
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
            inv_mass: 1.0 / f.mass,
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
    fn arrays(&mut self) -> [&mut Vec<f64>; 12] {
        [
            &mut self.mass,
            &mut self.inv_mass,
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
            lead.inv_mass,
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

/// What a row keeps beside its pair data (which the loop writes straight
/// into the row): whether each pair must be computed one at a time.
#[derive(Debug, Default)]
struct Out {
    scalar: Vec<bool>,
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
    /// Gas: 1/α, Ω, H, ηv_K.
    pub inv_alpha: f64,
    pub omega: f64,
    pub scale_height: f64,
    pub eta_vk: f64,
    /// Monomer internal density ρ₀ and mass m₀; collisional-compaction onset 3bE_roll.
    pub rho0: f64,
    pub m0: f64,
    /// 1/m₀.
    pub inv_m0: f64,
    pub onset: f64,
    /// 1/(3bE_roll).
    pub inv_onset: f64,
    /// Thresholds and erosion prefactor c₁.
    pub r_crit: f64,
    pub v_eros: f64,
    /// 1/v_eros.
    pub inv_v_eros: f64,
    pub v_frag: f64,
    pub v_bounce: f64,
    pub c1: f64,
    /// From the engine: V, f_m, f_φ.
    pub rule: PairRule,
    /// 1/V.
    pub inv_volume: f64,
}

thread_local! {
    static OUT: RefCell<Out> = RefCell::new(Out::default());
}

/// Where the loop writes a row: K/V and headroom into the row of pair data,
/// and whether each pair must be computed one at a time.
struct Sink<'a> {
    c: &'a mut [f64],
    headroom: &'a mut [f32],
    scalar: &'a mut [bool],
}

/// Computes the pair data of `lead` with every family j of `lanes` into
/// entry j of `out`; the pairs that `exact` must compute one at a time are passed to
/// it (it gets the index j). The loop runs eight pairs to an instruction
/// where the processor has AVX-512 (the compiler makes the vectors), four
/// where it has AVX2 and two in WebAssembly with its 128-bit vectors (both
/// through [`super::wide`]); elsewhere every pair is computed by `exact`
/// (without vectors the loop is not worth both sides of every choice).
pub(crate) fn pair_data_row(
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    mut out: PairRow<'_>,
    mut exact: impl FnMut(usize) -> Pair,
) {
    if let Some(run) = Vectors::found().runner() {
        return in_rows(k, lead, lanes, out, exact, run);
    }
    for j in 0..lanes.len().min(out.c.len()) {
        out.set(j, exact(j));
    }
}

/// The vector units the loop can use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Vectors {
    /// None: the loop one pair at a time.
    None,
    /// AVX2: four pairs a step.
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    Avx2,
    /// AVX-512: eight pairs a step.
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    Avx512,
    /// WebAssembly's 128-bit vectors: two pairs a step.
    Simd128,
}

/// A row's loop, given whether to take the compaction law in it; returns
/// how many pairs stick beyond the onset of collisional compaction.
type Runner = fn(bool, &RowConstants, &Lead, &Lanes, Sink) -> usize;

impl Vectors {
    /// The best this processor has.
    pub(crate) fn found() -> Vectors {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f") {
                return Vectors::Avx512;
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                return Vectors::Avx2;
            }
        }
        if cfg!(all(target_arch = "wasm32", target_feature = "simd128")) {
            return Vectors::Simd128;
        }
        Vectors::None
    }

    /// The loop for these units; `None` for [`Vectors::None`] and for units
    /// this processor does not have.
    fn runner(self) -> Option<Runner> {
        #[cfg(target_arch = "x86_64")]
        {
            if self == Vectors::Avx512 && std::arch::is_x86_feature_detected!("avx512f") {
                let run: Runner = |compact, k, lead, lanes, row| {
                    // SAFETY: the processor has AVX-512F (checked above).
                    unsafe {
                        if compact {
                            run_avx512::<true>(k, lead, lanes, row)
                        } else {
                            run_avx512::<false>(k, lead, lanes, row)
                        }
                    }
                };
                return Some(run);
            }
            if self == Vectors::Avx2 && std::arch::is_x86_feature_detected!("avx2") {
                let run: Runner = |compact, k, lead, lanes, row| {
                    // SAFETY: the processor has AVX2 (checked above).
                    unsafe {
                        if compact {
                            run_avx2::<true>(k, lead, lanes, row)
                        } else {
                            run_avx2::<false>(k, lead, lanes, row)
                        }
                    }
                };
                return Some(run);
            }
        }
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        if self == Vectors::Simd128 {
            let run: Runner = |compact, k, lead, lanes, row| {
                if compact {
                    kernel::<super::wide::F2, true>(k, lead, lanes, row)
                } else {
                    kernel::<super::wide::F2, false>(k, lead, lanes, row)
                }
            };
            return Some(run);
        }
        None
    }
}

/// [`pair_data_row`] by the loop on the given vector units (the loop
/// without vectors for [`Vectors::None`]), taking the compaction law in the
/// loop or not: what the loop computes, for the tests that hold it to one
/// pair at a time. `units` must be among what [`Vectors::found`] allows.
#[cfg(test)]
pub(crate) fn loop_row(
    units: Vectors,
    compact: bool,
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    out: PairRow<'_>,
    exact: impl FnMut(usize) -> Pair,
) {
    let scalar: Runner = |compact, k, lead, lanes, row| {
        if compact { kernel::<f64, true>(k, lead, lanes, row) } else { kernel::<f64, false>(k, lead, lanes, row) }
    };
    let run = units.runner().unwrap_or(scalar);
    in_rows(k, lead, lanes, out, exact, move |_, k, lead, lanes, row| run(compact, k, lead, lanes, row));
}

/// A row by `run` (given whether to take the compaction law in the loop),
/// with the pairs it marks computed by `exact`.
fn in_rows(
    k: &RowConstants,
    lead: &Lead,
    lanes: &Lanes,
    mut out: PairRow<'_>,
    mut exact: impl FnMut(usize) -> Pair,
    run: impl FnOnce(bool, &RowConstants, &Lead, &Lanes, Sink) -> usize,
) {
    OUT.with(|cell| {
        let mut row = cell.borrow_mut();
        let row = &mut *row;
        let n = lanes.len().min(out.c.len()).min(out.headroom.len());
        row.scalar.resize(n, false);
        let sink = Sink { c: &mut out.c[..n], headroom: &mut out.headroom[..n], scalar: &mut row.scalar[..n] };
        let compacting = run(row.compact, k, lead, lanes, sink);
        row.compact = 32 * compacting > n;
        for (j, _) in row.scalar[..n].iter().enumerate().filter(|(_, s)| **s) {
            out.set(j, exact(j));
        }
    });
}

/// The loop, compiled for AVX-512 (the compiler makes it eight pairs a step).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn run_avx512<const COMPACT: bool>(k: &RowConstants, lead: &Lead, lanes: &Lanes, out: Sink) -> usize {
    kernel::<f64, COMPACT>(k, lead, lanes, out)
}

/// The loop, four pairs a step in AVX2's registers.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_avx2<const COMPACT: bool>(k: &RowConstants, lead: &Lead, lanes: &Lanes, out: Sink) -> usize {
    kernel::<super::wide::F4, COMPACT>(k, lead, lanes, out)
}

/// ⌊log₂ x⌋ from the binary exponent, and whether x is a positive normal
/// number (where that is exact; see `monte_carlo::floor_log2`).
#[inline(always)]
fn exponent<V: Wide>(x: V) -> (V, V::Mask) {
    let biased = x.to_bits().shr::<52>().and(0x7ff);
    (small_integer::<V>(biased) - V::splat(1023.0), x.gt(V::splat(0.0)) & !biased.eq(0) & !biased.eq(0x7ff))
}

/// ⌊log₂(fx/dx)⌋ of `monte_carlo::room` for dx > 0, from the binary
/// exponents and significands of fx and dx, and whether both are positive
/// normal numbers (where that is exact).
#[inline(always)]
fn room<V: Wide>(fx: V, dx: V) -> (V, V::Mask) {
    let ((ea, oka), (eb, okb)) = (exponent(fx), exponent(dx));
    let significand = |y: V| V::from_bits(y.to_bits().and(SIGNIFICAND).or_c(1f64.to_bits()));
    let borrow = V::select(significand(fx).lt(significand(dx)), V::splat(1.0), V::splat(0.0));
    (ea - eb - borrow, oka & okb)
}

/// One row, without branches: the same operations as the pair-at-a-time
/// functions, with both sides of every choice computed and one kept; `V::LANES`
/// pairs at a time, and the last few one at a time.
#[inline(always)]
fn kernel<V: Wide, const COMPACT: bool>(k: &RowConstants, a: &Lead, lanes: &Lanes, out: Sink) -> usize {
    let n = lanes.len().min(out.c.len());
    let columns = Columns {
        mass: &lanes.mass[..n],
        inv_mass: &lanes.inv_mass[..n],
        filling: &lanes.filling[..n],
        volume: &lanes.volume[..n],
        stokes: &lanes.stokes[..n],
        sqrt_stokes: &lanes.sqrt_stokes[..n],
        inv_1p: &lanes.inv_1p[..n],
        settling: &lanes.settling[..n],
        radial: &lanes.radial[..n],
        azimuthal: &lanes.azimuthal[..n],
        radius: &lanes.radius[..n],
        scale_height2: &lanes.scale_height2[..n],
    };
    let (c, headroom, scalar) = (&mut out.c[..n], &mut out.headroom[..n], &mut out.scalar[..n]);
    // A count rather than a flag per pair: one more array to write tips
    // the compiler's estimate against vectors.
    let mut compacting = 0usize;
    let whole = n - n % V::LANES;
    for i in (0..whole).step_by(V::LANES) {
        compacting += pairs::<V, COMPACT>(k, a, &columns, (&mut *c, &mut *headroom, &mut *scalar), i);
    }
    for i in whole..n {
        compacting += pairs::<f64, COMPACT>(k, a, &columns, (&mut *c, &mut *headroom, &mut *scalar), i);
    }
    compacting
}

/// [`Lanes`] cut to the families of one row.
struct Columns<'a> {
    mass: &'a [f64],
    inv_mass: &'a [f64],
    filling: &'a [f64],
    volume: &'a [f64],
    stokes: &'a [f64],
    sqrt_stokes: &'a [f64],
    inv_1p: &'a [f64],
    settling: &'a [f64],
    radial: &'a [f64],
    azimuthal: &'a [f64],
    radius: &'a [f64],
    scale_height2: &'a [f64],
}

/// The pairs of `a` with families `i..i + V::LANES`, written to `out` (K/V,
/// headroom, whether to compute the pair one at a time); returns how many of
/// them stick beyond the onset of collisional compaction.
#[inline(always)]
fn pairs<V: Wide, const COMPACT: bool>(
    k: &RowConstants,
    a: &Lead,
    l: &Columns,
    out: (&mut [f64], &mut [f32], &mut [bool]),
    i: usize,
) -> usize {
    let s = V::splat;
    let (mb, phib, sb) = (V::load(l.mass, i), V::load(l.filling, i), V::load(l.stokes, i));
    let d = &a.drift;
    // Relative velocity (Column::velocity_with).
    let a_first = s(d.stokes).ge(sb);
    let s1 = V::select(a_first, s(d.stokes), sb);
    let s2 = V::select(a_first, sb, s(d.stokes));
    let gap = s1 - s2;
    let spread = s(k.epsilon) * s1;
    let diff = (gap * gap + spread * spread).sqrt();
    let s2e = (s1 - diff).max(s(0.0));
    let brownian2 = s(k.brownian) * (s(a.inv_mass) + V::load(l.inv_mass, i));
    let sqrt1 = V::select(a_first, s(d.sqrt_stokes), V::load(l.sqrt_stokes, i));
    // 1/(1 + St₁), kept per family.
    let inv1p = V::select(a_first, s(a.inv_1p), V::load(l.inv_1p, i));
    let fast = s(k.vg) * (inv1p + s(1.0) / (s(1.0) + s2e)).sqrt();
    let turbulence =
        V::select(s1.lt(s(k.st_eta)), s(k.vg_re) * diff, V::select(s1.lt(s(1.0)), s(k.vg_155) * sqrt1, fast));
    let inv1 = s(1.0) / (s(1.0) + s2e);
    let inv2 = s(1.0) / (s(1.0) + s2e * s2e);
    let h_d = s(1.0) / (s(1.0) + s2e * s(k.inv_alpha) * (s(1.0) + s(2.0) * s2e) * inv1).sqrt();
    let settling2 = s(k.omega) * s2e * inv1 * h_d * s(k.scale_height);
    let radial2 = s(2.0) * s2e * s(k.eta_vk) * inv2;
    let azimuthal2 = s(k.eta_vk) * inv2;
    let ds = V::select(a_first, s(d.settling), V::load(l.settling, i)) - settling2;
    let dr = V::select(a_first, s(d.radial), V::load(l.radial, i)) - radial2;
    let da = V::select(a_first, s(d.azimuthal), V::load(l.azimuthal, i)) - azimuthal2;
    let v = (brownian2 + turbulence * turbulence + ds * ds + dr * dr + da * da).sqrt();
    // Rate coefficient (Column::rate_at).
    let r = s(a.radius) + V::load(l.radius, i);
    let rate = s(1.253_314_137_315_500_3) * r * r * v / (s(a.scale_height2) + V::load(l.scale_height2, i)).sqrt();
    // Outcome (aggregate::outcome).
    let a_target = s(a.mass).ge(mb);
    let (tm, tphi) = (V::select(a_target, s(a.mass), mb), V::select(a_target, s(a.filling), phib));
    let pm = V::select(a_target, mb, s(a.mass));
    // Volumes m/(ρ₀φ), kept per family.
    let volume = V::load(l.volume, i);
    let (vt, vp) = (V::select(a_target, s(a.volume), volume), V::select(a_target, volume, s(a.volume)));
    let small = tm.min(pm).lt(s(k.r_crit) * tm.max(pm));
    let eroding = small & v.gt(s(k.v_eros));
    let shattering = v.ge(s(k.v_frag));
    let fragment = !small & shattering;
    let bounce = !small & !shattering & v.ge(s(k.v_bounce));
    let stick = !(eroding | fragment | bounce);
    let lost = s(k.c1) * (s(1.0) * (v * s(k.inv_v_eros))) * pm;
    let shatter = fragment | (eroding & lost.ge(tm));
    // Filling-factor change of sticking (coagulation::filling_change_with).
    let larger = vt.ge(vp);
    let (va, vb) = (V::select(larger, vt, vp), V::select(larger, vp, vt));
    // hit_and_stick_void: capped above V₁/V₂ = 650.
    let void = V::select(
        va.gt(s(650.0) * vb),
        s(6.94) * vb,
        (s(0.99) - s(1.03) * ln_normal(s(2.0) * vb / (va + vb))).min(s(6.94)) * vb,
    );
    let m = tm + pm;
    let phi_hs = m / (s(k.rho0) * (va + vb + void));
    let full = phi_hs.ge(s(1.0));
    let inv_m = s(1.0) / m;
    let e = s(0.5) * tm * pm * inv_m * v * v;
    let n_mono = m * s(k.inv_m0);
    let x = e * s(k.m0) * inv_m * s(k.inv_onset);
    let hs2 = phi_hs * phi_hs;
    let hs10 = hs2 * hs2 * hs2 * hs2 * hs2;
    let below = (x * x * x).lt(hs10 * n_mono * n_mono * s(1.0 - 1e-9));
    // Collisional compaction: the power law where it may exceed φ_hs.
    let compacting_here = !(full | e.le(s(k.onset)) | (below & hs10.gt(s(1e-250)) & n_mono.lt(s(1e100))));
    // Without COMPACT, every pair that gets here is computed one at a time.
    let (phi_c, in_range) = if COMPACT {
        let (okx, okn) = (exponent(x).1, exponent(n_mono).1);
        let power = s(0.3) * ln_normal(x) - s(0.2) * ln_normal(n_mono);
        (exp_moderate(power), okx & okn & power.abs().lt(s(EXP_RANGE)))
    } else {
        (s(0.0), s(0.0).lt(s(0.0)))
    };
    let compacted = compacting_here & phi_c.gt(phi_hs);
    let grown = vp + void;
    let change = V::select(
        full,
        s(1.0) - tphi,
        V::select(compacted, phi_c.min(s(1.0)) - tphi, tphi * (pm * vt - tm * grown) / (tm * (vt + grown))),
    );
    // Pair data (PairRule::data).
    let c = rate * s(k.inv_volume);
    let dm = V::select(stick, pm, V::select(bounce, s(0.0), V::select(shatter, tm, lost)));
    let dphi = V::select(stick, change.abs(), V::select(bounce | !shatter, s(0.0), tphi));
    let (hm, ok_m) = room(s(k.rule.f_m) * tm, dm);
    let (hp, ok_p) = room(s(k.rule.f_phi) * tphi, dphi);
    let (moves_m, moves_phi) = (dm.gt(s(0.0)), dphi.gt(s(0.0)));
    let hm = V::select(moves_m, hm, s(f64::INFINITY));
    let hp = V::select(moves_phi, hp, s(f64::INFINITY));
    let (out_c, out_h, out_s) = out;
    V::select(bounce, s(0.0), c).store(out_c, i);
    hm.min(hp).store_f32(out_h, i);
    let one_at_a_time = (stick & compacting_here & !in_range) | (moves_m & !ok_m) | (moves_phi & !ok_p);
    V::store_mask(one_at_a_time, out_s, i);
    V::count(stick & compacting_here)
}
