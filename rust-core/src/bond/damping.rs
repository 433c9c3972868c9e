//! Percentage (non-viscous) damping of the bond (docs/models/bond-nonlinear.md eq. 11-12): each force
//! and torque is reduced by a fraction of its magnitude, directed against the
//! relative motion, so its power on that motion is never positive.

use super::hysteresis::select;
use crate::real::Real;
use crate::vector::Vector;

/// Kernels pass `smooth` as a constant.
///
/// `sgn(v)`, or its smooth form `clamp(v / v_eps, -1, 1)`. `sgn(0) = 0`.
#[inline(always)]
pub fn sign<R: Real>(v: R, v_eps: f64, smooth: bool) -> R {
    if smooth {
        (v / R::splat(v_eps)).clamp(-1.0, 1.0)
    } else {
        // Without jumps: the sign of the normal rate varies from bond to bond.
        let zero = R::splat(0.0);
        select(
            v.gt(zero),
            R::splat(1.0),
            select(v.lt(zero), R::splat(-1.0), zero),
        )
    }
}

/// The divisor that makes a vector of length `len` its unit vector `v/|v|`,
/// or its smooth form `v / max(|v|, v_eps)`.
#[inline(always)]
pub fn unit_scale<R: Real>(len: R, v_eps: f64, smooth: bool) -> R {
    if smooth {
        len.max(R::splat(v_eps))
    } else {
        len
    }
}

/// `v / scale` given `inv_scale = 1 / scale` (one division, not three, and
/// a kernel can pair it with another one); zero unless `scale > 0`.
#[inline(always)]
pub fn reciprocal_unit<R: Real, V: Vector<R>>(v: V, scale: R, inv_scale: R) -> V {
    V::select(scale.gt(R::splat(0.0)), v * inv_scale, V::zeros())
}

/// `F - eta |F| sgn(v_n)` for the scalar normal force.
#[inline(always)]
pub fn damp_scalar<R: Real>(force: R, eta: f64, rate: R, eps: f64, smooth: bool) -> R {
    force - R::splat(eta) * force.abs() * sign(rate, eps, smooth)
}

/// `F - eta |F| v/|v|` for a force or torque vector, given `|F|` and the
/// (smooth) unit vector of the rate.
#[inline(always)]
pub fn damp_along<R: Real, V: Vector<R>>(force: V, force_norm: R, eta: f64, unit_rate: V) -> V {
    force - unit_rate * (R::splat(eta) * force_norm)
}
