//! [`Real`] in packed registers: [`F64x4`] (AVX, 4 bonds) and [`F64x8`]
//! (AVX-512F, 8 bonds), for the wide kernels of `bond::wide`.
//!
//! Each operation is the IEEE operation on every lane (add, sub, mul, div
//! and sqrt are correctly rounded, packed or not; compares are the ordered
//! ones of `<`, `>`, `>=`), and `abs` and `neg` touch only the sign bit, as
//! for `f64` (`max`, `min`, `clamp` are compares and blends, the same for
//! all, see [`Real::max`]). So each lane holds the bits the scalar kernel
//! computes.
//!
//! These values exist only inside the kernels compiled with
//! `#[target_feature(enable = "avx2")]` / `"avx512f"`, which `crate::simd`
//! chooses only on CPUs that have them: the methods are `#[inline(always)]`
//! and take on those features where they are inlined. That is what makes the
//! `unsafe` intrinsic calls below sound.

use super::Real;
use core::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// A real number in each of the lanes of a packed register.
pub(crate) trait Pack: Real {
    const WIDTH: usize;
    /// Lane `i` is `f(i)`.
    fn gather(f: impl Fn(usize) -> f64) -> Self;
    /// Lane `i` of the two registers from `f(i)`: where `f` reads two
    /// numbers next to each other, one load a lane fills both.
    #[inline(always)]
    fn gather2(f: impl Fn(usize) -> [f64; 2]) -> (Self, Self) {
        (Self::gather(|i| f(i)[0]), Self::gather(|i| f(i)[1]))
    }
    /// The numbers `f(i)` of every lane added up in some lane, each once:
    /// for a check over all of them, which needs no number in its own lane.
    #[inline(always)]
    fn gather2_sum(f: impl Fn(usize) -> [f64; 2]) -> Self {
        let (a, b) = Self::gather2(f);
        a + b
    }
    /// `f(i, lane i)` for every lane, in order.
    fn for_each_lane(self, f: impl FnMut(usize, f64));
    /// `f(i, [lane i of a, lane i of b])` for every lane, in order: where
    /// `f` writes the two next to each other, one store a lane.
    #[inline(always)]
    fn for_each_lane2(a: Self, b: Self, mut f: impl FnMut(usize, [f64; 2])) {
        let mut first = [0.0; 8];
        a.for_each_lane(|i, x| first[i] = x);
        b.for_each_lane(|i, y| f(i, [first[i], y]));
    }
    /// `f(i, [lane i of a, lane i of b])` as `i32` for every lane, in order.
    /// For codes (small whole numbers), which both conversions keep
    /// exactly; other values may come out as the CPU's, not Rust's, `as`.
    #[inline(always)]
    fn for_each_lane_codes(a: Self, b: Self, mut f: impl FnMut(usize, [i32; 2])) {
        let mut first = [0; 8];
        a.for_each_lane(|i, x| first[i] = x as i32);
        b.for_each_lane(|i, x| f(i, [first[i], x as i32]));
    }
    /// The first `WIDTH` numbers of `values`, one a lane.
    fn load(values: &[f64]) -> Self;
    /// `f(i, lane i of (x, y, z))` for every lane, in order: each lane's
    /// 3-vector ready to be added to 3 numbers in memory ([`Lane3`]).
    #[inline(always)]
    fn for_each_lane3(x: Self, y: Self, z: Self, mut f: impl FnMut(usize, Lane3)) {
        let (mut first, mut second) = ([0.0; 8], [0.0; 8]);
        x.for_each_lane(|i, v| first[i] = v);
        y.for_each_lane(|i, v| second[i] = v);
        // SAFETY: SSE2, which every x86_64 CPU has.
        z.for_each_lane(|i, v| unsafe {
            f(
                i,
                Lane3 {
                    xy: _mm_set_pd(second[i], first[i]),
                    z: _mm_set_sd(v),
                },
            )
        });
    }
}

/// One lane's 3-vector taken out of three registers: x and y side by side,
/// z alone, so that adding it to 3 numbers in memory takes one 16-byte and
/// one 8-byte operation. Each component is the `f64` operation, so the sums
/// are the bits of one component at a time.
#[derive(Clone, Copy)]
pub(crate) struct Lane3 {
    xy: __m128d,
    // in the low half
    z: __m128d,
}

