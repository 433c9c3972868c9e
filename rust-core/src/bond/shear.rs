//! Incremental shear force of the bond (docs/models/bond-nonlinear.md eq. 7-8).

use crate::real::Real;
use crate::vector::{tangential_part, Vector};

/// `Ft <- Ft - k_t A dt v_tr`, then projected onto the tangent plane of the
/// current axis `n`. `v_tr` is the slip velocity at the contact point
/// (`kinematics::slip_velocity`), which vanishes in rigid motion.
#[inline(always)]
pub fn update_shear_force<R: Real, V: Vector<R>>(
    shear_force: V,
    stiffness_area: R,
    dt: R,
    slip: V,
    n: V,
) -> V {
    tangential_part(shear_force - slip * (stiffness_area * dt), n)
}
