//! The arithmetic of the Monte Carlo pair loop ([`super::column_row`]) on one
//! number or on several at once.
//!
//! The loop is written once, over a type that is either one `f64` (what a
//! pair computed by itself takes, and what a compiler may turn into vectors
//! by itself, as it does for AVX-512) or four `f64` in one AVX2 register
//! ([`F4`]), used where the processor has AVX2 but not AVX-512: there the
//! compiler's own estimate keeps the loop out of vectors. Every operation
//! rounds as the scalar one does (IEEE addition, multiplication, division
//! and square root are exact to the last bit in any lane), so the four lanes
//! give each pair's numbers to the last bit; a test holds them to the pairs
//! computed one at a time.
//!
//! Comparisons are ordered (false when either side is NaN), as Rust's are.
//! `max`/`min` follow `f64::max`/`f64::min` when the second operand is a
//! number, which is how the loop calls them.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Not, Sub};

/// Numbers the pair loop computes with: one `f64` or a vector of them.
pub(crate) trait Wide:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// A comparison's result, lane by lane.
    type Mask: Copy + BitAnd<Output = Self::Mask> + BitOr<Output = Self::Mask> + Not<Output = Self::Mask>;
    /// The bits of each lane as a 64-bit unsigned integer.
    type Bits: Bits<Mask = Self::Mask>;
    /// Lanes in one value.
    const LANES: usize;

    /// Every lane `x`.
    fn splat(x: f64) -> Self;
    /// `LANES` values from `s[i..]`.
    fn load(s: &[f64], i: usize) -> Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// `f64::max(self, c)` for a number `c`.
    fn max(self, c: Self) -> Self;
    /// `f64::min(self, c)` for a number `c`.
    fn min(self, c: Self) -> Self;
    /// |self|.
    fn abs(self) -> Self;
    /// Rounded towards zero.
    fn trunc(self) -> Self;
    /// self < o.
    fn lt(self, o: Self) -> Self::Mask;
    /// self ≤ o.
    fn le(self, o: Self) -> Self::Mask;
    /// self > o.
    fn gt(self, o: Self) -> Self::Mask;
    /// self ≥ o.
    fn ge(self, o: Self) -> Self::Mask;
    /// `a` where `m` holds, `b` elsewhere.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// The bits of each lane.
    fn to_bits(self) -> Self::Bits;
    /// Each lane from its bits.
    fn from_bits(b: Self::Bits) -> Self;
    /// Stores the lanes at `out[i..]`.
    fn store(self, out: &mut [f64], i: usize);
    /// Stores the lanes, rounded to `f32`, at `out[i..]`.
    fn store_f32(self, out: &mut [f32], i: usize);
    /// Stores the mask's lanes at `out[i..]`.
    fn store_mask(m: Self::Mask, out: &mut [bool], i: usize);
    /// How many lanes of `m` hold.
    fn count(m: Self::Mask) -> usize;
}

/// The bits of [`Wide`] lanes.
pub(crate) trait Bits: Copy {
    /// A comparison's result, lane by lane.
    type Mask;
    /// self >> N.
    fn shr<const N: i32>(self) -> Self;
    /// self << N.
    fn shl<const N: i32>(self) -> Self;
    /// self + c (wrapping).
    fn add(self, c: u64) -> Self;
    /// self − c (wrapping).
    fn sub(self, c: u64) -> Self;
    /// self & c.
    fn and(self, c: u64) -> Self;
    /// self | o.
    fn or(self, o: Self) -> Self;
    /// self | c.
    fn or_c(self, c: u64) -> Self;
    /// self == c.
    fn eq(self, c: u64) -> Self::Mask;
    /// self > c, for values and c below 2⁶³.
    fn gt(self, c: u64) -> Self::Mask;
}

impl Wide for f64 {
    type Mask = bool;
    type Bits = u64;
    const LANES: usize = 1;

    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn load(s: &[f64], i: usize) -> f64 {
        s[i]
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn max(self, c: f64) -> f64 {
        f64::max(self, c)
    }
    #[inline(always)]
    fn min(self, c: f64) -> f64 {
        f64::min(self, c)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn trunc(self) -> f64 {
        f64::trunc(self)
    }
    #[inline(always)]
    fn lt(self, o: f64) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: f64) -> bool {
        self <= o
    }
    #[inline(always)]
    fn gt(self, o: f64) -> bool {
        self > o
    }
    #[inline(always)]
    fn ge(self, o: f64) -> bool {
        self >= o
    }
    #[inline(always)]
    fn select(m: bool, a: f64, b: f64) -> f64 {
        if m { a } else { b }
    }
    #[inline(always)]
    fn to_bits(self) -> u64 {
        f64::to_bits(self)
    }
    #[inline(always)]
    fn from_bits(b: u64) -> f64 {
        f64::from_bits(b)
    }
    #[inline(always)]
    fn store(self, out: &mut [f64], i: usize) {
        out[i] = self;
    }
    #[inline(always)]
    fn store_f32(self, out: &mut [f32], i: usize) {
        out[i] = self as f32;
    }
    #[inline(always)]
    fn store_mask(m: bool, out: &mut [bool], i: usize) {
        out[i] = m;
    }
    #[inline(always)]
    fn count(m: bool) -> usize {
        usize::from(m)
    }
}

impl Bits for u64 {
    type Mask = bool;

