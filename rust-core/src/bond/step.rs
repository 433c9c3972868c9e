//! The assembled step: every law of the bond, in order, for one bond
//! (`f64`) or a chunk of bonds in lanes, over the parts switched on. The
//! scalar and wide paths ([`super::scalar`], [`super::wide`]) only move
//! numbers in and out of it.
//!
//! The step runs in stages, so that in lanes what one stage holds is dead
//! before the next stage's numbers come in (16 AVX2 registers): the pair's
//! kinematics are reduced to what the laws read as soon as they are loaded
//! ([`relative`]); then each law in the order of the state's slots reads
//! its history, writes it back and is damped ([`advance`], through
//! [`HistoryIo`]).

use super::breakage::{distance_criterion, section_stresses, stress_criterion, summed_criterion, BreakMode};
use super::damping::{damp_along, damp_scalar, reciprocal_unit, sign, unit_scale};
use super::features::{BEND, COMPRESSION, DAMPING, SHEAR, SMOOTH, TENSION, TWIST};
use super::laws::BondLaws;
use super::paired::{norms, reciprocals};
use super::section::{lever_arms_scaled, section, Section};
use super::shear::update_shear_force;
use super::switches::Switches;
use super::twist_bend::{advance_bend, advance_twist, split_relative_spin, BendHistory, TwistHistory};
use crate::kinematics::{slip_velocity, CentreLine};
use crate::real::Real;
use crate::vector::Vector;

/// Where a step reads what it needs of a pair besides its centre line,
/// each when [`relative`] first needs it.
pub(crate) trait MotionSource<R, V> {
    /// `(R_i, R_j)`.
    fn radii(&mut self) -> (R, R);
    /// `(v_i, v_j)`.
    fn velocities(&mut self) -> (V, V);
    /// `(w_i, w_j)`.
    fn spins(&mut self) -> (V, V);
}

/// Where a step reads a bond's history and writes it back, one group of
/// slots at a time, and where its force goes as soon as it is known.
/// [`advance`] reads a group just before its law needs it and hands every
/// group back once, in the order of the slots: the new values, or `None`
/// for a law switched off, whose slots stay as they are.
pub(crate) trait HistoryIo<R, V> {
    fn delta_extremes(&mut self) -> (R, R);
    fn shear_force(&mut self) -> V;
    fn twist_angle(&mut self) -> V;
    fn bend_angle(&mut self) -> V;
    fn twist_extremes(&mut self) -> TwistHistory<R>;
    fn bend_history(&mut self) -> BendHistory<R, V>;
    /// `delta_max`, `delta_min`.
    fn put_delta_extremes(&mut self, new: Option<(R, R)>);
    fn put_shear_force(&mut self, new: Option<V>);
    fn put_twist_angle(&mut self, new: Option<V>);
    fn put_bend_angle(&mut self, new: Option<V>);
    fn put_twist_extremes(&mut self, new: Option<TwistHistory<R>>);
    fn put_bend_history(&mut self, new: Option<BendHistory<R, V>>);
    /// The force on `i` as soon as it is known, before the twisting and
    /// bending laws (it is returned with the other loads too).
    fn put_force(&mut self, force: V);
}

/// What the laws read of a pair: its centre line and section, and its
/// relative motion in the terms the laws use, each only where a law
/// switched on reads it (zero otherwise).
#[derive(Clone, Copy)]
pub(crate) struct Relative<R, V> {
    pub n: V,
    /// `r0 - r`.
    pub delta: R,
    pub section: Section<R>,
    pub inv_rb: R,
    pub lever_i: R,
    pub lever_j: R,
    pub slip: V,
    /// `(v_i - v_j) . n`, for the damping of the normal force.
    pub normal_rate: R,
    /// `w_i - w_j`.
    pub spin: V,
}

/// Whether the bond breaks on its centre distance `r` (distance mode).
#[inline(always)]
pub(crate) fn breaks_by_distance<R: Real>(laws: &BondLaws, r: R) -> R::Mask {
    if laws.stress_break {
        R::mask(false)
    } else {
        distance_criterion(r, laws.params.max_distance)
    }
}

