//! Stability limit of explicit (symplectic Euler) integration of a
//! spring-dashpot oscillator, shared by the bond and contact estimates.

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
    let omega = (stiffness / inertia).sqrt();
    let zeta = damping / (2.0 * (stiffness * inertia).sqrt());
    2.0 * ((1.0 + zeta * zeta).sqrt() - zeta) / omega
}
