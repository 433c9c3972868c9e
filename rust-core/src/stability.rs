//! Stability limit of explicit (symplectic Euler) integration of a
//! spring-dashpot oscillator, shared by the bond and contact estimates.

/// The recommended step as a fraction of the critical step, for bonds and
/// contacts alike (docs/speed-accuracy.md). The estimates are the limit of
/// one bond or contact between two spheres; a sphere bonded to six
/// neighbours (a cubic packing) goes unstable below that limit, and the
/// square root's rattle amplitude shrinks as the fourth power of the step.
/// The fraction leaves a margin to the coordinated limit and keeps the
/// reference oscillators' periods and the cantilever's first frequency
/// close to their analytic values; docs/speed-accuracy.md gives the
/// measured margins and errors.
pub const RECOMMENDED_FRACTION: f64 = 0.2;

/// Moment of inertia of a solid sphere.
pub fn sphere_inertia(mass: f64, radius: f64) -> f64 {
    0.4 * mass * radius * radius
}

/// Largest stable step of `inertia x'' + damping x' + stiffness x = 0` under
/// symplectic Euler: `2 (sqrt(1 + zeta^2) - zeta) / omega`, which is
/// `2 sqrt(inertia / stiffness)` without damping. Infinite when there is no
/// stiffness.
pub fn oscillator_limit(inertia: f64, stiffness: f64, damping: f64) -> f64 {
    if !(stiffness > 0.0) {
        return f64::INFINITY;
    }
    let (sqrt_k, sqrt_m) = (stiffness.sqrt(), inertia.sqrt());
    let zeta = damping / (2.0 * sqrt_k * sqrt_m);
    // sqrt(1 + zeta^2) - zeta = 1 / (sqrt(1 + zeta^2) + zeta): the difference
    // cancels to 0 for heavy damping (zeta above ~1e8, as rolling damping
    // of micrometre spheres), the sum does not; hypot does not overflow.
    2.0 * (sqrt_m / sqrt_k) / (1f64.hypot(zeta) + zeta)
}
