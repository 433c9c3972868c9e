//! The vectors the contact laws compute with: `Vec3`, or in the AVX2 copy
//! of the engines' per-contact step one register each
//! (`contact::wide::Y3`). The laws are written once, over [`ContactVector`].

use crate::vector::{v3, Vec3, Vector};
use std::ops::Div;

/// A 3-vector of the contact laws: [`Vector`], and a division of each
/// component by a number (the friction cap's reset).
pub trait ContactVector: Vector<f64> + Div<f64, Output = Self> {}

impl<V: Vector<f64> + Div<f64, Output = V>> ContactVector for V {}

/// How the engines' per-contact step moves its vectors between the engine's
/// memory and the laws.
///
/// # Safety
/// Each pointer must be valid for three doubles (`write_over`,
/// `write_joined`: four).
pub(crate) trait StepVector: ContactVector {
    /// Three doubles the engine wrote long before the call, read as the
    /// compiler likes.
    unsafe fn read(p: *const f64) -> Self;
    /// Three doubles the engine may have just written, one double at a time
    /// ([`read_fresh3`]).
    unsafe fn read_fresh(p: *const f64) -> Self;
    /// The three components to `p[0..3]`.
    unsafe fn write(self, p: *mut f64);
    /// The three components to `p[0..3]`, and anything to `p[3]`, which the
    /// caller writes afterwards.
    unsafe fn write_over(self, p: *mut f64);
    /// The three components to `p[0..3]` and the first of `next` to `p[3]`
    /// (in one store where the vector is one register).
    unsafe fn write_joined(self, next: Self, p: *mut f64);
    /// Whether every component of `a`, `b` and `c` is finite.
    fn finite3(a: Self, b: Self, c: Self) -> bool;
}

impl StepVector for Vec3 {
    #[inline(always)]
    unsafe fn read(p: *const f64) -> Self {
        v3(*(p as *const [f64; 3]))
    }
    #[inline(always)]
    unsafe fn read_fresh(p: *const f64) -> Self {
        v3(read_fresh3(p))
    }
    #[inline(always)]
    unsafe fn write(self, p: *mut f64) {
        *(p as *mut [f64; 3]) = self.into();
    }
    #[inline(always)]
    unsafe fn write_over(self, p: *mut f64) {
        self.write(p)
    }
    #[inline(always)]
    unsafe fn write_joined(self, next: Self, p: *mut f64) {
        self.write(p);
        *p.add(3) = next.x;
    }
    #[inline(always)]
    fn finite3(a: Self, b: Self, c: Self) -> bool {
        let all = a.iter().chain(&b).chain(&c);
        // x * 0 is 0 for every finite x and NaN for NaN and infinity
        all.fold(0.0, |sum, x| sum + x * 0.0) == 0.0
    }
}

/// One double of a record the engine has just written. The engine writes
/// its records field by field just before the call, and the stores are
/// still in flight when the kernel starts. A 16-byte load that spans two
/// 8-byte stores cannot be served from the store buffer (store-to-load
/// forwarding fails, the load waits until both stores reach the cache),
/// and the compiler pairs neighbouring doubles into such loads at will. A
/// volatile read keeps the load exactly one double wide: it is served by
/// the store that wrote it, whatever width the engine's compiler chose.
#[inline(always)]
unsafe fn load(p: *const f64) -> f64 {
    std::ptr::read_volatile(p)
}

/// Three doubles the engine has just written, one at a time ([`load`]).
#[inline(always)]
pub(crate) unsafe fn read_fresh3(p: *const f64) -> [f64; 3] {
    [load(p), load(p.add(1)), load(p.add(2))]
}

/// The first two of [`read_fresh3`].
#[inline(always)]
pub(crate) unsafe fn read_fresh2(p: *const f64) -> [f64; 2] {
    [load(p), load(p.add(1))]
}