    #[inline(always)]
    fn shr<const N: i32>(self) -> u64 {
        self >> N
    }
    #[inline(always)]
    fn shl<const N: i32>(self) -> u64 {
        self << N
    }
    #[inline(always)]
    fn add(self, c: u64) -> u64 {
        self.wrapping_add(c)
    }
    #[inline(always)]
    fn sub(self, c: u64) -> u64 {
        self.wrapping_sub(c)
    }
    #[inline(always)]
    fn and(self, c: u64) -> u64 {
        self & c
    }
    #[inline(always)]
    fn or(self, o: u64) -> u64 {
        self | o
    }
    #[inline(always)]
    fn or_c(self, c: u64) -> u64 {
        self | c
    }
    #[inline(always)]
    fn eq(self, c: u64) -> bool {
        self == c
    }
    #[inline(always)]
    fn gt(self, c: u64) -> bool {
        self > c
    }
}

#[cfg(target_arch = "x86_64")]
pub(crate) use avx2::F4;

/// Four lanes in AVX2 registers. Each operation is an intrinsic in an
/// `unsafe` block: the types are only made and used inside functions
/// compiled for AVX2 (`#[target_feature(enable = "avx2")]`, entered after
/// the processor was found to have it), where these always-inlined
/// operations become single instructions.
#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::{Bits, Wide};
    use std::arch::x86_64::*;
    use std::ops::{Add, BitAnd, BitOr, Div, Mul, Not, Sub};

    /// Four `f64`.
    #[derive(Clone, Copy)]
    pub(crate) struct F4(__m256d);
    /// Four lanes of a comparison: all bits set where it holds.
    #[derive(Clone, Copy)]
    pub(crate) struct M4(__m256d);
    /// Four 64-bit integers.
    #[derive(Clone, Copy)]
    pub(crate) struct U4(__m256i);

    macro_rules! binary {
        ($trait:ident, $method:ident, $type:ident, $intrinsic:ident) => {
            impl $trait for $type {
                type Output = $type;
                #[inline(always)]
                fn $method(self, o: $type) -> $type {
                    // SAFETY: see the module's note (AVX2 is present).
                    $type(unsafe { $intrinsic(self.0, o.0) })
                }
            }
        };
    }
    binary!(Add, add, F4, _mm256_add_pd);
    binary!(Sub, sub, F4, _mm256_sub_pd);
    binary!(Mul, mul, F4, _mm256_mul_pd);
    binary!(Div, div, F4, _mm256_div_pd);
    binary!(BitAnd, bitand, M4, _mm256_and_pd);
    binary!(BitOr, bitor, M4, _mm256_or_pd);

