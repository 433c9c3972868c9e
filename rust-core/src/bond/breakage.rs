//! When a bond breaks (docs/models/bond-nonlinear.md eq. 14-15).

use crate::real::Real;

/// Why a bond broke. Values are part of the C ABI.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BreakMode {
    /// Intact, or broken in an earlier step.
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
pub fn section_stresses<R: Real>(
    normal_force: R,
    shear_force: R,
    twist_torque: R,
    bend_torque: R,
    inv_rb: R,
) -> (R, R) {
    use std::f64::consts::FRAC_1_PI;
    let inv_area = R::splat(FRAC_1_PI) * (inv_rb * inv_rb);
    let per_moment = inv_area * inv_rb; // 1 / (pi rb^3)
    let sigma = normal_force.abs() * inv_area + bend_torque * (R::splat(4.0) * per_moment);
    let tau = shear_force * inv_area + twist_torque * (R::splat(2.0) * per_moment);
    (sigma, tau)
}

/// Limits of the stress mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StressLimits {
    /// Normal strength `sigma_max` (Pa; docs/models/bond-nonlinear.md eq. 15).
    pub max_sigma: f64,
    /// Shear strength `tau_max` (Pa; docs/models/bond-nonlinear.md eq. 15).
    pub max_tau: f64,
    /// Factor on `max_sigma` while stretched (`gamma`, or 1).
    pub tension_factor: f64,
}

/// The [`BreakMode`] of a bond with section stresses `sigma`, `tau` at
/// compression `delta`, as its number (`None` = 0), one per lane: the limit
/// of `sigma` first, then that of `tau`.
#[inline(always)]
pub fn stress_criterion<R: Real>(sigma: R, tau: R, delta: R, limits: &StressLimits) -> R {
    let mode = |m: BreakMode| R::splat(m as i32 as f64);
    let stretched = delta.lt(R::splat(0.0));
    let sigma_limit = R::select(
        stretched,
        R::splat(limits.max_sigma * limits.tension_factor),
        R::splat(limits.max_sigma),
    );
    R::select(
        sigma.ge(sigma_limit),
        R::select(stretched, mode(BreakMode::Tension), mode(BreakMode::Compression)),
        R::select(
            tau.ge(R::splat(limits.max_tau)),
            mode(BreakMode::Shear),
            mode(BreakMode::None),
        ),
    )
}

/// The critical loads of the BPM mode (LAMMPS `bond_style bpm/rotational`'s
/// `F_rc`, `F_sc`, `T_bc`, `T_tc`); infinite ones add nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SummedLimits {
    /// Tensile normal force (N).
    pub normal: f64,
    /// Shear force (N).
    pub shear: f64,
    /// Bending torque (N m).
    pub bend: f64,
    /// Twisting torque (N m).
    pub twist: f64,
}

/// BPM's summed rule, as the [`BreakMode`] number of each lane: the bond
/// breaks when `F_t/F_rc + |F_s|/F_sc + |T_b|/T_bc + |T_t|/T_tc >= 1`, from
/// the undamped loads, where `F_t` is the normal force counted positive in
/// tension (`normal_force` is positive in compression, which so holds a
/// bond together). A break of the normal and bending terms mostly is a
/// tension (or, compressed, compression) break; of the shear and twisting
/// terms a shear break, as [`stress_criterion`] sorts the section's stresses.
#[inline(always)]
pub fn summed_criterion<R: Real>(
    normal_force: R,
    shear_force: R,
    twist_torque: R,
    bend_torque: R,
    delta: R,
    limits: &SummedLimits,
) -> R {
    let mode = |m: BreakMode| R::splat(m as i32 as f64);
    let zero = R::splat(0.0);
    let bending =
        (zero - normal_force) * R::splat(1.0 / limits.normal) + bend_torque * R::splat(1.0 / limits.bend);
    let twisting = shear_force * R::splat(1.0 / limits.shear) + twist_torque * R::splat(1.0 / limits.twist);
    let stretched = delta.lt(zero);
    R::select(
        (bending + twisting).ge(R::splat(1.0)),
        R::select(
            bending.ge(twisting),
            R::select(stretched, mode(BreakMode::Tension), mode(BreakMode::Compression)),
            mode(BreakMode::Shear),
        ),
        mode(BreakMode::None),
    )
}

/// Whether the centre distance `r` broke the bond (distance mode).
#[inline(always)]
pub fn distance_criterion<R: Real>(r: R, max_distance: f64) -> R::Mask {
    r.gt(R::splat(max_distance))
}

impl BreakMode {
    /// The mode of its number (see [`stress_criterion`]).
    #[inline(always)]
    pub fn from_number(x: f64) -> Self {
        match x as i32 {
            1 => BreakMode::Distance,
            2 => BreakMode::Tension,
            3 => BreakMode::Compression,
            4 => BreakMode::Shear,
            _ => BreakMode::None,
        }
    }
}
