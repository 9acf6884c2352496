//! The exponential, the cube root and the bounds (`max`, `min`) of the batch
//! model's inner loops, for WebAssembly.
//!
//! A WebAssembly module has no C library: `f64::exp` and `f64::cbrt` there
//! are Rust's `libm`, FreeBSD's `e_exp.c` (a division and several branches,
//! about 13 ns a call in V8 against 5 ns for glibc's natively) and CORE-MATH's
//! correctly rounded cube root, which takes fused multiply-adds that
//! WebAssembly does not have and `libm` emulates in software (70 ns against
//! 20 ns). In the browser's formation zone they were a fifth and a twelfth
//! of the workers' time. (The Monte Carlo column's drag and radii take them
//! too, so a column in the browser takes its own random path, as it did
//! with `libm`.) [`exp`] and [`cbrt`] are the functions the model's
//! hot paths call: on every other target they are `std`'s, bit for bit (a
//! native result does not change); in WebAssembly they are [`exp_tabled`]
//! and [`cbrt_newton`], which need no fused multiply-add:
//! - exp x = 2^k 2^{i/128} e^r with |r| ≤ ln 2/256, 2^{i/128} from a table
//!   of 128 double-word values made at compile time, e^r − 1 by a
//!   polynomial of degree 5; no division, one branch for the range;
//! - the cube root from an estimate of 5 % by the exponent's bits, two
//!   Halley steps to 10⁻¹², and a last step from that value rounded to 26
//!   bits, whose cube is an exact double word.
//!
//! Tests hold both to glibc's over millions of arguments: the exponential
//! within one unit in the last place of it (equal in all but 0.06 %), the
//! cube root within half a unit of the true root, by its residual. The crates that offer such
//! functions either are `libm` itself or assume hardware fused multiply-adds.

/// e^x: `std`'s natively, [`exp_tabled`] in WebAssembly.
#[inline]
pub fn exp(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        exp_tabled(x)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        x.exp()
    }
}

/// ∛x: `std`'s natively, [`cbrt_newton`] in WebAssembly.
#[inline]
pub fn cbrt(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        cbrt_newton(x)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        x.cbrt()
    }
}

/// The larger and the smaller of two numbers in the model's inner loops, as
/// `f64::max` and `f64::min` (a NaN gives the other number): `std`'s
/// natively, bit for bit; in WebAssembly, whose `f64.max` and `f64.min`
/// return a NaN where Rust's must not, `std`'s become calls to `libm`'s
/// `fmax` and `fmin` (6 % of the formation zone's time in V8 11.3; newer
/// engines inline them), and these are two comparisons kept in line. (They
/// may differ from `std`'s in the sign of a zero, which Rust leaves open
/// too.)
pub trait Bounds {
    /// The larger of `self` and `other`, as `f64::max`.
    fn at_least(self, other: Self) -> Self;
    /// The smaller of `self` and `other`, as `f64::min`.
    fn at_most(self, other: Self) -> Self;
}

impl Bounds for f64 {
    #[inline(always)]
    fn at_least(self, other: f64) -> f64 {
        #[cfg(target_arch = "wasm32")]
        {
            larger(self, other)
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.max(other)
        }
    }

    #[inline(always)]
    fn at_most(self, other: f64) -> f64 {
        #[cfg(target_arch = "wasm32")]
        {
            smaller(self, other)
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.min(other)
        }
    }
}

/// [`Bounds::at_least`] in WebAssembly: `b` if `a` is a NaN or `b > a`, else `a`.
#[inline(always)]
pub fn larger(a: f64, b: f64) -> f64 {
    if a.is_nan() || b > a { b } else { a }
}

/// [`Bounds::at_most`] in WebAssembly: `b` if `a` is a NaN or `b < a`, else `a`.
#[inline(always)]
pub fn smaller(a: f64, b: f64) -> f64 {
    if a.is_nan() || b < a { b } else { a }
}

/// Entries of the table: 2^{i/N}.
const N: usize = 128;

/// ln 2 as a double word (hi + lo).
const LN2: (f64, f64) = (f64::from_bits(0x3fe6_2e42_fefa_39ef), f64::from_bits(0x3c7a_bc9e_3b39_803f));

/// ln 2/N in two parts: the first with 36 significant bits, so that k ln2/N
/// is exact for |k| < 2¹⁷ (|x| < 708 gives |k| < 131 000), and the rest.
const LN2_N_HI: f64 = f64::from_bits((LN2.0 / N as f64).to_bits() & !0x1_ffff);
const LN2_N_LO: f64 = (LN2.0 / N as f64 - LN2_N_HI) + LN2.1 / N as f64;

/// N/ln 2.
const N_LN2: f64 = N as f64 / LN2.0;

/// 1.5 × 2⁵²: x + SHIFT − SHIFT rounds x to an integer (|x| < 2⁵¹), whose
/// low bits are those of x + SHIFT.
const SHIFT: f64 = 6_755_399_441_055_744.0;

/// 2^{i/N} as double words (hi, lo), i = 0 … N − 1.
static TABLE: [(f64, f64); N] = table();