    impl Not for M4 {
        type Output = M4;
        #[inline(always)]
        fn not(self) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_xor_pd(self.0, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) })
        }
    }

    impl Wide for F4 {
        type Mask = M4;
        type Bits = U4;
        const LANES: usize = 4;

        #[inline(always)]
        fn splat(x: f64) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_set1_pd(x) })
        }
        #[inline(always)]
        fn load(s: &[f64], i: usize) -> F4 {
            let s = &s[i..i + 4];
            // SAFETY: `s` holds four values (checked by the slice).
            F4(unsafe { _mm256_loadu_pd(s.as_ptr()) })
        }
        #[inline(always)]
        fn sqrt(self) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_sqrt_pd(self.0) })
        }
        #[inline(always)]
        fn max(self, c: F4) -> F4 {
            // maxpd gives its second operand when either is NaN or both are zero.
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_max_pd(self.0, c.0) })
        }
        #[inline(always)]
        fn min(self, c: F4) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_min_pd(self.0, c.0) })
        }
        #[inline(always)]
        fn abs(self) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
        }
        #[inline(always)]
        fn trunc(self) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_round_pd::<{ _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC }>(self.0) })
        }
        #[inline(always)]
        fn lt(self, o: F4) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_cmp_pd::<_CMP_LT_OQ>(self.0, o.0) })
        }
        #[inline(always)]
        fn le(self, o: F4) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_cmp_pd::<_CMP_LE_OQ>(self.0, o.0) })
        }
        #[inline(always)]
        fn gt(self, o: F4) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_cmp_pd::<_CMP_GT_OQ>(self.0, o.0) })
        }
        #[inline(always)]
        fn ge(self, o: F4) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_cmp_pd::<_CMP_GE_OQ>(self.0, o.0) })
        }
        #[inline(always)]
        fn select(m: M4, a: F4, b: F4) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_blendv_pd(b.0, a.0, m.0) })
        }
        #[inline(always)]
        fn to_bits(self) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_castpd_si256(self.0) })
        }
        #[inline(always)]
        fn from_bits(b: U4) -> F4 {
            // SAFETY: see the module's note.
            F4(unsafe { _mm256_castsi256_pd(b.0) })
        }
        #[inline(always)]
        fn store(self, out: &mut [f64], i: usize) {
            let out = &mut out[i..i + 4];
            // SAFETY: `out` holds four values (checked by the slice).
            unsafe { _mm256_storeu_pd(out.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn store_f32(self, out: &mut [f32], i: usize) {
            let out = &mut out[i..i + 4];
            // Rounds to nearest, as `as f32` does.
            // SAFETY: `out` holds four values (checked by the slice).
            unsafe { _mm_storeu_ps(out.as_mut_ptr(), _mm256_cvtpd_ps(self.0)) }
        }
        #[inline(always)]
        fn store_mask(m: M4, out: &mut [bool], i: usize) {
            // SAFETY: see the module's note.
            let bits = unsafe { _mm256_movemask_pd(m.0) };
            for (j, o) in out[i..i + 4].iter_mut().enumerate() {
                *o = (bits >> j) & 1 == 1;
            }
        }
        #[inline(always)]
        fn count(m: M4) -> usize {
            // SAFETY: see the module's note.
            unsafe { _mm256_movemask_pd(m.0) }.count_ones() as usize
        }
    }

    impl Bits for U4 {
        type Mask = M4;

        #[inline(always)]
        fn shr<const N: i32>(self) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_srli_epi64::<N>(self.0) })
        }
        #[inline(always)]
        fn shl<const N: i32>(self) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_slli_epi64::<N>(self.0) })
        }
        #[inline(always)]
        fn add(self, c: u64) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_add_epi64(self.0, _mm256_set1_epi64x(c as i64)) })
        }
        #[inline(always)]
        fn sub(self, c: u64) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_sub_epi64(self.0, _mm256_set1_epi64x(c as i64)) })
        }
        #[inline(always)]
        fn and(self, c: u64) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_and_si256(self.0, _mm256_set1_epi64x(c as i64)) })
        }
        #[inline(always)]
        fn or(self, o: U4) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_or_si256(self.0, o.0) })
        }
        #[inline(always)]
        fn or_c(self, c: u64) -> U4 {
            // SAFETY: see the module's note.
            U4(unsafe { _mm256_or_si256(self.0, _mm256_set1_epi64x(c as i64)) })
        }
        #[inline(always)]
        fn eq(self, c: u64) -> M4 {
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_castsi256_pd(_mm256_cmpeq_epi64(self.0, _mm256_set1_epi64x(c as i64))) })
        }
        #[inline(always)]
        fn gt(self, c: u64) -> M4 {
            // A signed comparison, which is the unsigned one below 2⁶³.
            // SAFETY: see the module's note.
            M4(unsafe { _mm256_castsi256_pd(_mm256_cmpgt_epi64(self.0, _mm256_set1_epi64x(c as i64))) })
        }
    }
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
pub(crate) use simd128::F2;