impl Lane3 {
    /// The 3-vector `v`.
    #[inline(always)]
    pub(crate) fn load(v: &[f64; 3]) -> Self {
        // SAFETY: `v` holds 3 numbers; SSE2, which every x86_64 CPU has.
        unsafe {
            Lane3 {
                xy: _mm_loadu_pd(v.as_ptr()),
                z: _mm_load_sd(v.as_ptr().add(2)),
            }
        }
    }

    /// `to[c] += self[c]` for the 3 components.
    ///
    /// # Safety
    /// `to` must be valid for reads and writes of 3 `f64`.
    #[inline(always)]
    pub(crate) unsafe fn add_to(self, to: *mut f64) {
        // SAFETY: the caller's; SSE2, which every x86_64 CPU has.
        unsafe {
            _mm_storeu_pd(to, _mm_add_pd(_mm_loadu_pd(to), self.xy));
            _mm_store_sd(to.add(2), _mm_add_sd(_mm_load_sd(to.add(2)), self.z));
        }
    }

    /// `to[c] -= self[c]` for the 3 components.
    ///
    /// # Safety
    /// As [`Self::add_to`].
    #[inline(always)]
    pub(crate) unsafe fn subtract_from(self, to: *mut f64) {
        // SAFETY: as in `add_to`.
        unsafe {
            _mm_storeu_pd(to, _mm_sub_pd(_mm_loadu_pd(to), self.xy));
            _mm_store_sd(to.add(2), _mm_sub_sd(_mm_load_sd(to.add(2)), self.z));
        }
    }
}

/// 4 `f64` (AVX).
#[derive(Clone, Copy)]
pub(crate) struct F64x4(__m256d);

/// Per-lane truth of [`F64x4`]: all bits set or none.
#[derive(Clone, Copy)]
pub(crate) struct Mask4(__m256d);

macro_rules! binary {
    ($t:ident, $trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for $t {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                // SAFETY: see the module documentation.
                $t(unsafe { $intrinsic(self.0, rhs.0) })
            }
        }
    };
}

binary!(F64x4, Add, add, _mm256_add_pd);
binary!(F64x4, Sub, sub, _mm256_sub_pd);
binary!(F64x4, Mul, mul, _mm256_mul_pd);
binary!(F64x4, Div, div, _mm256_div_pd);
binary!(Mask4, BitAnd, bitand, _mm256_and_pd);
binary!(Mask4, BitOr, bitor, _mm256_or_pd);

impl Neg for F64x4 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl Not for Mask4 {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        // SAFETY: see the module documentation.
        Mask4(unsafe { _mm256_xor_pd(self.0, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) })
    }
}

impl F64x4 {
    /// The pairs `f(i)` of lanes 0 and 2 side by side in one register, of
    /// lanes 1 and 3 in the other: one load a lane.
    #[inline(always)]
    fn pairs(f: impl Fn(usize) -> [f64; 2]) -> (__m256d, __m256d) {
        // SAFETY: see the module documentation.
        unsafe {
            let pair = |i| {
                let [x, y] = f(i);
                _mm_set_pd(y, x)
            };
            let even = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(0)), pair(2));
            let odd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(1)), pair(3));
            (even, odd)
        }
    }
    #[inline(always)]
    fn cmp<const P: i32>(self, other: Self) -> Mask4 {
        // SAFETY: see the module documentation.
        Mask4(unsafe { _mm256_cmp_pd::<P>(self.0, other.0) })
    }
}

impl Real for F64x4 {
    type Mask = Mask4;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_set1_pd(x) })
    }
    #[inline(always)]
    fn mask(b: bool) -> Mask4 {
        let x = f64::from_bits(if b { u64::MAX } else { 0 });
        // SAFETY: see the module documentation.
        Mask4(unsafe { _mm256_set1_pd(x) })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
    }
    #[inline(always)]
    fn is_nan(self) -> Mask4 {
        self.cmp::<_CMP_UNORD_Q>(self)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Mask4 {
        self.cmp::<_CMP_LT_OQ>(other)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Mask4 {
        self.cmp::<_CMP_GT_OQ>(other)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> Mask4 {
        self.cmp::<_CMP_GE_OQ>(other)
    }
    #[inline(always)]
    fn select(m: Mask4, a: Self, b: Self) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_blendv_pd(b.0, a.0, m.0) })
    }
    #[inline(always)]
    fn pin(self) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { pinned(self.0) })
    }
    #[inline(always)]
    fn any(m: Mask4) -> bool {
        // SAFETY: see the module documentation.
        unsafe { _mm256_movemask_pd(m.0) != 0 }
    }
    #[inline(always)]
    fn all(m: Mask4) -> bool {
        // SAFETY: see the module documentation.
        unsafe { _mm256_movemask_pd(m.0) == 0b1111 }
    }
}

