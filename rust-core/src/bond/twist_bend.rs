//! Twisting and bending torques (spec eq. 9-10): accumulated relative
//! rotations about and across the bond axis, with the hysteresis loop applied
//! to their magnitudes so the torque does not depend on the coordinate axes.

use super::hysteresis::Loop;
use super::lanes::{div2, sqrt2};
use crate::vector::{tangential_part, Vec3};

/// Splits the relative angular velocity into its part along `n` (twisting)
/// and across it (bending); also returns `w_rel . n`, whose magnitude is the
/// length of the part along `n` (no square root needed).
#[inline(always)]
pub fn split_relative_spin(w_rel: Vec3, n: Vec3) -> (Vec3, Vec3, f64) {
    let rate = w_rel.dot(&n);
    let along = n * rate;
    (along, w_rel - along, rate)
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
/// torque, the new history maximum and the torque's magnitude
/// `|h| * moment` (its norm up to rounding, without a square root; 0 for a
/// zero angle).
#[inline(always)]
pub fn restoring_torque(theta: Vec3, theta_max: f64, law: &Loop, moment: f64) -> (Vec3, f64, f64) {
    let magnitude = theta.norm();
    let new_max = theta_max.max(magnitude);
    if magnitude > 0.0 {
        let inv = 1.0 / magnitude;
        let h = law.value(magnitude, new_max);
        (theta * (-h * moment * inv), new_max, h.abs() * moment)
    } else {
        (Vec3::zeros(), new_max, 0.0)
    }
}

/// [`restoring_torque`] of two angles at once (twisting and bending): their
/// norms and reciprocals share instructions (see [`super::lanes`]); each
/// result is the same, bit for bit. Arguments per angle: `(theta, theta_max,
/// law, moment)`.
#[inline(always)]
pub fn restoring_torques(
    a: (Vec3, f64, &Loop, f64),
    b: (Vec3, f64, &Loop, f64),
) -> ((Vec3, f64, f64), (Vec3, f64, f64)) {
    let (mag_a, mag_b) = sqrt2(a.0.norm_squared(), b.0.norm_squared());
    // The reciprocals depend only on the norms, so the division overlaps
    // with the hysteresis laws.
    let (inv_a, inv_b) = div2(1.0, mag_a, 1.0, mag_b);
    let (max_a, max_b) = (a.1.max(mag_a), b.1.max(mag_b));
    let (h_a, h_b) = (a.2.value(mag_a, max_a), b.2.value(mag_b, max_b));
    let (on_a, on_b) = (mag_a > 0.0, mag_b > 0.0);
    let t_a = if on_a {
        a.0 * (-h_a * a.3 * inv_a)
    } else {
        Vec3::zeros()
    };
    let t_b = if on_b {
        b.0 * (-h_b * b.3 * inv_b)
    } else {
        Vec3::zeros()
    };
    let m_a = if on_a { h_a.abs() * a.3 } else { 0.0 };
    let m_b = if on_b { h_b.abs() * b.3 } else { 0.0 };
    ((t_a, max_a, m_a), (t_b, max_b, m_b))
}