/// e^x to within one unit in the last place, for any x (outside
/// |x| < 708, and for NaN, by `std`).
pub fn exp_tabled(x: f64) -> f64 {
    if x.is_nan() || x.abs() >= 708.0 {
        return x.exp();
    }
    let z = x * N_LN2;
    let shifted = z + SHIFT;
    let kd = shifted - SHIFT;
    // The integer nearest z, from the low bits of `shifted`.
    let ki = shifted.to_bits() as i64 as i32;
    let r = (x - kd * LN2_N_HI) - kd * LN2_N_LO;
    let (hi, lo) = TABLE[(ki & (N as i32 - 1)) as usize];
    let k = ki >> 7;
    // e^r − 1, |r| ≤ ln 2/256: the terms beyond r⁵ are below 2⁻⁶⁰ of it.
    let p = r + r * r * (0.5 + r * (1.0 / 6.0 + r * (1.0 / 24.0 + r * (1.0 / 120.0))));
    let y = hi + (hi * p + lo);
    // |x| < 708 keeps 2^k and the result normal numbers.
    y * f64::from_bits(((k + 1023) as u64) << 52)
}

/// ∛x to within one unit in the last place, for any x (zero, infinities,
/// NaN and subnormal numbers by `std`).
pub fn cbrt_newton(x: f64) -> f64 {
    if !x.is_normal() {
        return x.cbrt();
    }
    // |x| = m 2^{3j} with 1 ≤ m < 8, so that ∛|x| = ∛m 2^j and no cube
    // below overflows.
    let bits = x.abs().to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32 - 1023;
    let j = e.div_euclid(3);
    let a = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | (((e - 3 * j + 1023) as u64) << 52));
    // An estimate within about 5 %: a third of the biased exponent and
    // mantissa read as one integer (the exponent bias kept).
    let mut y = f64::from_bits(a.to_bits() / 3 + 0x2a9f_7893_782d_a1ce);
    // Halley's steps: the error cubes, 5 % → 10⁻⁴ → 10⁻¹².
    for _ in 0..2 {
        let y3 = y * y * y;
        y *= (y3 + 2.0 * a) / (2.0 * y3 + a);
    }
    // A last step from y rounded to 26 bits, t: its square is exact and its
    // cube an exact double word, so ρ = a/t³ − 1 is as exact as a quotient,
    // and ∛a = t (1 + ρ)^{1/3} = t (1 + ρ/3 − ρ²/9) to 10⁻²² (|ρ| < 2⁻²⁴).
    let t = f64::from_bits((y.to_bits() + 0x400_0000) & !0x7ff_ffff);
    let (cube, cube_lo) = two_product(t * t, t);
    let rho = ((a - cube) - cube_lo) / cube;
    // 2^j, |j| ≤ 341: a normal number, so the product is exact.
    let root = (t + t * (rho * (1.0 / 3.0 - rho * (1.0 / 9.0)))) * f64::from_bits(((j + 1023) as u64) << 52);
    if x < 0.0 { -root } else { root }
}

