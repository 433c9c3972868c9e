//! Lengths and reciprocals the bond step wants only for some switches: the
//! kernels pass the switches as constants, so an unwanted one is compiled
//! out, and two wanted ones share one instruction ([`crate::real::paired`]).

use crate::real::Real;
use crate::vector::Vector;

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
