//! The three-branch hysteresis loop shared by every bond law.
//!
//! In terms of a non-negative loading measure `x` with history maximum
//! `x_max >= x` (compression: `s(delta)`; tension: `-delta`; each side of
//! the twisting and bending laws: the angle on that side),
//! docs/models/bond-nonlinear.md eq. 6 and its torque analogues all read
//!
//! ```text
//! h(x) = k x                        x >= x_max            (virgin loading)
//!        ku x + (k - ku) x_max      c x_max <= x < x_max  (unloading)
//!       -kc x                       0 <= x < c x_max      (reverse)
//! with c = (ku - k) / (ku + kc)
//! ```
//!
//! `c` makes the law continuous at `c x_max`; at `x_max` continuity holds by
//! construction. Comparing `x` against `c x_max` instead of computing the
//! model's `delta_c1 = c^2 delta_max` avoids a square root and is the same
//! test, because `s` is monotonic.

use crate::real::Real;

/// Loading, unloading and reverse stiffnesses of one law, with the branch
/// ratio `c` precomputed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Loop {
    /// `k`: the slope of the virgin-loading branch.
    pub k: f64,
    /// `ku`: the slope of the unloading branch (`ku >= k`).
    pub ku: f64,
    /// `kc`: the slope of the reverse branch.
    pub kc: f64,
    /// `c = (ku - k)/(ku + kc)`: where unloading meets reverse, as a fraction
    /// of `x_max` (`dc1`, `dc2` of docs/models/bond-nonlinear.md eq. 5).
    pub c: f64,
}

impl Loop {
    /// The loop of the three stiffnesses, with its `c` (0 for a law that is
    /// zero everywhere, `ku + kc = 0`).
    pub fn new(k: f64, ku: f64, kc: f64) -> Self {
        // ku + kc = 0 only when all three are zero: the law is identically
        // zero and any ratio will do.
        let c = if ku + kc > 0.0 { (ku - k) / (ku + kc) } else { 0.0 };
        Self { k, ku, kc, c }
    }

    /// `h(x)` for `0 <= x <= x_max`.
    ///
    /// All three branches are evaluated and one is selected without a jump:
    /// which branch a bond is on is data-dependent (and differs from bond to
    /// bond in a batch), so a conditional jump here is mispredicted often,
    /// which costs more than the few multiplications saved.
    #[inline(always)]
    pub fn value<R: Real>(&self, x: R, x_max: R) -> R {
        let virgin = R::splat(self.k) * x;
        let unloading = R::splat(self.ku) * x + R::splat(self.k - self.ku) * x_max;
        let reverse = R::splat(-self.kc) * x;
        select(
            x.ge(x_max),
            virgin,
            select(x.ge(R::splat(self.c) * x_max), unloading, reverse),
        )
    }

    /// `E(x; x_max)`, the integral of `h(s; x_max)` over `0 <= s <= x` at
    /// that history: the work it takes to deform the law from zero to `x`
    /// while the history stays `x_max`, so `dE/dx = h` (for `x > x_max`
    /// the virgin line continues it). Each branch is linear in `s`, so
    /// the trapezoid from the branch's start is exact:
    /// `E(x) = E(b) + (x - b) (h(x) + h(b)) / 2`, `b` = 0, `c x_max` or
    /// `x_max`.
    #[inline(always)]
    pub fn work<R: Real>(&self, x: R, x_max: R) -> R {
        let half = R::splat(0.5);
        let zero = R::splat(0.0);
        let kink = R::splat(self.c) * x_max;
        let at_kink = R::splat(-self.kc) * kink;
        let work_kink = half * at_kink * kink;
        let at_max = R::splat(self.k) * x_max;
        let work_max = work_kink + half * (x_max - kink) * (at_max + at_kink);
        let virgin = x.ge(x_max);
        let unloading = x.ge(kink);
        let start = select(virgin, x_max, select(unloading, kink, zero));
        let h_start = select(virgin, at_max, select(unloading, at_kink, zero));
        let w_start = select(virgin, work_max, select(unloading, work_kink, zero));
        w_start + half * (x - start) * (self.value(x, x_max) + h_start)
    }

    /// The largest slope `|dh/dx|` anywhere on the loop.
    pub fn max_slope(&self) -> f64 {
        self.k.max(self.ku).max(self.kc)
    }
}

/// The history extremes of a signed measure `x` after a step, updated
/// before the law so `min <= x <= max` (`max >= 0 >= min` when they start
/// there). With `reset` (LIGGGHTS-INL's rule) being on one side
/// forgets the other side's extreme.
#[inline(always)]
pub fn update_extremes<R: Real>(x: R, max: R, min: R, reset: bool) -> (R, R) {
    let (mut hi, mut lo) = (max, min);
    if reset {
        let zero = R::splat(0.0);
        hi = select(x.lt(zero), zero, hi);
        lo = select(x.gt(zero), zero, lo);
    }
    (hi.max(x), lo.min(x))
}

/// `if cond { a } else { b }` for two values that are already computed (so
/// both sides are evaluated): for `f64` LLVM turns this into a compare and a
/// mask, not a jump (checked in the x86_64 asm of the kernels); for lanes it
/// is a blend. For the data-dependent choices of the bond laws a mispredicted
/// jump costs more than evaluating both sides. Returns exactly `a` or `b`,
/// bit for bit.
#[inline(always)]
pub fn select<R: Real>(cond: R::Mask, a: R, b: R) -> R {
    R::select(cond, a, b)
}
