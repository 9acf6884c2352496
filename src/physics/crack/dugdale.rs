//! The exact crack-speed relation of a three-element viscoelastic solid with
//! a Dugdale (Maugis–Dugdale) cohesive zone, for any modulus ratio k.
//!
//! The solid has the creep compliance ψ(t)/E* with ψ(t) = 1 − (1 − k)e^{−t/T}
//! (ψ(0) = k: the instantaneous modulus is E*/k, the relaxed one E*). At the
//! contact edge a cohesive zone of length c carries the uniform stress
//! σ₀ = γ/z₀ over a separation h₀ = γ/σ₀ (Dugdale). A crack moving steadily
//! at speed V takes the time τ = c/V to cross the zone; write θ = τ/T.
//!
//! **Opening crack** (Schapery; Greenwood & Johnson 1981; Greenwood 2004).
//! The stresses are the elastic ones and the opening is the hereditary
//! integral of the elastic opening δ_e(ρ) of the uniform-stress zone. The
//! opening where the zone ends must be h₀, which gives
//!
//!   1/β = ∫₀¹ ψ(τ(1 − u²)) u ln[(1 + u)/(1 − u)] du = k + (1 − k) F_L(θ),
//!
//! with G = K²/(2E*) the far-field (relaxed) energy release rate, β = G/γ and
//! c = πE*βγ/(4σ₀²), so that the scaled crack speed is
//! g = σ₀²Tȧ/(E*γ) = −(π/4)β/θ.
//!
//! **Healing crack.** A point meets the cohesive stress σ₀ once its faces
//! come within h₀ and is bonded when they touch. With the relaxation form
//! of the correspondence principle the elastic-equivalent stress in the
//! zone is σ₀ψ(t) (t the time since the point entered it), and the elastic
//! problem of a semi-infinite crack loaded by that stress, free of a stress
//! singularity where the faces close and opened by h₀ where they enter the
//! zone, gives
//!
//!   J₂ = ∫₀¹ ψ(τ(1 − u²)) du = k + (1 − k) F₁(θ),
//!   J₁ = ∫₀¹ ψ(τ(1 − u²)) [2 − u ln((1 + u)/(1 − u))] du = k + (1 − k)(2F₁ − F_L),
//!   β = J₂²/J₁,   g = (π/4)/(θ J₁).
//!
//! Both are exact within the Dugdale model, and depend on k only through
//! ψ. The four functions of θ alone,
//!
//!   E₁(θ) = ∫₀¹ e^{−θ(1−u²)} du,   E_L(θ) = ∫₀¹ e^{−θ(1−u²)} u ln[(1+u)/(1−u)] du,
//!
//! and their complements F₁ = 1 − E₁, F_L = 1 − E_L (computed directly, so
//! that neither end loses digits), are integrated once per process on a
//! grid of ln θ; the table of a k is arithmetic on them (under 0.1 ms) and is
//! kept in a small cache. Between nodes ln|g| is a cubic Hermite function of
//! z = ln(β − k) − ln(1 − β) (of 1/β for the opening branch) with exact
//! slopes at the nodes, so g(β) is continuously differentiable, monotone and
//! smooth in k; beyond the table it continues linearly in z, where
//! ln|g| ≈ −z + const holds to the logarithm of a logarithm. A collision
//! evaluates the law some thousand times: it reads |g| off bins of
//! r = e^z picked by r's binary exponent and leading significand bits,
//! a polynomial on each fitted to the Hermite function when first used
//! (`Binned`), with no logarithm or exponential.
//!
//! Limits: slow cracks give 1 ∓ β ≈ (1 − k)[ln(4θ) + γ_E]/(2θ) with
//! g = ±(π/4)/θ; fast ones β − k ≈ (1 − k)θ/3 (healing) and
//! 1/β − k ≈ (1 − k)θ/3 (opening).

use std::f64::consts::PI;
use std::sync::{Arc, Mutex, OnceLock};

