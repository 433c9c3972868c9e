//! Energy of a bond, two measures.
//!
//! The energy it stores now ([`BondModel::stored_energy`]): each law
//! integrated from zero deformation to the present one at the present
//! history (docs/models/bond-nonlinear.md, "Energy"). At a fixed history
//! every law is the gradient of it, so the loads do work only by changing
//! it; a history update never raises it, so what the loads take out of the
//! bond beyond it is what the hysteresis dissipated. After a yield it can
//! be negative: the well of a permanent set lies below zero deformation.
//!
//! The loading-curve energy ([`BondModel::elastic_energy`]): the integral of
//! each law's virgin branch (`k`), exact for elastic bonds (`ku = k`,
//! `kc = 0`), where every branch is the loading curve; used by the
//! speed/accuracy study (docs/speed-accuracy.md):
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
use super::hysteresis::Loop;
use super::inl::DEAD_ZONE;
use super::laws::BondLaws;
use super::model::BondModel;
use super::params::BondParams;
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
        if self.linear {
            return linear_stored_energy(self, state, delta, radius_i, radius_j);
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

/// `E(q) = integral of h(s(q'); s(q_max)) dq'` over `0 <= q' <= q`: the
/// work of one side of the normal law per unit area at a fixed history,
/// for a loading measure `s` (compression: the square root continued
/// linearly below `eps`; tension: `s(q) = q`). On each branch `h` is
/// `a s + b`, so its integral is `a (P(q2) - P(q1)) + b (q2 - q1)` with
/// `P(q) = integral of s` ([`compression_energy`] per unit stiffness).
fn measured_loop_work(l: &Loop, q: f64, q_max: f64, eps: Option<f64>) -> f64 {
    let s = |q: f64| match eps {
        Some(e) if q < e => q / e.sqrt(),
        Some(_) => q.sqrt(),
        None => q,
    };
    let s_inv = |y: f64| match eps {
        Some(e) if y * y < e => y * e.sqrt(),
        Some(_) => y * y,
        None => y,
    };
    let p = |q: f64| match eps {
        Some(e) => compression_energy(1.0, q, e),
        None => 0.5 * q * q,
    };
    let m = s(q_max);
    let q_kink = s_inv(l.c * m).min(q_max);
    let reverse_end = q.min(q_kink);
    let mut work = -l.kc * p(reverse_end);
    if q > q_kink {
        let end = q.min(q_max);
        work += l.ku * (p(end) - p(q_kink)) + (l.k - l.ku) * m * (end - q_kink);
    }
    if q > q_max {
        work += l.k * (p(q) - p(q_max));
    }
    work
}

impl BondModel {
    /// The energy a bond with state `state` at compression `delta = r0 - r`
    /// and axis `axis` (`n`, from `j` to `i`; it signs the twisting angle)
    /// stores now, between spheres of radii `radius_i`, `radius_j` (J): each
    /// law switched on integrated from zero deformation to its present one
    /// at the history in `state` (as a step leaves it: updated for the
    /// deformation it holds). Normal: the branches of eq. 6 from 0 to
    /// `delta`; shear: `|Ft|^2 / (2 k_ft A)`; twisting: [`twist_work`] times
    /// `J`; bending: [`bend_work`] times `I`. Zero for a bond that is not
    /// intact.
    pub fn stored_energy(
        &self,
        state: &BondState,
        axis: [f64; 3],
        delta: f64,
        radius_i: f64,
        radius_j: f64,
    ) -> BondEnergy {
        if state.status() != BondStatus::Intact {
            return BondEnergy::default();
        }
        if self.linear {
            return linear_stored_energy(self, state, delta, radius_i, radius_j);
        }
        let f = self.features;
        let sec = section(self.params.lambda, radius_i, radius_j);
        let normal = &self.normal;
        let mut e = BondEnergy::default();
        if delta < 0.0 && f & TENSION != 0 {
            e.normal =
                sec.area * measured_loop_work(&normal.tension, -delta, -state.delta_min.min(0.0), None);
        }
        if delta >= 0.0 && f & COMPRESSION != 0 {
            let eps = normal.linear_below;
            e.normal = sec.area
                * measured_loop_work(&normal.compression, delta, state.delta_max.max(0.0), Some(eps));
        }
        if f & SHEAR != 0 {
            e.shear = spring_energy_from_force(v3(state.shear_force).norm(), self.params.k_ft * sec.area);
        }
        if f & TWIST != 0 {
            let phi = v3(state.twist_angle).dot(&v3(axis));
            e.twist = sec.polar * twist_work(&self.twist.hysteresis, phi, state.twist_max, state.twist_min);
        }
        if f & BEND != 0 {
            e.bend = sec.inertia
                * bend_work(
                    &self.bend.hysteresis,
                    state.bend_angle,
                    state.bend_history,
                    state.bend_opposite,
                );
        }
        e
    }
}

/// The bending energy per unit `I` of the angle `theta_t` at the history
/// `beta`, `beta_opp` (docs/models/bond-nonlinear.md, "Bending"):
/// `((1 + c) E(x; |beta|) + (1 - c) E(x; beta_opp)) / 2`, `x = |theta_t|`,
/// `c` the cosine of the angle between `theta_t` and `beta` (1 while
/// `beta` is zero), `E` the loop's [`Loop::work`]. On the line of `beta`
/// it is the signed law's energy; off it the two sides' energies blend
/// continuously, so the torque, its gradient, does no work over a closed
/// path at a fixed history.
pub fn bend_work(law: &Loop, theta_t: [f64; 3], beta: [f64; 3], beta_opp: f64) -> f64 {
    let (theta, beta) = (v3(theta_t), v3(beta));
    let (x, extreme) = (theta.norm(), beta.norm());
    if x == 0.0 {
        return 0.0;
    }
    let cosine = if extreme > 0.0 {
        (theta.dot(&beta) / (x * extreme)).clamp(-1.0, 1.0)
    } else {
        1.0
    };
    0.5 * ((1.0 + cosine) * law.work(x, extreme) + (1.0 - cosine) * law.work(x, beta_opp))
}

/// The twisting energy per unit `J` of the signed angle `phi` at the
/// history `phi_max >= 0`, `phi_min <= 0`: the loop's [`Loop::work`] on
/// the side `phi` is on.
pub fn twist_work(law: &Loop, phi: f64, phi_max: f64, phi_min: f64) -> f64 {
    if phi >= 0.0 {
        law.work(phi, phi_max)
    } else {
        law.work(-phi, -phi_min)
    }
}

/// The energy a linear bond with state `state` at compression `delta`
/// stores between spheres of radii `radius_i`, `radius_j` (J): `k_n A d^2
/// / 2` on the side switched on, `|F_t|^2 / (2 k_t A)`, `k_t J |theta_n|^2
/// / 2` and `k_n I |theta_t|^2 / 2`. Every law is linear, so this is also
/// its loading-curve energy.
fn linear_stored_energy(
    laws: &BondLaws,
    state: &BondState,
    delta: f64,
    radius_i: f64,
    radius_j: f64,
) -> BondEnergy {
    let p = &laws.params;
    let on = BondParams::switch;
    let sec = section(p.lambda, radius_i, radius_j);
    let mut e = BondEnergy::default();
    if (on(p.tension) && delta < -DEAD_ZONE) || (on(p.compression) && delta > DEAD_ZONE) {
        e.normal = linear_energy(p.k_n * sec.area, delta);
    }
    if on(p.shear) {
        e.shear = spring_energy_from_force(v3(state.shear_force).norm(), p.k_t * sec.area);
    }
    if on(p.twist) {
        e.twist = linear_energy(p.k_t * sec.polar, v3(state.twist_angle).norm());
    }
    if on(p.bend) {
        e.bend = linear_energy(p.k_n * sec.inertia, v3(state.bend_angle).norm());
    }
    e
}