/// `x`, which an empty `asm!` takes and gives back in a register: it
/// cannot be moved, so `x` is computed before it. Compiled for AVX (the
/// `asm!`'s register class needs it) and inlined into the AVX2 kernels.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn pinned(mut x: __m256d) -> __m256d {
    // SAFETY: no instruction; the register goes out as it came in.
    unsafe {
        std::arch::asm!("/* {0} */", inout(ymm_reg) x, options(nomem, nostack, preserves_flags));
    }
    x
}

impl Pack for F64x4 {
    const WIDTH: usize = 4;
    #[inline(always)]
    fn gather(f: impl Fn(usize) -> f64) -> Self {
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_set_pd(f(3), f(2), f(1), f(0)) })
    }
    /// [`F64x4::pairs`] with the halves' lanes interleaved.
    #[inline(always)]
    fn gather2(f: impl Fn(usize) -> [f64; 2]) -> (Self, Self) {
        let (even, odd) = Self::pairs(f);
        // SAFETY: see the module documentation.
        unsafe {
            (
                F64x4(_mm256_unpacklo_pd(even, odd)),
                F64x4(_mm256_unpackhi_pd(even, odd)),
            )
        }
    }
    /// [`F64x4::pairs`] added, without the shuffle of [`Pack::gather2`].
    #[inline(always)]
    fn gather2_sum(f: impl Fn(usize) -> [f64; 2]) -> Self {
        let (even, odd) = Self::pairs(f);
        // SAFETY: see the module documentation.
        F64x4(unsafe { _mm256_add_pd(even, odd) })
    }
    /// The inverse of [`Pack::gather2`]'s shuffle: each lane's pair in one
    /// half of a register.
    #[inline(always)]
    fn for_each_lane2(a: Self, b: Self, mut f: impl FnMut(usize, [f64; 2])) {
        // SAFETY: see the module documentation.
        unsafe {
            let (even, odd) = (_mm256_unpacklo_pd(a.0, b.0), _mm256_unpackhi_pd(a.0, b.0));
            let pair = |v: __m128d| [_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))];
            f(0, pair(_mm256_castpd256_pd128(even)));
            f(1, pair(_mm256_castpd256_pd128(odd)));
            f(2, pair(_mm256_extractf128_pd::<1>(even)));
            f(3, pair(_mm256_extractf128_pd::<1>(odd)));
        }
    }
    /// Lanes read out of the register, not through a copy on the stack: a
    /// lane stored to memory becomes one store instruction.
    #[inline(always)]
    fn for_each_lane(self, mut f: impl FnMut(usize, f64)) {
        // SAFETY: see the module documentation.
        unsafe {
            let low = _mm256_castpd256_pd128(self.0);
            let high = _mm256_extractf128_pd::<1>(self.0);
            f(0, _mm_cvtsd_f64(low));
            f(1, _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)));
            f(2, _mm_cvtsd_f64(high));
            f(3, _mm_cvtsd_f64(_mm_unpackhi_pd(high, high)));
        }
    }
    /// Both registers converted at once and interleaved, so that each
    /// lane's pair is one 64-bit store.
    #[inline(always)]
    fn for_each_lane_codes(a: Self, b: Self, mut f: impl FnMut(usize, [i32; 2])) {
        // SAFETY: see the module documentation.
        unsafe {
            let (a, b) = (_mm256_cvttpd_epi32(a.0), _mm256_cvttpd_epi32(b.0));
            let (low, high) = (_mm_unpacklo_epi32(a, b), _mm_unpackhi_epi32(a, b));
            let pair = |x: i64| [x as i32, (x >> 32) as i32];
            f(0, pair(_mm_cvtsi128_si64(low)));
            f(1, pair(_mm_extract_epi64::<1>(low)));
            f(2, pair(_mm_cvtsi128_si64(high)));
            f(3, pair(_mm_extract_epi64::<1>(high)));
        }
    }
    /// The pairs of (x, y) interleaved as [`Pack::for_each_lane2`] does,
    /// the halves of z split: no copy on the stack.
    #[inline(always)]
    fn for_each_lane3(x: Self, y: Self, z: Self, mut f: impl FnMut(usize, Lane3)) {
        // SAFETY: see the module documentation.
        unsafe {
            let (even, odd) = (_mm256_unpacklo_pd(x.0, y.0), _mm256_unpackhi_pd(x.0, y.0));
            let (z01, z23) = (_mm256_castpd256_pd128(z.0), _mm256_extractf128_pd::<1>(z.0));
            let lane = |xy, z| Lane3 { xy, z };
            f(0, lane(_mm256_castpd256_pd128(even), z01));
            f(1, lane(_mm256_castpd256_pd128(odd), _mm_unpackhi_pd(z01, z01)));
            f(2, lane(_mm256_extractf128_pd::<1>(even), z23));
            f(
                3,
                lane(_mm256_extractf128_pd::<1>(odd), _mm_unpackhi_pd(z23, z23)),
            );
        }
    }
    #[inline(always)]
    fn load(values: &[f64]) -> Self {
        let values = &values[..4];
        // SAFETY: see the module documentation; `values` holds 4 numbers.
        F64x4(unsafe { _mm256_loadu_pd(values.as_ptr()) })
    }
}