/// ln θ of the first and last node, and the spacing.
const LN_THETA_MIN: f64 = -24.0;
const LN_THETA_MAX: f64 = 24.0;
const LN_THETA_STEP: f64 = 0.125;

/// Gauss–Legendre points of one panel.
const GAUSS_POINTS: usize = 12;

/// E₁, F₁, E_L, F_L and the derivatives dE₁/dθ, dE_L/dθ at one θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Moments {
    pub e1: f64,
    pub f1: f64,
    pub el: f64,
    pub fl: f64,
    pub de1: f64,
    pub del: f64,
}

/// Gauss–Legendre nodes and weights on [−1, 1] by Newton's iteration on
/// P_n (a dozen lines; no quadrature crate is needed for one fixed rule).
pub(crate) fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut rule = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=n {
                let p2 = ((2 * j - 1) as f64 * x * p1 - (j - 1) as f64 * p0) / j as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        rule.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    rule
}

/// The moments at θ by composite Gauss–Legendre quadrature, written over
/// v = 1 − u² ∈ (0, 1): E₁ = ∫ e^{−θv} dv/(2√(1−v)), E_L = ∫ e^{−θv} artanh√(1−v) dv.
/// On (0, ½] the variable is ln v (the log singularity of artanh and the
/// boundary layer of width 1/θ become smooth), on [½, 1) it is r = √(1−v).
pub(crate) fn moments(theta: f64, rule: &[(f64, f64)]) -> Moments {
    let mut m = Moments { e1: 0.0, f1: 0.0, el: 0.0, fl: 0.0, de1: 0.0, del: 0.0 };
    let mut add = |v: f64, w1: f64, wl: f64, jac: f64| {
        let e = (-theta * v).exp();
        let f = -(-theta * v).exp_m1();
        m.e1 += jac * e * w1;
        m.f1 += jac * f * w1;
        m.el += jac * e * wl;
        m.fl += jac * f * wl;
        m.de1 -= jac * v * e * w1;
        m.del -= jac * v * e * wl;
    };
    // (0, ½] in t = ln v, panels of unit width down to where nothing is left.
    let t_top = 0.5f64.ln();
    let t_low = -(40.0 + theta.ln().max(0.0));
    let panels = (t_top - t_low).ceil() as usize;
    for p in 0..panels {
        let hi = t_top - p as f64;
        let lo = hi - 1.0;
        let (mid, half) = (0.5 * (hi + lo), 0.5 * (hi - lo));
        for &(x, w) in rule {
            let t = mid + half * x;
            let v = t.exp();
            let r = (1.0 - v).sqrt();
            // artanh r = ln(1 + r) − ½ ln v, without the cancellation in 1 − r.
            let wl = (1.0 + r).ln() - 0.5 * t;
            add(v, 0.5 / r, wl, w * half * v);
        }
    }
    // [½, 1) in r = √(1 − v): dv = 2r dr, so dv/(2√(1−v)) = dr.
    let r_top = 0.5f64.sqrt();
    let n = 4;
    for p in 0..n {
        let lo = r_top * p as f64 / n as f64;
        let hi = r_top * (p + 1) as f64 / n as f64;
        let (mid, half) = (0.5 * (hi + lo), 0.5 * (hi - lo));
        for &(x, w) in rule {
            let r = mid + half * x;
            let v = 1.0 - r * r;
            add(v, 1.0 / (2.0 * r), r.atanh(), w * half * 2.0 * r);
        }
    }
    m
}

/// The k-independent moments on the ln θ grid.
struct Base {
    ln_theta: Vec<f64>,
    moments: Vec<Moments>,
}

fn base() -> &'static Base {
    static BASE: OnceLock<Base> = OnceLock::new();
    BASE.get_or_init(|| {
        let rule = gauss_legendre(GAUSS_POINTS);
        let n = ((LN_THETA_MAX - LN_THETA_MIN) / LN_THETA_STEP).round() as usize;
        let ln_theta: Vec<f64> = (0..=n).map(|i| LN_THETA_MIN + i as f64 * LN_THETA_STEP).collect();
        let moments = ln_theta.iter().map(|&s| moments(s.exp(), &rule)).collect();
        Base { ln_theta, moments }
    })
}

