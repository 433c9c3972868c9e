//! Two independent square roots, or two independent quotients, in one
//! instruction.
//!
//! Square roots and divisions dominate the cost of a bond step: they all go
//! through one divider unit, which takes about as long for two packed `f64`
//! lanes as for one. The kernel pairs up the ones that do not depend on each
//! other (the bending angle with its history extreme, shear force with slip
//! velocity, ...). Each lane is the correctly rounded IEEE result, exactly what `f64::sqrt` and
//! `/` give, so pairing changes no bit of any result.

use crate::real::Real;
use crate::vector::Vector;

#[cfg(target_arch = "x86_64")]
mod imp {
    use core::arch::x86_64::{_mm_cvtsd_f64, _mm_div_pd, _mm_set_pd, _mm_sqrt_pd, _mm_unpackhi_pd};

    #[inline(always)]
    pub fn sqrt2(a: f64, b: f64) -> (f64, f64) {
        // SAFETY: SSE2 is part of the x86_64 baseline; no memory is touched.
        unsafe {
            let r = _mm_sqrt_pd(_mm_set_pd(b, a));
            (_mm_cvtsd_f64(r), _mm_cvtsd_f64(_mm_unpackhi_pd(r, r)))
        }
    }

    #[inline(always)]
    pub fn div2(a: f64, b: f64, c: f64, d: f64) -> (f64, f64) {
        // SAFETY: as above.
        unsafe {
            let r = _mm_div_pd(_mm_set_pd(c, a), _mm_set_pd(d, b));
            (_mm_cvtsd_f64(r), _mm_cvtsd_f64(_mm_unpackhi_pd(r, r)))
        }
    }
}

#[cfg(not(target_arch = "x86_64"))]
mod imp {
    #[inline(always)]
    pub fn sqrt2(a: f64, b: f64) -> (f64, f64) {
        (a.sqrt(), b.sqrt())
    }

    #[inline(always)]
    pub fn div2(a: f64, b: f64, c: f64, d: f64) -> (f64, f64) {
        (a / b, c / d)
    }
}

/// `(a.sqrt(), b.sqrt())`.
#[inline(always)]
pub fn sqrt2(a: f64, b: f64) -> (f64, f64) {
    imp::sqrt2(a, b)
}

/// `(a / b, c / d)`.
#[inline(always)]
pub fn div2(a: f64, b: f64, c: f64, d: f64) -> (f64, f64) {
    imp::div2(a, b, c, d)
}

/// Lengths of `a` and `b` (`v.norm()`), each only if wanted (else 0): the
/// kernels pass constants, so an unwanted one is compiled out, and two wanted
/// ones share an instruction.
#[inline(always)]
pub fn norms<R: Real, V: Vector<R>>(a: V, want_a: bool, b: V, want_b: bool) -> (R, R) {
    let zero = R::splat(0.0);
    match (want_a, want_b) {
        (true, true) => R::sqrt2(a.norm_squared(), b.norm_squared()),
        (true, false) => (a.norm(), zero),
        (false, true) => (zero, b.norm()),
        (false, false) => (zero, zero),
    }
}

/// `(1 / a, 1 / b)`, each only if wanted (else 0), like [`norms`]: two wanted
/// ones share an instruction.
#[inline(always)]
pub fn reciprocals<R: Real>(a: R, want_a: bool, b: R, want_b: bool) -> (R, R) {
    let (zero, one) = (R::splat(0.0), R::splat(1.0));
    match (want_a, want_b) {
        (true, true) => R::div2(one, a, one, b),
        (true, false) => (one / a, zero),
        (false, true) => (zero, one / b),
        (false, false) => (zero, zero),
    }
}
