//! The vector type of the physics and the few operations on it that the laws
//! share.

pub type Vec3 = nalgebra::Vector3<f64>;

#[inline(always)]
pub fn v3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

/// Removes the component of `a` along the unit vector `n`.
#[inline(always)]
pub fn tangential_part(a: Vec3, n: Vec3) -> Vec3 {
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