/// The cubic Hermite interpolant of values `y` with slopes `slope` on the
/// interval from node `i` to `i + 1` of width `h`, at fraction `t` of it:
/// its value and slope.
fn hermite(y: &[f64], slope: &[f64], i: usize, t: f64, h: f64) -> (f64, f64) {
    let (y0, y1) = (y[i], y[i + 1]);
    let (m0, m1) = (slope[i] * h, slope[i + 1] * h);
    let t2 = t * t;
    let t3 = t2 * t;
    let value =
        (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * m0 + (-2.0 * t3 + 3.0 * t2) * y1 + (t3 - t2) * m1;
    let rate = ((6.0 * t2 - 6.0 * t) * y0
        + (3.0 * t2 - 4.0 * t + 1.0) * m0
        + (-6.0 * t2 + 6.0 * t) * y1
        + (3.0 * t2 - 2.0 * t) * m1)
        / h;
    (value, rate)
}

/// One branch of the law at one k: ln|g| against z, with slopes.
#[derive(Debug, Clone)]
struct Branch {
    z: Vec<f64>,
    y: Vec<f64>,
    slope: Vec<f64>,
}

impl Branch {
    /// ln|g| and d ln|g|/dz at z (cubic Hermite inside, linear outside).
    fn eval(&self, z: f64) -> (f64, f64) {
        let n = self.z.len();
        if z <= self.z[0] {
            return (self.y[0] + self.slope[0] * (z - self.z[0]), self.slope[0]);
        }
        if z >= self.z[n - 1] {
            return (self.y[n - 1] + self.slope[n - 1] * (z - self.z[n - 1]), self.slope[n - 1]);
        }
        let i = self.z.partition_point(|&x| x <= z).clamp(1, n - 1) - 1;
        let h = self.z[i + 1] - self.z[i];
        let t = (z - self.z[i]) / h;
        hermite(&self.y, &self.slope, i, t, h)
    }
}

/// Bins of r per factor of two (a power of two: the bins are read off r's
/// leading significand bits).
const BIN_BITS: u32 = 5;

/// The significand bits below a bin's: their value is r's place in its bin.
const BIN_SHIFT: u32 = 52 - BIN_BITS;

/// Degree of a bin's polynomial.
const BIN_DEGREE: usize = 5;

/// A branch as |g| against r = e^z, on bins that r's binary exponent and
/// its leading `BIN_BITS` significand bits pick, each a 32nd of a factor of
/// two wide (3 % of r, a 32nd of ln 2 in z): an evaluation takes neither
/// the logarithm for z nor the exponential of ln|g|, only integer
/// arithmetic on r's bits and two polynomials. On each bin |g| is the
/// polynomial of degree 5 in u ∈ [−1, 1) (linear in r) through the
/// branch's values at the six Chebyshev points; over the bins it differs
/// from the branch by below 10⁻⁹ relative, and its slope by below 10⁻⁶ (a
/// test holds both). A bin is fitted when it is first evaluated (six
/// evaluations of the branch and a 6 × 6 product): a collision meets a few
/// hundred of some 2 000, and a new k costs only its branches. Where r lies
/// outside the bins (beyond the nodes, or in the first or last bin, which
/// the nodes only partly cover) the branch itself is evaluated.
#[derive(Debug, Clone)]
struct Binned {
    branch: Branch,
    /// r's bits shifted right by `BIN_SHIFT` at the first bin.
    first: u64,
    /// The coefficients of u⁰ … u⁵ on each bin, once fitted.
    bins: Box<[OnceLock<[f64; BIN_DEGREE + 1]>]>,
}

/// The Chebyshev points of a bin's fit on [−1, 1], and the inverse of their
/// Vandermonde matrix (which turns the values there into the coefficients).
struct Fit {
    nodes: [f64; BIN_DEGREE + 1],
    inverse: nalgebra::SMatrix<f64, { BIN_DEGREE + 1 }, { BIN_DEGREE + 1 }>,
}

fn fit() -> &'static Fit {
    static FIT: OnceLock<Fit> = OnceLock::new();
    FIT.get_or_init(|| {
        let nodes: [f64; BIN_DEGREE + 1] =
            std::array::from_fn(|i| -((2 * i + 1) as f64 * PI / (2 * (BIN_DEGREE + 1)) as f64).cos());
        let vandermonde =
            nalgebra::SMatrix::<f64, { BIN_DEGREE + 1 }, { BIN_DEGREE + 1 }>::from_fn(|i, j| nodes[i].powi(j as i32));
        // The Vandermonde matrix of distinct points is invertible (its
        // condition number here is about 10²).
        let inverse = vandermonde.try_inverse().unwrap_or_else(nalgebra::SMatrix::zeros);
        Fit { nodes, inverse }
    })
}

