//! The vector type of the physics and the few operations on it that the laws
//! share.
//!
//! The laws are written once, generic over [`Vector`]: [`Vec3`] (one bond)
//! or [`V3`] of packed lanes (`real::packed`: several bonds side by side,
//! `bond::wide`). `V3` computes `dot`, `cross` and `norm` with the same
//! operations in the same order as nalgebra does for `Vec3`, so both give
//! the same bits.

use crate::real::Real;
use std::ops::{Add, Mul, Neg, Sub, SubAssign};

/// The 3-vector of one bond or contact: nalgebra's, of `f64`.
pub type Vec3 = nalgebra::Vector3<f64>;

/// The [`Vec3`] of an array (how states and the C ABI hold vectors).
#[inline(always)]
pub fn v3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

/// A 3-vector over the numbers `R`. Method names and signatures are
/// nalgebra's, so the laws read the same for both implementations.
pub trait Vector<R: Real>:
    Copy + Add<Output = Self> + Sub<Output = Self> + Neg<Output = Self> + Mul<R, Output = Self> + SubAssign
{
    /// The zero vector.
    fn zeros() -> Self;
    /// Dot product.
    fn dot(&self, rhs: &Self) -> R;
    /// Cross product `self x rhs`.
    fn cross(&self, rhs: &Self) -> Self;
    /// Squared length.
    fn norm_squared(&self) -> R;
    /// Length.
    #[inline(always)]
    fn norm(&self) -> R {
        self.norm_squared().sqrt()
    }
    /// `if m { a } else { b }` per lane.
    fn select(m: R::Mask, a: Self, b: Self) -> Self;
    /// [`Real::pin`] of each component.
    #[inline(always)]
    fn pin(self) -> Self {
        self
    }
}

impl Vector<f64> for Vec3 {
    #[inline(always)]
    fn zeros() -> Self {
        nalgebra::Vector3::zeros()
    }
    #[inline(always)]
    fn dot(&self, rhs: &Self) -> f64 {
        nalgebra::Vector3::dot(self, rhs)
    }
    #[inline(always)]
    fn cross(&self, rhs: &Self) -> Self {
        nalgebra::Vector3::cross(self, rhs)
    }
    #[inline(always)]
    fn norm_squared(&self) -> f64 {
        nalgebra::Vector3::norm_squared(self)
    }
    #[inline(always)]
    fn norm(&self) -> f64 {
        nalgebra::Vector3::norm(self)
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

/// A 3-vector of any [`Real`]; the wide kernel's vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<R> {
    /// The x component.
    pub x: R,
    /// The y component.
    pub y: R,
    /// The z component.
    pub z: R,
}

impl<R: Real> V3<R> {
    /// The vector `(x, y, z)`.
    #[inline(always)]
    pub fn new(x: R, y: R, z: R) -> Self {
        Self { x, y, z }
    }
}

impl<R: Real> Add for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn add(self, b: Self) -> Self {
        V3::new(self.x + b.x, self.y + b.y, self.z + b.z)
    }
}

impl<R: Real> Sub for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, b: Self) -> Self {
        V3::new(self.x - b.x, self.y - b.y, self.z - b.z)
    }
}

impl<R: Real> SubAssign for V3<R> {
    #[inline(always)]
    fn sub_assign(&mut self, b: Self) {
        *self = *self - b;
    }
}

impl<R: Real> Neg for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        V3::new(-self.x, -self.y, -self.z)
    }
}

impl<R: Real> Mul<R> for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: R) -> Self {
        V3::new(self.x * s, self.y * s, self.z * s)
    }
}

impl<R: Real> Vector<R> for V3<R> {
    #[inline(always)]
    fn zeros() -> Self {
        let z = R::splat(0.0);
        V3::new(z, z, z)
    }
    /// nalgebra's order: `(a + b) + c`.
    #[inline(always)]
    fn dot(&self, b: &Self) -> R {
        self.x * b.x + self.y * b.y + self.z * b.z
    }
    /// nalgebra's order of operations.
    #[inline(always)]
    fn cross(&self, b: &Self) -> Self {
        V3::new(
            self.y * b.z - self.z * b.y,
            self.z * b.x - self.x * b.z,
            self.x * b.y - self.y * b.x,
        )
    }
    /// nalgebra adds the dot product to a zero; `0 + s = s` for every
    /// `s >= 0` (and NaN), so that addition changes no bit and is left out.
    #[inline(always)]
    fn norm_squared(&self) -> R {
        self.dot(self)
    }
    #[inline(always)]
    fn select(m: R::Mask, a: Self, b: Self) -> Self {
        V3::new(
            R::select(m, a.x, b.x),
            R::select(m, a.y, b.y),
            R::select(m, a.z, b.z),
        )
    }
    #[inline(always)]
    fn pin(self) -> Self {
        V3::new(self.x.pin(), self.y.pin(), self.z.pin())
    }
}

/// Removes the component of `a` along the unit vector `n`.
#[inline(always)]
pub fn tangential_part<R: Real, V: Vector<R>>(a: V, n: V) -> V {
    a - n * a.dot(&n)
}

/// `a / |a|`, or zero for a zero vector (the sign of an exact zero is zero).
#[inline(always)]
pub fn direction_or_zero(a: Vec3) -> Vec3 {
    let len2 = a.norm_squared();
    if len2 > 0.0 {
        a / len2.sqrt()
    } else {
        Vec3::zeros()
    }
}
