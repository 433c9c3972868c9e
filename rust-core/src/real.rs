//! The numbers the bond laws compute with: one bond's `f64`, or packed lanes of
//! several bonds side by side, so one copy of each law serves the scalar
//! kernel and the wide one.
//!
//! Every lane operation is the `f64` operation on each lane (IEEE add, sub,
//! mul, div and sqrt are correctly rounded in packed form too; `max`, `min`,
//! `abs` and `clamp` are `f64`'s own, lane by lane), so a bond gets the same
//! bits whichever lane of whichever chunk it lands in. No fused
//! multiply-add: the lane loops are plain `*` and `+`, which LLVM does not
//! contract.
//!
//! A data-dependent choice is a [`Real::Mask`] and [`Real::select`] instead
//! of a jump: for `f64` the mask is a `bool`, for lanes one all-ones or
//! all-zeros word per lane.
//!
//! The lane types (`real::packed`: 4 lanes with AVX2, 8 with AVX-512) wrap the
//! packed registers and their intrinsics, so LLVM keeps every quantity of a
//! chunk in one register instead of re-forming vectors from scalars.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

#[cfg(target_arch = "x86_64")]
pub(crate) mod packed;
pub mod paired;

/// A number the laws compute with: one bond's `f64`, or packed lanes of
/// several bonds, each lane computed as `f64` would compute it.
pub trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self>
{
    /// Per-lane truth value of a comparison.
    type Mask: Copy + BitAnd<Output = Self::Mask> + BitOr<Output = Self::Mask> + Not<Output = Self::Mask>;

    /// `x` in every lane (a parameter of the bond type, a constant).
    fn splat(x: f64) -> Self;
    /// `b` in every lane.
    fn mask(b: bool) -> Self::Mask;
    /// Square root, per lane.
    fn sqrt(self) -> Self;
    /// Absolute value, per lane.
    fn abs(self) -> Self;
    /// The larger of the two; `other` only if it is larger or `self` is NaN
    /// (so NaN loses, as in `f64::max`, and of `+0` and `-0` it is `self`:
    /// `f64::max` leaves that choice to the compiler, which need not make it
    /// alike in scalar and packed code).
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        Self::select(other.gt(self) | self.is_nan(), other, self)
    }
    /// The smaller of the two, in the same way as [`Real::max`].
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        Self::select(other.lt(self) | self.is_nan(), other, self)
    }
    /// `f64::clamp`: raised to `lo` if below, then lowered to `hi` if above
    /// (NaN stays NaN).
    #[inline(always)]
    fn clamp(self, lo: f64, hi: f64) -> Self {
        let (lo, hi) = (Self::splat(lo), Self::splat(hi));
        let x = Self::select(self.lt(lo), lo, self);
        Self::select(x.gt(hi), hi, x)
    }
    /// Per lane, whether the value is NaN.
    fn is_nan(self) -> Self::Mask;
    /// Per lane, `self < other`.
    fn lt(self, other: Self) -> Self::Mask;
    /// Per lane, `self > other`.
    fn gt(self, other: Self) -> Self::Mask;
    /// Per lane, `self >= other`.
    fn ge(self, other: Self) -> Self::Mask;
    /// `if m { a } else { b }` per lane, bit for bit.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// Whether `m` holds in any lane.
    fn any(m: Self::Mask) -> bool;
    /// Whether `m` holds in every lane.
    fn all(m: Self::Mask) -> bool;

    /// `(a.sqrt(), b.sqrt())`. Lanes are wide already; `f64` pairs the two
    /// in one instruction (see [`paired`]).
    #[inline(always)]
    fn sqrt2(a: Self, b: Self) -> (Self, Self) {
        (a.sqrt(), b.sqrt())
    }

    /// `(a / b, c / d)`, paired like [`Real::sqrt2`].
    #[inline(always)]
    fn div2(a: Self, b: Self, c: Self, d: Self) -> (Self, Self) {
        (a / b, c / d)
    }

    /// The value itself, computed by here (no instruction). LLVM computes
    /// a value only where it is first used, so a value used after a branch
    /// is computed after it, and what it is computed from is held across
    /// the branch instead; for lanes, where that is more than the
    /// registers hold, this keeps a step's stages apart. `f64` needs none.
    #[inline(always)]
    fn pin(self) -> Self {
        self
    }
}

impl Real for f64 {
    type Mask = bool;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn mask(b: bool) -> bool {
        b
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn is_nan(self) -> bool {
        f64::is_nan(self)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> bool {
        self < other
    }
    #[inline(always)]
    fn gt(self, other: Self) -> bool {
        self > other
    }
    #[inline(always)]
    fn ge(self, other: Self) -> bool {
        self >= other
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        // LLVM turns this into a compare and a mask, not a jump (see
        // `bond::hysteresis::select`).
        if m {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn any(m: bool) -> bool {
        m
    }
    #[inline(always)]
    fn all(m: bool) -> bool {
        m
    }
    #[inline(always)]
    fn sqrt2(a: Self, b: Self) -> (Self, Self) {
        paired::sqrt2(a, b)
    }
    #[inline(always)]
    fn div2(a: Self, b: Self, c: Self, d: Self) -> (Self, Self) {
        paired::div2(a, b, c, d)
    }
}
