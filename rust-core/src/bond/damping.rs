//! Percentage (non-viscous) damping of the bond (spec eq. 11-12): each force
//! and torque is reduced by a fraction of its magnitude, directed against the
//! relative motion, so its power on that motion is never positive.

use crate::vector::Vec3;

/// Kernels pass `smooth` as a constant.
///
/// `sgn(v)`, or its smooth form `clamp(v / v_eps, -1, 1)`. `sgn(0) = 0`.
#[inline(always)]
pub fn sign(v: f64, v_eps: f64, smooth: bool) -> f64 {
    if smooth {
        (v / v_eps).clamp(-1.0, 1.0)
    } else if v > 0.0 {
        1.0
    } else if v < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// `v/|v|`, or its smooth form `v / max(|v|, v_eps)`; zero for `v = 0`.
#[inline(always)]
pub fn unit(v: Vec3, v_eps: f64, smooth: bool) -> Vec3 {
    let len = v.norm();
    let scale = if smooth { len.max(v_eps) } else { len };
    if scale > 0.0 {
        v / scale
    } else {
        Vec3::zeros()
    }
}

/// `F - eta |F| sgn(v_n)` for the scalar normal force.
#[inline(always)]
pub fn damp_scalar(force: f64, eta: f64, rate: f64, eps: f64, smooth: bool) -> f64 {
    force - eta * force.abs() * sign(rate, eps, smooth)
}

/// `F - eta |F| v/|v|` for a force or torque vector.
#[inline(always)]
pub fn damp_vector(force: Vec3, eta: f64, rate: Vec3, eps: f64, smooth: bool) -> Vec3 {
    force - unit(rate, eps, smooth) * (eta * force.norm())
}