impl Binned {
    fn of(branch: Branch) -> Binned {
        let (z0, z1) = (branch.z[0], branch.z[branch.z.len() - 1]);
        // Bins wholly inside [e^{z0}, e^{z1}].
        let first = (z0.exp().to_bits() >> BIN_SHIFT) + 1;
        let end = (z1.exp().to_bits() >> BIN_SHIFT).max(first);
        let bins = (first..end).map(|_| OnceLock::new()).collect();
        Binned { branch, first, bins }
    }

    /// The coefficients of bin `i` (relative to the first), fitted to the branch.
    #[cold]
    fn fitted(&self, i: usize) -> [f64; BIN_DEGREE + 1] {
        let bin = self.first + i as u64;
        let (lo, hi) = (f64::from_bits(bin << BIN_SHIFT), f64::from_bits((bin + 1) << BIN_SHIFT));
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        let fit = fit();
        let values = nalgebra::SVector::<f64, { BIN_DEGREE + 1 }>::from_fn(|j, _| {
            self.branch.eval((mid + half * fit.nodes[j]).ln()).0.exp()
        });
        let c = fit.inverse * values;
        std::array::from_fn(|j| c[j])
    }

    /// |g| and d|g|/dr at r = e^z > 0.
    #[inline]
    fn eval(&self, r: f64) -> (f64, f64) {
        let bits = r.to_bits();
        // r ≤ 0, NaN and r beyond the bins fall outside (a negative r's sign
        // bit makes its index huge).
        let i = (bits >> BIN_SHIFT).wrapping_sub(self.first) as usize;
        let Some(cell) = self.bins.get(i) else {
            let (y, dy) = self.branch.eval(r.ln());
            let g = y.exp();
            return (g, g * dy / r);
        };
        let c = cell.get_or_init(|| self.fitted(i));
        // r's place in its bin, u ∈ [−1, 1), from the bits below the bin's.
        let t = (bits & ((1 << BIN_SHIFT) - 1)) as f64 * (1.0 / (1u64 << BIN_SHIFT) as f64);
        let u = 2.0 * t - 1.0;
        // Estrin's scheme: pairs of terms side by side, half the chain of
        // dependent operations of Horner's (each evaluation waits on it).
        let u2 = u * u;
        let u4 = u2 * u2;
        let g = (c[0] + c[1] * u) + u2 * (c[2] + c[3] * u) + u4 * (c[4] + c[5] * u);
        let dg_du = (c[1] + 2.0 * c[2] * u) + u2 * (3.0 * c[3] + 4.0 * c[4] * u) + u4 * (5.0 * c[5]);
        // du/dr = 2/w for the bin's width w = 2^(E − 1023 − BIN_BITS), E
        // r's biased exponent (normal here): 2/w = 2^(1024 + BIN_BITS − E),
        // whose biased exponent is 2047 + BIN_BITS − E.
        let du_dr = f64::from_bits((2047 + u64::from(BIN_BITS) - (bits >> 52)) << 52);
        (g, dg_du * du_dr)
    }
}

/// The exact Dugdale crack law at one modulus ratio k.
#[derive(Debug, Clone)]
pub struct FullLaw {
    k: f64,
    healing: Binned,
    opening: Binned,
}