/// The loads of a bond broken by its centre distance at compression
/// `delta`: nothing, no stresses; its history stays as it was.
#[inline(always)]
pub(crate) fn broken_by_distance<R: Real, V: Vector<R>>(delta: R) -> Loads<R, V> {
    let zero = R::splat(0.0);
    Loads {
        force_i: V::zeros(),
        torque_i: V::zeros(),
        torque_j: V::zeros(),
        normal_force: zero,
        sigma: zero,
        tau: zero,
        delta,
        mode: R::splat(BreakMode::Distance as i32 as f64),
    }
}

/// The pair's motion reduced to what the laws switched on read, with its
/// centre line and the bond's rest length `r0`.
#[inline(always)]
pub(crate) fn relative<S: Switches, R: Real, V: Vector<R>>(
    laws: &BondLaws,
    m: &mut impl MotionSource<R, V>,
    line: CentreLine<R, V>,
    r0: R,
) -> Relative<R, V> {
    let on = |bits| S::of(laws).any(bits);
    let zero = R::splat(0.0);
    // Each value is computed where it is pinned, from numbers that die
    // there, whatever branch comes before its first use (see `Real::pin`);
    // pinned as soon as it is computed, while it is in a register.
    let n = line.n.pin();
    let delta = (r0 - line.r).pin();
    let (shear, spins) = (on(SHEAR), on(TWIST | BEND));
    let normal_damping = on(DAMPING) && on(TENSION | COMPRESSION);
    let (radius_i, radius_j) = m.radii();
    let sec = section(laws.params.lambda, radius_i, radius_j);
    // The only divisions by the radii: the stresses and lever arms multiply.
    let (inv_rb, inv_radius_sum) = super::section::reciprocals(&sec, radius_i, radius_j);
    let (mut lever_i, mut lever_j) = (zero, zero);
    let (mut slip, mut normal_rate, mut spin) = (V::zeros(), zero, V::zeros());
    if shear || normal_damping {
        let (v_i, v_j) = m.velocities();
        if normal_damping {
            normal_rate = (v_i - v_j).dot(&n).pin();
        }
        if shear || spins {
            let (w_i, w_j) = m.spins();
            if shear {
                let (i, j) = lever_arms_scaled(line.r, inv_radius_sum, radius_i, radius_j);
                (lever_i, lever_j) = (i.pin(), j.pin());
                slip = slip_velocity(v_i - v_j, w_i, w_j, n, lever_i, lever_j).pin();
            }
            if spins {
                spin = (w_i - w_j).pin();
            }
        }
    } else if spins {
        let (w_i, w_j) = m.spins();
        spin = (w_i - w_j).pin();
    }
    Relative {
        n,
        delta,
        section: sec,
        inv_rb,
        lever_i,
        lever_j,
        slip,
        normal_rate,
        spin,
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

/// The physics of one step of an intact bond with usable kinematics that
/// does not break by distance ([`breaks_by_distance`]), for one bond
/// (`f64`) or a chunk of lanes (see [`super::wide`]): updates the history
/// in `h` and returns the loads.
///
/// A bond broken by stress (`mode` not 0) has its history updated and
/// reports the stresses that broke it; the caller zeroes its force and
/// torques, as it exerts nothing.
#[inline(always)]
pub(crate) fn advance<S: Switches, R: Real, V: Vector<R>, H: HistoryIo<R, V>>(
    laws: &BondLaws,
    k: &Relative<R, V>,
    dt: R,
    h: &mut H,
) -> Loads<R, V> {
    let on = |bits| S::of(laws).any(bits);
    let zero = R::splat(0.0);
    let (n, delta, sec) = (k.n, k.delta, &k.section);
    let (shear, twist, bend, damping) = (on(SHEAR), on(TWIST), on(BEND), on(DAMPING));
    let smooth = on(SMOOTH);
    let p = &laws.params;
    let (ve, we) = (p.smooth_velocity, p.smooth_angular_velocity);

    let mut normal_force = zero;
    if on(TENSION | COMPRESSION) {
        let (max, min) = h.delta_extremes();
        let (hi, lo) = laws.normal.update_history(delta, max, min);
        h.put_delta_extremes(Some((hi, lo)));
        normal_force = sec.area * laws.normal.stress(delta, hi, lo, on(TENSION), on(COMPRESSION));
    } else {
        h.put_delta_extremes(None);
    }
    let undamped = normal_force;
    if damping && on(TENSION | COMPRESSION) {
        normal_force = damp_scalar(normal_force, p.eta_fn, k.normal_rate, ve, smooth);
    }

    // Lengths, two per instruction: the shear force (for the stresses and
    // the damping) and, with damping, the slip speed the damping opposes.
    let (mut shear_force, mut shear_magnitude, mut slip_speed) = (V::zeros(), zero, zero);
    if shear {
        let stiffness = R::splat(p.k_ft) * sec.area;
        shear_force = update_shear_force(h.shear_force(), stiffness, dt, k.slip, n);
        h.put_shear_force(Some(shear_force));
        (shear_magnitude, slip_speed) = norms(shear_force, true, k.slip, damping);
    } else {
        h.put_shear_force(None);
    }
    let (w_along, w_across, spin_rate) = if twist || bend {
        split_relative_spin(k.spin, n)
    } else {
        (V::zeros(), V::zeros(), zero)
    };
    // The (smooth) unit vectors of the slip and of the bending spin: one
    // reciprocal each, both in one instruction.
    let (mut scale_b, mut inv_b) = (zero, zero);
    if damping {
        let spin_across = if bend { w_across.norm() } else { zero };
        let scale_s = unit_scale(slip_speed, ve, smooth);
        scale_b = unit_scale(spin_across, we, smooth);
        let inv_s;
        (inv_s, inv_b) = reciprocals(scale_s, shear, scale_b, bend);
        if shear {
            let direction = reciprocal_unit(k.slip, scale_s, inv_s);
            shear_force = damp_along(shear_force, shear_magnitude, p.eta_ft, direction);
        }
    }
    let force = n * normal_force + shear_force;
    h.put_force(force);
    let arm = if shear { n.cross(&shear_force) } else { V::zeros() };

    // |torque| = |h| * moment, from the laws (no square roots).
    let (mut twist_torque, mut twist_magnitude) = (V::zeros(), zero);
    let mut twist_history = None;
    if twist {
        let theta = advance_twist(h.twist_angle(), w_along, n, dt);
        h.put_twist_angle(Some(theta));
        let (t, history) = laws.twist.twist(theta, n, h.twist_extremes(), sec.polar);
        twist_history = Some(history);
        (twist_torque, twist_magnitude) = (t.torque, t.magnitude);
        if damping {
            // w_along = n (w . n), so its unit vector is n sgn(w . n) (and
            // the smooth one n clamp(w . n / we, -1, 1), the same thing).
            let direction = n * sign(spin_rate, we, smooth);
            twist_torque = damp_along(twist_torque, twist_magnitude, p.eta_tn, direction);
        }
    } else {
        h.put_twist_angle(None);
    }
    let (mut bend_torque, mut bend_magnitude) = (V::zeros(), zero);
    if bend {
        let theta = advance_bend(h.bend_angle(), w_across, n, dt);
        h.put_bend_angle(Some(theta));
        h.put_twist_extremes(twist_history);
        let (t, history) = laws.bend.bend(theta, n, h.bend_history(), sec.inertia);
        h.put_bend_history(Some(history));
        (bend_torque, bend_magnitude) = (t.torque, t.magnitude);
        if damping {
            let direction = reciprocal_unit(w_across, scale_b, inv_b);
            bend_torque = damp_along(bend_torque, bend_magnitude, p.eta_tt, direction);
        }
    } else {
        h.put_bend_angle(None);
        h.put_twist_extremes(twist_history);
        h.put_bend_history(None);
    }

    let (sigma, tau) = section_stresses(
        undamped,
        shear_magnitude,
        twist_magnitude,
        bend_magnitude,
        k.inv_rb,
    );
    let couple = bend_torque + twist_torque;
    let (mut torque_i, mut torque_j) = (couple, -couple);
    if shear {
        torque_i -= arm * k.lever_i;
        torque_j -= arm * k.lever_j;
    }
    Loads {
        force_i: force,
        torque_i,
        torque_j,
        normal_force: undamped,
        sigma,
        tau,
        delta,
        // (0 unless the bond breaks.)
        mode: if laws.stress_break {
            stress_criterion(sigma, tau, delta, &laws.limits)
        } else if laws.bpm_break {
            summed_criterion(
                undamped,
                shear_magnitude,
                twist_magnitude,
                bend_magnitude,
                delta,
                &laws.summed,
            )
        } else {
            zero
        },
    }
}
