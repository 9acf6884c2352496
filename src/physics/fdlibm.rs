//! The natural logarithm and exponential of FreeBSD's `e_log.c` and
//! `e_exp.c` (fdlibm, as in Rust's `libm` crate), written without branches
//! for the arguments a model meets (positive normal numbers; |x| < 708) so
//! that a loop over arrays that takes them compiles to vector instructions
//! (`column_row`). They are accurate to below one unit in the last place and
//! give the same bits on every platform and in WebAssembly; `std`'s `ln` and
//! `exp` are the platform's C library, which may differ from them in the last
//! bit. A model that computes a quantity both one at a time and in vectors
//! takes these in both, so that the two agree exactly.

use super::wide::{Bits, Wide};

// The constants of `e_log.c` and `e_exp.c`, by their bits.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
const LG1: f64 = f64::from_bits(0x3fe5_5555_5555_5593);
const LG2: f64 = f64::from_bits(0x3fd9_9999_9997_fa04);
const LG3: f64 = f64::from_bits(0x3fd2_4924_9422_9359);
const LG4: f64 = f64::from_bits(0x3fcc_71c5_1d8e_78af);
const LG5: f64 = f64::from_bits(0x3fc7_4664_96cb_03de);
const LG6: f64 = f64::from_bits(0x3fc3_9a09_d078_c69f);
const LG7: f64 = f64::from_bits(0x3fc2_f112_df3e_5244);
const INV_LN2: f64 = f64::from_bits(0x3ff7_1547_652b_82fe);
const P1: f64 = f64::from_bits(0x3fc5_5555_5555_553e);
const P2: f64 = f64::from_bits(0xbf66_c16c_16be_bd93);
const P3: f64 = f64::from_bits(0x3f11_566a_af25_de2c);
const P4: f64 = f64::from_bits(0xbebb_bd41_c5d2_6bf1);
const P5: f64 = f64::from_bits(0x3e66_3769_72be_a4d0);

/// ln x; positive normal x without a branch, anything else by `std`.
pub fn ln(x: f64) -> f64 {
    if x.is_normal() && x > 0.0 { ln_normal(x) } else { x.ln() }
}

/// ln x for a positive normal x (anything else gives a meaningless number,
/// never a panic), in each lane of `x` ([`Wide`]: one number or several).
#[inline(always)]
pub(crate) fn ln_normal<V: Wide>(x: V) -> V {
    let s = V::splat;
    let ui = x.to_bits();
    // Reduce x to 2^k (1 + f) with √2/2 < 1 + f < √2, in 64-bit integers
    // throughout (narrower ones cost vector units a shuffle each).
    let hx = ui.shr::<32>().add(0x3ff0_0000 - 0x3fe6_a09e).and(0xffff_ffff);
    let biased = hx.shr::<20>();
    let hx = hx.and(0x000f_ffff).add(0x3fe6_a09e);
    let x = V::from_bits(hx.shl::<32>().or(ui.and(0xffff_ffff)));
    let f = x - s(1.0);
    let hfsq = s(0.5) * f * f;
    let q = f / (s(2.0) + f);
    let z = q * q;
    let w = z * z;
    let t1 = w * (s(LG2) + w * (s(LG4) + w * s(LG6)));
    let t2 = z * (s(LG1) + w * (s(LG3) + w * (s(LG5) + w * s(LG7))));
    let r = t2 + t1;
    let dk = small_integer::<V>(biased) - s(1023.0);
    q * (hfsq + r) + dk * s(LN2_LO) - hfsq + f + dk * s(LN2_HI)
}

/// exp x; |x| < 708 without a branch, anything else by `std`.
pub fn exp(x: f64) -> f64 {
    if x.abs() < EXP_RANGE { exp_moderate(x) } else { x.exp() }
}

/// Where [`exp_moderate`] holds: exp x is a normal number and `e_exp.c` takes
/// none of its special cases.
pub(crate) const EXP_RANGE: f64 = 708.0;