/// β, g and their θ-derivatives of the healing branch at one node.
pub(crate) struct Node {
    /// β (healing) or 1/β (opening).
    #[cfg_attr(not(test), allow(dead_code))]
    pub beta: f64,
    pub beta_minus_k: f64,
    pub one_minus_beta: f64,
    pub g: f64,
    pub dbeta: f64,
    pub dlng: f64,
}

/// The healing crack (β < 1) at θ from its moments.
pub(crate) fn healing_node(k: f64, theta: f64, m: &Moments) -> Node {
    let q = 1.0 - k;
    let j1 = k + q * (2.0 * m.f1 - m.fl);
    let j2 = k + q * m.f1;
    let dj1 = q * (-2.0 * m.de1 + m.del);
    let dj2 = -q * m.de1;
    Node {
        beta: j2 * j2 / j1,
        beta_minus_k: q * (q * m.f1 * m.f1 + k * m.fl) / j1,
        one_minus_beta: q * (m.el - q * m.e1 * m.e1) / j1,
        g: PI / 4.0 / (theta * j1),
        dbeta: (2.0 * j2 * dj2 * j1 - j2 * j2 * dj1) / (j1 * j1),
        dlng: -1.0 / theta - dj1 / j1,
    }
}

/// The opening crack (β > 1) at θ, written for b = 1/β (g is −`g`).
pub(crate) fn opening_node(k: f64, theta: f64, m: &Moments) -> Node {
    let q = 1.0 - k;
    let b = k + q * m.fl;
    let db = -q * m.del;
    Node {
        beta: b,
        beta_minus_k: q * m.fl,
        one_minus_beta: q * m.el,
        g: PI / 4.0 / (theta * b),
        dbeta: db,
        dlng: -1.0 / theta - db / b,
    }
}

/// The healing and opening branches at modulus ratio `k`, from the shared moments.
fn branches(k: f64) -> (Branch, Branch) {
    let base = base();
    let mut healing = Branch { z: Vec::new(), y: Vec::new(), slope: Vec::new() };
    let mut opening = healing.clone();
    for (&s, m) in base.ln_theta.iter().zip(&base.moments) {
        let theta = s.exp();
        for (branch, node) in [(&mut healing, healing_node(k, theta, m)), (&mut opening, opening_node(k, theta, m))] {
            if !(node.beta_minus_k > 0.0 && node.one_minus_beta > 0.0) {
                continue;
            }
            let z = node.beta_minus_k.ln() - node.one_minus_beta.ln();
            let dz = node.dbeta * (1.0 / node.beta_minus_k + 1.0 / node.one_minus_beta);
            if branch.z.last().is_some_and(|&last| z <= last) || dz <= 0.0 {
                continue;
            }
            branch.z.push(z);
            branch.y.push(node.g.ln());
            branch.slope.push(node.dlng / dz);
        }
    }
    (healing, opening)
}

impl FullLaw {
    /// Builds the law at modulus ratio `k` (0 < k < 1) from the shared moments.
    fn new(k: f64) -> FullLaw {
        let (healing, opening) = branches(k);
        FullLaw { k, healing: Binned::of(healing), opening: Binned::of(opening) }
    }

    /// The law at `k`, from a cache of recently used k.
    pub fn at(k: f64) -> Arc<FullLaw> {
        static CACHE: Mutex<Vec<Arc<FullLaw>>> = Mutex::new(Vec::new());
        let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(law) = cache.iter().find(|l| l.k.to_bits() == k.to_bits()) {
            return law.clone();
        }
        let law = Arc::new(FullLaw::new(k));
        if cache.len() >= 64 {
            cache.remove(0);
        }
        cache.push(law.clone());
        law
    }

    /// g(β) = σ₀²T ȧ/(E*γ) and dg/dβ for k < β < 1/k.
    pub fn speed(&self, beta: f64) -> (f64, f64) {
        self.speed_of_ratio(beta, 1.0)
    }

