//! Elastic energy stored in a bond: the integral of each law's loading curve
//! (`k`, the virgin branch), so it is exact for elastic bonds (`ku = k`,
//! `kc = 0`), where every branch is the loading curve. For hysteretic bonds
//! it is the energy the same deformation would store on first loading, not a
//! state function (the loop dissipates). Used by energy-balance checks and
//! the speed/accuracy study (docs/speed-accuracy.md).
//!
//! ```text
//! tension        k_n2 A d^2 / 2                          (d = r0 - r < 0)
//! compression    (2/3) k_n1 A d^(3/2)                    (d > 0)
//!   with delta_eps: k_n1 A d^2 / (2 sqrt(eps))          d < eps
//!                   k_n1 A ((2/3) d^(3/2) - eps^(3/2)/6)  d >= eps
//! shear          |Ft|^2 / (2 k_t A)
//! twisting       k_tn J |theta_n|^2 / 2
//! bending        k_tt I |theta_t|^2 / 2
//! ```

use super::features::{BEND, COMPRESSION, SHEAR, TENSION, TWIST};
use super::model::BondModel;
use super::section::section;
use super::state::{BondState, BondStatus};
use crate::vector::v3;

/// Energy of `F = k A d` from 0 to `d` (either sign).
#[inline]
pub fn linear_energy(stiffness: f64, d: f64) -> f64 {
    0.5 * stiffness * d * d
}

/// Energy of the compression law `F = k A s(d)` from 0 to `d >= 0`, where
/// `s` is the square root continued linearly below `eps` (`eps = 0`: the
/// plain square root). `stiffness` is `k A`.
#[inline]
pub fn compression_energy(stiffness: f64, d: f64, eps: f64) -> f64 {
    if d <= 0.0 {
        0.0
    } else if d < eps {
        0.5 * stiffness * d * d / eps.sqrt()
    } else {
        stiffness * (2.0 / 3.0 * d * d.sqrt() - eps * eps.sqrt() / 6.0)
    }
}

/// Energy of a shear spring of stiffness `k_t A` carrying the force `|Ft|`.
#[inline]
pub fn spring_energy_from_force(force: f64, stiffness: f64) -> f64 {
    if stiffness > 0.0 {
        0.5 * force * force / stiffness
    } else {
        0.0
    }
}

/// The parts of a bond's elastic energy (J).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BondEnergy {
    /// Normal law: tension or compression (J).
    pub normal: f64,
    /// Shear spring (J).
    pub shear: f64,
    /// Twisting (J).
    pub twist: f64,
    /// Bending (J).
    pub bend: f64,
}

impl BondEnergy {
    /// The sum of the four parts (J).
    pub fn total(&self) -> f64 {
        self.normal + self.shear + self.twist + self.bend
    }
}

impl BondModel {
    /// Elastic energy (loading curves) of a bond with state `state` at
    /// compression `delta = r0 - r`, between spheres of radii `radius_i`,
    /// `radius_j`. Only the active degrees of freedom count; a bond that is
    /// not intact stores nothing.
    pub fn elastic_energy(&self, state: &BondState, delta: f64, radius_i: f64, radius_j: f64) -> BondEnergy {
        if state.status() != BondStatus::Intact {
            return BondEnergy::default();
        }
        let p = &self.params;
        let f = self.features;
        let sec = section(p.lambda, radius_i, radius_j);
        let mut e = BondEnergy::default();
        if delta < 0.0 && f & TENSION != 0 {
            e.normal = linear_energy(p.k_fn2 * sec.area, delta);
        }
        if delta > 0.0 && f & COMPRESSION != 0 {
            e.normal = compression_energy(
                p.k_fn1 * self.compression_area(sec.area),
                delta,
                p.compression_linear_below,
            );
        }
        if f & SHEAR != 0 {
            e.shear = spring_energy_from_force(v3(state.shear_force).norm(), p.k_ft * sec.area);
        }
        if f & TWIST != 0 {
            e.twist = linear_energy(p.k_tn * sec.polar, v3(state.twist_angle).norm());
        }
        if f & BEND != 0 {
            e.bend = linear_energy(p.k_tt * sec.inertia, v3(state.bend_angle).norm());
        }
        e
    }
}
