//! Symplectic Euler (docs/models/voigt.md, "Time integration"): velocities from the current
//! loads, then positions from the new velocities. The engines integrate for
//! themselves; this is for the crate's own scene runner and tests.

use crate::vector::Vec3;

/// Translational and rotational state of one sphere. `rotation` accumulates
/// `dt w` (a rotation vector for small angles; for output only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Centre (m).
    pub x: Vec3,
    /// Velocity (m/s).
    pub v: Vec3,
    /// Angular velocity (rad/s).
    pub w: Vec3,
    /// Accumulated `dt w` (rad).
    pub rotation: Vec3,
    /// Mass (kg).
    pub mass: f64,
    /// Moment of inertia (kg m^2).
    pub inertia: f64,
}

/// `v += dt F/m; w += dt T/I; x += dt v; theta += dt w`.
#[inline]
pub fn symplectic_euler(body: &mut Body, force: Vec3, torque: Vec3, dt: f64) {
    body.v += force * (dt / body.mass);
    body.w += torque * (dt / body.inertia);
    body.x += body.v * dt;
    body.rotation += body.w * dt;
}
