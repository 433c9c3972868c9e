//! Incremental shear force of the bond (spec eq. 7-8).

use crate::vector::{tangential_part, Vec3};

/// `Ft <- Ft - k_t A dt v_tr`, then projected onto the tangent plane of the
/// current axis `n`. `v_tr` is the slip velocity at the contact point
/// (`kinematics::tangential_slip_velocity`), which vanishes in rigid motion.
#[inline(always)]
pub fn update_shear_force(shear_force: Vec3, stiffness_area: f64, dt: f64, slip: Vec3, n: Vec3) -> Vec3 {
    tangential_part(shear_force - slip * (stiffness_area * dt), n)
}
