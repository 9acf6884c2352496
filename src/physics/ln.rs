//! The natural logarithm of FreeBSD's `e_log.c` (as in musl's former and
//! Rust's `libm` crate), written without branches for positive normal numbers
//! so that a loop over arrays that takes it compiles to vector instructions
//! (`column_row`). It is accurate to below one unit in the last place and
//! gives the same bits on every platform and in WebAssembly; `std`'s `ln`
//! is the platform's C library, which may differ from it in the last bit.
//! A model that computes a quantity both one at a time and in vectors takes
//! this one in both, so that the two agree exactly.

// The constants of `e_log.c`, by their bits.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
const LG1: f64 = f64::from_bits(0x3fe5_5555_5555_5593);
const LG2: f64 = f64::from_bits(0x3fd9_9999_9997_fa04);
const LG3: f64 = f64::from_bits(0x3fd2_4924_9422_9359);
const LG4: f64 = f64::from_bits(0x3fcc_71c5_1d8e_78af);
const LG5: f64 = f64::from_bits(0x3fc7_4664_96cb_03de);
const LG6: f64 = f64::from_bits(0x3fc3_9a09_d078_c69f);
const LG7: f64 = f64::from_bits(0x3fc2_f112_df3e_5244);

/// ln x; positive normal x without a branch, anything else by `std`.
pub fn ln(x: f64) -> f64 {
    if x.is_normal() && x > 0.0 { ln_normal(x) } else { x.ln() }
}

/// ln x for a positive normal x (anything else gives a meaningless number,
/// never a panic).
#[inline(always)]
pub(crate) fn ln_normal(x: f64) -> f64 {
    let ui = x.to_bits();
    // Reduce x to 2^k (1 + f) with √2/2 < 1 + f < √2.
    let hx = ((ui >> 32) as u32).wrapping_add(0x3ff0_0000 - 0x3fe6_a09e);
    let k = (hx >> 20) as i32 - 0x3ff;
    let hx = (hx & 0x000f_ffff) + 0x3fe6_a09e;
    let x = f64::from_bits((u64::from(hx) << 32) | (ui & 0xffff_ffff));
    let f = x - 1.0;
    let hfsq = 0.5 * f * f;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG2 + w * (LG4 + w * LG6));
    let t2 = z * (LG1 + w * (LG3 + w * (LG5 + w * LG7)));
    let r = t2 + t1;
    let dk = f64::from(k);
    s * (hfsq + r) + dk * LN2_LO - hfsq + f + dk * LN2_HI
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
}
