//! When a bond breaks (spec eq. 14-15).

/// Why a bond broke. Values are part of the C ABI.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BreakMode {
    None = 0,
    /// Centre distance above `max_distance`.
    Distance = 1,
    /// `sigma` reached its limit while the bond was stretched.
    Tension = 2,
    /// `sigma` reached its limit while the bond was compressed.
    Compression = 3,
    /// `tau` reached `max_tau`.
    Shear = 4,
}

/// Normal and shear stress of the bond section from the undamped loads:
/// `sigma = |Fn|/A + |Tt| rb / I`, `tau = |Ft|/A + |Tn| rb / J`, with
/// `A = pi rb^2`, `J = pi rb^4 / 2`, `I = J / 2` (see [`super::section`]),
/// so `1/A = 1/(pi rb^2)`, `rb/I = 4/(pi rb^3)`, `rb/J = 2/(pi rb^3)`: given
/// `inv_rb = 1 / rb` (computed once per bond) no division is left.
#[inline(always)]
pub fn section_stresses(
    normal_force: f64,
    shear_force: f64,
    twist_torque: f64,
    bend_torque: f64,
    inv_rb: f64,
) -> (f64, f64) {
    use std::f64::consts::FRAC_1_PI;
    let inv_area = FRAC_1_PI * (inv_rb * inv_rb);
    let per_moment = inv_area * inv_rb; // 1 / (pi rb^3)
    let sigma = normal_force.abs() * inv_area + bend_torque * (4.0 * per_moment);
    let tau = shear_force * inv_area + twist_torque * (2.0 * per_moment);
    (sigma, tau)
}

/// Limits of the stress mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StressLimits {
    pub max_sigma: f64,
    pub max_tau: f64,
    /// Factor on `max_sigma` while stretched (`gamma`, or 1).
    pub tension_factor: f64,
}

#[inline(always)]
pub fn stress_criterion(sigma: f64, tau: f64, delta: f64, limits: &StressLimits) -> BreakMode {
    let stretched = delta < 0.0;
    let sigma_limit = if stretched {
        limits.max_sigma * limits.tension_factor
    } else {
        limits.max_sigma
    };
    if sigma >= sigma_limit {
        if stretched {
            BreakMode::Tension
        } else {
            BreakMode::Compression
        }
    } else if tau >= limits.max_tau {
        BreakMode::Shear
    } else {
        BreakMode::None
    }
}

#[inline(always)]
pub fn distance_criterion(r: f64, max_distance: f64) -> BreakMode {
    if r > max_distance {
        BreakMode::Distance
    } else {
        BreakMode::None
    }
}