/// 8 `f64` (AVX-512F).
#[derive(Clone, Copy)]
pub(crate) struct F64x8(__m512d);

/// Per-lane truth of [`F64x8`]: one bit a lane.
#[derive(Clone, Copy)]
pub(crate) struct Mask8(__mmask8);

binary!(F64x8, Add, add, _mm512_add_pd);
binary!(F64x8, Sub, sub, _mm512_sub_pd);
binary!(F64x8, Mul, mul, _mm512_mul_pd);
binary!(F64x8, Div, div, _mm512_div_pd);

impl BitAnd for Mask8 {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, rhs: Self) -> Self {
        Mask8(self.0 & rhs.0)
    }
}

impl BitOr for Mask8 {
    type Output = Self;
    #[inline(always)]
    fn bitor(self, rhs: Self) -> Self {
        Mask8(self.0 | rhs.0)
    }
}

impl Not for Mask8 {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        Mask8(!self.0)
    }
}

impl Neg for F64x8 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe {
            _mm512_castsi512_pd(_mm512_xor_si512(
                _mm512_castpd_si512(self.0),
                _mm512_set1_epi64(i64::MIN),
            ))
        })
    }
}

impl F64x8 {
    #[inline(always)]
    fn cmp<const P: i32>(self, other: Self) -> Mask8 {
        // SAFETY: see the module documentation.
        Mask8(unsafe { _mm512_cmp_pd_mask::<P>(self.0, other.0) })
    }
}

impl Real for F64x8 {
    type Mask = Mask8;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe { _mm512_set1_pd(x) })
    }
    #[inline(always)]
    fn mask(b: bool) -> Mask8 {
        Mask8(if b { 0xFF } else { 0 })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe { _mm512_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe {
            _mm512_castsi512_pd(_mm512_and_si512(
                _mm512_castpd_si512(self.0),
                _mm512_set1_epi64(i64::MAX),
            ))
        })
    }
    #[inline(always)]
    fn is_nan(self) -> Mask8 {
        self.cmp::<_CMP_UNORD_Q>(self)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Mask8 {
        self.cmp::<_CMP_LT_OQ>(other)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Mask8 {
        self.cmp::<_CMP_GT_OQ>(other)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> Mask8 {
        self.cmp::<_CMP_GE_OQ>(other)
    }
    #[inline(always)]
    fn select(m: Mask8, a: Self, b: Self) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe { _mm512_mask_blend_pd(m.0, b.0, a.0) })
    }
    #[inline(always)]
    fn any(m: Mask8) -> bool {
        m.0 != 0
    }
    #[inline(always)]
    fn all(m: Mask8) -> bool {
        m.0 == 0xFF
    }
}

impl Pack for F64x8 {
    const WIDTH: usize = 8;
    #[inline(always)]
    fn gather(f: impl Fn(usize) -> f64) -> Self {
        // SAFETY: see the module documentation.
        F64x8(unsafe { _mm512_set_pd(f(7), f(6), f(5), f(4), f(3), f(2), f(1), f(0)) })
    }
    #[inline(always)]
    fn for_each_lane(self, mut f: impl FnMut(usize, f64)) {
        // SAFETY: __m512d is 8 f64.
        let lanes = unsafe { std::mem::transmute::<__m512d, [f64; 8]>(self.0) };
        for (i, x) in lanes.into_iter().enumerate() {
            f(i, x);
        }
    }
    #[inline(always)]
    fn load(values: &[f64]) -> Self {
        let values = &values[..8];
        // SAFETY: see the module documentation; `values` holds 8 numbers.
        F64x8(unsafe { _mm512_loadu_pd(values.as_ptr()) })
    }
}
