//! Two independent square roots, or two independent quotients, in one
//! instruction.
//!
//! Square roots and divisions dominate the cost of a bond step: they all go
//! through one divider unit, which takes about as long for two packed `f64`
//! lanes as for one. The kernel pairs up the ones that do not depend on each
//! other (the bending angle with its history extreme, shear force with slip
//! velocity, ...). Each lane is the correctly rounded IEEE result, exactly
//! what `f64::sqrt` and `/` give, so pairing changes no bit of any result.

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
