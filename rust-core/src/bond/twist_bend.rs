//! Twisting and bending torques (spec eq. 9-10): accumulated relative
//! rotations about and across the bond axis, with the hysteresis loop applied
//! to their magnitudes so the torque does not depend on the coordinate axes.

use super::hysteresis::Loop;
use crate::real::Real;
use crate::vector::{tangential_part, Vector};

/// Splits the relative angular velocity into its part along `n` (twisting)
/// and across it (bending); also returns `w_rel . n`, whose magnitude is the
/// length of the part along `n` (no square root needed).
#[inline(always)]
pub fn split_relative_spin<R: Real, V: Vector<R>>(w_rel: V, n: V) -> (V, V, R) {
    let rate = w_rel.dot(&n);
    let along = n * rate;
    (along, w_rel - along, rate)
}

/// Twisting angle: kept parallel to the current axis, then advanced.
#[inline(always)]
pub fn advance_twist<R: Real, V: Vector<R>>(theta: V, w_along: V, n: V, dt: R) -> V {
    n * theta.dot(&n) + w_along * dt
}

/// Bending angle: kept in the current tangent plane, then advanced.
#[inline(always)]
pub fn advance_bend<R: Real, V: Vector<R>>(theta: V, w_across: V, n: V, dt: R) -> V {
    tangential_part(theta, n) + w_across * dt
}

/// Torque on `i` for the angle `theta` with history maximum `theta_max`
/// (already updated): `-h(|theta|) * moment * theta/|theta|`. Returns the
/// torque, the new history maximum and the torque's magnitude
/// `|h| * moment` (its norm up to rounding, without a square root; 0 for a
/// zero angle).
#[inline(always)]
pub fn restoring_torque<R: Real, V: Vector<R>>(theta: V, theta_max: R, law: &Loop, moment: R) -> (V, R, R) {
    let magnitude = theta.norm();
    torque_of(
        theta,
        magnitude,
        R::splat(1.0) / magnitude,
        theta_max,
        law,
        moment,
    )
}

/// [`restoring_torque`] given `|theta|` and its reciprocal.
#[inline(always)]
fn torque_of<R: Real, V: Vector<R>>(
    theta: V,
    magnitude: R,
    inv: R,
    theta_max: R,
    law: &Loop,
    moment: R,
) -> (V, R, R) {
    let new_max = theta_max.max(magnitude);
    let h = law.value(magnitude, new_max);
    // A zero angle has no direction: no torque (the selected-away side is
    // NaN there).
    let on = magnitude.gt(R::splat(0.0));
    (
        V::select(on, theta * (-h * moment * inv), V::zeros()),
        new_max,
        R::select(on, h.abs() * moment, R::splat(0.0)),
    )
}

/// [`restoring_torque`] of two angles at once (twisting and bending): their
/// norms and reciprocals share instructions (see [`super::lanes`]); each
/// result is the same, bit for bit. Arguments per angle: `(theta, theta_max,
/// law, moment)`.
#[inline(always)]
#[allow(clippy::type_complexity)]
pub fn restoring_torques<R: Real, V: Vector<R>>(
    a: (V, R, &Loop, R),
    b: (V, R, &Loop, R),
) -> ((V, R, R), (V, R, R)) {
    let (mag_a, mag_b) = R::sqrt2(a.0.norm_squared(), b.0.norm_squared());
    // The reciprocals depend only on the norms, so the division overlaps
    // with the hysteresis laws.
    let one = R::splat(1.0);
    let (inv_a, inv_b) = R::div2(one, mag_a, one, mag_b);
    (
        torque_of(a.0, mag_a, inv_a, a.1, a.2, a.3),
        torque_of(b.0, mag_b, inv_b, b.1, b.2, b.3),
    )
}