    /// [`FullLaw::speed`] at β = p/s (s > 0). r is (p − ks)/(s − p) on the
    /// healing branch and (s − kp)/(p − s) on the opening one (r of 1/β),
    /// and on both dg/dβ = d|g|/dr · (1 − k)(s/|s − p|)²: one division, where
    /// β itself and then r took two in turn.
    pub fn speed_of_ratio(&self, p: f64, s: f64) -> (f64, f64) {
        let k = self.k;
        if p < s {
            let q = 1.0 / (s - p);
            let (g, dg_dr) = self.healing.eval((p - k * s) * q);
            let sq = s * q;
            (g, dg_dr * ((1.0 - k) * sq * sq))
        } else if p > s {
            let q = 1.0 / (p - s);
            let (g, dg_dr) = self.opening.eval((s - k * p) * q);
            let sq = s * q;
            (-g, dg_dr * ((1.0 - k) * sq * sq))
        } else {
            (0.0, 0.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// E₁, F₁, E_L, F_L, dE₁/dθ, dE_L/dθ at θ, integrated with mpmath at 30 digits.
    // The digits as the quadrature printed them.
    #[allow(clippy::excessive_precision)]
    const REFERENCE: [(f64, [f64; 6]); 8] = [
        (
            1e-9,
            [
                0.99999999933333333,
                6.666666664e-10,
                0.99999999966666667,
                3.3333333324444444e-10,
                -0.66666666613333333,
                -0.33333333315555556,
            ],
        ),
        (
            1e-4,
            [
                0.99993333599992381,
                6.6664000076188783e-5,
                0.99996666755553651,
                3.3332444463491725e-5,
                -0.66661333561897989,
                -0.33331555612697058,
            ],
        ),
        (
            0.1,
            [
                0.93592547232883117,
                0.064074527671168822,
                0.96753684149705082,
                0.032463158502949183,
                -0.61555283397298706,
                -0.31611369168219639,
            ],
        ),
        (
            1.0,
            [
                0.53807950691276842,
                0.46192049308723158,
                0.7394416300990793,
                0.2605583699009207,
                -0.30711926036915263,
                -0.20136212318631088,
            ],
        ),
        (
            10.0,
            [
                0.053037580992901645,
                0.94696241900709835,
                0.21057151592798644,
                0.78942848407201356,
                -0.0056894600425467271,
                -0.015753393493508479,
            ],
        ),
        (
            1e3,
            [
                0.0005002503759407961,
                0.9994997496240592,
                0.004435382464688457,
                0.99556461753531154,
                -5.0050112876649542e-7,
                -3.9351320887476609e-6,
            ],
        ),
        (
            1e6,
            [
                5.00000250000375e-7,
                0.99999949999974999,
                7.8895100419926613e-6,
                0.99999211048995801,
                -5.00000500001125e-13,
                -7.3895097919922863e-12,
            ],
        ),
        (
            1e9,
            [
                5.0000000025e-10,
                0.99999999949999999,
                1.1343387931233917e-8,
                0.99999998865661207,
                -5.000000005e-19,
                -1.0843387930983917e-17,
            ],
        ),
    ];

    #[test]
    fn moments_match_a_thirty_digit_quadrature() {
        let rule = gauss_legendre(GAUSS_POINTS);
        for (theta, want) in REFERENCE {
            let m = moments(theta, &rule);
            let got = [m.e1, m.f1, m.el, m.fl, m.de1, m.del];
            for (g, w) in got.iter().zip(want) {
                assert!((g / w - 1.0).abs() < 1e-12, "θ = {theta}: {got:?} against {want:?}");
            }
        }
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        let rule = gauss_legendre(GAUSS_POINTS);
        for p in 0..(2 * GAUSS_POINTS) {
            let sum: f64 = rule.iter().map(|(x, w)| w * x.powi(p as i32)).sum();
            let exact = if p % 2 == 1 { 0.0 } else { 2.0 / (p as f64 + 1.0) };
            assert!((sum - exact).abs() < 1e-14, "x^{p}: {sum} against {exact}");
        }
    }

    #[test]
    fn interpolation_between_nodes_matches_the_relation() {
        // Halfway between two nodes of ln θ the interpolated g(β) must equal
        // the relation computed directly there.
        let rule = gauss_legendre(GAUSS_POINTS);
        for k in [0.005, 0.02, 0.1, 0.3] {
            let law = FullLaw::new(k);
            let mut worst: f64 = 0.0;
            let mut s = LN_THETA_MIN + 0.5 * LN_THETA_STEP;
            while s < LN_THETA_MAX {
                let theta = s.exp();
                let m = moments(theta, &rule);
                let h = healing_node(k, theta, &m);
                if h.one_minus_beta > 1e-8 && h.beta_minus_k > 1e-8 * k {
                    let (g, _) = law.speed(h.beta);
                    worst = worst.max((g / h.g - 1.0).abs());
                }
                let o = opening_node(k, theta, &m);
                if o.one_minus_beta > 1e-8 && o.beta_minus_k > 1e-8 * k {
                    let (g, _) = law.speed(1.0 / o.beta);
                    worst = worst.max((-g / o.g - 1.0).abs());
                }
                s += LN_THETA_STEP;
            }
            assert!(worst < 2e-6, "k = {k}: largest relative error of g between nodes {worst:e}");
        }
    }

    #[test]
    fn the_bins_equal_the_branch_they_tabulate() {
        // |g| and d|g|/dr from the bins against the branch's cubic Hermite
        // function of z at 40 points a bin, both ends of a bin among them.
        for k in [0.005, 0.02, 0.1, 0.3, 0.9] {
            let (healing, opening) = branches(k);
            for (name, branch) in [("healing", healing), ("opening", opening)] {
                let bins = Binned::of(branch.clone());
                assert!(bins.bins.len() > 1000, "k = {k}, {name}: {} bins", bins.bins.len());
                let (mut worst_g, mut worst_slope): (f64, f64) = (0.0, 0.0);
                for bin in 0..bins.bins.len() as u64 {
                    let lo = f64::from_bits((bins.first + bin) << BIN_SHIFT);
                    let hi = f64::from_bits((bins.first + bin + 1) << BIN_SHIFT);
                    for j in 0..40 {
                        let r = (lo + (hi - lo) * j as f64 / 40.0).max(lo);
                        let (g, dg) = bins.eval(r);
                        let (y, dy) = branch.eval(r.ln());
                        let (g_ref, dg_ref) = (y.exp(), y.exp() * dy / r);
                        worst_g = worst_g.max((g / g_ref - 1.0).abs());
                        worst_slope = worst_slope.max((dg / dg_ref - 1.0).abs());
                    }
                }
                assert!(worst_g < 1e-9, "k = {k}, {name}: |g| off by {worst_g:e}");
                assert!(worst_slope < 1e-6, "k = {k}, {name}: d|g|/dr off by {worst_slope:e}");
            }
        }
    }

    #[test]
    fn the_law_from_a_ratio_equals_the_law_at_the_quotient() {
        // β = p/s on both branches and over the whole domain, s over many
        // decades: r from p and s differs from r from β by rounding, which
        // may pick the neighbouring bin (the bins agree to 10⁻⁹ there).
        for k in [0.005, 0.02, 0.3] {
            let law = FullLaw::new(k);
            for i in 1..400 {
                let beta = k * (1.0 / (k * k)).powf(i as f64 / 400.0);
                for s in [1e-3, 0.7, 1.0, 3.0, 1e4] {
                    let (g, dg) = law.speed_of_ratio(beta * s, s);
                    let (g_ref, dg_ref) = law.speed(beta);
                    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1e-300);
                    assert!(close(g, g_ref, 1e-9), "k = {k}, β = {beta}, s = {s}: g {g} against {g_ref}");
                    assert!(close(dg, dg_ref, 1e-6), "k = {k}, β = {beta}, s = {s}: dg/dβ {dg} against {dg_ref}");
                }
            }
            assert_eq!(law.speed_of_ratio(2.0, 2.0), (0.0, 0.0));
        }
    }
}
