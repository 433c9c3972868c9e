//! The contact laws' vectors in one AVX register each ([`Y3`]), for the
//! AVX2 copy of the engines' per-contact step (`contact::dispatch`).
//!
//! A 3-vector held as `x`, `y`, `z` in two registers (what the compiler
//! makes of `Vec3`) costs two instructions per operation and shuffles
//! between them; in one register every operation is one instruction and a
//! cross product four permutes, two products and a difference. Each lane
//! operation is the `f64` operation, and `dot` and `cross` add and subtract
//! in nalgebra's order, so the results are `Vec3`'s bits.
//!
//! The fourth lane is zero in every vector read from memory, and every
//! operation keeps it zero for finite operands (0 x finite, 0 +- 0, 0 /
//! positive; the permutes keep lane 3 in lane 3). Nothing reads it back
//! except the stores, which write it only where the caller writes that slot
//! again afterwards.
//!
//! These values exist only inside the AVX2 copies: the methods are
//! `#[inline(always)]` and take on the AVX2 feature where they are inlined,
//! which `crate::simd` chooses only on CPUs that have it. That is what makes
//! the `unsafe` intrinsic calls below sound.

use super::vectors::StepVector;
use crate::vector::Vector;
use core::arch::x86_64::*;
use std::ops::{Add, Div, Mul, Neg, Sub, SubAssign};

/// `x`, `y`, `z` in lanes 0-2 of an AVX register, lane 3 zero.
#[derive(Clone, Copy)]
pub(crate) struct Y3(__m256d);

macro_rules! binary {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for Y3 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                // SAFETY: see the module documentation.
                Y3(unsafe { $intrinsic(self.0, rhs.0) })
            }
        }
    };
}

binary!(Add, add, _mm256_add_pd);
binary!(Sub, sub, _mm256_sub_pd);

impl SubAssign for Y3 {
    #[inline(always)]
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl Neg for Y3 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: see the module documentation.
        Y3(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl Mul<f64> for Y3 {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: f64) -> Self {
        // SAFETY: see the module documentation.
        Y3(unsafe { _mm256_mul_pd(self.0, _mm256_set1_pd(s)) })
    }
}

impl Div<f64> for Y3 {
    type Output = Self;
    #[inline(always)]
    fn div(self, s: f64) -> Self {
        // SAFETY: see the module documentation.
        Y3(unsafe { _mm256_div_pd(self.0, _mm256_set1_pd(s)) })
    }
}

/// Lanes `(y, z, x)` and `(z, x, y)` of `a`, lane 3 kept.
#[inline(always)]
fn rotations(a: __m256d) -> (__m256d, __m256d) {
    // SAFETY: see the module documentation.
    unsafe {
        (
            _mm256_permute4x64_pd::<0b11_00_10_01>(a),
            _mm256_permute4x64_pd::<0b11_01_00_10>(a),
        )
    }
}

impl Vector<f64> for Y3 {
    #[inline(always)]
    fn zeros() -> Self {
        // SAFETY: see the module documentation.
        Y3(unsafe { _mm256_setzero_pd() })
    }
    /// nalgebra's order: `(x x' + y y') + z z'`.
    #[inline(always)]
    fn dot(&self, rhs: &Self) -> f64 {
        // SAFETY: see the module documentation.
        unsafe {
            let p = _mm256_mul_pd(self.0, rhs.0);
            let low = _mm256_castpd256_pd128(p);
            let xy = _mm_add_sd(low, _mm_unpackhi_pd(low, low));
            _mm_cvtsd_f64(_mm_add_sd(xy, _mm256_extractf128_pd::<1>(p)))
        }
    }
    /// nalgebra's order: `(y z' - z y', z x' - x z', x y' - y x')`.
    #[inline(always)]
    fn cross(&self, rhs: &Self) -> Self {
        let (a_yzx, a_zxy) = rotations(self.0);
        let (b_yzx, b_zxy) = rotations(rhs.0);
        // SAFETY: see the module documentation.
        Y3(unsafe { _mm256_sub_pd(_mm256_mul_pd(a_yzx, b_zxy), _mm256_mul_pd(a_zxy, b_yzx)) })
    }
    /// As [`crate::vector::V3`]: the dot product with itself (nalgebra's
    /// added zero changes no bit of it).
    #[inline(always)]
    fn norm_squared(&self) -> f64 {
        self.dot(self)
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m {
            a
        } else {
            b
        }
    }
}

/// Lanes 0-2 of a load or store.
#[inline(always)]
fn three_lanes() -> __m256i {
    // SAFETY: see the module documentation.
    unsafe { _mm256_set_epi64x(0, -1, -1, -1) }
}

impl StepVector for Y3 {
    #[inline(always)]
    unsafe fn read(p: *const f64) -> Self {
        Y3(_mm256_maskload_pd(p, three_lanes()))
    }
    #[inline(always)]
    unsafe fn read_fresh(p: *const f64) -> Self {
        let [x, y] = super::vectors::read_fresh2(p);
        // z one double wide too: a load of its own that cannot be merged
        // with the volatile ones, and it zeroes lane 3 as it loads
        let z = _mm_load_sd(p.add(2));
        Y3(_mm256_insertf128_pd::<1>(
            _mm256_castpd128_pd256(_mm_set_pd(y, x)),
            z,
        ))
    }
    #[inline(always)]
    unsafe fn write(self, p: *mut f64) {
        let low = _mm256_castpd256_pd128(self.0);
        _mm_storeu_pd(p, low);
        _mm_store_sd(p.add(2), _mm256_extractf128_pd::<1>(self.0));
    }
    #[inline(always)]
    unsafe fn write_over(self, p: *mut f64) {
        _mm256_storeu_pd(p, self.0);
    }
    #[inline(always)]
    unsafe fn write_joined(self, next: Self, p: *mut f64) {
        let first = _mm256_broadcastsd_pd(_mm256_castpd256_pd128(next.0));
        _mm256_storeu_pd(p, _mm256_blend_pd::<0b1000>(self.0, first));
    }
    #[inline(always)]
    fn finite3(a: Self, b: Self, c: Self) -> bool {
        // x * 0 is 0 for every finite x and NaN otherwise; a sum of such
        // terms is NaN if any of them is
        // SAFETY: see the module documentation.
        unsafe {
            let zero = _mm256_setzero_pd();
            let sum = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(a.0, zero), _mm256_mul_pd(b.0, zero)),
                _mm256_mul_pd(c.0, zero),
            );
            _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_UNORD_Q>(sum, sum)) & 0b0111 == 0
        }
    }
}
