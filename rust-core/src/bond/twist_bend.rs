//! Twisting and bending torques (spec eq. 9-10): accumulated relative
//! rotations about and across the bond axis, with the hysteresis loop applied
//! to their magnitudes so the torque does not depend on the coordinate axes.

use super::hysteresis::Loop;
use super::lanes::{div2, sqrt2};
use crate::vector::{tangential_part, Vec3};

/// Splits the relative angular velocity into its part along `n` (twisting)
/// and across it (bending).
#[inline(always)]
pub fn split_relative_spin(w_rel: Vec3, n: Vec3) -> (Vec3, Vec3) {
    let along = n * w_rel.dot(&n);
    (along, w_rel - along)
}

/// Twisting angle: kept parallel to the current axis, then advanced.
#[inline(always)]
pub fn advance_twist(theta: Vec3, w_along: Vec3, n: Vec3, dt: f64) -> Vec3 {
    n * theta.dot(&n) + w_along * dt
}

/// Bending angle: kept in the current tangent plane, then advanced.
#[inline(always)]
pub fn advance_bend(theta: Vec3, w_across: Vec3, n: Vec3, dt: f64) -> Vec3 {
    tangential_part(theta, n) + w_across * dt
}

/// Torque on `i` for the angle `theta` with history maximum `theta_max`
/// (already updated): `-h(|theta|) * moment * theta/|theta|`. Returns the
/// torque and the new history maximum.
#[inline(always)]
pub fn restoring_torque(theta: Vec3, theta_max: f64, law: &Loop, moment: f64) -> (Vec3, f64) {
    let magnitude = theta.norm();
    let new_max = theta_max.max(magnitude);
    if magnitude > 0.0 {
        let h = law.value(magnitude, new_max);
        (theta * (-h * moment / magnitude), new_max)
    } else {
        (Vec3::zeros(), new_max)
    }
}

/// [`restoring_torque`] of two angles at once (twisting and bending): their
/// norms and quotients share instructions (see [`super::lanes`]); each result
/// is the same, bit for bit. Arguments per angle: `(theta, theta_max, law,
/// moment)`.
#[inline(always)]
pub fn restoring_torques(
    a: (Vec3, f64, &Loop, f64),
    b: (Vec3, f64, &Loop, f64),
) -> ((Vec3, f64), (Vec3, f64)) {
    let (mag_a, mag_b) = sqrt2(a.0.norm_squared(), b.0.norm_squared());
    let (max_a, max_b) = (a.1.max(mag_a), b.1.max(mag_b));
    let (h_a, h_b) = (a.2.value(mag_a, max_a), b.2.value(mag_b, max_b));
    let (f_a, f_b) = div2(-h_a * a.3, mag_a, -h_b * b.3, mag_b);
    let t_a = if mag_a > 0.0 { a.0 * f_a } else { Vec3::zeros() };
    let t_b = if mag_b > 0.0 { b.0 * f_b } else { Vec3::zeros() };
    ((t_a, max_a), (t_b, max_b))
}