/// exp x for |x| < [`EXP_RANGE`] (anything else gives a meaningless number,
/// never a panic), in each lane of `x`: `e_exp.c`'s three ranges of |x|
/// computed alike and one kept.
#[inline(always)]
pub(crate) fn exp_moderate<V: Wide>(x: V) -> V {
    let s = V::splat;
    let bits = x.to_bits();
    let hx = bits.shr::<32>().and(0x7fff_ffff);
    let negative = bits.shr::<63>().eq(1);
    // Reduce x to r = x − k ln 2 with |r| ≤ ln 2 / 2 (k = 0 below that).
    let far = (s(INV_LN2) * x + V::select(negative, s(-0.5), s(0.5))).trunc();
    let near = V::select(negative, s(-1.0), s(1.0));
    let k = V::select(hx.gt(0x3fd6_2e42), V::select(hx.gt(0x3ff0_a2b1), far, near), s(0.0));
    let hi = x - k * s(LN2_HI);
    let lo = k * s(LN2_LO);
    let r = hi - lo;
    let rr = r * r;
    let c = r - rr * (s(P1) + rr * (s(P2) + rr * (s(P3) + rr * (s(P4) + rr * s(P5)))));
    let y = s(1.0) + (r * c / (s(2.0) - c) - lo + hi);
    // y 2^k, exact while it is a normal number.
    let scale = V::from_bits(small_integer_of(k + s(1023.0)).and(0x7ff).shl::<52>());
    V::select(hx.gt(0x3e30_0000), y * scale, s(1.0) + x)
}

/// The integer n of a float 0 ≤ n < 2⁵² that holds one, without a
/// float-to-integer conversion.
#[inline(always)]
fn small_integer_of<V: Wide>(n: V) -> V::Bits {
    const TWO_52: f64 = 4_503_599_627_370_496.0;
    (n + V::splat(TWO_52)).to_bits().sub(TWO_52.to_bits())
}

/// An integer n < 2⁵² as a float, exactly, without an integer-to-float
/// conversion: 2⁵² + n has n as its last bits.
#[inline(always)]
pub(crate) fn small_integer<V: Wide>(n: V::Bits) -> V {
    const TWO_52: f64 = 4_503_599_627_370_496.0;
    V::from_bits(n.or_c(TWO_52.to_bits())) - V::splat(TWO_52)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn equals_libm_bit_for_bit_and_std_within_one_ulp() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let mut worst = 0i64;
        for n in 0..200_000 {
            // Log-uniform over the normal numbers, and near 1.
            let x = if n % 2 == 0 {
                f64::from_bits(rng.random_range(0x0010_0000_0000_0000u64..0x7fef_ffff_ffff_ffff))
            } else {
                1.0 + rng.random_range(-0.3..0.3)
            };
            let ours = ln(x);
            assert_eq!(ours.to_bits(), libm::log(x).to_bits(), "ln({x:e})");
            let reference = x.ln();
            let apart = (ours.to_bits() as i64 - reference.to_bits() as i64).abs();
            if reference != 0.0 {
                worst = worst.max(apart);
            }
        }
        assert!(worst <= 1, "{worst} ulp from std");
        for x in [0.0, -1.0, f64::INFINITY, f64::NAN, 5e-324, 1.0] {
            let (a, b) = (ln(x), x.ln());
            assert!(a == b || (a.is_nan() && b.is_nan()), "ln({x:e}) = {a} against {b}");
        }
    }

    #[test]
    fn exp_equals_libm_bit_for_bit_and_std_within_one_ulp() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(8);
        let mut worst = 0i64;
        for n in 0..200_000 {
            // Every range of e_exp.c: tiny, below and above 1.5 ln 2, large.
            let x = match n % 4 {
                0 => rng.random_range(-707.9..707.9),
                1 => rng.random_range(-1.1..1.1),
                2 => rng.random_range(-1e-8..1e-8),
                _ => rng.random_range(-30.0..3.0),
            };
            let ours = exp(x);
            assert_eq!(ours.to_bits(), libm::exp(x).to_bits(), "exp({x:e})");
            worst = worst.max((ours.to_bits() as i64 - x.exp().to_bits() as i64).abs());
        }
        assert!(worst <= 1, "{worst} ulp from std");
        for x in [0.0, -0.0, 0.5 * std::f64::consts::LN_2, 1.5 * std::f64::consts::LN_2, 1e-300, 707.99, -707.99] {
            assert_eq!(exp(x).to_bits(), libm::exp(x).to_bits(), "exp({x:e})");
        }
        for x in [709.0, -720.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            let (a, b) = (exp(x), x.exp());
            assert!(a == b || (a.is_nan() && b.is_nan()), "exp({x:e}) = {a} against {b}");
        }
    }
}