/// a + b exactly, as a double word.
const fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a × b exactly, as a double word (Dekker's product, without a fused
/// multiply-add).
const fn two_product(a: f64, b: f64) -> (f64, f64) {
    const fn split(a: f64) -> (f64, f64) {
        let c = 134_217_729.0 * a;
        let hi = c - (c - a);
        (hi, a - hi)
    }
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// The sum of two double words.
const fn dd_add(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (s, e) = two_sum(a.0, b.0);
    two_sum(s, e + a.1 + b.1)
}

/// The product of two double words.
const fn dd_mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (p, e) = two_product(a.0, b.0);
    two_sum(p, e + a.0 * b.1 + a.1 * b.0)
}

/// A double word divided by a small positive integer.
const fn dd_div(a: (f64, f64), n: f64) -> (f64, f64) {
    let q = a.0 / n;
    let (p, e) = two_product(q, n);
    let rest = ((a.0 - p) - e + a.1) / n;
    two_sum(q, rest)
}

/// 2^{i/N} for i = 0 … N − 1, each the Taylor series of e^t at t = i ln 2/N
/// summed in double words to 30 terms (the last below 10⁻³³).
const fn table() -> [(f64, f64); N] {
    let mut out = [(0.0, 0.0); N];
    let mut i = 0;
    while i < N {
        let t = dd_div(dd_mul(LN2, (i as f64, 0.0)), N as f64);
        let mut term = (1.0, 0.0);
        let mut sum = (1.0, 0.0);
        let mut n = 1;
        while n < 30 {
            term = dd_div(dd_mul(term, t), n as f64);
            sum = dd_add(sum, term);
            n += 1;
        }
        out[i] = sum;
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Distance in units in the last place between two finite numbers of
    /// one sign.
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    /// The comparisons WebAssembly takes for `max` and `min` give `std`'s
    /// answer for NaNs, infinities, equal numbers and random ones (zeros
    /// aside, whose sign either may choose).
    #[test]
    fn bounds_follow_std() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let mut values =
            vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.0, -1.0, 1e-300, f64::MAX, f64::MIN_POSITIVE];
        values.extend((0..200).map(|_| rng.random_range(-1e3..1e3)));
        for &a in &values {
            for &b in &values {
                for (got, want) in [(larger(a, b), a.max(b)), (smaller(a, b), a.min(b))] {
                    assert!(
                        got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                        "{a} {b}: {got} against {want}"
                    );
                }
            }
        }
        assert_eq!(f64::NAN.at_least(2.0), 2.0);
        assert_eq!(2f64.at_most(f64::NAN), 2.0);
    }

    #[test]
    fn the_table_holds_two_to_the_i_over_128() {
        // 2^{1/2}, 2^{1/4}, 2^{3/4} as double words: hi is the correctly
        // rounded value, lo the rest to within 10⁻³² of hi.
        let sqrt2 = TABLE[64];
        assert_eq!(sqrt2.0, std::f64::consts::SQRT_2);
        let (p, e) = two_product(sqrt2.0, sqrt2.0);
        let square = two_sum(p, e + 2.0 * sqrt2.0 * sqrt2.1);
        assert!((square.0 - 2.0).abs() + square.1.abs() < 1e-30, "{square:?}");
        assert_eq!(TABLE[0], (1.0, 0.0));
        for (i, &(hi, lo)) in TABLE.iter().enumerate() {
            assert_eq!(hi + lo, hi, "entry {i}: lo beyond half an ulp");
            assert!(ulps(hi, (i as f64 / N as f64).exp2()) <= 1, "entry {i}");
        }
    }

    #[test]
    fn the_exponential_is_within_an_ulp_of_the_c_library_and_mostly_equal() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let mut differ = 0;
        let n = 2_000_000;
        for k in 0..n {
            // Uniform over the whole range, and near zero where r is the
            // whole argument.
            let x: f64 = if k % 2 == 0 { rng.random_range(-707.9..707.9) } else { rng.random_range(-1e-3..1e-3) };
            let (ours, theirs) = (exp_tabled(x), x.exp());
            assert!(ulps(ours, theirs) <= 1, "exp({x:e}): {ours:e} against {theirs:e}");
            differ += usize::from(ours != theirs);
        }
        // Both are within about half an ulp of the true value, so they differ
        // only where it lies near a midpoint.
        assert!(differ < n / 100, "{differ} of {n} differ");
    }

    #[test]
    fn the_exponential_keeps_its_edges() {
        for x in [0.0, -0.0, 1.0, -1.0, 707.9, -707.9, 708.0, -708.0, 709.7, 710.0, -745.0, -746.0, 1e-300] {
            assert!(ulps(exp_tabled(x), x.exp()) <= 1, "exp({x:e})");
        }
        assert_eq!(exp_tabled(0.0), 1.0);
        assert_eq!(exp_tabled(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp_tabled(f64::NEG_INFINITY), 0.0);
        assert!(exp_tabled(f64::NAN).is_nan());
    }

    /// The error of y as ∛x in units in the last place of y, from the
    /// residual x − y³ in double words: (x − y³)/(3y²) over the ulp.
    fn cbrt_error(x: f64, y: f64) -> f64 {
        let cube = dd_mul(two_product(y, y), (y, 0.0));
        let rest = dd_add((x, 0.0), (-cube.0, -cube.1));
        let ulp = f64::from_bits(y.abs().to_bits() + 1) - y.abs();
        (rest.0 / (3.0 * y * y) / ulp).abs()
    }

    #[test]
    fn the_cube_root_is_within_half_an_ulp_and_a_little() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let (mut worst, mut worst_c) = (0.0f64, 0.0f64);
        for _ in 0..2_000_000 {
            // Log-uniform over the normal numbers, either sign.
            let x = rng.random_range(-1.0f64..1.0).signum() * 2f64.powf(rng.random_range(-1021.0..1023.0));
            let (ours, theirs) = (cbrt_newton(x), x.cbrt());
            assert!(ulps(ours, theirs) <= 1, "cbrt({x:e}): {ours:e} against {theirs:e}");
            // The residual's low word underflows for the smallest cubes.
            if x.abs() > 1e-290 {
                worst = worst.max(cbrt_error(x, ours));
                worst_c = worst_c.max(cbrt_error(x, theirs));
            }
        }
        // Half an ulp is the rounding of the last addition; the C library's
        // own are within an ulp (0.5 where correctly rounded).
        assert!(worst < 0.501, "worst {worst} ulp (the C library's {worst_c})");
        assert!(worst_c <= 1.0, "the C library's worst {worst_c} ulp");
        for (x, root) in [(27.0, 3.0), (-8.0, -2.0), (1.0, 1.0), (0.125, 0.5)] {
            assert_eq!(cbrt_newton(x), root, "cbrt({x:e})");
        }
        assert_eq!(cbrt_newton(0.0), 0.0);
        assert_eq!(cbrt_newton(f64::INFINITY), f64::INFINITY);
        assert!(cbrt_newton(f64::NAN).is_nan());
        assert!(ulps(cbrt_newton(f64::MIN_POSITIVE / 8.0), (f64::MIN_POSITIVE / 8.0).cbrt()) <= 1);
    }
}
