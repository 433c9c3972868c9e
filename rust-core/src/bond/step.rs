//! The assembled step: every law of the bond, in order, for one bond
//! (`f64`) or a chunk of bonds in lanes, over the parts switched on. The
//! scalar and wide paths ([`super::scalar`], [`super::wide`]) only move
//! numbers in and out of it.

use super::breakage::{distance_criterion, section_stresses, stress_criterion, BreakMode};
use super::damping::{damp_along, damp_scalar, reciprocal_unit, sign, unit_scale};
use super::features::{BEND, COMPRESSION, DAMPING, SHEAR, SMOOTH, TENSION, TWIST};
use super::laws::BondLaws;
use super::paired::{norms, reciprocals};
use super::section::{lever_arms_scaled, section};
use super::shear::update_shear_force;
use super::switches::Switches;
use super::twist_bend::{advance_bend, advance_twist, split_relative_spin, BendHistory, TwistHistory};
use crate::kinematics::{slip_velocity, CentreLine};
use crate::real::Real;
use crate::vector::Vector;

/// What a step reads of a pair besides its centre line.
#[derive(Clone, Copy)]
pub(crate) struct Motion<R, V> {
    pub v_i: V,
    pub v_j: V,
    pub w_i: V,
    pub w_j: V,
    pub radius_i: R,
    pub radius_j: R,
}

/// The slots of [`BondState`] a step updates (all but the status).
#[derive(Clone, Copy)]
pub(crate) struct History<R, V> {
    pub r0: R,
    pub delta_max: R,
    pub delta_min: R,
    pub shear_force: V,
    pub twist_angle: V,
    pub bend_angle: V,
    pub twist: TwistHistory<R>,
    pub bend: BendHistory<R, V>,
}

impl<R: Real, V: Vector<R>> History<R, V> {
    #[inline(always)]
    fn select(m: R::Mask, a: Self, b: Self) -> Self {
        Self {
            r0: R::select(m, a.r0, b.r0),
            delta_max: R::select(m, a.delta_max, b.delta_max),
            delta_min: R::select(m, a.delta_min, b.delta_min),
            shear_force: V::select(m, a.shear_force, b.shear_force),
            twist_angle: V::select(m, a.twist_angle, b.twist_angle),
            bend_angle: V::select(m, a.bend_angle, b.bend_angle),
            twist: TwistHistory {
                max: R::select(m, a.twist.max, b.twist.max),
                min: R::select(m, a.twist.min, b.twist.min),
            },
            bend: BendHistory {
                leading: V::select(m, a.bend.leading, b.bend.leading),
                opposite: R::select(m, a.bend.opposite, b.bend.opposite),
            },
        }
    }
}

/// What a step produces: [`BondOutput`] but the status, which follows from
/// `mode`, the [`BreakMode`] as a number (0: the bond holds).
#[derive(Clone, Copy)]
pub(crate) struct Loads<R, V> {
    pub force_i: V,
    pub torque_i: V,
    pub torque_j: V,
    pub normal_force: R,
    pub sigma: R,
    pub tau: R,
    pub delta: R,
    pub mode: R,
}