/// Two lanes in WebAssembly's 128-bit vectors (the web build enables them
/// for the whole program, so the operations are safe to call).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod simd128 {
    use super::{Bits, Wide};
    use std::arch::wasm32::*;
    use std::ops::{Add, BitAnd, BitOr, Div, Mul, Not, Sub};

    /// Two `f64`.
    #[derive(Clone, Copy)]
    pub(crate) struct F2(v128);
    /// Two lanes of a comparison: all bits set where it holds.
    #[derive(Clone, Copy)]
    pub(crate) struct M2(v128);
    /// Two 64-bit integers.
    #[derive(Clone, Copy)]
    pub(crate) struct U2(v128);

    macro_rules! binary {
        ($trait:ident, $method:ident, $type:ident, $op:ident) => {
            impl $trait for $type {
                type Output = $type;
                #[inline(always)]
                fn $method(self, o: $type) -> $type {
                    $type($op(self.0, o.0))
                }
            }
        };
    }
    binary!(Add, add, F2, f64x2_add);
    binary!(Sub, sub, F2, f64x2_sub);
    binary!(Mul, mul, F2, f64x2_mul);
    binary!(Div, div, F2, f64x2_div);
    binary!(BitAnd, bitand, M2, v128_and);
    binary!(BitOr, bitor, M2, v128_or);

    impl Not for M2 {
        type Output = M2;
        #[inline(always)]
        fn not(self) -> M2 {
            M2(v128_not(self.0))
        }
    }

    impl Wide for F2 {
        type Mask = M2;
        type Bits = U2;
        const LANES: usize = 2;

        #[inline(always)]
        fn splat(x: f64) -> F2 {
            F2(f64x2_splat(x))
        }
        #[inline(always)]
        fn load(s: &[f64], i: usize) -> F2 {
            F2(f64x2(s[i], s[i + 1]))
        }
        #[inline(always)]
        fn sqrt(self) -> F2 {
            F2(f64x2_sqrt(self.0))
        }
        #[inline(always)]
        fn max(self, c: F2) -> F2 {
            // pmax(c, x) = c < x ? x : c: `f64::max(x, c)` for a number c.
            F2(f64x2_pmax(c.0, self.0))
        }
        #[inline(always)]
        fn min(self, c: F2) -> F2 {
            // pmin(c, x) = x < c ? x : c.
            F2(f64x2_pmin(c.0, self.0))
        }
        #[inline(always)]
        fn abs(self) -> F2 {
            F2(f64x2_abs(self.0))
        }
        #[inline(always)]
        fn trunc(self) -> F2 {
            F2(f64x2_trunc(self.0))
        }
        #[inline(always)]
        fn lt(self, o: F2) -> M2 {
            M2(f64x2_lt(self.0, o.0))
        }
        #[inline(always)]
        fn le(self, o: F2) -> M2 {
            M2(f64x2_le(self.0, o.0))
        }
        #[inline(always)]
        fn gt(self, o: F2) -> M2 {
            M2(f64x2_gt(self.0, o.0))
        }
        #[inline(always)]
        fn ge(self, o: F2) -> M2 {
            M2(f64x2_ge(self.0, o.0))
        }
        #[inline(always)]
        fn select(m: M2, a: F2, b: F2) -> F2 {
            F2(v128_bitselect(a.0, b.0, m.0))
        }
        #[inline(always)]
        fn to_bits(self) -> U2 {
            U2(self.0)
        }
        #[inline(always)]
        fn from_bits(b: U2) -> F2 {
            F2(b.0)
        }
        #[inline(always)]
        fn store(self, out: &mut [f64], i: usize) {
            out[i] = f64x2_extract_lane::<0>(self.0);
            out[i + 1] = f64x2_extract_lane::<1>(self.0);
        }
        #[inline(always)]
        fn store_f32(self, out: &mut [f32], i: usize) {
            // Rounds to nearest, as `as f32` does.
            let narrow = f32x4_demote_f64x2_zero(self.0);
            out[i] = f32x4_extract_lane::<0>(narrow);
            out[i + 1] = f32x4_extract_lane::<1>(narrow);
        }
        #[inline(always)]
        fn store_mask(m: M2, out: &mut [bool], i: usize) {
            let bits = i64x2_bitmask(m.0);
            out[i] = bits & 1 == 1;
            out[i + 1] = bits & 2 == 2;
        }
        #[inline(always)]
        fn count(m: M2) -> usize {
            i64x2_bitmask(m.0).count_ones() as usize
        }
    }

    impl Bits for U2 {
        type Mask = M2;

        #[inline(always)]
        fn shr<const N: i32>(self) -> U2 {
            U2(u64x2_shr(self.0, N as u32))
        }
        #[inline(always)]
        fn shl<const N: i32>(self) -> U2 {
            U2(i64x2_shl(self.0, N as u32))
        }
        #[inline(always)]
        fn add(self, c: u64) -> U2 {
            U2(i64x2_add(self.0, u64x2_splat(c)))
        }
        #[inline(always)]
        fn sub(self, c: u64) -> U2 {
            U2(i64x2_sub(self.0, u64x2_splat(c)))
        }
        #[inline(always)]
        fn and(self, c: u64) -> U2 {
            U2(v128_and(self.0, u64x2_splat(c)))
        }
        #[inline(always)]
        fn or(self, o: U2) -> U2 {
            U2(v128_or(self.0, o.0))
        }
        #[inline(always)]
        fn or_c(self, c: u64) -> U2 {
            U2(v128_or(self.0, u64x2_splat(c)))
        }
        #[inline(always)]
        fn eq(self, c: u64) -> M2 {
            M2(i64x2_eq(self.0, u64x2_splat(c)))
        }
        #[inline(always)]
        fn gt(self, c: u64) -> M2 {
            // A signed comparison, which is the unsigned one below 2⁶³.
            M2(i64x2_gt(self.0, u64x2_splat(c)))
        }
    }
}
