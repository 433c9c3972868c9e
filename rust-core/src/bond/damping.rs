//! Percentage (non-viscous) damping of the bond (spec eq. 11-12): each force
//! and torque is reduced by a fraction of its magnitude, directed against the
//! relative motion, so its power on that motion is never positive.

use super::hysteresis::select;
use super::lanes::div2;
use crate::vector::Vec3;

/// Kernels pass `smooth` as a constant.
///
/// `sgn(v)`, or its smooth form `clamp(v / v_eps, -1, 1)`. `sgn(0) = 0`.
#[inline(always)]
pub fn sign(v: f64, v_eps: f64, smooth: bool) -> f64 {
    if smooth {
        (v / v_eps).clamp(-1.0, 1.0)
    } else {
        // Without jumps: the sign of the normal rate varies from bond to bond.
        select(v > 0.0, 1.0, select(v < 0.0, -1.0, 0.0))
    }
}

/// `v/|v|`, or its smooth form `v / max(|v|, v_eps)`; zero for `v = 0`.
#[inline(always)]
pub fn unit(v: Vec3, v_eps: f64, smooth: bool) -> Vec3 {
    scaled_unit(v, unit_scale(v.norm(), v_eps, smooth))
}

/// The divisor of [`unit`] for a vector of length `len`.
#[inline(always)]
pub fn unit_scale(len: f64, v_eps: f64, smooth: bool) -> f64 {
    if smooth {
        len.max(v_eps)
    } else {
        len
    }
}

/// `v / scale`, zero unless `scale > 0` (the last step of [`unit`]),
/// computed as `v * (1 / scale)`: one division, not three.
#[inline(always)]
pub fn scaled_unit(v: Vec3, scale: f64) -> Vec3 {
    reciprocal_unit(v, scale, 1.0 / scale)
}

/// [`scaled_unit`] given `inv_scale = 1 / scale` (so a kernel can pair that
/// division with another one).
#[inline(always)]
pub fn reciprocal_unit(v: Vec3, scale: f64, inv_scale: f64) -> Vec3 {
    if scale > 0.0 {
        v * inv_scale
    } else {
        Vec3::zeros()
    }
}

/// [`scaled_unit`] of two vectors, their reciprocals in one two-lane division.
#[inline(always)]
pub fn scaled_units(a: Vec3, scale_a: f64, b: Vec3, scale_b: f64) -> (Vec3, Vec3) {
    let (inv_a, inv_b) = div2(1.0, scale_a, 1.0, scale_b);
    (
        reciprocal_unit(a, scale_a, inv_a),
        reciprocal_unit(b, scale_b, inv_b),
    )
}

/// `F - eta |F| sgn(v_n)` for the scalar normal force.
#[inline(always)]
pub fn damp_scalar(force: f64, eta: f64, rate: f64, eps: f64, smooth: bool) -> f64 {
    force - eta * force.abs() * sign(rate, eps, smooth)
}

/// `F - eta |F| v/|v|` for a force or torque vector.
#[inline(always)]
pub fn damp_vector(force: Vec3, eta: f64, rate: Vec3, eps: f64, smooth: bool) -> Vec3 {
    damp_along(force, force.norm(), eta, unit(rate, eps, smooth))
}

/// [`damp_vector`] given `|F|` and the (smooth) unit vector of the rate.
#[inline(always)]
pub fn damp_along(force: Vec3, force_norm: f64, eta: f64, unit_rate: Vec3) -> Vec3 {
    force - unit_rate * (eta * force_norm)
}
