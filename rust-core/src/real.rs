//! The numbers the bond laws compute with: one bond's `f64`, or [`Lanes`] of
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
//! of a jump: for `f64` the mask is a `bool` (the scalar kernel's code is the
//! same as before), for lanes one all-ones or all-zeros word per lane.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

pub trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self>
{
    /// Per-lane truth value of a comparison.
    type Mask: Copy + BitAnd<Output = Self::Mask> + BitOr<Output = Self::Mask> + Not<Output = Self::Mask>;

    /// `x` in every lane (a parameter of the bond type, a constant).
    fn splat(x: f64) -> Self;
    /// `b` in every lane.
    fn mask(b: bool) -> Self::Mask;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    /// `f64::max` per lane (NaN loses).
    fn max(self, other: Self) -> Self;
    /// `f64::min` per lane (NaN loses).
    fn min(self, other: Self) -> Self;
    /// `f64::clamp` per lane.
    fn clamp(self, lo: f64, hi: f64) -> Self;
    fn lt(self, other: Self) -> Self::Mask;
    fn gt(self, other: Self) -> Self::Mask;
    fn ge(self, other: Self) -> Self::Mask;
    /// `if m { a } else { b }` per lane, bit for bit.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// Whether `m` holds in any lane / in every lane.
    fn any(m: Self::Mask) -> bool;
    fn all(m: Self::Mask) -> bool;

    /// `(a.sqrt(), b.sqrt())`. Lanes are wide already; `f64` pairs the two
    /// in one instruction (see [`crate::bond::lanes`]).
    #[inline(always)]
    fn sqrt2(a: Self, b: Self) -> (Self, Self) {
        (a.sqrt(), b.sqrt())
    }

    /// `(a / b, c / d)`, paired like [`Real::sqrt2`].
    #[inline(always)]
    fn div2(a: Self, b: Self, c: Self, d: Self) -> (Self, Self) {
        (a / b, c / d)
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
    fn max(self, other: Self) -> Self {
        f64::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        f64::min(self, other)
    }
    #[inline(always)]
    fn clamp(self, lo: f64, hi: f64) -> Self {
        f64::clamp(self, lo, hi)
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
        crate::bond::lanes::sqrt2(a, b)
    }
    #[inline(always)]
    fn div2(a: Self, b: Self, c: Self, d: Self) -> (Self, Self) {
        crate::bond::lanes::div2(a, b, c, d)
    }
}

/// `N` bonds' values of one quantity. The operations are loops over the
/// lanes, `#[inline(always)]`, which LLVM turns into packed instructions of
/// the width the calling kernel is compiled for (see `bond::chunk`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes<const N: usize>(pub [f64; N]);

/// Per-lane truth: all bits set or none.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LaneMask<const N: usize>(pub [u64; N]);

#[inline(always)]
fn lanewise<const N: usize>(a: [f64; N], b: [f64; N], f: impl Fn(f64, f64) -> f64) -> [f64; N] {
    std::array::from_fn(|i| f(a[i], b[i]))
}

#[inline(always)]
fn compare<const N: usize>(a: [f64; N], b: [f64; N], f: impl Fn(f64, f64) -> bool) -> LaneMask<N> {
    LaneMask(std::array::from_fn(|i| if f(a[i], b[i]) { u64::MAX } else { 0 }))
}

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const N: usize> $trait for Lanes<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                Lanes(lanewise(self.0, rhs.0, |a, b| a $op b))
            }
        }
    };
}

lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<const N: usize> Neg for Lanes<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Lanes(self.0.map(|a| -a))
    }
}

macro_rules! mask_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const N: usize> $trait for LaneMask<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                LaneMask(std::array::from_fn(|i| self.0[i] $op rhs.0[i]))
            }
        }
    };
}

mask_op!(BitAnd, bitand, &);
mask_op!(BitOr, bitor, |);

impl<const N: usize> Not for LaneMask<N> {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        LaneMask(self.0.map(|m| !m))
    }
}

impl<const N: usize> Real for Lanes<N> {
    type Mask = LaneMask<N>;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Lanes([x; N])
    }
    #[inline(always)]
    fn mask(b: bool) -> LaneMask<N> {
        LaneMask([if b { u64::MAX } else { 0 }; N])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Lanes(self.0.map(f64::sqrt))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Lanes(self.0.map(f64::abs))
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        Lanes(lanewise(self.0, other.0, f64::max))
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        Lanes(lanewise(self.0, other.0, f64::min))
    }
    #[inline(always)]
    fn clamp(self, lo: f64, hi: f64) -> Self {
        Lanes(self.0.map(|a| a.clamp(lo, hi)))
    }
    #[inline(always)]
    fn lt(self, other: Self) -> LaneMask<N> {
        compare(self.0, other.0, |a, b| a < b)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> LaneMask<N> {
        compare(self.0, other.0, |a, b| a > b)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> LaneMask<N> {
        compare(self.0, other.0, |a, b| a >= b)
    }
    #[inline(always)]
    fn select(m: LaneMask<N>, a: Self, b: Self) -> Self {
        Lanes(std::array::from_fn(|i| {
            f64::from_bits((a.0[i].to_bits() & m.0[i]) | (b.0[i].to_bits() & !m.0[i]))
        }))
    }
    #[inline(always)]
    fn any(m: LaneMask<N>) -> bool {
        m.0.iter().fold(0, |acc, &x| acc | x) != 0
    }
    #[inline(always)]
    fn all(m: LaneMask<N>) -> bool {
        m.0.iter().fold(u64::MAX, |acc, &x| acc & x) != 0
    }
}