/// The physics of one step of an intact bond with usable kinematics, for one
/// bond (`f64`) or a chunk of lanes (see [`super::wide`]): updates
/// `history` and returns the loads.
///
/// A bond that breaks exerts nothing. One broken by distance keeps its
/// history as it was and reports no stresses; one broken by stress has its
/// history updated and reports the stresses that broke it. The scalar
/// kernel returns as soon as its bond breaks; in lanes every lane is
/// computed and the broken ones are masked at the end (and the history of
/// the ones broken by distance restored), unless all of them broke.
#[inline(always)]
pub(crate) fn advance<S: Switches, R: Real, V: Vector<R>>(
    laws: &BondLaws,
    m: &Motion<R, V>,
    line: CentreLine<R, V>,
    dt: R,
    h: &mut History<R, V>,
) -> Loads<R, V> {
    let on = |bits| S::of(laws).any(bits);
    let zero = R::splat(0.0);
    let n = line.n;
    let delta = h.r0 - line.r;
    let broken = |normal_force, sigma, tau, mode| Loads {
        force_i: V::zeros(),
        torque_i: V::zeros(),
        torque_j: V::zeros(),
        normal_force,
        sigma,
        tau,
        delta,
        mode,
    };
    let distance_mode = R::splat(BreakMode::Distance as i32 as f64);
    let gone = if laws.stress_break {
        R::mask(false)
    } else {
        distance_criterion(line.r, laws.params.max_distance)
    };
    if R::all(gone) {
        return broken(zero, zero, zero, distance_mode);
    }
    let before = *h;
    let sec = section(laws.params.lambda, m.radius_i, m.radius_j);
    // The only divisions by the radii: the stresses and lever arms multiply.
    let (inv_rb, inv_radius_sum) = super::section::reciprocals(&sec, m.radius_i, m.radius_j);

    let mut normal_force = zero;
    if on(TENSION | COMPRESSION) {
        let (hi, lo) = laws.normal.update_history(delta, h.delta_max, h.delta_min);
        h.delta_max = hi;
        h.delta_min = lo;
        normal_force = sec.area * laws.normal.stress(delta, hi, lo, on(TENSION), on(COMPRESSION));
    }

    let (mut lever_i, mut lever_j) = (zero, zero);
    let mut slip = V::zeros();
    let mut shear_force = V::zeros();
    if on(SHEAR) {
        (lever_i, lever_j) = lever_arms_scaled(line.r, inv_radius_sum, m.radius_i, m.radius_j);
        slip = slip_velocity(m.v_i - m.v_j, m.w_i, m.w_j, n, lever_i, lever_j);
        let stiffness = R::splat(laws.params.k_ft) * sec.area;
        shear_force = update_shear_force(h.shear_force, stiffness, dt, slip, n);
        h.shear_force = shear_force;
    }

    let (twist, bend) = (on(TWIST), on(BEND));
    let (w_along, w_across, spin_rate) = if twist || bend {
        split_relative_spin(m.w_i - m.w_j, n)
    } else {
        (V::zeros(), V::zeros(), zero)
    };
    let (mut twist_torque, mut bend_torque) = (V::zeros(), V::zeros());
    // |torque| = |h| * moment, from the laws (no square roots).
    let (mut twist_magnitude, mut bend_magnitude) = (zero, zero);
    if twist {
        let theta = advance_twist(h.twist_angle, w_along, n, dt);
        let (t, history) = laws.twist.twist(theta, n, h.twist, sec.polar);
        h.twist_angle = theta;
        h.twist = history;
        (twist_torque, twist_magnitude) = (t.torque, t.magnitude);
    }
    if bend {
        let theta = advance_bend(h.bend_angle, w_across, n, dt);
        let (t, history) = laws.bend.bend(theta, n, h.bend, sec.inertia);
        h.bend_angle = theta;
        h.bend = history;
        (bend_torque, bend_magnitude) = (t.torque, t.magnitude);
    }
    // Lanes broken by distance keep their history (a scalar bond returned
    // above; for it `gone` is false here and this vanishes).
    if R::any(gone) {
        *h = History::select(gone, before, *h);
    }

    // Lengths, two per instruction: the shear force (for the stresses and
    // the damping) and, with damping, the slip speed the damping opposes.
    let (shear, damping) = (on(SHEAR), on(DAMPING));
    let (shear_magnitude, slip_speed) = norms(shear_force, shear, slip, shear && damping);
    let (sigma, tau) = section_stresses(
        normal_force,
        shear_magnitude,
        twist_magnitude,
        bend_magnitude,
        inv_rb,
    );
    let undamped = normal_force;
    let stress_mode = if laws.stress_break {
        stress_criterion(sigma, tau, delta, &laws.limits)
    } else {
        zero
    };
    let snapped = stress_mode.gt(zero);
    if R::all(snapped) {
        return broken(normal_force, sigma, tau, stress_mode);
    }

    if damping {
        let smooth = on(SMOOTH);
        let p = &laws.params;
        let (ve, we) = (p.smooth_velocity, p.smooth_angular_velocity);
        if on(TENSION | COMPRESSION) {
            let vn = (m.v_i - m.v_j).dot(&n);
            normal_force = damp_scalar(normal_force, p.eta_fn, vn, ve, smooth);
        }
        // The (smooth) unit vectors of the slip and of the bending spin: one
        // reciprocal each, both in one instruction.
        let spin_across = if bend { w_across.norm() } else { zero };
        let scale_s = unit_scale(slip_speed, ve, smooth);
        let scale_b = unit_scale(spin_across, we, smooth);
        let (inv_s, inv_b) = reciprocals(scale_s, shear, scale_b, bend);
        if shear {
            let direction = reciprocal_unit(slip, scale_s, inv_s);
            shear_force = damp_along(shear_force, shear_magnitude, p.eta_ft, direction);
        }
        if twist {
            // w_along = n (w . n), so its unit vector is n sgn(w . n) (and
            // the smooth one n clamp(w . n / we, -1, 1), the same thing).
            let direction = n * sign(spin_rate, we, smooth);
            twist_torque = damp_along(twist_torque, twist_magnitude, p.eta_tn, direction);
        }
        if bend {
            let direction = reciprocal_unit(w_across, scale_b, inv_b);
            bend_torque = damp_along(bend_torque, bend_magnitude, p.eta_tt, direction);
        }
    }

    let force = n * normal_force + shear_force;
    let couple = bend_torque + twist_torque;
    let (mut torque_i, mut torque_j) = (couple, -couple);
    if shear {
        let arm = n.cross(&shear_force);
        torque_i -= arm * lever_i;
        torque_j -= arm * lever_j;
    }
    // The lanes that broke (none for a scalar bond here) exert nothing.
    let off = gone | snapped;
    let load = |v| V::select(off, V::zeros(), v);
    Loads {
        force_i: load(force),
        torque_i: load(torque_i),
        torque_j: load(torque_j),
        normal_force: R::select(gone, zero, undamped),
        sigma: R::select(gone, zero, sigma),
        tau: R::select(gone, zero, tau),
        delta,
        // (`stress_mode` is 0 unless `snapped`; spelt out, the scalar
        // kernel sees a constant here.)
        mode: R::select(gone, distance_mode, R::select(snapped, stress_mode, zero)),
    }
}
